// Scene warnings (render/scene_warnings.h).
#include "render/scene_warnings.h"

#include "accel/accel.h"
#include "core/error.h"
#include "render/camera.h"
#include "scene/bounds.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <type_traits>

namespace drt {

namespace {

// Whether the object is a closed surface around a solid inside, so that a
// ray leaving it proves that it started inside: each shape says so itself
// (closedSolid(), scene/scene.h). Hollow objects are meant to be entered;
// inverse and clipped ones have no dependable inside.
bool isClosedSolid(const Object& object) {
    if (object.hollow || object.inverse || !object.clippedBy.empty())
        return false;
    return std::visit(
        [](const auto& shape) {
            using T = std::decay_t<decltype(shape)>;
            if constexpr (std::is_same_v<T, Csg>) {
                for (const Object& child : shape.children)
                    if (!isClosedSolid(child))
                        return false;
                return !shape.children.empty();
            } else
                return shape.closedSolid();
        },
        object.shape);
}

// Whether the object's bounds hold the point (a moving object's are not
// known here: it may).
bool mayHold(const Object& object, const Vec3& point) {
    if (!object.motion.empty())
        return true;
    Vec3 lower, upper;
    if (!objectBounds(object, lower, upper))
        return true;
    const double margin = 1e-9 * std::max({1.0, std::fabs(point.x), std::fabs(point.y), std::fabs(point.z)});
    return point.x >= lower.x - margin && point.x <= upper.x + margin && point.y >= lower.y - margin &&
           point.y <= upper.y + margin && point.z >= lower.z - margin && point.z <= upper.z + margin;
}

// The closed object the point lies in, if any. From outside every closed
// surface, the first crossing along any ray enters; a ray whose first crossing
// leaves an object started inside it. Fourteen directions (axes and
// diagonals, slightly skewed off edges and seams); two that leave the same
// object, and none that enters it, decide.
const Object* enclosingObject(const Scene& closed, const Vec3& point, double time) {
    const Accelerator accelerator(closed, time);
    std::map<const Object*, int> exits, entries;
    for (int i = 0; i < 14; ++i) {
        Vec3 d;
        if (i < 6) {
            d = Vec3{0, 0, 0};
            (i / 2 == 0 ? d.x : i / 2 == 1 ? d.y : d.z) = i % 2 ? -1 : 1;
        } else {
            d = Vec3{(i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0};
        }
        d = normalize(d + Vec3{0.0123, 0.0217, 0.0071});
        Ray ray;
        ray.origin = point;
        ray.direction = d;
        ray.time = time;
        Hit hit;
        if (!accelerator.intersect(ray, hit) || !hit.object)
            continue;
        (dot(hit.geometricNormal, d) > 0 ? exits : entries)[hit.object]++;
    }
    for (const auto& [object, count] : exits)
        if (count >= 2 && !entries.count(object))
            return object;
    return nullptr;
}

} // namespace

void warnAboutScene(const Scene& scene, const std::string& scenePath, Diagnostics& diagnostics) {
    if (!scene.camera.loc.valid())
        diagnostics.warning({}, fmt::format("{} has no camera: the default one at the origin looking along +z is used",
                                            scenePath));
    if (scene.lights.empty())
        diagnostics.warning({}, fmt::format("{} has no light_source: only ambient light and emission show", scenePath));

    const int width = scene.render.width.value_or(320), height = scene.render.height.value_or(240);
    const ResolvedCamera camera = resolveCamera(scene.camera, width, height);
    // Only objects whose bounds hold the camera can hold it; leaving the others
    // out changes no answer (a ray's first crossing of an object the camera is
    // outside is an entry, whatever else is there) and keeps `drt check` of a
    // large scene from copying it and building its accelerator.
    Scene closed;
    for (const Object& object : scene.objects)
        if (isClosedSolid(object) && mayHold(object, camera.location))
            closed.objects.push_back(object);
    if (closed.objects.empty())
        return;
    try {
        if (const Object* inside = enclosingObject(closed, camera.location, scene.camera.shutterOpen))
            diagnostics.warning(inside->loc.valid() ? inside->loc : scene.camera.loc,
                                fmt::format("the camera at <{:g}, {:g}, {:g}> is inside this object: the picture shows "
                                            "it from inside (make it `hollow` if that is meant)",
                                            camera.location.x, camera.location.y, camera.location.z));
    } catch (const RenderError&) {
        // A scene the accelerator cannot build fails later with its own message.
    }
}

} // namespace drt
