// Motion from a scene's own clock dependence (animation.h): the scene is
// evaluated at several clock values over the shutter and the evaluations are
// merged into one moving scene.
//
// Pairing: an object or light is known by where it was made in the scene text
// (its SourceLoc) and by its order among those made there (a loop makes
// several at one place). An object pairs with its namesake in every
// evaluation when its shape is the same, or the same up to an affine map
// (a sphere's centre and radius, a box's corners, a plane's offset); its
// placement at each clock value, with that map, is a sample of its path.
// Objects that appear or vanish during the shutter, or whose shape changes
// otherwise (a mesh's vertices, a torus's radii, a CSG whose members move
// relative to each other), cannot be paired: they stay as they are at the
// shutter's opening (FrameReport::unpaired names them). Textures, colours and
// everything else that is not a placement are those at the shutter's opening.
#include "animation/clock_motion.h"
#include "render/camera_path.h"
#include "render/light_path.h"
#include "scene/bounds.h"

#include <algorithm>
#include <cmath>
#include <concepts>
#include <map>
#include <memory>
#include <tuple>

namespace drt {

namespace {

// ---------------------------------------------------------------- shapes

bool sameChain(const MotionChain& a, const MotionChain& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        const Motion &m = a[i].motion, &n = b[i].motion;
        if (!(a[i].after == b[i].after) || m.keys != n.keys || m.spline != n.spline || m.sampled() || n.sampled())
            return false;
    }
    return true;
}

bool sameObjectTree(const Object& a, const Object& b);

// Shapes equal in every number that shapes them (textures aside): each shape's
// own operator== (scene/scene.h), and here the shapes that hold other objects
// or shared data.
struct SameShape {
    const Shape& other;
    template <class S>
        requires std::equality_comparable<S>
    bool operator()(const S& s) const {
        return s == std::get<S>(other);
    }
    bool operator()(const Mesh& s) const {
        const auto& o = std::get<Mesh>(other);
        const bool sameIndexed = s.indexed == o.indexed ||
                                 (s.indexed && o.indexed && sameIndexedMesh(*s.indexed, *o.indexed));
        const bool sameSource = s.source == o.source || (s.source && o.source && s.source->kind == o.source->kind &&
                                                           s.source->path == o.source->path);
        return sameSource && sameIndexed && s.vertices == o.vertices && s.triangles == o.triangles &&
               s.normals == o.normals && s.normalIndices == o.normalIndices;
    }
    bool operator()(const Csg& s) const {
        const auto& o = std::get<Csg>(other);
        if (s.op != o.op || s.children.size() != o.children.size()) return false;
        for (size_t i = 0; i < s.children.size(); ++i)
            if (!sameObjectTree(s.children[i], o.children[i])) return false;
        return true;
    }
};

bool sameShape(const Shape& a, const Shape& b) {
    return a.index() == b.index() && std::visit(SameShape{b}, a);
}

// Members of a CSG: the same shapes at the same places.
bool sameObjectTree(const Object& a, const Object& b) {
    return sameShape(a.shape, b.shape) && a.transform == b.transform && sameChain(a.motion, b.motion) &&
           a.inverse == b.inverse && a.clippedBy.size() == b.clippedBy.size();
}

// The affine map (object space) taking shape `from` onto shape `to`: the
// identity for equal shapes; nothing when no affine map is known to do it.
std::optional<Transform> shapeChange(const Shape& from, const Shape& to) {
    if (sameShape(from, to)) return Transform();
    if (from.index() != to.index()) return std::nullopt;
    if (const auto* a = std::get_if<Sphere>(&from)) {
        const auto& b = std::get<Sphere>(to);
        if (!(a->radius > 0) || !(b.radius > 0)) return std::nullopt;
        return Transform::translate(-a->center)
            .then(Transform::scale(Vec3(b.radius / a->radius)))
            .then(Transform::translate(b.center));
    }
    if (const auto* a = std::get_if<Box>(&from)) {
        const auto& b = std::get<Box>(to);
        const Vec3 lo0 = min(a->corner1, a->corner2), hi0 = max(a->corner1, a->corner2);
        const Vec3 lo1 = min(b.corner1, b.corner2), hi1 = max(b.corner1, b.corner2);
        Vec3 s;
        for (int i = 0; i < 3; ++i) {
            s[i] = (hi1[i] - lo1[i]) / (hi0[i] - lo0[i]);
            if (!(s[i] > 0) || !std::isfinite(s[i])) return std::nullopt;
        }
        return Transform::translate(-lo0).then(Transform::scale(s)).then(Transform::translate(lo1));
    }
    if (const auto* a = std::get_if<Plane>(&from)) {
        const auto& b = std::get<Plane>(to);
        const double n2 = dot(a->normal, a->normal);
        if (!(a->normal == b.normal) || !(n2 > 0)) return std::nullopt;
        return Transform::translate(a->normal * ((b.distance - a->distance) / n2));
    }
    return std::nullopt;
}

// ---------------------------------------------------------------- paths

struct Merge {
    const std::vector<Evaluation>& evaluations;
    FrameReport& report;
    std::vector<std::string> notes;

    std::string where(const SourceLoc& loc) const {
        return loc.valid() ? std::to_string(loc.line) + ":" + std::to_string(loc.column) : "(no location)";
    }

    // The object's path over the evaluations, or nothing if it does not move
    // with the clock or cannot be paired (noted).
    std::optional<Motion> objectPath(const Object& base, const Identity& id,
                                     const std::vector<std::map<Identity, size_t>>& index) {
        std::vector<double> times;
        std::vector<Transform> samples;
        bool changes = false;
        const Transform rest = restPlacement(base.transform, base.motion);
        const Transform toRest = rest.inverted();
        for (size_t j = 0; j < evaluations.size(); ++j) {
            const auto found = index[j].find(id);
            if (found == index[j].end()) {
                notes.push_back(where(base.loc) + ": an object absent at another clock value over the shutter");
                return std::nullopt;
            }
            const Object& other = evaluations[j].scene.objects[found->second];
            changes = changes || !sameShape(base.shape, other.shape) || !(base.transform == other.transform) ||
                      !sameChain(base.motion, other.motion);
            const std::optional<Transform> placed = placementIn(base, other, evaluations[j].time);
            if (!placed) {
                notes.push_back(where(base.loc) + ": an object whose shape changes over the shutter");
                return std::nullopt;
            }
            times.push_back(evaluations[j].time);
            samples.push_back(toRest.then(*placed));
        }
        if (!changes) return std::nullopt;
        Vec3 centre;
        double size = 1;
        objectExtent(base, centre, size);
        return sampledMotion(std::move(times), std::move(samples), rest.point(centre));
    }
};

bool samePose(const LightKey& a, const LightKey& b) {
    return a.position == b.position && a.pointAt == b.pointAt && a.axis1 == b.axis1 && a.axis2 == b.axis2;
}

} // namespace

// ---------------------------------------------------------------- identity

std::vector<Identity> identities(const std::vector<SourceLoc>& locs) {
    std::map<std::tuple<int, int, int>, int> seen;
    std::vector<Identity> out;
    for (const SourceLoc& loc : locs) {
        const auto place = loc.valid() ? std::make_tuple(loc.file, loc.line, loc.column) : std::make_tuple(-1, 0, 0);
        out.emplace_back(std::get<0>(place), std::get<1>(place), std::get<2>(place), seen[place]++);
    }
    return out;
}

std::map<Identity, size_t> indexByIdentity(const std::vector<Identity>& ids) {
    std::map<Identity, size_t> index;
    for (size_t i = 0; i < ids.size(); ++i) index[ids[i]] = i;
    return index;
}

std::optional<Transform> placementIn(const Object& base, const Object& object, double time) {
    const std::optional<Transform> change = shapeChange(base.shape, object.shape);
    if (!change) return std::nullopt;
    return change->then(placementAt(object.transform, object.motion, time));
}

void objectExtent(const Object& object, Vec3& centre, double& size) {
    Object local = object;
    local.transform = Transform();
    local.motion.clear();
    local.clippedBy.clear();
    Vec3 lo, hi;
    if (objectBounds(local, lo, hi) && isFinite(lo) && isFinite(hi)) {
        centre = 0.5 * (lo + hi);
        size = std::max(length(hi - lo), 1e-9);
    } else {
        centre = {};
        size = 1;
    }
}

LightKey lightPose(const Light& light, double time) {
    const Light at = lightAt(light, time);
    LightKey k{time, at.position, at.pointAt, {}, {}};
    if (at.area) {
        k.axis1 = at.area->axis1;
        k.axis2 = at.area->axis2;
    }
    return k;
}

bool sameCamera(const CameraSpec& a, const CameraSpec& b) {
    return a.location == b.location && a.direction == b.direction && a.up == b.up && a.right == b.right &&
           a.sky == b.sky && a.lookAt == b.lookAt && a.angle == b.angle && a.verticalAngle == b.verticalAngle &&
           a.aperture == b.aperture && a.focalPoint == b.focalPoint && a.focalDistance == b.focalDistance &&
           a.transform == b.transform && sameChain(a.motion, b.motion);
}

// Merges evaluations (sorted by time; the first is the frame's base) into one
// moving scene.
Scene mergeEvaluations(const std::vector<Evaluation>& evaluations, FrameReport& report) {
    Scene out = evaluations.front().scene;
    Merge merge{evaluations, report, {}};
    std::vector<std::map<Identity, size_t>> objectIndex, lightIndex;
    for (const Evaluation& e : evaluations) {
        objectIndex.push_back(indexByIdentity(objectIdentities(e.scene)));
        lightIndex.push_back(indexByIdentity(lightIdentities(e.scene)));
    }
    const std::vector<Identity> objectIds = objectIdentities(out);
    for (size_t i = 0; i < out.objects.size(); ++i) {
        Object& o = out.objects[i];
        std::optional<Motion> path = merge.objectPath(o, objectIds[i], objectIndex);
        if (!path) continue;
        o.transform = restPlacement(o.transform, o.motion);
        o.motion = {MotionStage{std::move(*path), Transform()}};
        ++report.objectsFromClock;
    }
    const std::vector<Identity> lightIds = lightIdentities(out);
    for (size_t i = 0; i < out.lights.size(); ++i) {
        Light& l = out.lights[i];
        std::vector<LightKey> keys;
        bool paired = true, changes = false;
        for (size_t j = 0; j < evaluations.size() && paired; ++j) {
            const auto found = lightIndex[j].find(lightIds[i]);
            if (found == lightIndex[j].end()) {
                paired = false;
                merge.notes.push_back(merge.where(l.loc) + ": a light absent at another clock value over the shutter");
                break;
            }
            const Light& other = evaluations[j].scene.lights[found->second];
            keys.push_back(lightPose(other, evaluations[j].time));
            changes = changes || !samePose(keys.back(), lightPose(l, evaluations[j].time));
        }
        if (!paired || !changes) continue;
        auto motion = std::make_shared<LightMotion>();
        motion->keys = std::move(keys);
        l.motion = std::move(motion);
        ++report.lightsFromClock;
    }
    bool cameraChanges = false;
    for (const Evaluation& e : evaluations) cameraChanges = cameraChanges || !sameCamera(e.scene.camera, out.camera);
    if (cameraChanges) {
        for (const Evaluation& e : evaluations) out.cameraKeys.push_back({e.time, e.scene.camera});
        report.cameraFromClock = true;
    }
    report.unpaired = merge.notes;
    return out;
}

} // namespace drt
