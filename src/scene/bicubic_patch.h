// POV-Ray's bicubic_patch: a Bezier surface of 16 control points, which the
// front ends lower to a smooth triangle mesh (Mesh::indexed), as POV-Ray
// itself tessellates it:
//   S(u, v) = sum over i, j of B_i(u) B_j(v) points[4 j + i],   u, v in [0, 1]
// with the Bernstein polynomials B_0(t) = (1-t)^3, B_1 = 3t(1-t)^2,
// B_2 = 3t^2(1-t), B_3 = t^3. So u runs along each row of four points as
// written and v across the rows (measured on POV-Ray with uv_mapping).
//
// The mesh is the regular grid of 2^uSteps x 2^vSteps quads over the unit
// square, two triangles each, with the surface's own unit normal
// (dS/du x dS/dv) at every vertex and uv coordinates from uvCorners (the
// bilinear blend of the corners' uvs: POV-Ray's uv_vectors, by default the
// unit square). POV-Ray may stop subdividing a piece once it is flatter than
// `flatness`; drt always subdivides to the full depth, so it keeps `type`
// and `flatness` only to write them back.
#pragma once

#include "scene/indexed_mesh.h"

#include <array>
#include <memory>

namespace drt {

struct BicubicPatch {
    int type = 0;          // POV-Ray's 0 (computed as needed) or 1 (kept in memory): the same surface here
    double flatness = 0;   // written back only (see above)
    int uSteps = 0;        // 2^uSteps quads along u
    int vSteps = 0;        // 2^vSteps quads along v
    std::array<Vec3, 16> points{};
    // The uvs of the corners (u, v) = (0, 0), (1, 0), (1, 1), (0, 1).
    std::array<Float2, 4> uvCorners{Float2{0, 0}, Float2{1, 0}, Float2{1, 1}, Float2{0, 1}};
    bool operator==(const BicubicPatch& o) const;
};

// The largest uSteps / vSteps (4^10 quads, two million triangles).
inline constexpr int kMaxBicubicPatchSteps = 10;

Vec3 bicubicPatchPoint(const BicubicPatch& patch, double u, double v);
// The unit normal dS/du x dS/dv; where that vanishes (control points that
// meet in a corner or an edge, as at the tip of a teapot's lid) the normal of
// a point a little inside the patch stands in; zero only for a patch that
// is degenerate everywhere near (u, v).
Vec3 bicubicPatchNormal(const BicubicPatch& patch, double u, double v);
// The triangle mesh described above. Steps must be in 0..kMaxBicubicPatchSteps.
std::shared_ptr<IndexedMesh> tessellateBicubicPatch(const BicubicPatch& patch);

} // namespace drt
