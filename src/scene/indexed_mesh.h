// An indexed triangle mesh stored once, in single precision, in the layout
// Embree reads directly (float3 vertices, uint3 triangles): the accelerator
// hands these arrays to Embree as shared buffers (no copy) and every object
// that shows the same IndexedMesh (Mesh::indexed, a shared pointer) becomes
// an Embree instance of one BVH.
//
// Precision: vertices, normals and UVs are floats in object space. Hits are
// refined in double (accel.cpp): the ray is mapped into object space in
// double and intersected with the float triangle, whose corners are exact in
// double, so the refined point lies on that triangle to double precision.
// Rounding a vertex to float moves the surface by at most 2^-24 of the
// vertex's coordinates, the same for every ray, which shading cannot see and
// which cannot cause self-intersection (the next ray starts from a point on
// the very triangle Embree traverses, offset by accel's ULP rule).
#pragma once

#include "core/vec.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace drt {

struct Float3 {
    float x = 0, y = 0, z = 0;
    Vec3 toVec3() const { return {x, y, z}; }
    static Float3 of(const Vec3& v) { return {float(v.x), float(v.y), float(v.z)}; }
};
struct Float2 {
    float u = 0, v = 0;
};

// Means "the object's own texture" in IndexedMesh::faceTextures.
inline constexpr uint32_t kObjectTexture = 0xFFFFFFFFu;

struct IndexedMesh {
    std::vector<Float3> positions;
    std::vector<uint32_t> indices; // 3 per triangle into positions, counter-clockwise seen from outside
    // Optional per-vertex attributes, each with its own index triples (3 per
    // triangle) or, when its index array is empty, indexed by `indices`.
    std::vector<Float3> normals;
    std::vector<uint32_t> normalIndices;
    std::vector<Float2> uvs;
    std::vector<uint32_t> uvIndices;
    // Optional textures: 3 per triangle (one per corner, POV-Ray's mesh2
    // face_indices texture triples) indexing Mesh::textures, or kObjectTexture.
    // Corners with different textures blend them by barycentric weight.
    std::vector<uint32_t> faceTextures;

    size_t triangleCount() const { return indices.size() / 3; }
    std::array<uint32_t, 3> triangle(size_t i) const {
        return {indices[3 * i], indices[3 * i + 1], indices[3 * i + 2]};
    }
    // The corners' normal / uv indices of triangle i (their own or the vertex indices).
    std::array<uint32_t, 3> normalTriangle(size_t i) const { return corners(normalIndices, i); }
    std::array<uint32_t, 3> uvTriangle(size_t i) const { return corners(uvIndices, i); }
    // Bytes held by the arrays (capacity), for memory figures.
    size_t bytes() const;

  private:
    std::array<uint32_t, 3> corners(const std::vector<uint32_t>& own, size_t i) const {
        const std::vector<uint32_t>& from = own.empty() ? indices : own;
        return {from[3 * i], from[3 * i + 1], from[3 * i + 2]};
    }
};

// "" if every index is in range, every vertex finite and the arrays have
// whole triangles (textureCount: the size of Mesh::textures); else what is
// wrong, in words.
std::string validateIndexedMesh(const IndexedMesh& mesh, size_t textureCount);

// Makes room for one more position than there are, without adding one: Embree
// reads 4 bytes past the last float3 of a shared vertex buffer. Builders call
// it once they are done (the accelerator copies the positions otherwise).
inline void padForEmbree(IndexedMesh& mesh) {
    mesh.positions.reserve(mesh.positions.size() + 1);
}

// Whether two meshes hold the same arrays, bit for bit.
bool sameIndexedMesh(const IndexedMesh& a, const IndexedMesh& b);

// Object-space bounds; false for a mesh without triangles.
bool indexedMeshBounds(const IndexedMesh& mesh, Vec3& lower, Vec3& upper);

} // namespace drt
