// Pattern value modifiers: frequency, phase and the wave types (POV-Ray's order and shapes).
#include "lang/load.h"
#include "pov/load.h"
#include "render/noise.h"
#include "render/pattern_wave.h"
#include "render/pigment.h"

#include <gtest/gtest.h>

#include <cmath>

namespace drt {
namespace {

constexpr double kEps = 1e-12;

TEST(PatternWave, ShapesMatchTheirClosedForms) {
    EXPECT_NEAR(waveShape(WaveKind::Ramp, 0.3, 1), 0.3, kEps);
    EXPECT_NEAR(waveShape(WaveKind::Triangle, 0.25, 1), 0.5, kEps);
    EXPECT_NEAR(waveShape(WaveKind::Triangle, 0.75, 1), 0.5, kEps);
    EXPECT_NEAR(waveShape(WaveKind::Triangle, 0.5, 1), 1.0, kEps);
    EXPECT_NEAR(waveShape(WaveKind::Triangle, 0.0, 1), 0.0, kEps);
    EXPECT_NEAR(waveShape(WaveKind::Sine, 0.0, 1), 0.5, kEps);
    EXPECT_NEAR(waveShape(WaveKind::Sine, 0.25, 1), 1.0, kEps);
    EXPECT_NEAR(waveShape(WaveKind::Sine, 0.75, 1), 0.0, kEps);
    EXPECT_NEAR(waveShape(WaveKind::Scallop, 0.5, 1), 1.0, kEps);
    EXPECT_NEAR(waveShape(WaveKind::Scallop, 1.0 / 6, 1), 0.5, kEps); // sin(pi/6)
    EXPECT_NEAR(waveShape(WaveKind::Scallop, 0.0, 1), 0.0, kEps);
    for (double t : {0.0, 0.2, 0.5, 0.9, 1.0})
        EXPECT_NEAR(waveShape(WaveKind::Cubic, t, 1), 3 * t * t - 2 * t * t * t, kEps) << t;
    EXPECT_NEAR(waveShape(WaveKind::Poly, 0.5, 3), 0.125, kEps);
    EXPECT_NEAR(waveShape(WaveKind::Poly, 0.25, 0.5), 0.5, kEps);
}

TEST(PatternWave, FrequencyAndPhaseComeBeforeTheShape) {
    PatternWave w;
    w.frequency = 2;
    w.phase = 0.25;
    // 0.1 * 2 + 0.25 = 0.45 (ramp); 0.45 -> 0.9 (triangle)
    EXPECT_NEAR(applyPatternWave(w, 0.1), 0.45, kEps);
    w.kind = WaveKind::Triangle;
    EXPECT_NEAR(applyPatternWave(w, 0.1), 0.9, kEps);
    // Wrapping uses POV-Ray's period 1.00001: 0.6 * 2 + 0.25 = 1.45 -> 0.44999.
    w.kind = WaveKind::Ramp;
    EXPECT_NEAR(applyPatternWave(w, 0.6), 1.45 - 1.00001, kEps);
    // A negative frequency wraps into [0, 1): 0.3 * -1 = -0.3 -> 0.7.
    PatternWave negative;
    negative.frequency = -1;
    EXPECT_NEAR(applyPatternWave(negative, 0.3), 0.7, kEps);
    // Frequency 0 leaves the value alone (then the shape).
    PatternWave zero;
    zero.frequency = 0;
    zero.kind = WaveKind::Cubic;
    EXPECT_NEAR(applyPatternWave(zero, 0.5), 0.5, kEps);
    EXPECT_EQ(applyPatternWave(PatternWave{}, NAN), 0.0);
}

Pigment loadPigment(const std::string& pigmentText) {
    Diagnostics diags;
    const std::optional<Scene> scene = loadSceneText("sphere { 0, 1 " + pigmentText + " }", "w.drt", diags);
    EXPECT_TRUE(scene) << diags.formatAll();
    return scene ? scene->objects.at(0).texture->pigment : Pigment{};
}

TEST(PatternWave, GradientWithFrequencyAndPhaseGivesTheColourMapColours) {
    const Pigment p = loadPigment(
        "pigment { gradient x color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] } frequency 2 phase 0.25 }");
    // v = frac(x) * 2 + 0.25, wrapped with period 1.00001; colour (1 - v, 0, v).
    for (const auto& [x, v] : {std::pair{0.1, 0.45}, std::pair{0.3, 0.85}, std::pair{0.5, 1.25 - 1.00001},
                               std::pair{1.2, 0.65}, std::pair{-0.25, 1.75 - 1.00001}}) {
        const ColorFT c = evaluatePigment(p, Vec3(x, 0.3, -0.7));
        EXPECT_NEAR(c.rgb.r, 1 - v, 1e-9) << x;
        EXPECT_NEAR(c.rgb.g, 0, 1e-12) << x;
        EXPECT_NEAR(c.rgb.b, v, 1e-9) << x;
    }
    const Pigment tri = loadPigment("pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } triangle_wave }");
    EXPECT_NEAR(evaluatePigment(tri, Vec3(0.25, 0, 0)).rgb.g, 0.5, 1e-9);
    EXPECT_NEAR(evaluatePigment(tri, Vec3(0.75, 0, 0)).rgb.g, 0.5, 1e-9);
}

TEST(PatternWave, DefaultsLeaveEveryPatternUnchanged) {
    const Pigment plain = loadPigment("pigment { marble turbulence 0.5 }");
    const Pigment ramp = loadPigment("pigment { gradient y }");
    const Pigment rampExplicit = loadPigment("pigment { gradient y ramp_wave frequency 1 phase 0 }");
    for (double t = -2; t < 2; t += 0.37) {
        const Vec3 q(t, 0.61 * t + 0.05, 0.3 - t);
        EXPECT_EQ(evaluatePigment(ramp, q).rgb, evaluatePigment(rampExplicit, q).rgb) << t;
        // Marble's own shape is the triangle wave: an explicit triangle_wave only adds POV-Ray's
        // wrap period 1.00001, a shift of 1e-5 per period of x (here |x| + turbulence < 3 periods).
        const Pigment marbleTriangle = loadPigment("pigment { marble turbulence 0.5 triangle_wave }");
        EXPECT_NEAR(evaluatePigment(plain, q).rgb.r, evaluatePigment(marbleTriangle, q).rgb.r, 2 * 3e-5) << t;
    }
    // Marble with ramp_wave: x wrapped with period 1.00001 (no turbulence).
    const Pigment marbleRamp = loadPigment("pigment { marble ramp_wave }");
    EXPECT_NEAR(evaluatePigment(marbleRamp, Vec3(2.3, 0, 0)).rgb.r, 2.3 - 2 * 1.00001, 1e-9);
    EXPECT_NEAR(evaluatePigment(marbleRamp, Vec3(2.8, 0, 0)).rgb.r, 2.8 - 2 * 1.00001, 1e-9);
}

TEST(PatternWave, SlopeNormalsUseTheWaveButBumpsDoNot) {
    // A pattern normal follows the slope of the waved pattern value: a
    // constant value (frequency 0, v^~0) has no slope, so no tilt.
    Normal n;
    n.pattern = PatternKind::Bozo;
    const Vec3 up(0, 1, 0);
    Normal flat = n;
    flat.wave.frequency = 0;
    flat.wave.kind = WaveKind::Poly;
    flat.wave.exponent = 1e-9;
    const Vec3 q(0.37, 0.0, 0.81);
    EXPECT_GT(length(perturbNormal(n, q, up) - up), 1e-4);
    EXPECT_NEAR(length(perturbNormal(flat, q, up) - up), 0, 1e-9);
    // POV-Ray's bumps normal has a formula of its own: the wave is not used.
    Normal bumps = n, bumpsFlat = flat;
    bumps.pattern = bumpsFlat.pattern = PatternKind::Bumps;
    EXPECT_GT(length(perturbNormal(bumps, q, up) - up), 1e-4);
    EXPECT_EQ(perturbNormal(bumps, q, up), perturbNormal(bumpsFlat, q, up));
}

TEST(PatternWave, PovScenesWithWaveModifiersConvertWithoutWarnings) {
    Diagnostics diags;
    const std::optional<Scene> scene = loadPovSceneText(R"(
camera { location <0, 0, -5> look_at 0 }
sphere { 0, 1 pigment { gradient x frequency 2 phase 0.25 triangle_wave color_map { [0 rgb 0] [1 rgb 1] } } }
sphere { 0, 1 pigment { bozo sine_wave } normal { bumps 0.5 frequency 3 scallop_wave } }
sphere { 0, 1 texture { gradient y cubic_wave texture_map { [0 pigment { rgb 1 }] [1 pigment { rgb 0 }] } } }
sphere { 0, 1 pigment { onion poly_wave 2 ramp_wave poly_wave } }
)", "w.pov", diags);
    ASSERT_TRUE(scene) << diags.formatAll();
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    ASSERT_EQ(scene->objects.size(), 4u);
    const PatternWave& g = scene->objects[0].texture->pigment.wave;
    EXPECT_EQ(g.frequency, 2);
    EXPECT_EQ(g.phase, 0.25);
    EXPECT_EQ(g.kind, WaveKind::Triangle);
    EXPECT_EQ(scene->objects[1].texture->pigment.wave.kind, WaveKind::Sine);
    ASSERT_TRUE(scene->objects[1].texture->normal);
    EXPECT_EQ(scene->objects[1].texture->normal->wave.frequency, 3);
    EXPECT_EQ(scene->objects[1].texture->normal->wave.kind, WaveKind::Scallop);
    EXPECT_EQ(scene->objects[2].texture->pigment.wave.kind, WaveKind::Cubic);
    EXPECT_EQ(scene->objects[3].texture->pigment.wave.kind, WaveKind::Poly);
    EXPECT_EQ(scene->objects[3].texture->pigment.wave.exponent, 1); // the last poly_wave, without exponent
}

TEST(PatternWave, PovPolyWaveWithANonPositiveExponentWarns) {
    Diagnostics diags;
    const std::optional<Scene> scene =
        loadPovSceneText("sphere { 0, 1 pigment { onion poly_wave -1 } }", "w.pov", diags);
    ASSERT_TRUE(scene);
    EXPECT_EQ(diags.warningCount(), 1) << diags.formatAll();
    EXPECT_EQ(scene->objects.at(0).texture->pigment.wave.exponent, 1);
}

TEST(PatternWave, PovWarpTurbulenceBeforeAnyTransformIsTheTurbulence) {
    Diagnostics diags;
    const std::optional<Scene> scene = loadPovSceneText(R"(
sphere { 0, 1 pigment { crackle warp { turbulence <0.6, 0.2, 0.1> octaves 3 omega 0.4 lambda 2.5 } scale 0.5 } }
sphere { 0, 1 pigment { crackle turbulence <0.6, 0.2, 0.1> octaves 3 omega 0.4 lambda 2.5 scale 0.5 } }
)", "w.pov", diags);
    ASSERT_TRUE(scene) << diags.formatAll();
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    const Pigment &warped = scene->objects.at(0).texture->pigment, &plain = scene->objects.at(1).texture->pigment;
    EXPECT_EQ(warped.turbulence.amount, Vec3(0.6, 0.2, 0.1));
    EXPECT_EQ(warped.turbulence.octaves, 3);
    EXPECT_EQ(warped.turbulence.omega, 0.4);
    EXPECT_EQ(warped.turbulence.lambda, 2.5);
    for (double t = -1; t < 1; t += 0.29) {
        const Vec3 q(t, 0.3 - t, 0.7 * t);
        EXPECT_EQ(evaluatePigment(warped, q).rgb, evaluatePigment(plain, q).rgb) << t;
    }
}

TEST(PovWarp, TurbulenceAfterATransformAndOtherWarpsWarn) {
    Diagnostics diags;
    const std::optional<Scene> scene = loadPovSceneText(R"(
sphere { 0, 1 pigment { bozo scale 2 warp { turbulence 0.5 } } }
sphere { 0, 1 pigment { bozo warp { repeat x } } }
)", "w.pov", diags);
    ASSERT_TRUE(scene) << diags.formatAll();
    EXPECT_EQ(diags.warningCount(), 2) << diags.formatAll();
    EXPECT_EQ(scene->objects.at(0).texture->pigment.turbulence.amount, Vec3(0, 0, 0));
}

} // namespace
} // namespace drt
