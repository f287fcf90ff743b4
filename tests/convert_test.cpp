// `drt convert` (src/cli/convert_command.cpp): POV-Ray scene -> .drt file that
// renders the same image; `--report DIR` sorts scenes into clean / warnings /
// failed and survives scenes that never finish.
#include "lang/load.h"
#include "pov/load.h"
#include "render/render.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

namespace drt {
namespace {

namespace fs = std::filesystem;
using test::runDrt;

const char* const kSimplePov = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 1, 0> angle 40 right x * image_width / image_height }
light_source { <-5, 8, -6>, color rgb 1 area_light <2, 0, 0>, <0, 0, 2>, 3, 3 jitter }
#declare Ball = sphere { 0, 1 pigment { color rgb <0.8, 0.2, 0.1> } finish { phong 0.6 } }
object { Ball translate <0, 1, 0> }
plane { y, 0 pigment { checker color rgb 1, color rgb 0.2 scale 0.5 } rotate 10 * y }
)";

Image renderSmall(const Scene& scene) {
    RenderOptions options = resolveRenderOptions(scene.render);
    options.width = 48;
    options.height = 36;
    options.samplesPerPixel = 2;
    return render(scene, options).color;
}

// `drt convert POV -o DRT`, which must succeed with no warning; the .drt text.
std::string convertCleanly(const std::string& pov, const std::string& drt) {
    const auto r = runDrt("convert '" + pov + "' -o '" + drt + "'");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("0 warnings"), std::string::npos) << r.out << r.err;
    return test::readFile(drt);
}

// The POV-Ray scene and its conversion, each read by its own front end; an
// error in either fails the test.
void loadBoth(const std::string& pov, const std::string& drt, std::optional<Scene>& original,
              std::optional<Scene>& converted) {
    Diagnostics povDiags, drtDiags;
    original = loadPovSceneFile(pov, povDiags);
    converted = loadSceneFile(drt, drtDiags);
    ASSERT_TRUE(original) << povDiags.formatAll();
    ASSERT_TRUE(converted && !drtDiags.hasErrors()) << drtDiags.formatAll();
}

TEST(Convert, WritesADrtFileThatRendersTheSameImage) {
    const std::string dir = test::tempDir();
    const std::string pov = test::writeFile(dir + "/ball.pov", kSimplePov);
    const auto r = runDrt("convert '" + pov + "' -o '" + dir + "/ball.drt'");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string text = test::readFile(dir + "/ball.drt");
    EXPECT_NE(text.find("// Converted from ball.pov"), std::string::npos) << text;
    EXPECT_NE(text.find("// ball.pov:6"), std::string::npos) << text; // the object's source line

    std::optional<Scene> original, converted;
    loadBoth(pov, dir + "/ball.drt", original, converted);
    ASSERT_TRUE(original && converted);
    EXPECT_TRUE(renderSmall(*original).pixels == renderSmall(*converted).pixels);
}

// trace() and inside() are answered while the scene is read, as for a render,
// and the converted scene holds what they gave (before: an error, "this
// loader gives none", for 11 of POV-Ray's sample scenes).
TEST(Convert, TraceAndInsideAtParseTimeAreEvaluatedAndWrittenAsValues) {
    const std::string dir = test::tempDir();
    const std::string pov = test::writeFile(dir + "/traced.pov", R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 1, 0> }
light_source { <-5, 8, -6>, color rgb 1 }
#declare Ground = plane { y, 0.25 }
#declare Hit = trace(Ground, <0.5, 10, 0>, -y);
#declare Inside = inside(sphere { 0, 1 }, <0, 0.5, 0>);
sphere { Hit, 0.5 + 0.25 * Inside pigment { rgb 1 } }
)");
    const std::string text = convertCleanly(pov, dir + "/traced.drt");
    EXPECT_NE(text.find("sphere {"), std::string::npos) << text;
    Diagnostics diags;
    const std::optional<Scene> converted = loadSceneFile(dir + "/traced.drt", diags);
    ASSERT_TRUE(converted && !diags.hasErrors()) << diags.formatAll() << text;
    ASSERT_EQ(converted->objects.size(), 1u);
    const Sphere* ball = std::get_if<Sphere>(&converted->objects[0].shape);
    ASSERT_NE(ball, nullptr);
    // The sphere's centre in the world is the traced point <0.5, 0.25, 0>; its radius 0.75.
    const Vec3 centre = converted->objects[0].transform.point(ball->center);
    EXPECT_NEAR(centre.x, 0.5, 1e-9);
    EXPECT_NEAR(centre.y, 0.25, 1e-6);
    EXPECT_NEAR(centre.z, 0, 1e-9);
    EXPECT_NEAR(length(converted->objects[0].transform.vector(Vec3(ball->radius, 0, 0))), 0.75, 1e-9);
}

TEST(Convert, LayeredAndMappedTexturesConvertWithoutWarningsAndRenderTheSame) {
    const std::string dir = test::tempDir();
    const std::string pov = test::writeFile(dir + "/layers.pov", R"(
camera { location <0, 2, -4> look_at <0, 0.5, 0> }
light_source { <-3, 5, -4> color rgb 1 }
#declare Decal = texture { pigment { gradient y color_map { [0 rgbt 1] [0.5 rgbf <1, 0.5, 0, 0.6>] [1 rgbt 1] } scale 0.3 } }
sphere { y, 1 texture { pigment { rgb <0.2, 0.4, 0.9> } finish { reflection 0.2 } } texture { Decal } }
plane { y, 0 texture { gradient x texture_map { [0.2 pigment { rgb 1 }] [0.8 pigment { rgb 0.1 } finish { reflection 0.4 }] } } }
box { <1, 0, 1>, <2, 1, 2> texture { tiles { texture { pigment { rgb x } } texture { Decal } tile2 texture { pigment { rgb z } } } scale 0.25 } }
)");
    const std::string text = convertCleanly(pov, dir + "/layers.drt");
    EXPECT_NE(text.find("texture_map"), std::string::npos) << text;
    EXPECT_NE(text.find("tiles {"), std::string::npos) << text;

    std::optional<Scene> original, converted;
    loadBoth(pov, dir + "/layers.drt", original, converted);
    ASSERT_TRUE(original && converted);
    EXPECT_TRUE(renderSmall(*original).pixels == renderSmall(*converted).pixels);
}

// POV-Ray takes a spotlight's cone angles through their cosines, so a
// negative angle (camera/mesh_camera's `falloff -90`) is its magnitude: the
// .drt file gets that, reads back without an error and renders the same.
// Negative values with no such equivalent are written and reported.
TEST(Convert, NegativeSpotlightAnglesBecomeTheirMagnitudesAndOtherNegativesAreReported) {
    const std::string dir = test::tempDir();
    const std::string pov = test::writeFile(dir + "/spot.pov", R"(
camera { location <0, 2, -4> look_at <0, 0, 0> }
light_source { <0, 4, 0> color rgb 1 spotlight radius -20 falloff -35 tightness 3 point_at <0.5, 0, 0> }
plane { y, 0 pigment { rgb 1 } }
)");
    const std::string text = convertCleanly(pov, dir + "/spot.drt");
    EXPECT_NE(text.find("radius 20 falloff 35"), std::string::npos) << text;
    std::optional<Scene> original, converted;
    loadBoth(pov, dir + "/spot.drt", original, converted);
    ASSERT_TRUE(original && converted);
    const Image a = renderSmall(*original), b = renderSmall(*converted);
    EXPECT_TRUE(a.pixels == b.pixels);
    // The cone shows: the picture is not uniform.
    EXPECT_NE(*std::max_element(a.pixels.begin(), a.pixels.end()), *std::min_element(a.pixels.begin(), a.pixels.end()));

    test::writeFile(dir + "/tight.pov", "light_source { <0, 4, 0> color rgb 1 spotlight tightness -2 }\n"
                                        "plane { y, 0 pigment { rgb 1 } }\n");
    const auto t = runDrt("convert '" + dir + "/tight.pov' -o '" + dir + "/tight.drt'");
    EXPECT_NE((t.out + t.err).find("a light's negative 'tightness' (the .drt dialect refuses it)"), std::string::npos)
        << t.out << t.err;
}

TEST(Convert, BadInputIsReportedAndNothingIsWritten) {
    const std::string dir = test::tempDir();
    auto missing = runDrt("convert '" + dir + "/none.pov' -o '" + dir + "/none.drt'");
    EXPECT_EQ(missing.exitCode, 3) << missing.err;
    EXPECT_NE(missing.err.find("no such file"), std::string::npos) << missing.err;

    const std::string bad =
        test::writeFile(dir + "/bad.pov", "sphere { <0, 0, 0>, 1\n  pigment { color rgb < }\n}\n");
    auto syntax = runDrt("convert '" + bad + "' -o '" + dir + "/bad.drt'");
    EXPECT_EQ(syntax.exitCode, 1);
    EXPECT_NE(syntax.err.find("bad.pov:2:"), std::string::npos) << syntax.err;
    EXPECT_FALSE(fs::exists(dir + "/bad.drt"));

    const std::string good = test::writeFile(dir + "/good.pov", kSimplePov);
    auto unwritable = runDrt("convert '" + good + "' -o '" + dir + "/no/such/folder/good.drt'");
    EXPECT_EQ(unwritable.exitCode, 3) << unwritable.err;
    EXPECT_FALSE(fs::exists(dir + "/no"));

    EXPECT_EQ(runDrt("convert '" + good + "'").exitCode, 2);                        // no -o
    EXPECT_EQ(runDrt("convert").exitCode, 2);                                       // nothing to do
    EXPECT_EQ(runDrt("convert '" + good + "' --report '" + dir + "'").exitCode, 2); // both
    EXPECT_EQ(runDrt("convert --report '" + dir + "/none'").exitCode, 3);
}

TEST(Convert, ReportSortsScenesAndSurvivesOnesThatNeverFinish) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/a_clean.pov", kSimplePov);
    test::writeFile(dir + "/b_warning.pov", "sphere { 0, 1 pigment { rgb 1 } normal { facets 0.5 } }\n");
    test::writeFile(dir + "/c_error.pov", "sphere { 0, 1 pigment { rgb 1 }\n");
    test::writeFile(dir + "/sub/d_loop.pov", "#declare I = 0;\n#while (1)\n#declare I = I + 1;\n#end\n");
    test::writeFile(dir + "/notes.txt", "not a scene");
    const auto r = runDrt("convert --report '" + dir + "' --timeout 2");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("clean     a_clean.pov\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("warnings  b_warning.pov: 'normal'"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("FAILED    c_error.pov: load: c_error.pov:"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("FAILED    sub/d_loop.pov: timed out after 2 s"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("4 scenes under"), std::string::npos) << r.out;
    EXPECT_NE(
        r.out.find("1 clean (25.0%), 1 with warnings (25.0%), 2 failed (50.0%); 0 crashed, 1 timed out"),
        std::string::npos)
        << r.out;
}

} // namespace
} // namespace drt
