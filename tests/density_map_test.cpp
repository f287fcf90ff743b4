// POV-Ray's density_map: a media density whose pattern picks among whole
// densities, as a pigment_map picks among pigments (a density is evaluated as
// a pigment). Only inside a density block.
#include "lang/load.h"
#include "lang/writer.h"
#include "render/pigment.h"

#include <gtest/gtest.h>

namespace drt {
namespace {

const char* kScene = "#declare D1 = density { spherical color_map { [0 rgb 0] [1 rgb <1, 0.5, 0>] } }\n"
                     "#declare D2 = density { rgb <0, 0, 1> }\n"
                     "sphere { 0, 1 hollow pigment { rgbt 1 } interior { media { emission 1\n"
                     "  density { gradient x density_map { [0.5 D1] [0.5 D2] } } } } }\n";

TEST(DensityMap, EntriesAreWholeDensitiesPickedByThePatternInBothDialects) {
    for (const char* name : {"m.pov", "m.drt"}) {
        Diagnostics diags;
        const auto s = loadSceneText(kScene, name, diags);
        ASSERT_TRUE(s) << name << "\n" << diags.formatAll();
        EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
        const Pigment& density = s->objects.at(0).interior.media.at(0).densities.at(0);
        ASSERT_EQ(density.pigmentMap.size(), 2u);
        // x = 0.25: gradient 0.25 < 0.5, the first density, spherical at |p| = 0.25: 0.75 of <1, 0.5, 0>.
        const ColorFT first = evaluatePigment(density, Vec3(0.25, 0, 0));
        EXPECT_NEAR(first.rgb.r, 0.75, 1e-9) << name;
        EXPECT_NEAR(first.rgb.g, 0.375, 1e-9) << name;
        EXPECT_NEAR(first.rgb.b, 0, 1e-9) << name;
        // x = 0.75: the second.
        const ColorFT second = evaluatePigment(density, Vec3(0.75, 0, 0));
        EXPECT_NEAR(second.rgb.r, 0, 1e-9) << name;
        EXPECT_NEAR(second.rgb.b, 1, 1e-9) << name;
    }
}

TEST(DensityMap, AConvertedSceneKeepsIt) {
    Diagnostics diags;
    const auto pov = loadSceneText(kScene, "m.pov", diags);
    ASSERT_TRUE(pov) << diags.formatAll();
    const std::string text = writeDrtScene(*pov);
    Diagnostics again;
    const auto drt = loadSceneText(text, "converted.drt", again);
    ASSERT_TRUE(drt) << text << "\n" << again.formatAll();
    const Pigment& a = pov->objects.at(0).interior.media.at(0).densities.at(0);
    const Pigment& b = drt->objects.at(0).interior.media.at(0).densities.at(0);
    for (const Vec3 p : {Vec3(0.1, 0.2, 0), Vec3(0.3, 0, 0.1), Vec3(0.8, 0.1, 0.1)}) {
        EXPECT_NEAR(evaluatePigment(a, p).rgb.r, evaluatePigment(b, p).rgb.r, 1e-9) << text;
        EXPECT_NEAR(evaluatePigment(a, p).rgb.b, evaluatePigment(b, p).rgb.b, 1e-9) << text;
    }
}

TEST(DensityMap, OutsideADensityItIsALocatedError) {
    for (const char* name : {"m.pov", "m.drt"}) {
        Diagnostics diags;
        EXPECT_FALSE(loadSceneText("sphere { 0, 1 pigment { gradient x density_map { [0 rgb 0] [1 rgb 1] } } }", name, diags));
        const std::string expected = std::string(name) + ":1:36: error: 'density_map' goes in a 'density' block";
        EXPECT_NE(diags.formatAll().find(expected), std::string::npos) << diags.formatAll();
        // An empty map: an error in .drt; POV-Ray's dialect lets it pass, as an empty pigment_map.
        Diagnostics empty;
        const bool drt = std::string(name) == "m.drt";
        EXPECT_EQ(bool(loadSceneText("sphere { 0, 1 interior { media { density { gradient x density_map { } } } } }", name,
                                     empty)),
                  !drt);
        EXPECT_EQ(empty.formatAll().find(":1:55: error: density_map has no entries") != std::string::npos, drt)
            << empty.formatAll();
    }
}

} // namespace
} // namespace drt
