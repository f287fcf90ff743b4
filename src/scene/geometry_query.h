// Geometry questions a scene asks while it is read: POV-Ray's trace() and
// inside() need an object's surface at parse time. The front end declares what
// it needs here, below it; a layer that has the intersection code implements
// it (accel/geometry_query.h) and the loader passes it in, so the front end
// never includes the accelerator.
#pragma once

#include "core/vec.h"
#include "scene/scene.h"

#include <optional>

namespace drt {

struct SurfaceHit {
    Vec3 point;
    Vec3 normal; // unit, pointing out of the surface (not turned to face the ray)
};

class SceneGeometryQuery {
public:
    virtual ~SceneGeometryQuery() = default;
    // The first point of `object` (placed in world space) along the ray from
    // `origin` in `direction` (not necessarily unit length), or nothing.
    virtual std::optional<SurfaceHit> trace(const Object& object, const Vec3& origin, const Vec3& direction) = 0;
    // Whether `point` lies inside `object` (POV-Ray's inside()).
    virtual bool inside(const Object& object, const Vec3& point) = 0;
};

} // namespace drt
