#include "core/transform.h"

#include <cmath>

namespace drt {

Mat4 operator*(const Mat4& a, const Mat4& b) {
    Mat4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double s = 0;
            for (int k = 0; k < 4; ++k) s += a.m[i][k] * b.m[k][j];
            r.m[i][j] = s;
        }
    return r;
}

Mat4 transpose(const Mat4& a) {
    Mat4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = a.m[j][i];
    return r;
}

// Gauss-Jordan elimination with partial pivoting.
std::optional<Mat4> inverse(const Mat4& a) {
    std::array<std::array<double, 8>, 4> w{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            w[i][j] = a.m[i][j];
            w[i][j + 4] = (i == j) ? 1.0 : 0.0;
        }
    for (int col = 0; col < 4; ++col) {
        int pivot = col;
        for (int r = col + 1; r < 4; ++r)
            if (std::fabs(w[r][col]) > std::fabs(w[pivot][col])) pivot = r;
        if (std::fabs(w[pivot][col]) < 1e-300 || !std::isfinite(w[pivot][col])) return std::nullopt;
        std::swap(w[col], w[pivot]);
        const double inv = 1.0 / w[col][col];
        for (double& v : w[col]) v *= inv;
        for (int r = 0; r < 4; ++r) {
            if (r == col) continue;
            const double f = w[r][col];
            if (f == 0) continue;
            for (int j = 0; j < 8; ++j) w[r][j] -= f * w[col][j];
        }
    }
    Mat4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = w[i][j + 4];
    return r;
}

Transform Transform::translate(const Vec3& t) {
    Mat4 m, inv;
    for (int i = 0; i < 3; ++i) {
        m.m[i][3] = t[i];
        inv.m[i][3] = -t[i];
    }
    return Transform(m, inv);
}

Transform Transform::scale(const Vec3& s) {
    Mat4 m, inv;
    for (int i = 0; i < 3; ++i) {
        m.m[i][i] = s[i];
        inv.m[i][i] = 1.0 / s[i];
    }
    return Transform(m, inv);
}

Transform Transform::rotateAxis(const Vec3& axisIn, double degrees) {
    // Rodrigues' formula for a left-handed rotation as POV-Ray defines it: rotating
    // by +a about +x takes +y toward +z (the same matrix as right-handed maths).
    const Vec3 a = normalize(axisIn);
    const double th = degrees * kPi / 180.0;
    const double c = std::cos(th), s = std::sin(th), t = 1 - c;
    Mat4 m;
    m.m[0] = {t * a.x * a.x + c, t * a.x * a.y - s * a.z, t * a.x * a.z + s * a.y, 0};
    m.m[1] = {t * a.x * a.y + s * a.z, t * a.y * a.y + c, t * a.y * a.z - s * a.x, 0};
    m.m[2] = {t * a.x * a.z - s * a.y, t * a.y * a.z + s * a.x, t * a.z * a.z + c, 0};
    return Transform(m, transpose(m)); // rotations are orthogonal
}

Transform Transform::rotate(const Vec3& degrees) {
    return rotateAxis({1, 0, 0}, degrees.x)
        .then(rotateAxis({0, 1, 0}, degrees.y))
        .then(rotateAxis({0, 0, 1}, degrees.z));
}

std::optional<Transform> Transform::fromMatrix(const Mat4& m) {
    auto inv = inverse(m);
    if (!inv) return std::nullopt;
    return Transform(m, *inv);
}

std::optional<Transform> Transform::fromPovMatrix(const std::array<double, 12>& v) {
    // POV-Ray lists the matrix row by row for row vectors (p' = p * M), so the
    // column-vector matrix is its transpose.
    Mat4 m;
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 3; ++col) m.m[col][row] = v[row * 3 + col];
    return fromMatrix(m);
}

Transform Transform::then(const Transform& next) const {
    return Transform(next.m_ * m_, inv_ * next.inv_);
}

static Vec3 applyPoint(const Mat4& m, const Vec3& p) {
    return {m.m[0][0] * p.x + m.m[0][1] * p.y + m.m[0][2] * p.z + m.m[0][3],
            m.m[1][0] * p.x + m.m[1][1] * p.y + m.m[1][2] * p.z + m.m[1][3],
            m.m[2][0] * p.x + m.m[2][1] * p.y + m.m[2][2] * p.z + m.m[2][3]};
}

static Vec3 applyVector(const Mat4& m, const Vec3& v) {
    return {m.m[0][0] * v.x + m.m[0][1] * v.y + m.m[0][2] * v.z,
            m.m[1][0] * v.x + m.m[1][1] * v.y + m.m[1][2] * v.z,
            m.m[2][0] * v.x + m.m[2][1] * v.y + m.m[2][2] * v.z};
}

Vec3 Transform::point(const Vec3& p) const { return applyPoint(m_, p); }
Vec3 Transform::vector(const Vec3& v) const { return applyVector(m_, v); }
Vec3 Transform::inversePoint(const Vec3& p) const { return applyPoint(inv_, p); }
Vec3 Transform::inverseVector(const Vec3& v) const { return applyVector(inv_, v); }

Vec3 Transform::normal(const Vec3& n) const {
    const Mat4& i = inv_;
    return {i.m[0][0] * n.x + i.m[1][0] * n.y + i.m[2][0] * n.z,
            i.m[0][1] * n.x + i.m[1][1] * n.y + i.m[2][1] * n.z,
            i.m[0][2] * n.x + i.m[1][2] * n.y + i.m[2][2] * n.z};
}

} // namespace drt
