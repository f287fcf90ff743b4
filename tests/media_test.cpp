// Participating media (scene.h Media, render/media.h): phase functions
// against their defining integrals, the estimator against closed forms
// (absorption, emission, single scattering), rendered pixels through an
// absorbing slab, density scaling, determinism across thread counts, and the
// POV-Ray and .drt front ends.
#include "accel/accel.h"
#include "lang/load.h"
#include "pov/load.h"
#include "render/media.h"
#include "render/render.h"
#include "sampling/sampler.h"

#include <cmath>
#include <gtest/gtest.h>

namespace drt {
namespace {

// 2 pi int_{-1}^{1} f(c) p(c) dc by the midpoint rule.
double sphereIntegral(int type, double g, double (*f)(double)) {
    const int n = 200000;
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        const double c = -1 + (i + 0.5) * 2.0 / n;
        sum += f(c) * phaseFunction(type, g, c);
    }
    return 2 * kPi * sum * 2.0 / n;
}

TEST(MediaPhase, EveryTypeIntegratesToOneOverTheSphere) {
    for (int type = 1; type <= 5; ++type)
        for (double g : {-0.7, 0.0, 0.3, 0.9}) {
            SCOPED_TRACE(testing::Message() << "type " << type << " g " << g);
            EXPECT_NEAR(sphereIntegral(type, g, [](double) { return 1.0; }), 1.0, 1e-6);
        }
}

TEST(MediaPhase, HenyeyGreensteinHasMeanCosineG) {
    for (double g : {-0.6, -0.2, 0.0, 0.4, 0.8})
        EXPECT_NEAR(sphereIntegral(5, g, [](double c) { return c; }), g, 1e-5) << "g " << g;
    // Isotropic and Rayleigh are symmetric: mean cosine 0; Mie scatters forward.
    EXPECT_NEAR(sphereIntegral(1, 0, [](double c) { return c; }), 0, 1e-9);
    EXPECT_NEAR(sphereIntegral(4, 0, [](double c) { return c; }), 0, 1e-9);
    EXPECT_GT(sphereIntegral(2, 0, [](double c) { return c; }), 0.1);
    EXPECT_GT(sphereIntegral(3, 0, [](double c) { return c; }), sphereIntegral(2, 0, [](double c) { return c; }));
    // Shapes: isotropic is 1/(4 pi); Rayleigh 3 (1 + c^2) / (16 pi).
    EXPECT_NEAR(phaseFunction(1, 0, 0.3), 1 / (4 * kPi), 1e-15);
    EXPECT_NEAR(phaseFunction(4, 0, 0.5), 3 * 1.25 / (16 * kPi), 1e-15);
}

std::unique_ptr<Sampler> fixedSampler(uint64_t seed = 11) {
    std::unique_ptr<Sampler> s = makeSampler("sobol", 1, seed);
    s->startPixelSample(0, 0, 0);
    return s;
}

TEST(MediaEstimator, HomogeneousEmissionWithAbsorptionIsExact) {
    Media m;
    m.emission = Color(0.3, 0.6, 0.9);
    m.absorption = Color(0.5, 1.0, 2.0);
    m.samples = 3;
    const double length = 2.5;
    auto sampler = fixedSampler();
    RayCounts counts;
    const MediaEffect e = integrateMedia({&m}, {0, 0, 0}, {0, 0, 1}, length, {}, *sampler, kFirstMediaDimension, counts);
    for (int c = 0; c < 3; ++c) {
        const double a = m.absorption[c];
        EXPECT_NEAR(e.scale[c], std::exp(-a * length), 1e-12);
        EXPECT_NEAR(e.add[c], m.emission[c] * (1 - std::exp(-a * length)) / a, 1e-12);
    }
}

TEST(MediaEstimator, EmissionWithoutAbsorptionIsELAndDensityScalesIt) {
    Media m;
    m.emission = Color(0.2, 0.4, 0.8);
    auto sampler = fixedSampler();
    RayCounts counts;
    const MediaEffect plain = integrateMedia({&m}, {1, 2, 3}, {1, 0, 0}, 4, {}, *sampler, kFirstMediaDimension, counts);
    EXPECT_NEAR(plain.add.b, 0.8 * 4, 1e-12);
    EXPECT_EQ(plain.scale.g, 1.0);
    // Two constant densities multiply: 0.5 x 0.4 = 0.2 of the emission.
    Pigment half, twoFifths;
    half.color.rgb = Color(0.5);
    twoFifths.color.rgb = Color(0.4);
    m.densities = {half, twoFifths};
    const MediaEffect dense = integrateMedia({&m}, {1, 2, 3}, {1, 0, 0}, 4, {}, *sampler, kFirstMediaDimension, counts);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(dense.add[c], 0.2 * plain.add[c], 1e-12);
}

// The mean of many N-sample estimates against a closed form: z = |mean -
// exact| / (standard error) below 4 (fixed seeds, so the outcome is fixed);
// and the estimates do vary (the test would notice a constant estimator).
template <class Estimate> void expectUnbiased(Estimate estimate, double exact, int runs = 4096) {
    double sum = 0, sum2 = 0;
    for (int i = 0; i < runs; ++i) {
        const double v = estimate(i);
        sum += v;
        sum2 += v * v;
    }
    const double mean = sum / runs;
    const double variance = std::max(0.0, sum2 / runs - mean * mean);
    const double standardError = std::sqrt(variance / runs);
    EXPECT_GT(standardError, 0);
    EXPECT_LT(std::abs(mean - exact), 4 * standardError + 1e-12)
        << "mean " << mean << " exact " << exact << " standard error " << standardError;
}

TEST(MediaEstimator, GradientDensityMeanMatchesItsIntegral) {
    // density x along x (gradient x, black to white), emission 1 over [0, 0.9]:
    // int_0^0.9 x dx = 0.405.
    Media m;
    m.emission = Color(1);
    m.samples = 4;
    Pigment ramp;
    ramp.pattern = PatternKind::Gradient;
    ramp.gradientAxis = {1, 0, 0};
    ramp.colorMap = {{0, ColorFT{Color(0)}}, {1, ColorFT{Color(1)}}};
    m.densities = {ramp};
    std::unique_ptr<Sampler> sampler = makeSampler("sobol", 1, 5);
    RayCounts counts;
    expectUnbiased(
        [&](int i) {
            sampler->startPixelSample(i % 64, i / 64, 0);
            return integrateMedia({&m}, {0, 0, 0}, {1, 0, 0}, 0.9, {}, *sampler, kFirstMediaDimension, counts).add.r;
        },
        0.405);
}

// In-scattering of an isotropic medium without extinction along the x axis
// from 0 to L, lit by an inverse-square point light of colour I at height h:
// s I int_0^L 4 pi p / (h^2 + x^2) dx = s I atan(L / h) / h.
TEST(MediaEstimator, IsotropicSingleScatteringMatchesTheLineIntegral) {
    Scene scene;
    Light light;
    light.position = {0, 2, 0};
    light.color = Color(3);
    light.inverseSquare = true;
    scene.lights.push_back(light);
    Media m;
    m.scatteringType = 1;
    m.scattering = Color(0.25);
    m.extinction = 0;
    m.samples = 2;
    scene.media.push_back(m);
    const Accelerator accel(scene);
    const double length = 5, h = 2;
    std::unique_ptr<Sampler> sampler = makeSampler("sobol", 1, 9);
    RayCounts counts;
    expectUnbiased(
        [&](int i) {
            sampler->startPixelSample(i % 64, i / 64, 0);
            return integrateMedia({&scene.media[0]}, {0, 0, 0}, {1, 0, 0}, length, {&scene, &accel, 0}, *sampler,
                                  kFirstMediaDimension, counts)
                .add.g;
        },
        0.25 * 3 * std::atan(length / h) / h);
}

// Henyey-Greenstein with a POV-Ray light (no distance falloff): the closed
// form is a numerical line integral of s I 4 pi p(cos theta(x)).
TEST(MediaEstimator, HenyeyGreensteinScatteringMatchesTheNumericalIntegral) {
    Scene scene;
    Light light;
    light.position = {6, 1, 0};
    light.color = Color(1);
    scene.lights.push_back(light);
    Media m;
    m.scatteringType = 5;
    m.eccentricity = 0.6;
    m.scattering = Color(0.1);
    m.extinction = 0;
    scene.media.push_back(m);
    const Accelerator accel(scene);
    const double length = 4;
    double exact = 0;
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        const double x = (i + 0.5) * length / n;
        const Vec3 toLight = normalize(light.position - Vec3{x, 0, 0});
        exact += 0.1 * 4 * kPi * phaseFunction(5, 0.6, toLight.x) * length / n;
    }
    std::unique_ptr<Sampler> sampler = makeSampler("sobol", 1, 21);
    RayCounts counts;
    expectUnbiased(
        [&](int i) {
            sampler->startPixelSample(i % 64, i / 64, 0);
            return integrateMedia({&scene.media[0]}, {0, 0, 0}, {1, 0, 0}, length, {&scene, &accel, 0}, *sampler,
                                  kFirstMediaDimension, counts)
                .add.r;
        },
        exact);
}

TEST(MediaEstimator, ShadowRaysAreDimmedByTheMediaTheyCross) {
    Scene scene;
    Media m;
    m.absorption = Color(0.5);
    scene.media.push_back(m);
    const Accelerator accel(scene);
    Hit from;
    from.point = {0, 0, 0};
    RayCounts counts;
    const Color t = shadowTransmittance(accel, from, {0, 3, 0}, 0, counts, &scene);
    EXPECT_NEAR(t.r, std::exp(-0.5 * 3), 1e-6); // the origin is offset by float rounding only
    EXPECT_EQ(shadowTransmittance(accel, from, {0, 3, 0}, 0, counts).r, 1.0);
}

// A ray inside media object M (hollow) meets objects G: which media does each segment see?
TEST(MediaSegments, HollowObjectsLetTheSurroundingMediaInAndSolidOnesDoNot) {
    Scene scene;
    scene.media.resize(1); // atmospheric
    Object m, hollowGlass, solidGlass;
    m.interior.media.resize(2);
    m.hollow = true;
    hollowGlass.hollow = true;
    const Vec3 d{0, 0, 1};
    auto hitOn = [&](const Object& o, bool leaving) {
        Hit h;
        h.object = &o;
        h.geometricNormal = leaving ? Vec3{0, 0, 1} : Vec3{0, 0, -1};
        return h;
    };
    MediaList out;
    auto media = [&](const Object* inside, const Hit* hit) {
        out.clear();
        segmentMedia(scene, inside, hit, d, out);
        return out;
    };
    const Hit enterHollow = hitOn(hollowGlass, false), leaveHollow = hitOn(hollowGlass, true);
    const Hit leaveSolid = hitOn(solidGlass, true), leaveM = hitOn(m, true);
    // Inside M up to another object: M's media and the atmosphere (M is hollow).
    EXPECT_EQ(media(&m, &enterHollow), (MediaList{&m.interior.media[0], &m.interior.media[1], &scene.media[0]}));
    // Inside a hollow object within M: M's media still; inside a solid one: nothing.
    EXPECT_EQ(media(&m, &leaveHollow), (MediaList{&m.interior.media[0], &m.interior.media[1], &scene.media[0]}));
    EXPECT_EQ(media(&m, &leaveSolid), MediaList{});
    // Leaving M itself, or a media object the ray did not know it was in.
    EXPECT_EQ(media(&m, &leaveM), (MediaList{&m.interior.media[0], &m.interior.media[1], &scene.media[0]}));
    EXPECT_EQ(media(nullptr, &leaveM), (MediaList{&m.interior.media[0], &m.interior.media[1], &scene.media[0]}));
    // Outside everything: the atmosphere, also for rays that hit nothing.
    EXPECT_EQ(media(nullptr, &enterHollow), MediaList{&scene.media[0]});
    EXPECT_EQ(media(nullptr, nullptr), MediaList{&scene.media[0]});
    // What a transmitted ray is inside after crossing a surface.
    EXPECT_EQ(mediumAfterCrossing(nullptr, m, true), &m);
    EXPECT_EQ(mediumAfterCrossing(&m, hollowGlass, true), &m); // no media of its own: keeps M
    EXPECT_EQ(mediumAfterCrossing(&m, hollowGlass, false), &m);
    EXPECT_EQ(mediumAfterCrossing(&m, m, false), nullptr);
}

TEST(MediaEstimator, LightsWithoutMediaInteractionDoNotScatter) {
    Scene scene;
    Light light;
    light.position = {0, 2, 0};
    light.mediaInteraction = false;
    scene.lights.push_back(light);
    Media m;
    m.scatteringType = 1;
    m.scattering = Color(0.5);
    scene.media.push_back(m);
    const Accelerator accel(scene);
    auto sampler = fixedSampler();
    RayCounts counts;
    const MediaEffect off = integrateMedia({&scene.media[0]}, {0, 0, 0}, {1, 0, 0}, 3, {&scene, &accel, 0}, *sampler,
                                           kFirstMediaDimension, counts);
    EXPECT_EQ(off.add.r, 0.0);
    EXPECT_NEAR(off.scale.r, std::exp(-0.5 * 3), 1e-12); // it still dims what lies behind
    scene.lights[0].mediaInteraction = true;
    const MediaEffect on = integrateMedia({&scene.media[0]}, {0, 0, 0}, {1, 0, 0}, 3, {&scene, &accel, 0}, *sampler,
                                          kFirstMediaDimension, counts);
    EXPECT_GT(on.add.r, 0.0);
}

RenderOptions tinyOptions(int threads = 1) {
    RenderOptions o;
    o.width = 5;
    o.height = 5;
    o.samplesPerPixel = 1;
    o.seed = 3;
    o.threads = threads;
    return o;
}

// A self-lit wall at z = 10 seen through a clear hollow box from z = 2 to 2 + d
// holding an absorbing medium: the wall's colour times exp(-a d).
Scene slabScene(double thickness, const Color& absorption) {
    Scene scene;
    Object wall;
    wall.shape = Plane{{0, 0, -1}, -10};
    wall.texture.edit().pigment.color.rgb = {0.9, 0.5, 0.2};
    wall.texture.edit().finish.ambient = Color(1);
    wall.texture.edit().finish.diffuse = 0;
    scene.objects.push_back(wall);
    Object slab;
    slab.shape = Box{{-5, -5, 2}, {5, 5, 2 + thickness}};
    slab.texture.edit().pigment.color = ColorFT{Color(1), 0, 1};
    slab.texture.edit().finish.ambient = Color(0);
    slab.texture.edit().finish.diffuse = 0;
    slab.hollow = true;
    Media m;
    m.absorption = absorption;
    slab.interior.media.push_back(m);
    scene.objects.push_back(slab);
    scene.camera.angle = 0.5;
    return scene;
}

TEST(MediaRender, AbsorbingSlabTransmitsExpMinusAD) {
    const Color a(0.3, 0.7, 1.5);
    const double d = 1.5;
    const Image image = render(slabScene(d, a), tinyOptions()).color;
    const Color wall(0.9, 0.5, 0.2);
    // Tolerance: spawned rays start offset by float rounding (about 1e-4 at z = 3.5), which changes d.
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.at(2, 2, c), wall[c] * std::exp(-a[c] * d), 1e-4);
    // Without the medium the wall is seen unchanged.
    EXPECT_NEAR(render(slabScene(d, Color(0)), tinyOptions()).color.at(2, 2, 0), wall.r, 1e-6);
}

// A clear hollow sphere of radius 1 at z = 5 holding an emitting, absorbing
// medium, seen through its centre (chord 2) in front of a self-lit wall:
// e (1 - exp(-2 a)) / a + exp(-2 a) wall.
TEST(MediaRender, EmittingSphereAddsItsClosedFormInFrontOfTheWall) {
    Scene scene = slabScene(0, Color(0));
    scene.objects.pop_back();
    Object ball;
    ball.shape = Sphere{{0, 0, 5}, 1};
    ball.texture.edit().pigment.color = ColorFT{Color(1), 0, 1};
    ball.texture.edit().finish.ambient = Color(0);
    ball.texture.edit().finish.diffuse = 0;
    ball.hollow = true;
    Media m;
    m.emission = Color(0.25, 0.5, 0.75);
    m.absorption = Color(0.4, 0.1, 0);
    ball.interior.media.push_back(m);
    scene.objects.push_back(ball);
    scene.camera.angle = 0.05; // rays within 1e-3 of the axis: chords 2 within 1e-6
    const Image image = render(scene, tinyOptions()).color;
    const Color wall(0.9, 0.5, 0.2);
    for (int c = 0; c < 3; ++c) {
        const double a = m.absorption[c], e = m.emission[c];
        const double glow = a > 0 ? e * (1 - std::exp(-2 * a)) / a : 2 * e;
        EXPECT_NEAR(image.at(2, 2, c), glow + std::exp(-2 * a) * wall[c], 1e-4) << "channel " << c;
    }
}

TEST(MediaRender, ScatteringImageIsTheSameForAnyThreadCount) {
    Scene scene = slabScene(2, Color(0.1));
    Media haze;
    haze.scatteringType = 2;
    haze.scattering = Color(0.05);
    haze.samples = 3;
    scene.media.push_back(haze);
    Light light;
    light.position = {1, 3, 4};
    scene.lights.push_back(light);
    RenderOptions one = tinyOptions(1), three = tinyOptions(3);
    one.width = three.width = 24;
    one.height = three.height = 16;
    one.tileSize = three.tileSize = 4;
    const Image a = render(scene, one).color, b = render(scene, three).color;
    EXPECT_TRUE(a.pixels == b.pixels);
    for (float v : a.pixels) EXPECT_TRUE(std::isfinite(v));
}

// ------------------------------------------------------------ front ends

Scene loadPov(const std::string& text, Diagnostics& diags) {
    std::optional<Scene> scene = loadPovSceneText(text, "s.pov", diags, PovOptions{});
    EXPECT_TRUE(scene) << diags.formatAll();
    return scene ? *scene : Scene{};
}

TEST(PovMedia, InteriorAndAtmosphericMediaAreReadWithoutWarnings) {
    Diagnostics diags;
    const Scene s = loadPov(R"(#version 3.7;
#declare Glow = media { emission 0.05 intervals 2 samples 5, 10 method 3 confidence 0.9 variance 0.01 ratio 0.9
                        jitter 0.5 aa_threshold 0.1 aa_level 4
                        density { spherical ramp_wave color_map { [0 rgb 0] [1 rgb <1, 1, 0>] } } }
#declare D = density { gradient y }
media { scattering { 2, rgb 0.03 extinction 0.5 } }
light_source { <0, 15, 0> rgb 0.7 media_interaction off }
light_source { <0, 15, 2> rgb 0.7 media_attenuation on }
sphere { 0, 1 pigment { rgbt 1 } interior { media { Glow } media { absorption rgb <1, 2, 3> density { D scale 2 } } }
         scale 28 hollow }
)", diags);
    EXPECT_EQ(diags.formatAll(), "");
    ASSERT_EQ(s.media.size(), 1u);
    EXPECT_EQ(s.media[0].scatteringType, 2);
    EXPECT_DOUBLE_EQ(s.media[0].extinction, 0.5);
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_FALSE(s.lights[0].mediaInteraction);
    EXPECT_FALSE(s.lights[0].mediaAttenuation); // POV-Ray's default
    EXPECT_TRUE(s.lights[1].mediaAttenuation);
    ASSERT_EQ(s.objects.size(), 1u);
    const std::vector<Media>& media = s.objects[0].interior.media;
    ASSERT_EQ(media.size(), 2u);
    EXPECT_EQ(media[0].intervals, 2);
    EXPECT_EQ(media[0].samples, 5);
    EXPECT_EQ(media[0].emission, Color(0.05));
    ASSERT_EQ(media[0].densities.size(), 1u);
    EXPECT_EQ(media[0].densities[0].pattern, PatternKind::Spherical);
    // The object's scale moves the densities: spherical is 1 - r / 28 in world space.
    EXPECT_NEAR(mediaDensity(media[0], {14, 0, 0}).g, 0.5, 1e-12);
    EXPECT_EQ(media[1].absorption, Color(1, 2, 3));
    EXPECT_NEAR(mediaDensity(media[1], {0, 28 * 2 * 0.25, 0}).r, 0.25, 1e-12); // gradient y scaled by 2 then 28
}

TEST(PovMedia, ABadScatteringTypeIsAnErrorWithItsLocation) {
    Diagnostics diags;
    const std::optional<Scene> s =
        loadPovSceneText("media {\n  scattering { 7, 0.1 } }", "s.pov", diags, PovOptions{});
    EXPECT_FALSE(s);
    ASSERT_GE(diags.errorCount(), 1);
    EXPECT_EQ(diags.all()[0].message, "the scattering type must be 1, 2, 3, 4 or 5, got 7");
    EXPECT_EQ(diags.all()[0].loc.line, 2);
    EXPECT_EQ(diags.all()[0].loc.column, 16);
}

TEST(DrtMedia, DensityDefaultsToOneAndTransformsFollowTheObject) {
    Diagnostics diags;
    const std::optional<Scene> s = loadSceneText(R"(
media { absorption 0.1 }
sphere { 0, 1 interior { media { emission 1 density { } density { onion } } } scale 4 translate x hollow }
)", "m.drt", diags);
    ASSERT_TRUE(s) << diags.formatAll();
    ASSERT_EQ(s->media.size(), 1u);
    const Media& m = s->objects[0].interior.media[0];
    EXPECT_EQ(mediaDensity(m, {1, 0, 0}).r, 0.0);         // onion at the (moved) centre
    EXPECT_NEAR(mediaDensity(m, {3, 0, 0}).r, 0.5, 1e-12); // distance 2 in world, 0.5 in pattern space
}

} // namespace
} // namespace drt
