// Stability where methods fail: each test drives the renderer into a
// regime where a naive method breaks (tiny or huge scenes, far from the origin,
// total internal reflection, grazing rays, degenerate lights, lenses, shutters
// and triangles, deep recursion, coincident surfaces) and asserts no NaN/Inf,
// no crash, and the stated limiting behaviour.
#include "render/render.h"

#include "accel/accel.h"
#include "core/hash.h"
#include "lang/load.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <filesystem>

namespace drt {
namespace {

Texture solid(Color rgb, double filter = 0, double transmit = 0) {
    Texture t;
    t.pigment.color = ColorFT{rgb, filter, transmit};
    return t;
}

// Lossless clear glass: Fresnel reflection plus transmission sum to one.
Texture clearGlass(double refractionBlur = 0) {
    Texture t = solid(Color(1), 0, 1);
    t.finish.ambient = Color(0);
    t.finish.diffuse = 0;
    t.finish.reflectionMin = Color(0);
    t.finish.reflectionMax = Color(1);
    t.finish.reflectionFresnel = true;
    t.finish.conserveEnergy = true;
    t.finish.refractionBlur = refractionBlur;
    return t;
}

Object object(Shape shape, Texture texture) {
    Object o;
    o.shape = std::move(shape);
    o.texture = texture;
    return o;
}

RenderOptions options(int w, int h, int spp, int threads = 1) {
    RenderOptions o;
    o.width = w;
    o.height = h;
    o.samplesPerPixel = spp;
    o.threads = threads;
    return o;
}

void expectAllFinite(const RenderResult& r) {
    EXPECT_EQ(r.stats.nonFiniteSamples, 0u);
    for (float v : r.color.pixels) ASSERT_TRUE(std::isfinite(v) && v >= 0) << v;
    for (float v : r.variance.pixels) ASSERT_TRUE(std::isfinite(v) && v >= 0) << v;
}

// Fraction of pixels whose largest channel differs by more than `threshold`.
double fractionDiffering(const Image& a, const Image& b, double threshold) {
    int64_t differing = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            double worst = 0;
            for (int c = 0; c < 3; ++c) worst = std::max(worst, double(std::fabs(a.at(x, y, c) - b.at(x, y, c))));
            differing += worst > threshold;
        }
    return double(differing) / (double(a.width) * a.height);
}

// ---------------------------------------------------------------- scale and position

// A lit scene with every kind of spawned ray: an opaque sphere (shadow), a glass
// sphere (refraction in and out), a reflective box of triangles, a floor plane.
// Everything is scaled by `s` about the origin, then moved by `offset`.
Scene scaledScene(double s, Vec3 offset) {
    Scene scene;
    const auto at = [&](Vec3 p) { return offset + p * s; };
    Texture red = solid({0.8, 0.1, 0.1});
    red.finish.phong = 0.5;
    scene.objects.push_back(object(Sphere{at({-1.2, 1, 0}), s}, red));
    Object glass = object(Sphere{at({1.2, 0.8, -0.5}), 0.8 * s}, clearGlass());
    glass.interior.ior = 1.5;
    scene.objects.push_back(glass);
    Texture mirror = solid({0.2, 0.5, 0.2});
    mirror.finish.reflectionMin = mirror.finish.reflectionMax = Color(0.4);
    scene.objects.push_back(object(Box{at({-0.4, 0, 1}), at({0.6, 1.4, 2})}, mirror));
    Texture floor = solid(Color(0.7));
    floor.pigment.pattern = PatternKind::Checker;
    floor.pigment.children = {Pigment{}, Pigment{}};
    floor.pigment.children[0].color = ColorFT{Color(0.9), 0, 0};
    floor.pigment.children[1].color = ColorFT{Color(0.3), 0, 0};
    floor.pigment.toWorld = Transform::scale(Vec3(s)).then(Transform::translate(offset));
    scene.objects.push_back(object(Plane{{0, 1, 0}, offset.y}, floor));
    Light light;
    light.position = at({-4, 6, -5});
    scene.lights.push_back(light);
    scene.background = {0.5, 0.6, 0.8};
    scene.camera.location = at({0, 1.5, -5});
    scene.camera.lookAt = at({0, 0.8, 0});
    scene.global.maxTraceLevel = 8;
    return scene;
}

// Shadow acne speckles whole lit surfaces and leaks light whole shadows, so
// either would change far more than the 2% of pixels (edges whose samples move
// by float rounding) that this allows; the mean error bounds subtler drift.
void expectSameImage(const RenderResult& candidate, const RenderResult& reference, const char* what) {
    expectAllFinite(candidate);
    EXPECT_LT(fractionDiffering(candidate.color, reference.color, 0.02), 0.02) << what;
    double sum = 0;
    for (size_t i = 0; i < candidate.color.pixels.size(); ++i)
        sum += std::fabs(candidate.color.pixels[i] - reference.color.pixels[i]);
    EXPECT_LT(sum / double(candidate.color.pixels.size()), 2e-3) << what;
}

TEST(Stability, SceneRendersTheSameScaledDownScaledUpAndFarFromTheOrigin) {
    const RenderResult reference = render(scaledScene(1, {}), options(64, 48, 4));
    expectAllFinite(reference);
    expectSameImage(render(scaledScene(1e-4, {}), options(64, 48, 4)), reference, "scaled by 1e-4");
    expectSameImage(render(scaledScene(1e4, {}), options(64, 48, 4)), reference, "scaled by 1e4");
    expectSameImage(render(scaledScene(1, {1e5, 1e5, 1e5}), options(64, 48, 4)), reference, "moved by 1e5");
}

// Rays spawned off a surface point toward the outside of a convex shape must
// hit nothing (the scene holds only that shape); rays spawned inward must cross
// to the far side, at the exact chord length up to a tolerance far below the
// shape's size (so never stop at their own origin, nor skip the far side);
// and the spawned origin stays that close to the hit point.
// `exitDistance(o, d)`: the exact distance from o (just inside) along unit d to
// where the shape is left.
template <class ExitDistance>
void expectNoSelfHits(const Shape& shape, double size, Vec3 center, ExitDistance exitDistance, const char* what) {
    Scene scene;
    scene.objects.push_back(object(shape, solid(Color(1))));
    const Accelerator accel(scene);
    // Embree's rays are float: far from the origin no origin is closer to a
    // point than half a float ULP of its coordinates, so allow 8 ULPs there.
    const double farthest = std::max({std::fabs(center.x), std::fabs(center.y), std::fabs(center.z)});
    const double tolerance = 1e-4 * size + 8 * FLT_EPSILON * farthest;
    int hits = 0, outwardFailures = 0, inwardFailures = 0, farOrigins = 0;
    for (uint64_t i = 0; i < 2000; ++i) {
        // A ray from a point outside aimed at a random point of the shape.
        const Vec3 target = center + Vec3(unitFromHash(hashValues({i, 1})) - 0.5, unitFromHash(hashValues({i, 2})) - 0.5,
                                          unitFromHash(hashValues({i, 3})) - 0.5) * size;
        const Vec3 from = center + Vec3(0.3, 1, -3) * size * 2;
        Ray ray{from, target - from};
        Hit hit;
        if (!accel.intersect(ray, hit)) continue;
        ++hits;
        const Vec3 n = hit.geometricNormal;
        Vec3 t, b;
        orthonormalBasis(n, t, b);
        // Outward, down to grazing angles of 1e-4 rad.
        const double u = unitFromHash(hashValues({i, 4})), phi = 6.283185307 * unitFromHash(hashValues({i, 5}));
        const double cosTheta = std::max(1e-4, u);
        const double sinTheta = std::sqrt(1 - cosTheta * cosTheta);
        const Vec3 out = n * cosTheta + (t * std::cos(phi) + b * std::sin(phi)) * sinTheta;
        Ray spawned{Accelerator::offsetOrigin(hit, out), out};
        Hit again;
        outwardFailures += accel.intersect(spawned, again);
        farOrigins += !(length(spawned.origin - hit.point) <= tolerance); // a leak through thin walls
        const Vec3 in = -out;
        Ray inward{Accelerator::offsetOrigin(hit, in), in};
        const double expected = exitDistance(inward.origin, in);
        inwardFailures += !accel.intersect(inward, again) || !(std::fabs(again.t - expected) <= tolerance);
    }
    EXPECT_GT(hits, 1000) << what;
    EXPECT_EQ(outwardFailures, 0) << what << ": outward rays that hit their own surface again";
    EXPECT_EQ(farOrigins, 0) << what << ": spawned origins farther than " << tolerance << " from the hit";
    EXPECT_EQ(inwardFailures, 0) << what << ": inward rays that missed the far side by more than " << tolerance;
}

void expectNoSelfHitsOnSphere(Vec3 center, double radius, const char* what) {
    // |o + t d - c| = r, the larger root: t = -b + sqrt(b^2 - (|o - c|^2 - r^2)), b = (o - c).d
    expectNoSelfHits(Sphere{center, radius}, 2 * radius, center,
                     [&](Vec3 o, Vec3 d) {
                         const Vec3 oc = o - center;
                         const double b = dot(oc, d);
                         return -b + std::sqrt(std::max(0.0, b * b - (dot(oc, oc) - radius * radius)));
                     },
                     what);
}

void expectNoSelfHitsOnBox(Vec3 center, double half, const char* what) {
    const Vec3 lo = center - Vec3(half), hi = center + Vec3(half);
    expectNoSelfHits(Box{lo, hi}, 2 * half, center,
                     [&](Vec3 o, Vec3 d) { // the nearest slab exit
                         double t = 1e300;
                         for (int i = 0; i < 3; ++i)
                             if (d[i] != 0) t = std::min(t, ((d[i] > 0 ? hi[i] : lo[i]) - o[i]) / d[i]);
                         return t;
                     },
                     what);
}

TEST(Stability, SpawnedRaysNeverRehitTheirOwnSurfaceAtAnyScale) {
    for (const double s : {1e-4, 1.0, 1e4}) {
        expectNoSelfHitsOnSphere({}, s, ("sphere of radius " + std::to_string(s)).c_str());
        expectNoSelfHitsOnBox({}, s, ("box of half size " + std::to_string(s)).c_str());
    }
    const Vec3 far{1e5, -1e5, 1e5};
    expectNoSelfHitsOnSphere(far, 1, "sphere at 1e5");
    expectNoSelfHitsOnBox(far, 1, "box at 1e5");
}

// ---------------------------------------------------------------- glass

// A lossless dielectric in a uniform environment renders exactly the
// environment (the white furnace test): whatever the Fresnel
// split, total internal reflection included, no energy appears or vanishes
// beyond what the depth limit and the per-sample ray budget cut off.
Scene furnace(Shape shape, Texture texture) {
    Scene scene;
    scene.background = Color(1);
    scene.global.ambientLight = Color(0);
    scene.global.adcBailout = 1e-4;
    scene.global.maxTraceLevel = 40;
    Object o = object(std::move(shape), texture);
    o.interior.ior = 1.5;
    o.transform = Transform::rotate({30, 40, 0}); // faces at odd angles: plenty of internal reflection
    scene.objects.push_back(o);
    scene.camera.location = {0, 0, -4};
    scene.camera.lookAt = Vec3(0, 0, 0);
    return scene;
}

TEST(Stability, ClearGlassWithTotalInternalReflectionKeepsTheFurnaceWhite) {
    for (const Shape& shape : {Shape{Box{}}, Shape{Sphere{{0, 0, 0}, 1.2}}, Shape{Cylinder{{0, -1, 0}, {0, 1, 0}, 1}}}) {
        const RenderResult r = render(furnace(shape, clearGlass()), options(24, 24, 2));
        expectAllFinite(r);
        for (float v : r.color.pixels) EXPECT_NEAR(v, 1.0, 2e-3);
    }
}

TEST(Stability, TranslucentGlassNeverGainsEnergyAndStaysFinite) {
    // A blurred refraction sample that lands on the wrong side of the surface
    // has weight 0, so the furnace may darken but never brighten.
    for (const double blur : {0.05, 0.5, 1.0}) {
        const RenderResult r = render(furnace(Box{}, clearGlass(blur)), options(24, 24, 4));
        expectAllFinite(r);
        for (float v : r.color.pixels) EXPECT_LE(v, 1.0 + 1e-5);
        double sum = 0;
        for (float v : r.color.pixels) sum += v;
        EXPECT_GT(sum / double(r.color.pixels.size()), 0.5) << "blur " << blur;
    }
}

TEST(Stability, GrazingRaysOnPlanesAndGlassAreFinite) {
    // The eye sits 1e-9 above an infinite mirror floor, under a glass ceiling,
    // and looks along them: the rays meet both at grazing angles.
    for (const double blur : {0.0, 0.3}) {
        Scene scene;
        scene.background = Color(0.5);
        Texture floor = solid(Color(0.6));
        floor.finish.reflectionMin = floor.finish.reflectionMax = Color(0.5);
        floor.finish.reflectionBlur = blur;
        floor.finish.phong = 1;
        scene.objects.push_back(object(Plane{{0, 1, 0}, 0}, floor));
        Object glass = object(Plane{{0, -1, 0}, -2}, clearGlass(blur)); // a glass ceiling at y = 2
        glass.interior.ior = 1.5;
        scene.objects.push_back(glass);
        scene.objects.push_back(object(Sphere{{0, 0, 10}, 1}, clearGlass(blur)));
        Light light;
        light.position = {0, 1e-6, 100};
        scene.lights.push_back(light);
        scene.camera.location = {0, 1e-9, 0};
        scene.camera.direction = {0, 0, 1};
        const RenderResult r = render(scene, options(16, 16, 4));
        expectAllFinite(r);
    }
}

// ---------------------------------------------------------------- degenerate effects

Scene shadowScene() {
    Scene scene;
    scene.objects.push_back(object(Plane{{0, 1, 0}, 0}, solid(Color(0.8))));
    scene.objects.push_back(object(Sphere{{0, 1, 0}, 0.7}, solid({0.2, 0.4, 0.9})));
    Light light;
    light.position = {1, 5, -1};
    scene.lights.push_back(light);
    scene.camera.location = {0, 3, -5};
    scene.camera.lookAt = Vec3(0, 0.5, 0);
    return scene;
}

TEST(Stability, VanishingAreaLightsTendToThePointLight) {
    const RenderResult point = render(shadowScene(), options(32, 24, 2));
    for (const bool cook : {false, true}) {
        for (const double size : {0.0, 1e-12}) {
            Scene scene = shadowScene();
            AreaLight area;
            area.axis1 = {size, 0, 0};
            area.axis2 = {0, 0, size};
            area.size1 = area.size2 = 3;
            area.jitter = true;
            area.sampling = cook ? AreaSampling::Stratified : AreaSampling::PovGrid;
            scene.lights[0].area = area;
            scene.lights[0].areaIllumination = cook;
            const RenderResult r = render(scene, options(32, 24, 2));
            expectAllFinite(r);
            for (size_t i = 0; i < r.color.pixels.size(); ++i)
                EXPECT_NEAR(r.color.pixels[i], point.color.pixels[i], 1e-5) << "size " << size;
        }
    }
}

TEST(Stability, HighlightsOfTinyHugeAndGrazingAreaLightsAreFinite) {
    // Area lights' highlights draw a direction from the highlight's lobe and
    // weigh it against the light's density (render/lighting.h): a light of
    // 1e-80 x 1e-80 (its density per steradian, 1e161, squares past the
    // largest double) and one of 1e-150 (whose area underflows), lobes of
    // exponent 1e9 and 0, highlights of 1e6, a light edge-on to the floor.
    // Every pixel finite; the tiny light's image within 1e-5 of the point
    // light's, as VanishingAreaLightsTendToThePointLight asks without highlights.
    struct Case {
        double size, phong, phongSize, specular, roughness;
        Vec3 axis2;
    };
    const Case cases[] = {
        {1e-80, 1, 40, 0.8, 0.01, {0, 0, 1}}, {1e-12, 1, 1e9, 1, 1e-9, {0, 0, 1}}, {1, 1e6, 0, 1e6, 1, {0, 0, 1}},
        {2, 1, 80, 1, 0.003, {0, 1, 0}},       {1e-150, 0, 40, 1, 0.05, {0, 0, 1}},
    };
    for (const AreaSampling sampling : {AreaSampling::Stratified, AreaSampling::SolidAngle}) {
        for (const bool inverseSquare : {false, true}) {
            for (const Case& c : cases) {
                const auto make = [&](bool area) {
                    Scene scene = shadowScene();
                    for (Object& o : scene.objects) {
                        Finish& f = o.texture.edit().finish;
                        f.phong = c.phong;
                        f.phongSize = c.phongSize;
                        f.specular = c.specular;
                        f.roughness = c.roughness;
                    }
                    scene.lights[0].inverseSquare = inverseSquare;
                    if (area) {
                        AreaLight light;
                        light.axis1 = {c.size, 0, 0};
                        light.axis2 = c.axis2 * c.size;
                        light.size1 = light.size2 = 2;
                        light.sampling = sampling;
                        scene.lights[0].area = light;
                        scene.lights[0].areaIllumination = true;
                    }
                    return scene;
                };
                const RenderResult r = render(make(true), options(16, 12, 4));
                expectAllFinite(r);
                if (c.size < 1e-9 && !inverseSquare) {
                    const RenderResult point = render(make(false), options(16, 12, 4));
                    for (size_t i = 0; i < r.color.pixels.size(); ++i)
                        EXPECT_NEAR(r.color.pixels[i], point.color.pixels[i], 1e-5) << "size " << c.size;
                }
            }
        }
    }
}

TEST(Stability, AreaLightsWithParallelAxesAreFiniteLineLights) {
    for (const bool inverseSquare : {false, true}) {
        for (const AreaSampling sampling : {AreaSampling::PovGrid, AreaSampling::Stratified, AreaSampling::SolidAngle}) {
            Scene scene = shadowScene();
            AreaLight area;
            area.axis1 = {1, 0, 0};
            area.axis2 = {2, 0, 0};
            area.size1 = area.size2 = 3;
            area.sampling = sampling;
            scene.lights[0].area = area;
            scene.lights[0].areaIllumination = sampling != AreaSampling::PovGrid;
            scene.lights[0].inverseSquare = inverseSquare;
            const RenderResult r = render(scene, options(16, 12, 2));
            expectAllFinite(r);
        }
    }
}

TEST(Stability, ZeroAreaLightAxesAreSceneErrorsWithALocation) {
    Diagnostics diagnostics;
    EXPECT_FALSE(loadSceneText("light_source {\n  <0, 5, 0>, rgb 1 area_light <0, 0, 0>, <0, 0, 1>, 2, 2\n}",
                               "light.drt", diagnostics));
    EXPECT_NE(diagnostics.formatAll().find("light.drt:2:"), std::string::npos) << diagnostics.formatAll();
}

TEST(Stability, ZeroApertureIsThePinholeAndHugeAperturesStayFinite) {
    const RenderResult pinhole = render(shadowScene(), options(32, 24, 4));
    Scene zero = shadowScene();
    zero.camera.aperture = 0;
    zero.camera.focalDistance = 3;
    const RenderResult same = render(zero, options(32, 24, 4));
    EXPECT_EQ(same.color.pixels, pinhole.color.pixels);
    EXPECT_FALSE(same.stats.effects.depthOfField);
    for (const double aperture : {1e-12, 1e6, 1e30}) {
        Scene scene = shadowScene();
        scene.camera.aperture = aperture;
        scene.camera.focalDistance = 5;
        const RenderResult r = render(scene, options(16, 12, 4));
        expectAllFinite(r);
        EXPECT_TRUE(r.stats.effects.depthOfField);
        if (aperture < 1e-6) { // a vanishing lens converges to the pinhole
            EXPECT_LT(fractionDiffering(render(scene, options(32, 24, 4)).color, pinhole.color, 1e-4), 0.01);
        }
    }
}

TEST(Stability, ZeroShutterIsStaticAndLongShuttersStayFinite) {
    Scene moving = shadowScene();
    moving.objects[1].motion = {MotionStage{motionTo({1, 0, 0}), {}}};
    const RenderResult still = render(shadowScene(), options(32, 24, 4));
    moving.camera.shutterOpen = moving.camera.shutterClose = 0; // time 0: the pose without motion
    const RenderResult zero = render(moving, options(32, 24, 4));
    EXPECT_FALSE(zero.stats.effects.motionBlur);
    for (size_t i = 0; i < zero.color.pixels.size(); ++i)
        EXPECT_NEAR(zero.color.pixels[i], still.color.pixels[i], 1e-5);
    moving.camera.shutterClose = 1e9; // objects hold their end pose beyond time 1
    const RenderResult longShutter = render(moving, options(16, 12, 4));
    expectAllFinite(longShutter);
    EXPECT_TRUE(longShutter.stats.effects.motionBlur);
}

// ---------------------------------------------------------------- recursion

TEST(Stability, DeepRecursionBetweenMirrorsSumsTheGeometricSeries) {
    // The eye sits between two parallel mirrors of reflectivity 1/2 and ambient
    // a: the ray bounces forever, each hit adding a (1/2)^k, so with trace depth
    // L the pixel is a (1 - 2^-L) / (1 - 1/2). No stack growth at L = 256.
    const double a = 0.1;
    for (const int level : {1, 5, 64, 256, 100000}) {
        Scene scene;
        Texture mirror = solid(Color(1));
        mirror.finish.ambient = Color(a);
        mirror.finish.diffuse = 0;
        mirror.finish.reflectionMin = mirror.finish.reflectionMax = Color(0.5);
        scene.objects.push_back(object(Plane{{0, 0, 1}, 1}, mirror));
        scene.objects.push_back(object(Plane{{0, 0, -1}, 1}, mirror)); // z = -1, facing +z
        scene.global.maxTraceLevel = level;
        scene.global.adcBailout = 0;
        scene.camera.location = {0, 0, 0};
        scene.camera.direction = {0, 0, 1};
        scene.camera.up = {0, 1e-9, 0};
        scene.camera.right = Vec3{1e-9, 0, 0};
        const RenderResult r = render(scene, options(1, 1, 1));
        expectAllFinite(r);
        const int depth = std::min(level, 256); // the renderer's stated limit (integrator.h)
        EXPECT_NEAR(r.color.at(0, 0, 0), a * (1 - std::pow(0.5, depth)) / 0.5, 1e-6) << level;
    }
}

// ---------------------------------------------------------------- coincident and degenerate geometry

TEST(Stability, CoincidentSurfacesGiveTheSameImageEveryRunAndThreadCount) {
    Scene scene = shadowScene();
    scene.objects.push_back(object(Sphere{{0, 1, 0}, 0.7}, solid({0.9, 0.8, 0.1})));  // on top of the sphere
    scene.objects.push_back(object(Plane{{0, 1, 0}, 0}, solid({0.1, 0.9, 0.1})));     // on top of the floor
    scene.objects.push_back(object(Box{{-2, 0, -2}, {-1, 1, -1}}, solid({0.9, 0.1, 0.1})));
    scene.objects.push_back(object(Box{{-2, 0, -2}, {-1, 1, -1}}, solid({0.1, 0.1, 0.9}))); // the same box twice
    const RenderResult first = render(scene, options(48, 36, 2, 1));
    expectAllFinite(first);
    for (const int threads : {1, 2, 4}) {
        RenderOptions o = options(48, 36, 2, threads);
        o.tileSize = 5 + threads;
        EXPECT_EQ(render(scene, o).color.pixels, first.color.pixels) << threads << " threads";
    }
}

TEST(Stability, DegenerateTrianglesRenderNoNaN) {
    Scene scene = shadowScene();
    Mesh mesh;
    mesh.vertices = {{-2, 0.2, -1.5}, {0, 0.2, -1.5}, {2, 0.2, -1.5}, {0, 3, -1.5}, {5, 5, 5}};
    mesh.triangles = {{0, 1, 2},  // collinear
                      {4, 4, 4},  // one point
                      {0, 0, 3},  // a repeated vertex
                      {0, 2, 3}}; // a real one
    mesh.normals = {{0, 0, 0}, {0, 0, -1}, {0, 0, -1}, {0, 0, -1}, {0, 1, 0}}; // one zero normal
    mesh.normalIndices = mesh.triangles;
    scene.objects.push_back(object(mesh, solid({0.9, 0.9, 0.1})));
    const RenderResult r = render(scene, options(32, 24, 4, 2));
    expectAllFinite(r);
    // The real triangle is still there: the centre of the image sees its yellow.
    EXPECT_GT(r.color.at(16, 10, 1), r.color.at(16, 10, 2));
}

// ---------------------------------------------------------------- the NaN/Inf counter

TEST(Stability, EveryExampleRendersWithoutNonFiniteSamples) {
    int rendered = 0;
    for (const auto& entry : std::filesystem::directory_iterator(test::sourcePath("examples"))) {
        if (entry.path().extension() != ".drt") continue;
        Diagnostics diagnostics;
        std::optional<Scene> scene = loadSceneFile(entry.path().string(), diagnostics);
        ASSERT_TRUE(scene) << entry.path() << "\n" << diagnostics.formatAll();
        scene = test::withAssets(std::move(*scene));
        RenderSettings small;
        small.width = 24;
        small.height = 18;
        small.samplesPerPixel = 2;
        small.threads = 2;
        RenderOptions o = resolveRenderOptions(overlaySettings(scene->render, small));
        o.adaptive = false;
        const RenderResult r = render(*scene, o);
        EXPECT_EQ(r.stats.nonFiniteSamples, 0u) << entry.path();
        for (float v : r.color.pixels) ASSERT_TRUE(std::isfinite(v)) << entry.path();
        ++rendered;
    }
    EXPECT_GE(rendered, 2);
}

TEST(Stability, NonFiniteSamplesAreCountedAndReportedInTheFileMetadata) {
    const std::string dir = test::tempDir();
    const std::string scene = test::writeFile(dir + "/s.drt", "sphere { <0, 0, 5>, 1 pigment { rgb 1 } }\n");
    const test::CommandResult r = test::runDrt("render '" + scene + "' -o '" + dir + "/out.exr' --width 8 --height 6");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("0 NaN/Inf samples"), std::string::npos) << r.err;
    Image image;
    Metadata metadata;
    ASSERT_EQ(readImage(dir + "/out.exr", image, &metadata), "");
    const auto value = [&](const std::string& key) {
        for (const auto& [k, v] : metadata)
            if (k == key) return v;
        return std::string("(missing)");
    };
    EXPECT_EQ(value("drt:nonfinite_samples"), "0");
    EXPECT_EQ(value("drt:nonfinite_pixels"), "0");
    EXPECT_EQ(value("drt:effects"), "none");
}

} // namespace
} // namespace drt
