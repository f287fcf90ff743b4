// POV-Ray's bicubic_patch, lowered to a smooth triangle mesh: closed forms
// (a patch of planar control points lies in their plane, the corners
// interpolate the corner points, a bilinear patch is exact at every grid
// vertex, the normal is the plane's), the grid POV-Ray uses (2^u_steps x
// 2^v_steps quads, u along each row of points), uv corners, both front ends,
// the .drt writer's round trip and located errors. The render against
// POV-Ray's is in the wide table (objects/bezier.pov, portfolio/allobjects.pov).
#include "accel/accel.h"
#include "lang/load.h"
#include "lang/writer.h"
#include "pov/load.h"
#include "scene/bicubic_patch.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace drt {
namespace {

// Control points on the plane z = 0.5 x + 0.25 y + 1, at uneven spacings
// (so the surface is not the bilinear map of its corners).
BicubicPatch planarPatch() {
    BicubicPatch p;
    const double xs[4] = {0, 0.7, 2.1, 3}, ys[4] = {0, 1.3, 1.6, 3};
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            const double x = xs[i] + 0.2 * j, y = ys[j] - 0.1 * i;
            p.points[size_t(4 * j + i)] = {x, y, 0.5 * x + 0.25 * y + 1};
        }
    return p;
}

double planeDistance(const Vec3& p) {
    // |0.5 x + 0.25 y - z + 1| / |(0.5, 0.25, -1)|
    return std::fabs(0.5 * p.x + 0.25 * p.y - p.z + 1) / std::sqrt(0.25 + 0.0625 + 1);
}

TEST(BicubicPatch, PlanarControlPointsGiveAPatchInTheirPlane) {
    BicubicPatch p = planarPatch();
    p.uSteps = 3, p.vSteps = 2;
    const Vec3 planeNormal = normalize(Vec3{0.5, 0.25, -1});
    for (double u = 0; u <= 1; u += 0.125)
        for (double v = 0; v <= 1; v += 0.125) {
            EXPECT_LT(planeDistance(bicubicPatchPoint(p, u, v)), 1e-12) << u << " " << v;
            EXPECT_NEAR(std::fabs(dot(bicubicPatchNormal(p, u, v), planeNormal)), 1, 1e-12) << u << " " << v;
        }
    const auto mesh = tessellateBicubicPatch(p);
    ASSERT_EQ(mesh->positions.size(), size_t(9 * 5));
    ASSERT_EQ(mesh->triangleCount(), size_t(8 * 4 * 2));
    for (const Float3& v : mesh->positions) EXPECT_LT(planeDistance(v.toVec3()), 1e-5);
    // A ray through the accelerator hits the plane exactly where the plane is.
    Mesh lowered;
    lowered.indexed = mesh;
    const Scene scene = test::sceneOf({test::makeObject(lowered)});
    const Accelerator accel(scene);
    for (const Vec3 target : {Vec3{1, 1, 0}, Vec3{1.9, 0.6, 0}, Vec3{2.5, 2.5, 0}}) {
        const double z = 0.5 * target.x + 0.25 * target.y + 1;
        const std::optional<Hit> hit = test::trace(accel, {target.x, target.y, -10}, {0, 0, 1});
        ASSERT_TRUE(hit) << target.x;
        EXPECT_NEAR(hit->point.z, z, 1e-5) << target.x;
        EXPECT_NEAR(std::fabs(dot(normalize(hit->shadingNormal), planeNormal)), 1, 1e-5);
    }
}

TEST(BicubicPatch, CornersInterpolateTheCornerPointsAndTheGridIsPovRays) {
    BicubicPatch p;
    for (size_t k = 0; k < 16; ++k) p.points[k] = {double(k % 4), std::sin(double(k)), double(k / 4)};
    p.uSteps = 2, p.vSteps = 1;
    EXPECT_EQ(bicubicPatchPoint(p, 0, 0), p.points[0]);
    EXPECT_EQ(bicubicPatchPoint(p, 1, 0), p.points[3]);
    EXPECT_EQ(bicubicPatchPoint(p, 0, 1), p.points[12]);
    EXPECT_EQ(bicubicPatchPoint(p, 1, 1), p.points[15]);
    const auto mesh = tessellateBicubicPatch(p);
    // 4 x 2 quads: vertex (i, j) at u = i / 4, v = j / 2, row by row.
    ASSERT_EQ(mesh->positions.size(), size_t(5 * 3));
    EXPECT_EQ(mesh->triangleCount(), size_t(4 * 2 * 2));
    for (int j = 0; j <= 2; ++j)
        for (int i = 0; i <= 4; ++i) {
            const Vec3 expected = bicubicPatchPoint(p, i / 4.0, j / 2.0);
            const Vec3 got = mesh->positions[size_t(5 * j + i)].toVec3();
            EXPECT_NEAR(length(got - expected), 0, 1e-6) << i << " " << j;
            EXPECT_FLOAT_EQ(mesh->uvs[size_t(5 * j + i)].u, float(i / 4.0));
            EXPECT_FLOAT_EQ(mesh->uvs[size_t(5 * j + i)].v, float(j / 2.0));
        }
}

TEST(BicubicPatch, EvenlySpacedPointsMakeTheBilinearMapAndOwnUvsBlend) {
    // Points at thirds of a square's edges: S(u, v) = (3u, 3v, 0) exactly.
    BicubicPatch p;
    for (size_t k = 0; k < 16; ++k) p.points[k] = {double(k % 4), double(k / 4), 0};
    p.uvCorners = {Float2{2, 4}, Float2{3, 4}, Float2{3, 6}, Float2{2, 6}};
    EXPECT_EQ(bicubicPatchPoint(p, 0.25, 0.75), (Vec3{0.75, 2.25, 0}));
    const Vec3 n = bicubicPatchNormal(p, 0.3, 0.6);
    EXPECT_NEAR(n.z, 1, 1e-12); // dS/du x dS/dv = x * y
    p.uSteps = 1, p.vSteps = 1;
    const auto mesh = tessellateBicubicPatch(p);
    EXPECT_FLOAT_EQ(mesh->uvs[4].u, 2.5f); // the middle vertex: the mean of the corners' uvs
    EXPECT_FLOAT_EQ(mesh->uvs[4].v, 5.0f);
}

TEST(BicubicPatch, CollapsedEdgeTakesTheNormalFromInside) {
    // The v = 0 row meets in one point (a cone's tip, as at a teapot's lid): dS/du vanishes there.
    BicubicPatch p;
    for (size_t k = 0; k < 16; ++k) {
        const double r = double(k / 4) / 3;
        p.points[k] = {r * double(k % 4), r * double(3 - k % 4), -r};
    }
    const Vec3 n = bicubicPatchNormal(p, 0.5, 0);
    ASSERT_NEAR(length(n), 1, 1e-9);
    EXPECT_NEAR(length(n - bicubicPatchNormal(p, 0.5, 0.01)), 0, 0.02);
    BicubicPatch point; // every control point the same: no surface at all
    p.uSteps = 1;
    EXPECT_EQ(bicubicPatchNormal(point, 0.5, 0.5), (Vec3{0, 0, 0}));
    const auto mesh = tessellateBicubicPatch(point);
    for (const Float3& normal : mesh->normals) EXPECT_EQ(normal.toVec3(), (Vec3{0, 1, 0}));
}

TEST(BicubicPatch, StepsOutOfRangeAreRefused) {
    BicubicPatch p;
    p.uSteps = kMaxBicubicPatchSteps + 1;
    EXPECT_THROW(tessellateBicubicPatch(p), std::invalid_argument);
    p.uSteps = 0, p.vSteps = -1;
    EXPECT_THROW(tessellateBicubicPatch(p), std::invalid_argument);
}

// ------------------------------------------------------------ front ends

const char* const kPovPatch = R"(
bicubic_patch { type 1 flatness 0.01 u_steps 2 v_steps 3,
   <0, 0, 2>, <1, 0, 0>, <2, 0, 0>, <3, 0, -2>,
   <0, 1, 0>, <1, 1, 0>, <2, 1, 0>, <3, 1,  0>,
   <0, 2, 0>, <1, 2, 0>, <2, 2, 0>, <3, 2,  0>,
   <0, 3, 2>, <1, 3, 0>, <2, 3, 0>, <3, 3, -2>
   pigment { rgb 1 } translate <1, 0, 0> }
#declare P = <0, 3, 2>;
bicubic_patch { type 0 uv_vectors <0,0> <2,0> <2,2> <0,2>
   <0,0,0> <1,0,0> <2,0,0> <3,0,0> <0,1,0> <1,1,0> <2,1,0> <3,1,0>
   <0,2,0> <1,2,0> <2,2,0> <3,2,0> P <1,3,0> <2,3,0> <3,3,0> }
)";

TEST(PovBicubicPatch, ReadsPovRaysFormIntoAMesh) {
    Diagnostics diags;
    const std::optional<Scene> scene = loadPovSceneText(kPovPatch, "s.pov", diags);
    ASSERT_TRUE(scene) << diags.formatAll();
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    ASSERT_EQ(scene->objects.size(), 2u);
    const Mesh& a = std::get<Mesh>(scene->objects[0].shape);
    ASSERT_TRUE(a.patch && a.indexed);
    EXPECT_EQ(a.patch->type, 1);
    EXPECT_EQ(a.patch->flatness, 0.01);
    EXPECT_EQ(a.indexed->triangleCount(), size_t(4 * 8 * 2));
    EXPECT_EQ(a.patch->points[3], (Vec3{3, 0, -2}));
    const Mesh& b = std::get<Mesh>(scene->objects[1].shape);
    EXPECT_EQ(b.indexed->triangleCount(), 2u); // POV-Ray's default steps: one quad
    EXPECT_EQ(b.patch->points[12], (Vec3{0, 3, 2}));
    EXPECT_EQ(b.patch->uvCorners[2].u, 2.0f);
}

TEST(PovBicubicPatch, ObjectUvMappingMapsTheTexturesAfterIt) {
    // portfolio/allobjects.pov: `uv_mapping texture { pigment { checker ... scale 1/3 } }` in the patch.
    const std::string points = "<0,0,0> <1,0,0> <2,0,0> <3,0,0> <0,1,0> <1,1,0> <2,1,0> <3,1,0> "
                               "<0,2,0> <1,2,0> <2,2,0> <3,2,0> <0,3,0> <1,3,0> <2,3,0> <3,3,0>";
    Diagnostics diags;
    const std::optional<Scene> scene = loadPovSceneText(
        "bicubic_patch { type 1 " + points +
            " uv_mapping texture { pigment { checker rgb 0 rgb 1 scale 1/3 } } scale 5 }\n"
            "sphere { 0, 1 texture { pigment { checker rgb 0 rgb 1 } } uv_mapping }",
        "s.pov", diags);
    ASSERT_TRUE(scene) << diags.formatAll();
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    const Pigment& mapped = scene->objects[0].texture->pigment;
    EXPECT_TRUE(mapped.uvMapping);
    EXPECT_TRUE(mapped.children.at(0).uvMapping);
    EXPECT_NEAR(mapped.toWorld.point({1, 0, 0}).x, 1.0 / 3, 1e-12); // the object's scale 5 leaves it
    EXPECT_FALSE(scene->objects[1].texture->pigment.uvMapping);      // a texture before it is not mapped
}

TEST(PovBicubicPatch, MeshOfADeclaredMeshIsACopyOfIt) {
    // POV-Ray's `mesh { Name modifiers }` (camera/mesh_camera demos), here with a declared patch.
    const std::string points = "<0,0,0> <1,0,0> <2,0,0> <3,0,0> <0,1,0> <1,1,0> <2,1,0> <3,1,0> "
                               "<0,2,0> <1,2,0> <2,2,0> <3,2,0> <0,3,0> <1,3,0> <2,3,0> <3,3,0>";
    Diagnostics diags;
    const std::optional<Scene> scene = loadPovSceneText("#declare M = bicubic_patch { type 1 u_steps 1 " + points +
                                                            " translate x }\nmesh { M translate y }",
                                                        "s.pov", diags);
    ASSERT_TRUE(scene) << diags.formatAll();
    ASSERT_EQ(scene->objects.size(), 1u);
    const Mesh& m = std::get<Mesh>(scene->objects[0].shape);
    ASSERT_TRUE(m.patch);
    EXPECT_EQ(m.indexed->triangleCount(), 4u);
    EXPECT_EQ(scene->objects[0].transform.point({0, 0, 0}), (Vec3{1, 1, 0}));
}

TEST(DrtBicubicPatch, ParsesAndRoundTripsAsAPatch) {
    const std::string text = R"(
camera { location <0, 2, -8> look_at <0, 0, 0> }
light_source { <5, 10, -10>, rgb 1 }
bicubic_patch { type 1 flatness 0.5 u_steps 3 v_steps 1 uv_vectors <0, 0>, <1, 0>, <1, 0.5>, <0, 0.5>
  <0, 0, 2>, <1, 0, 0>, <2, 0, 0>, <3, 0, -2>,
  <0, 1, 0>, <1, 1, 0>, <2, 1, 0>, <3, 1, 0>,
  <0, 2, 0>, <1, 2, 0>, <2, 2, 0>, <3, 2, 0>,
  <0, 3, 2>, <1, 3, 0>, <2, 3, 0>, <3, 3, -2>
  pigment { rgb <1, 0, 0> } rotate <30, -60, 0> }
)";
    Diagnostics diags;
    const std::optional<Scene> scene = loadSceneText(text, "a.drt", diags, ".");
    ASSERT_TRUE(scene) << diags.formatAll();
    const Mesh& m = std::get<Mesh>(scene->objects.at(0).shape);
    ASSERT_TRUE(m.patch);
    EXPECT_EQ(m.indexed->triangleCount(), size_t(8 * 2 * 2));
    const std::string written = writeDrtScene(*scene);
    EXPECT_NE(written.find("bicubic_patch { type 1 flatness 0.5 u_steps 3 v_steps 1 uv_vectors <0, 0>, <1, 0>, "
                           "<1, 0.5>, <0, 0.5>"),
              std::string::npos)
        << written;
    Diagnostics again;
    const std::optional<Scene> reread = loadSceneText(written, "b.drt", again, ".");
    ASSERT_TRUE(reread) << again.formatAll() << written;
    EXPECT_EQ(writeDrtScene(*reread), written);
    const Mesh& back = std::get<Mesh>(reread->objects.at(0).shape);
    ASSERT_TRUE(back.patch);
    EXPECT_EQ(*back.patch, *m.patch);
    EXPECT_TRUE(sameIndexedMesh(*back.indexed, *m.indexed));
}

TEST(BicubicPatchErrors, BadPatchesAreErrorsWithLocations) {
    const std::string points = "<0,0,0> <1,0,0> <2,0,0> <3,0,0> <0,1,0> <1,1,0> <2,1,0> <3,1,0> "
                               "<0,2,0> <1,2,0> <2,2,0> <3,2,0> <0,3,0> <1,3,0> <2,3,0> <3,3,0>";
    const struct { std::string source; bool pov; const char* message; int line, column; } cases[] = {
        {"bicubic_patch { u_steps 2\n  " + points + " }", true,
         "bicubic_patch needs its 'type' (0 or 1) before the control points", 1, 1},
        {"bicubic_patch { type 2 " + points + " }", true, "the bicubic_patch type must be 0 or 1, got 2", 1, 22},
        {"bicubic_patch { type 1 u_steps 11 " + points + " }", true,
         "u_steps 11 is out of range (0 to 10)", 1, 32},
        {"bicubic_patch { type 1 v_steps -1 " + points + " }", true, "v_steps -1 is out of range (0 to 10)", 1, 32},
        {"bicubic_patch { type 1 <0,0,0> <1,0,0>\n }", true,
         "expected a value (a number, a vector <x, y, z> or a name), found '}'", 2, 2},
        {"bicubic_patch { type 1 flatness -1 <0,0,0>, <1,0,0> }", false,
         "the bicubic_patch flatness must not be negative, got -1", 1, 33},
        {"bicubic_patch { type 1 <0,0,0> <1,0,0> }", false, "expected ',' after the control point, found '<'", 1, 32},
    };
    for (const auto& c : cases) {
        Diagnostics diags;
        const bool loaded = c.pov ? bool(loadPovSceneText(c.source, "e.pov", diags))
                                  : bool(loadSceneText(c.source, "e.drt", diags, "."));
        EXPECT_FALSE(loaded) << c.source;
        test::expectErrorAt(diags, c.pov ? "e.pov" : "e.drt", c.line, c.column, c.message);
    }
}

} // namespace
} // namespace drt
