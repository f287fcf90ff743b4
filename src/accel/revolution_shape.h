// Ray crossings of surfaces of revolution (scene/revolution.h) in double
// precision, following POV-Ray's formulation:
//  - lathe: each spline segment is (r(s), y(s)), cubics in s on [0, 1]. With
//    t = (y(s) - oy) / dy the ray meets the segment where
//    (dy ox + dx Y)^2 + (dy oz + dz Y)^2 - dy^2 r(s)^2 = 0, Y = y(s) - oy: a
//    polynomial in s of degree 6 (cubic), 4 (quadratic) or 2 (linear). A
//    near-horizontal ray solves y(s) = oy and then the circle of radius r(s).
//    Each hit is polished by 2D Newton steps on (s, t).
//  - sor: per segment r^2 = A y^3 + B y^2 + C y + D over [y1, y2]; with
//    y = oy + t dy this is a cubic in t. Base and cap discs unless open.
#pragma once

#include "accel/shapes.h"
#include "scene/revolution.h"

#include <vector>

namespace drt::accel {

class RevolutionGeometry {
public:
    // Throws std::invalid_argument for too few points, non-finite points, a
    // Bezier lathe whose count is not a multiple of 4, or sor heights that do
    // not increase.
    explicit RevolutionGeometry(const Revolution& r);

    // Every crossing of the line o + t d, sorted by t, outward normals.
    void intersect(const Vec3& o, const Vec3& d, std::vector<Crossing>& out) const;
    bool inside(const Vec3& p) const;
    bool solid() const { return solid_; }
    void bounds(Vec3& lower, Vec3& upper) const;

private:
    struct Segment {
        double r[4], y[4]; // lathe: r(s) = sum r[i] s^i, y(s) likewise; sor: r^2(y) = sum r[i] y^i
        double yLow, yHigh; // height range
        double radiusMax;   // largest |r| on the segment
    };
    // Whether the line stays farther from the axis than the segment's
    // radius everywhere within the segment's height range (a bounding-cylinder test).
    static bool missesSegmentBound(const Segment& seg, const Vec3& o, const Vec3& d);
    void latheCrossings(const Vec3& o, const Vec3& d, std::vector<Crossing>& out) const;
    void sorCrossings(const Vec3& o, const Vec3& d, std::vector<Crossing>& out) const;
    void addLatheHit(const Segment& seg, double s, double t, const Vec3& o, const Vec3& d,
                     std::vector<Crossing>& out) const;
    bool acceptS(size_t index, double s) const;

    Revolution::Kind kind_;
    std::vector<Segment> segments_;
    bool solid_ = true;
    bool closedOutline_ = false; // lathe: the last segment ends where the first starts
    double orientation_ = 1;     // lathe: +1 when the outline runs counter-clockwise in (r, y)
    double radiusMax_ = 0, yMin_ = 0, yMax_ = 0;
    double baseRadius2_ = 0, capRadius2_ = 0; // sor discs
};

} // namespace drt::accel
