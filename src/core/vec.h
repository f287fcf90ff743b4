// Small vector maths for the scene model and the renderer (double precision;
// Embree receives floats). POV-Ray convention: left-handed, x right, y up, z in.
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>

namespace drt {

struct Vec3 {
    double x = 0, y = 0, z = 0;

    constexpr Vec3() = default;
    constexpr Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
    constexpr explicit Vec3(double s) : x(s), y(s), z(s) {}

    constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

    constexpr Vec3 operator-() const { return {-x, -y, -z}; }
    constexpr Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
    constexpr Vec3& operator-=(const Vec3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
    constexpr Vec3& operator*=(double s) { x *= s; y *= s; z *= s; return *this; }
    constexpr bool operator==(const Vec3&) const = default;
};

constexpr Vec3 operator+(Vec3 a, const Vec3& b) { return a += b; }
constexpr Vec3 operator-(Vec3 a, const Vec3& b) { return a -= b; }
constexpr Vec3 operator*(Vec3 a, double s) { return a *= s; }
constexpr Vec3 operator*(double s, Vec3 a) { return a *= s; }
constexpr Vec3 operator/(const Vec3& a, double s) { return {a.x / s, a.y / s, a.z / s}; }
// Component-wise product and quotient (POV-Ray's vector * vector).
constexpr Vec3 operator*(const Vec3& a, const Vec3& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
constexpr Vec3 operator/(const Vec3& a, const Vec3& b) { return {a.x / b.x, a.y / b.y, a.z / b.z}; }

constexpr double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalize(const Vec3& a) { return a / length(a); }
inline bool isFinite(const Vec3& a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }
inline Vec3 abs(const Vec3& a) { return {std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)}; }
inline double maxComponent(const Vec3& a) { return std::fmax(a.x, std::fmax(a.y, a.z)); }
inline Vec3 min(const Vec3& a, const Vec3& b) { return {std::fmin(a.x, b.x), std::fmin(a.y, b.y), std::fmin(a.z, b.z)}; }
inline Vec3 max(const Vec3& a, const Vec3& b) { return {std::fmax(a.x, b.x), std::fmax(a.y, b.y), std::fmax(a.z, b.z)}; }

// An orthonormal basis around a unit vector n (Duff et al. 2017, "Building an
// orthonormal basis, revisited"): returns t, b with (t, b, n) right-handed.
// Narrows [t0, t1] of the ray origin + t direction to the part inside the box
// (the slab test). False when nothing is left (t0 > t1), or when the ray runs
// outside the box parallel to an axis; a NaN quotient leaves its bound as it was.
inline bool clipToBox(const Vec3& lower, const Vec3& upper, const Vec3& origin, const Vec3& direction, double& t0,
                      double& t1) {
    for (int i = 0; i < 3; ++i) {
        if (direction[i] == 0) {
            if (origin[i] < lower[i] || origin[i] > upper[i]) return false;
            continue;
        }
        double a = (lower[i] - origin[i]) / direction[i], b = (upper[i] - origin[i]) / direction[i];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
        if (t0 > t1) return false;
    }
    return true;
}

inline void orthonormalBasis(const Vec3& n, Vec3& t, Vec3& b) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double c = n.x * n.y * a;
    t = {1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x};
    b = {c, sign + n.y * n.y * a, -n.y};
}

struct Vec2 {
    double x = 0, y = 0;
    constexpr bool operator==(const Vec2&) const = default;
};

inline constexpr double kPi = 3.14159265358979323846;

} // namespace drt
