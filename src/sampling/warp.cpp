#include "sampling/warp.h"

#include <algorithm>
#include <cmath>

namespace drt {

// ---------------------------------------------------------------- discs

Vec2 squareToConcentricDisc(Vec2 u) {
    // Map to [-1, 1]^2; the larger coordinate picks the square's ring (the
    // radius), the ratio of the two picks the angle within an octant.
    const double a = 2.0 * u.x - 1.0;
    const double b = 2.0 * u.y - 1.0;
    if (a == 0.0 && b == 0.0) return {0.0, 0.0};
    double r, phi;
    if (std::fabs(a) > std::fabs(b)) {
        r = a;
        phi = (kPi / 4.0) * (b / a);
    } else {
        r = b;
        phi = kPi / 2.0 - (kPi / 4.0) * (a / b);
    }
    return {r * std::cos(phi), r * std::sin(phi)};
}

Vec2 squareToUniformDiscPolar(Vec2 u) {
    const double r = std::sqrt(u.x);
    const double phi = 2.0 * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi)};
}

// ---------------------------------------------------------------- spheres

namespace {
// Direction with the given cos(theta) about z and azimuth 2 pi v.
Vec3 fromCosTheta(double cosTheta, double v) {
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    const double phi = 2.0 * kPi * v;
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

// A direction given in the frame whose z is the unit `axis`, in world space.
Vec3 aboutAxis(const Vec3& axis, const Vec3& local) {
    Vec3 t, b;
    orthonormalBasis(axis, t, b);
    return normalize(t * local.x + b * local.y + axis * local.z);
}
} // namespace

Vec3 squareToUniformSphere(Vec2 u) { return fromCosTheta(1.0 - 2.0 * u.x, u.y); }

Vec3 squareToUniformHemisphere(Vec2 u) { return fromCosTheta(u.x, u.y); }

Vec3 squareToCosineHemisphere(Vec2 u) {
    // Malley: uniform on the disc, projected up; the projected density is
    // (1/pi) * cos(theta) because dA = cos(theta) d omega.
    const Vec2 d = squareToConcentricDisc(u);
    return {d.x, d.y, std::sqrt(std::max(0.0, 1.0 - d.x * d.x - d.y * d.y))};
}

Vec3 sampleCosineAround(const Vec3& axis, Vec2 u) { return aboutAxis(axis, squareToCosineHemisphere(u)); }

// ---------------------------------------------------------------- Phong lobe

Vec3 squareToPhongLobe(Vec2 u, double exponent) {
    // P(cos theta > c) = 1 - c^{n+1} over the hemisphere, so c = (1 - u1)^{1/(n+1)};
    // 1 - u1 lies in (0, 1], never 0, so no pow(0, .) at u1 = 0.
    const double cosTheta = std::pow(1.0 - u.x, 1.0 / (exponent + 1.0));
    return fromCosTheta(cosTheta, u.y);
}

double phongLobePdf(double cosTheta, double exponent) {
    if (cosTheta <= 0.0) return 0.0;
    return (exponent + 1.0) / (2.0 * kPi) * std::pow(cosTheta, exponent);
}

Vec3 sampleLobeAround(const Vec3& axis, double exponent, Vec2 u) {
    return aboutAxis(axis, squareToPhongLobe(u, exponent));
}

double lobeAroundPdf(const Vec3& axis, double exponent, const Vec3& direction) {
    return phongLobePdf(dot(axis, direction), exponent);
}

// ---------------------------------------------------------------- area lights

Vec3 sampleParallelogram(const Vec3& corner, const Vec3& edge1, const Vec3& edge2, Vec2 u) {
    return corner + edge1 * u.x + edge2 * u.y;
}

double parallelogramPdf(const Vec3& edge1, const Vec3& edge2) {
    const double area = length(cross(edge1, edge2));
    return area > 0.0 ? 1.0 / area : 0.0;
}

double areaToSolidAnglePdf(double pdfArea, const Vec3& from, const Vec3& point, const Vec3& normal) {
    // d omega = |cos theta_light| dA / r^2. A grazing point has unbounded
    // density; report 0 (it cannot be importance sampled) rather than Inf.
    const Vec3 d = point - from;
    const double distanceSquared = dot(d, d);
    const double cosLight = std::fabs(dot(normal, d)) / std::sqrt(distanceSquared);
    if (cosLight <= 0.0 || distanceSquared <= 0.0) return 0.0;
    return pdfArea * distanceSquared / cosLight;
}

// Urena, Fajardo & King (2013). In a frame with x, y along the edges and the
// origin at the shading point, the rectangle is [x0, x1] x [y0, y1] at height
// z0 <= 0. Its solid angle is the area of a spherical quad, S = sum of the
// interior angles - 2 pi. Cutting the quad by planes through the y axis
// direction at abscissa x gives a solid-angle CDF along x that inverts in closed
// form (the paper's equations for fu, cu, xu); along the chosen line,
// h = y / sqrt(x^2 + y^2 + z0^2) is uniform in solid angle, which inverts for y.
SphericalRectangle::SphericalRectangle(const Vec3& origin, const Vec3& corner, const Vec3& edge1, const Vec3& edge2)
    : origin_(origin) {
    const double lengthX = length(edge1), lengthY = length(edge2);
    x0_ = x1_ = y0_ = y1_ = z0_ = b0_ = b1_ = k_ = 0;
    if (!(lengthX > 0) || !(lengthY > 0)) return;
    x_ = edge1 / lengthX;
    y_ = edge2 / lengthY;
    z_ = cross(x_, y_);
    const Vec3 d = corner - origin;
    z0_ = dot(d, z_);
    if (z0_ > 0) {
        z_ = -z_;
        z0_ = -z0_;
    }
    x0_ = dot(d, x_);
    y0_ = dot(d, y_);
    x1_ = x0_ + lengthX;
    y1_ = y0_ + lengthY;
    if (!(z0_ < 0)) return; // in the plane: no solid angle

    // Unit normals of the quad's great-circle edges (cross products of
    // consecutive corners v00, v10, v11, v01, written out).
    const auto unit = [](Vec3 v) { return normalize(v); };
    const Vec3 n0 = unit({0, z0_, -y0_});
    const Vec3 n1 = unit({-z0_, 0, x1_});
    const Vec3 n2 = unit({0, -z0_, y1_});
    const Vec3 n3 = unit({z0_, 0, -x0_});
    const auto angle = [](const Vec3& a, const Vec3& b) { return std::acos(std::clamp(-dot(a, b), -1.0, 1.0)); };
    const double g0 = angle(n0, n1), g1 = angle(n1, n2), g2 = angle(n2, n3), g3 = angle(n3, n0);
    b0_ = n0.z;
    b1_ = n2.z;
    k_ = 2.0 * kPi - g2 - g3;
    const double s = g0 + g1 - k_;
    // Below ~1e-12 sr the angle sum cancels to noise; callers sample by area.
    solidAngle_ = s > 1e-12 ? s : 0.0;
}

Vec3 SphericalRectangle::sample(Vec2 u) const {
    // 1. The abscissa xu whose sub-quad [x0, xu] has solid angle u1 * S.
    const double au = u.x * solidAngle_ + k_;
    const double fu = (std::cos(au) * b0_ - b1_) / std::sin(au);
    double cu = std::copysign(1.0, fu) / std::sqrt(fu * fu + b0_ * b0_);
    cu = std::clamp(cu, -1.0, 1.0);
    const double sinU = std::sqrt(std::max(0.0, 1.0 - cu * cu));
    double xu = sinU > 0 ? -(cu * z0_) / sinU : (cu * z0_ > 0 ? x0_ : x1_);
    xu = std::clamp(xu, x0_, x1_);
    // 2. Along the segment at xu, h = y / sqrt(d^2 + y^2) is uniform in solid angle.
    const double dist = std::sqrt(xu * xu + z0_ * z0_);
    const double h0 = y0_ / std::sqrt(dist * dist + y0_ * y0_);
    const double h1 = y1_ / std::sqrt(dist * dist + y1_ * y1_);
    const double hv = h0 + u.y * (h1 - h0);
    const double hv2 = hv * hv;
    double yv = hv2 < 1.0 - 1e-12 ? hv * dist / std::sqrt(1.0 - hv2) : y1_;
    yv = std::clamp(yv, y0_, y1_);
    return origin_ + x_ * xu + y_ * yv + z_ * z0_;
}

} // namespace drt
