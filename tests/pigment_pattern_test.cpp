// POV-Ray's pigment_pattern: a pigment read as a pattern, its value the grey
// of the pigment's colour, 0.297 red + 0.589 green + 0.114 blue, with filter
// and transmit left out. The weights were measured on POV-Ray 3.7 (an
// ambient-only plane under `pigment_pattern { color C } color_map { [0 rgb 0]
// [1 rgb 1] }`, 16-bit linear output: red 19464/65535, green 38600, blue 7471,
// rgbt <1, 0, 0, 0.5> and rgbf alike 19464). Read in both dialects, as a
// pigment, a texture pattern, a normal and a media density.
#include "lang/load.h"
#include "lang/writer.h"
#include "render/pigment.h"

#include <gtest/gtest.h>

#include <cmath>

namespace drt {
namespace {

std::optional<Scene> load(const std::string& text, const std::string& name, Diagnostics& diags) {
    return loadSceneText(text, name, diags);
}

double grey(double r, double g, double b) { return 0.297 * r + 0.589 * g + 0.114 * b; }

TEST(PigmentPattern, TheValueIsThePigmentsGreyInBothDialects) {
    for (const char* name : {"p.pov", "p.drt"}) {
        Diagnostics diags;
        const auto s = load("sphere { 0, 1 pigment { pigment_pattern { gradient x color_map { [0 rgbt <1, 0, 0, 0.5>] [1 rgbf <0.2, 0.6, 1, 0.9>] } }"
                            " color_map { [0 rgb 0] [1 rgb <1, 0.5, 0.25>] } } }",
                            name, diags);
        ASSERT_TRUE(s) << name << "\n" << diags.formatAll();
        EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
        const Pigment& pigment = s->objects.at(0).texture->pigment;
        ASSERT_EQ(pigment.pattern, PatternKind::Function) << name;
        ASSERT_TRUE(pigment.function);
        const Vec3 red(0, 0.5, 0.5), quarter(0.25, 0.5, 0.5); // the inner gradient's first entry, and a quarter on
        EXPECT_NEAR(pigment.function->at(red), grey(1, 0, 0), 1e-12) << name;
        const double v = 0.75 * grey(1, 0, 0) + 0.25 * grey(0.2, 0.6, 1);
        EXPECT_NEAR(pigment.function->at(quarter), v, 1e-12) << name;
        // Through the colour map: value v gives v * <1, 0.5, 0.25>.
        const ColorFT c = evaluatePigment(pigment, quarter);
        EXPECT_NEAR(c.rgb.r, v, 1e-9) << name;
        EXPECT_NEAR(c.rgb.g, 0.5 * v, 1e-9) << name;
        EXPECT_NEAR(c.rgb.b, 0.25 * v, 1e-9) << name;
    }
}

TEST(PigmentPattern, ATransformedInnerPigmentMovesWithItsOwnTransformsAndTheOuterOnes) {
    Diagnostics diags;
    const auto s = load("sphere { 0, 1 pigment { pigment_pattern { gradient x scale 2 } translate x } }", "p.pov", diags);
    ASSERT_TRUE(s) << diags.formatAll();
    const Pigment& pigment = s->objects.at(0).texture->pigment;
    // The outer translate moves the point by -1 first, the inner gradient
    // (period 2) then reads x / 2: at world x = 1.5 the value is 0.25.
    EXPECT_NEAR(evaluatePigment(pigment, Vec3(1.5, 0, 0)).rgb.r, 0.25, 1e-9);
    EXPECT_NEAR(evaluatePigment(pigment, Vec3(2.0, 0, 0)).rgb.r, 0.5, 1e-9);
}

TEST(PigmentPattern, TexturePatternNormalAndDensity) {
    Diagnostics diags;
    const auto s = load("sphere { 0, 1 texture { pigment_pattern { rgb <0, 1, 0> }"
                        " texture_map { [0 pigment { rgb 0 }] [1 pigment { rgb 1 }] } } }\n"
                        "sphere { 0, 1 pigment { rgb 1 } normal { pigment_pattern { gradient x } 0.7 } }\n"
                        "sphere { 0, 1 hollow pigment { rgbt 1 } interior { media { emission 1"
                        " density { pigment_pattern { rgb <0, 0, 1> } } } } }\n",
                        "p.pov", diags);
    ASSERT_TRUE(s) << diags.formatAll();
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    const Pigment& texturePattern = s->objects.at(0).texture->pigment;
    ASSERT_TRUE(texturePattern.function);
    EXPECT_NEAR(texturePattern.function->at(Vec3(0.3, 0.1, 0.2)), 0.589, 1e-12);
    ASSERT_TRUE(s->objects.at(1).texture->normal);
    const Normal& normal = *s->objects.at(1).texture->normal;
    EXPECT_EQ(normal.pattern, PatternKind::Function);
    EXPECT_DOUBLE_EQ(normal.amount, 0.7);
    ASSERT_TRUE(normal.function);
    EXPECT_NEAR(normal.function->at(Vec3(0.4, 0, 0)), 0.4, 1e-9);
    const auto& media = s->objects.at(2).interior.media;
    ASSERT_EQ(media.size(), 1u);
    ASSERT_EQ(media[0].densities.size(), 1u);
    ASSERT_TRUE(media[0].densities[0].function);
    EXPECT_NEAR(media[0].densities[0].function->at(Vec3(0.1, 0.1, 0.1)), 0.114, 1e-12);
}

TEST(PigmentPattern, AConvertedSceneKeepsTheValues) {
    Diagnostics diags;
    const auto pov = load("sphere { 0, 1 pigment { pigment_pattern { checker rgb <1, 0, 0> rgb <0, 0, 1> scale 0.5 }"
                          " color_map { [0 rgb 0] [1 rgb 1] } } }",
                          "p.pov", diags);
    ASSERT_TRUE(pov) << diags.formatAll();
    const std::string text = writeDrtScene(*pov);
    Diagnostics again;
    const auto drt = load(text, "converted.drt", again);
    ASSERT_TRUE(drt) << text << "\n" << again.formatAll();
    for (const Vec3 p : {Vec3(0.1, 0.1, 0.1), Vec3(0.6, 0.1, 0.1), Vec3(-0.3, 0.7, 0.2)})
        EXPECT_NEAR(evaluatePigment(drt->objects.at(0).texture->pigment, p).rgb.r,
                    evaluatePigment(pov->objects.at(0).texture->pigment, p).rgb.r, 1e-12)
            << text;
}

TEST(PigmentPattern, ErrorsAreLocated) {
    struct Case {
        const char* text;
        const char* message;
    };
    for (const Case& c : {Case{"sphere { 0, 1 pigment { pigment_pattern 5 } }", "p.pov:1:41: error: expected '{' after 'pigment_pattern'"},
                          Case{"sphere { 0, 1 pigment { pigment_pattern { rgb 1 ior 1.5 } } }", "p.pov:1:49: error: 'ior' goes in 'interior'"},
                          Case{"sphere { 0, 1 pigment { pigment_pattern { rgb 1 ", "p.pov:1:25:"}}) {
        Diagnostics diags;
        EXPECT_FALSE(load(c.text, "p.pov", diags)) << c.text;
        EXPECT_NE(diags.formatAll().find(c.message), std::string::npos) << c.text << "\n" << diags.formatAll();
    }
}

} // namespace
} // namespace drt
