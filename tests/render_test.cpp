// The renderer end to end on scenes built in C++: hand-computed pixels, POV-Ray
// trace-depth semantics, determinism across threads and tiles, and robustness.
#include "lang/load.h"
#include "render/render.h"

#include "render/directions.h"
#include "render/film.h"
#include "render/pigment.h"
#include "render/lighting.h"
#include "render/shading.h"
#include "sampling/sampler.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <memory>
#include <optional>
#include <random>
#include <vector>

namespace drt {
namespace {

Texture solid(Color rgb, double filter = 0, double transmit = 0) {
    Texture t;
    t.pigment.color = ColorFT{rgb, filter, transmit};
    return t;
}

Object plane(Vec3 normal, double distance, Texture texture) {
    Object o;
    o.shape = Plane{normal, distance};
    o.texture = texture;
    return o;
}

Object sphere(Vec3 center, double radius, Texture texture) {
    Object o;
    o.shape = Sphere{center, radius};
    o.texture = texture;
    return o;
}

Light pointLight(Vec3 position, Color color) {
    Light l;
    l.position = position;
    l.color = color;
    return l;
}

// A camera whose every ray leaves `location` along `direction` (right and up
// are vanishingly small), so a 1x1 image samples one known ray.
CameraSpec needleCamera(Vec3 location, Vec3 direction, Vec3 upHint = {0, 0, 1}) {
    CameraSpec c;
    c.location = location;
    c.direction = direction;
    c.up = normalize(upHint) * 1e-9;
    c.right = normalize(cross(upHint, direction)) * 1e-9;
    return c;
}

RenderOptions options(int w, int h, int spp = 1) {
    RenderOptions o;
    o.width = w;
    o.height = h;
    o.samplesPerPixel = spp;
    o.threads = 1;
    return o;
}

Color pixel(const RenderResult& r, int x = 0, int y = 0) {
    return {r.color.at(x, y, 0), r.color.at(x, y, 1), r.color.at(x, y, 2)};
}

void expectColorNear(const Color& a, const Color& b, double tolerance) {
    EXPECT_NEAR(a.r, b.r, tolerance);
    EXPECT_NEAR(a.g, b.g, tolerance);
    EXPECT_NEAR(a.b, b.b, tolerance);
}

void expectAllFinite(const Image& image) {
    for (float v : image.pixels) ASSERT_TRUE(std::isfinite(v));
}

// ---------------------------------------------------------------- shading by hand

TEST(Render, DiffusePlanePixelMatchesHandComputedValue) {
    Scene scene;
    Texture t = solid({0.8, 0.6, 0.4});
    t.finish.ambient = Color(0.1);
    t.finish.diffuse = 0.6;
    scene.objects.push_back(plane({0, 1, 0}, 0, t));
    scene.lights.push_back(pointLight({3, 4, 0}, {1, 0.5, 0.25}));
    scene.camera = needleCamera({0, 1, 0}, {0, -1, 0});
    // ambient P*0.1 + diffuse 0.6 * (N.L = 4/5) * P * I.
    const Color expected{0.8 * 0.1 + 0.6 * 0.8 * 0.8 * 1.0, 0.6 * 0.1 + 0.6 * 0.8 * 0.6 * 0.5,
                         0.4 * 0.1 + 0.6 * 0.8 * 0.4 * 0.25};
    const RenderResult r = render(scene, options(1, 1));
    expectColorNear(pixel(r), expected, 1e-6);
    EXPECT_EQ(r.stats.cameraRays, 1u);
    EXPECT_EQ(r.stats.shadowRays, 1u);
}

TEST(Render, HighlightsAndBrillianceMatchPovFormulas) {
    Scene scene;
    Texture t = solid({0.5, 0.5, 0.5});
    t.finish.ambient = Color(0);
    t.finish.diffuse = 0.5;
    t.finish.brilliance = 2;
    t.finish.phong = 0.7;
    t.finish.phongSize = 10;
    t.finish.specular = 0.3;
    t.finish.roughness = 0.1;
    scene.objects.push_back(plane({0, 1, 0}, 0, t));
    scene.lights.push_back(pointLight({3, 4, 0}, Color(1)));
    scene.camera = needleCamera({0, 1, 0}, {0, -1, 0});
    // N = y, L = (0.6, 0.8, 0), I = -y: R = y so R.L = 0.8; H = normalize(0.6, 1.8, 0).
    const double cosNH = 1.8 / std::sqrt(0.6 * 0.6 + 1.8 * 1.8);
    const double value = 0.5 * std::pow(0.8, 2) * 0.5 + 0.7 * std::pow(0.8, 10) + 0.3 * std::pow(cosNH, 10);
    expectColorNear(pixel(render(scene, options(1, 1))), Color(value), 1e-6);
}

TEST(Render, MirrorReflectsBackgroundExactly) {
    Scene scene;
    scene.background = {0.2, 0.4, 0.6};
    Texture t = solid(Color(0));
    t.finish.ambient = Color(0);
    t.finish.diffuse = 0;
    t.finish.reflectionMin = t.finish.reflectionMax = Color(0.5);
    scene.objects.push_back(plane({0, 1, 0}, 0, t));
    scene.camera.location = {0, 1, -3};
    scene.camera.lookAt = Vec3(0, 0, 0);
    const RenderResult r = render(scene, options(6, 4, 2));
    for (int y = 0; y < 4; ++y) // the plane fills the lower half
        for (int x = 0; x < 6; ++x)
            if (y >= 2) {
                EXPECT_EQ(r.color.at(x, y, 0), 0.1f);
                EXPECT_EQ(r.color.at(x, y, 1), 0.2f);
                EXPECT_EQ(r.color.at(x, y, 2), 0.3f);
            }
}

TEST(Render, MetallicReflectionIsTintedByThePigment) {
    Scene scene;
    scene.background = Color(1);
    Texture t = solid({1, 0.5, 0});
    t.finish.ambient = Color(0);
    t.finish.diffuse = 0;
    t.finish.reflectionMin = t.finish.reflectionMax = Color(0.5);
    t.finish.reflectionMetallic = 1;
    scene.objects.push_back(plane({0, 1, 0}, 0, t));
    scene.camera = needleCamera({0, 1, 0}, {0, -1, 0});
    // Head on, POV-Ray's empirical Fresnel term is ~0: the full pigment tint.
    expectColorNear(pixel(render(scene, options(1, 1))), {0.5, 0.25, 0}, 1e-6);
}

TEST(Render, GlossyReflectionOfUniformBackgroundKeepsItsEnergy) {
    // Facing the mirror head on, every lobe direction leaves the surface: the
    // glossy mirror of a uniform background is exactly reflection * background.
    Scene scene;
    scene.background = Color(0.5);
    Texture t = solid(Color(0));
    t.finish.ambient = Color(0);
    t.finish.diffuse = 0;
    t.finish.reflectionMin = t.finish.reflectionMax = Color(0.5);
    t.finish.reflectionBlur = 0.4;
    scene.objects.push_back(plane({0, 1, 0}, 0, t));
    scene.camera = needleCamera({0, 1, 0}, {0, -1, 0});
    expectColorNear(pixel(render(scene, options(1, 1, 16))), Color(0.25), 1e-7);

    // At grazing incidence part of the lobe dips below the surface: weight 0,
    // never negative, so the pixel lies in [0, 0.25] and loses energy.
    t.finish.reflectionBlur = 1;
    scene.objects[0] = plane({0, 1, 0}, 0, t);
    scene.camera = needleCamera({0, 1, 0}, {1, -0.05, 0}, {0, 1, 0});
    const Color grazing = pixel(render(scene, options(1, 1, 64)));
    EXPECT_GE(grazing.r, 0.0);
    EXPECT_LT(grazing.r, 0.25);
    EXPECT_GT(grazing.r, 0.05);
}

TEST(Render, TransparentSphereWithIorOneIsInvisible) {
    Scene scene;
    Pigment checker;
    checker.pattern = PatternKind::Checker;
    checker.children.resize(2);
    checker.children[0].color.rgb = {1, 1, 1};
    checker.children[1].color.rgb = {0.1, 0.2, 0.7};
    Texture floor;
    floor.pigment = checker;
    scene.objects.push_back(plane({0, 1, 0}, -1, floor));
    scene.lights.push_back(pointLight({-3, 6, -4}, Color(1)));
    scene.camera.location = {0, 1.5, -5};
    scene.camera.lookAt = Vec3(0, -0.5, 0);
    const RenderResult without = render(scene, options(24, 16));

    Texture glass = solid({1, 1, 1}, 0, 1);
    glass.finish.ambient = Color(0);
    glass.finish.diffuse = 0;
    scene.objects.push_back(sphere({0, 0, 0}, 1, glass));
    const RenderResult with = render(scene, options(24, 16));
    for (size_t i = 0; i < with.color.pixels.size(); ++i)
        EXPECT_NEAR(with.color.pixels[i], without.color.pixels[i], 1e-5) << i;
    EXPECT_GT(with.stats.secondaryRays, 0u);
}

// Inside glass of ior 1.5 below the plane y = 0, looking up: a steep ray leaves
// and sees the red ceiling; a grazing one is totally reflected into the blue
// background below.
Scene totalInternalReflectionScene(Vec3 direction) {
    Scene scene;
    scene.background = {0, 0, 1};
    Texture glass = solid({1, 1, 1}, 0, 1);
    glass.finish.ambient = Color(0);
    glass.finish.diffuse = 0;
    Object surface = plane({0, 1, 0}, 0, glass);
    surface.interior.ior = 1.5;
    scene.objects.push_back(surface);
    Texture red = solid({1, 0, 0});
    red.finish.ambient = Color(1);
    red.finish.diffuse = 0;
    scene.objects.push_back(plane({0, -1, 0}, -10, red)); // y = 10, facing down
    scene.camera = needleCamera({0, -1, 0}, direction, {0, 0, 1});
    return scene;
}

TEST(Render, TotalInternalReflectionTracesTheReflectedRay) {
    // sin(theta) = 0.98 > 1/1.5: total internal reflection.
    const RenderResult grazing = render(totalInternalReflectionScene({1, 0.2, 0}), options(1, 1));
    expectColorNear(pixel(grazing), {0, 0, 1}, 1e-6);
    // sin(theta) = 0.196: refracted out to the ceiling.
    const RenderResult steep = render(totalInternalReflectionScene({0.2, 1, 0}), options(1, 1));
    expectColorNear(pixel(steep), {1, 0, 0}, 1e-6);
    EXPECT_EQ(grazing.stats.nonFiniteSamples + steep.stats.nonFiniteSamples, 0u);
}

// POV-Ray's rule where the transmitted ray is totally reflected: the light it
// brings back is not filtered, and the surface's reflection about the same
// normal is not traced as well (it would add the same mirror ray twice). Glass
// with filter 0.6, transmit 0.2 and reflection 0.3: a grazing ray sees the blue
// background once, at full strength; a steep one the red ceiling through the
// filter (0.8 red) plus 0.3 of the blue reflection.
TEST(Render, TotalInternalReflectionTracesTheMirrorRayOnceUnfiltered) {
    for (const bool conserve : {false, true}) {
        const auto scene = [&](Vec3 direction) {
            Scene s = totalInternalReflectionScene(direction);
            Texture& glass = s.objects[0].texture.edit();
            glass.pigment.color = ColorFT{Color(1, 0.5, 0.25), 0.6, 0.2};
            glass.finish.reflectionMin = glass.finish.reflectionMax = Color(0.3);
            glass.finish.conserveEnergy = conserve;
            return s;
        };
        const RenderResult grazing = render(scene({1, 0.2, 0}), options(1, 1));
        expectColorNear(pixel(grazing), {0, 0, 1}, 1e-6);
        EXPECT_EQ(grazing.stats.secondaryRays, 1u) << "the mirror ray alone";
        const RenderResult steep = render(scene({0.2, 1, 0}), options(1, 1));
        const double through = conserve ? 0.7 : 1.0; // conserve_energy: what is reflected is not transmitted
        expectColorNear(pixel(steep), {0.8 * through, 0, 0.3}, 1e-6);
    }
}

// Two facing mirrors with ambient a and reflection r: the pixel is
// a (1 + r + ... + r^(levels-1)).
Scene hallOfMirrors(int maxTraceLevel) {
    Scene scene;
    Texture t = solid(Color(1));
    t.finish.ambient = Color(0.1);
    t.finish.diffuse = 0;
    t.finish.reflectionMin = t.finish.reflectionMax = Color(0.5);
    scene.objects.push_back(plane({0, 0, 1}, 1, t));  // z = 1
    scene.objects.push_back(plane({0, 0, -1}, 0, t)); // z = 0
    scene.camera = needleCamera({0, 0, 0.5}, {0, 0, 1}, {0, 1, 0});
    scene.global.maxTraceLevel = maxTraceLevel;
    scene.global.adcBailout = 0;
    return scene;
}

TEST(Render, MaxTraceLevelCountsLevelsLikePovRay) {
    // (The film stores floats: tolerances are float rounding.)
    expectColorNear(pixel(render(hallOfMirrors(1), options(1, 1))), Color(0.1), 1e-7);
    expectColorNear(pixel(render(hallOfMirrors(3), options(1, 1))), Color(0.1 * 1.75), 1e-7);
}

TEST(Render, HugeMaxTraceLevelIsClampedNotACrash) {
    const RenderResult r = render(hallOfMirrors(1000), options(2, 2));
    // Clamped to kTraceLevelLimit = 256 levels: 0.1 (1 - 0.5^256) / (1 - 0.5).
    expectColorNear(pixel(r), Color(0.2), 1e-6);
    EXPECT_EQ(r.stats.secondaryRays, 4u * 255u);
}

TEST(Render, AdcBailoutStopsFaintRays) {
    Scene scene = hallOfMirrors(100);
    scene.global.adcBailout = 0.1; // weights 1, 0.5, 0.25, 0.125 pass; 0.0625 does not
    expectColorNear(pixel(render(scene, options(1, 1))), Color(0.1 * 1.875), 1e-7);
}

// ---------------------------------------------------------------- lights

// A white floor (diffuse 1, no ambient) at y = 0, seen straight down at the
// origin by a needle camera; the tests add the lights and blockers.
Scene litFloorScene() {
    Scene scene;
    Texture t = solid(Color(1));
    t.finish.ambient = Color(0);
    t.finish.diffuse = 1;
    scene.objects.push_back(plane({0, 1, 0}, 0, t));
    scene.camera = needleCamera({0, 1, 0}, {0, -1, 0});
    return scene;
}

TEST(Render, SpotlightAndFadeScaleTheDiffuseTerm) {
    Scene scene = litFloorScene();
    Light spot = pointLight({0, 2, 0}, Color(1));
    spot.spotlight = true;
    spot.pointAt = {2, 0, 0}; // 45 degrees off the shaded point (0, 0, 0)
    spot.radius = 30;
    spot.falloff = 60;
    spot.fadeDistance = 1;
    spot.fadePower = 2;
    scene.lights.push_back(spot);
    const double cosFalloff = std::cos(kPi / 3), cosRadius = std::cos(kPi / 6), c = std::cos(kPi / 4);
    const double s = (c - cosFalloff) / (cosRadius - cosFalloff);
    const double expected = s * s * (3 - 2 * s) * (2.0 / (1 + 4.0)); // N.L = 1, distance 2
    expectColorNear(pixel(render(scene, options(1, 1))), Color(expected), 1e-6);
}

TEST(Shading, SpotlightAttenuation) {
    Light spot;
    spot.spotlight = true;
    spot.position = {0, 0, 0};
    spot.pointAt = {0, 0, 1};
    spot.radius = 20;
    spot.falloff = 40;
    EXPECT_DOUBLE_EQ(spotlightAttenuation(spot, spot.position, {0, 0, 5}), 1.0);
    EXPECT_DOUBLE_EQ(spotlightAttenuation(spot, spot.position, {std::tan(0.3), 0, 1}), 1.0); // 17 degrees
    EXPECT_DOUBLE_EQ(spotlightAttenuation(spot, spot.position, {1, 0, 1}), 0.0);             // 45 degrees
    EXPECT_DOUBLE_EQ(spotlightAttenuation(spot, spot.position, {0, 0, -1}), 0.0);            // behind
    spot.tightness = 10;
    EXPECT_NEAR(spotlightAttenuation(spot, spot.position, {std::tan(0.3), 0, 1}), std::pow(std::cos(0.3), 10), 1e-12);
    Light plain;
    EXPECT_DOUBLE_EQ(spotlightAttenuation(plain, plain.position, {1, 0, -1}), 1.0);
}

// outsideSpotCone is a safe shortcut: wherever it says a point is outside,
// the centre's attenuation is exactly 0; and it does say so well outside the
// falloff cone and behind the light. Points are drawn densely around the
// falloff cone's edge (within 1e-6 rad), where the two could disagree.
TEST(Shading, OutsideSpotConeOnlyWhereTheAttenuationIsZero) {
    Light spot;
    spot.spotlight = true;
    spot.position = {1, -2, 3};
    spot.pointAt = {4, 2, 15};
    for (const double falloff : {0.5, 11.0, 40.0, 89.0, 90.0, 120.0}) {
        spot.radius = falloff / 2;
        spot.falloff = falloff;
        const SpotCones cones = spotCones(spot);
        const Vec3 axis = cones.centreAxis / cones.centreAxisLength;
        Vec3 t, b;
        orthonormalBasis(axis, t, b);
        std::mt19937_64 bits(7);
        const auto uniform = [&bits] { return double(bits() >> 11) * 0x1p-53; };
        int outside = 0, zero = 0;
        for (int i = 0; i < 20000; ++i) {
            const double edge = falloff * kPi / 180;
            const double angle = i % 2 ? edge + (uniform() - 0.5) * 2e-6 : uniform() * kPi;
            const double phi = 2 * kPi * uniform(), r = std::exp(uniform() * 20 - 10);
            const Vec3 direction = axis * std::cos(angle) + (t * std::cos(phi) + b * std::sin(phi)) * std::sin(angle);
            const Vec3 point = spot.position + direction * r;
            const double attenuation = spotlightAttenuation(spot, cones, spot.position, point, true);
            if (outsideSpotCone(spot, cones, point)) {
                ++outside;
                ASSERT_EQ(attenuation, 0.0) << "falloff " << falloff << " angle " << angle;
            }
            zero += attenuation == 0;
        }
        // Nearly every zero is found (all but the sliver within 1e-9 of the edge).
        EXPECT_GT(outside, zero * 9 / 10) << falloff;
    }
    EXPECT_TRUE(outsideSpotCone(spot, spotCones(spot), spot.position - (spot.pointAt - spot.position))); // behind
    Light plain;
    EXPECT_FALSE(outsideSpotCone(plain, spotCones(plain), {0, 0, -1})); // not a spotlight
}

// The cone cosines and centre axis computed once per light give the
// attenuation computed from the light at every call, to the bit.
TEST(Shading, SpotConesGiveTheSameAttenuationToTheBit) {
    Light spot;
    spot.spotlight = true;
    spot.position = {0.3, 2, -0.7};
    spot.pointAt = {0.1, 0, 0.2};
    uint64_t state = 12345;
    const auto next = [&state] {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return double(state >> 11) * 0x1.0p-53;
    };
    int lit = 0, partial = 0;
    for (const auto& [radius, falloff, tightness] :
         std::vector<std::array<double, 3>>{{20, 40, 0}, {20, 40, 10}, {40, 20, 3}, {0, 11, 0}, {30, 30, 0.5}}) {
        spot.radius = radius;
        spot.falloff = falloff;
        spot.tightness = tightness;
        const SpotCones cones = spotCones(spot);
        for (int i = 0; i < 2000; ++i) {
            const Vec3 point{4 * next() - 2, 0, 4 * next() - 2};
            const double expected = spotlightAttenuation(spot, spot.position, point);
            ASSERT_EQ(spotlightAttenuation(spot, cones, spot.position, point, true), expected) << i;
            ASSERT_EQ(spotlightAttenuation(spot, cones, spot.position, point, false), expected) << i;
            const Vec3 elsewhere = spot.position + Vec3{next() - 0.5, 0, next() - 0.5};
            ASSERT_EQ(spotlightAttenuation(spot, cones, elsewhere, point, false),
                      spotlightAttenuation(spot, elsewhere, point))
                << i;
            lit += expected > 0;
            partial += expected > 0 && expected < 1;
        }
    }
    EXPECT_GT(lit, 1000);    // the cones were inside the points' range
    EXPECT_GT(partial, 100); // and so were their edges
}

// A sampler that records the dimensions asked of it.
class RecordingSampler : public Sampler {
public:
    explicit RecordingSampler(std::unique_ptr<Sampler> inner)
        : Sampler(inner->samplesPerPixel(), inner->seed()), inner_(std::move(inner)) {}
    std::unique_ptr<Sampler> clone() const override { return std::make_unique<RecordingSampler>(inner_->clone()); }
    void startPixelSample(int x, int y, int index) override { inner_->startPixelSample(x, y, index); }
    double get1D(int d) override { return asked.push_back(d), inner_->get1D(d); }
    Vec2 get2D(int d) override { return asked.push_back(d), inner_->get2D(d); }
    Vec2 get2DStratified(int d, int k, int n) override { return asked.push_back(d), inner_->get2DStratified(d, k, n); }
    std::string name() const override { return "recording"; }
    bool wasAsked(int d) const { return std::find(asked.begin(), asked.end(), d) != asked.end(); }
    std::vector<int> asked;

private:
    std::unique_ptr<Sampler> inner_;
};

// A light's samples are drawn only where its light can arrive: an area
// spotlight whose cone misses the point draws none, and what the point
// receives is the same, to the bit, as without that light.
TEST(Lighting, ALightWhoseConeMissesThePointDrawsNoSamples) {
    Scene scene;
    Texture t = solid(Color(0.8));
    t.finish.diffuse = 0.7;
    t.finish.specular = 0.5;
    t.finish.roughness = 0.1;
    scene.objects.push_back(plane({0, 1, 0}, 0, t));
    const auto areaSpot = [](Vec3 pointAt) {
        Light light = pointLight({0, 4, 0}, Color(1));
        light.area = AreaLight{};
        light.area->axis1 = {1, 0, 0};
        light.area->axis2 = {0, 0, 1};
        light.area->size1 = light.area->size2 = 4;
        light.area->jitter = true;
        light.spotlight = true;
        light.pointAt = pointAt;
        light.radius = 5;
        light.falloff = 10;
        return light;
    };
    Scene withMiss = scene;
    scene.lights.push_back(areaSpot({0, 0, 0}));
    withMiss.lights = {areaSpot({0, 0, 0}), areaSpot({30, 0, 0})};
    const auto shadeFloor = [](const Scene& s, RecordingSampler& sampler, RayCounts& counts) {
        const Accelerator accel(s);
        Ray ray;
        ray.origin = {0.05, 1, 0.02};
        ray.direction = {0, -1, 0};
        Hit hit;
        EXPECT_TRUE(accel.intersect(ray, hit));
        const DirectLighting lighting(s, accel);
        PointLightSamples samples;
        samples.clear();
        ShadingPoint sp;
        sp.hit = &hit;
        sp.normal = {0, 1, 0};
        sp.incoming = {0, -1, 0};
        sp.pigment = s.objects[0].texture->pigment.color;
        sp.finish = &s.objects[0].texture->finish;
        sampler.startPixelSample(2, 3, 5);
        return lighting.shade(sp, samples, sampler, counts);
    };
    RecordingSampler alone(makeSampler("sobol", 16, 1)), both(makeSampler("sobol", 16, 1));
    RayCounts aloneCounts, bothCounts;
    const Color expected = shadeFloor(scene, alone, aloneCounts);
    const Color got = shadeFloor(withMiss, both, bothCounts);
    EXPECT_GT(expected.r, 0);
    EXPECT_EQ(got.r, expected.r);
    EXPECT_EQ(got.g, expected.g);
    EXPECT_EQ(got.b, expected.b);
    EXPECT_TRUE(both.wasAsked(lightDimension(0, 0)));
    EXPECT_FALSE(both.wasAsked(lightDimension(0, 1))) << "the light that cannot reach the point drew a sample";
    EXPECT_EQ(bothCounts.shadow, aloneCounts.shadow);
    EXPECT_EQ(bothCounts.shadow, 1u);
}

// DirectLighting::shade takes a short way for a plain point light (still,
// neither a spotlight nor an area or parallel light, not fading, not black),
// and traces the shadow rays of an area light's points together
// (traceAhead: K split points, a pov_grid light's n1 n2). Every shaded point
// must be the bits, and count the rays, the general way gives
// (DirectLighting's shortWays off): random points, finishes and pigments, two
// layers at a point (the second takes the first's shadows), at depths 0 to 2,
// under plain lights of every colour, inverse_square and shadowless among
// lights that are not plain, with 1 and 4 points a sample, with the shadows
// traced ahead (opaque casters) and traced through a filtering caster.
TEST(Lighting, ShortWaysShadeAsTheGeneralWayDoes) {
    const std::string lights = R"(
camera { location <0, 2, -6> look_at <0, 0.5, 0> angle 60 }
light_source { <-4, 6, -4>, color rgb <0.8, 0.7, 0.6> }
light_source { <3, 5, -3>, color rgb 0.5 spotlight point_at <0, 0, 0> radius 20 falloff 30 }
light_source { <1, 3, -2>, color rgb <2, 1.5, 1> inverse_square }
light_source { <0, 8, 2>, color rgb 0.4 area_light <1, 0, 0>, <0, 0, 1>, 2, 2 }
light_source { <2, 3, -5>, color rgb 0.3 shadowless }
light_source { <5, 4, 0>, color rgb 0.6 fade_distance 3 fade_power 2 }
light_source { <-5, 2, 1>, color rgb 0 }
light_source { <0, 9, -9>, color rgb 0.5 parallel point_at <0, 0, 0> }
light_source { <-2, 1.5, -1>, color rgb <-0.1, 0.4, 0.2> }
light_source { <1, 7, -1>, color rgb 0.4 area_light <1.5, 0, 0>, <0, 0, 1.5>, 3, 3 jitter area_illumination off }
light_source { <-1, 6, -2>, color rgb 0.3 area_light <2, 0, 0>, <0, 0, 1>, 2, 3 area_sampling pov_grid
               area_illumination off }
plane { y, 0 pigment { color rgb 0.7 } }
sphere { <0, 0.8, 0>, 0.8 pigment { color rgb <0.8, 0.3, 0.2> } }
sphere { <-1.6, 0.5, 0.5>, 0.5 pigment { color rgb 0.6 } }
box { <1, 0, -1>, <2, 1.5, 0> pigment { color rgb 0.9 } }
)";
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> u(0, 1);
    for (const auto& [filtering, split] : {std::pair{false, 1}, std::pair{true, 1}, std::pair{false, 4},
                                           std::pair{true, 4}}) {
        Diagnostics diagnostics;
        const std::optional<Scene> scene = loadSceneText(
            lights + (filtering ? "sphere { <0.5, 2.2, -1.5>, 0.4 pigment { color rgbf <1, 0.8, 0.8, 0.7> } }\n" : ""),
            "plain-lights.drt", diagnostics);
        ASSERT_TRUE(scene && !diagnostics.hasErrors()) << diagnostics.formatAll();
        const Accelerator accel(*scene);
        const DirectLighting fast(*scene, accel, true, split), general(*scene, accel, false, split);
        const std::unique_ptr<Sampler> fastSampler = makeSampler("sobol", 8, 3), generalSampler = fastSampler->clone();
        PointLightSamples fastSamples, generalSamples;
        RayCounts fastCounts, generalCounts;
        int shaded = 0, lit = 0;
        for (int packet = 0; packet < 150; ++packet) {
            Ray rays[Accelerator::kPacketSize];
            const Vec3 aim{-4 + 8 * u(rng), -0.5 + 3 * u(rng), 0};
            for (Ray& r : rays) {
                r.origin = {0, 2, -6};
                r.direction = aim + Vec3{0.3 * u(rng), 0.3 * u(rng), 0} - r.origin;
                r.time = 0;
            }
            Hit hits[Accelerator::kPacketSize];
            bool found[Accelerator::kPacketSize];
            accel.intersectPacket(rays, Accelerator::kPacketSize, hits, found);
            CameraShadows fastAhead, generalAhead;
            fast.traceCameraShadows(rays, hits, found, Accelerator::kPacketSize, fastAhead);
            general.traceCameraShadows(rays, hits, found, Accelerator::kPacketSize, generalAhead);
            for (int k = 0; k < Accelerator::kPacketSize; ++k) {
                if (!found[k]) continue;
                ShadingPoint fastPoint;
                fastPoint.hit = &hits[k];
                fastPoint.incoming = normalize(rays[k].direction);
                fastPoint.normal = dot(fastPoint.incoming, hits[k].shadingNormal) < 0 ? hits[k].shadingNormal
                                                                                       : -hits[k].shadingNormal;
                fastPoint.depth = k % 3;
                fastPoint.cameraShadows = fastPoint.depth == 0 ? &fastAhead : nullptr;
                ShadingPoint generalPoint = fastPoint;
                generalPoint.cameraShadows = fastPoint.depth == 0 ? &generalAhead : nullptr;
                fastSamples.clear();
                generalSamples.clear();
                fastSampler->startPixelSample(packet % 16, packet / 16, k);
                generalSampler->startPixelSample(packet % 16, packet / 16, k);
                for (int layer = 0; layer < 2; ++layer, ++shaded) {
                    Finish finish;
                    finish.diffuse = u(rng);
                    if (u(rng) < 0.4) finish.brilliance = 0.5 + 3 * u(rng);
                    if (u(rng) < 0.4) finish.phong = u(rng), finish.phongSize = 1 + 80 * u(rng);
                    if (u(rng) < 0.4) finish.specular = u(rng), finish.roughness = 0.001 + 0.1 * u(rng);
                    if (u(rng) < 0.3) finish.metallic = u(rng);
                    if (u(rng) < 0.3) finish.crand = 0.3 * u(rng);
                    fastPoint.pigment = generalPoint.pigment = {Color(1.4 * u(rng) - 0.1, u(rng), u(rng)), 0.2 * u(rng), 0};
                    fastPoint.finish = generalPoint.finish = &finish;
                    const Color a = fast.shade(fastPoint, fastSamples, *fastSampler, fastCounts);
                    const Color b = general.shade(generalPoint, generalSamples, *generalSampler, generalCounts);
                    if (!isBlack(a)) ++lit;
                    for (int c = 0; c < 3; ++c)
                        ASSERT_EQ(std::bit_cast<uint64_t>(a[c]), std::bit_cast<uint64_t>(b[c]))
                            << (filtering ? "filtering" : "opaque") << ", K = " << split << ", point " << shaded
                            << " channel " << c;
                }
            }
        }
        EXPECT_GT(lit, shaded / 2);
        EXPECT_EQ(fastCounts.shadow, generalCounts.shadow);
        EXPECT_GT(generalCounts.shadow, uint64_t(shaded));
    }
}

// ambientTerm and lightTerm (inline in shading.h, called at every shaded
// point) against their formulas in shading.h, for random finishes without
// highlights: the ambient and emission times the pigment and its opacity, and
// (diffuse (N.L)^brilliance - U crand) alpha P I_L, black when N.L <= 0.
TEST(Shading, AmbientAndDiffuseTermsFollowTheirFormulas) {
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> u(0, 1);
    int lit = 0;
    for (int i = 0; i < 500; ++i) {
        Finish finish;
        finish.ambient = Color(u(rng), u(rng), u(rng));
        finish.emission = Color(0.3 * u(rng), 0.2 * u(rng), 0.1 * u(rng));
        finish.diffuse = u(rng);
        finish.brilliance = i % 2 ? 1.0 : 0.5 + 3 * u(rng);
        finish.crand = i % 3 ? 0.3 * u(rng) : 0.0;
        const ColorFT pigment{Color(u(rng), u(rng), u(rng)), 0.3 * u(rng), 0.2 * u(rng)};
        const Color ambientLight(u(rng), u(rng), u(rng)), intensity(2 * u(rng), u(rng), u(rng));
        const Vec3 normal = normalize(Vec3(u(rng) - 0.5, u(rng), u(rng) - 0.5));
        const Vec3 toLight = normalize(Vec3(u(rng) - 0.5, u(rng) - 0.3, u(rng) - 0.5));
        const Vec3 incoming = normalize(Vec3(u(rng) - 0.5, -u(rng), u(rng) - 0.5));
        const double crandU = u(rng);
        const double alpha = 1 - pigment.filter - pigment.transmit;
        const Color ambient = ambientTerm(finish, pigment, ambientLight);
        const Color light = lightTerm(finish, pigment, normal, incoming, toLight, intensity, crandU);
        const double cosNL = dot(normal, toLight);
        if (cosNL > 0) ++lit;
        for (int c = 0; c < 3; ++c) {
            EXPECT_DOUBLE_EQ(ambient[c],
                             pigment.rgb[c] * (finish.ambient[c] * ambientLight[c] + finish.emission[c]) * alpha);
            const double diffuse =
                cosNL > 0 ? (finish.diffuse * std::pow(cosNL, finish.brilliance) - crandU * finish.crand) * alpha : 0.0;
            EXPECT_DOUBLE_EQ(light[c], diffuse * pigment.rgb[c] * intensity[c]) << "case " << i << " channel " << c;
        }
    }
    EXPECT_GT(lit, 100);
}

// shadeLayers takes a reflection whose min and max are equal, without a
// metallic tint, as its value; reflectivity times the tint must give exactly
// that, for any incidence, ior and pigment.
TEST(Shading, AConstantReflectionIsItsValueToTheBit) {
    uint64_t state = 777;
    const auto next = [&state] {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return double(state >> 11) * 0x1.0p-53;
    };
    for (int i = 0; i < 5000; ++i) {
        Finish f;
        f.reflectionMin = i % 7 == 0 ? Color(0) : Color(next(), next() * 2, -next());
        f.reflectionMax = f.reflectionMin;
        f.reflectionFresnel = i % 2 == 0;
        f.reflectionFalloff = 0.5 + 3 * next();
        f.reflectionMetallic = i % 3 == 0 ? 0.0 : -next();
        ColorFT pigment;
        pigment.rgb = Color(next(), next(), 5 * next());
        const double cosIncident = next(), eta = 0.5 + next();
        const Color general =
            reflectivity(f, cosIncident, eta) * metallicTint(f.reflectionMetallic, pigment, cosIncident);
        for (int c = 0; c < 3; ++c)
            ASSERT_EQ(std::bit_cast<uint64_t>(general[c]), std::bit_cast<uint64_t>(f.reflectionMin[c])) << i;
    }
}

TEST(Shading, FadeAttenuation) {
    Light light;
    EXPECT_DOUBLE_EQ(fadeAttenuation(light, 100), 1.0);
    light.fadeDistance = 2;
    light.fadePower = 1;
    EXPECT_DOUBLE_EQ(fadeAttenuation(light, 0), 2.0);
    EXPECT_DOUBLE_EQ(fadeAttenuation(light, 2), 1.0);
    EXPECT_DOUBLE_EQ(fadeAttenuation(light, 6), 0.5);
    light.fadePower = 2;
    EXPECT_DOUBLE_EQ(fadeAttenuation(light, 4), 0.4);
}

TEST(Shading, FresnelAndReflectivity) {
    EXPECT_NEAR(fresnelDielectric(1.0, 1 / 1.5), 0.04, 1e-12);
    EXPECT_DOUBLE_EQ(fresnelDielectric(0.1, 1.5), 1.0); // total internal reflection
    Finish f;
    f.reflectionMin = Color(0.1);
    f.reflectionMax = Color(0.9);
    EXPECT_NEAR(reflectivity(f, 0.5, 1).r, 0.1 + 0.8 * 0.5, 1e-12); // (1 - cos)^1
    f.reflectionFalloff = 2;
    EXPECT_NEAR(reflectivity(f, 0.5, 1).r, 0.1 + 0.8 * 0.25, 1e-12);
    f.reflectionFresnel = true;
    EXPECT_NEAR(reflectivity(f, 1.0, 1 / 1.5).r, 0.1 + 0.8 * 0.04, 1e-12);
}

TEST(Shading, MetallicTintsHighlightsAtNormalIncidence) {
    Finish f;
    f.diffuse = 0;
    f.phong = 1;
    f.phongSize = 1;
    ColorFT p{{1, 0.5, 0}, 0, 0};
    const Vec3 n{0, 1, 0}, incoming{0, -1, 0}, toLight{0, 1, 0};
    expectColorNear(lightTerm(f, p, n, incoming, toLight, Color(1)), Color(1), 1e-12);
    f.metallic = 1;
    expectColorNear(lightTerm(f, p, n, incoming, toLight, Color(1)), p.rgb, 1e-3);
}

TEST(Render, AreaLightPovModeAveragesOnlyTheShadow) {
    // Two grid points at x = -1 and x = +1; a small sphere hides only the second.
    Scene scene = litFloorScene();
    scene.objects.push_back(sphere({0.9, 9, 0}, 0.3, solid(Color(1))));
    Light light = pointLight({0, 10, 0}, Color(1));
    light.area = AreaLight{};
    light.area->axis1 = {2, 0, 0};
    light.area->size1 = 2;
    light.area->size2 = 1;
    light.area->sampling = AreaSampling::PovGrid; // POV-Ray's placement,
    light.areaIllumination = false;               // and its shadow-only averaging
    scene.lights.push_back(light);
    // Shading as the point light at the centre (N.L = 1) times visibility 1/2.
    const RenderResult r = render(scene, options(1, 1));
    expectColorNear(pixel(r), Color(0.5), 1e-6);
    EXPECT_EQ(r.stats.shadowRays, 2u); // two samples; the opaque blocker ends its ray in one query
}

TEST(Render, AreaLightFullIlluminationConvergesToThePointLight) {
    Scene scene = litFloorScene();
    Light light = pointLight({1, 3, 0}, Color(1));
    scene.lights.push_back(light);
    const Color point = pixel(render(scene, options(1, 1)));
    scene.lights[0].area = AreaLight{};
    scene.lights[0].area->axis1 = {1e-4, 0, 0};
    scene.lights[0].area->axis2 = {0, 0, 1e-4};
    scene.lights[0].area->size1 = 3;
    scene.lights[0].area->size2 = 3;
    scene.lights[0].area->sampling = AreaSampling::Stratified;
    scene.lights[0].areaIllumination = true;
    expectColorNear(pixel(render(scene, options(1, 1, 4))), point, 1e-4);
}

TEST(Render, AreaLightSendsOneShadowRayPerCameraSampleOrKWhenSplit) {
    // Cook's association: a shading point sends one shadow ray per camera
    // sample whatever n1 x n2 and spp, K with light_samples K; POV-Ray's own
    // method (pov_grid) sends all n1 n2 at every sample whatever K.
    Scene scene = litFloorScene();
    Light light = pointLight({0, 4, 0}, Color(1));
    light.area = AreaLight{{1, 0, 0}, {0, 0, 1}, 4, 4};
    scene.lights.push_back(light);
    for (const AreaSampling sampling :
         {AreaSampling::Stratified, AreaSampling::SolidAngle, AreaSampling::Grid, AreaSampling::PovGrid}) {
        scene.lights[0].area->sampling = sampling;
        for (const auto& [spp, k] : {std::pair{1, 1}, std::pair{3, 1}, std::pair{16, 1}, std::pair{64, 1},
                                     std::pair{5, 3}, std::pair{5, 8}}) {
            RenderOptions o = options(1, 1, spp);
            o.lightSamples = k;
            const RenderResult r = render(scene, o);
            const uint64_t perSample = sampling == AreaSampling::PovGrid ? 16u : uint64_t(k);
            EXPECT_EQ(r.stats.shadowRays, perSample * uint64_t(spp))
                << int(sampling) << " at " << spp << " spp, K = " << k;
        }
    }
}

// A floor point below POV-Ray's n x n grid light with a ball hiding some of
// its points (the needle camera sees one point: nothing else varies).
Scene partlyHiddenGridScene(int n) {
    Scene scene = litFloorScene();
    scene.objects.push_back(sphere({0.5, 2, 0.4}, 0.45, solid(Color(1))));
    Light light = pointLight({0, 4, 0}, Color(1));
    light.area = AreaLight{{2, 0, 0}, {0, 0, 2}, n, n};
    light.areaIllumination = false;
    light.area->sampling = AreaSampling::PovGrid;
    scene.lights.push_back(light);
    return scene;
}

TEST(Render, GridAreaLightVisitsEveryPointOnceInPowerOfTwoCounts) {
    // POV-Ray weighs its grid points by the trapezoid rule (render/lighting.cpp,
    // AreaSampler::sampleFrom): on a 5 x 5 grid the end points of a row weigh
    // 1/8, the others 1/4. The sample's 2-D light value picks the point nearest
    // it, so each point's share of the unit square is a whole number of the
    // 8 x 8 squares of side 1/8; a scrambled (0,2)-sequence puts exactly spp / 64
    // of the first spp points in each, so at 64, 128 and 256 spp the pixel is
    // exactly POV-Ray's weighted sum over the grid, which pov_grid computes at
    // every sample.
    Scene scene = partlyHiddenGridScene(5);
    const Color pov = pixel(render(scene, options(1, 1)));
    EXPECT_GT(pov.r, 0.1); // partly shadowed: some grid points are hidden,
    EXPECT_LT(pov.r, 0.9); // some are not
    {
        // The weights matter here: the plain mean of the 25 points is another value.
        Scene plain = scene;
        plain.lights[0].area->sampling = AreaSampling::Stratified;
        plain.lights[0].area->size1 = plain.lights[0].area->size2 = 1;
        EXPECT_GT(std::fabs(pixel(render(plain, options(1, 1))).r - pov.r), 0.0); // (a sanity check on the scene)
    }
    scene.lights[0].area->sampling = AreaSampling::Grid;
    for (const int spp : {64, 128, 256}) expectColorNear(pixel(render(scene, options(1, 1, spp))), pov, 1e-6);
    // Split samples keep the stratification: the K points of sample i are the
    // light sequence's points K i .. K i + K - 1, so N samples of K points each
    // visit the grid exactly as N K samples of one point do.
    for (const auto& [spp, k] : {std::pair{8, 8}, std::pair{4, 16}, std::pair{16, 4}, std::pair{1, 64}, std::pair{16, 8}}) {
        RenderOptions o = options(1, 1, spp);
        o.lightSamples = k;
        expectColorNear(pixel(render(scene, o)), pov, 1e-6);
    }
    {
        // Not so with too few points (a control: the test can fail).
        RenderOptions o = options(1, 1, 2);
        o.lightSamples = 3;
        EXPECT_GT(std::fabs(pixel(render(scene, o)).r - pov.r), 1e-3);
    }
    // And the same with area_illumination on (each point a light of 1/16 the colour).
    scene.lights[0].areaIllumination = true;
    scene.lights[0].area->sampling = AreaSampling::PovGrid;
    const Color povFull = pixel(render(scene, options(1, 1)));
    scene.lights[0].area->sampling = AreaSampling::Grid;
    expectColorNear(pixel(render(scene, options(1, 1, 64))), povFull, 1e-6);
}

// The weights of POV-Ray's grid (the trapezoid rule: its quadrant-by-quadrant
// average, each cell the mean of its four corners): pov_grid's pixel under a
// 3 x 3 grid with exactly one point hidden is 1 minus that point's weight,
// 1/16 for a corner, 1/8 for an edge point, 1/4 for the centre, not 1/9.
TEST(Render, PovGridWeighsItsPointsByTheTrapezoidRule) {
    for (const auto& [hidden, weight] : {std::pair{Vec3{-1, 4, -1}, 1.0 / 16}, std::pair{Vec3{0, 4, -1}, 1.0 / 8},
                                         std::pair{Vec3{0, 4, 0}, 1.0 / 4}}) {
        Scene scene = litFloorScene();
        Light light = pointLight({0, 4, 0}, Color(1));
        light.area = AreaLight{{2, 0, 0}, {0, 0, 2}, 3, 3};
        light.areaIllumination = false;
        light.area->sampling = AreaSampling::PovGrid;
        scene.lights.push_back(light);
        const double lit = pixel(render(scene, options(1, 1))).r;
        ASSERT_GT(lit, 0.1);
        // A small ball halfway between the floor point (the origin) and one grid point.
        scene.objects.push_back(sphere(hidden * 0.5, 0.05, solid(Color(1))));
        const double shadowed = pixel(render(scene, options(1, 1))).r;
        EXPECT_NEAR(shadowed / lit, 1 - weight, 1e-9) << "hidden point at " << hidden.x << ", " << hidden.z;
    }
}

TEST(Render, GridAreaLightConvergesToPovRaysSumOverAnyGrid) {
    // A 4 x 4 grid's weights (1/6, 1/3, 1/3, 1/6 a row) do not split the unit
    // square into power-of-two cells, so a pixel is no longer exact: its mean
    // over seeds is POV-Ray's sum. 64 seeds at 6 spp (not a power of two
    // either, so that no count is fixed by the sequence's nets); z-test of the
    // mean against the pov_grid value, |z| < 4.
    Scene scene = partlyHiddenGridScene(4);
    const double pov = pixel(render(scene, options(1, 1))).r;
    EXPECT_GT(pov, 0.1);
    EXPECT_LT(pov, 0.9);
    scene.lights[0].area->sampling = AreaSampling::Grid;
    constexpr int kSeeds = 64;
    double sum = 0, sum2 = 0;
    bool varies = false;
    double first = 0;
    for (int seed = 0; seed < kSeeds; ++seed) {
        RenderOptions o = options(1, 1, 6);
        o.seed = uint64_t(seed);
        const double v = pixel(render(scene, o)).r;
        if (seed == 0) first = v;
        varies = varies || v != first;
        sum += v;
        sum2 += v * v;
    }
    ASSERT_TRUE(varies); // otherwise the z-test below is meaningless
    const double mean = sum / kSeeds;
    const double var = (sum2 - kSeeds * mean * mean) / (kSeeds - 1);
    const double z = (mean - pov) / std::sqrt(var / kSeeds);
    EXPECT_LT(std::fabs(z), 4.0) << "mean " << mean << " pov " << pov;
    // And the pixels are close to it, not just right on average: 6 samples of
    // a 16-point sum stratified by cell are within 0.15 of it.
    EXPECT_LT(std::sqrt(var), 0.15);
}

// ---------------------------------------------------------------- determinism and robustness

Scene busyScene() {
    Scene scene;
    Pigment checker;
    checker.pattern = PatternKind::Checker;
    checker.children.resize(2);
    checker.children[0].color.rgb = {0.9, 0.9, 0.9};
    checker.children[1].color.rgb = {0.2, 0.3, 0.1};
    Texture floor;
    floor.pigment = checker;
    floor.finish.reflectionMin = floor.finish.reflectionMax = Color(0.2);
    floor.finish.reflectionBlur = 0.2;
    scene.objects.push_back(plane({0, 1, 0}, -1, floor));
    Texture glass = solid({0.9, 1, 0.9}, 0.2, 0.7);
    glass.finish.phong = 0.8;
    glass.finish.reflectionMin = Color(0.05);
    glass.finish.reflectionMax = Color(1);
    glass.finish.reflectionFresnel = true;
    glass.finish.refractionBlur = 0.1;
    Object ball = sphere({-0.6, 0, 0.5}, 0.9, glass);
    ball.interior.ior = 1.5;
    scene.objects.push_back(ball);
    Texture chrome = solid({0.8, 0.3, 0.2});
    chrome.finish.reflectionMin = chrome.finish.reflectionMax = Color(0.6);
    chrome.finish.specular = 0.5;
    scene.objects.push_back(sphere({1.2, -0.2, 1.5}, 0.8, chrome));
    Light soft = pointLight({-3, 5, -3}, Color(0.7));
    soft.area = AreaLight{{1, 0, 0}, {0, 0, 1}, 3, 2, true};
    soft.area->sampling = AreaSampling::Stratified;
    soft.areaIllumination = true;
    scene.lights.push_back(soft);
    Light pov = pointLight({4, 4, -2}, Color(0.5));
    pov.area = AreaLight{{0.5, 0, 0}, {0, 0.5, 0}, 2, 2, true};
    pov.area->sampling = AreaSampling::PovGrid;
    pov.areaIllumination = false;
    Light solid = pointLight({-4, 3, -4}, Color(0.4));
    solid.area = AreaLight{{0.8, 0, 0}, {0, 0.8, 0}, 2, 2};
    solid.area->sampling = AreaSampling::SolidAngle;
    solid.areaIllumination = true;
    solid.inverseSquare = true;
    scene.lights.push_back(solid);
    scene.lights.push_back(pov);
    scene.background = {0.1, 0.2, 0.4};
    scene.camera.location = {0, 1, -5};
    scene.camera.lookAt = Vec3(0, 0, 0);
    scene.camera.aperture = 0.1;
    scene.camera.focalPoint = Vec3(0, 0, 0);
    return scene;
}

TEST(Render, ImagesAreIdenticalForAnyThreadCountAndTileSize) {
    // With one light point a sample and with split samples (light_samples 3,
    // whose points are traced together): busyScene's area lights.
    const Scene scene = busyScene();
    std::vector<float> unsplit;
    for (const int split : {1, 3}) {
        RenderOptions reference = options(37, 23, 3);
        reference.seed = 7;
        reference.lightSamples = split;
        const RenderResult base = render(scene, reference);
        expectAllFinite(base.color);
        for (int threads : {2, 8}) {
            for (int tile : {8, 32, 64}) {
                RenderOptions o = reference;
                o.threads = threads;
                o.tileSize = tile;
                const RenderResult r = render(scene, o);
                EXPECT_EQ(r.color.pixels, base.color.pixels) << threads << " threads, tile " << tile << ", K " << split;
                EXPECT_EQ(r.variance.pixels, base.variance.pixels);
                EXPECT_EQ(r.stats.totalRays(), base.stats.totalRays());
            }
        }
        RenderOptions otherSeed = reference;
        otherSeed.seed = 8;
        EXPECT_NE(render(scene, otherSeed).color.pixels, base.color.pixels);
        if (split == 1) unsplit = base.color.pixels;
        else EXPECT_NE(base.color.pixels, unsplit); // the split points are other points
    }
}

TEST(Render, DegenerateScenesGiveFiniteImages) {
    Scene scene;
    Texture odd = solid({1, 1, 1}, 0.5, 0.5);
    odd.finish.reflectionMin = Color(0);
    odd.finish.reflectionMax = Color(1);
    odd.finish.reflectionFresnel = true;
    odd.finish.reflectionBlur = 1;
    odd.finish.refractionBlur = 1;
    odd.finish.brilliance = 0;
    odd.finish.roughness = 0;
    odd.finish.specular = 1;
    Object zeroIor = sphere({0, 0, 0}, 1, odd);
    zeroIor.interior.ior = 0;
    zeroIor.interior.fadeDistance = 0.5;
    zeroIor.interior.fadePower = 2;
    scene.objects.push_back(zeroIor);
    Object hugeIor = sphere({2, 0, 0}, 0.5, odd);
    hugeIor.interior.ior = 1e6;
    scene.objects.push_back(hugeIor);
    Texture emptyChecker;
    emptyChecker.pigment.pattern = PatternKind::Checker; // no sub-pigments: black
    scene.objects.push_back(plane({0, 1, 0}, -1, emptyChecker));
    Light onSurface = pointLight({0, 1, 0}, Color(1)); // on the sphere
    scene.lights.push_back(onSurface);
    Light spot = pointLight({0, 3, 0}, Color(1));
    spot.spotlight = true;
    spot.pointAt = spot.position; // no axis
    scene.lights.push_back(spot);
    Light flat = pointLight({0, 4, 0}, Color(1));
    flat.area = AreaLight{{0, 0, 0}, {0, 0, 0}, 4, 4, true, -1, true, true}; // zero size, circular, oriented
    flat.area->sampling = AreaSampling::Stratified;
    flat.areaIllumination = true;
    flat.inverseSquare = true;
    scene.lights.push_back(flat);
    Light flatSolidAngle = flat; // zero solid angle: falls back to area sampling
    flatSolidAngle.area->sampling = AreaSampling::SolidAngle;
    flatSolidAngle.area->circular = false;
    scene.lights.push_back(flatSolidAngle);
    Light zeroFade = pointLight({1, 1, -3}, Color(1));
    zeroFade.fadeDistance = 1;
    zeroFade.fadePower = 3;
    scene.lights.push_back(zeroFade);
    scene.camera.location = {0, 0, -4};
    scene.camera.angle = 120;
    const RenderResult r = render(scene, options(16, 12, 2));
    expectAllFinite(r.color);
    expectAllFinite(r.variance);
    EXPECT_EQ(r.stats.nonFiniteSamples, 0u);
}

TEST(Render, BadOptionsAreRenderErrors) {
    Scene scene;
    EXPECT_THROW(render(scene, options(0, 4)), RenderError);
    EXPECT_THROW(render(scene, options(4, 4, 0)), RenderError);
    RenderOptions badTile = options(4, 4);
    badTile.tileSize = 0;
    EXPECT_THROW(render(scene, badTile), RenderError);
    Scene badFilter;
    badFilter.render.filter = "no-such-filter";
    EXPECT_THROW(render(badFilter, options(4, 4)), RenderError);
    RenderOptions badSampler = options(4, 4);
    badSampler.sampler = "no-such-sampler";
    EXPECT_THROW(render(scene, badSampler), RenderError);
}

TEST(Render, ProgressReachesOne) {
    Scene scene;
    RenderOptions o = options(20, 10);
    o.tileSize = 8;
    int calls = 0;
    double last = 0;
    o.progress = [&](double f) {
        ++calls;
        last = f;
    };
    render(scene, o);
    EXPECT_EQ(calls, 3 * 2);
    EXPECT_DOUBLE_EQ(last, 1.0);
}

TEST(Render, OptionsComeFromOverridesThenSceneThenDefaults) {
    Scene scene;
    scene.render.width = 640;
    scene.render.samplesPerPixel = 9;
    scene.render.seed = 3;
    RenderSettings overrides;
    overrides.samplesPerPixel = 4;
    overrides.threads = 2;
    const RenderOptions o = resolveRenderOptions(overlaySettings(scene.render, overrides));
    EXPECT_EQ(o.width, 640);
    EXPECT_EQ(o.height, 240);
    EXPECT_EQ(o.samplesPerPixel, 4);
    EXPECT_EQ(o.seed, 3u);
    EXPECT_EQ(o.threads, 2);
    EXPECT_EQ(o.sampler, "");
}

// ---------------------------------------------------------------- film and pigments

TEST(Film, VarianceOfTheMeanAndDroppedSamples) {
    PixelAccumulator p;
    for (double v : {1.0, 2.0, 3.0, 6.0}) p.add(Color(v));
    EXPECT_FALSE(p.add(Color(std::nan(""), 0, 0)));
    EXPECT_FALSE(p.add(Color(INFINITY)));
    EXPECT_EQ(p.count(), 4);
    EXPECT_EQ(p.nonFinite(), 2u);
    EXPECT_DOUBLE_EQ(p.mean().g, 3.0);
    // Sample variance (4 + 1 + 0 + 9) / 3, over n = 4.
    EXPECT_DOUBLE_EQ(p.varianceOfMean().b, 14.0 / 3.0 / 4.0);
}

TEST(Pigment, BlockPatterns) {
    EXPECT_EQ(checkerIndex({0.5, 0.0, 0.5}), 0);
    EXPECT_EQ(checkerIndex({1.5, 0.0, 0.5}), 1);
    EXPECT_EQ(checkerIndex({-0.5, 0.0, 0.5}), 1);
    EXPECT_EQ(checkerIndex({0.5, -1e-11, 0.5}), 0); // a plane at y = 0 stays on one side
    EXPECT_EQ(checkerIndex({0.5, -1e-9, 0.5}), 1);  // POV-Ray's tolerance is 1e-10, no more
    EXPECT_EQ(checkerIndex({0.5, -0.0005, 0.5}), 1);
    EXPECT_EQ(hexagonIndex({0, 0, 0}), 0);
    EXPECT_EQ(hexagonIndex({0, 0, std::sqrt(3.0)}), 1);
    EXPECT_EQ(hexagonIndex({1.5, 0, std::sqrt(3.0) / 2}), 2);
    EXPECT_EQ(hexagonIndex({0.9, 0, 0}), 0);  // inside the central hexagon (corner at x = 1)
    EXPECT_EQ(hexagonIndex({0.95, 0, 0.2}), 2); // just across its slanted edge
    EXPECT_EQ(hexagonIndex({1.2, 0, 0.3}), 2);
    for (Vec3 p : {Vec3{0.3, 0, 0.7}, Vec3{2.2, 0, -1.1}, Vec3{-4.1, 0, 3.3}}) {
        EXPECT_EQ(hexagonIndex(p), hexagonIndex({-p.x, 0, p.z}));              // POV-Ray mirrors x
        EXPECT_EQ(hexagonIndex(p), hexagonIndex({p.x, 0, p.z + 3 * std::sqrt(3.0)})); // period in z
    }
    EXPECT_EQ(brickIndex({2, 1.5, 1}, {8, 3, 4.5}, 0.5), 1);
    EXPECT_EQ(brickIndex({2, 2.9, 1}, {8, 3, 4.5}, 0.5), 0); // in the mortar between courses
    EXPECT_EQ(brickIndex({-0.3, 1.5, 1}, {8, 3, 4.5}, 0.5), 0); // the vertical joint at x = 0
}

TEST(Pigment, ColourMapsAndPatternSpace) {
    Pigment g;
    g.pattern = PatternKind::Gradient;
    g.gradientAxis = {0, 2, 0}; // normalised: period 1 along y
    g.colorMap = {{0, ColorFT{Color(0), 0, 0}}, {0.5, ColorFT{Color(1), 0.5, 0}}};
    EXPECT_NEAR(evaluatePigment(g, {0, 0.25, 0}).rgb.r, 0.5, 1e-12);
    EXPECT_NEAR(evaluatePigment(g, {0, 0.25, 0}).filter, 0.25, 1e-12);
    EXPECT_NEAR(evaluatePigment(g, {0, 1.75, 0}).rgb.r, 1.0, 1e-12); // above the last entry
    g.toWorld = Transform::translate({0, 0.25, 0});
    EXPECT_NEAR(evaluatePigment(g, {0, 0.25, 0}).rgb.r, 0.0, 1e-12);
    EXPECT_NEAR(radialValue({0, 0, -1}), 0.25, 1e-12);
    EXPECT_NEAR(radialValue({1, 0, 0}), 0.0, 1e-12);
    EXPECT_NEAR(onionValue({0, 2.5, 0}), 0.5, 1e-12);
}

// POV-Ray's place patterns: 1 at the origin (plane, axis), falling linearly
// to 0 one unit away, and 0 beyond.
TEST(Pigment, PlanarCylindricalAndBoxedFallFromOneToZeroOverOneUnit) {
    EXPECT_NEAR(planarValue({7, 0.25, -3}), 0.75, 1e-12);
    EXPECT_NEAR(planarValue({0, -0.6, 0}), 0.4, 1e-12);
    EXPECT_EQ(planarValue({0, 2, 0}), 0.0);
    EXPECT_NEAR(cylindricalValue({0.3, 9, 0.4}), 0.5, 1e-12);
    EXPECT_EQ(cylindricalValue({3, 0, 4}), 0.0);
    EXPECT_NEAR(boxedValue({0.2, -0.6, 0.1}), 0.4, 1e-12);
    EXPECT_NEAR(boxedValue({0, 0, 0}), 1.0, 1e-12);
    EXPECT_EQ(boxedValue({0.5, 0.5, -1.5}), 0.0);
    // Through a pigment: the colour map at the value, in pattern space.
    Pigment p;
    p.pattern = PatternKind::Planar;
    p.colorMap = {{0, ColorFT{Color(0), 0, 0}}, {1, ColorFT{Color(1), 0, 0}}};
    p.toWorld = Transform::scale(Vec3(2));
    EXPECT_NEAR(evaluatePigment(p, {5, 0.5, 5}).rgb.g, 0.75, 1e-12);
}

// assumed_gamma G: pixel v becomes max(v, 0)^G and its variance of the mean
// (G v^(G-1))^2 var (delta method); G = 1 changes nothing.
TEST(Film, WorkingGammaDecodesPixelsAndPropagatesVariance) {
    Image color(2, 1, 3), variance(2, 1, 3);
    for (int c = 0; c < 3; ++c) {
        color.at(0, 0, c) = 0.5f;
        variance.at(0, 0, c) = 0.01f;
        color.at(1, 0, c) = -0.25f; // noise below zero clamps to black
        variance.at(1, 0, c) = 0.02f;
    }
    Image sameColor = color, sameVariance = variance;
    decodeWorkingGamma(sameColor, sameVariance, 1.0);
    EXPECT_EQ(sameColor.pixels, color.pixels);
    EXPECT_EQ(sameVariance.pixels, variance.pixels);
    decodeWorkingGamma(color, variance, 2.2);
    EXPECT_NEAR(color.at(0, 0, 1), std::pow(0.5, 2.2), 1e-6);
    const double slope = 2.2 * std::pow(0.5, 1.2);
    EXPECT_NEAR(variance.at(0, 0, 1), slope * slope * 0.01, 1e-7);
    EXPECT_EQ(color.at(1, 0, 2), 0.0f);
    EXPECT_EQ(variance.at(1, 0, 2), 0.0f);
}

} // namespace
} // namespace drt
