// POV-Ray's non-planar cameras (formulas in render/camera.h, after POV-Ray
// 3.7's tracepixel.cpp): fisheye, ultra_wide_angle, panoramic, cylinder 1-4,
// spherical and omnimax.
#include "render/camera.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace drt {

namespace {

// POV-Ray's stand-in for tan(+-pi/2) at the panoramic camera's poles.
constexpr double kPoleTangent = 2e10;

struct Basis {
    Vec3 d, r, u;             // unit direction, right, up
    double lengthRight = 1, lengthUp = 1;
};

Basis basisOf(const ResolvedCamera& c) {
    return {normalize(c.direction), normalize(c.right), normalize(c.up), length(c.right), length(c.up)};
}

// The fisheye's image-plane point scaled so that its circle has radius 1.
Vec2 fisheyePoint(const ResolvedCamera& c, double x0, double y0) {
    return {2 * x0 * length(c.right), 2 * y0 * length(c.up)};
}

// POV-Ray's omnimax, a projection for a tilted dome (render/camera.h): the
// unit direction of image point (x0, y0), or none where it traces no ray.
std::optional<Vec3> omnimaxDirection(const ResolvedCamera& c, double x0, double y0) {
    // POV-Ray's constants: the image aspect its dome fills, and the polynomial
    // from the distance off the circle's centre to the angle off the axis.
    constexpr double kDomeAspect = 1.283458;
    double x = 2 * x0, y = 2 * y0;
    const double aspect = length(c.right) / length(c.up);
    if (aspect > kDomeAspect) {
        x *= aspect / kDomeAspect;
        y = (y - 1) / kDomeAspect + 1;
    } else if (aspect > 1) {
        y = (y - 1) / aspect + 1;
    } else {
        y /= aspect;
    }
    const double rad = std::hypot(x, y);
    if (!(rad <= 1)) return std::nullopt;
    const double s = rad > 0 ? std::asin(std::clamp(y / rad, -1.0, 1.0)) : 0.0;
    const double phi = x < 0 ? kPi - s : s;
    const double r2 = rad * rad;
    const double theta = rad * (1.411269 + r2 * (-0.09439 + r2 * 0.25674));
    const double sinTheta = std::sin(theta), cosTheta = std::cos(theta);
    // Nothing more than 45 degrees below the axis: sin(phi) sin(theta) < tan(135 deg) cos(theta).
    if (std::sin(phi) * sinTheta < -cosTheta) return std::nullopt;
    const Basis b = basisOf(c);
    return sinTheta * (std::cos(phi) * b.r + std::sin(phi) * b.u) + cosTheta * b.d;
}

} // namespace

bool ResolvedCamera::covers(double px, double py) const {
    if (mapping == CameraMapping::Omnimax) return omnimaxDirection(*this, px / width - 0.5, 0.5 - py / height).has_value();
    if (mapping != CameraMapping::Fisheye) return true;
    const Vec2 p = fisheyePoint(*this, px / width - 0.5, 0.5 - py / height);
    return std::hypot(p.x, p.y) <= 1.0;
}

Ray ResolvedCamera::mappedRay(double px, double py) const {
    const double x0 = px / width - 0.5;
    const double y0 = 0.5 - py / height;
    const double a = mappingAngle;
    const Basis b = basisOf(*this);
    Ray ray;
    ray.origin = location;
    switch (mapping) {
    case CameraMapping::Fisheye: {
        const Vec2 p = fisheyePoint(*this, x0, y0);
        const double rho = std::min(std::hypot(p.x, p.y), 1.0); // covers() excludes rho > 1
        const double phi = rho > 0 ? std::atan2(p.y, p.x) : 0.0;
        const double theta = rho * a / 2;
        ray.direction = std::sin(theta) * (std::cos(phi) * b.r + std::sin(phi) * b.u) + std::cos(theta) * b.d;
        break;
    }
    case CameraMapping::UltraWideAngle: {
        const double h = x0 * a, v = y0 * a * b.lengthUp / b.lengthRight;
        ray.direction = std::sin(h) * b.r + std::sin(v) * b.u + std::cos(h) * std::cos(v) * b.d;
        break;
    }
    case CameraMapping::Panoramic: {
        const double p = (1 - px / width) * kPi;
        const double q = y0 * kPi;
        const double t = std::abs(kPi / 2 - std::abs(q)) < 1e-10 ? std::copysign(kPoleTangent, q)
                                                                 : std::clamp(std::tan(q), -kPoleTangent, kPoleTangent);
        ray.direction = std::cos(p) * right + t * up + std::sin(p) * direction;
        break;
    }
    case CameraMapping::Cylinder1:
        ray.direction = std::sin(x0 * a) * b.r + y0 * b.lengthUp * b.u + std::cos(x0 * a) * b.d;
        break;
    case CameraMapping::Cylinder2:
        ray.direction = x0 * b.lengthRight * b.r + std::sin(y0 * a) * b.u + std::cos(y0 * a) * b.d;
        break;
    case CameraMapping::Cylinder3:
        ray.origin = location + y0 * b.lengthUp * b.u;
        ray.direction = std::sin(x0 * a) * b.r + std::cos(x0 * a) * b.d;
        break;
    case CameraMapping::Cylinder4:
        ray.origin = location + x0 * b.lengthRight * b.r;
        ray.direction = std::sin(y0 * a) * b.u + std::cos(y0 * a) * b.d;
        break;
    case CameraMapping::Spherical: {
        // Latitude y0 v, longitude x0 h, on the sphere of radius |direction|.
        const double lat = y0 * verticalAngle, lon = x0 * a;
        ray.direction = length(direction) * (std::cos(lat) * (std::cos(lon) * b.d + std::sin(lon) * b.r) +
                                             std::sin(lat) * b.u);
        break;
    }
    case CameraMapping::Omnimax: // covers() excludes the points without a ray
        ray.direction = omnimaxDirection(*this, x0, y0).value_or(b.d);
        break;
    case CameraMapping::Planar:
        break;
    }
    return ray;
}

} // namespace drt
