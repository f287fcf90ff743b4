#include "scene/height_field.h"

namespace drt {

Mesh heightFieldMesh(const std::vector<double>& heights, int columns, int rows, bool smooth, double waterLevel) {
    Mesh m;
    if (columns < 2 || rows < 2 || heights.size() != size_t(columns) * rows) return m;
    m.vertices.reserve(heights.size());
    for (int z = 0; z < rows; ++z)
        for (int x = 0; x < columns; ++x)
            m.vertices.push_back({double(x) / (columns - 1), heights[size_t(z) * columns + x], double(z) / (rows - 1)});
    auto index = [&](int x, int z) { return z * columns + x; };
    auto keep = [&](const std::array<int, 3>& t) {
        return m.vertices[t[0]].y >= waterLevel || m.vertices[t[1]].y >= waterLevel ||
               m.vertices[t[2]].y >= waterLevel;
    };
    for (int z = 0; z + 1 < rows; ++z)
        for (int x = 0; x + 1 < columns; ++x) {
            // Wound so that the face normal points up (+y) on a flat field.
            const std::array<int, 3> lower{index(x, z), index(x, z + 1), index(x + 1, z)};
            const std::array<int, 3> upper{index(x + 1, z), index(x, z + 1), index(x + 1, z + 1)};
            if (keep(lower)) m.triangles.push_back(lower);
            if (keep(upper)) m.triangles.push_back(upper);
        }
    if (smooth && !m.triangles.empty()) {
        m.normals.assign(m.vertices.size(), Vec3{0, 0, 0});
        for (const auto& t : m.triangles) {
            // The cross product's length is twice the area: an area-weighted sum.
            const Vec3 n = cross(m.vertices[t[1]] - m.vertices[t[0]], m.vertices[t[2]] - m.vertices[t[0]]);
            for (int i : t) m.normals[i] = m.normals[i] + n;
        }
        for (Vec3& n : m.normals) {
            const double len = length(n);
            n = len > 0 ? n / len : Vec3{0, 1, 0};
        }
        m.normalIndices = m.triangles;
    }
    return m;
}

} // namespace drt
