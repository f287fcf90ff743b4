// POV-Ray's fractal patterns (mandel, julia, magnet 1|2 mandel|julia): their
// values at points computed by hand from the definitions in
// render/pattern_fractal.h (and a few measured on POV-Ray 3.7 itself through
// a function { pigment { ... } } with an identity colour map), and how both
// dialects read and write them, with their errors.
#include "lang/load.h"
#include "lang/writer.h"
#include "render/pattern_fractal.h"
#include "render/pigment.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace drt {
namespace {

FractalPattern mandel(long long n) {
    FractalPattern f;
    f.iterations = n;
    return f;
}

TEST(FractalValue, MandelExteriorIsTheEscapeStepOverTheIterations) {
    // c = 1 + i: z1 = c^2 + c = 1 + 3i, |z1|^2 = 10 > 4 at the first step (0).
    EXPECT_DOUBLE_EQ(fractalValue(mandel(10), 1, 1), 0.0);
    // c = 0.5 + 0.5i: z1 = 0.5 + i, z2 = -0.25 + 1.5i, z3 = -1.6875 - 0.25i, z4 = 3.285 + 1.34i escapes: step 3.
    EXPECT_DOUBLE_EQ(fractalValue(mandel(10), 0.5, 0.5), 0.3);
    EXPECT_DOUBLE_EQ(fractalValue(mandel(20), 0.5, 0.5), 0.15);
    // c = -1: 0, -1, 0, ... never escapes: interior type 0, factor 1.
    EXPECT_DOUBLE_EQ(fractalValue(mandel(10), -1, 0), 1.0);
    EXPECT_DOUBLE_EQ(fractalValue(mandel(10), 0, 0), 1.0);
    // No iterations: every point is inside.
    EXPECT_DOUBLE_EQ(fractalValue(mandel(0), 5, 5), 1.0);
}

TEST(FractalValue, ExteriorTypes) {
    // c = 2 + 2i: z1 = (4 - 4 + 8i) + c = 2 + 10i escapes at step 0.
    FractalPattern f = mandel(10);
    f.exteriorFactor = 0.5;
    const double expected[] = {0.5, 0.0, 1.0, 5.0, 2.0, 50.0, std::sqrt(104.0) * 0.5};
    for (int type = 0; type <= 6; ++type) {
        f.exteriorType = type;
        EXPECT_DOUBLE_EQ(fractalValue(f, 2, 2), expected[type]) << "exterior type " << type;
    }
    // c = 0.5 + 0.5i escapes at step 3: type 7 is fmod(3, F) / F, type 8 fmod(3, F + 1) / F.
    f.exteriorFactor = 3;
    f.exteriorType = 7;
    EXPECT_DOUBLE_EQ(fractalValue(f, 0.5, 0.5), 0.0);
    f.exteriorType = 8;
    EXPECT_DOUBLE_EQ(fractalValue(f, 0.5, 0.5), 1.0);
    f.exteriorFactor = 2;
    f.exteriorType = 7;
    EXPECT_DOUBLE_EQ(fractalValue(f, 0.5, 0.5), 0.5);
}

TEST(FractalValue, InteriorTypes) {
    // One iteration at c = 0.2 + 0.1i: z1 = 0.23 + 0.14i stays inside.
    FractalPattern f = mandel(1);
    f.interiorFactor = 2;
    f.interiorType = 0;
    EXPECT_DOUBLE_EQ(fractalValue(f, 0.2, 0.1), 2.0);
    f.interiorType = 1; // the smallest |z|: |c|^2 = 0.05 < |z1|^2 = 0.0725
    EXPECT_NEAR(fractalValue(f, 0.2, 0.1), std::sqrt(0.05) * 2, 1e-12);
    f.interiorType = 2;
    EXPECT_NEAR(fractalValue(f, 0.2, 0.1), 0.46, 1e-12);
    f.interiorType = 3;
    EXPECT_NEAR(fractalValue(f, 0.2, 0.1), 0.28, 1e-12);
    f.interiorType = 4;
    EXPECT_NEAR(fractalValue(f, 0.2, 0.1), 0.0529 * 2, 1e-12);
    f.interiorType = 5;
    EXPECT_NEAR(fractalValue(f, 0.2, 0.1), 0.0196 * 2, 1e-12);
    // Type 6 as POV-Ray 3.7 renders it: (Re z)^2 + (Im z)^2 F (measured: 0.1875 at c = 0.5i, F = 0.5).
    f.interiorType = 6;
    f.interiorFactor = 0.5;
    EXPECT_NEAR(fractalValue(f, 0, 0.5), 0.0625 + 0.25 * 0.5, 1e-12);
}

TEST(FractalValue, JuliaAndExponents) {
    FractalPattern j = mandel(10);
    j.kind = FractalKind::Julia;
    j.cx = 1;
    // From z = 0 with c = 1: 1, 2 (|z|^2 = 4 stays), 5 escapes at step 2.
    EXPECT_DOUBLE_EQ(fractalValue(j, 0, 0), 0.2);
    // From z = 1.5: 3.25 escapes at step 0.
    EXPECT_DOUBLE_EQ(fractalValue(j, 1.5, 0), 0.0);
    // exponent 3 at c = 0.5i: z1 = (0.5i)^3 + 0.5i = 0.375i (interior type 3: Im z).
    FractalPattern m = mandel(1);
    m.exponent = 3;
    m.interiorType = 3;
    EXPECT_NEAR(fractalValue(m, 0, 0.5), 0.375, 1e-12);
    m.exponent = 7; // (0.5i)^7 = -0.0078125i
    EXPECT_NEAR(fractalValue(m, 0, 0.5), 0.5 - 0.0078125, 1e-12);
    m.exponent = 5; // c = 0.2 + 0.1i: |c|^5 (cos 5t + i sin 5t) + c, t = atan(0.5)
    m.interiorType = 2;
    const double r5 = std::pow(0.05, 2.5), t = std::atan2(0.1, 0.2);
    EXPECT_NEAR(fractalValue(m, 0.2, 0.1), 0.2 + r5 * std::cos(5 * t), 1e-12);
}

TEST(FractalValue, Magnets) {
    FractalPattern f = mandel(10);
    f.kind = FractalKind::Magnet1Mandel;
    // c = 3: z1 = ((0 + 2) / (0 + 1))^2 = 4, z2 = ((16 + 2) / (8 + 1))^2 = 4: a fixed point inside.
    f.interiorType = 2;
    EXPECT_DOUBLE_EQ(fractalValue(f, 3, 0), 4.0);
    // c = 1.5: z1 = (0.5 / -0.5)^2 = 1: settled on 1 at step 0 (exterior type 1: 0; type 2: Re z).
    f.interiorType = 0;
    EXPECT_DOUBLE_EQ(fractalValue(f, 1.5, 0), 0.0);
    f.exteriorType = 2;
    EXPECT_DOUBLE_EQ(fractalValue(f, 1.5, 0), 1.0);
    // magnet 2 mandel at c = 1: (c - 1)(c - 2) = 0, so z stays 0; interior type 1 is then 0.
    f.kind = FractalKind::Magnet2Mandel;
    f.interiorType = 1;
    EXPECT_DOUBLE_EQ(fractalValue(f, 1, 0), 0.0);
    // Measured on POV-Ray 3.7 (function { pigment { ... } }, in 13-bit colour
    // steps): magnet 1 mandel 10 at (-2, -2) gives 0.2, magnet 2 mandel 10 0.1.
    FractalPattern m = mandel(10);
    m.kind = FractalKind::Magnet1Mandel;
    EXPECT_NEAR(fractalValue(m, -2, -2), 0.2, 1e-12);
    m.kind = FractalKind::Magnet2Mandel;
    EXPECT_NEAR(fractalValue(m, -2, -2), 0.1, 1e-12);
}

// ------------------------------------------------------------------ reading

std::optional<Scene> load(const std::string& text, const std::string& name, Diagnostics& diags) {
    return loadSceneText(text, name, diags, LoadOptions{});
}

class FractalDialects : public ::testing::TestWithParam<const char*> {};

TEST_P(FractalDialects, PigmentsNormalsAndTexturePatterns) {
    const std::string name = GetParam();
    Diagnostics diags;
    const auto scene = load("sphere { 0, 1 pigment { mandel 50 exponent 3 exterior 6, 0.5 interior 1, 2\n"
                  "  color_map { [0 rgb 0] [1 rgb 1] } } normal { julia <0.3, 0.4>, 20, 0.7 interior 5, 1 } }\n"
                  "sphere { 0, 1 texture { magnet 2 julia <1.3, 0.2> 30 exterior 8, 2 texture_map {\n"
                  "  [0 pigment { rgb 0 }] [1 pigment { rgb 1 }] } } }\n"
                  "sphere { 0, 1 pigment { magnet 1 mandel 40 max_iteration 12 } }\n",
                  name, diags);
    ASSERT_TRUE(scene) << diags.formatAll();
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    const Scene& s = *scene;
    const Pigment& p = s.objects.at(0).texture->pigment;
    ASSERT_EQ(p.pattern, PatternKind::Fractal);
    ASSERT_TRUE(p.fractal);
    EXPECT_EQ(p.fractal->kind, FractalKind::Mandel);
    EXPECT_EQ(p.fractal->iterations, 50);
    EXPECT_EQ(p.fractal->exponent, 3);
    EXPECT_EQ(p.fractal->exteriorType, 6);
    EXPECT_EQ(p.fractal->exteriorFactor, 0.5);
    EXPECT_EQ(p.fractal->interiorType, 1);
    EXPECT_EQ(p.fractal->interiorFactor, 2);
    // The pigment's colour at a point is its colour map at the fractal's value.
    const double v = fractalValue(*p.fractal, 0.3, -0.2);
    EXPECT_NEAR(evaluatePigment(p, Vec3(0.3, -0.2, 7)).rgb.r, std::fmod(v, 1.00001), 1e-9);
    const Normal& n = *s.objects.at(0).texture->normal;
    ASSERT_EQ(n.pattern, PatternKind::Fractal);
    EXPECT_EQ(n.fractal->kind, FractalKind::Julia);
    EXPECT_EQ(n.fractal->cx, 0.3);
    EXPECT_EQ(n.fractal->cy, 0.4);
    EXPECT_EQ(n.fractal->iterations, 20);
    EXPECT_EQ(n.fractal->interiorType, 5);
    EXPECT_EQ(n.amount, 0.7);
    const Pigment& t = s.objects.at(1).texture->pigment;
    ASSERT_EQ(t.pattern, PatternKind::Fractal);
    EXPECT_EQ(t.fractal->kind, FractalKind::Magnet2Julia);
    EXPECT_EQ(t.fractal->cx, 1.3);
    EXPECT_EQ(t.fractal->exteriorType, 8);
    EXPECT_EQ(s.objects.at(1).texture->map.size(), 2u);
    const Pigment& m = s.objects.at(2).texture->pigment;
    EXPECT_EQ(m.fractal->kind, FractalKind::Magnet1Mandel);
    EXPECT_EQ(m.fractal->iterations, 12);

    // drt convert's writer keeps every parameter: written and read back, the same values.
    const std::string written = writeDrtScene(s);
    Diagnostics backDiags;
    const auto back = load(written, "back.drt", backDiags);
    ASSERT_TRUE(back) << backDiags.formatAll() << "\n" << written;
    for (size_t i = 0; i < 3; ++i) {
        const Pigment& a = s.objects.at(i).texture->pigment;
        const Pigment& b = back->objects.at(i).texture->pigment;
        ASSERT_TRUE(b.fractal) << written;
        for (const Vec3 q : {Vec3(0.1, 0.2, 0), Vec3(-0.7, 0.3, 1), Vec3(1.2, -0.4, 0)})
            EXPECT_DOUBLE_EQ(fractalValue(*a.fractal, q.x, q.y), fractalValue(*b.fractal, q.x, q.y)) << written;
    }
    const Normal& nb = *back->objects.at(0).texture->normal;
    ASSERT_TRUE(nb.fractal) << written;
    EXPECT_EQ(nb.amount, 0.7);
    EXPECT_EQ(nb.fractal->interiorType, 5);
}

INSTANTIATE_TEST_SUITE_P(Dialects, FractalDialects, ::testing::Values("f.drt", "f.pov"),
                         [](const auto& info) { return std::string(info.param[2] == 'd' ? "Drt" : "Pov"); });

struct FractalError {
    const char* name;
    const char* source;
    const char* message;
    int line, column;
};

class FractalErrors : public ::testing::TestWithParam<FractalError> {};

TEST_P(FractalErrors, MessageLocationAndCaret) {
    const FractalError& c = GetParam();
    for (const char* file : {"e.drt", "e.pov"}) {
        Diagnostics diags;
        EXPECT_FALSE(load(c.source, file, diags)) << file;
        test::expectErrorAt(diags, file, c.line, c.column, c.message);
    }
}

// clang-format off
const FractalError kFractalErrors[] = {
    {"ExteriorTypeTooLarge", "sphere { 0, 1 pigment { mandel 10 exterior 9, 1 } }",
     "the exterior type must be a whole number from 0 to 8, got 9", 1, 44},
    {"InteriorTypeTooLarge", "sphere { 0, 1 pigment { mandel 10\n interior 7, 1 } }",
     "the interior type must be a whole number from 0 to 6, got 7", 2, 11},
    {"InteriorTypeNotWhole", "sphere { 0, 1 pigment { mandel 10 interior 1.5, 1 } }",
     "the interior type must be a whole number from 0 to 6, got 1.5", 1, 44},
    {"FactorWithoutComma", "sphere { 0, 1 pigment { mandel 10 exterior 2 1 } }",
     "expected ',' between the exterior type and its factor, found '1'", 1, 46},
    {"MagnetType", "sphere { 0, 1 pigment { magnet 3 mandel 10 } }",
     "the magnet type must be 1 or 2, got 3", 1, 32},
    {"MagnetForm", "sphere { 0, 1 pigment { magnet 1 bozo 10 } }",
     "expected 'mandel' or 'julia' after 'magnet 1', found 'bozo'", 1, 34},
    {"MagnetExponent", "sphere { 0, 1 pigment { magnet 1 mandel 10 exponent 3 } }",
     "'exponent' is only for 'mandel' and 'julia', not for 'magnet'", 1, 44},
    {"NegativeIterations", "sphere { 0, 1 normal { mandel -5 } }",
     "the iteration count must be between 0 and 4294967295, got -5", 1, 31},
    {"JuliaWithoutCount", "sphere { 0, 1 pigment { julia 10 } }",
     "expected a value (a number, a vector <x, y, z> or a name), found '}'", 1, 34},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Cases, FractalErrors, ::testing::ValuesIn(kFractalErrors),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(FractalErrors, ExponentOutsidePovRaysRangeIsAnErrorInDrtOnly) {
    const char* source = "sphere { 0, 1 pigment { mandel 10 exponent 34 } }";
    Diagnostics drt;
    EXPECT_FALSE(load(source, "e.drt", drt));
    test::expectErrorAt(drt, "e.drt", 1, 44, "the fractal exponent must be a whole number from 2 to 33, got 34");
    Diagnostics pov; // POV-Ray reads it without a word
    const auto scene = load(source, "e.pov", pov);
    ASSERT_TRUE(scene) << pov.formatAll();
    EXPECT_EQ(scene->objects.at(0).texture->pigment.fractal->exponent, 33);
}

TEST(FractalErrors, InteriorOutsideAFractalPigmentStillBelongsToTheObject) {
    Diagnostics diags;
    EXPECT_FALSE(load("sphere { 0, 1 pigment { bozo interior 1, 1 } }", "e.drt", diags));
    EXPECT_NE(diags.formatAll().find("'interior' goes in"), std::string::npos) << diags.formatAll();
}

} // namespace
} // namespace drt
