#include "accel/shapes.h"

#include "accel/algebraic_shapes.h"
#include "accel/extrusion_shape.h"
#include "accel/polynomial.h"
#include "accel/revolution_shape.h"
#include "accel/blob_shape.h"
#include "accel/isosurface_shape.h"
#include "accel/julia_fractal_shape.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace drt::accel {

namespace {

bool finite(double v) { return std::isfinite(v); }

void require(bool ok, const char* message) {
    if (!ok) throw std::invalid_argument(message);
}

struct CrossingList {
    Crossing* out;
    int count = 0;
    void add(double t, const Vec3& normal) {
        if (count < kMaxCrossings && std::isfinite(t)) out[count++] = {t, normal};
    }
    int sorted() {
        std::sort(out, out + count, [](const Crossing& a, const Crossing& b) { return a.t < b.t; });
        return count;
    }
};

int intersectSphere(const AnalyticShape& s, const Vec3& o, const Vec3& d, CrossingList& list) {
    double t0, t1;
    if (!sphereRoots(s, o, d, t0, t1)) return 0;
    list.add(t0, o + t0 * d - s.center);
    list.add(t1, o + t1 * d - s.center);
    return list.sorted();
}

int intersectPlane(const AnalyticShape& s, const Vec3& o, const Vec3& d, CrossingList& list) {
    const double dn = dot(s.normal, d);
    if (dn == 0) return 0;
    list.add((s.distance - dot(s.normal, o)) / dn, s.normal);
    return list.count;
}

// Cone in its local frame: x^2 + y^2 = (r0 + k z)^2 with k = (r1 - r0) / h and
// 0 <= z <= h; the gradient (x, y, -k (r0 + k z)) is the outward normal. Caps
// are the discs z = 0 (normal -W) and z = h (normal +W).
int intersectCone(const AnalyticShape& s, const Vec3& oWorld, const Vec3& dWorld, CrossingList& list) {
    const Vec3 rel = oWorld - s.center;
    const Vec3 o{dot(rel, s.axisU), dot(rel, s.axisV), dot(rel, s.axisW)};
    const Vec3 d{dot(dWorld, s.axisU), dot(dWorld, s.axisV), dot(dWorld, s.axisW)};
    const double k = (s.capRadius - s.baseRadius) / s.height;
    const double radiusAtOrigin = s.baseRadius + k * o.z;
    const double a = d.x * d.x + d.y * d.y - k * k * d.z * d.z;
    const double b = 2 * (o.x * d.x + o.y * d.y - k * d.z * radiusAtOrigin);
    const double c = o.x * o.x + o.y * o.y - radiusAtOrigin * radiusAtOrigin;
    double roots[2];
    const int n = (a == 0 && b == 0) ? 0 : solveQuadratic(a, b, c, roots);
    for (int i = 0; i < n; ++i) {
        if (n == 2 && i == 1 && a == 0) break; // linear case: one root reported twice
        const double t = roots[i];
        const Vec3 p = o + t * d;
        if (p.z < 0 || p.z > s.height) continue;
        const Vec3 local{p.x, p.y, -k * (s.baseRadius + k * p.z)};
        list.add(t, local.x * s.axisU + local.y * s.axisV + local.z * s.axisW);
    }
    if (!s.open && d.z != 0) {
        const double tBase = -o.z / d.z;
        const Vec3 pb = o + tBase * d;
        if (pb.x * pb.x + pb.y * pb.y <= s.baseRadius * s.baseRadius) list.add(tBase, -s.axisW);
        const double tCap = (s.height - o.z) / d.z;
        const Vec3 pc = o + tCap * d;
        if (pc.x * pc.x + pc.y * pc.y <= s.capRadius * s.capRadius) list.add(tCap, s.axisW);
    }
    return list.sorted();
}

int intersectDisc(const AnalyticShape& s, const Vec3& o, const Vec3& d, CrossingList& list) {
    const double dn = dot(s.normal, d);
    if (dn == 0) return 0;
    const double t = dot(s.center - o, s.normal) / dn;
    const Vec3 r = o + t * d - s.center;
    const double rho2 = dot(r, r);
    if (rho2 <= s.radius * s.radius && rho2 >= s.innerRadius * s.innerRadius) list.add(t, s.normal);
    return list.count;
}

// Torus around y with major radius R and minor radius r:
// (|p|^2 + R^2 - r^2)^2 = 4 R^2 (x^2 + z^2). The ray is first clipped to the
// bounding sphere of radius R + r and re-origined at its entry with a unit
// direction, so the quartic in s (distance from the entry) is well scaled:
// with e = |o|^2 + R^2 - r^2 and f = o.d,
//   s^4 + 4f s^3 + (4f^2 + 2e - 4R^2(dx^2+dz^2)) s^2
//     + (4fe - 8R^2(ox dx + oz dz)) s + e^2 - 4R^2(ox^2 + oz^2) = 0.
int intersectTorus(const AnalyticShape& s, const Vec3& oIn, const Vec3& dIn, CrossingList& list) {
    const double R = s.radius, r = s.innerRadius;
    const double scale = length(dIn);
    if (scale == 0) return 0;
    const Vec3 d = dIn / scale;
    AnalyticShape bound;
    bound.radius = (R + r) * 1.001;
    Crossing chord[kMaxCrossings];
    CrossingList chordList{chord};
    if (intersectSphere(bound, oIn, d, chordList) < 2) return 0;
    const double start = chord[0].t, span = chord[1].t - chord[0].t;
    const Vec3 o = oIn + start * d;
    const double e = dot(o, o) + R * R - r * r;
    const double f = dot(o, d);
    const double coefficients[5] = {
        e * e - 4 * R * R * (o.x * o.x + o.z * o.z),
        4 * f * e - 8 * R * R * (o.x * d.x + o.z * d.z),
        4 * f * f + 2 * e - 4 * R * R * (d.x * d.x + d.z * d.z),
        4 * f,
        1,
    };
    double roots[5];
    const int n = polynomialRootsInInterval(coefficients, 4, 0, span, roots);
    for (int i = 0; i < n; ++i) {
        const Vec3 p = o + roots[i] * d;
        // Outward normal: from the nearest point of the core circle to p.
        const double ring = std::sqrt(p.x * p.x + p.z * p.z);
        const Vec3 core = ring > 0 ? Vec3{p.x * R / ring, 0, p.z * R / ring} : Vec3{};
        list.add((start + roots[i]) / scale, p - core);
    }
    return list.sorted();
}

// Slabs: the line is inside [lower, upper] for t in [tNear, tFar].
int intersectBox(const AnalyticShape& s, const Vec3& o, const Vec3& d, CrossingList& list) {
    double tNear = -INFINITY, tFar = INFINITY;
    int nearAxis = -1, farAxis = -1;
    double nearSign = 0, farSign = 0;
    for (int axis = 0; axis < 3; ++axis) {
        if (d[axis] == 0) {
            if (o[axis] < s.lower[axis] || o[axis] > s.upper[axis]) return 0;
            continue;
        }
        double t0 = (s.lower[axis] - o[axis]) / d[axis];
        double t1 = (s.upper[axis] - o[axis]) / d[axis];
        double sign0 = -1, sign1 = 1; // outward normal of the lower and upper faces
        if (t0 > t1) {
            std::swap(t0, t1);
            std::swap(sign0, sign1);
        }
        if (t0 > tNear) { tNear = t0; nearAxis = axis; nearSign = sign0; }
        if (t1 < tFar) { tFar = t1; farAxis = axis; farSign = sign1; }
    }
    if (nearAxis < 0 || farAxis < 0 || tNear > tFar) return 0;
    Vec3 nNear, nFar;
    nNear[nearAxis] = nearSign;
    nFar[farAxis] = farSign;
    list.add(tNear, nNear);
    list.add(tFar, nFar);
    return list.count;
}

} // namespace

std::optional<AnalyticShape> prepareShape(const Shape& shape) {
    AnalyticShape s;
    if (const auto* sphere = std::get_if<Sphere>(&shape)) {
        require(isFinite(sphere->center) && finite(sphere->radius) && sphere->radius > 0,
                "sphere needs a finite centre and a positive radius");
        s.kind = ShapeKind::Sphere;
        s.center = sphere->center;
        s.radius = sphere->radius;
    } else if (const auto* plane = std::get_if<Plane>(&shape)) {
        const double len = length(plane->normal);
        require(finite(len) && len > 0 && finite(plane->distance), "plane needs a non-zero finite normal");
        // dot(normal, p) = distance with the normal as given (scene.h); dividing
        // both by |normal| keeps the same set of points.
        s.kind = ShapeKind::Plane;
        s.normal = plane->normal / len;
        s.distance = plane->distance / len;
    } else if (const auto* cylinder = std::get_if<Cylinder>(&shape)) {
        s.kind = ShapeKind::Cone;
        s.center = cylinder->base;
        const Vec3 axis = cylinder->cap - cylinder->base;
        s.height = length(axis);
        require(finite(s.height) && s.height > 0 && finite(cylinder->radius) && cylinder->radius > 0,
                "cylinder needs distinct finite end points and a positive radius");
        s.axisW = axis / s.height;
        orthonormalBasis(s.axisW, s.axisU, s.axisV);
        s.baseRadius = s.capRadius = cylinder->radius;
        s.open = cylinder->open;
    } else if (const auto* cone = std::get_if<Cone>(&shape)) {
        s.kind = ShapeKind::Cone;
        s.center = cone->base;
        const Vec3 axis = cone->cap - cone->base;
        s.height = length(axis);
        require(finite(s.height) && s.height > 0, "cone needs distinct finite end points");
        require(finite(cone->baseRadius) && finite(cone->capRadius) && cone->baseRadius >= 0 &&
                    cone->capRadius >= 0 && cone->baseRadius + cone->capRadius > 0,
                "cone radii must be non-negative and not both zero");
        s.axisW = axis / s.height;
        orthonormalBasis(s.axisW, s.axisU, s.axisV);
        s.baseRadius = cone->baseRadius;
        s.capRadius = cone->capRadius;
        s.open = cone->open;
    } else if (const auto* disc = std::get_if<Disc>(&shape)) {
        const double len = length(disc->normal);
        require(finite(len) && len > 0 && isFinite(disc->center), "disc needs a non-zero finite normal");
        require(finite(disc->radius) && disc->radius > 0 && disc->holeRadius >= 0,
                "disc needs a positive radius and a non-negative hole radius");
        s.kind = ShapeKind::Disc;
        s.center = disc->center;
        s.normal = disc->normal / len;
        s.radius = disc->radius;
        s.innerRadius = disc->holeRadius;
    } else if (const auto* torus = std::get_if<Torus>(&shape)) {
        require(finite(torus->majorRadius) && finite(torus->minorRadius) && torus->majorRadius > 0 &&
                    torus->minorRadius > 0,
                "torus needs positive radii");
        s.kind = ShapeKind::Torus;
        s.radius = torus->majorRadius;
        s.innerRadius = torus->minorRadius;
    } else if (const auto* box = std::get_if<Box>(&shape)) {
        require(isFinite(box->corner1) && isFinite(box->corner2), "box corners must be finite");
        s.kind = ShapeKind::Box;
        s.lower = min(box->corner1, box->corner2);
        s.upper = max(box->corner1, box->corner2);
    } else if (const auto* algebraic = std::get_if<Algebraic>(&shape)) {
        s.kind = ShapeKind::Polynomial;
        s.polynomial = std::make_shared<const PolynomialSurface>(preparePolynomial(*algebraic));
    } else if (const auto* super = std::get_if<Superellipsoid>(&shape)) {
        require(finite(super->e) && finite(super->n) && super->e > 0 && super->n > 0,
                "superellipsoid needs positive finite exponents");
        s.kind = ShapeKind::Superellipsoid;
        s.exponentE = super->e;
        s.exponentN = super->n;
    } else if (const auto* extrusion = std::get_if<Extrusion>(&shape)) {
        s.kind = ShapeKind::Extrusion;
        s.extrusion = std::make_shared<const ExtrusionGeometry>(*extrusion);
    } else if (const auto* revolution = std::get_if<Revolution>(&shape)) {
        s.kind = ShapeKind::Revolution;
        s.revolution = std::make_shared<const RevolutionGeometry>(*revolution);
    } else if (const auto* blob = std::get_if<Blob>(&shape)) {
        s.kind = ShapeKind::Blob;
        s.blob = std::make_shared<const BlobGeometry>(*blob);
    } else if (const auto* iso = std::get_if<Isosurface>(&shape)) {
        s.kind = ShapeKind::Isosurface;
        s.isosurface = std::make_shared<const IsosurfaceGeometry>(*iso);
    } else if (const auto* julia = std::get_if<JuliaFractal>(&shape)) {
        s.kind = ShapeKind::JuliaFractal;
        s.julia = std::make_shared<const JuliaFractalGeometry>(*julia);
    } else {
        return std::nullopt;
    }
    return s;
}

namespace {

// The crossings of the shapes listed by their own code, one buffer per use,
// kept per thread (no allocation per ray once warm: accel/thread_scratch.h).
struct ShapeScratch {
    std::vector<Crossing> extrusion, revolution, blob, isosurface, julia, firstListed;
};
ShapeScratch& shapeScratch() { return ThreadScratch<ShapeScratch>::get(); }

} // namespace

std::unique_ptr<InstalledScratch> installShapeScratch() { return ThreadScratch<ShapeScratch>::install(); }

int intersectShape(const AnalyticShape& s, const Vec3& o, const Vec3& d, Crossing out[kMaxCrossings]) {
    CrossingList list{out};
    switch (s.kind) {
    case ShapeKind::Sphere: return intersectSphere(s, o, d, list);
    case ShapeKind::Plane: return intersectPlane(s, o, d, list);
    case ShapeKind::Cone: return intersectCone(s, o, d, list);
    case ShapeKind::Disc: return intersectDisc(s, o, d, list);
    case ShapeKind::Torus: return intersectTorus(s, o, d, list);
    case ShapeKind::Box: return intersectBox(s, o, d, list);
    case ShapeKind::Polynomial: return intersectPolynomial(*s.polynomial, o, d, out, kMaxCrossings);
    case ShapeKind::Superellipsoid: return intersectSuperellipsoid(s.exponentE, s.exponentN, o, d, out, kMaxCrossings);
    case ShapeKind::Extrusion: {
        std::vector<Crossing>& many = shapeScratch().extrusion;
        s.extrusion->intersect(o, d, many);
        for (const Crossing& c : many) list.add(c.t, c.normal);
        return list.count;
    }
    case ShapeKind::Revolution: {
        std::vector<Crossing>& many = shapeScratch().revolution;
        s.revolution->intersect(o, d, many);
        for (const Crossing& c : many) list.add(c.t, c.normal);
        return list.count;
    }
    case ShapeKind::Blob: {
        std::vector<Crossing>& many = shapeScratch().blob;
        s.blob->intersect(o, d, many);
        for (const Crossing& c : many) list.add(c.t, c.normal);
        return list.count;
    }
    case ShapeKind::Isosurface: {
        std::vector<Crossing>& many = shapeScratch().isosurface;
        s.isosurface->intersect(o, d, -INFINITY, INFINITY, kMaxCrossings, many);
        for (const Crossing& c : many) list.add(c.t, c.normal);
        return list.count;
    }
    case ShapeKind::JuliaFractal: {
        std::vector<Crossing>& many = shapeScratch().julia;
        s.julia->intersect(o, d, -INFINITY, INFINITY, kMaxCrossings, many);
        for (const Crossing& c : many) list.add(c.t, c.normal);
        return list.count;
    }
    }
    return 0;
}

int allCrossings(const AnalyticShape& s, const Vec3& o, const Vec3& d, Crossing fixed[kMaxCrossings],
                 std::vector<Crossing>& many, const Crossing*& first) {
    if (s.kind == ShapeKind::Extrusion) {
        s.extrusion->intersect(o, d, many);
        first = many.data();
        return static_cast<int>(many.size());
    }
    if (s.kind == ShapeKind::Revolution) {
        s.revolution->intersect(o, d, many);
        first = many.data();
        return static_cast<int>(many.size());
    }
    if (s.kind == ShapeKind::Blob) {
        s.blob->intersect(o, d, many);
        first = many.data();
        return static_cast<int>(many.size());
    }
    if (s.kind == ShapeKind::Isosurface) {
        s.isosurface->intersect(o, d, -INFINITY, INFINITY, SIZE_MAX, many);
        first = many.data();
        return static_cast<int>(many.size());
    }
    if (s.kind == ShapeKind::JuliaFractal) {
        s.julia->intersect(o, d, -INFINITY, INFINITY, SIZE_MAX, many);
        first = many.data();
        return static_cast<int>(many.size());
    }
    first = fixed;
    return intersectShape(s, o, d, fixed);
}

bool firstCrossingListed(const AnalyticShape& s, const Vec3& o, const Vec3& d, double tMin, double tMax,
                         Crossing& out) {
    // Not zero-initialised per call: kMaxCrossings entries are a kilobyte.
    thread_local Crossing fixed[kMaxCrossings];
    std::vector<Crossing>& many = shapeScratch().firstListed;
    if (s.kind == ShapeKind::Isosurface) { // marches only as far as the first crossing
        s.isosurface->intersect(o, d, tMin, tMax, 1, many);
        if (many.empty()) return false;
        out = many.front();
        return true;
    }
    if (s.kind == ShapeKind::JuliaFractal) { // the same: marches only as far as the first crossing
        s.julia->intersect(o, d, tMin, tMax, 1, many);
        if (many.empty()) return false;
        out = many.front();
        return true;
    }
    const Crossing* c = nullptr;
    const int n = allCrossings(s, o, d, fixed, many, c);
    for (int i = 0; i < n; ++i)
        if (c[i].t > tMin && c[i].t < tMax) {
            out = c[i];
            return true;
        }
    return false;
}

bool isSolidShape(const AnalyticShape& s) {
    switch (s.kind) {
    case ShapeKind::Disc: return false;
    case ShapeKind::Cone: return !s.open;
    case ShapeKind::Extrusion: return s.extrusion->solid();
    case ShapeKind::Revolution: return s.revolution->solid();
    case ShapeKind::Isosurface: return s.isosurface->solid();
    default: return true;
    }
}

bool insideShape(const AnalyticShape& s, const Vec3& p) {
    switch (s.kind) {
    case ShapeKind::Sphere: return dot(p - s.center, p - s.center) < s.radius * s.radius;
    case ShapeKind::Plane: return dot(s.normal, p) < s.distance;
    case ShapeKind::Cone: {
        if (s.open) return false;
        const Vec3 rel = p - s.center;
        const double z = dot(rel, s.axisW);
        if (z <= 0 || z >= s.height) return false;
        const double x = dot(rel, s.axisU), y = dot(rel, s.axisV);
        const double radius = s.baseRadius + (s.capRadius - s.baseRadius) * z / s.height;
        return x * x + y * y < radius * radius;
    }
    case ShapeKind::Disc: return false;
    case ShapeKind::Torus: {
        const double ring = std::sqrt(p.x * p.x + p.z * p.z) - s.radius;
        return ring * ring + p.y * p.y < s.innerRadius * s.innerRadius;
    }
    case ShapeKind::Box:
        return p.x > s.lower.x && p.y > s.lower.y && p.z > s.lower.z && p.x < s.upper.x && p.y < s.upper.y &&
               p.z < s.upper.z;
    case ShapeKind::Polynomial: return insidePolynomial(*s.polynomial, p);
    case ShapeKind::Superellipsoid: return superellipsoidFunction(s.exponentE, s.exponentN, p) < 0;
    case ShapeKind::Extrusion: return s.extrusion->inside(p);
    case ShapeKind::Revolution: return s.revolution->inside(p);
    case ShapeKind::Blob: return s.blob->inside(p);
    case ShapeKind::Isosurface: return s.isosurface->inside(p);
    case ShapeKind::JuliaFractal: return s.julia->inside(p);
    }
    return false;
}

bool shapeBounds(const AnalyticShape& s, Vec3& lower, Vec3& upper) {
    switch (s.kind) {
    case ShapeKind::Sphere:
        lower = s.center - Vec3(s.radius);
        upper = s.center + Vec3(s.radius);
        return true;
    case ShapeKind::Plane: return false;
    case ShapeKind::Cone: {
        // Each end disc of radius r around centre c with unit normal w spans
        // c_i +- r sqrt(1 - w_i^2) along axis i.
        const Vec3 top = s.center + s.height * s.axisW;
        Vec3 extent;
        for (int i = 0; i < 3; ++i) extent[i] = std::sqrt(std::fmax(0.0, 1 - s.axisW[i] * s.axisW[i]));
        lower = min(s.center - s.baseRadius * extent, top - s.capRadius * extent);
        upper = max(s.center + s.baseRadius * extent, top + s.capRadius * extent);
        return true;
    }
    case ShapeKind::Disc: {
        Vec3 extent;
        for (int i = 0; i < 3; ++i) extent[i] = s.radius * std::sqrt(std::fmax(0.0, 1 - s.normal[i] * s.normal[i]));
        lower = s.center - extent;
        upper = s.center + extent;
        return true;
    }
    case ShapeKind::Torus: {
        const double outer = s.radius + s.innerRadius;
        lower = {-outer, -s.innerRadius, -outer};
        upper = {outer, s.innerRadius, outer};
        return true;
    }
    case ShapeKind::Box:
        lower = s.lower;
        upper = s.upper;
        return true;
    case ShapeKind::Polynomial:
        lower = s.polynomial->lower;
        upper = s.polynomial->upper;
        return s.polynomial->bounded;
    case ShapeKind::Superellipsoid:
        lower = Vec3(-1);
        upper = Vec3(1);
        return true;
    case ShapeKind::Extrusion: s.extrusion->bounds(lower, upper); return true;
    case ShapeKind::Revolution: s.revolution->bounds(lower, upper); return true;
    case ShapeKind::Blob: s.blob->bounds(lower, upper); return true;
    case ShapeKind::Isosurface: s.isosurface->bounds(lower, upper); return true;
    case ShapeKind::JuliaFractal: s.julia->bounds(lower, upper); return true;
    }
    return false;
}

} // namespace drt::accel
