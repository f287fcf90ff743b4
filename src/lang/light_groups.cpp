// POV-Ray's light_group, in both dialects:
//   light_group { { object | light_source | light_group } [global_lights [on | off]] { transform } }
// A union of its objects whose lights light only those objects (and the
// objects of light groups inside it); with `global_lights` (off by default) the
// objects are lit by the scene's other lights too. Every object still casts
// shadows from every light (scene.h, lightReaches).
#include "lang/evaluator.h"

namespace drt::lang {

namespace {

// Puts an object and its members into `group`, unless they belong to a light
// group inside it, which then sits inside `group`.
void joinGroup(ObjectValue& o, int group, bool globalLights, std::vector<int>& parents) {
    if (o.object.lightGroup != 0 && o.object.lightGroup != group) {
        int& parent = parents[size_t(o.object.lightGroup)];
        if (parent == 0) parent = group;
        return;
    }
    o.object.lightGroup = group;
    o.object.globalLights = globalLights;
    for (ObjectValue& child : o.children) joinGroup(child, group, globalLights, parents);
}

} // namespace

ObjectValue Evaluator::lightGroup(const Token& keyword) {
    ObjectValue po;
    po.object.loc = keyword.loc;
    po.object.shape = Csg{Csg::Op::Union, {}};
    std::vector<int>& parents = scene_.lightGroupParents;
    const int group = static_cast<int>(parents.size());
    parents.push_back(0);
    bool globalLights = false; // POV-Ray's default
    for (;;) {
        const Token t = peek();
        if (t.is("}")) {
            next();
            break;
        }
        if (isObjectWord(t) || t.isWord("light_source")) {
            next();
            addChild(po, object(t));
            continue;
        }
        if (std::optional<Transform> tr = transformItem()) {
            applyTransform(po, *tr, t.loc);
            continue;
        }
        if (t.isWord("global_lights")) {
            next();
            globalLights = optionalBool(true);
            continue;
        }
        next();
        failInBlock(t, "an object, a light_source, a transform, 'global_lights' or '}' in light_group");
    }
    for (Light& l : po.lights) {
        if (l.group == 0) l.group = group;
        else if (l.group != group && parents[size_t(l.group)] == 0) parents[size_t(l.group)] = group;
    }
    for (ObjectValue& child : po.children) joinGroup(child, group, globalLights, parents);
    po.object.lightGroup = group;
    po.object.globalLights = globalLights;
    if (po.children.empty()) po.lightOnly = true; // lights alone light nothing: POV-Ray renders the same
    return po;
}

} // namespace drt::lang
