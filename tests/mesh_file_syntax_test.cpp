// `mesh { file "..." }` and `uv_mapping` in .drt and .pov scenes, end to end:
// the front end finds the file, the assets stage reads it, and the render
// shows it with its uv-mapped pattern at known pixels; errors carry file,
// line, column and caret.
#include "assets/assets.h"
#include "lang/load.h"
#include "render/render.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace drt {
namespace {

// A 2 x 2 square in x-y facing -z with uv = position / 2.
const char* kSquareObj = R"(v 0 0 0
v 2 0 0
v 2 2 0
v 0 2 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
f 1/1 3/3 2/2
f 1/1 4/4 3/3
)";

std::optional<Scene> parse(const std::string& dir, const std::string& text, Diagnostics& diags,
                           const std::string& name = "scene.drt") {
    const std::string path = test::writeFile(dir + "/" + name, text);
    auto scene = loadSceneFile(path, diags);
    if (scene && !diags.hasErrors())
        resolveAssets(*scene, diags);
    return scene;
}

TEST(MeshFileSyntax, ModelFileWithUvMappedCheckerShowsItsCells) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/models/square.obj", kSquareObj);
    // uv cells of 1/4: the pixel at uv (0.375, 0.125) is in cell (1, 0), the
    // checker's second colour; uv (0.125, 0.125) the first.
    const std::string scene = R"(
camera { orthographic location <1, 1, -5> direction z right 2 * x up 2 * y }
mesh { file "models/square.obj"
  pigment { uv_mapping checker color rgb <1, 0, 0>, color rgb <0, 0, 1> scale 0.25 }
  finish { ambient 1 diffuse 0 } }
)";
    Diagnostics diags;
    const auto loaded = parse(dir, scene, diags);
    ASSERT_TRUE(loaded && !diags.hasErrors()) << diags.formatAll();
    RenderOptions options;
    options.width = options.height = 8; // pixel (x, y) centre: uv ((x + 0.5) / 8, 1 - (y + 0.5) / 8)
    options.samplesPerPixel = 1;
    const RenderResult r = render(*loaded, options);
    // Pixel (2, 6): uv (0.3125, 0.1875): cell (1, 0): blue. Pixel (0, 7): uv (0.0625, 0.0625): red.
    EXPECT_NEAR(r.color.at(2, 6, 2), 1, 1e-6);
    EXPECT_NEAR(r.color.at(2, 6, 0), 0, 1e-6);
    EXPECT_NEAR(r.color.at(0, 7, 0), 1, 1e-6);
    // Without uv_mapping the same checker follows space, where the square is
    // twice as large: pixel (1, 7) at uv (0.1875, 0.0625) is red in uv space
    // (cell (0, 0)) but at x = 0.375, y = 0.125 it is in cell (1, 0): blue.
    Diagnostics again;
    std::string spatial = scene;
    spatial.replace(spatial.find("uv_mapping "), 11, "");
    const auto plain = parse(dir, spatial, again);
    ASSERT_TRUE(plain && !again.hasErrors()) << again.formatAll();
    EXPECT_NEAR(r.color.at(1, 7, 0), 1, 1e-6);
    EXPECT_NEAR(render(*plain, options).color.at(1, 7, 2), 1, 1e-6);
}

TEST(MeshFileSyntax, DeclaredModelUsedTwiceIsReadOnce) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/square.obj", kSquareObj);
    Diagnostics diags;
    const auto scene = parse(dir, R"(
#declare Square = mesh { file "square.obj" }
object { Square }
object { Square translate x * 3 }
)",
                             diags);
    ASSERT_TRUE(scene && !diags.hasErrors()) << diags.formatAll();
    ASSERT_EQ(scene->objects.size(), 2u);
    EXPECT_EQ(std::get<Mesh>(scene->objects[0].shape).indexed,
              std::get<Mesh>(scene->objects[1].shape).indexed);
}

TEST(MeshFileSyntax, MissingAndMalformedFilesAreErrorsWithLineColumnAndCaret) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/bad.ply", "ply\nformat ascii 1.0\nelement vertex x\nend_header\n");
    test::writeFile(dir + "/missing.drt", "mesh {\n  file \"nothing.obj\" }\n");
    test::writeFile(dir + "/bad.drt", "mesh { file \"bad.ply\" }\n");
    const test::CommandResult missing = test::runDrt("check " + dir + "/missing.drt");
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_NE(missing.err.find("missing.drt:2:8: error: cannot find model file 'nothing.obj'"),
              std::string::npos)
        << missing.err;
    EXPECT_NE(missing.err.find("^"), std::string::npos) << missing.err;
    const test::CommandResult bad = test::runDrt("render " + dir + "/bad.drt -o " + dir + "/bad.png");
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_NE(bad.err.find("bad.drt:1:13: error: cannot read the model"), std::string::npos) << bad.err;
    EXPECT_NE(bad.err.find("malformed or truncated"), std::string::npos) << bad.err;
    EXPECT_FALSE(std::filesystem::exists(dir + "/bad.png"));
}

// The checker of ModelFileWithUvMappedCheckerShowsItsCells, written as a
// POV-Ray scene with uv_mapping in the texture: the same cells.
TEST(MeshFileSyntax, PovSceneReadsTheModelAndUvMapsTheTexture) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/square.obj", kSquareObj);
    const std::string scene = R"(
camera { orthographic location <1, 1, -5> direction z right 2 * x up 2 * y }
#declare Name = "square";
mesh { file concat(Name, ".obj")
  texture { uv_mapping pigment { checker color rgb <1, 0, 0>, color rgb <0, 0, 1> scale 0.25 }
            finish { ambient 1 diffuse 0 } }
  translate x * 0 }
)";
    Diagnostics diags;
    const auto loaded = parse(dir, scene, diags, "scene.pov");
    ASSERT_TRUE(loaded && !diags.hasErrors()) << diags.formatAll();
    RenderOptions options;
    options.width = options.height = 8;
    options.samplesPerPixel = 1;
    const RenderResult r = render(*loaded, options);
    EXPECT_NEAR(r.color.at(2, 6, 2), 1, 1e-6);
    EXPECT_NEAR(r.color.at(2, 6, 0), 0, 1e-6);
    EXPECT_NEAR(r.color.at(0, 7, 0), 1, 1e-6);
    EXPECT_NEAR(r.color.at(1, 7, 0), 1, 1e-6);
}

// The object's transforms move a uv-mapped pattern with the surface (it
// stays on the same uv cells); the pigment's own transforms act in uv space.
TEST(MeshFileSyntax, UvMappedPatternIgnoresTheObjectsTransformsButNotItsOwn) {
    Diagnostics diags;
    const auto scene = loadSceneText(R"(
mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
  pigment { uv_mapping checker color rgb 1, color rgb 0 scale 0.5 translate x }
  scale 3 rotate y * 30 }
)",
                                     "uv.drt", diags);
    ASSERT_TRUE(scene && !diags.hasErrors()) << diags.formatAll();
    const Pigment& p = scene->objects[0].texture->pigment;
    EXPECT_TRUE(p.uvMapping);
    EXPECT_TRUE(p.children.empty() || p.children[0].uvMapping);
    // Pattern space = uv space scaled by 0.5, then moved by x: the object's scale and rotation are not in it.
    const Vec3 uvPoint = p.toWorld.inversePoint(Vec3(1.25, 0.5, 0));
    EXPECT_NEAR(uvPoint.x, 0.5, 1e-12);
    EXPECT_NEAR(uvPoint.y, 1.0, 1e-12);
    EXPECT_NEAR(uvPoint.z, 0.0, 1e-12);
}

TEST(MeshFileSyntax, EveryFrontEndErrorIsLocated) {
    const std::string dir = test::tempDir();
    std::filesystem::create_directories(dir + "/folder.obj");
    struct Case {
        const char* file;
        const char* text;
        const char* expected;
    };
    const Case cases[] = {
        {"missing.pov", "mesh {\n  file \"nothing.obj\" }\n",
         "missing.pov:2:8: error: cannot find model file 'nothing.obj'"},
        {"unquoted.drt", "mesh { file square }\n", "unquoted.drt:1:13: error: expected the model file name in quotes"},
        {"folder.drt", "mesh { file \"folder.obj\" }\n", "folder.drt:1:13: error: cannot read the model"},
    };
    for (const Case& c : cases) {
        test::writeFile(dir + "/" + c.file, c.text);
        const test::CommandResult r = test::runDrt("render " + dir + "/" + c.file + " -o " + dir + "/out.png");
        EXPECT_EQ(r.exitCode, 1) << c.file;
        EXPECT_NE(r.err.find(c.expected), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("^"), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir + "/out.png")) << c.file;
    }
    const test::CommandResult folder = test::runDrt("render " + dir + "/folder.drt -o " + dir + "/out.png");
    EXPECT_NE(folder.err.find("it is a directory"), std::string::npos) << folder.err;
}

// drt convert keeps a model as `mesh { file }` with the file's absolute path,
// which resolves from wherever the output is written; the converted scene
// renders the same image (drt compare: no pixel differs).
TEST(MeshFileSyntax, ConvertKeepsTheModelFileReference) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/in/models/square.obj", kSquareObj);
    test::writeFile(dir + "/in/scene.pov", R"(
camera { orthographic location <1, 1, -5> direction z right 2 * x up 2 * y }
light_source { <1, 3, -5> color rgb 1 }
mesh { file "models/square.obj"
  pigment { uv_mapping checker color rgb <1, 0, 0>, color rgb <0, 0, 1> scale 0.25 }
  rotate 10 * y }
)");
    std::filesystem::create_directories(dir + "/out");
    const test::CommandResult c = test::runDrt("convert " + dir + "/in/scene.pov -o " + dir + "/out/converted.drt");
    ASSERT_EQ(c.exitCode, 0) << c.err;
    const std::string text = test::readFile(dir + "/out/converted.drt");
    const std::string absolute = std::filesystem::canonical(dir + "/in/models/square.obj").string();
    EXPECT_NE(text.find("mesh { file \"" + absolute + "\""), std::string::npos) << text;
    EXPECT_EQ(text.find("mesh2"), std::string::npos) << text; // the reference, not the triangles
    const std::string size = " --width 16 --height 16 --spp 1";
    ASSERT_EQ(test::runDrt("render " + dir + "/in/scene.pov -o " + dir + "/a.png" + size).exitCode, 0);
    ASSERT_EQ(test::runDrt("render " + dir + "/out/converted.drt -o " + dir + "/b.png" + size).exitCode, 0);
    const test::CommandResult same =
        test::runDrt("compare " + dir + "/b.png " + dir + "/a.png --fail 0 --fail-percent 0");
    EXPECT_EQ(same.exitCode, 0) << same.out << same.err;
}

} // namespace
} // namespace drt
