// Ray crossings of POV-Ray's julia_fractal (scene/julia_fractal.h) in double
// precision, by POV-Ray 3.7's own march so the surfaces agree:
//   - the line is clipped to the bounding sphere (radius R about the origin);
//   - from each point the orbit is iterated; outside the set it yields a
//     distance estimate (quaternions: |q_n| log|q_n|^2 / (2^n |q_n'|) for sqr,
//     3^n for cube; hypercomplex: |q_n|^2 / (2 |n . d|) from the orbit's
//     normal n, used only between 1 and 30 times the smallest step), the march
//     steps by it but never by less than 1/precision;
//   - a step that changes inside/outside is bisected down to 1e-7, and the
//     crossing is the inside end of the final interval;
//   - the normal is the orbit's derivative applied to its last point (the
//     gradient of |q_n|^2 for quaternions), as POV-Ray computes it.
// Steps are in object-space distance along the unit direction.
#pragma once

#include "accel/shapes.h"
#include "scene/julia_fractal.h"

#include <vector>

namespace drt::accel {

class JuliaFractalGeometry {
public:
    // A 4-D number: x + y i + z j + w k.
    struct Quad {
        double x = 0, y = 0, z = 0, w = 0;
    };

    // Throws std::invalid_argument for non-finite numbers, max_iteration < 1,
    // precision < 1, a zero slice normal or one with no w part, or a
    // quaternion function other than sqr and cube.
    explicit JuliaFractalGeometry(const JuliaFractal& fractal);

    // Crossings of the line o + t d with tMin < t < tMax, sorted by t, outward
    // normals; at most `limit` of them (the first ones).
    void intersect(const Vec3& o, const Vec3& d, double tMin, double tMax, size_t limit,
                   std::vector<Crossing>& out) const;
    bool inside(const Vec3& p) const;
    void bounds(Vec3& lower, Vec3& upper) const { lower = Vec3(-radius_), upper = Vec3(radius_); }

    // The orbit of p: orbit[0] is p's 4-D number; returns whether it stays
    // within the exit value for every iteration. On escape, orbit holds the
    // numbers up to the last one within it and `escapedAt` the iteration that
    // left (else maxIteration + 1).
    bool iterate(const Vec3& p, std::vector<Quad>& orbit, int& escapedAt) const;
    // The orbit's normal after n iterations (orbit[0..n] used).
    Vec3 orbitNormal(const std::vector<Quad>& orbit, int n) const;

private:
    // The march's step from p along the unit direction (and whether p is inside).
    bool stepFrom(const Vec3& p, const Vec3& direction, double& step, std::vector<Quad>& orbit) const;
    Quad map(const Quad& q) const;  // a hypercomplex f(q), without c
    Quad next(const Quad& q) const; // the orbit's next number, f(q) + c

    JuliaFractal f_;
    double radius_ = 2, exitValue_ = 4, smallestStep_ = 0.05;
};

} // namespace drt::accel
