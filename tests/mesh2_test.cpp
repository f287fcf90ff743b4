// POV-Ray's mesh2 and `mesh { triangle ... }` in both dialects, read into the
// compact mesh model files use (scene/indexed_mesh.h): the arrays they give,
// per-face and per-corner textures and uv_vectors at known pixels, sharing
// between copies, the writer's mesh2 text reading back to the same mesh, and
// every error located.
#include "lang/load.h"
#include "render/render.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fmt/format.h>
#include <cstdio>
#include <cmath>
#include <cstring>
#include <random>

namespace drt {
namespace {

std::optional<Scene> parse(const std::string& text, Diagnostics& diags,
                           const std::string& name = "scene.pov") {
    const std::string path = test::writeFile(test::tempDir() + "/" + name, text);
    return loadSceneFile(path, diags);
}

const IndexedMesh& indexedOf(const Scene& scene, size_t i = 0) {
    const Mesh& mesh = std::get<Mesh>(scene.objects.at(i).shape);
    EXPECT_TRUE(mesh.indexed);
    return *mesh.indexed;
}

// 8 x 8 pixels, one sample each.
RenderResult render8x8(const Scene& scene) {
    RenderOptions options;
    options.width = options.height = 8;
    options.samplesPerPixel = 1;
    return render(scene, options);
}

// A unit square in x-y facing -z (two faces) seen by an orthographic camera
// that fills 8 x 8 pixels with it; ambient-only finishes show the pigments.
const char* kCamera = "camera { orthographic location <0.5, 0.5, -5> direction z right x up y }\n";

TEST(Mesh2, ArraysAreTheListsWithTheirIndices) {
    Diagnostics diags;
    const auto scene = parse(R"(
mesh2 {
  vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }
  normal_vectors { 2, <0,0,-1>, <0,0,-2> }
  uv_vectors { 3, <0,0>, <1,0>, <0.5,1> }
  texture_list { 2, texture { pigment { rgb <1,0,0> } } texture { pigment { rgb <0,0,1> } } }
  face_indices { 2, <0,2,1>, 1, <0,3,2>, 0, 1, 1 }
  normal_indices { 2, <0,0,1>, <1,1,1> }
  uv_indices { 2, <0,1,2>, <2,1,0> }
})",
                             diags);
    ASSERT_TRUE(scene && !diags.hasErrors()) << diags.formatAll();
    const IndexedMesh& m = indexedOf(*scene);
    EXPECT_EQ(m.positions.size(), 4u);
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 2, 1, 0, 3, 2}));
    EXPECT_EQ(m.normalIndices, (std::vector<uint32_t>{0, 0, 1, 1, 1, 1}));
    EXPECT_EQ(m.uvIndices, (std::vector<uint32_t>{0, 1, 2, 2, 1, 0}));
    EXPECT_EQ(m.uvs[2].u, 0.5f);
    EXPECT_EQ(m.normals[1].z, -2.0f);
    // One index textures the face; three texture its corners.
    EXPECT_EQ(m.faceTextures, (std::vector<uint32_t>{1, 1, 1, 0, 1, 1}));
    EXPECT_EQ(std::get<Mesh>(scene->objects[0].shape).textures.size(), 2u);
    EXPECT_EQ(validateIndexedMesh(m, 2), "");
}

TEST(Mesh2, WithoutIndexListsNormalsAndUvsFollowTheVertices) {
    Diagnostics diags;
    const auto scene = parse(R"(
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  normal_vectors { 3, <0,0,-1>, <0,0,-1>, <0,0,-1> }
  uv_vectors { 3, <0,0>, <1,0>, <0,1> }
  face_indices { 1, <0,1,2> }
})",
                             diags);
    ASSERT_TRUE(scene && !diags.hasErrors()) << diags.formatAll();
    const IndexedMesh& m = indexedOf(*scene);
    EXPECT_TRUE(m.normalIndices.empty());
    EXPECT_TRUE(m.uvIndices.empty());
    EXPECT_TRUE(m.faceTextures.empty()); // no texture indices: the object's texture
}

// Face 0 (lower right, x > y) red, face 1 (upper left) blue, at every pixel.
TEST(Mesh2, PerFaceTexturesShowOnTheirFaces) {
    for (const char* dialect : {"pov", "drt"}) {
        Diagnostics diags;
        const auto scene = parse(std::string(kCamera) + R"(
mesh2 {
  vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }
  texture_list { 2,
    texture { pigment { color rgb <1,0,0> } finish { ambient 1 diffuse 0 } }
    texture { pigment { color rgb <0,0,1> } finish { ambient 1 diffuse 0 } } }
  face_indices { 2, <0,2,1>, 0, <0,3,2>, 1 }
  pigment { color rgb <0,1,0> }
})",
                                 diags, std::string("faces.") + dialect);
        ASSERT_TRUE(scene && !diags.hasErrors()) << dialect << diags.formatAll();
        const RenderResult r = render8x8(*scene);
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x) {
                if (x == 7 - y)
                    continue;                      // on the diagonal
                const bool lowerRight = x > 7 - y; // image y grows downward
                EXPECT_NEAR(r.color.at(x, y, 0), lowerRight ? 1 : 0, 1e-6) << dialect << " " << x << "," << y;
                EXPECT_NEAR(r.color.at(x, y, 2), lowerRight ? 0 : 1, 1e-6) << dialect << " " << x << "," << y;
                EXPECT_NEAR(r.color.at(x, y, 1), 0, 1e-6);
            }
    }
}

// Corner textures red, green, blue on one triangle: each pixel is the
// barycentric blend of the three, the closed form w0 red + w1 green + w2 blue.
TEST(Mesh2, CornerTexturesBlendByBarycentricWeight) {
    Diagnostics diags;
    const auto scene = parse(std::string(kCamera) + R"(
#declare F = finish { ambient 1 diffuse 0 }
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  texture_list { 3, texture { pigment { rgb x } finish { F } } texture { pigment { rgb y } finish { F } }
                    texture { pigment { rgb z } finish { F } } }
  face_indices { 1, <0,1,2>, 0, 1, 2 }
})",
                             diags);
    ASSERT_TRUE(scene && !diags.hasErrors()) << diags.formatAll();
    const RenderResult r = render8x8(*scene);
    // The one sample of pixel (px, py) lies within the pixel (jittered): at
    // x = (px + a) / 8, y = 1 - (py + b) / 8 with a, b in [0, 1), weights
    // (1 - x - y, x, y). So red + green + blue = 1 exactly, green is x and
    // blue is y to within a pixel (1/8).
    int inside = 0;
    for (int py = 0; py < 8; ++py)
        for (int px = 0; px + 1 < py; ++px) { // x + y < (px + 1) / 8 + 1 - py / 8 < 1: inside
            const double red = r.color.at(px, py, 0), green = r.color.at(px, py, 1),
                         blue = r.color.at(px, py, 2);
            EXPECT_NEAR(red + green + blue, 1, 1e-5) << px << "," << py;
            EXPECT_GE(green, px / 8.0 - 1e-6);
            EXPECT_LE(green, (px + 1) / 8.0 + 1e-6);
            EXPECT_GE(blue, 1 - (py + 1) / 8.0 - 1e-6);
            EXPECT_LE(blue, 1 - py / 8.0 + 1e-6);
            ++inside;
        }
    EXPECT_EQ(inside, 21);
}

// uv_vectors with uv_mapping: a checker of cells 1/4 in uv space, where uv is
// mirrored in u against position (u = 1 - x), so the cell colours differ from
// the spatial checker's.
TEST(Mesh2, UvVectorsPlaceAUvMappedChecker) {
    Diagnostics diags;
    const auto scene = parse(std::string(kCamera) + R"(
mesh2 {
  vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }
  uv_vectors { 4, <1,0>, <0,0>, <0,1>, <1,1> }
  face_indices { 2, <0,2,1>, <0,3,2> }
  pigment { uv_mapping checker color rgb <1,0,0>, color rgb <0,0,1> scale 0.25 }
  finish { ambient 1 diffuse 0 }
})",
                             diags);
    ASSERT_TRUE(scene && !diags.hasErrors()) << diags.formatAll();
    const RenderResult r = render8x8(*scene);
    // Pixel (0, 7): x = 0.0625, y = 0.0625: uv (0.9375, 0.0625): cell (3, 0): blue.
    EXPECT_NEAR(r.color.at(0, 7, 2), 1, 1e-6);
    // Pixel (7, 7): uv (0.0625, 0.0625): cell (0, 0): red.
    EXPECT_NEAR(r.color.at(7, 7, 0), 1, 1e-6);
}

TEST(MeshTriangles, OwnTexturesAndUvVectorsInBothDialects) {
    const char* body = R"(
mesh {
  triangle { <0,0,0>, <1,1,0>, <1,0,0> uv_vectors <0,0>, <1,1>, <1,0>
             texture { pigment { color rgb <1,0,0> } finish { ambient 1 diffuse 0 } } }
  triangle { <0,0,0>, <0,1,0>, <1,1,0> }
  pigment { color rgb <0,0,1> } finish { ambient 1 diffuse 0 }
})";
    for (const char* name : {"t.pov", "t.drt"}) {
        Diagnostics diags;
        const auto scene = parse(std::string(kCamera) + body, diags, name);
        ASSERT_TRUE(scene && !diags.hasErrors()) << name << diags.formatAll();
        const IndexedMesh& m = indexedOf(*scene);
        EXPECT_EQ(m.triangleCount(), 2u);
        EXPECT_EQ(m.faceTextures,
                  (std::vector<uint32_t>{0, 0, 0, kObjectTexture, kObjectTexture, kObjectTexture}));
        ASSERT_EQ(m.uvs.size(), 6u);
        EXPECT_EQ(m.uvs[1].u, 1.0f);
        // The triangle without uv_vectors has POV-Ray's <0,0>, <1,0>, <1,1>.
        EXPECT_EQ(m.uvs[4].u, 1.0f);
        EXPECT_EQ(m.uvs[4].v, 0.0f);
        const RenderResult r = render8x8(*scene);
        EXPECT_NEAR(r.color.at(6, 6, 0), 1, 1e-6) << name; // lower right: its own red
        EXPECT_NEAR(r.color.at(1, 1, 2), 1, 1e-6) << name; // upper left: the object's blue
    }
}

// A spatial pattern in a face's texture moves with the object, like the
// object's own texture: translated by one checker cell, the colours swap.
TEST(Mesh2, FaceTexturesMoveWithTheObject) {
    const std::string mesh = R"(
mesh2 {
  vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }
  texture_list { 1, texture { pigment { checker color rgb <1,0,0>, color rgb <0,0,1> scale 0.5 }
                              finish { ambient 1 diffuse 0 } } }
  face_indices { 2, <0,2,1>, 0, <0,3,2>, 0 }
  translate <TX, 0, 0>
})";
    std::array<double, 2> red{};
    for (int moved = 0; moved < 2; ++moved) {
        std::string text = std::string(kCamera) + "#declare TX = " + (moved ? "0.5" : "0") + ";\n" + mesh;
        Diagnostics diags;
        const auto scene = parse(text, diags);
        ASSERT_TRUE(scene && !diags.hasErrors()) << diags.formatAll();
        // Pixel (5, 6): x = 0.6875, y = 0.1875 in the image; on the mesh at x - TX.
        red[size_t(moved)] = render8x8(*scene).color.at(5, 6, 0);
    }
    EXPECT_NE(red[0], red[1]); // one red, one blue
}

TEST(Mesh2, CopiesOfADeclaredMeshShareItsArrays) {
    Diagnostics diags;
    const auto scene = parse(R"(
#declare M = mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,2> } }
object { M } object { M translate x }
)",
                             diags);
    ASSERT_TRUE(scene && !diags.hasErrors()) << diags.formatAll();
    EXPECT_EQ(std::get<Mesh>(scene->objects[0].shape).indexed,
              std::get<Mesh>(scene->objects[1].shape).indexed);
}

// The .drt writer gives mesh2 text that reads back to the very same arrays.
// `drt convert STEM.pov -o STEM.drt`, then both read back (errors fail the test).
void convertAndLoad(const std::string& stem, std::optional<Scene>& original, std::optional<Scene>& converted) {
    const test::CommandResult c = test::runDrt("convert " + stem + ".pov -o " + stem + ".drt");
    ASSERT_EQ(c.exitCode, 0) << c.err;
    Diagnostics a, b;
    original = loadSceneFile(stem + ".pov", a);
    converted = loadSceneFile(stem + ".drt", b);
    ASSERT_TRUE(original && converted && !a.hasErrors() && !b.hasErrors()) << a.formatAll() << b.formatAll();
}

TEST(Mesh2, WrittenTextReadsBackToTheSameMesh) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/m.pov", std::string(kCamera) + R"(
mesh2 {
  vertex_vectors { 4, <0,0,0>, <1.1,0,0>, <1,1,0.3333333>, <0,1,0> }
  normal_vectors { 2, <0,0,-1>, <0.1,0,-1> }
  uv_vectors { 3, <0,0>, <1,0>, <0.5,1> }
  texture_list { 2, texture { pigment { checker rgb x, rgb y scale 0.3 } } texture { pigment { rgb z } } }
  face_indices { 2, <0,2,1>, 1, <0,3,2>, 0, 1, 1 }
  normal_indices { 2, <0,0,1>, <1,1,1> }
  uv_indices { 2, <0,1,2>, <2,1,0> }
  rotate 30 * y translate <0.2, 0, 1>
})");
    std::optional<Scene> original, converted;
    convertAndLoad(dir + "/m", original, converted);
    ASSERT_TRUE(original && converted);
    EXPECT_TRUE(sameIndexedMesh(indexedOf(*original), indexedOf(*converted)));
    RenderOptions options;
    options.width = options.height = 16;
    options.samplesPerPixel = 1;
    const RenderResult ra = render(*original, options), rb = render(*converted, options);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            for (int k = 0; k < 3; ++k)
                ASSERT_NEAR(ra.color.at(x, y, k), rb.color.at(x, y, k), 1e-9);
}

// Vertices are floats: the writer gives each its float's shortest text (0.1,
// not the double 0.10000000149011612), which reads back to the same float, so
// a converted mesh is the same bit for bit and about half the text. Random
// bit patterns over the whole float range (denormals included) check it.
TEST(Mesh2, WrittenVerticesAreTheFloatsShortestTextAndExact) {
    std::mt19937 random(7);
    std::uniform_int_distribution<uint32_t> bits(0, 0xFFFFFFFFu);
    const int n = 3000;
    std::string list;
    for (int i = 0; i < n; ++i) {
        float f = 0;
        do {
            const uint32_t b = bits(random);
            std::memcpy(&f, &b, sizeof f);
        } while (!std::isfinite(f) || std::fabs(f) > 1e30f); // drt's vectors stay within 1e30
        char text[64];
        std::snprintf(text, sizeof text, "%.9g", double(f));
        list += fmt::format(", <{}, 0.1, {}>", text, i % 2 ? "1e-40" : "-3.4e-38");
    }
    std::string faces;
    for (int i = 0; i + 2 < n; i += 3) faces += fmt::format(", <{}, {}, {}>", i, i + 1, i + 2);
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/f.pov", std::string(kCamera) + "mesh2 { vertex_vectors { " + std::to_string(n) + list +
                                        " } face_indices { " + std::to_string(n / 3) + faces + " } }\n");
    std::optional<Scene> original, converted;
    convertAndLoad(dir + "/f", original, converted);
    ASSERT_TRUE(original && converted);
    const IndexedMesh& m = indexedOf(*original);
    ASSERT_EQ(m.positions.size(), size_t(n));
    EXPECT_TRUE(sameIndexedMesh(m, indexedOf(*converted)));
    const std::string written = test::readFile(dir + "/f.drt");
    EXPECT_NE(written.find(", 0.1, "), std::string::npos);
    EXPECT_EQ(written.find("0.10000000149011612"), std::string::npos);
}

TEST(Mesh2, EveryErrorIsLocated) {
    struct Case {
        const char* text;
        const char* expected;
    };
    const char* v = "mesh2 {\n vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n";
    const Case cases[] = {
        {"face_indices { 1, <0,1,2>, 0 } }", "s.pov:3:28: error: texture index 0 is out of range"},
        {"texture_list { 1, texture { } } face_indices { 1, <0,1,2>, 0, 0 } }",
         "s.pov:3:51: error: a face takes one texture index or three, not 2"},
        {"texture_list { 1, pigment { } } face_indices { 1, <0,1,2> } }",
         "s.pov:3:19: error: expected 'texture'"},
        {"uv_vectors { 2, <0,0>, <1,0> } face_indices { 1, <0,1,2> } }",
         "s.pov:1:1: error: mesh2: vertex index 2 has no uv vector"},
        {"uv_vectors { 3, <0,0>, <1,0>, <1,1> } face_indices { 1, <0,1,2> } uv_indices { 1, <0,1,3> } }",
         "s.pov:3:83: error: uv index 3 is out of range"},
        {"uv_vectors { 3, <0,0>, <1,0>, <1,1> } face_indices { 2, <0,1,2>, <0,2,1> } uv_indices { 1, <0,1,2> "
         "} }",
         "s.pov:1:1: error: mesh2: uv_indices and face_indices have different counts"},
        {"normal_vectors { 1, z } face_indices { 1, <0,1,2> } normal_indices { 1, <0,0,0>, 1 } }",
         "s.pov:3:82: error: texture indices follow face_indices only, not normal indices"},
    };
    for (const Case& c : cases) {
        const std::string dir = test::tempDir();
        test::writeFile(dir + "/s.pov", std::string(v) + c.text + "\n");
        const test::CommandResult r = test::runDrt("render " + dir + "/s.pov -o " + dir + "/out.png");
        EXPECT_EQ(r.exitCode, 1) << c.text;
        EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.text << "\n" << r.err;
        EXPECT_NE(r.err.find("^"), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir + "/out.png"));
    }
    // In a mesh: an unknown item in a triangle.
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/t.pov", "mesh { triangle { <0,0,0>, x, y\n  scale 2 } }\n");
    const test::CommandResult r = test::runDrt("render " + dir + "/t.pov -o " + dir + "/out.png");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("t.pov:2:3: error: expected 'uv_vectors', 'texture' or '}'"), std::string::npos)
        << r.err;
}

} // namespace
} // namespace drt

namespace drt {
namespace {

// shapes.inc's HF macros write faces as sums of vector identifiers, `F1+A, F2+A,`: after a
// face's comma a vector identifier starts the next face, not a texture index.
TEST(Mesh2, FacesFromVectorIdentifiersFollowEachOther) {
    for (const char* name : {"faces.pov", "faces.drt"}) {
        Diagnostics diags;
        const auto scene = parse("#declare F1 = <0, 1, 2>;\n#declare F2 = <0, 2, 3>;\n#declare A = 1;\n"
                                 "mesh2 { vertex_vectors { 5, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0>, <2,2,0> }\n"
                                 "  face_indices { 2, F1+A, F2 + A, } }\n",
                                 diags, name);
        ASSERT_TRUE(scene) << diags.formatAll();
        const IndexedMesh& m = indexedOf(*scene);
        EXPECT_EQ(m.indices, (std::vector<uint32_t>{1, 2, 3, 1, 3, 4})) << name;
    }
}

} // namespace
} // namespace drt
