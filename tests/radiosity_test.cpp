// POV-Ray's radiosity { } as drt estimates it (scene.h Radiosity): each
// shaded layer sends one cosine-distributed ray whose radiance, times diffuse *
// pigment * brightness, adds to the layer, recursion_limit bounces deep.
// Closed forms measured against POV-Ray 3.7 itself: inside a closed sphere of
// emission e and diffuse kd, POV-Ray renders e (1 + kd + ... + kd^n) for
// recursion_limit n (e = 0.2, kd = 0.5: 0.300, 0.351, 0.376 for n = 1, 2, 3),
// and a finish's `ambient` does not glow under radiosity with #version 3.7
// (black) but does with 3.6 (0.300 as with emission). Every gathering ray
// there sees the same radiance, so the estimate is exact, not just on average
// (to the image's float precision, 1e-6).
// The cross-check against a POV-Ray render is
// tests/pov_crosscheck/fidelity/radiosity.pov.
#include "render/render.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace drt {
namespace {

double centrePixel(const std::string& text, bool pov = true, int spp = 4) {
    const auto run = test::readSceneText(text, pov);
    EXPECT_TRUE(run->scene) << run->diags.formatAll();
    if (!run->scene) return -1;
    RenderOptions o;
    o.width = 4;
    o.height = 3;
    o.samplesPerPixel = spp;
    o.threads = 1;
    const RenderResult r = render(*run->scene, o);
    return r.color.at(2, 1, 0);
}

std::string furnace(const std::string& version, int recursion, const std::string& finish) {
    return "#version " + version + ";\n" +
           "global_settings { assumed_gamma 1.0 radiosity { count 200 recursion_limit " + std::to_string(recursion) +
           " error_bound 0.5 } }\n"
           "camera { location 0 look_at z angle 60 }\n"
           "sphere { 0, 10 pigment { rgb 1 } finish { " + finish + " } }\n";
}

TEST(Radiosity, AClosedFurnaceAddsOneDiffuseShareABounce) {
    const double e = 0.2, kd = 0.5;
    double expected = e;
    for (int n = 1; n <= 3; ++n) {
        expected += e * std::pow(kd, n);
        EXPECT_NEAR(centrePixel(furnace("3.7", n, "emission 0.2 ambient 0 diffuse 0.5")), expected, 1e-6) << n;
    }
}

TEST(Radiosity, AmbientGlowsOnlyBefore37) {
    // POV-Ray 3.7: black; #version 3.6: ambient acts as emission does (0.3).
    EXPECT_NEAR(centrePixel(furnace("3.7", 1, "ambient 0.2 diffuse 0.5")), 0.0, 1e-6);
    EXPECT_NEAR(centrePixel(furnace("3.6", 1, "ambient 0.2 diffuse 0.5")), 0.3, 1e-6);
    // Without radiosity ambient is ambient, whatever the version.
    const std::string plain = "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
                              "camera { location 0 look_at z angle 60 }\n"
                              "sphere { 0, 10 pigment { rgb 1 } finish { ambient 0.2 diffuse 0.5 } }\n";
    EXPECT_NEAR(centrePixel(plain), 0.2, 1e-6);
}

TEST(Radiosity, AFloorUnderTheSkySeesItTimesDiffuseAndBrightness) {
    // Only the background lights the floor: its hemisphere is all sky, so
    // diffuse * pigment * brightness * background, whatever the direction drawn.
    for (const bool pov : {true, false}) {
        SCOPED_TRACE(pov ? ".pov" : ".drt");
        const std::string scene =
            "global_settings { radiosity { recursion_limit 1 brightness 1.5 } }\n"
            "background { color rgb <0.4, 0.6, 0.8> }\n"
            "camera { location <0, 1, 0> look_at <0, 0, 1> angle 30 }\n"
            "plane { y, 0 pigment { rgb 0.5 } finish { ambient 0 emission 0 diffuse 0.8 } }\n";
        EXPECT_NEAR(centrePixel(scene, pov, 8), 0.4 * 0.5 * 0.8 * 1.5, 1e-6);
    }
}

TEST(Radiosity, TheSummaryNamesItWhereADiffuseFinishGathers) {
    const auto effectsOf = [](const std::string& text) {
        const auto run = test::readSceneText(text, true);
        EXPECT_TRUE(run->scene) << run->diags.formatAll();
        return run->scene ? sceneEffects(*run->scene, RenderOptions{}) : SceneEffects{};
    };
    const SceneEffects gathers = effectsOf(furnace("3.7", 1, "emission 0.2 diffuse 0.5"));
    EXPECT_TRUE(gathers.radiosity);
    EXPECT_EQ(describeEffects(gathers), "radiosity");
    // No diffuse surface to gather for, or no radiosity { }: not used.
    EXPECT_FALSE(effectsOf(furnace("3.7", 1, "emission 0.2 diffuse 0")).radiosity);
    EXPECT_FALSE(effectsOf("camera { location 0 look_at z }\nsphere { 0, 10 pigment { rgb 1 } }\n").radiosity);
}

TEST(Radiosity, BadSettingsAreLocatedErrors) {
    const auto zero = test::readSceneText("global_settings { radiosity { recursion_limit 0 } }\n", true);
    test::expectErrorAt(zero->diags, "t.pov", 1, 47, "'recursion_limit' must be 1 to 100, got 0");
    const auto word = test::readSceneText("global_settings {\n  radiosity { count 35 colour 1 } }\n", true);
    test::expectErrorAt(word->diags, "t.pov", 2, 24, "expected a radiosity keyword (recursion_limit, brightness, count, error_bound, gray_threshold, "
                    "nearest_count, pretrace_start, pretrace_end, ...) or '}', found 'colour'");
}

} // namespace
} // namespace drt
