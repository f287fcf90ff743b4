#include "scene/bounds.h"

#include <algorithm>
#include <cmath>
#include <concepts>

namespace drt {

namespace {

struct Box3 {
    Vec3 lower, upper;
    bool bounded = false;
};

Box3 unbounded() { return {Vec3(-kUnboundedExtent), Vec3(kUnboundedExtent), false}; }

Box3 box(const Vec3& a, const Vec3& b) { return {min(a, b), max(a, b), true}; }

// Object-space bounds of an extrusion (conic sweeps scale the outline by the height).
Box3 extrusionBox(const Extrusion& e) {
    Vec2 lo{1e300, 1e300}, hi{-1e300, -1e300};
    for (const auto& contour : e.contours)
        for (const Vec2& p : contour) lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)}, hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    if (e.text) lo = e.text->boxLower, hi = e.text->boxUpper; // POV-Ray's glyph boxes
    const double h1 = std::min(e.height1, e.height2), h2 = std::max(e.height1, e.height2);
    if (e.conic) {
        const double s = std::max(std::fabs(h1), std::fabs(h2));
        const double r = s * std::max({std::fabs(lo.x), std::fabs(lo.y), std::fabs(hi.x), std::fabs(hi.y)});
        lo = {-r, -r}, hi = {r, r};
    }
    if (lo.x > hi.x) return unbounded(); // no outline
    return box(e.plane == Extrusion::Plane::XZ ? Vec3{lo.x, h1, lo.y} : Vec3{lo.x, lo.y, h1},
               e.plane == Extrusion::Plane::XZ ? Vec3{hi.x, h2, hi.y} : Vec3{hi.x, hi.y, h2});
}

// Object-space bounds from the points (for min_extent / max_extent): the
// control hull holds linear and Bezier outlines; quadratic and cubic splines
// and sor profiles may overshoot it, so theirs is widened by a quarter of its
// size (conservative, not tight).
Box3 revolutionBox(const Revolution& r) {
    double rmax = 0, ylo = 1e300, yhi = -1e300;
    const auto& P = r.points;
    const size_t first = r.kind == Revolution::Kind::Sor ? 1 : 0;
    const size_t last = r.kind == Revolution::Kind::Sor ? P.size() - 2 : P.size() - 1;
    for (size_t i = 0; i < P.size(); ++i) {
        if (i < first || i > last) continue;
        ylo = std::min(ylo, P[i].y), yhi = std::max(yhi, P[i].y);
    }
    for (const Vec2& p : P) rmax = std::max(rmax, std::fabs(p.x));
    const bool overshoots = r.kind == Revolution::Kind::Sor || r.spline == Revolution::Spline::Quadratic ||
                            r.spline == Revolution::Spline::Cubic;
    if (overshoots) {
        if (r.kind == Revolution::Kind::Lathe)
            for (const Vec2& p : P) ylo = std::min(ylo, p.y), yhi = std::max(yhi, p.y);
        const double span = std::max(rmax, yhi - ylo);
        rmax += 0.25 * span;
        if (r.kind == Revolution::Kind::Lathe) ylo -= 0.25 * span, yhi += 0.25 * span;
    }
    if (!(ylo <= yhi)) return unbounded();
    return box({-rmax, ylo, -rmax}, {rmax, yhi, rmax});
}

// Object-space boxes of every shape and no catch-all: a shape added to Shape
// does not compile until it says how it is bounded, by its own bounds() (the
// simple shapes, scene/scene.h) or by an overload here.
struct ShapeBox {
    template <class S>
        requires requires(const S& s, Vec3& v) {
            { s.bounds(v, v) } -> std::same_as<bool>;
        }
    Box3 operator()(const S& s) const {
        Vec3 lower, upper;
        return s.bounds(lower, upper) ? box(lower, upper) : unbounded();
    }
    Box3 operator()(const Mesh& m) const {
        if (m.indexed) {
            Box3 b;
            b.bounded = indexedMeshBounds(*m.indexed, b.lower, b.upper);
            return b.bounded ? b : unbounded();
        }
        if (m.vertices.empty()) return unbounded();
        Box3 b{m.vertices.front(), m.vertices.front(), true};
        for (const Vec3& v : m.vertices) b.lower = min(b.lower, v), b.upper = max(b.upper, v);
        return b;
    }
    Box3 operator()(const Csg& csg) const {
        Box3 result = unbounded();
        bool first = true;
        for (const Object& member : csg.children) {
            Box3 b;
            b.bounded = objectBounds(member, b.lower, b.upper);
            if (csg.op == Csg::Op::Union || csg.op == Csg::Op::Merge) {
                if (!b.bounded) return unbounded();
                result = first ? b : Box3{min(result.lower, b.lower), max(result.upper, b.upper), true};
            } else if (csg.op == Csg::Op::Intersection || first) {
                // An unbounded member leaves the others' overlap as it is.
                if (b.bounded)
                    result = result.bounded ? Box3{max(result.lower, b.lower), min(result.upper, b.upper), true} : b;
            }
            first = false;
        }
        if (result.bounded) result.upper = max(result.upper, result.lower); // empty overlap: a point
        return result;
    }
    Box3 operator()(const Extrusion& e) const { return extrusionBox(e); }
    Box3 operator()(const Revolution& r) const { return revolutionBox(r); }
    Box3 operator()(const Blob& b) const {
        Box3 result;
        result.bounded = blobBounds(b, result.lower, result.upper);
        return result.bounded ? result : box(Vec3(0), Vec3(0)); // no component: nothing to bound
    }
};

} // namespace

bool objectBounds(const Object& object, Vec3& lower, Vec3& upper) {
    Box3 b = object.inverse ? unbounded() : std::visit(ShapeBox{}, object.shape);
    if (b.bounded) {
        // The eight corners through the transform.
        Box3 out{Vec3(INFINITY), Vec3(-INFINITY), true};
        for (int c = 0; c < 8; ++c) {
            const Vec3 p = object.transform.point(
                {(c & 1) ? b.upper.x : b.lower.x, (c & 2) ? b.upper.y : b.lower.y, (c & 4) ? b.upper.z : b.lower.z});
            out.lower = min(out.lower, p);
            out.upper = max(out.upper, p);
        }
        b = out;
        if (!(maxComponent(abs(b.lower)) < kUnboundedExtent && maxComponent(abs(b.upper)) < kUnboundedExtent))
            b = unbounded();
    }
    // Clips live in the same space as the transformed object.
    for (const Object& clip : object.clippedBy) {
        Vec3 lo, hi;
        if (!objectBounds(clip, lo, hi)) continue;
        b = b.bounded ? Box3{max(b.lower, lo), min(b.upper, hi), true} : Box3{lo, hi, true};
        b.upper = max(b.upper, b.lower);
    }
    lower = b.lower;
    upper = b.upper;
    return b.bounded;
}

} // namespace drt
