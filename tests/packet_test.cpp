// Accelerator::intersectPacket (camera rays traced as one Embree packet) must
// give every ray exactly the hit Accelerator::intersect gives it alone: the
// renderer relies on that for images that do not depend on how rays are traced.
#include "accel/accel.h"
#include "lang/load.h"
#include "render/render.h"
#include "scene/motion.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <bit>
#include <random>

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
    RenderOptions options = resolveRenderOptions(scene->render);
    options.width = 40;
    options.height = 30;
    options.threads = 2;
    options.samplesPerPixel = 13; // packets of samples 0-7 and 8-12
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

} // namespace
} // namespace drt
