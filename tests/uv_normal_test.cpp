// uv_mapping on normals and on texture patterns (docs/meshes.md): the bump
// pattern at the surface's (u, v, 0), its tilt carried to the surface by the uv
// tangent frame (render/noise.h perturbNormalUv), checked against the spatial
// normal it must equal when uv space and space agree, under rotations, mirrors
// and scales of the uv layout; then on meshes in both dialects, through the
// writer, and on surfaces without uvs.
#include "accel/accel.h"
#include "lang/load.h"
#include "lang/writer.h"
#include "render/noise.h"
#include "render/render.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace drt {
namespace {

// A slope pattern (POV-Ray's `gradient x` normal) and a noise one.
Normal gradientNormal() {
    Normal n;
    n.pattern = PatternKind::Gradient;
    n.gradientAxis = {1, 0, 0};
    n.amount = 0.7;
    return n;
}

Normal bumpsNormal() {
    Normal n;
    n.pattern = PatternKind::Bumps;
    n.amount = 0.8;
    n.toWorld = Transform::scale(Vec3(0.15));
    return n;
}

void expectNear(const Vec3& a, const Vec3& b, double tolerance, const std::string& what) {
    EXPECT_NEAR(a.x, b.x, tolerance) << what;
    EXPECT_NEAR(a.y, b.y, tolerance) << what;
    EXPECT_NEAR(a.z, b.z, tolerance) << what;
}

const Vec3 kUvs[] = {{0.3, 0.4, 0}, {0.61, 0.07, 0}, {0.125, 0.93, 0}, {0.77, 0.52, 0}};

// With the frame dP/du = x, dP/dv = y and normal z, uv space is space: the
// uv-mapped normal is the spatial one at the point (u, v, 0).
TEST(UvNormal, WithTheIdentityFrameItIsTheSpatialNormal) {
    for (const Normal& n : {gradientNormal(), bumpsNormal()})
        for (const Vec3& uv : kUvs) {
            const Vec3 spatial = perturbNormal(n, uv, {0, 0, 1});
            EXPECT_GT(length(spatial - Vec3(0, 0, 1)), 1e-3) << "the pattern tilts the normal";
            expectNear(perturbNormalUv(n, uv, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}), spatial, 1e-12, "identity frame");
        }
}

// The uv layout turned a quarter round the normal (u along y, v along -x):
// the tilt turns with it. Scaled uniformly by 3: the slopes stay, as for an
// object scaled by 3. Mirrored (u along -x): the tilt is mirrored and still
// faces the normal's side.
TEST(UvNormal, TheTiltFollowsRotatedScaledAndMirroredLayouts) {
    for (const Normal& n : {gradientNormal(), bumpsNormal()})
        for (const Vec3& uv : kUvs) {
            const Vec3 s = perturbNormal(n, uv, {0, 0, 1});
            expectNear(perturbNormalUv(n, uv, {0, 1, 0}, {-1, 0, 0}, {0, 0, 1}), Vec3(-s.y, s.x, s.z), 1e-12,
                       "quarter turn");
            expectNear(perturbNormalUv(n, uv, {3, 0, 0}, {0, 3, 0}, {0, 0, 1}), s, 1e-12, "uniform scale");
            const Vec3 mirrored = perturbNormalUv(n, uv, {-1, 0, 0}, {0, 1, 0}, {0, 0, 1});
            expectNear(mirrored, Vec3(-s.x, s.y, s.z), 1e-12, "mirror");
            EXPECT_GT(mirrored.z, 0);
        }
}

// A slope along u tilts the normal along the gradient of u on the surface,
// which for a sheared layout is not dP/du: with dP/du = x and dP/dv = x + y,
// u grows along x - y (moving along dP/dv keeps u), so a pattern varying
// only in u tilts the normal in the x - y direction.
TEST(UvNormal, ASlopeAlongUTiltsAlongTheGradientOfUOnAShearedLayout) {
    const Normal n = gradientNormal();
    const Vec3 tilted = perturbNormalUv(n, {0.3, 0.4, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 1});
    ASSERT_GT(std::hypot(tilted.x, tilted.y), 1e-3);
    EXPECT_NEAR(tilted.x, -tilted.y, 1e-12);
    EXPECT_NEAR(length(tilted), 1, 1e-12);
}

TEST(UvNormal, ADegenerateFrameLeavesTheNormal) {
    const Normal n = bumpsNormal();
    for (const Vec3& uv : kUvs) {
        EXPECT_EQ(perturbNormalUv(n, uv, {0, 0, 0}, {0, 1, 0}, {0, 0, 1}), Vec3(0, 0, 1));
        EXPECT_EQ(perturbNormalUv(n, uv, {1, 0, 0}, {2, 0, 0}, {0, 0, 1}), Vec3(0, 0, 1));
        EXPECT_EQ(perturbNormalUv(n, uv, {NAN, 0, 0}, {0, 1, 0}, {0, 0, 1}), Vec3(0, 0, 1));
    }
}

// ---------------------------------------------------------------- scenes

std::optional<Scene> parse(const std::string& text, Diagnostics& diags, const std::string& name) {
    const std::string path = test::writeFile(test::tempDir() + "/" + name, text);
    return loadSceneFile(path, diags);
}

RenderResult render16(const Scene& scene) {
    RenderOptions options;
    options.width = options.height = 16;
    options.samplesPerPixel = 1;
    return render(scene, options);
}

double maxDifference(const RenderResult& a, const RenderResult& b) {
    double worst = 0;
    for (size_t i = 0; i < a.color.pixels.size(); ++i)
        worst = std::max(worst, double(std::fabs(a.color.pixels[i] - b.color.pixels[i])));
    return worst;
}

// A unit square whose uvs are its x, y, lit from the side so that bumps show,
// seen square on by an orthographic camera; `placed` moves the object.
std::string square(const std::string& normal, const std::string& placed) {
    return "camera { orthographic location <0.5, 0.5, -5> direction z right x up y }\n"
           "light_source { <-3, 4, -2> color rgb 1 }\n"
           "mesh2 {\n"
           "  vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }\n"
           "  uv_vectors { 4, <0,0>, <1,0>, <1,1>, <0,1> }\n"
           "  face_indices { 2, <0,2,1>, <0,3,2> }\n"
           "  pigment { color rgb 1 } finish { ambient 0 diffuse 1 }\n"
           "  normal { " + normal + " }\n" + placed + "}\n";
}

// On a mesh whose uvs are its object-space x and y, a uv-mapped normal is a
// spatial normal of the unmoved object: the square faces -z (its corners turn
// clockwise seen from the camera), so the third axis of its uv space, along
// the normal, is -z, and the equal spatial pattern is mirrored in z. Moved
// (turned about the view axis and scaled), the uv-mapped one stays glued to the
// surface as the spatial one moves with the object: the images agree in both
// dialects. The unmirrored spatial pattern gives another picture (the
// comparison can fail).
TEST(UvNormal, OnAMeshWhoseUvsAreItsXyItEqualsTheSpatialNormalAndMovesWithIt) {
    const std::string place = "  translate <-0.5, -0.5, 0> rotate <0, 0, 30> scale 1.4 translate <0.5, 0.5, 0>\n";
    for (const char* name : {"n.drt", "n.pov"}) {
        Diagnostics d1, d2, d3, d4;
        const auto uv = parse(square("uv_mapping bumps 0.9 scale 0.1", ""), d1, name);
        const auto spatial = parse(square("bumps 0.9 scale <0.1, 0.1, -0.1>", ""), d2, name);
        const auto uvMoved = parse(square("uv_mapping bumps 0.9 scale 0.1", place), d3, name);
        const auto spatialMoved = parse(square("bumps 0.9 scale <0.1, 0.1, -0.1>", place), d4, name);
        Diagnostics d5;
        const auto unmirrored = parse(square("bumps 0.9 scale 0.1", ""), d5, name);
        ASSERT_TRUE(unmirrored);
        ASSERT_TRUE(uv && spatial && uvMoved && spatialMoved) << d1.formatAll() << d3.formatAll();
        EXPECT_EQ(d1.formatAll().find("not supported"), std::string::npos) << d1.formatAll();
        const RenderResult a = render16(*uv), b = render16(*spatial);
        EXPECT_LT(maxDifference(a, b), 1e-5) << name;
        const RenderResult c = render16(*uvMoved), e = render16(*spatialMoved);
        EXPECT_LT(maxDifference(c, e), 1e-5) << name;
        // The bumps are there: the moved image is not the unmoved one.
        EXPECT_GT(maxDifference(a, c), 0.05) << name;
        EXPECT_GT(maxDifference(a, render16(*unmirrored)), 0.05) << name;
    }
}

// Mirrored uvs (u = 1 - x): the uv-mapped normal differs from the spatial one.
TEST(UvNormal, MirroredUvsGiveAnotherPicture) {
    Diagnostics d1, d2;
    std::string mirrored = square("uv_mapping bumps 0.9 scale 0.1", "");
    mirrored.replace(mirrored.find("<0,0>, <1,0>, <1,1>, <0,1>"), 26, "<1,0>, <0,0>, <0,1>, <1,1>");
    const auto uv = parse(mirrored, d1, "m.drt");
    const auto spatial = parse(square("bumps 0.9 scale 0.1", ""), d2, "m.drt");
    ASSERT_TRUE(uv && spatial) << d1.formatAll();
    EXPECT_GT(maxDifference(render16(*uv), render16(*spatial)), 0.05);
}

// A surface without uvs has nothing for a uv-mapped normal to vary over: the
// sphere renders as without the normal, with no NaN.
TEST(UvNormal, ASurfaceWithoutUvsShowsNoBumps) {
    const std::string scene = "camera { location <0, 0, -4> look_at 0 }\n"
                              "light_source { <-3, 4, -2> color rgb 1 }\n"
                              "sphere { 0, 1 pigment { color rgb 1 }";
    Diagnostics d1, d2;
    const auto bumped = parse(scene + " normal { uv_mapping bumps 1 scale 0.1 } }\n", d1, "s.drt");
    const auto plain = parse(scene + " }\n", d2, "s.drt");
    ASSERT_TRUE(bumped && plain) << d1.formatAll();
    const RenderResult a = render16(*bumped), b = render16(*plain);
    EXPECT_EQ(maxDifference(a, b), 0);
    for (float v : a.color.pixels) ASSERT_TRUE(std::isfinite(v));
}

// uv_mapping in a texture applies to its normal too; in front of a texture
// pattern (or among its modifiers) to the pattern: a checker of textures in uv
// space, where uv is mirrored in u against position (u = 1 - x).
TEST(UvNormal, TexturePatternsTakeUvMappingInBothDialects) {
    const char* body = R"(
camera { orthographic location <0.5, 0.5, -5> direction z right x up y }
mesh2 {
  vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }
  uv_vectors { 4, <1,0>, <0,0>, <0,1>, <1,1> }
  face_indices { 2, <0,2,1>, <0,3,2> }
  texture { PATTERN }
})";
    const std::string checker = "checker texture { pigment { color rgb <1,0,0> } finish { ambient 1 diffuse 0 } } "
                                "texture { pigment { color rgb <0,0,1> } finish { ambient 1 diffuse 0 } } scale 0.25";
    for (const char* name : {"p.drt", "p.pov"})
        for (const std::string& pattern : {"uv_mapping " + checker, checker + " uv_mapping"}) {
            std::string text = body;
            text.replace(text.find("PATTERN"), 7, pattern);
            Diagnostics diags;
            const auto scene = parse(text, diags, name);
            ASSERT_TRUE(scene && !diags.hasErrors()) << diags.formatAll();
            EXPECT_EQ(diags.formatAll().find("not supported"), std::string::npos) << diags.formatAll();
            EXPECT_TRUE(scene->objects.at(0).texture->pigment.uvMapping);
            RenderOptions options;
            options.width = options.height = 8;
            options.samplesPerPixel = 1;
            const RenderResult r = render(*scene, options);
            // Pixel (0, 7): x = y = 0.0625: uv (0.9375, 0.0625): cell (3, 0): blue.
            EXPECT_NEAR(r.color.at(0, 7, 2), 1, 1e-6) << name << " " << pattern;
            // Pixel (7, 7): uv (0.0625, 0.0625): cell (0, 0): red.
            EXPECT_NEAR(r.color.at(7, 7, 0), 1, 1e-6) << name << " " << pattern;
        }
}

TEST(UvNormal, UvMappingInATextureReachesItsNormalAndTheWriterKeepsBoth) {
    const std::string text = "camera { location <0, 0, -4> look_at 0 }\n"
                             "sphere { 0, 1 texture { uv_mapping pigment { checker scale 0.5 } "
                             "normal { bumps 0.4 scale 0.2 } } rotate <0, 30, 0> translate x }\n"
                             "sphere { 0, 1 normal { uv_mapping ripples 0.3 scale 0.5 } translate y }\n";
    Diagnostics diags;
    const auto scene = parse(text, diags, "w.drt");
    ASSERT_TRUE(scene && !diags.hasErrors()) << diags.formatAll();
    const auto check = [](const Scene& s, const std::string& what) {
        ASSERT_EQ(s.objects.size(), 2u) << what;
        const Texture& t0 = s.objects[0].texture;
        ASSERT_TRUE(t0.normal) << what;
        EXPECT_TRUE(t0.pigment.uvMapping) << what;
        EXPECT_TRUE(t0.normal->uvMapping) << what;
        // In uv space: the object's rotate and translate did not move it.
        expectNear(t0.normal->toWorld.point({1, 1, 1}), Vec3(0.2, 0.2, 0.2), 1e-12, what);
        const Texture& t1 = s.objects[1].texture;
        ASSERT_TRUE(t1.normal) << what;
        EXPECT_TRUE(t1.normal->uvMapping) << what;
        EXPECT_FALSE(t1.pigment.uvMapping) << what;
        expectNear(t1.normal->toWorld.point({1, 1, 1}), Vec3(0.5, 0.5, 0.5), 1e-12, what);
    };
    check(*scene, "read");
    const std::string written = writeDrtScene(*scene);
    Diagnostics again;
    const auto reread = parse(written, again, "w2.drt");
    ASSERT_TRUE(reread && !again.hasErrors()) << again.formatAll() << written;
    check(*reread, "written and read again");
}

} // namespace
} // namespace drt
