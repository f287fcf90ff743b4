// Smaller POV-Ray front-end features: finish crand, the bounds behind
// min_extent / max_extent, trace() and inside(), and files a scene writes.
#include "pov/load.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace drt {
namespace {

std::optional<Scene> load(const std::string& text, Diagnostics& diags) {
    return loadPovSceneText(text, "f.pov", diags, PovOptions{});
}

TEST(PovFeatures, CrandIsReadWithoutAWarning) {
    Diagnostics diags;
    const auto s = load("sphere { 0, 1 finish { crand 0.25 diffuse 0.7 } }", diags);
    ASSERT_TRUE(s) << diags.formatAll();
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    EXPECT_EQ(s->objects.at(0).texture->finish.crand, 0.25);
    EXPECT_EQ(s->objects.at(0).texture->finish.diffuse, 0.7);
}

TEST(PovFeatures, MinAndMaxExtent) {
    Diagnostics diags;
    const auto s = load("#declare B = box { <1, 2, 3>, <4, 5, 6> translate x }\n"
                        "#declare D = difference { object { B } sphere { 0, 10 } }\n"
                        "#warning vstr(3, min_extent(B), \",\", 0, 0)\n"
                        "#warning vstr(3, max_extent(D), \",\", 0, 0)\n"
                        "#warning vstr(3, max_extent(plane { y, 0 }), \",\", 0, 0)\n"
                        "#declare T = ovus { 1, 0.5 }\n"
                        "#warning vstr(3, min_extent(T) + max_extent(T), \",\", 0, 0)\n",
                        diags);
    ASSERT_TRUE(s) << diags.formatAll();
    std::vector<std::string> messages;
    for (const Diagnostic& d : diags.all())
        if (d.message.rfind("#warning: ", 0) == 0) messages.push_back(d.message.substr(10));
    // A shape the front end leaves out (with its own warning) is unbounded, as
    // POV-Ray's infinite objects: the centring idiom min + (max - min) / 2 gives 0.
    EXPECT_EQ(messages, (std::vector<std::string>{"2,2,3", "5,5,6", "10000000000,10000000000,10000000000", "0,0,0"}));
    Diagnostics light;
    EXPECT_FALSE(load("#declare L = light_source { 0, 1 }\n#declare M = min_extent(L);", light));
    EXPECT_NE(light.formatAll().find("'min_extent' needs an object"), std::string::npos) << light.formatAll();
}

TEST(PovFeatures, WrittenFilesAreDroppedAndFileErrorsAreLocated) {
    // The portfolio scenes write HTML through html_gen.inc.
    Diagnostics diags;
    const auto s = load("#declare Name = \"drt_pov_features_test.html\";\n"
                        "#fopen Out Name write\n#write(Out \"<p>\", str(2, 0, 0) \"</p>\\n\")\n"
                        "#write (Out, Name)\n#fclose Out\n#fopen Log \"drt_pov_features_test.log\" append\n"
                        "#warning \"done\"\n",
                        diags);
    ASSERT_TRUE(s) << diags.formatAll();
    EXPECT_EQ(diags.warningCount(), 1) << diags.formatAll(); // the #warning only
    EXPECT_FALSE(std::filesystem::exists("drt_pov_features_test.html"));
    struct Case {
        const char* text;
        const char* message;
        int column;
    };
    // Reading is file_input_test.cpp's; here only that a missing file and an unopened ID are errors.
    for (const Case& c : {Case{"#fopen In \"no_such_drt_data.txt\" read",
                               "cannot find the file \"no_such_drt_data.txt\" to read", 11},
                          Case{"#read (In, V)", "'In' is not an open file", 8},
                          Case{"#fopen In \"data.txt\" writ", "expected 'read', 'write' or 'append' after the file name", 22}}) {
        Diagnostics bad;
        EXPECT_FALSE(load(c.text, bad)) << c.text;
        ASSERT_GE(bad.errorCount(), 1);
        EXPECT_NE(bad.all()[0].message.find(c.message), std::string::npos) << bad.formatAll();
        EXPECT_EQ(bad.all()[0].loc.column, c.column) << c.text;
    }
}

// quilted is POV-Ray's formula (lang/quilted.h, measured against POV-Ray's
// renders); control0 and control1 change it wherever they come after it.
TEST(PovFeatures, QuiltedIsPovRaysFormulaWithItsControls) {
    Diagnostics diags;
    const auto s = load("sphere { 0, 1 pigment { quilted control0 0.5 control1 0.2 color_map { [0 rgb 0] [1 rgb 1] } } }\n"
                        "sphere { 0, 1 texture { quilted control0 0.2 texture_map { [0 pigment { rgb 0 }] [1 pigment { rgb 1 }] }"
                        " control1 1 } }\n"
                        "sphere { 0, 1 normal { quilted 0.6 control1 0.3 } }\n",
                        diags);
    ASSERT_TRUE(s) << diags.formatAll();
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    // value = 2 / (3 sqrt 3) (|v.x| + |v.y| + |v.z|) B(|v|), v = frac(p) - 1/2, B the cubic of the controls
    const auto quilted = [](Vec3 p, double c0, double c1) {
        const Vec3 v(p.x - std::floor(p.x) - 0.5, p.y - std::floor(p.y) - 0.5, p.z - std::floor(p.z) - 0.5);
        const double t = length(v), b = 3 * t * (1 - t) * (1 - t) * c0 + 3 * t * t * (1 - t) * c1 + t * t * t;
        return 2 / (3 * std::sqrt(3.0)) * (std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z)) * b;
    };
    const Pigment& pigment = s->objects.at(0).texture->pigment;
    ASSERT_EQ(pigment.pattern, PatternKind::Function);
    ASSERT_TRUE(pigment.function);
    const Texture& texture = s->objects.at(1).texture;
    ASSERT_TRUE(texture.pigment.function);
    ASSERT_TRUE(s->objects.at(2).texture->normal);
    const Normal& normal = *s->objects.at(2).texture->normal;
    ASSERT_TRUE(normal.function);
    EXPECT_DOUBLE_EQ(normal.amount, 0.6);
    for (const Vec3 p : {Vec3(0.1, 0.2, 0.3), Vec3(-1.7, 2.45, 0.9), Vec3(3.5, 3.5, 3.5), Vec3(0, 0, 0)}) {
        EXPECT_NEAR(pigment.function->at(p), quilted(p, 0.5, 0.2), 1e-12) << p.x;
        EXPECT_NEAR(texture.pigment.function->at(p), quilted(p, 0.2, 1), 1e-12) << p.x;
        EXPECT_NEAR(normal.function->at(p), quilted(p, 1, 0.3), 1e-12) << p.x;
    }
    Diagnostics bad;
    EXPECT_FALSE(load("sphere { 0, 1 pigment { bozo control0 1 } }", bad));
    EXPECT_NE(bad.formatAll().find("f.pov:1:30: error: unknown keyword 'control0'"), std::string::npos)
        << bad.formatAll();
}

// trace() and inside() ask the scene's geometry while the scene is read (drt
// check and render give it): the hit point and normal, a miss as <0, 0, 0>.
TEST(PovFeatures, TraceAndInsideAnswerFromTheObjectsGeometry) {
    const std::string scene = test::writeFile(test::tempDir() + "/trace.pov", R"(#version 3.7;
#declare S = sphere { <0, 0, 5>, 1 }
#declare N = <9, 9, 9>;
#declare P = trace(S, <0, 0, 0>, <0, 0, 1>, N);
#warning concat("P=", vstr(3, P, ",", 0, 3), " N=", vstr(3, N, ",", 0, 3))
#warning concat("I=", str(inside(S, <0, 0, 5>), 0, 0), str(inside(S, <0, 0, 0>), 0, 0))
#warning concat("M=", vstr(3, trace(S, <0, 0, 0>, <0, 1, 0>), ",", 0, 3))
)");
    const test::CommandResult r = test::runDrt("check '" + scene + "'");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("P=0.000,0.000,4.000 N=0.000,0.000,-1.000"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("I=10"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("M=0.000,0.000,0.000"), std::string::npos) << r.err;
}

// A shape drt leaves out (ovus) is not in the scene: trace() misses it and
// inside() is 0, each with a warning at the call; the scene still renders as
// the rest of it. A light has no surface: a located error.
TEST(PovFeatures, TraceOfALeftOutShapeMissesWithAWarningAndOfALightIsAnError) {
    const std::string dir = test::tempDir();
    const std::string leftOut = test::writeFile(dir + "/iso.pov", R"(#declare Iso = ovus { 1, 0.5 }
#declare Q = trace(Iso, <0, 0, -5>, <0, 0, 1>);
#declare J = inside(Iso, <0, 0, 0>);
#warning concat("Q=", vstr(3, Q, ",", 0, 3), " J=", str(J, 0, 0))
)");
    const test::CommandResult r = test::runDrt("check '" + leftOut + "'");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("iso.pov:2:20: warning: 'trace' is given an object drt leaves out"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("iso.pov:3:21: warning: 'inside' is given an object drt leaves out"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("Q=0.000,0.000,0.000 J=0"), std::string::npos) << r.err;

    const std::string light = test::writeFile(dir + "/light.pov", "#declare L = light_source { 0, 1 }\n#declare P = trace(L, 0, z);\n");
    const test::CommandResult e = test::runDrt("check '" + light + "'");
    EXPECT_EQ(e.exitCode, 1) << e.err;
    EXPECT_NE(e.err.find("light.pov:2:20: error: 'trace' needs an object with a surface, not a light_source\n"
                         "  #declare P = trace(L, 0, z);\n"
                         "                     ^"),
              std::string::npos)
        << e.err;
}

// `#local V = M()` whose `;` lies in M's body (tracevines.pov's FindTmp): the
// name goes to the scope that was open when the directive began, not to M's,
// and `#declare` there sets the outer name even when M has a local of it.
TEST(PovFeatures, ADeclarationEndedInsideAMacroGoesToTheScopeWhereItBegan) {
    const std::string scene = test::writeFile(test::tempDir() + "/scope.pov", R"(#macro Pick(A)
  #local W = 100;
  #if (A > 0) A; #else -A; #end
#end
#macro Outer()
  #local V = Pick(-7)
  #warning concat("V=", str(V, 0, 0))
#end
Outer()
#declare W = 1;
#declare W = Pick(5)
#warning concat("W=", str(W, 0, 0))
)");
    const test::CommandResult r = test::runDrt("check '" + scene + "'");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("V=7"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("W=5"), std::string::npos) << r.err;
}

// POV-Ray's commas between macro arguments are optional (incdemo/shapes.pov:
// `Align_Object(Center_Object(...), x)\n -y, <0, 0, 0>)`); .drt requires them.
TEST(PovFeatures, MacroArgumentsNeedNoCommasInPovButDoInDrt) {
    const std::string dir = test::tempDir();
    const char* body = "#macro Second(A, B, C) B #end\n#declare V = Second(sphere { 0, 1 } -y, 3);\n"
                       "#warning concat(\"V=\", vstr(3, V, \",\", 0, 0))\n";
    const test::CommandResult pov = test::runDrt("check '" + test::writeFile(dir + "/m.pov", body) + "'");
    EXPECT_EQ(pov.exitCode, 0) << pov.err;
    EXPECT_NE(pov.err.find("V=-0,-1,-0"), std::string::npos) << pov.err;
    const test::CommandResult drt = test::runDrt("check '" + test::writeFile(dir + "/m.drt", body) + "'");
    EXPECT_EQ(drt.exitCode, 1) << drt.err;
    EXPECT_NE(drt.err.find("m.drt:2:37: error: expected ')' after the macro arguments, found '-'"), std::string::npos)
        << drt.err;
}

} // namespace
} // namespace drt
