// Ray crossings of POV-Ray's isosurface (scene/isosurface.h) in double
// precision. Along the ray, inside the container, g(t) = f(o + t d) - threshold
// is marched: from a point where |g| = v no root lies closer than
// v / (max_gradient |d|), so the march steps by that (never less than the
// accuracy), and a sign change between two steps is refined by bisection to
// a small fraction of the accuracy. Where the inside (g < 0) reaches the
// container and the isosurface is not `open`, the container's surface is a
// crossing too. Normals are the function's gradient by central differences.
#pragma once

#include "accel/shapes.h"
#include "scene/isosurface.h"

#include <vector>

namespace drt::accel {

class IsosurfaceGeometry {
public:
    // Throws std::invalid_argument for a missing function or one that does not
    // take 3 parameters, a non-positive max_gradient or accuracy, an empty
    // container or non-finite numbers.
    explicit IsosurfaceGeometry(const Isosurface& iso);

    // Crossings of the line o + t d with tMin < t < tMax, sorted by t, outward
    // normals; at most `limit` of them (the first ones).
    void intersect(const Vec3& o, const Vec3& d, double tMin, double tMax, size_t limit,
                   std::vector<Crossing>& out) const;
    bool inside(const Vec3& p) const { return insideContainer(p) && value(p) < 0; }
    void bounds(Vec3& lower, Vec3& upper) const { lower = lower_, upper = upper_; }
    bool solid() const { return !iso_.open; }

    double value(const Vec3& p) const { return iso_.function->at(p) - iso_.threshold; }
    Vec3 gradient(const Vec3& p) const;

private:
    bool insideContainer(const Vec3& p) const;
    // The part of the line inside the container: false when it misses.
    bool containerSpan(const Vec3& o, const Vec3& d, double& t0, double& t1, Vec3& n0, Vec3& n1) const;

    Isosurface iso_;
    Vec3 lower_, upper_;
    double step_ = 1e-5; // of the central differences
};

} // namespace drt::accel
