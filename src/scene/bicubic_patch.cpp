#include "scene/bicubic_patch.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace drt {

namespace {

// Bernstein polynomials of degree 3 at t, and their derivatives.
std::array<double, 4> bernstein(double t) {
    const double s = 1 - t;
    return {s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t};
}
std::array<double, 4> bernsteinDerivative(double t) {
    const double s = 1 - t;
    return {-3 * s * s, 3 * s * s - 6 * t * s, 6 * t * s - 3 * t * t, 3 * t * t};
}

Vec3 blend(const BicubicPatch& patch, const std::array<double, 4>& bu, const std::array<double, 4>& bv) {
    Vec3 sum{0, 0, 0};
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) sum += (bu[size_t(i)] * bv[size_t(j)]) * patch.points[size_t(4 * j + i)];
    return sum;
}

// dS/du x dS/dv, not normalised.
Vec3 tangentCross(const BicubicPatch& patch, double u, double v) {
    const Vec3 du = blend(patch, bernsteinDerivative(u), bernstein(v));
    const Vec3 dv = blend(patch, bernstein(u), bernsteinDerivative(v));
    return cross(du, dv);
}

} // namespace

bool BicubicPatch::operator==(const BicubicPatch& o) const {
    for (size_t k = 0; k < 4; ++k)
        if (uvCorners[k].u != o.uvCorners[k].u || uvCorners[k].v != o.uvCorners[k].v) return false;
    return type == o.type && flatness == o.flatness && uSteps == o.uSteps && vSteps == o.vSteps &&
           points == o.points;
}

Vec3 bicubicPatchPoint(const BicubicPatch& patch, double u, double v) {
    return blend(patch, bernstein(u), bernstein(v));
}

Vec3 bicubicPatchNormal(const BicubicPatch& patch, double u, double v) {
    // Measured against the patch's size, so that the test does not depend on its scale.
    double size = 0;
    for (const Vec3& p : patch.points) size = std::max(size, length(p - patch.points[0]));
    const double tiny = 1e-10 * size * size; // |dS/du x dS/dv| grows with the square of the size
    // Where the tangents vanish or are parallel, step toward the middle of the
    // patch: the normal there is the limit of the nearby normals.
    for (double step : {0.0, 1e-7, 1e-5, 1e-3, 1e-2}) {
        const Vec3 n = tangentCross(patch, u + step * (0.5 - u), v + step * (0.5 - v));
        const double l = length(n);
        if (l > tiny && l > 0) return n / l;
    }
    return {0, 0, 0};
}

std::shared_ptr<IndexedMesh> tessellateBicubicPatch(const BicubicPatch& patch) {
    if (patch.uSteps < 0 || patch.uSteps > kMaxBicubicPatchSteps || patch.vSteps < 0 ||
        patch.vSteps > kMaxBicubicPatchSteps)
        throw std::invalid_argument("bicubic_patch steps must be in 0.." + std::to_string(kMaxBicubicPatchSteps));
    const int columns = 1 << patch.uSteps, rows = 1 << patch.vSteps;
    auto mesh = std::make_shared<IndexedMesh>();
    const size_t vertices = size_t(columns + 1) * size_t(rows + 1);
    mesh->positions.reserve(vertices + 1); // + 1: padForEmbree
    mesh->normals.reserve(vertices);
    mesh->uvs.reserve(vertices);
    const std::array<Float2, 4>& c = patch.uvCorners;
    for (int j = 0; j <= rows; ++j) {
        const double v = double(j) / rows;
        for (int i = 0; i <= columns; ++i) {
            const double u = double(i) / columns;
            mesh->positions.push_back(Float3::of(bicubicPatchPoint(patch, u, v)));
            Vec3 n = bicubicPatchNormal(patch, u, v);
            if (dot(n, n) == 0) n = {0, 1, 0}; // a patch collapsed to a line or a point: no surface to shade
            mesh->normals.push_back(Float3::of(n));
            // The bilinear blend of the corner uvs.
            const double w00 = (1 - u) * (1 - v), w10 = u * (1 - v), w11 = u * v, w01 = (1 - u) * v;
            mesh->uvs.push_back({float(w00 * c[0].u + w10 * c[1].u + w11 * c[2].u + w01 * c[3].u),
                                 float(w00 * c[0].v + w10 * c[1].v + w11 * c[2].v + w01 * c[3].v)});
        }
    }
    // Each quad (i, j)..(i+1, j+1) as two triangles wound like dS/du x dS/dv.
    mesh->indices.reserve(size_t(columns) * size_t(rows) * 6);
    const auto at = [&](int i, int j) { return uint32_t(j * (columns + 1) + i); };
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i) {
            const uint32_t a = at(i, j), b = at(i + 1, j), c11 = at(i + 1, j + 1), d = at(i, j + 1);
            mesh->indices.insert(mesh->indices.end(), {a, b, c11, a, c11, d});
        }
    padForEmbree(*mesh);
    return mesh;
}

} // namespace drt
