// Geometry questions a scene asks while it is read: POV-Ray's trace() and
// inside() need an object's surface at parse time. The front end declares what
// it needs here, below it; a layer that has the intersection code implements
// it (accel/geometry_query.h) and the loader passes it in, so the front end
// never includes the accelerator.
#pragma once

#include "core/vec.h"
#include "scene/scene.h"

#include <functional>
#include <memory>
#include <optional>

namespace drt {

struct SurfaceHit {
    Vec3 point;
    Vec3 normal; // unit, pointing out of the surface (not turned to face the ray)
};

// The object a question is about. `identity` is the same pointer for every
// question about the same object, which does not change while the pointer
// lives (the front end's declared value): what answering needs (an
// accelerator) may be built once and kept. A null identity: built anew.
// `make` gives the object placed in world space, when it is needed.
struct QueriedObject {
    std::shared_ptr<const void> identity;
    std::function<Object()> make;
};

class SceneGeometryQuery {
public:
    virtual ~SceneGeometryQuery() = default;
    // The first point of the object along the ray from `origin` in
    // `direction` (not necessarily unit length), or nothing.
    virtual std::optional<SurfaceHit> trace(const QueriedObject& object, const Vec3& origin,
                                            const Vec3& direction) = 0;
    // Whether `point` lies inside the object (POV-Ray's inside()).
    virtual bool inside(const QueriedObject& object, const Vec3& point) = 0;
};

} // namespace drt
