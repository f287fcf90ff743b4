// POV-Ray's isosurface in the scene model: the surface where a user-defined
// function (scene/function.h) of x, y, z equals the threshold, inside a
// container (a box or a sphere). Inside is where the function is below the
// threshold. Without `open` the container's surface closes the solid where
// the inside reaches it.
//
// max_gradient is the largest rate of change of the function along any line
// (a Lipschitz bound, per unit of object-space distance): the root finder
// (accel/isosurface_shape.h) steps by |f - threshold| / max_gradient, so a
// function steeper than that may lose parts of its surface, as in POV-Ray.
// accuracy is the object-space step below which a sign change is looked for
// at fixed steps.
#pragma once

#include "core/vec.h"
#include "scene/function.h"

#include <memory>

namespace drt {

struct Isosurface {
    std::shared_ptr<const Function> function; // of x, y, z
    enum class Container { Box, Sphere };
    Container container = Container::Box;
    Vec3 corner1{-1, -1, -1}, corner2{1, 1, 1}; // Box
    Vec3 center;                                 // Sphere
    double radius = 1;                           // Sphere
    double threshold = 0;
    double accuracy = 0.001;
    double maxGradient = 1.1;
    bool open = false;
    // Read and written back, not used: drt lists every crossing (CSG needs
    // them) and keeps max_gradient fixed.
    int maxTrace = 1;            // 0: all_intersections
    bool evaluate = false;
    Vec3 evaluateParams{0, 0, 0};

    bool bounds(Vec3& lower, Vec3& upper) const {
        if (container == Container::Box) {
            lower = min(corner1, corner2), upper = max(corner1, corner2);
        } else {
            lower = center - Vec3(radius), upper = center + Vec3(radius);
        }
        return true;
    }
    bool closedSolid() const { return !open; }
    bool operator==(const Isosurface& o) const {
        const bool sameFunction =
            function == o.function || (function && o.function && *function == *o.function);
        return sameFunction && container == o.container && corner1 == o.corner1 && corner2 == o.corner2 &&
               center == o.center && radius == o.radius && threshold == o.threshold && accuracy == o.accuracy &&
               maxGradient == o.maxGradient && open == o.open && maxTrace == o.maxTrace &&
               evaluate == o.evaluate && evaluateParams == o.evaluateParams;
    }
};

} // namespace drt
