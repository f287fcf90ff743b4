// Procedural compact meshes for the mesh tests and benchmarks: a UV sphere
// and a height-field grid of any size, made in memory (never downloaded).
#pragma once

#include "scene/indexed_mesh.h"

#include <cmath>
#include <cstdint>
#include <memory>

namespace drt::test {

// A unit sphere at the origin as `rings` x `segments` latitude-longitude
// quads (two triangles each, one at each pole cap), wound counter-clockwise
// seen from outside, with unit normals (smooth) and uv = (longitude / 360,
// latitude fraction from the south pole) when asked.
inline std::shared_ptr<IndexedMesh> sphereMesh(int rings, int segments, bool normals = true,
                                               bool uvs = false) {
    auto mesh = std::make_shared<IndexedMesh>();
    // (segments + 1) columns so the seam has its own uv; rows 0 (south) .. rings (north).
    for (int r = 0; r <= rings; ++r) {
        const double theta = kPi * r / rings - kPi / 2; // latitude
        for (int s = 0; s <= segments; ++s) {
            const double phi = 2 * kPi * s / segments;
            const Vec3 p{std::cos(theta) * std::cos(phi), std::sin(theta), std::cos(theta) * std::sin(phi)};
            mesh->positions.push_back(Float3::of(p));
            if (normals)
                mesh->normals.push_back(Float3::of(p));
            if (uvs)
                mesh->uvs.push_back({float(double(s) / segments), float(double(r) / rings)});
        }
    }
    const auto at = [segments](int r, int s) { return uint32_t(r * (segments + 1) + s); };
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const uint32_t a = at(r, s), b = at(r, s + 1), c = at(r + 1, s + 1), d = at(r + 1, s);
            // Seen from outside (left-handed POV-Ray axes), a b c d runs counter-clockwise.
            if (r > 0)
                mesh->indices.insert(mesh->indices.end(), {a, c, b});
            if (r + 1 < rings)
                mesh->indices.insert(mesh->indices.end(), {a, d, c});
        }
    padForEmbree(*mesh);
    return mesh;
}

// A grid of n x n cells over [0, 1]^2 in x-z with a gentle bump in y, two
// triangles per cell: 2 n^2 triangles.
inline std::shared_ptr<IndexedMesh> gridMesh(int n) {
    auto mesh = std::make_shared<IndexedMesh>();
    mesh->positions.reserve(size_t(n + 1) * (n + 1) + 1);
    mesh->indices.reserve(size_t(6) * n * n);
    for (int z = 0; z <= n; ++z)
        for (int x = 0; x <= n; ++x) {
            const double u = double(x) / n, v = double(z) / n;
            mesh->positions.push_back(Float3::of({u, 0.05 * std::sin(6 * u) * std::cos(5 * v), v}));
        }
    const auto at = [n](int z, int x) { return uint32_t(z * (n + 1) + x); };
    for (int z = 0; z < n; ++z)
        for (int x = 0; x < n; ++x) {
            const uint32_t a = at(z, x), b = at(z, x + 1), c = at(z + 1, x + 1), d = at(z + 1, x);
            mesh->indices.insert(mesh->indices.end(), {a, d, c, a, c, b});
        }
    padForEmbree(*mesh);
    return mesh;
}

} // namespace drt::test
