// Sampling routines ("warps"): maps from uniform values u in [0, 1)^2 to points
// or directions, each with its density. Directions are unit vectors; a local
// frame has z as its axis. Every routine here is chi-square tested
// (tests/statistical/chi2_test.cpp).
#pragma once

#include "core/vec.h"

namespace drt {

// ---------------------------------------------------------------- discs
// Shirley & Chiu (1997), "A low distortion map between disk and square": maps
// concentric squares to concentric circles, keeping strata compact. Unit disc;
// density 1/pi with respect to area.
Vec2 squareToConcentricDisc(Vec2 u);
// Polar map r = sqrt(u1), phi = 2 pi u2. Unit disc; density 1/pi.
Vec2 squareToUniformDiscPolar(Vec2 u);
inline constexpr double uniformDiscPdf() { return 1.0 / kPi; }

// ---------------------------------------------------------------- spheres
// Uniform on the unit sphere: z = 1 - 2 u1, phi = 2 pi u2; density 1/(4 pi) sr^-1.
Vec3 squareToUniformSphere(Vec2 u);
inline constexpr double uniformSpherePdf() { return 1.0 / (4.0 * kPi); }
// Uniform on the hemisphere z >= 0: z = u1; density 1/(2 pi).
Vec3 squareToUniformHemisphere(Vec2 u);
inline constexpr double uniformHemispherePdf() { return 1.0 / (2.0 * kPi); }
// Cosine-weighted hemisphere about z (Malley's method: a concentric disc point
// lifted to the hemisphere); density cos(theta) / pi.
Vec3 squareToCosineHemisphere(Vec2 u);
inline double cosineHemispherePdf(double cosTheta) { return cosTheta > 0 ? cosTheta / kPi : 0.0; }
// The same about an arbitrary unit axis (world space), e.g. a surface normal for
// diffuse interreflection; density cos(theta) / pi with theta from the axis.
Vec3 sampleCosineAround(const Vec3& axis, Vec2 u);

// ---------------------------------------------------------------- Phong lobe
// Density proportional to cos^n(theta) about z on the hemisphere around the
// axis: p = (n + 1) / (2 pi) cos^n(theta). Inverting the CDF of cos(theta),
// 1 - cos^{n+1}(theta), gives cos(theta) = (1 - u1)^{1/(n+1)}. n >= 0.
Vec3 squareToPhongLobe(Vec2 u, double exponent);
double phongLobePdf(double cosTheta, double exponent);
// The same lobe about an arbitrary unit axis (world space), e.g. the mirror or
// refracted direction for glossy reflection and translucency. Directions that
// fall below a surface must be given weight zero by the caller.
Vec3 sampleLobeAround(const Vec3& axis, double exponent, Vec2 u);
double lobeAroundPdf(const Vec3& axis, double exponent, const Vec3& direction);

// ---------------------------------------------------------------- area lights
// Uniform point on the parallelogram corner + s edge1 + t edge2, (s, t) = u;
// density 1 / |edge1 x edge2| with respect to area.
Vec3 sampleParallelogram(const Vec3& corner, const Vec3& edge1, const Vec3& edge2, Vec2 u);
double parallelogramPdf(const Vec3& edge1, const Vec3& edge2);

// Solid-angle sampling of a rectangle seen from a point (Urena, Fajardo & King
// 2013, "An Area-Preserving Parametrization for Spherical Rectangles"): the
// sampled points are uniform in the solid angle the rectangle subtends, density
// 1 / solidAngle() per steradian. Requires perpendicular edges; a point in the
// rectangle's plane sees zero solid angle (valid() is false: sample by area).
class SphericalRectangle {
public:
    SphericalRectangle(const Vec3& origin, const Vec3& corner, const Vec3& edge1, const Vec3& edge2);
    bool valid() const { return solidAngle_ > 0; }
    double solidAngle() const { return solidAngle_; }
    double pdf() const { return valid() ? 1.0 / solidAngle_ : 0.0; }
    // A point on the rectangle (world space).
    Vec3 sample(Vec2 u) const;

private:
    Vec3 origin_, x_, y_, z_;    // local frame: x along edge1, y along edge2, z toward the rectangle
    double x0_, x1_, y0_, y1_, z0_; // the rectangle in the local frame: [x0, x1] x [y0, y1] at height z0 (<= 0)
    double b0_, b1_, k_;          // from the spherical quad's edge normals and angles
    double solidAngle_ = 0;
};

// Area-to-solid-angle conversion: density per steradian of a point sampled with
// density pdfArea on a surface with unit normal `normal`, seen from `from`.
double areaToSolidAnglePdf(double pdfArea, const Vec3& from, const Vec3& point, const Vec3& normal);

} // namespace drt
