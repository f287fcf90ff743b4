// Accelerator::intersectPacket (camera rays traced as one Embree packet) must
// give every ray exactly the hit Accelerator::intersect gives it alone: the
// renderer relies on that for images that do not depend on how rays are traced.
#include "accel/accel.h"
#include "lang/load.h"
#include "render/integrator.h"
#include "render/render.h"
#include "sampling/sampler.h"
#include "scene/motion.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <bit>
#include <iomanip>
#include <limits>
#include <random>
#include <sstream>

namespace drt {
namespace {

using test::makeObject;
using test::sceneOf;

// Bit for bit: a packet may not round differently from a single ray.
void expectSameBits(double a, double b, const char* what, int ray) {
    EXPECT_EQ(std::bit_cast<uint64_t>(a), std::bit_cast<uint64_t>(b)) << what << " of ray " << ray;
}
void expectSameBits(const Vec3& a, const Vec3& b, const char* what, int ray) {
    for (int k = 0; k < 3; ++k) expectSameBits(a[k], b[k], what, ray);
}

void expectSameHit(const Hit& single, const Hit& packet, int ray) {
    expectSameBits(single.t, packet.t, "t", ray);
    expectSameBits(single.point, packet.point, "point", ray);
    expectSameBits(single.geometricNormal, packet.geometricNormal, "geometric normal", ray);
    expectSameBits(single.shadingNormal, packet.shadingNormal, "shading normal", ray);
    expectSameBits(single.restPoint, packet.restPoint, "rest point", ray);
    EXPECT_EQ(single.object, packet.object) << "ray " << ray;
    EXPECT_EQ(single.primitive, packet.primitive) << "ray " << ray;
    EXPECT_EQ(single.instance, packet.instance) << "ray " << ray;
    EXPECT_EQ(single.frameUnit, packet.frameUnit) << "ray " << ray;
}

// Every kind of geometry the accelerator builds: analytic shapes with and
// without a transform, CSG, a clipped shape, triangles, a mesh and a moving
// object (an Embree instance whose callbacks see each ray at its own time).
Scene mixedScene() {
    std::vector<Object> objects;
    objects.push_back(makeObject(Plane{{0, 1, 0}, -1}));
    objects.push_back(makeObject(Sphere{{0, 0, 0}, 1}));
    objects.push_back(makeObject(Sphere{{0, 0, 0}, 1}, Transform::scale({2, 0.5, 1}).then(Transform::translate({3, 0, 1}))));
    objects.push_back(makeObject(Box{{-1, -1, -1}, {1, 1, 1}}, Transform::rotate({10, 30, 0}).then(Transform::translate({-3, 0, 0}))));
    objects.push_back(makeObject(Torus{1, 0.3}, Transform::translate({0, 0, 4})));
    Csg difference{Csg::Op::Difference, {makeObject(Sphere{{0, 0, 0}, 1}), makeObject(Box{{0, -2, -2}, {2, 2, 2}})}};
    objects.push_back(makeObject(difference, Transform::translate({0, 2.5, 0})));
    Object clipped = makeObject(Sphere{{0, 0, 0}, 1}, Transform::translate({3, 2.5, 0}));
    clipped.clippedBy.push_back(makeObject(Plane{{1, 0, 0}, 3}));
    objects.push_back(clipped);
    Mesh mesh;
    mesh.vertices = {{-4, 2, 3}, {-2, 2, 3}, {-4, 4, 3}, {-2, 4, 4}};
    mesh.triangles = {{0, 1, 2}, {1, 3, 2}};
    objects.push_back(makeObject(mesh));
    Object moving = makeObject(Sphere{{0, 0, 0}, 0.7}, Transform::translate({-1.5, 0, -2}));
    moving.motion = {MotionStage{motionTo({1.5, 0.5, 0}), {}}};
    objects.push_back(moving);
    return sceneOf(std::move(objects));
}

// The options of the small renders below: 40x30 pixels on 2 threads.
RenderOptions smallRender(const Scene& scene, int samplesPerPixel) {
    RenderOptions options = resolveRenderOptions(scene.render);
    options.width = 40;
    options.height = 30;
    options.threads = 2;
    options.samplesPerPixel = samplesPerPixel;
    return options;
}

// Packets of every size, some coherent (one pixel's rays from a camera),
// some not (random origins and directions), at random times.
TEST(Packet, EveryRayGetsTheHitItGetsAlone) {
    const Scene scene = mixedScene();
    const Accelerator accel(scene);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    int hits = 0, rays = 0;
    for (int packet = 0; packet < 400; ++packet) {
        const int count = 1 + packet % Accelerator::kPacketSize;
        const bool coherent = packet % 2 == 0;
        const Vec3 eye{-1 + 2 * u(rng), 1 + u(rng), -8};
        const Vec3 aim{-4 + 8 * u(rng), -1 + 4 * u(rng), 0};
        Ray batch[Accelerator::kPacketSize];
        for (int i = 0; i < count; ++i) {
            Ray& r = batch[i];
            if (coherent) {
                r.origin = eye;
                r.direction = aim + Vec3{0.01 * u(rng), 0.01 * u(rng), 0} - eye;
            } else {
                r.origin = {-6 + 12 * u(rng), -0.5 + 5 * u(rng), -8 + 4 * u(rng)};
                r.direction = test::randomUnitVector(rng);
                if (r.direction.z < 0) r.direction.z = -r.direction.z;
            }
            r.tMin = packet % 5 == 0 ? 0.5 : 0;
            r.time = u(rng);
        }
        Hit packed[Accelerator::kPacketSize];
        bool found[Accelerator::kPacketSize];
        accel.intersectPacket(batch, count, packed, found);
        for (int i = 0; i < count; ++i, ++rays) {
            Hit alone;
            const bool foundAlone = accel.intersect(batch[i], alone);
            ASSERT_EQ(foundAlone, found[i]) << "ray " << rays;
            if (!foundAlone) continue;
            ++hits;
            expectSameHit(alone, packed[i], rays);
        }
    }
    EXPECT_GT(hits, rays / 3); // the rays do hit things
}

// Shadow rays go in packets too (Accelerator::occludedPacket): each must get
// the answer occluded() gives it alone, coherent (one hit area toward one
// light) or not, from near the surfaces as shadow rays start.
TEST(Packet, EveryShadowRayGetsTheAnswerItGetsAlone) {
    const Scene scene = mixedScene();
    const Accelerator accel(scene);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0, 1);
    int blocked = 0, rays = 0;
    for (int packet = 0; packet < 400; ++packet) {
        const int count = 1 + packet % Accelerator::kPacketSize;
        const bool coherent = packet % 2 == 0;
        const Vec3 light{-6 + 12 * u(rng), 2 + 6 * u(rng), -6 + 12 * u(rng)};
        const Vec3 near{-4 + 8 * u(rng), -1 + 0.2 * u(rng), -2 + 6 * u(rng)}; // on or near the ground plane
        Ray batch[Accelerator::kPacketSize];
        for (int i = 0; i < count; ++i) {
            Ray& r = batch[i];
            r.origin = coherent ? near + Vec3{0.05 * u(rng), 0, 0.05 * u(rng)}
                                : Vec3{-6 + 12 * u(rng), -1 + 5 * u(rng), -6 + 12 * u(rng)};
            r.direction = light - r.origin; // the light at t = 1
            r.tMin = 0;
            r.tMax = packet % 7 == 0 ? 0.5 : 1;
            r.time = u(rng);
        }
        bool packed[Accelerator::kPacketSize];
        accel.occludedPacket(batch, count, packed);
        for (int i = 0; i < count; ++i, ++rays) {
            const bool alone = accel.occluded(batch[i]);
            ASSERT_EQ(alone, packed[i]) << "shadow ray " << rays;
            blocked += alone;
        }
    }
    EXPECT_GT(blocked, rays / 10); // some are blocked
    EXPECT_LT(blocked, rays - rays / 10); // and some are not
}

// A packet converts the interval and time that its rays share with ray 0
// once (fillPacket): a lane whose own differ, alone or next to lanes that
// share them, must still be traced with its own, for hits and shadow rays.
TEST(Packet, LanesWithTheirOwnIntervalAndTimeKeepThem) {
    const Scene scene = mixedScene();
    const Accelerator accel(scene);
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> u(0, 1);
    const double tMins[] = {0, -0.0, 0.5, 3, 7.25};
    const double tMaxes[] = {1e30, 8, 9.5, 12, std::numeric_limits<double>::infinity()};
    const double times[] = {0, 0.25, 0.5, 1, 2};
    int differing = 0, hits = 0;
    for (int packet = 0; packet < 300; ++packet) {
        const int count = 2 + packet % (Accelerator::kPacketSize - 1);
        const Vec3 eye{-1 + 2 * u(rng), 1 + u(rng), -8};
        const Vec3 aim{-4 + 8 * u(rng), -1 + 4 * u(rng), 0};
        Ray batch[Accelerator::kPacketSize];
        for (int i = 0; i < count; ++i) {
            Ray& r = batch[i];
            r.origin = eye;
            r.direction = aim + Vec3{0.3 * u(rng), 0.3 * u(rng), 0} - eye;
            // Mostly the first ray's values, with some lanes of their own.
            const bool own = i > 0 && u(rng) < 0.4;
            r.tMin = own ? tMins[rng() % 5] : tMins[packet % 5];
            r.tMax = own ? tMaxes[rng() % 5] : tMaxes[packet % 5];
            r.time = own ? times[rng() % 5] : times[packet % 5];
            differing += own;
        }
        Hit packed[Accelerator::kPacketSize];
        bool found[Accelerator::kPacketSize];
        accel.intersectPacket(batch, count, packed, found);
        bool blocked[Accelerator::kPacketSize];
        accel.occludedPacket(batch, count, blocked);
        for (int i = 0; i < count; ++i) {
            Hit alone;
            const bool foundAlone = accel.intersect(batch[i], alone);
            ASSERT_EQ(foundAlone, found[i]) << "packet " << packet << " ray " << i;
            ASSERT_EQ(accel.occluded(batch[i]), blocked[i]) << "packet " << packet << " ray " << i;
            if (!foundAlone) continue;
            ++hits;
            expectSameHit(alone, packed[i], i);
        }
    }
    EXPECT_GT(differing, 300);
    EXPECT_GT(hits, 300);
}

// A packet of rays from `origin` along the directions from `eye` to `aim`
// moved by up to 0.3 in x and 0.2 in y.
void jitteredPacket(Ray (&rays)[Accelerator::kPacketSize], const Vec3& origin, const Vec3& eye, const Vec3& aim,
                    std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0, 1);
    for (Ray& r : rays) {
        r.origin = origin;
        r.direction = aim + Vec3{0.3 * u(rng), 0.2 * u(rng), 0} - eye;
        r.time = 0;
    }
}

// The renderer traces the shadow rays of a packet's camera hits ahead
// (Integrator::traceCameraShadows) and the shading takes their answers and
// the hits' facings worked out for them: every sample must be the bits, and
// count the rays, it gives with each shadow ray traced alone and each facing
// worked out by the shading. The scene has what may and what may not go in packets (a
// point light, a spotlight, an area light, a shadowless light), a bumped
// surface whose normal is not the one the rays were planned with, layers, and
// camera rays that miss; the second scene also a glass ball and a filtering
// box that cast shadows (rays through them only get no answer ahead).
void expectShadowRaysTracedAheadGiveTheSameSamples(const std::string& extra) {
    Diagnostics diagnostics;
    std::optional<Scene> scene = loadSceneText(R"(
camera { location <0, 2, -6> look_at <0, 0.5, 0> angle 60 }
light_source { <-4, 6, -4>, color rgb 0.7 }
light_source { <3, 5, -3>, color rgb 0.5 spotlight point_at <0, 0, 0> radius 20 falloff 30 }
light_source { <0, 8, 2>, color rgb 0.4 area_light <1, 0, 0>, <0, 0, 1>, 2, 2 }
light_source { <2, 3, -5>, color rgb 0.3 shadowless }
light_source { <5, 0.3, 0>, color rgb 0.3 }
background { color rgb <0.3, 0.4, 0.6> }
plane { y, 0 pigment { checker rgb 0.8, rgb 0.4 } normal { bumps 0.6 scale 0.2 } }
sphere { <0, 0.8, 0>, 0.8 pigment { color rgb <0.8, 0.3, 0.2> } finish { reflection 0.3 phong 0.5 } }
sphere { <1.6, 0.5, 1>, 0.5 texture { pigment { color rgb <0.2, 0.5, 0.8> } }
                            texture { pigment { color rgbt <1, 1, 1, 0.6> } finish { specular 0.4 } } no_shadow }
box { <-2.5, 0, -1>, <-1.5, 1.2, 0> pigment { color rgb 0.9 } rotate y*20 }
)" + extra, "shadow-packets.drt", diagnostics);
    ASSERT_TRUE(scene && !diagnostics.hasErrors()) << diagnostics.formatAll();
    const Accelerator accel(*scene);
    const Integrator integrator(*scene, accel);
    const std::unique_ptr<Sampler> sampler = makeSampler("sobol", 8, 3);
    std::mt19937 rng(5);
    const Vec3 eye{0, 2, -6};
    int samples = 0;
    RayCounts aheadCounts, aloneCounts;
    for (int pixel = 0; pixel < 300; ++pixel) {
        const int x = pixel % 20, y = pixel / 20;
        const Vec3 aim{-3.5 + 7 * (x + 0.5) / 20, 2.5 - 3 * (y + 0.5) / 15, 0};
        Ray rays[Accelerator::kPacketSize];
        jitteredPacket(rays, eye, eye, aim, rng);
        Hit hits[Accelerator::kPacketSize];
        bool found[Accelerator::kPacketSize];
        accel.intersectPacket(rays, Accelerator::kPacketSize, hits, found);
        CameraShadows ahead;
        integrator.traceCameraShadows(rays, hits, found, Accelerator::kPacketSize, ahead);
        for (int k = 0; k < Accelerator::kPacketSize; ++k, ++samples) {
            sampler->startPixelSample(x, y, k);
            const Color withAhead = integrator.trace(rays[k], hits[k], found[k], *sampler, aheadCounts, &ahead);
            sampler->startPixelSample(x, y, k);
            const Color alone = integrator.trace(rays[k], hits[k], found[k], *sampler, aloneCounts);
            for (int c = 0; c < 3; ++c)
                ASSERT_EQ(std::bit_cast<uint64_t>(withAhead[c]), std::bit_cast<uint64_t>(alone[c]))
                    << "sample " << samples << " channel " << c;
        }
    }
    EXPECT_EQ(aheadCounts.camera, aloneCounts.camera);
    EXPECT_EQ(aheadCounts.shadow, aloneCounts.shadow);
    EXPECT_EQ(aheadCounts.secondary, aloneCounts.secondary);
    EXPECT_GT(aloneCounts.shadow, uint64_t(samples)); // the lights do send shadow rays
}

TEST(Packet, ShadowRaysTracedAheadGiveTheSameSamples) {
    expectShadowRaysTracedAheadGiveTheSameSamples("");
    expectShadowRaysTracedAheadGiveTheSameSamples(R"(
sphere { <-0.9, 1.9, -1.2>, 0.45 pigment { color rgbf <0.9, 1, 0.9, 0.8> } }
box { <0.6, 0, -2.2>, <1.2, 0.7, -1.6> pigment { color rgbt <0.3, 0.3, 0.9, 0.5> } }
)");
}

// What decides which lights go ahead: the first and the last light of the
// scene above (plain point lights) do, the others do not; a caster that lets
// light through changes nothing (rays through it alone get no answer).
TEST(Packet, OnlyLightsOneOcclusionQueryAnswersAreTracedAhead) {
    const auto lightsAhead = [](const char* text) {
        Diagnostics diagnostics;
        std::optional<Scene> scene = loadSceneText(text, "ahead.drt", diagnostics);
        EXPECT_TRUE(scene && !diagnostics.hasErrors()) << diagnostics.formatAll();
        const Accelerator accel(*scene);
        const Integrator integrator(*scene, accel);
        Ray ray;
        ray.origin = {0, 2, -6};
        ray.direction = Vec3{0, 0, 0} - ray.origin;
        Hit hit;
        bool found = accel.intersect(ray, hit);
        EXPECT_TRUE(found);
        CameraShadows ahead;
        integrator.traceCameraShadows(&ray, &hit, &found, 1, ahead);
        std::vector<size_t> lights;
        for (size_t i = 0; i < ahead.answers_.size(); i += Accelerator::kPacketSize)
            if (ahead.answers_[i] != 0) lights.push_back(i / Accelerator::kPacketSize);
        return lights;
    };
    const std::string lights = R"(
camera { location <0, 2, -6> look_at <0, 0, 0> }
light_source { <-4, 6, -4>, color rgb 0.7 }
light_source { <3, 5, -3>, color rgb 0.5 spotlight point_at <0, 0, 0> }
light_source { <0, 8, 2>, color rgb 0.4 area_light <1, 0, 0>, <0, 0, 1>, 2, 2 }
light_source { <2, 3, -5>, color rgb 0.3 shadowless }
light_source { <5, 6, 0>, color rgb 0.3 }
light_source { <5, 6, 0>, color rgb 0 }
plane { y, 0 pigment { color rgb 0.8 } }
)";
    EXPECT_EQ(lightsAhead(lights.c_str()), (std::vector<size_t>{0, 4}));
    EXPECT_EQ(lightsAhead((lights + "sphere { <3, 1, 3>, 1 pigment { color rgbf <1, 1, 1, 0.5> } }").c_str()),
              (std::vector<size_t>{0, 4}));
}

// A render traces a pixel's camera rays in packets of up to kPacketSize from
// the first sample it takes; adaptive rounds start packets elsewhere (here at
// samples 3, 4 and 8 instead of 8). A pixel's samples must not depend on that.
TEST(Packet, APixelsSamplesDoNotDependOnWherePacketsStart) {
    Diagnostics diagnostics;
    std::optional<Scene> scene = loadSceneText(R"(
camera { location <0, 2, -6> look_at <0, 0.5, 0> angle 50 aperture 0.2 focal_point <0, 0.5, 0> }
light_source { <-4, 6, -4>, color rgb 1 area_light <1, 0, 0>, <0, 0, 1>, 4, 4 }
background { color rgb <0.3, 0.4, 0.6> }
plane { y, 0 pigment { color rgb 0.7 } }
sphere { <0, 0.8, 0>, 0.8 pigment { color rgb <0.8, 0.3, 0.2> } finish { reflection 0.3 } }
sphere { <1.6, 0.5, 1>, 0.5 pigment { color rgb <0.2, 0.5, 0.8> } }
)", "packets.drt", diagnostics);
    ASSERT_TRUE(scene && !diagnostics.hasErrors()) << diagnostics.formatAll();
    RenderOptions options = smallRender(*scene, 13); // packets of samples 0-7 and 8-12
    const RenderResult fixed = render(*scene, options);
    options.adaptive = true;      // rounds 0-2, 3, 4-7, 8-12
    options.adaptiveError = 1e-6;
    options.minSamplesPerPixel = 3;
    options.maxSamplesPerPixel = 13;
    const RenderResult adaptive = render(*scene, options);
    int compared = 0;
    for (int y = 0; y < options.height; ++y)
        for (int x = 0; x < options.width; ++x) {
            if (adaptive.sampleCount.at(x, y, 0) != 13) continue; // stopped early: other samples
            ++compared;
            for (int c = 0; c < 3; ++c)
                ASSERT_EQ(std::bit_cast<uint32_t>(fixed.color.at(x, y, c)),
                          std::bit_cast<uint32_t>(adaptive.color.at(x, y, c)))
                    << "pixel " << x << ", " << y;
        }
    EXPECT_GT(compared, options.width * options.height / 2);
}

// The scene with every object's texture wrapped in an `average` texture map of
// one entry, which Integrator::shade shades through shadePatterned and
// shadeTexture (with a weight of exactly 1): its general path, none of its
// short ways for plain textures.
Scene throughTheGeneralPath(const Scene& scene) {
    Scene wrapped = scene;
    for (Object& object : wrapped.objects) {
        EXPECT_TRUE(object.texture->plain());
        Texture map;
        map.pigment.pattern = PatternKind::Average;
        map.map.push_back({1.0, object.texture});
        object.texture = std::move(map);
    }
    return wrapped;
}

// Integrator::shade takes a short way for the common surface (the object's own
// plain texture, straight to shadeLayers). It must shade exactly as the general
// way: the same scene with every texture wrapped in an `average` texture map of
// one entry (which shades the entry through shadePatterned and shadeTexture,
// with a weight of exactly 1) gives the same image to the bit, with reflections
// constant, Fresnel-blended and metallic, a filtering glass ball with
// conserve_energy, highlights, and point, spot and area lights. (shadeLayers'
// short way for a constant reflection is on both sides here: its own test is
// Shading.AConstantReflectionIsItsValueToTheBit.)
TEST(Packet, PlainTexturesShadeAsTheGeneralPathDoes) {
    Diagnostics diagnostics;
    std::optional<Scene> scene = loadSceneText(R"(
camera { location <0, 2, -6> look_at <0, 0.5, 0> angle 50 aperture 0.2 focal_point <0, 0.5, 0> }
light_source { <-4, 6, -4>, color rgb 1 area_light <1, 0, 0>, <0, 0, 1>, 2, 2 }
light_source { <3, 5, -3>, color rgb 0.5 }
light_source { <0, 6, 0>, color rgb 0.7 spotlight point_at <0, 0, 0> radius 10 falloff 20 }
background { color rgb <0.3, 0.4, 0.6> }
plane { y, 0 pigment { checker color rgb 0.7, color rgb 0.2 } finish { reflection 0.2 } }
sphere { <0, 0.8, 0>, 0.8 pigment { color rgb <0.8, 0.3, 0.2> } finish { phong 0.5 reflection { 0.1, 0.6 fresnel on } } }
sphere { <1.6, 0.5, 1>, 0.5 pigment { color rgb <0.2, 0.5, 0.8> } finish { specular 0.4 roughness 0.01 reflection { 0.3 metallic 1 } } }
sphere { <-1.5, 0.6, -0.5>, 0.6 pigment { color rgbf <0.9, 1, 0.9, 0.8> } finish { reflection 0.1 conserve_energy } interior { ior 1.5 } }
sphere { <-0.5, 0.3, -1.5>, 0.3 pigment { color rgb 0.9 } finish { reflection { 0.25, 0.25 } diffuse 0.5 } }
)", "plain.drt", diagnostics);
    ASSERT_TRUE(scene && !diagnostics.hasErrors()) << diagnostics.formatAll();
    const RenderOptions options = smallRender(*scene, 4);
    const RenderResult plain = render(*scene, options);
    const RenderResult general = render(throughTheGeneralPath(*scene), options);
    EXPECT_EQ(plain.stats.shadowRays, general.stats.shadowRays);
    EXPECT_EQ(plain.stats.secondaryRays, general.stats.secondaryRays);
    EXPECT_GT(plain.stats.secondaryRays, 0u);
    for (int y = 0; y < options.height; ++y)
        for (int x = 0; x < options.width; ++x)
            for (int c = 0; c < 3; ++c)
                ASSERT_EQ(std::bit_cast<uint32_t>(plain.color.at(x, y, c)),
                          std::bit_cast<uint32_t>(general.color.at(x, y, c)))
                    << "pixel " << x << ", " << y;
}

// Integrator::shade takes a shorter way still for a matte surface (a solid
// pigment without filter or transmit, no bumps, no reflection: shadeMatte
// adds its ambient and light terms and spawns nothing). Every sample must be
// the bits, and count the rays, the general way gives: random matte finishes
// (ambient, emission, diffuse, brilliance, phong, specular, metallic, crand),
// colours beyond [0, 1], surfaces seen from inside, among surfaces that do
// not qualify (a reflection, a filter, bumps), under point, spot, area,
// fading and shadowless lights, and with no light at all. The general way is
// the same scene with every texture an `average` map of one entry.
TEST(Packet, MatteSurfacesShadeAsTheGeneralPathDoes) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0, 1);
    const auto number = [](double v) {
        std::ostringstream out;
        out << std::setprecision(17) << v;
        return out.str();
    };
    const auto colour = [&] {
        return "<" + number(1.4 * u(rng) - 0.1) + ", " + number(1.2 * u(rng)) + ", " + number(u(rng)) + ">";
    };
    std::string objects;
    for (int i = 0; i < 14; ++i) {
        std::string finish = "ambient " + number(0.3 * u(rng)) + " diffuse " + number(u(rng));
        if (u(rng) < 0.4) finish += " brilliance " + number(0.5 + 3 * u(rng));
        if (u(rng) < 0.4) finish += " phong " + number(u(rng)) + " phong_size " + number(1 + 80 * u(rng));
        if (u(rng) < 0.4) finish += " specular " + number(u(rng)) + " roughness " + number(0.001 + 0.1 * u(rng));
        if (u(rng) < 0.3) finish += " metallic " + number(u(rng));
        if (u(rng) < 0.3) finish += " crand " + number(0.3 * u(rng));
        if (u(rng) < 0.2) finish += " emission " + number(0.5 * u(rng));
        std::string pigment = "color rgb " + colour();
        std::string extra;
        const int kind = i % 7; // 0-4 matte, 5 reflective, 6 filtering or bumped
        if (kind == 5) finish += " reflection " + number(0.1 + 0.5 * u(rng));
        if (kind == 6) {
            if (i % 2) pigment = "color rgbf <0.9, 0.9, 0.9, 0.5>";
            else extra = " normal { bumps 0.5 scale 0.2 }";
        }
        const double x = -4 + 8 * u(rng), z = -1 + 5 * u(rng), r = 0.3 + 0.6 * u(rng);
        objects += "sphere { <" + number(x) + ", " + number(r) + ", " + number(z) + ">, " + number(r) +
                   " pigment { " + pigment + " } finish { " + finish + " }" + extra + " }\n";
    }
    // A sphere around the camera's packet of rays at the top left: seen from inside.
    objects += "sphere { <-3, 2.5, -5>, 0.8 pigment { color rgb <0.6, 0.7, 0.2> } finish { diffuse 0.7 } }\n";
    objects += "plane { y, 0 pigment { color rgb " + colour() + " } finish { ambient 0.2 diffuse 0.6 } }\n";
    const std::string lights = R"(
light_source { <-4, 6, -4>, color rgb 0.8 }
light_source { <3, 5, -3>, color rgb 0.5 spotlight point_at <0, 0, 0> radius 20 falloff 30 }
light_source { <0, 8, 2>, color rgb 0.4 area_light <1, 0, 0>, <0, 0, 1>, 2, 2 }
light_source { <2, 3, -5>, color rgb 0.3 shadowless }
light_source { <5, 4, 0>, color rgb 0.6 fade_distance 3 fade_power 2 }
)";
    const std::string head = R"(
global_settings { ambient_light rgb <0.9, 1, 1.2> }
camera { location <0, 2, -6> look_at <0, 0.5, 0> angle 60 }
background { color rgb <0.3, 0.4, 0.6> }
)";
    for (const bool lit : {true, false}) {
        Diagnostics diagnostics;
        std::optional<Scene> scene = loadSceneText(head + (lit ? lights : "") + objects, "matte.drt", diagnostics);
        ASSERT_TRUE(scene && !diagnostics.hasErrors()) << diagnostics.formatAll();
        const Scene wrapped = throughTheGeneralPath(*scene);
        const Accelerator accel(*scene), wrappedAccel(wrapped);
        const Integrator integrator(*scene, accel), general(wrapped, wrappedAccel);
        const std::unique_ptr<Sampler> sampler = makeSampler("sobol", 8, 3);
        const Vec3 eye{0, 2, -6};
        int samples = 0, inside = 0;
        RayCounts shortCounts, generalCounts;
        for (int pixel = 0; pixel < 400; ++pixel) {
            const int x = pixel % 20, y = pixel / 20;
            const Vec3 aim{-4.5 + 9 * (x + 0.5) / 20, 3 - 4 * (y + 0.5) / 20, 0};
            Ray rays[Accelerator::kPacketSize];
            jitteredPacket(rays, pixel == 0 ? Vec3{-3, 2.5, -5} : eye, eye, aim, rng);
            Hit hits[Accelerator::kPacketSize], wrappedHits[Accelerator::kPacketSize];
            bool found[Accelerator::kPacketSize], wrappedFound[Accelerator::kPacketSize];
            accel.intersectPacket(rays, Accelerator::kPacketSize, hits, found);
            wrappedAccel.intersectPacket(rays, Accelerator::kPacketSize, wrappedHits, wrappedFound);
            CameraShadows ahead, wrappedAhead;
            integrator.traceCameraShadows(rays, hits, found, Accelerator::kPacketSize, ahead);
            general.traceCameraShadows(rays, wrappedHits, wrappedFound, Accelerator::kPacketSize, wrappedAhead);
            for (int k = 0; k < Accelerator::kPacketSize; ++k, ++samples) {
                if (found[k] && dot(rays[k].direction, hits[k].geometricNormal) > 0) ++inside;
                sampler->startPixelSample(x, y, k);
                const Color fast = integrator.trace(rays[k], hits[k], found[k], *sampler, shortCounts, &ahead);
                sampler->startPixelSample(x, y, k);
                const Color slow =
                    general.trace(rays[k], wrappedHits[k], wrappedFound[k], *sampler, generalCounts, &wrappedAhead);
                for (int c = 0; c < 3; ++c)
                    ASSERT_EQ(std::bit_cast<uint64_t>(fast[c]), std::bit_cast<uint64_t>(slow[c]))
                        << (lit ? "lit" : "unlit") << " sample " << samples << " channel " << c;
            }
        }
        EXPECT_GT(inside, 0);
        EXPECT_EQ(shortCounts.camera, generalCounts.camera);
        EXPECT_EQ(shortCounts.shadow, generalCounts.shadow);
        EXPECT_EQ(shortCounts.secondary, generalCounts.secondary);
        EXPECT_GT(generalCounts.secondary, 0u); // the reflective and filtering spheres spawn rays
        if (lit) {
            EXPECT_GT(generalCounts.shadow, uint64_t(samples));
        }
    }
}

// The rays a hit spawns are traced at the camera ray's time: a mirror seen
// straight down reflects a glowing ball that moves away over the shutter
// (x = 2 t), so the ball is in the mirror at times 0 and 0.1 and gone by 0.4
// and 0.9. A spawned ray at another time (half the camera ray's, or 0) sees
// it at 0.4 too. Also checks what the spawned ray carries besides: its weight
// (the mirror's reflection 0.5) and its depth (one secondary ray).
TEST(Integrator, SpawnedRaysKeepTheCameraRaysTime) {
    Diagnostics diagnostics;
    std::optional<Scene> scene = loadSceneText(R"(
camera { location <0, 1, -5> look_at <0, 0, 0> }
background { color rgb 0 }
plane { y, 0 pigment { color rgb 0 } finish { ambient 0 diffuse 0 reflection 0.5 } }
sphere { <0, 2, 0>, 0.5 pigment { color rgb 1 } finish { ambient 1 diffuse 0 } motion { translate <2, 0, 0> } }
)", "spawned-time.drt", diagnostics);
    ASSERT_TRUE(scene && !diagnostics.hasErrors()) << diagnostics.formatAll();
    const Accelerator accel(*scene);
    const Integrator integrator(*scene, accel);
    const std::unique_ptr<Sampler> sampler = makeSampler("sobol", 1, 3);
    for (const double time : {0.0, 0.1, 0.4, 0.9}) {
        Ray ray;
        ray.origin = {0, 1, 0}; // between the mirror and the ball
        ray.direction = {0, -1, 0};
        ray.time = time;
        Hit hit;
        const bool found = accel.intersect(ray, hit);
        ASSERT_TRUE(found);
        sampler->startPixelSample(0, 0, 0);
        RayCounts counts;
        const Color c = integrator.trace(ray, hit, found, *sampler, counts);
        const Color expected(time < 0.25 ? 0.5 : 0.0); // the ball's ambient 1 through the reflection 0.5
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], expected[k], 1e-12) << "time " << time;
        EXPECT_EQ(counts.camera, 1u);
        EXPECT_EQ(counts.secondary, 1u);
    }
}

} // namespace
} // namespace drt
