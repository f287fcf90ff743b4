// Analytic shapes prepared for ray intersection in object space, in double
// precision. Each shape reports every crossing of the whole line o + t d (not
// only t > 0), sorted by t, with the outward object-space normal; CSG walks
// these crossings to classify inside and outside, and single shapes keep the
// first one inside the ray's interval.
#pragma once

#include "accel/thread_scratch.h"
#include "core/vec.h"
#include "scene/scene.h"

#include <cmath>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace drt::accel {

struct Crossing {
    double t = 0;
    Vec3 normal; // object space, outward, not normalised
};

// A poly of order 35 (the largest) can cross a line 35 times.
inline constexpr int kMaxCrossings = 36;

struct PolynomialSurface; // algebraic_shapes.h

enum class ShapeKind { Sphere, Plane, Cone, Disc, Torus, Box, Polynomial, Superellipsoid, Extrusion,
                       Revolution, Blob, Isosurface, JuliaFractal };

class ExtrusionGeometry; // accel/extrusion_shape.h
class RevolutionGeometry; // accel/revolution_shape.h
class BlobGeometry; // accel/blob_shape.h
class IsosurfaceGeometry; // accel/isosurface_shape.h
class JuliaFractalGeometry; // accel/julia_fractal_shape.h

// A shape in the form its intersection routine wants. Cylinders are cones
// with equal radii; cones and cylinders are stored in a local frame whose z
// axis runs from base (z = 0) to cap (z = height).
struct AnalyticShape {
    ShapeKind kind = ShapeKind::Sphere;
    Vec3 center;           // Sphere, Disc; Cone: base point
    Vec3 normal{0, 1, 0};  // Plane, Disc: unit normal
    double radius = 1;     // Sphere, Disc; Torus: major radius
    double innerRadius = 0; // Disc: hole radius; Torus: minor radius
    double distance = 0;   // Plane
    Vec3 axisU, axisV, axisW; // Cone: orthonormal frame, W along the axis
    double height = 1;     // Cone
    double baseRadius = 1, capRadius = 1; // Cone
    bool open = false;     // Cone: no end caps
    Vec3 lower, upper;     // Box
    std::shared_ptr<const PolynomialSurface> polynomial; // Polynomial
    double exponentE = 1, exponentN = 1;                 // Superellipsoid
    std::shared_ptr<const ExtrusionGeometry> extrusion; // Extrusion
    std::shared_ptr<const RevolutionGeometry> revolution; // Revolution (lathe, sor)
    std::shared_ptr<const BlobGeometry> blob; // Blob
    std::shared_ptr<const IsosurfaceGeometry> isosurface; // Isosurface
    std::shared_ptr<const JuliaFractalGeometry> julia; // JuliaFractal
};

// Builds the analytic form of an analytic scene shape. Returns nothing for
// Mesh and Csg; throws std::invalid_argument with a message for degenerate
// input (zero radius, base == cap, zero normal, non-finite values).
std::optional<AnalyticShape> prepareShape(const Shape& shape);

// Every crossing of the line o + t d with the surface, sorted by t; returns
// the count (at most kMaxCrossings; an extrusion reports its first ones).
// d need not be unit length.
int intersectShape(const AnalyticShape& shape, const Vec3& o, const Vec3& d, Crossing out[kMaxCrossings]);

// All crossings, however many (extrusions and lathes may have more than kMaxCrossings):
// points to `fixed` or to `many`, and returns the count.
int allCrossings(const AnalyticShape& shape, const Vec3& o, const Vec3& d, Crossing fixed[kMaxCrossings],
                 std::vector<Crossing>& many, const Crossing*& first);

// Sphere: |o + t d - c|^2 = r^2. The discriminant is computed as
// a (r^2 - |f - (f.d / d.d) d|^2) with f = o - c, which stays accurate when the
// ray starts far away (Haines et al., Ray Tracing Gems ch. 7).
inline bool sphereRoots(const Vec3& center, double radius, const Vec3& o, const Vec3& d, double& t0, double& t1) {
    const Vec3 f = o - center;
    const double a = dot(d, d);
    const double b = dot(f, d);
    const Vec3 l = f - (b / a) * d;
    const double discriminant = a * (radius * radius - dot(l, l));
    if (discriminant < 0) return false;
    const double q = -b - std::copysign(std::sqrt(discriminant), b);
    const double c = dot(f, f) - radius * radius;
    t0 = q / a;
    t1 = q != 0 ? c / q : t0;
    return true;
}
inline bool sphereRoots(const AnalyticShape& s, const Vec3& o, const Vec3& d, double& t0, double& t1) {
    return sphereRoots(s.center, s.radius, o, d, t0, t1);
}

// firstCrossing of a sphere and of a plane, from the values they use (so a
// caller can hold them in registers across many rays).
inline bool firstSphereCrossing(const Vec3& center, double radius, const Vec3& o, const Vec3& d, double tMin,
                                double tMax, Crossing& out) {
    // The same roots, in the same order, as intersectSphere.
    double t0, t1;
    if (!sphereRoots(center, radius, o, d, t0, t1)) return false;
    if (std::isfinite(t0) && std::isfinite(t1) && t1 < t0) std::swap(t0, t1);
    for (const double t : {t0, t1})
        if (std::isfinite(t) && t > tMin && t < tMax) {
            out = {t, o + t * d - center};
            return true;
        }
    return false;
}
inline bool firstPlaneCrossing(const Vec3& normal, double distance, const Vec3& o, const Vec3& d, double tMin,
                               double tMax, Crossing& out) {
    const double dn = dot(normal, d);
    if (dn == 0) return false;
    const double t = (distance - dot(normal, o)) / dn;
    if (!(std::isfinite(t) && t > tMin && t < tMax)) return false;
    out = {t, normal};
    return true;
}

// firstCrossing for the shapes without a shortcut: the first listed crossing.
bool firstCrossingListed(const AnalyticShape& shape, const Vec3& o, const Vec3& d, double tMin, double tMax,
                         Crossing& out);

// The first crossing of the line o + t d with tMin < t < tMax: the same t
// and normal as intersectShape's entry, found without listing the others
// where the shape allows (spheres, planes). `out` is written only if found.
// Inline: every ray that reaches a sphere or a plane comes here.
inline bool firstCrossing(const AnalyticShape& s, const Vec3& o, const Vec3& d, double tMin, double tMax,
                          Crossing& out) {
    if (s.kind == ShapeKind::Sphere) return firstSphereCrossing(s.center, s.radius, o, d, tMin, tMax, out);
    if (s.kind == ShapeKind::Plane) return firstPlaneCrossing(s.normal, s.distance, o, d, tMin, tMax, out);
    return firstCrossingListed(s, o, d, tMin, tMax, out);
}

// Whether the shape encloses a volume (discs, open cones and open extrusions do not).
bool isSolidShape(const AnalyticShape& shape);

// Whether the object-space point p is strictly inside the shape (planes: the
// half-space below; discs and open cones have no inside).
bool insideShape(const AnalyticShape& shape, const Vec3& p);

// Object-space bounds; false when the shape is unbounded (planes, polynomials
// other than ellipsoids).
bool shapeBounds(const AnalyticShape& shape, Vec3& lower, Vec3& upper);

// Each installs its file's per-thread buffers for the calling thread
// (accel/thread_scratch.h; Accelerator::ThreadBuffers).
std::unique_ptr<InstalledScratch> installShapeScratch();     // shapes.cpp
std::unique_ptr<InstalledScratch> installAlgebraicScratch(); // algebraic_shapes.cpp
std::unique_ptr<InstalledScratch> installBlobScratch();      // blob_shape.cpp
std::unique_ptr<InstalledScratch> installJuliaScratch();     // julia_fractal_shape.cpp
std::unique_ptr<InstalledScratch> installCrossingScratch();  // crossings.cpp

} // namespace drt::accel
