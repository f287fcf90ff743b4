// Objects: a shape keyword and its arguments (shapes_*.cpp), `object { Name }`,
// CSG and the object modifiers. A texture given to an object moves with every
// transform of the object that follows it; a CSG's texture goes to its members
// that have none (POV-Ray).
#include "lang/evaluator.h"
#include "lang/shape_syntax.h"
#include "scene/bounds.h"

#include <fmt/format.h>

namespace drt::lang {

using Kind = Value::Kind;

// CSG: the members follow as object modifiers (objectModifiers). These come
// first: an explicit specialization must precede its first use in this file
// (the shape table and shapeHead use every shape's), or clang refuses it.
template <>
const std::vector<std::string>& ShapeSyntax<Csg>::keywords() {
    static const std::vector<std::string> w = [] {
        std::vector<std::string> words;
        for (const CsgWord& c : csgWords()) words.push_back(c.word);
        return words;
    }();
    return w;
}

template <>
void ShapeSyntax<Csg>::read(Evaluator&, const Token& keyword, ObjectValue& o) {
    Csg csg;
    csg.op = *csgOpNamed(keyword.text);
    o.object.shape = std::move(csg);
}

template <>
std::string ShapeSyntax<Csg>::head(const Csg& c, ShapeText& text) {
    if (c.children.empty()) {
        text.problems.insert("a CSG with no members (left out)");
        return "";
    }
    return std::string(csgWord(c.op)) + " {";
}

// ------------------------------------------------------------ the shape table

namespace {

template <class V> struct ReaderTable;
template <class... Ts> struct ReaderTable<std::variant<Ts...>> {
    static std::vector<std::pair<std::string, ShapeReader>> build() {
        std::vector<std::pair<std::string, ShapeReader>> table;
        (add<Ts>(table), ...);
        return table;
    }
    template <class T> static void add(std::vector<std::pair<std::string, ShapeReader>>& table) {
        for (const std::string& keyword : ShapeSyntax<T>::keywords()) table.emplace_back(keyword, &ShapeSyntax<T>::read);
    }
};

} // namespace

const std::vector<std::pair<std::string, ShapeReader>>& shapeReaders() {
    static const std::vector<std::pair<std::string, ShapeReader>> table = ReaderTable<Shape>::build();
    return table;
}

ShapeReader shapeReader(const std::string& keyword) {
    for (const auto& [word, reader] : shapeReaders())
        if (word == keyword) return reader;
    return nullptr;
}

bool isUnsupportedShape(const std::string& keyword) {
    const std::string_view w = keyword;
    return w == "parametric" || w == "sphere_sweep" || w == "ovus";
}

std::string shapeHead(const Shape& shape, ShapeText& text) {
    return std::visit([&](const auto& s) { return ShapeSyntax<std::decay_t<decltype(s)>>::head(s, text); }, shape);
}

// ------------------------------------------------------------ helpers

void transformProjectedThrough(Light& l, const Transform& t) {
    if (!l.projectedThrough) return;
    auto moved = std::make_shared<Scene>(*l.projectedThrough);
    for (Object& o : moved->objects) {
        for (Object& clip : o.clippedBy) clip.transform = clip.transform.then(t);
        o.transform = o.transform.then(t); // never moving: 'motion' and projected_through exclude each other
    }
    l.projectedThrough = std::move(moved);
}

namespace {

void transformLight(Light& l, const Transform& t) {
    transformProjectedThrough(l, t);
    if (l.motion && !l.motion->chain.empty()) { // after the light's motion (render/light_path.h)
        auto moved = std::make_shared<LightMotion>(*l.motion);
        moved->chain.back().after = moved->chain.back().after.then(t);
        l.motion = std::move(moved);
        return;
    }
    l.position = t.point(l.position);
    l.pointAt = t.point(l.pointAt);
    if (l.area) {
        l.area->axis1 = t.vector(l.area->axis1);
        l.area->axis2 = t.vector(l.area->axis2);
    }
}

// Members' textures and interiors live in their CSG's own space.
void inheritTexture(ObjectValue& o, const Texture& texture) {
    if (o.textured) return;
    o.object.texture = texture;
    if (o.children.empty()) return;
    Texture local = texture;
    transformTextureSpaces(local, o.object.transform.inverted());
    for (ObjectValue& child : o.children) inheritTexture(child, local);
}

void inheritInterior(ObjectValue& o, const Interior& interior) {
    if (o.interiorSet) return;
    o.object.interior = interior;
    if (o.children.empty()) return;
    Interior local = interior;
    transformInteriorSpaces(local, o.object.transform.inverted());
    for (ObjectValue& child : o.children) inheritInterior(child, local);
}

} // namespace

void Evaluator::setTexture(ObjectValue& o, const Texture& texture) {
    o.textured = false; // a new texture replaces the object's own one
    inheritTexture(o, texture);
    o.textured = true;
}

void Evaluator::setInterior(ObjectValue& o, const Interior& interior) {
    o.interiorSet = false;
    inheritInterior(o, interior);
    o.interiorSet = true;
}

void Evaluator::addChild(ObjectValue& parent, ObjectValue child) {
    // The child's lights join the parent's, in the space the parent's transform maps to.
    for (Light& l : child.lights) {
        transformLight(l, parent.object.transform);
        parent.lights.push_back(l);
    }
    child.lights.clear();
    if (child.lightOnly) return;
    if (parent.textured) {
        Texture local = parent.object.texture;
        transformTextureSpaces(local, parent.object.transform.inverted());
        inheritTexture(child, local);
    }
    if (parent.interiorSet) {
        Interior local = parent.object.interior;
        transformInteriorSpaces(local, parent.object.transform.inverted());
        inheritInterior(child, local);
    }
    parent.children.push_back(std::move(child));
}

// A transform goes after everything written so far, motions included
// (scene/motion.h). Textures and interiors are placed in the rest pose, so
// every transform moves them; clips are folded into the rest pose when the
// object reaches the scene (Flattener), so only transforms before a motion
// move them here.
void Evaluator::applyTransform(ObjectValue& po, const Transform& t, SourceLoc) {
    Object& o = po.object;
    if (o.motion.empty())
        for (Object& clip : o.clippedBy) clip.transform = clip.transform.then(t);
    appendTransform(o.transform, o.motion, t);
    transformObjectTextures(o, t);
    transformInteriorSpaces(o.interior, t);
    for (Light& l : po.lights) transformLight(l, t);
}

namespace {

// The members of a CSG as model objects: each keeps its transform relative to
// the CSG (the accelerator composes them), while pigments map all the way to
// world space like every pigment in the model.
std::vector<Object> csgChildren(Evaluator& e, ObjectValue& po, const Transform& csgToWorld) {
    std::vector<Object> children;
    for (ObjectValue& child : po.children) {
        Object o = std::move(child.object);
        transformObjectTextures(o, csgToWorld);
        transformInteriorSpaces(o.interior, csgToWorld);
        if (child.isCsg()) std::get<Csg>(o.shape).children = csgChildren(e, child, o.transform.then(csgToWorld));
        children.push_back(std::move(o));
    }
    return children;
}

bool hasMotionInside(const ObjectValue& po) {
    for (const ObjectValue& c : po.children)
        if (!c.object.motion.empty() || hasMotionInside(c)) return true;
    return false;
}

} // namespace

Object Evaluator::placed(ObjectValue po) {
    Object o = std::move(po.object);
    if (po.isCsg()) std::get<Csg>(o.shape).children = csgChildren(*this, po, o.transform);
    return o;
}

namespace {

// The geometry of an object value as a model object (members relative to their CSG).
Object geometryOf(const ObjectValue& v) {
    Object m = v.object;
    if (v.isCsg()) {
        std::vector<Object>& members = std::get<Csg>(m.shape).children;
        members.clear();
        for (const ObjectValue& c : v.children) members.push_back(geometryOf(c));
    }
    return m;
}

} // namespace

void objectBounds(const ObjectValue& po, Vec3& lower, Vec3& upper) { drt::objectBounds(geometryOf(po), lower, upper); }

// ------------------------------------------------------------ objects

bool Evaluator::isObjectWord(const Token& t) const {
    return t.kind == TokenKind::Word && !lookup(t) &&
           (t.text == "object" || t.text == "light_group" || shapeReader(t.text) || isUnsupportedShape(t.text));
}

namespace {

// An object's nodes: its own (scene/weight.h) and its CSG members', which stay
// ObjectValues until the object is placed. Stops counting past `cap`.
int64_t objectWeight(const ObjectValue& o, int64_t cap) {
    int64_t total = weightOf(o.object, cap).total();
    for (const ObjectValue& child : o.children)
        if (total <= cap) total += objectWeight(child, cap - total);
    return total;
}

} // namespace

void Evaluator::countBuilt(SourceLoc loc, int64_t weight) {
    const int64_t before = built_;
    built_ += weight;
    if (built_ > diags_.limits().objects)
        failLimit(loc, limitExceeded(diags_.limits(), &Limits::objects, "the scene's objects and patterns number",
                                double(built_)));
    if (built_ / kMemoryCheckInterval != before / kMemoryCheckInterval) checkMemoryAt(loc);
}

ObjectValue Evaluator::object(const Token& keyword) {
    DepthGuard guard(*this, keyword.loc);
    const std::string& w = keyword.text;
    ObjectValue po;
    po.object.loc = keyword.loc;
    if (w == "light_source") {
        std::optional<ObjectValue> looksLike;
        const Light light = lightSource(keyword.loc, &looksLike);
        if (looksLike) po = std::move(*looksLike); // the shape carries the light
        else po.lightOnly = true;
        po.lights.push_back(light);
        return po;
    }
    expectSymbol("{", "after '", w, "'");
    BlockScope scope(*this, w, keyword.loc);
    if (w == "light_group") return lightGroup(keyword);
    if (isUnsupportedShape(w)) {
        unsupported("shape-" + w, keyword.loc, "'" + w + "' is not supported; the object is left out");
        skipBlock();
        po.lightOnly = true; // nothing to render
        return po;
    }
    if (w == "object") {
        const Token t = next();
        const Cell c = t.kind == TokenKind::Word ? useIndexed(t) : nullptr;
        if (c && c->kind == Kind::Object) {
            // A copy counts what it copies, so a doubling of declared objects
            // stops at the limit before it fills the memory.
            countBuilt(t.loc, objectWeight(*c->object, diags_.limits().objects - built_ + 1));
            po = *c->object;
            po.object.loc = keyword.loc;
        } else if (isObjectWord(t) || t.isWord("light_source")) {
            po = object(t); // object { sphere { ... } modifiers }
        } else if (c) {
            fail(t.loc, "'" + t.text + "' is " + kindName(*c) + ", not an object");
        } else if (t.kind == TokenKind::Word) {
            failUnknownIn(t, declaredNames({Kind::Object}), "object");
        } else {
            failExpected(t, "the name of a declared object");
        }
    } else {
        countBuilt(keyword.loc, 1);
        shapeReader(w)(*this, keyword, po);
    }
    objectModifiers(po, keyword);
    return po;
}

void Evaluator::objectModifiers(ObjectValue& po, const Token& keyword) {
    Object& o = po.object;
    int textures = 0; // a second `texture` is a layer on top of the first (POV-Ray)
    // uv_mapping among the object's modifiers: the textures given after it read the surface's uvs.
    bool uvMapped = false;
    const auto uvMap = [&](Texture tex) {
        if (!uvMapped) return tex;
        const auto mapLayer = [](Texture& layer) {
            setUvMapping(layer.pigment, true);
            if (layer.normal) layer.normal->uvMapping = true;
        };
        mapLayer(tex);
        for (Texture& above : tex.layersAbove) mapLayer(above);
        return tex;
    };
    std::vector<Object> boundedBy; // for `clipped_by { bounded_by }`
    auto topTexture = [&]() -> Texture { return po.textured ? *o.texture : defaultTexture_; };
    for (;;) {
        const Token t = peek();
        if (t.is("}")) {
            next();
            break;
        }
        if (po.isCsg() && (isObjectWord(t) || t.isWord("light_source"))) {
            next();
            addChild(po, object(t));
            continue;
        }
        if (std::optional<Transform> tr = transformItem()) {
            applyTransform(po, *tr, t.loc);
            for (Object& b : boundedBy) b.transform = b.transform.then(*tr);
            continue;
        }
        next();
        if (t.kind != TokenKind::Word) failInBlock(t, "an object modifier or '}' to close '" + keyword.text + "'");
        const std::string& m = t.text;
        if (const Cell c = lookup(m)) {
            const std::string kind = kindName(*c);
            if (c->kind == Kind::Texture || c->kind == Kind::Pigment || c->kind == Kind::Finish ||
                c->kind == Kind::Interior || c->kind == Kind::Material || c->kind == Kind::Normal)
                fail(t.loc, "'" + m + "' is " + kind + "; write " + kind.substr(kind.find(' ') + 1) + " { " + m + " }");
            if (c->kind == Kind::Object) fail(t.loc, "'" + m + "' is an object; write object { " + m + " }");
            fail(t.loc, "'" + m + "' is " + kind + ", not an object modifier");
        }
        const SourceLoc valueLoc = peek().loc;
        if (m == "texture") {
            if (textures++ == 0) {
                setTexture(po, uvMap(texture(topTexture())));
            } else if (po.children.empty()) {
                // On the object's own texture (copied only if shared): a layer costs
                // no copy of the layers below it.
                Texture top = uvMap(texture(defaultTexture_));
                layerOnTop(o.texture.edit(), std::move(top), t.loc);
            } else { // a CSG's members each get the layer
                Texture layered = o.texture;
                layerOnTop(layered, uvMap(texture(defaultTexture_)), t.loc);
                setTexture(po, layered);
            }
        } else if (m == "pigment" || m == "finish" || m == "normal") {
            // Of the top layer (measured against POV-Ray); an untextured object starts from the default.
            Texture tex = topTexture();
            Texture& top = tex.layersAbove.empty() ? tex : tex.layersAbove.back();
            if (m == "pigment") top.pigment = pigment(top.pigment);
            else if (m == "finish") top.finish = finish(top.finish);
            else if (std::optional<Normal> n = normalBlock(t.loc, std::nullopt)) top.normal = std::move(n);
            else continue;
            setTexture(po, uvMap(tex));
        } else if (m == "interior") {
            setInterior(po, interior(o.interior));
        } else if (m == "material") {
            const Material mat = material(Material{});
            if (mat.texture) setTexture(po, *mat.texture);
            if (mat.interior) setInterior(po, *mat.interior);
        } else if (m == "hollow") {
            o.hollow = optionalBool(true);
        } else if (m == "no_shadow") {
            o.noShadow = true;
        } else if (m == "inverse") {
            o.inverse = !o.inverse;
        } else if (m == "motion") {
            o.motion.push_back(MotionStage{motionBlock(), Transform()});
        } else if (m == "open") {
            if (Cylinder* cy = std::get_if<Cylinder>(&o.shape)) cy->open = true;
            else if (Cone* co = std::get_if<Cone>(&o.shape)) co->open = true;
            else if (Extrusion* ex = std::get_if<Extrusion>(&o.shape); ex && ex->prism) ex->open = true;
            else if (Revolution* rv = std::get_if<Revolution>(&o.shape); rv && rv->kind == Revolution::Kind::Sor)
                rv->open = true;
            else if (Isosurface* iso = std::get_if<Isosurface>(&o.shape)) iso->open = true;
            else if (syntax().strictValues)
                error(t.loc, "'open' applies only to cylinder, cone and prism, and to sor and isosurface");
            else warnOnce("open", t.loc, "'open' applies to cylinder, cone, prism, sor and isosurface only; ignored");
        } else if (m == "sturm" || m == "smooth" || m == "split_union" || m == "hierarchy") {
            const bool on = optionalBool(true);
            if (Algebraic* a = std::get_if<Algebraic>(&o.shape); a && m == "sturm" && a->form != Algebraic::Form::Quadric)
                a->sturm = on;
            if (Revolution* rv = std::get_if<Revolution>(&o.shape); rv && m == "sturm") rv->sturm = on;
            if (Blob* b = std::get_if<Blob>(&o.shape); b && m == "sturm") b->sturm = on;
            if (Blob* b = std::get_if<Blob>(&o.shape); b && m == "hierarchy") b->hierarchy = on;
        } else if (m == "inside_vector") {
            vectorExpr();
        } else if (m == "bounded_by" || m == "clipped_by") {
            if (m == "clipped_by" && !o.motion.empty())
                error(t.loc, "clipped_by after 'motion' is not supported; put it before the motion");
            // POV-Ray treats bounded_by as an optimisation (it can only cut an
            // object it does not enclose), so ignoring it is a note; the
            // objects are kept for `clipped_by { bounded_by }`.
            const std::optional<std::vector<Object>> objects = clipObjects(t);
            if (m == "bounded_by") {
                noteOnce("note-bounded_by", t.loc, "'bounded_by' is ignored: drt builds its own bounds");
                if (objects) boundedBy = *objects;
            } else if (!objects) {
                o.clippedBy.insert(o.clippedBy.end(), boundedBy.begin(), boundedBy.end());
            } else {
                o.clippedBy.insert(o.clippedBy.end(), objects->begin(), objects->end());
            }
        } else if (m == "photons" || m == "radiosity" || m == "interior_texture") {
            unsupported(m, t.loc, "'" + m + "' is not supported and is ignored");
            expectSymbol("{", "after '", m, "'");
            skipBlock();
        } else if (m == "uv_mapping") {
            uvMapped = optionalBool(true);
        } else if (m == "no_image" || m == "no_reflection" || m == "no_radiosity" || m == "double_illuminate" ||
                   m == "cutaway_textures") {
            unsupported(m, t.loc, "'" + m + "' is not supported and is ignored");
            optionalBool(true);
        } else {
            (void)valueLoc;
            const auto& top = blockKeywords(Block::Statement);
            if (std::find(top.begin(), top.end(), m) != top.end() || isObjectWord(t))
                failInBlock(t, "an object modifier or '}' to close '" + keyword.text + "'");
            std::vector<std::string> extra;
            if (po.isCsg())
                for (const auto& [word, reader] : shapeReaders()) extra.push_back(word);
            failUnknown(t, Block::Object, extra);
        }
    }
    if (po.isCsg() && po.children.empty()) {
        if (!po.lights.empty()) po.lightOnly = true;
        else if (syntax().strictValues) error(keyword.loc, keyword.text + " has no objects");
        else {
            // POV-Ray itself only warns and renders nothing for it: the image is the same.
            noteOnce("note-empty-csg", keyword.loc, "'" + keyword.text + "' has no objects; left out (as POV-Ray)");
            po.lightOnly = true;
        }
    }
}

// motion = "motion" "{" [ "spline" ] ( key_items | { "at" float key_items } ) "}"
// key_items = { ("translate" | "rotate" | "scale") vector3 }   (each at most once per key)
// Without `at` the items are one key at time 1; keyed or not, the path starts
// from the identity at time 0 unless a key is given there (scene/motion.h).
// The same block moves objects, cameras (camera.cpp) and lights (lights.cpp).
Motion Evaluator::motionBlock() {
    const Token keyword = lastToken();
    expectSymbol("{", "after 'motion'");
    BlockScope scope(*this, "motion", keyword.loc);
    Motion m;
    bool keyed = false;
    bool seen[3] = {false, false, false};
    const auto startKey = [&](double time) {
        m.keys.push_back(MotionKey{time});
        seen[0] = seen[1] = seen[2] = false;
    };
    for (;;) {
        const Token word = next();
        if (word.is("}")) break;
        if (word.kind != TokenKind::Word)
            failInBlock(word, "'at', 'translate', 'rotate', 'scale', 'spline' or '}' in motion");
        if (word.text == "spline") {
            if (m.spline) error(word.loc, "'spline' given twice in motion");
            m.spline = true;
            continue;
        }
        if (word.text == "at") {
            if (!keyed && !m.keys.empty()) error(word.loc, "'at' after key items without a time; begin with 'at'");
            keyed = true;
            const SourceLoc loc = peek().loc;
            const double time = floatExpr("a time");
            if (!(time >= 0 && time <= 1)) error(loc, "motion key times must be in [0, 1]" + got(time));
            else if (!m.keys.empty() && !(time > m.keys.back().time)) error(loc, "motion key times must increase");
            startKey(time);
            continue;
        }
        const int index = word.text == "translate" ? 0 : word.text == "rotate" ? 1 : word.text == "scale" ? 2 : -1;
        if (index < 0) failUnknown(word, Block::Motion);
        if (m.keys.empty()) startKey(1);
        if (seen[index]) error(word.loc, "'" + word.text + "' given twice in " + (keyed ? "one motion key" : "motion"));
        seen[index] = true;
        const SourceLoc loc = peek().loc;
        const Vec3 v = vectorExpr();
        MotionKey& key = m.keys.back();
        if (index == 0) key.translate = v;
        else if (index == 1) key.rotate = v;
        else if (v.x == 0 || v.y == 0 || v.z == 0) error(loc, "motion scale has a zero component" + got(v));
        else key.scale = v;
    }
    if (m.keys.empty()) m.keys.push_back(MotionKey{1});
    if (m.keys.front().time > 0) m.keys.insert(m.keys.begin(), MotionKey{0});
    return m;
}

// The objects of `bounded_by { ... }` or `clipped_by { ... }` in the space the
// enclosing object's transform maps to: the object's own transforms so far do
// not move them, those written after the block do (applyTransform). Nothing for
// `clipped_by { bounded_by }` and `bounded_by { clipped_by }` (the other
// block's objects). Left-out shapes (warned about) are left out.
std::optional<std::vector<Object>> Evaluator::clipObjects(const Token& word) {
    const std::string& keyword = word.text;
    expectSymbol("{", "after '", keyword, "'");
    BlockScope scope(*this, keyword, word.loc);
    std::vector<Object> objects;
    const char* other = keyword == "clipped_by" ? "bounded_by" : "clipped_by";
    bool any = false;
    for (;;) {
        const Token t = next();
        if (t.is("}")) break;
        if (t.isWord(other) && !any) {
            expectSymbol("}", "after '", std::string(other), "'");
            return std::nullopt;
        }
        if (!isObjectWord(t)) failInBlock(t, "an object or '}' in " + keyword);
        any = true;
        ObjectValue clip = object(t);
        if (clip.lightOnly) continue;
        if (!clip.object.motion.empty()) error(clip.object.loc, "'motion' on a " + keyword + " object is not supported");
        objects.push_back(placed(std::move(clip)));
    }
    if (!any) error(word.loc, "'" + keyword + "' needs at least one object");
    return objects;
}

// ------------------------------------------------------------ placing

namespace {

struct Flattener {
    Evaluator& e;
    Scene& scene;

    // A union reaches the scene as its leaves, each carrying the union's
    // transforms and motions after its own (scene/motion.h appendPlacement):
    // the same surfaces as the union itself, moving as it does. `parentBefore`
    // and `parentChain` place the enclosing union in the world.
    void flatten(ObjectValue& po, const Transform& parentBefore, const MotionChain& parentChain, bool noShadow,
                 bool hollow, bool inverse, const std::vector<Object>& parentClips) {
        Object& o = po.object;
        Transform before = o.transform;
        MotionChain chain = o.motion;
        appendPlacement(before, chain, parentBefore, parentChain);
        const Transform parentRest = restPlacement(parentBefore, parentChain);
        noShadow = noShadow || o.noShadow;
        hollow = hollow || o.hollow;
        inverse = inverse != o.inverse;
        // Clips go to the rest pose's world; an enclosing union's clips apply to every leaf.
        std::vector<Object> clips = parentClips;
        const Transform clipToRest = restPlacement(Transform{}, o.motion).then(parentRest);
        for (Object& clip : o.clippedBy) {
            clip.transform = clip.transform.then(clipToRest);
            clips.push_back(std::move(clip));
        }
        o.clippedBy.clear();
        const Csg* csg = std::get_if<Csg>(&o.shape);
        if (csg && csg->op == Csg::Op::Union) {
            for (ObjectValue& child : po.children) flatten(child, before, chain, noShadow, hollow, inverse, clips);
            return;
        }
        if (csg) { // a solid CSG moves as a whole; its members cannot move on their own
            for (const ObjectValue& child : po.children)
                if (!child.object.motion.empty() || hasMotionInside(child))
                    e.error(child.object.loc, "'motion' inside merge, difference or intersection is not supported");
            std::get<Csg>(o.shape).children = csgChildren(e, po, restPlacement(before, chain));
        }
        o.transform = before;
        o.motion = std::move(chain);
        transformObjectTextures(o, parentRest);
        transformInteriorSpaces(o.interior, parentRest);
        o.noShadow = noShadow;
        o.hollow = hollow;
        o.inverse = inverse;
        o.clippedBy = std::move(clips);
        e.textureSharing_.share(o.texture);
        scene.objects.push_back(std::move(o));
    }
};

} // namespace

void Evaluator::addToScene(ObjectValue o) {
    scene_.lights.insert(scene_.lights.end(), o.lights.begin(), o.lights.end());
    if (o.lightOnly) return;
    o.lights.clear();
    // POV-Ray gives the #default texture to what has none when the object is placed.
    if (defaultSet_) inheritTexture(o, defaultTexture_);
    if (scene().keepUnions && o.object.motion.empty() && !hasMotionInside(o)) {
        Object top = placed(std::move(o));
        textureSharing_.share(top.texture);
        scene_.objects.push_back(std::move(top));
        return;
    }
    Flattener{*this, scene_}.flatten(o, Transform{}, MotionChain{}, false, false, false, {});
}

} // namespace drt::lang
