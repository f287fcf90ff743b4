// Affine transforms as 4x4 matrices with their inverse kept beside them.
// Composition follows POV-Ray: each new transform applies after those before it,
// so `scale 2 translate x` scales first, then moves.
#pragma once

#include "core/vec.h"

#include <array>
#include <optional>

namespace drt {

struct Mat4 {
    // Row-major; points are column vectors: p' = M * p.
    std::array<std::array<double, 4>, 4> m{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};

    static Mat4 identity() { return {}; }
    bool operator==(const Mat4&) const = default;
};

Mat4 operator*(const Mat4& a, const Mat4& b);
std::optional<Mat4> inverse(const Mat4& a);
Mat4 transpose(const Mat4& a);

class Transform {
public:
    Transform() = default;

    static Transform translate(const Vec3& t);
    static Transform scale(const Vec3& s); // every component must be non-zero
    // POV-Ray `rotate <a,b,c>`: degrees about x, then y, then z (left-handed).
    static Transform rotate(const Vec3& degrees);
    static Transform rotateAxis(const Vec3& axis, double degrees);
    // POV-Ray `matrix <m00..m32>`: 12 numbers, the last row is the translation.
    // Returns nothing when the matrix is singular.
    static std::optional<Transform> fromPovMatrix(const std::array<double, 12>& v);
    static std::optional<Transform> fromMatrix(const Mat4& m);
    // A matrix with an inverse the caller computed in closed form (trusted).
    static Transform fromMatrixAndInverse(const Mat4& m, const Mat4& inv) { return Transform(m, inv); }

    // this followed by `next` (next applied after this).
    Transform then(const Transform& next) const;
    Transform inverted() const { return Transform(inv_, m_); }

    Vec3 point(const Vec3& p) const;
    Vec3 vector(const Vec3& v) const;
    // Normals transform by the inverse transpose.
    Vec3 normal(const Vec3& n) const;
    Vec3 inversePoint(const Vec3& p) const;
    Vec3 inverseVector(const Vec3& v) const;

    const Mat4& matrix() const { return m_; }
    const Mat4& inverseMatrix() const { return inv_; }
    bool isIdentity() const { return m_ == Mat4::identity(); }
    bool operator==(const Transform& o) const { return m_ == o.m_; }

private:
    Transform(const Mat4& m, const Mat4& inv) : m_(m), inv_(inv) {}
    Mat4 m_;
    Mat4 inv_;
};

} // namespace drt
