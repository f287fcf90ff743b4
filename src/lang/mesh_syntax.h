// Private to the mesh entries of the front end (shapes_mesh.cpp,
// shapes_mesh_indexed.cpp): the pieces both use.
#pragma once

#include "lang/evaluator.h"
#include "lang/shape_syntax.h"

namespace drt::lang {

// Sets a flag for one expression, cleared again even if it fails.
struct FlagFor {
    bool& flag;
    explicit FlagFor(bool& f) : flag(f) { flag = true; }
    ~FlagFor() { flag = false; }
};

// The comma between a triangle's items: required in .drt, optional in POV-Ray.
void meshSeparator(Evaluator& e, const char* context);

// A triangle's corners and, for a smooth_triangle, their unit normals.
struct TriangleCorners {
    Vec3 corners[3];
    Vec3 normals[3];
};
TriangleCorners readTriangleCorners(Evaluator& e, bool smooth);

// mesh { triangle { ... [uv_vectors ...] [texture { ... }] } ... } and
// POV-Ray's mesh2, both into Mesh::indexed (scene/indexed_mesh.h) with
// Mesh::textures for the triangles' own textures.
void readTriangleMesh(Evaluator& e, const Token& keyword, Mesh& m);
void readMesh2(Evaluator& e, const Token& keyword, Mesh& m);

// bicubic_patch (shapes_bicubic_patch.cpp): its items and points, into
// Mesh::indexed and Mesh::patch; and its .drt text (without its closing brace).
void readBicubicPatch(Evaluator& e, const Token& keyword, Mesh& m);
std::string bicubicPatchHead(const Mesh& m, ShapeText& text);

// A compact mesh as mesh2 text (without its closing brace).
std::string indexedMeshHead(const Mesh& m, ShapeText& text);

} // namespace drt::lang
