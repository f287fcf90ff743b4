// POV-Ray's blob in the scene model: a sum of component fields and a threshold.
// A component at distance d from its centre point (sphere) or from its axis
// segment (cylinder, which therefore has hemispherical ends) contributes
// strength * (1 - (d/r)^2)^2 when d < r and nothing beyond. The surface is
// where the sum equals the threshold; inside is where it exceeds it, so
// negative strengths carve.
#pragma once

#include "core/transform.h"
#include "core/vec.h"

#include <vector>

namespace drt {

struct BlobComponent {
    enum class Kind { Sphere, Cylinder };
    Kind kind = Kind::Sphere;
    Vec3 center;          // Sphere: centre; Cylinder: one end of the axis
    Vec3 end;             // Cylinder: the other end
    double radius = 1;
    double strength = 1;
    Transform transform;  // component -> blob space (transforms inside the component)
    bool operator==(const BlobComponent&) const = default;
};

struct Blob {
    double threshold = 1; // POV-Ray's default
    std::vector<BlobComponent> components;
    bool sturm = false;     // POV-Ray's root-finder choice; kept for round trips only
    bool hierarchy = true;  // POV-Ray's bounding-hierarchy switch; kept for round trips only
    bool closedSolid() const { return true; }
    bool operator==(const Blob& o) const { return threshold == o.threshold && components == o.components; }
};

// Blob-space box around every component's region of influence (a ball or a
// capsule of the component's radius, carried through its transform); false
// when there is no component.
bool blobBounds(const Blob& blob, Vec3& lower, Vec3& upper);

} // namespace drt
