// POV-Ray's non-planar cameras (formulas in render/camera.h, after POV-Ray
// 3.7's tracepixel.cpp): fisheye, ultra_wide_angle, panoramic, cylinder 1-4
// and spherical.
#include "render/camera.h"

#include <algorithm>
#include <cmath>

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

} // namespace

bool ResolvedCamera::covers(double px, double py) const {
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
    case CameraMapping::Planar:
        break;
    }
    return ray;
}

} // namespace drt
