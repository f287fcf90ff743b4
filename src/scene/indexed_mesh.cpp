#include "scene/indexed_mesh.h"

#include <cmath>
#include <cstring>

namespace drt {

size_t IndexedMesh::bytes() const {
    return positions.capacity() * sizeof(Float3) + indices.capacity() * sizeof(uint32_t) +
           normals.capacity() * sizeof(Float3) + normalIndices.capacity() * sizeof(uint32_t) +
           uvs.capacity() * sizeof(Float2) + uvIndices.capacity() * sizeof(uint32_t) +
           faceTextures.capacity() * sizeof(uint32_t);
}

namespace {

bool finite(const Float3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// "" if `own` is empty or holds one in-range triple per triangle.
std::string checkIndices(const std::vector<uint32_t>& own, size_t triangles, size_t count, const char* what) {
    if (own.empty())
        return "";
    if (own.size() != 3 * triangles)
        return std::string("the mesh has ") + std::to_string(triangles) + " triangles but " +
               std::to_string(own.size() / 3) + " " + what + " index triples";
    for (uint32_t i : own)
        if (i >= count)
            return std::string(what) + " index " + std::to_string(i) + " is out of range (" +
                   std::to_string(count) + " " + what + (count == 1 ? "" : "s") + ")";
    return "";
}

} // namespace

std::string validateIndexedMesh(const IndexedMesh& mesh, size_t textureCount) {
    if (mesh.indices.size() % 3 != 0)
        return "the mesh's index count is not a multiple of 3";
    const size_t triangles = mesh.triangleCount();
    for (const Float3& v : mesh.positions)
        if (!finite(v))
            return "a mesh vertex is not finite";
    if (std::string e = checkIndices(mesh.indices, triangles, mesh.positions.size(), "vertex"); !e.empty())
        return e;
    if (!mesh.normals.empty() || !mesh.normalIndices.empty()) {
        const size_t count = mesh.normals.size();
        if (mesh.normalIndices.empty() && count != mesh.positions.size())
            return "the mesh has " + std::to_string(count) + " normals for " +
                   std::to_string(mesh.positions.size()) + " vertices and no normal indices";
        if (std::string e = checkIndices(mesh.normalIndices, triangles, count, "normal"); !e.empty())
            return e;
    }
    if (!mesh.uvs.empty() || !mesh.uvIndices.empty()) {
        const size_t count = mesh.uvs.size();
        if (mesh.uvIndices.empty() && count != mesh.positions.size())
            return "the mesh has " + std::to_string(count) + " uv vectors for " +
                   std::to_string(mesh.positions.size()) + " vertices and no uv indices";
        if (std::string e = checkIndices(mesh.uvIndices, triangles, count, "uv"); !e.empty())
            return e;
    }
    if (!mesh.faceTextures.empty()) {
        if (mesh.faceTextures.size() != 3 * triangles)
            return "the mesh needs one texture triple per triangle";
        for (uint32_t t : mesh.faceTextures)
            if (t != kObjectTexture && t >= textureCount)
                return "texture index " + std::to_string(t) + " is out of range (" +
                       std::to_string(textureCount) + " textures)";
    }
    return "";
}

namespace {

template <class T> bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

} // namespace

bool sameIndexedMesh(const IndexedMesh& a, const IndexedMesh& b) {
    return sameBytes(a.positions, b.positions) && sameBytes(a.indices, b.indices) && sameBytes(a.normals, b.normals) &&
           sameBytes(a.normalIndices, b.normalIndices) && sameBytes(a.uvs, b.uvs) &&
           sameBytes(a.uvIndices, b.uvIndices) && sameBytes(a.faceTextures, b.faceTextures);
}

bool indexedMeshBounds(const IndexedMesh& mesh, Vec3& lower, Vec3& upper) {
    if (mesh.indices.empty())
        return false;
    lower = Vec3(INFINITY);
    upper = Vec3(-INFINITY);
    for (uint32_t i : mesh.indices) { // only the vertices triangles use
        const Vec3 v = mesh.positions[i].toVec3();
        lower = min(lower, v);
        upper = max(upper, v);
    }
    return true;
}

} // namespace drt
