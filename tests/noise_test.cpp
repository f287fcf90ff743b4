// Noise patterns, turbulence and bump normals (render/noise.h), their .drt
// syntax and the POV-Ray front end's mapping onto them.
#include "lang/load.h"
#include "lang/writer.h"
#include "pov/load.h"
#include "render/noise.h"
#include "render/pigment.h"

#include "core/hash.h"
#include "core/limits.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <gtest/gtest.h>
#include <random>

namespace drt {
namespace {

const PatternKind kAllNoise[] = {PatternKind::Bozo,    PatternKind::Granite,  PatternKind::Marble, PatternKind::Wood,
                                 PatternKind::Agate,   PatternKind::Leopard,  PatternKind::Crackle,
                                 PatternKind::Wrinkles, PatternKind::Dents,   PatternKind::Bumps,
                                 PatternKind::Ripples, PatternKind::Waves};

Vec3 randomPoint(std::mt19937_64& rng, double extent) {
    std::uniform_real_distribution<double> u(-extent, extent);
    return Vec3(u(rng), u(rng), u(rng));
}

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

TEST(Noise, RangeIsZeroToOneAndUsesMostOfIt) {
    std::mt19937_64 rng(7);
    double lo = 1, hi = 0;
    for (int i = 0; i < 20000; ++i) {
        const double n = noise01(randomPoint(rng, 50));
        ASSERT_GE(n, 0.0);
        ASSERT_LE(n, 1.0);
        lo = std::min(lo, n), hi = std::max(hi, n);
    }
    EXPECT_LT(lo, 0.2); // a constant or squashed noise would fail these
    EXPECT_GT(hi, 0.8);
    EXPECT_DOUBLE_EQ(noise01(Vec3(3, -4, 5)), 0.5); // zero at lattice points (gradient noise)
}

// The noise as first defined, one hashValues({i, j, k, seed}) per corner and seed
// (render/noise.cpp shares the hashes' common steps): the faster code must give
// these values to the bit, or every noise pattern's image changes.
double referenceSignedNoise(const Vec3& p, uint64_t seed) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return 0;
    auto fade = [](double t) { return t * t * t * (t * (t * 6 - 15) + 10); };
    auto lerp = [](double a, double b, double t) { return a + t * (b - a); };
    const double fx = std::floor(p.x), fy = std::floor(p.y), fz = std::floor(p.z);
    const long long i = saturatingInteger(fx), j = saturatingInteger(fy), k = saturatingInteger(fz);
    const double x = p.x - fx, y = p.y - fy, z = p.z - fz;
    auto g = [&](int a, int b, int c) {
        const double dx = x - a, dy = y - b, dz = z - c;
        switch (hashValues({uint64_t(i + a), uint64_t(j + b), uint64_t(k + c), seed}) % 12) {
        case 0: return dx + dy;
        case 1: return -dx + dy;
        case 2: return dx - dy;
        case 3: return -dx - dy;
        case 4: return dx + dz;
        case 5: return -dx + dz;
        case 6: return dx - dz;
        case 7: return -dx - dz;
        case 8: return dy + dz;
        case 9: return -dy + dz;
        case 10: return dy - dz;
        default: return -dy - dz;
        }
    };
    const double u = fade(x), v = fade(y), w = fade(z);
    const double x00 = lerp(g(0, 0, 0), g(1, 0, 0), u), x10 = lerp(g(0, 1, 0), g(1, 1, 0), u);
    const double x01 = lerp(g(0, 0, 1), g(1, 0, 1), u), x11 = lerp(g(0, 1, 1), g(1, 1, 1), u);
    return lerp(lerp(x00, x10, v), lerp(x01, x11, v), w);
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(Noise, ValuesAreThoseOfOneHashPerCornerToTheBit) {
    std::mt19937_64 rng(5);
    std::vector<Vec3> points;
    for (const double extent : {1.0, 50.0, 1e6, 1e17, 1e19, 1e300})
        for (int n = 0; n < 3000; ++n) points.push_back(randomPoint(rng, extent));
    // Lattice points, their neighbours a few ulps away, zeros of both signs, the
    // saturated cells and non-finite coordinates.
    const double inf = std::numeric_limits<double>::infinity(), nan = std::nan("");
    for (const double a : {-3.0, -1.0, -0.0, 0.0, 1.0, 2.0, 0.5, std::nextafter(1.0, 0.0), std::nextafter(-2.0, 0.0),
                           4611686018427387904.0, -4611686018427387904.0, 1e30, inf, -inf, nan})
        for (const double b : {0.0, -0.0, 7.25, -7.75, std::nextafter(3.0, 4.0)})
            points.push_back(Vec3(a, b, -b)), points.push_back(Vec3(b, a, b)), points.push_back(Vec3(-b, b, a));
    for (const Vec3& p : points) {
        const double n = noise01(p);
        const double v = 0.5 + 0.5 * referenceSignedNoise(p, 0);
        const double expected = std::isfinite(v) ? std::clamp(v, 0.0, 1.0) : 0.0;
        ASSERT_TRUE(sameBits(n, expected)) << p.x << " " << p.y << " " << p.z << ": " << n << " " << expected;
        const Vec3 d = vectorNoise(p);
        ASSERT_TRUE(sameBits(d.x, std::clamp(referenceSignedNoise(p, 1), -1.0, 1.0)));
        ASSERT_TRUE(sameBits(d.y, std::clamp(referenceSignedNoise(p, 2), -1.0, 1.0)));
        ASSERT_TRUE(sameBits(d.z, std::clamp(referenceSignedNoise(p, 3), -1.0, 1.0)));
    }
}

TEST(Noise, IsContinuousAndDeterministic) {
    std::mt19937_64 rng(11);
    for (int i = 0; i < 2000; ++i) {
        const Vec3 p = randomPoint(rng, 20);
        // Gradients are bounded by a few units: a step of 1e-6 moves the value by < 1e-4.
        EXPECT_LT(std::fabs(noise01(p) - noise01(p + Vec3(1e-6, -1e-6, 1e-6))), 1e-4);
        EXPECT_EQ(noise01(p), noise01(p));
    }
    // Not constant across cells.
    EXPECT_NE(noise01(Vec3(0.5, 0.5, 0.5)), noise01(Vec3(1.5, 0.5, 0.5)));
}

TEST(Noise, TurbulenceWithOneOctaveIsAPlainNoiseWarp) {
    Turbulence t;
    t.amount = Vec3(0.3, 0.5, 0.7);
    t.octaves = 1;
    std::mt19937_64 rng(3);
    for (int i = 0; i < 200; ++i) {
        const Vec3 p = randomPoint(rng, 10);
        const Vec3 expected = t.amount * vectorNoise(p);
        const Vec3 got = turbulenceOffset(t, p);
        EXPECT_DOUBLE_EQ(got.x, expected.x);
        EXPECT_DOUBLE_EQ(got.y, expected.y);
        EXPECT_DOUBLE_EQ(got.z, expected.z);
        // and the pattern is evaluated at the warped point
        EXPECT_DOUBLE_EQ(noisePatternValue(PatternKind::Bozo, t, p),
                         noisePatternValue(PatternKind::Bozo, Turbulence{}, p + expected));
        // except marble, which adds the scalar turbulence to x (POV-Ray)
        EXPECT_NEAR(noisePatternValue(PatternKind::Marble, t, p),
                    noisePatternValue(PatternKind::Marble, Turbulence{},
                                      Vec3(p.x + t.amount.x * scalarTurbulence(t, p), 0, 0)),
                    1e-9);
    }
    const Vec3 none = turbulenceOffset(Turbulence{}, Vec3(1.3, 2.1, 0.4));
    EXPECT_EQ(none.x, 0.0);
    // More octaves add detail: the offset changes.
    Turbulence six = t;
    six.octaves = 6;
    EXPECT_NE(turbulenceOffset(six, Vec3(1.3, 2.1, 0.4)).x, turbulenceOffset(t, Vec3(1.3, 2.1, 0.4)).x);
}

TEST(Noise, PatternValuesStayInUnitRangeAndVary) {
    Turbulence t;
    t.amount = Vec3(0.4);
    std::mt19937_64 rng(5);
    for (PatternKind kind : kAllNoise) {
        double lo = 1, hi = 0;
        for (int i = 0; i < 3000; ++i) {
            const double v = noisePatternValue(kind, t, randomPoint(rng, 8));
            ASSERT_TRUE(v >= 0.0 && v <= 1.0) << int(kind) << " " << v;
            lo = std::min(lo, v), hi = std::max(hi, v);
        }
        EXPECT_GT(hi - lo, 0.3) << "pattern " << int(kind) << " is nearly constant";
    }
}

TEST(Noise, WoodIsConcentricAroundTheZAxis) {
    const Turbulence none;
    // Same radius from the z axis, any angle and any z: the same value.
    const double r = 1.3;
    const double v = noisePatternValue(PatternKind::Wood, none, Vec3(r, 0, 0));
    EXPECT_NEAR(noisePatternValue(PatternKind::Wood, none, Vec3(0, r, 5)), v, 1e-12);
    EXPECT_NEAR(noisePatternValue(PatternKind::Wood, none, Vec3(-r / std::sqrt(2.0), r / std::sqrt(2.0), -2)), v,
                1e-12);
    // Marble varies along x only.
    EXPECT_NEAR(noisePatternValue(PatternKind::Marble, none, Vec3(0.25, 3, -7)), 0.5, 1e-12);
}

TEST(Noise, BumpNormalsAreUnitOnTheSurfaceSideAndNeverNaN) {
    std::mt19937_64 rng(9);
    for (PatternKind kind : kAllNoise) {
        Normal bump;
        bump.pattern = kind;
        bump.amount = 0.5; // POV-Ray's default
        bump.toWorld = Transform::scale(Vec3(0.2));
        double maxTilt = 0;
        for (int i = 0; i < 500; ++i) {
            const Vec3 n = normalize(randomPoint(rng, 1) + Vec3(0, 0, 1e-3));
            const Vec3 b = perturbNormal(bump, randomPoint(rng, 5), n);
            ASSERT_TRUE(finite(b));
            EXPECT_NEAR(length(b), 1.0, 1e-9);
            if (kind == PatternKind::Bumps || kind == PatternKind::Dents) {
                EXPECT_GT(dot(b, n), 0.2);
            }
            maxTilt = std::max(maxTilt, 1 - dot(b, n));
        }
        EXPECT_GT(maxTilt, 1e-4) << "pattern " << int(kind) << " does not bump";
    }
    // Amount 0 leaves the normal exactly; huge or infinite inputs do not make NaN.
    Normal flat;
    flat.amount = 0;
    EXPECT_EQ(perturbNormal(flat, Vec3(0.3, 0.1, 0.2), Vec3(0, 1, 0)).y, 1.0);
    Normal big;
    big.amount = 1e9;
    EXPECT_TRUE(finite(perturbNormal(big, Vec3(0.31, 0.17, 0.29), Vec3(0, 1, 0))));
    EXPECT_TRUE(finite(perturbNormal(big, Vec3(INFINITY, 0, 0), Vec3(0, 1, 0))));
}

TEST(Noise, NormalPatternsPerturbInPatternSpace) {
    // POV-Ray carries the normal into pattern space before perturbing it: a
    // pattern scaled down uniformly gives the same tilt at the corresponding
    // point (smaller bumps, not steeper ones).
    std::mt19937_64 rng(4);
    for (PatternKind kind : {PatternKind::Bumps, PatternKind::Leopard, PatternKind::Waves, PatternKind::Granite}) {
        Normal unit, small;
        unit.pattern = small.pattern = kind;
        small.toWorld = Transform::scale(Vec3(0.05));
        for (int i = 0; i < 50; ++i) {
            const Vec3 p = randomPoint(rng, 3), n = normalize(randomPoint(rng, 1) + Vec3(0, 1e-3, 0));
            const Vec3 a = perturbNormal(unit, p, n), b = perturbNormal(small, p * 0.05, n);
            EXPECT_NEAR(dot(a, b), 1.0, 1e-9) << int(kind);
        }
    }
    // The slope of a gradient: the tilt is -(0.4 / 3) amount along the axis
    // (POV-Ray's tetrahedron of samples, 0.02 apart, weighted -5 amount).
    Normal ramp;
    ramp.pattern = PatternKind::Gradient;
    ramp.gradientAxis = Vec3(1, 0, 0);
    ramp.amount = 1.5;
    const Vec3 tilted = perturbNormal(ramp, Vec3(0.3, 0, 0.2), Vec3(0, 1, 0));
    EXPECT_NEAR(tilted.x / tilted.y, -0.4 / 3 * 1.5, 1e-9);
    EXPECT_NEAR(tilted.z, 0, 1e-12);
}

TEST(Noise, PigmentUsesTheColorMapAndTurbulence) {
    Pigment p;
    p.pattern = PatternKind::Bozo;
    p.colorMap = {{0, {Color(1, 0, 0), 0, 0}}, {1, {Color(0, 0, 1), 0, 0}}};
    const Vec3 q(0.37, 1.21, -2.6);
    const double v = noise01(q);
    const ColorFT c = evaluatePigment(p, q);
    EXPECT_NEAR(c.rgb.r, 1 - v, 1e-12);
    EXPECT_NEAR(c.rgb.b, v, 1e-12);
    // Turbulence on a gradient warps it too (POV-Ray applies it to every pattern).
    Pigment g;
    g.pattern = PatternKind::Gradient;
    g.colorMap = p.colorMap;
    const double straight = evaluatePigment(g, q).rgb.b;
    g.turbulence.amount = Vec3(0.5);
    EXPECT_NE(evaluatePigment(g, q).rgb.b, straight);
}

std::optional<Scene> loadDrt(const std::string& body, Diagnostics& diags) {
    return loadSceneText("camera { location <0, 0, -5> look_at <0, 0, 0> }\n" + body, "t.drt", diags);
}

TEST(NoiseLanguage, ParsesPatternsTurbulenceAndNormals) {
    Diagnostics diags;
    const auto s = loadDrt("sphere { 0, 1 texture { pigment { wood color_map { [0 rgb 0] [1 rgb 1] } "
                           "turbulence <0.1, 0.2, 0.3> octaves 3 omega 0.6 lambda 2.5 scale 2 }\n"
                           "normal { bumps 0.4 turbulence 0.2 scale 0.5 } } translate <1, 0, 0> }\n"
                           "sphere { 0, 1 pigment { granite } normal { dents } }",
                           diags);
    ASSERT_TRUE(s) << diags.formatAll();
    const Texture& t = s->objects[0].texture;
    EXPECT_EQ(t.pigment.pattern, PatternKind::Wood);
    EXPECT_EQ(t.pigment.turbulence.amount.y, 0.2);
    EXPECT_EQ(t.pigment.turbulence.octaves, 3);
    EXPECT_EQ(t.pigment.turbulence.omega, 0.6);
    EXPECT_EQ(t.pigment.turbulence.lambda, 2.5);
    ASSERT_TRUE(t.normal);
    EXPECT_EQ(t.normal->pattern, PatternKind::Bumps);
    EXPECT_EQ(t.normal->amount, 0.4);
    EXPECT_EQ(t.normal->turbulence.amount.x, 0.2);
    // The normal moves with the object: scale 0.5 then translate 1.
    const Vec3 origin = t.normal->toWorld.point(Vec3(0, 0, 0)), unit = t.normal->toWorld.point(Vec3(1, 0, 0));
    EXPECT_NEAR(origin.x, 1.0, 1e-12);
    EXPECT_NEAR(unit.x, 1.5, 1e-12);
    const Texture& u = s->objects[1].texture;
    EXPECT_EQ(u.pigment.pattern, PatternKind::Granite);
    ASSERT_TRUE(u.normal);
    EXPECT_EQ(u.normal->pattern, PatternKind::Dents);
    EXPECT_EQ(u.normal->amount, 0.5);
}

TEST(NoiseLanguage, ErrorsPointAtTheBadItem) {
    struct Case {
        const char* text;
        const char* message;
        int column;
    };
    const Case cases[] = {
        {"sphere { 0, 1 pigment { bozo octaves 0 } }", "'octaves' must be between 1 and 10", 38},
        {"sphere { 0, 1 pigment { bozo turbulence -1 } }", "'turbulence' must not be negative", 41},
        {"sphere { 0, 1 normal { bumpy 0.3 } }", "bumpy", 24},
        {"sphere { 0, 1 normal { bumps 0.3 octave 2 } }", "octave", 34},
    };
    for (const Case& c : cases) {
        Diagnostics diags;
        EXPECT_FALSE(loadSceneText(std::string(c.text), "e.drt", diags)) << c.text;
        ASSERT_GE(diags.errorCount(), 1) << c.text;
        const Diagnostic& d = diags.all().front();
        EXPECT_NE(d.message.find(c.message), std::string::npos) << d.message;
        EXPECT_EQ(d.loc.line, 1) << c.text;
        EXPECT_EQ(d.loc.column, c.column) << c.text << ": " << d.message;
    }
}

TEST(NoiseLanguage, WriterRoundTripIsExact) {
    Diagnostics diags;
    const auto s = loadDrt("sphere { 0, 1 texture { pigment { agate color_map { [0 rgb 0.2] [1 rgb <1, 0.5, 0>] } "
                           "turbulence <0.1, 0.2, 0.3> octaves 4 scale 0.3 } normal { wrinkles 0.7 omega 0.4 "
                           "rotate <0, 30, 0> } finish { phong 1 } } translate <1, 2, 0> }\n"
                           "box { -1, 1 pigment { crackle turbulence 0.2 } normal { ripples 0.2 } }",
                           diags);
    ASSERT_TRUE(s) << diags.formatAll();
    const std::string text = writeDrtScene(*s, {"test"});
    EXPECT_NE(text.find("agate"), std::string::npos) << text;
    EXPECT_NE(text.find("normal { wrinkles 0.7"), std::string::npos) << text;
    Diagnostics again;
    const auto reread = loadSceneText(text, "w.drt", again);
    ASSERT_TRUE(reread) << again.formatAll() << text;
    EXPECT_EQ(writeDrtScene(*reread, {"test"}), text);
    const Texture& a = s->objects[0].texture;
    const Texture& b = reread->objects[0].texture;
    ASSERT_TRUE(b.normal);
    EXPECT_EQ(b.pigment.pattern, PatternKind::Agate);
    EXPECT_EQ(b.pigment.turbulence.octaves, 4);
    EXPECT_EQ(b.normal->turbulence.omega, 0.4);
    const Vec3 q(0.3, 0.7, -0.2);
    EXPECT_EQ(evaluatePigment(a.pigment, q).rgb.g, evaluatePigment(b.pigment, q).rgb.g);
    EXPECT_EQ(perturbNormal(*a.normal, q, Vec3(0, 1, 0)).x, perturbNormal(*b.normal, q, Vec3(0, 1, 0)).x);
}

TEST(NoisePov, WoodWithTurbulenceAndBumpsLoadsWithNotesOnly) {
    Diagnostics diags;
    const auto s = loadPovSceneText("sphere { 0, 1 pigment { wood turbulence 0.3 color_map { [0 rgb <0.6, 0.3, 0.1>] "
                                    "[1 rgb <0.3, 0.1, 0>] } } normal { bumps 0.4 scale 0.2 } }\n"
                                    "sphere { 0, 1 pigment { wood octaves 3 } }",
                                    "s.pov", diags);
    ASSERT_TRUE(s) << diags.formatAll();
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    int woodNotes = 0;
    for (const Diagnostic& d : diags.all())
        if (d.severity == Severity::Note && d.message.find("'wood'") != std::string::npos) ++woodNotes;
    EXPECT_EQ(woodNotes, 1) << diags.formatAll();
    const Texture& t = s->objects[0].texture;
    EXPECT_EQ(t.pigment.pattern, PatternKind::Wood);
    EXPECT_EQ(t.pigment.turbulence.amount.z, 0.3);
    ASSERT_EQ(t.pigment.colorMap.size(), 2u);
    ASSERT_TRUE(t.normal);
    EXPECT_EQ(t.normal->pattern, PatternKind::Bumps);
    EXPECT_EQ(t.normal->amount, 0.4);
    EXPECT_NEAR(t.normal->toWorld.point(Vec3(1, 0, 0)).x, 0.2, 1e-12);
    EXPECT_EQ(s->objects[1].texture->pigment.turbulence.octaves, 3);
    // A normal pattern drt does not model still warns.
    Diagnostics other;
    ASSERT_TRUE(loadPovSceneText("sphere { 0, 1 normal { facets 0.4 } }", "q.pov", other));
    EXPECT_EQ(other.warningCount(), 1) << other.formatAll();
}

TEST(NoisePov, WoodWithoutAColourMapTakesPovRaysBrowns) {
    // Measured on POV-Ray 3.7 (pigment { wood } along x, no turbulence): light
    // brown up to x = 0.3 (value 0.6 of the triangle wave), dark brown to 0.7.
    Diagnostics diags;
    const auto s = loadPovSceneText("#declare P = pigment { wood }\n"
                                    "sphere { 0, 1 pigment { P } }\n"
                                    "sphere { 0, 1 pigment { P color_map { [0 rgb 0] [1 rgb 1] } } }",
                                    "s.pov", diags);
    ASSERT_TRUE(s) << diags.formatAll();
    const Pigment& bare = s->objects[0].texture->pigment;
    for (const double x : {0.05, 0.29, 0.71, 0.95}) {
        const ColorFT c = evaluatePigment(bare, Vec3(x, 0, 0));
        EXPECT_NEAR(c.rgb.r, 0.666, 1e-12) << x;
        EXPECT_NEAR(c.rgb.g, 0.312, 1e-12) << x;
        EXPECT_NEAR(c.rgb.b, 0.2, 1e-12) << x;
    }
    for (const double x : {0.31, 0.5, 0.69}) {
        const ColorFT c = evaluatePigment(bare, Vec3(0, x, 0)); // rings round the z axis
        EXPECT_NEAR(c.rgb.r, 0.4, 1e-12) << x;
        EXPECT_NEAR(c.rgb.g, 0.1333, 1e-12) << x;
        EXPECT_NEAR(c.rgb.b, 0.0667, 1e-12) << x;
    }
    // A colour map given later replaces the default.
    EXPECT_NEAR(evaluatePigment(s->objects[1].texture->pigment, Vec3(0.2, 0, 0)).rgb.g, 0.4, 1e-9);
}

} // namespace
} // namespace drt
