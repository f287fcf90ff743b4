// slope_map in normals (both dialects): the height a map gives a pattern value
// (POV-Ray's cubic Hermite rule), the normal it tilts, reading, writing back and
// the errors. POV-Ray's own render of such normals: tests/pov_crosscheck/fidelity/slope_map.pov.
#include "lang/load.h"
#include "lang/writer.h"
#include "render/noise.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace drt {
namespace {

std::vector<SlopeMapEntry> triangleWave() { return {{0, 0, 1}, {0.5, 1, 1}, {0.5, 1, -1}, {1, 0, -1}}; }

TEST(SlopeMap, HeightIsTheCubicThroughHeightsWithSlopesPerInterval) {
    // POV-Ray's documented triangle wave: slope 1 over an interval of 0.5 is the straight ramp.
    const auto tri = triangleWave();
    EXPECT_DOUBLE_EQ(slopeMapHeight(tri, 0.25), 0.5);
    EXPECT_DOUBLE_EQ(slopeMapHeight(tri, 0.5), 1);
    EXPECT_DOUBLE_EQ(slopeMapHeight(tri, 0.75), 0.5);
    EXPECT_DOUBLE_EQ(slopeMapHeight(tri, 0.1), 0.2);
    // Its "sine wave the hard way": halfway between <0.5, 1> and <1, 0> (t = 1/2) the
    // Hermite basis gives 0.5 * 0.5 + 1 * 0.125 + 1 * 0.5 + 0 = 0.875.
    const std::vector<SlopeMapEntry> sine = {{0, 0.5, 1}, {0.25, 1, 0}, {0.5, 0.5, -1}, {0.75, 0, 0}, {1, 0.5, 1}};
    EXPECT_DOUBLE_EQ(slopeMapHeight(sine, 0.125), 0.875);
    EXPECT_DOUBLE_EQ(slopeMapHeight(sine, 0.625), 0.125);
    EXPECT_DOUBLE_EQ(slopeMapHeight(sine, 0.25), 1);
    // Outside the entries: the end heights; NaN takes the first.
    const std::vector<SlopeMapEntry> inner = {{0.2, 0.3, 5}, {0.8, 0.9, 5}};
    EXPECT_DOUBLE_EQ(slopeMapHeight(inner, 0.1), 0.3);
    EXPECT_DOUBLE_EQ(slopeMapHeight(inner, 0.95), 0.9);
    EXPECT_DOUBLE_EQ(slopeMapHeight(inner, std::nan("")), 0.3);
    // One entry: flat.
    EXPECT_DOUBLE_EQ(slopeMapHeight({{0.5, 0.4, 2}}, 0.7), 0.4);
}

TEST(SlopeMap, TiltsTheNormalDownTheHeightsGradient) {
    // gradient x with the smoothstep map [0 <0, 0>] [1 <1, 0>]: h = 3v^2 - 2v^3, dh/dv = 1.5 at v = 0.5,
    // so the slope method tilts the normal by -(0.4 / 3) a 1.5 in x.
    Normal n;
    n.pattern = PatternKind::Gradient;
    n.gradientAxis = Vec3(1, 0, 0);
    n.amount = 0.6;
    n.accuracy = 1e-4;
    const Vec3 plain = perturbNormal(n, Vec3(0.5, 0, 0.2), Vec3(0, 1, 0));
    EXPECT_NEAR(plain.x / plain.y, -(0.4 / 3) * 0.6, 1e-6);
    n.slopeMap = {{0, 0, 0}, {1, 1, 0}};
    const Vec3 mapped = perturbNormal(n, Vec3(0.5, 0, 0.2), Vec3(0, 1, 0));
    EXPECT_NEAR(mapped.x / mapped.y, -(0.4 / 3) * 0.6 * 1.5, 1e-6);
    // At v = 0.05 the smoothstep is nearly flat: 6 v (1 - v) = 0.285 (the tetrahedron's samples
    // see the curvature there: 0.05% off).
    const Vec3 low = perturbNormal(n, Vec3(0.05, 0, 0.2), Vec3(0, 1, 0));
    EXPECT_NEAR(low.x / low.y, -(0.4 / 3) * 0.6 * 0.285, 2e-5);
}

class SlopeMapDialects : public ::testing::TestWithParam<const char*> {};

TEST_P(SlopeMapDialects, IsReadAndWrittenBack) {
    const std::string name = GetParam();
    Diagnostics diags;
    const auto scene = loadSceneText("sphere { 0, 1 normal { marble 0.6 slope_map { [0 <0, 1>] [0.5, <1, 0>]\n"
                                     "  [1 <0, -1.5>] } scale 0.5 } }\n",
                                     name, diags, LoadOptions{});
    ASSERT_TRUE(scene) << diags.formatAll();
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    const Normal& n = *scene->objects.at(0).texture->normal;
    EXPECT_EQ(n.pattern, PatternKind::Marble);
    EXPECT_EQ(n.amount, 0.6);
    ASSERT_EQ(n.slopeMap.size(), 3u);
    EXPECT_EQ(n.slopeMap[1].value, 0.5);
    EXPECT_EQ(n.slopeMap[1].height, 1);
    EXPECT_EQ(n.slopeMap[2].slope, -1.5);

    const std::string written = writeDrtScene(*scene);
    EXPECT_NE(written.find("slope_map { [0 <0, 1>] [0.5 <1, 0>] [1 <0, -1.5>] }"), std::string::npos) << written;
    Diagnostics backDiags;
    const auto back = loadSceneText(written, "back.drt", backDiags, LoadOptions{});
    ASSERT_TRUE(back) << backDiags.formatAll() << "\n" << written;
    const Normal& b = *back->objects.at(0).texture->normal;
    ASSERT_EQ(b.slopeMap.size(), 3u);
    for (size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(b.slopeMap[i].value, n.slopeMap[i].value);
        EXPECT_EQ(b.slopeMap[i].height, n.slopeMap[i].height);
        EXPECT_EQ(b.slopeMap[i].slope, n.slopeMap[i].slope);
    }
}

INSTANTIATE_TEST_SUITE_P(Dialects, SlopeMapDialects, ::testing::Values("f.drt", "f.pov"),
                         [](const auto& info) { return std::string(info.param[2] == 'd' ? "Drt" : "Pov"); });

struct SlopeMapError {
    const char* name;
    const char* source;
    const char* message;
    int line, column;
};

class SlopeMapErrors : public ::testing::TestWithParam<SlopeMapError> {};

TEST_P(SlopeMapErrors, MessageLocationAndCaret) {
    const SlopeMapError& c = GetParam();
    for (const char* file : {"e.drt", "e.pov"}) {
        Diagnostics diags;
        EXPECT_FALSE(loadSceneText(c.source, file, diags, LoadOptions{})) << file;
        test::expectErrorAt(diags, file, c.line, c.column, c.message);
    }
}

// clang-format off
const SlopeMapError kSlopeMapErrors[] = {
    {"NoBrace", "sphere { 0, 1 normal { bozo slope_map [0 <0, 1>] } }",
     "expected '{' after 'slope_map', found '['", 1, 39},
    {"NoBracket", "sphere { 0, 1 normal { bozo slope_map { 0 <0, 1> } } }",
     "expected '[' to start a slope_map entry, or '}', found '0'", 1, 41},
    {"Unclosed", "sphere { 0, 1 normal { bozo slope_map {\n [0 <0, 1> [1 <1, 0>] } } }",
     "expected ']' to end the slope_map entry, found '['", 2, 12},
    {"Empty", "sphere { 0, 1 normal { bozo slope_map { } } }",
     "slope_map has no entries", 1, 29},
    {"NotAVector", "sphere { 0, 1 normal { bozo slope_map { [0 \"up\"] } } }",
     "expected the entry's <height, slope>, found a string", 1, 44},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Cases, SlopeMapErrors, ::testing::ValuesIn(kSlopeMapErrors),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(SlopeMapErrors, DecreasingValuesAreAnErrorInDrtOnly) {
    const char* source = "sphere { 0, 1 normal { bozo slope_map { [0.5 <0, 1>]\n [0.2 <1, 0>] } } }";
    Diagnostics drt;
    EXPECT_FALSE(loadSceneText(source, "e.drt", drt, LoadOptions{}));
    test::expectErrorAt(drt, "e.drt", 2, 3, "slope_map values must not decrease, got 0.2");
    EXPECT_NE(drt.formatAll().find("  [0.2 <1, 0>] } } }\n    ^"), std::string::npos) << drt.formatAll();
    Diagnostics pov; // POV-Ray reads it without a word
    const auto scene = loadSceneText(source, "e.pov", pov, LoadOptions{});
    ASSERT_TRUE(scene) << pov.formatAll();
    EXPECT_EQ(scene->objects.at(0).texture->normal->slopeMap.size(), 2u);
}

} // namespace
} // namespace drt
