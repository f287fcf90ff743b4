// The algebraic shapes in the front ends: the POV-Ray reader (coefficients,
// `sturm`, errors, POV-Ray's own quartic torus rendering like drt's torus) and
// the .drt language (parsing and a bit-identical writer round trip).
#include "lang/load.h"
#include "lang/writer.h"
#include "pov/load.h"
#include "render/render.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace drt {
namespace {

std::optional<Scene> loadPov(const std::string& text, Diagnostics& diags) {
    return loadPovSceneText(text, "s.pov", diags);
}

Image renderSmall(const Scene& scene) {
    RenderOptions options = resolveRenderOptions(scene.render);
    options.width = 80;
    options.height = 60;
    options.samplesPerPixel = 1;
    options.threads = 1;
    return render(scene, options).color;
}

TEST(PovAlgebraic, EveryFormIsReadWithItsCoefficients) {
    Diagnostics diags;
    const auto s = loadPov("quadric { <1, 2, 3>, <4, 5, 6>, <7, 8, 9>, 10 }\n"
                           "cubic { <1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19,20> sturm translate x }\n"
                           "poly { 2 <1 0 0 0 1 0 0 1 0, -1> }\n"
                           "quartic { <1,0,0,0,2,0,0,2,0,-104, 0,0,0,0,0,0,0,0,0,0, 1,0,0,2,0,56,0,0,0,0, 1,0,-104,0,784> }\n"
                           "superellipsoid { <0.25, 0.5> }",
                           diags);
    ASSERT_TRUE(s) << diags.formatAll();
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    ASSERT_EQ(s->objects.size(), 5u);
    const auto& quadric = std::get<Algebraic>(s->objects[0].shape);
    EXPECT_EQ(quadric.form, Algebraic::Form::Quadric);
    EXPECT_EQ(quadric.coefficients, (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10}));
    const auto& cubic = std::get<Algebraic>(s->objects[1].shape);
    EXPECT_EQ(cubic.form, Algebraic::Form::Cubic);
    EXPECT_EQ(cubic.coefficients.size(), 20u);
    EXPECT_EQ(cubic.coefficients[19], 20);
    EXPECT_TRUE(cubic.sturm);
    const auto& poly = std::get<Algebraic>(s->objects[2].shape);
    EXPECT_EQ(poly.form, Algebraic::Form::Poly);
    EXPECT_EQ(poly.order, 2);
    EXPECT_EQ(poly.coefficients, (std::vector<double>{1, 0, 0, 0, 1, 0, 0, 1, 0, -1}));
    EXPECT_FALSE(poly.sturm);
    const auto& quartic = std::get<Algebraic>(s->objects[3].shape);
    EXPECT_EQ(quartic.form, Algebraic::Form::Quartic);
    EXPECT_EQ(quartic.coefficients[34], 784);
    const auto& super = std::get<Superellipsoid>(s->objects[4].shape);
    EXPECT_EQ(super.e, 0.25);
    EXPECT_EQ(super.n, 0.5);
}

TEST(PovAlgebraic, WrongCountsAndOrdersAreErrorsWithTheirLocation) {
    struct Case {
        const char* text;
        const char* message;
        int line, column;
    };
    const Case cases[] = {
        {"quartic {\n  <1, 2, 3> }", "quartic coefficient list needs 35 numbers, found 3", 2, 3},
        {"poly { 3, <1, 2> }", "poly coefficient list needs 20 numbers, found 2", 1, 11},
        {"poly { 36, <1> }", "poly order must be a whole number from 2 to 35, not 36", 1, 8},
        {"superellipsoid { <-1, 1> }", "superellipsoid exponents must be positive", 1, 18},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.text);
        Diagnostics diags;
        EXPECT_FALSE(loadPov(c.text, diags));
        ASSERT_GE(diags.errorCount(), 1);
        const Diagnostic& d = diags.all()[0];
        EXPECT_EQ(d.message, c.message);
        EXPECT_EQ(d.loc.line, c.line);
        EXPECT_EQ(d.loc.column, c.column);
    }
}

TEST(PovAlgebraic, ShippedQuarticTorusRendersLikeDrtsTorus) {
    // objects/quartic/torus.pov: a torus of major radius sqrt(40) and minor
    // radius sqrt(12) written as a quartic. Replacing the quartic by drt's
    // torus must give the same picture: every hit agrees to ~1e-9.
    const std::string path = "/usr/share/doc/povray/examples/objects/quartic/torus.pov";
    if (!std::filesystem::exists(path)) GTEST_FAIL() << "povray-examples is not installed: " << path;
    Diagnostics diags;
    std::optional<Scene> quartic = loadPovSceneFile(path, diags);
    ASSERT_TRUE(quartic) << diags.formatAll();
    for (const Diagnostic& d : diags.all()) EXPECT_NE(d.severity, Severity::Warning) << d.message;
    ASSERT_EQ(quartic->objects.size(), 1u);
    ASSERT_TRUE(std::holds_alternative<Algebraic>(quartic->objects[0].shape));
    Scene torus = *quartic;
    torus.objects[0].shape = Torus{std::sqrt(40.0), std::sqrt(12.0)};
    const Image a = renderSmall(*quartic), b = renderSmall(torus);
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    size_t differing = 0, lit = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        differing += std::fabs(a.pixels[i] - b.pixels[i]) > 1e-6f;
        lit += b.pixels[i] > 0.1f;
    }
    EXPECT_EQ(differing, 0u);
    EXPECT_GT(lit, a.pixels.size() / 10); // the torus fills a good part of the frame
}

TEST(DrtAlgebraic, ShapesParseAndRoundTripBitIdentically) {
    const std::string text = R"(
camera { location <0, 2, -8> look_at <0, 0.5, 0> }
light_source { <5, 10, -10>, rgb 1 }
quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 pigment { rgb <1, 0.2, 0.2> } translate x * -2.5 }
quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, -104, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 56, 0, 0, 0, 0, 1, 0, -104, 0, 784>
          sturm pigment { rgb <0.9, 0.6, 0.1> } scale 0.12 rotate x * -30 }
poly { 3, <0.3, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 1, 0, -1> pigment { rgb 0.7 } translate <2.5, 0, 0> }
superellipsoid { <0.2, 0.6> pigment { rgb <0.2, 0.5, 1> } scale 0.8 translate <0, 2, 1> }
difference {
  superellipsoid { <2.5, 2.5> }
  sphere { <0.8, 0.8, -0.8>, 0.6 }
  pigment { rgb <0.3, 0.9, 0.3> } translate <0, -1, 2>
}
)";
    Diagnostics diags;
    const std::optional<Scene> scene = loadSceneText(text, "a.drt", diags, ".");
    ASSERT_TRUE(scene) << diags.formatAll();
    ASSERT_EQ(scene->objects.size(), 5u);
    EXPECT_TRUE(std::get<Algebraic>(scene->objects[1].shape).sturm);
    EXPECT_EQ(std::get<Algebraic>(scene->objects[2].shape).order, 3);
    const std::string written = writeDrtScene(*scene);
    EXPECT_NE(written.find("superellipsoid { <0.2, 0.6>"), std::string::npos) << written;
    EXPECT_NE(written.find("quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1"), std::string::npos) << written;
    Diagnostics again;
    const std::optional<Scene> reread = loadSceneText(written, "b.drt", again, ".");
    ASSERT_TRUE(reread) << again.formatAll() << written;
    EXPECT_EQ(writeDrtScene(*reread), written);
    const Image a = renderSmall(*scene), b = renderSmall(*reread);
    EXPECT_TRUE(a.pixels == b.pixels);
    size_t lit = 0;
    for (float v : a.pixels) lit += v > 0.05f;
    EXPECT_GT(lit, a.pixels.size() / 10);
}

} // namespace
} // namespace drt
