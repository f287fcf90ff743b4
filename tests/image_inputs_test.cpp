// Image inputs of POV-Ray scenes: height_field (a mesh from an image's grey
// values) and image_map pigments (texels, projections, interpolation), in the
// POV front end, the .drt language and the writer.
#include "assets/assets.h"
#include "core/diagnostics.h"
#include "image/srgb.h"
#include "lang/load.h"
#include "lang/writer.h"
#include "pov/load.h"
#include "render/image_pattern.h"
#include "render/pigment.h"
#include "render/render.h"
#include "scene/height_field.h"
#include "scene/image_map.h"
#include "test_support.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>

namespace drt {
namespace {

// Writes raw 8-bit samples (rows top first) as a PNG; returns its path.
std::string writePng8(const std::string& path, int w, int h, int channels, const std::vector<uint8_t>& bytes) {
    auto out = OIIO::ImageOutput::create(path);
    EXPECT_TRUE(out);
    OIIO::ImageSpec spec(w, h, channels, OIIO::TypeDesc::UINT8);
    EXPECT_TRUE(out->open(path, spec));
    EXPECT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, bytes.data()));
    out->close();
    return path;
}

std::string writePng16(const std::string& path, int w, int h, const std::vector<uint16_t>& values) {
    auto out = OIIO::ImageOutput::create(path);
    EXPECT_TRUE(out);
    OIIO::ImageSpec spec(w, h, 1, OIIO::TypeDesc::UINT16);
    EXPECT_TRUE(out->open(path, spec));
    EXPECT_TRUE(out->write_image(OIIO::TypeDesc::UINT16, values.data()));
    out->close();
    return path;
}

// 2x2 RGB: top row red, green; bottom row blue, white.
std::string quadrants(const std::string& dir) {
    return writePng8(dir + "/quad.png", 2, 2, 3, {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255});
}

Scene loadPov(const std::string& text, const std::string& dir, Diagnostics& diags) {
    std::optional<Scene> s = loadPovSceneText(text, "s.pov", diags, PovOptions{}, dir);
    EXPECT_TRUE(s) << diags.formatAll();
    if (s) {
        EXPECT_TRUE(resolveAssets(*s, diags)) << diags.formatAll();
    }
    return s ? *s : Scene{};
}

const Mesh& onlyMesh(const Scene& s) {
    static const Mesh none;
    if (s.objects.size() != 1) return ADD_FAILURE() << "expected one object", none;
    const Mesh* m = std::get_if<Mesh>(&s.objects[0].shape);
    if (!m) return ADD_FAILURE() << "not a mesh", none;
    return *m;
}

void expectColor(const ColorFT& c, double r, double g, double b, double f = 0, double t = 0) {
    EXPECT_NEAR(c.rgb.r, r, 1e-7);
    EXPECT_NEAR(c.rgb.g, g, 1e-7);
    EXPECT_NEAR(c.rgb.b, b, 1e-7);
    EXPECT_NEAR(c.filter, f, 1e-7);
    EXPECT_NEAR(c.transmit, t, 1e-7);
}

ImageMap loadedMap(const std::string& dir, const std::string& items) {
    Diagnostics diags;
    const Scene s = loadPov("#version 3.7; sphere { 0, 1 pigment { image_map { png \"quad.png\" " + items + " } } }",
                            dir, diags);
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    if (s.objects.empty() || !s.objects[0].texture->pigment.imageMap) return ADD_FAILURE() << "no image map", ImageMap{};
    EXPECT_EQ(s.objects[0].texture->pigment.pattern, PatternKind::ImageMap);
    return *s.objects[0].texture->pigment.imageMap;
}

// ------------------------------------------------------------ height_field

TEST(HeightField, GreyPngGivesOneVertexPerPixelAndTwoTrianglesPerCell) {
    const std::string dir = test::tempDir();
    // Rows top first: the top row lands at z = 1.
    writePng8(dir + "/hf.png", 3, 3, 1, {0, 51, 102, 153, 204, 255, 10, 20, 30});
    Diagnostics diags;
    const Scene s = loadPov("height_field { png \"hf.png\" }", dir, diags);
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    const Mesh& m = onlyMesh(s);
    ASSERT_EQ(m.vertices.size(), 9u);
    EXPECT_EQ(m.triangles.size(), 8u);
    EXPECT_TRUE(m.normals.empty());
    // POV-Ray: height = grey * 65535 / 65536 (an 8-bit byte b gives 257 b / 65536); x = column / 2, z = (2 - row) / 2.
    auto height = [](int byte) { return byte * 257 / 65536.0; };
    const int bytes[3][3] = {{0, 51, 102}, {153, 204, 255}, {10, 20, 30}};
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) {
            const Vec3& v = m.vertices[size_t(2 - row) * 3 + col];
            EXPECT_DOUBLE_EQ(v.x, col / 2.0);
            EXPECT_DOUBLE_EQ(v.z, (2 - row) / 2.0);
            EXPECT_NEAR(v.y, height(bytes[row][col]), 1e-12) << row << "," << col;
        }
}

TEST(HeightField, SixteenBitAndEightBitColourRules) {
    const std::string dir = test::tempDir();
    writePng16(dir + "/hf16.png", 2, 2, {0, 1000, 65535, 32768});
    // 8-bit colour: red is the high byte, green the low byte.
    writePng8(dir + "/hfc.png", 2, 2, 3, {1, 2, 0, 0, 0, 0, 0, 0, 0, 255, 255, 9});
    Diagnostics diags;
    const Scene s16 = loadPov("height_field { png \"hf16.png\" }", dir, diags);
    const Mesh& m16 = onlyMesh(s16);
    ASSERT_EQ(m16.vertices.size(), 4u);
    EXPECT_NEAR(m16.vertices[0].y, 65535 / 65536.0, 1e-12); // bottom-left: 65535
    EXPECT_NEAR(m16.vertices[1].y, 32768 / 65536.0, 1e-12);
    EXPECT_NEAR(m16.vertices[3].y, 1000 / 65536.0, 1e-12);
    const Scene sc = loadPov("height_field { png \"hfc.png\" }", dir, diags);
    const Mesh& mc = onlyMesh(sc);
    ASSERT_EQ(mc.vertices.size(), 4u);
    EXPECT_NEAR(mc.vertices[2].y, (1 * 256 + 2) / 65536.0, 1e-12); // top-left pixel at z = 1
    EXPECT_NEAR(mc.vertices[1].y, (255 * 256 + 255) / 65536.0, 1e-12);
}

TEST(HeightField, WaterLevelDropsCellsBelowIt) {
    // Heights 0 except one raised corner: cells touching it stay.
    std::vector<double> h(9, 0.0);
    h[8] = 0.8; // (x = 2, z = 2)
    const Mesh all = heightFieldMesh(h, 3, 3, false, 0.0);
    EXPECT_EQ(all.triangles.size(), 8u);
    const Mesh cut = heightFieldMesh(h, 3, 3, false, 0.5);
    // Only the upper triangle of the top-right cell has the raised corner.
    ASSERT_EQ(cut.triangles.size(), 1u);
    EXPECT_EQ(cut.triangles[0], (std::array<int, 3>{5, 7, 8}));
    // Via the POV front end.
    const std::string dir = test::tempDir();
    writePng8(dir + "/hf.png", 3, 3, 1, {0, 0, 255, 0, 0, 0, 0, 0, 0});
    Diagnostics diags;
    const Scene s = loadPov("height_field { png \"hf.png\" water_level 0.5 }", dir, diags);
    EXPECT_EQ(onlyMesh(s).triangles.size(), 1u);
}

TEST(HeightField, SmoothGivesUnitVertexNormalsPointingUpOnAPlane) {
    std::vector<double> h(16);
    for (int z = 0; z < 4; ++z)
        for (int x = 0; x < 4; ++x) h[size_t(z) * 4 + x] = 0.25 * x; // a slope rising along x
    const Mesh m = heightFieldMesh(h, 4, 4, true, 0.0);
    ASSERT_EQ(m.normals.size(), 16u);
    EXPECT_EQ(m.normalIndices, m.triangles);
    // The slope y = 0.75 x (x in grid units / 3): normal (-0.75, 1, 0) / 1.25.
    for (const Vec3& n : m.normals) {
        EXPECT_NEAR(n.x, -0.6, 1e-12);
        EXPECT_NEAR(n.y, 0.8, 1e-12);
        EXPECT_NEAR(n.z, 0.0, 1e-12);
    }
    // Every face normal points up.
    for (const auto& t : m.triangles)
        EXPECT_GT(cross(m.vertices[t[1]] - m.vertices[t[0]], m.vertices[t[2]] - m.vertices[t[0]]).y, 0);
}

TEST(HeightField, MissingImageIsAnErrorAtTheFileName) {
    Diagnostics diags;
    const auto s = loadPovSceneText("sphere { 0, 1 }\nheight_field {  png \"nope.png\" }", "s.pov", diags,
                                    PovOptions{}, test::tempDir());
    EXPECT_FALSE(s);
    EXPECT_NE(diags.formatAll().find("s.pov:2:21"), std::string::npos) << diags.formatAll();
    EXPECT_NE(diags.formatAll().find("nope.png"), std::string::npos);
}

TEST(HeightField, UnreadableImageIsAnError) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/bad.png", "not a png");
    Diagnostics diags;
    // The file is found while parsing and decoded after it (assets/assets.h),
    // the error still pointing at the file name.
    auto s = loadPovSceneText("height_field { png \"bad.png\" }", "s.pov", diags, PovOptions{}, dir);
    ASSERT_TRUE(s) << diags.formatAll();
    EXPECT_FALSE(resolveAssets(*s, diags));
    EXPECT_NE(diags.formatAll().find("s.pov:1:20"), std::string::npos) << diags.formatAll();
}

// The function form samples the function (its values: function_test.cpp).
TEST(HeightField, FunctionFormIsAMeshOfTheFunctionsSamples) {
    Diagnostics diags;
    const Scene s = loadPov("height_field { function 10, 10 { x * y } smooth }\nsphere { 0, 1 }", ".", diags);
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    ASSERT_EQ(s.objects.size(), 2u);
    const Mesh* m = std::get_if<Mesh>(&s.objects[0].shape);
    ASSERT_TRUE(m);
    EXPECT_EQ(m->vertices.size(), 100u);
    EXPECT_EQ(m->normals.size(), 100u); // smooth
}

// ------------------------------------------------------------ image_map

TEST(ImageMap, PlanarRepeatsWithImageBottomAtYZero) {
    const std::string dir = test::tempDir();
    quadrants(dir);
    const ImageMap m = loadedMap(dir, "");
    ASSERT_EQ(m.width, 2);
    expectColor(imageMapColor(m, {0.25, 0.25, 0}), 0, 0, 1); // bottom-left: blue
    expectColor(imageMapColor(m, {0.75, 0.25, 7}), 1, 1, 1); // z is ignored
    expectColor(imageMapColor(m, {0.25, 0.75, 0}), 1, 0, 0);
    expectColor(imageMapColor(m, {0.75, 0.75, 0}), 0, 1, 0);
    expectColor(imageMapColor(m, {1.25, 0.75, 0}), 1, 0, 0);  // repeated
    expectColor(imageMapColor(m, {-0.25, -0.75, 0}), 1, 1, 1); // repeated below and left
}

TEST(ImageMap, OnceIsClearOutsideTheUnitSquare) {
    const std::string dir = test::tempDir();
    quadrants(dir);
    const ImageMap m = loadedMap(dir, "once");
    EXPECT_TRUE(m.once);
    expectColor(imageMapColor(m, {0.75, 0.75, 0}), 0, 1, 0);
    expectColor(imageMapColor(m, {1.25, 0.75, 0}), 1, 1, 1, 0, 1);
    expectColor(imageMapColor(m, {0.5, -0.1, 0}), 1, 1, 1, 0, 1);
}

TEST(ImageMap, SphericalMapsLongitudeAndLatitude) {
    const std::string dir = test::tempDir();
    quadrants(dir);
    const ImageMap m = loadedMap(dir, "map_type 1");
    EXPECT_EQ(m.projection, ImageMap::Projection::Spherical);
    // +x is u = 0 (left column); the northern half is the top row.
    expectColor(imageMapColor(m, {1, 0.5, 0}), 1, 0, 0);
    expectColor(imageMapColor(m, {1, -0.5, 0.01}), 0, 0, 1);
    // Half a turn round (towards +z then -x) is the right column.
    expectColor(imageMapColor(m, {-1, 0.5, -0.01}), 0, 1, 0);
    expectColor(imageMapColor(m, {0.01, -0.5, -1}), 1, 1, 1); // three quarters round
    expectColor(imageMapColor(m, {0.3, 0.2, 0.7}), 1, 0, 0);  // a quarter of a turn is still u < 0.5
}

TEST(ImageMap, CylindricalAndTorusProjections) {
    const std::string dir = test::tempDir();
    quadrants(dir);
    const ImageMap c = loadedMap(dir, "map_type 2");
    expectColor(imageMapColor(c, {2, 0.75, 0.01}), 1, 0, 0);   // height 0.75: top row; angle ~0: left
    expectColor(imageMapColor(c, {-2, 0.25, -0.01}), 1, 1, 1); // height 0.25: bottom row; just past half a turn: right
    const ImageMap t = loadedMap(dir, "map_type 5");
    // Just above the tube's outer equator the angle round the tube is just past half a turn: the top row.
    expectColor(imageMapColor(t, {1.25, 0.01, 0.001}), 1, 0, 0);
}

TEST(ImageMap, BilinearInterpolationBetweenTexelCentres) {
    const std::string dir = test::tempDir();
    writePng8(dir + "/quad.png", 2, 1, 1, {0, 255}); // black | white
    const ImageMap m = loadedMap(dir, "interpolate 2");
    EXPECT_EQ(m.interpolation, ImageMap::Interpolation::Bilinear);
    // Texel centres at x = 0.25 and 0.75; at x = 0.375 a quarter of the way from black to white.
    expectColor(imageMapColor(m, {0.375, 0.5, 0}), 0.25, 0.25, 0.25);
    expectColor(imageMapColor(m, {0.5, 0.5, 0}), 0.5, 0.5, 0.5);
    expectColor(imageMapColor(m, {0.75, 0.5, 0}), 1, 1, 1);
    // Repeating: halfway between the right texel and the next tile's left one.
    expectColor(imageMapColor(m, {1.0, 0.5, 0}), 0.5, 0.5, 0.5);
}

TEST(ImageMap, BicubicHitsTexelCentresAndReproducesALinearRamp) {
    const std::string dir = test::tempDir();
    // A linear ramp 0, 1/3, 2/3, 1 (gamma 1: as stored) repeated: Catmull-Rom is exact on the
    // ramp's inner span, where the four texels it uses are all on the ramp.
    writePng8(dir + "/quad.png", 4, 1, 1, {0, 85, 170, 255});
    const ImageMap m = loadedMap(dir, "interpolate 3 gamma 1");
    EXPECT_EQ(m.interpolation, ImageMap::Interpolation::Bicubic);
    expectColor(imageMapColor(m, {0.375, 0.5, 0}), 85 / 255.0, 85 / 255.0, 85 / 255.0); // texel 1's centre
    // Halfway between texels 1 and 2 (x = 0.5): (85 + 170) / 2.
    expectColor(imageMapColor(m, {0.5, 0.5, 0}), 0.5, 0.5, 0.5);
    // A quarter of the way from texel 1 to 2: weights -9/128, 111/128, 29/128, -3/128 on
    // 0, 85, 170, 255, which is the ramp's own value 1.25 / 3.
    const double v = (111 * 85 + 29 * 170 - 3 * 255) / 128.0 / 255.0;
    EXPECT_NEAR(v, 1.25 / 3, 1e-15);
    expectColor(imageMapColor(m, {0.375 + 0.0625, 0.5, 0}), v, v, v);
}

TEST(ImageMap, FilterAndTransmitAllAndAlpha) {
    const std::string dir = test::tempDir();
    quadrants(dir);
    const ImageMap m = loadedMap(dir, "filter all 0.3 transmit all 0.2");
    expectColor(imageMapColor(m, {0.25, 0.25, 0}), 0, 0, 1, 0.3, 0.2);
    // Alpha 51/255 is transmit 1 - 0.2.
    writePng8(dir + "/quad.png", 1, 1, 4, {255, 255, 255, 51});
    const ImageMap a = loadedMap(dir, "");
    expectColor(imageMapColor(a, {0.5, 0.5, 0}), 1, 1, 1, 0, 0.8);
}

TEST(ImageMap, EightBitFilesAreDecodedFromSrgbUnlessGammaIsGiven) {
    const std::string dir = test::tempDir();
    writePng8(dir + "/quad.png", 1, 1, 1, {128});
    const ImageMap srgb = loadedMap(dir, "");
    const double v = srgbDecode(128 / 255.0);
    expectColor(imageMapColor(srgb, {0.5, 0.5, 0}), v, v, v);
    const ImageMap linear = loadedMap(dir, "gamma 1.0");
    expectColor(imageMapColor(linear, {0.5, 0.5, 0}), 128 / 255.0, 128 / 255.0, 128 / 255.0);
    // A file that states its gamma (PNG gAMA) is decoded with it unless the scene gives one.
    {
        auto out = OIIO::ImageOutput::create(dir + "/quad.png");
        OIIO::ImageSpec spec(1, 1, 1, OIIO::TypeDesc::UINT8);
        spec.attribute("oiio:ColorSpace", "Gamma1.8");
        spec.attribute("oiio:Gamma", 1.8f);
        const uint8_t byte = 128;
        ASSERT_TRUE(out->open(dir + "/quad.png", spec) && out->write_image(OIIO::TypeDesc::UINT8, &byte));
        out->close();
    }
    const double g18 = std::pow(128 / 255.0, double(1.8f));
    expectColor(imageMapColor(loadedMap(dir, ""), {0.5, 0.5, 0}), g18, g18, g18);
    expectColor(imageMapColor(loadedMap(dir, "gamma 1"), {0.5, 0.5, 0}), 128 / 255.0, 128 / 255.0, 128 / 255.0);
    writePng8(dir + "/quad.png", 1, 1, 1, {128});
    // Through evaluatePigment, with the pigment's transform (scale 2: texel 0.5 of the map at x = 1).
    Diagnostics diags;
    const Scene s = loadPov("#version 3.7; sphere { 0, 1 pigment { image_map { png \"quad.png\" gamma 2 } scale 2 } }", dir,
                            diags);
    const double g = std::pow(128 / 255.0, 2.0);
    expectColor(evaluatePigment(s.objects[0].texture->pigment, {1, 1, 0}), g, g, g);
}

TEST(ImageMap, MissingFileIsAnErrorInBothLanguages) {
    const std::string dir = test::tempDir();
    Diagnostics pov;
    EXPECT_FALSE(loadPovSceneText("sphere { 0, 1\n  pigment { image_map { png \"gone.png\" } } }", "s.pov", pov,
                                  PovOptions{}, dir));
    EXPECT_NE(pov.formatAll().find("s.pov:2:29"), std::string::npos) << pov.formatAll();
    Diagnostics drt;
    EXPECT_FALSE(loadSceneText("sphere { 0, 1\n  pigment { image_map { \"gone.png\" } } }", "t.drt", drt, dir));
    EXPECT_NE(drt.formatAll().find("t.drt:2:25"), std::string::npos) << drt.formatAll();
    EXPECT_NE(drt.formatAll().find("gone.png"), std::string::npos);
}

TEST(ImageMap, UnreadableFileIsAnErrorAndBareNamesGetImageExtensions) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/bad.png", "not an image");
    Diagnostics diags;
    auto bad = loadPovSceneText("sphere { 0, 1 pigment { image_map { png \"bad.png\" } } }", "s.pov", diags,
                                PovOptions{}, dir);
    ASSERT_TRUE(bad) << diags.formatAll();
    EXPECT_FALSE(resolveAssets(*bad, diags));
    EXPECT_NE(diags.formatAll().find("s.pov:1:41"), std::string::npos) << diags.formatAll();
    // POV-Ray's "sign" finds sign.png (advanced/cliche/cliche.pov relies on it).
    quadrants(dir);
    Diagnostics ok;
    const Scene s = loadPov("sphere { 0, 1 pigment { image_map { \"quad\" } } }", dir, ok);
    ASSERT_EQ(s.objects.size(), 1u);
    ASSERT_TRUE(s.objects[0].texture->pigment.imageMap);
    EXPECT_EQ(std::filesystem::path(s.objects[0].texture->pigment.imageMap->path).filename(), "quad.png");
}

TEST(ImageMap, PovUnknownSettingsAreWarnings) {
    const std::string dir = test::tempDir();
    quadrants(dir);
    Diagnostics diags;
    const Scene s = loadPov("sphere { 0, 1 pigment { image_map { png \"quad.png\" map_type 7 interpolate 9 "
                            "filter 1, 0.5 } } }", dir, diags);
    EXPECT_EQ(diags.warningCount(), 3) << diags.formatAll();
    ASSERT_TRUE(s.objects[0].texture->pigment.imageMap);
    EXPECT_EQ(s.objects[0].texture->pigment.imageMap->projection, ImageMap::Projection::Planar);
    EXPECT_EQ(s.objects[0].texture->pigment.imageMap->interpolation, ImageMap::Interpolation::None);
}

TEST(ImageMap, DrtBadSettingsAreErrors) {
    const std::string dir = test::tempDir();
    quadrants(dir);
    Diagnostics diags;
    EXPECT_FALSE(loadSceneText("sphere { 0, 1 pigment { image_map { \"quad.png\" map_type 3 } } }", "t.drt", diags, dir));
    EXPECT_NE(diags.formatAll().find("t.drt:1:57"), std::string::npos) << diags.formatAll();
    Diagnostics more;
    EXPECT_FALSE(loadSceneText("sphere { 0, 1 pigment { image_map { \"quad.png\" filter 0.5 } } }", "t.drt", more, dir));
}

TEST(ImageMap, DrtWriterRoundTrip) {
    const std::string dir = test::tempDir();
    quadrants(dir);
    Diagnostics diags;
    const auto scene = loadSceneText(
        "sphere { 0, 1 pigment { image_map { \"quad.png\" map_type 2 once interpolate 4 filter all 0.25 "
        "transmit all 0.5 gamma 1.8 } scale 3 } }",
        "t.drt", diags, dir);
    ASSERT_TRUE(scene) << diags.formatAll();
    const std::string text = writeDrtScene(*scene);
    EXPECT_TRUE(drtInexpressible(*scene).empty());
    Diagnostics again;
    const auto back = loadSceneText(text, "back.drt", again, "/");
    ASSERT_TRUE(back) << again.formatAll() << "\n" << text;
    const Pigment& a = scene->objects[0].texture->pigment;
    const Pigment& b = back->objects[0].texture->pigment;
    ASSERT_TRUE(b.imageMap);
    EXPECT_EQ(b.imageMap->path, a.imageMap->path);
    EXPECT_EQ(b.imageMap->projection, ImageMap::Projection::Cylindrical);
    EXPECT_TRUE(b.imageMap->once);
    EXPECT_EQ(b.imageMap->interpolation, ImageMap::Interpolation::NormalizedDistance);
    EXPECT_EQ(b.imageMap->filterAll, 0.25);
    EXPECT_EQ(b.imageMap->transmitAll, 0.5);
    EXPECT_EQ(b.imageMap->gamma, 1.8);
    EXPECT_EQ(b.imageMap->rgbt, a.imageMap->rgbt);
    for (const Vec3 p : {Vec3{0.3, 1.2, -0.4}, Vec3{2.0, 0.5, 1.0}})
        EXPECT_EQ(evaluatePigment(a, p), evaluatePigment(b, p));
    EXPECT_EQ(writeDrtScene(*back), text);
}

TEST(ImageMap, PovImageMapConvertsAndRoundTrips) {
    const std::string dir = test::tempDir();
    quadrants(dir);
    Diagnostics diags;
    const Scene s = loadPov("#version 3.7; plane { z, 0 pigment { image_map { png \"quad.png\" interpolate 2 once } } }",
                            dir, diags);
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    const std::string text = writeDrtScene(s);
    Diagnostics again;
    const auto back = loadSceneText(text, "back.drt", again, "/");
    ASSERT_TRUE(back) << again.formatAll() << "\n" << text;
    const Vec3 p{0.4, 0.3, 0};
    const Scene backRead = test::withAssets(*back);
    EXPECT_EQ(evaluatePigment(backRead.objects[0].texture->pigment, p), evaluatePigment(s.objects[0].texture->pigment, p));
}

TEST(ImageMap, RenderRefusesAnImageThatWasNotRead) {
    const std::string dir = test::tempDir();
    quadrants(dir);
    Diagnostics diags;
    const auto s = loadPovSceneText("sphere { 0, 1 pigment { image_map { png \"quad.png\" } } }", "s.pov", diags,
                                    PovOptions{}, dir);
    ASSERT_TRUE(s) << diags.formatAll();
    EXPECT_FALSE(assetsResolved(*s));
    RenderOptions options;
    options.width = options.height = 4;
    EXPECT_THROW(render(*s, options), RenderError);
    EXPECT_TRUE(assetsResolved(test::withAssets(*s)));
}

// ------------------------------------------------------------ image_pattern

// The pattern value at p of the only object's pigment, through a colour map from black to white.
double patternValue(const Scene& s, const Vec3& p) {
    if (s.objects.empty()) return ADD_FAILURE() << "no object", -1;
    const Pigment& pigment = s.objects[0].texture->pigment;
    EXPECT_EQ(pigment.pattern, PatternKind::ImagePattern);
    return evaluatePigment(pigment, p).rgb.g;
}

TEST(ImagePattern, ValueIsTheGreyOfTheFilesOwnNumbers) {
    // Measured on POV-Ray 3.7: 0.297 r + 0.589 g + 0.114 b of the stored values, alpha ignored.
    const std::string dir = test::tempDir();
    quadrants(dir);
    Diagnostics diags;
    const Scene s = loadPov("#version 3.7; global_settings { assumed_gamma 1 }\n"
                            "plane { z, 0 pigment { image_pattern { png \"quad.png\" } "
                            "color_map { [0 rgb 0] [1 rgb 1] } } }",
                            dir, diags);
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    EXPECT_NEAR(patternValue(s, {0.25, 0.75, 0}), 0.297, 1e-6); // red
    EXPECT_NEAR(patternValue(s, {0.75, 0.75, 0}), 0.589, 1e-6); // green
    EXPECT_NEAR(patternValue(s, {0.25, 0.25, 0}), 0.114, 1e-6); // blue
    EXPECT_NEAR(patternValue(s, {1.75, 0.25, 3}), 1.0, 1e-6);   // white, repeated, z ignored
    // A grey of 128 is 128/255, not its sRGB-decoded 0.216; an alpha channel changes nothing.
    writePng8(dir + "/grey.png", 2, 1, 2, {128, 255, 64, 0});
    Diagnostics more;
    const Scene g = loadPov("#version 3.7; global_settings { assumed_gamma 1 }\n"
                            "plane { z, 0 pigment { image_pattern { png \"grey.png\" once } } }",
                            dir, more);
    EXPECT_NEAR(patternValue(g, {0.25, 0.5, 0}), 128 / 255.0, 1e-6);
    EXPECT_NEAR(patternValue(g, {0.75, 0.5, 0}), 64 / 255.0, 1e-6);
    EXPECT_EQ(patternValue(g, {1.25, 0.5, 0}), 0); // off a `once` map
}

TEST(ImagePattern, DrtRoundTripAndUseAlpha) {
    const std::string dir = test::tempDir();
    quadrants(dir);
    Diagnostics diags;
    const auto scene = loadSceneText(
        "sphere { 0, 1 pigment { image_pattern { \"quad.png\" interpolate 2 } "
        "colour_map { [0, rgb <1, 0, 0>] [1, rgb <0, 0, 1>] } scale 2 } }",
        "t.drt", diags, dir);
    ASSERT_TRUE(scene) << diags.formatAll();
    const std::string text = writeDrtScene(*scene);
    EXPECT_NE(text.find("image_pattern {"), std::string::npos) << text;
    EXPECT_TRUE(drtInexpressible(*scene).empty());
    Diagnostics again;
    const auto back = loadSceneText(text, "back.drt", again, "/");
    ASSERT_TRUE(back) << again.formatAll() << "\n" << text;
    EXPECT_EQ(writeDrtScene(*back), text);
    const Scene a = test::withAssets(*scene), b = test::withAssets(*back);
    for (const Vec3 p : {Vec3{0.3, 1.2, -0.4}, Vec3{2.0, 0.5, 1.0}})
        EXPECT_EQ(evaluatePigment(a.objects[0].texture->pigment, p), evaluatePigment(b.objects[0].texture->pigment, p));
    // use_alpha: a warning in a .pov scene, a located error in .drt.
    Diagnostics pov;
    loadPov("plane { z, 0 pigment { image_pattern { png \"quad.png\" use_alpha } } }", dir, pov);
    EXPECT_EQ(pov.warningCount(), 1) << pov.formatAll();
    Diagnostics drt;
    EXPECT_FALSE(loadSceneText("plane { z, 0\n  pigment { image_pattern { \"quad.png\" use_alpha } } }", "t.drt", drt, dir));
    test::expectErrorAt(drt, "t.drt", 2, 40, "image_pattern's use_alpha is not supported; the pattern is the image's grey");
    Diagnostics missing;
    EXPECT_FALSE(loadSceneText("plane { z, 0\n  pigment { image_pattern { \"gone.png\" } } }", "t.drt", missing, dir));
    EXPECT_NE(missing.formatAll().find("t.drt:2:29"), std::string::npos) << missing.formatAll();
}

} // namespace
} // namespace drt
