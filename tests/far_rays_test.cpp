// Rays beyond the range Embree traces in (Accelerator::kLargestCoordinate):
// never handed to Embree (Debian's Embree asserts on them and ends the
// process), a shadow ray toward a very far light traced with its direction
// scaled down, any other counted and taken to meet nothing, and a render that
// had some says so.
#include "accel/accel.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>

namespace drt {
namespace {

namespace fs = std::filesystem;

using test::makeObject;
using test::sceneOf;

Ray rayOf(Vec3 origin, Vec3 direction, double tMax = std::numeric_limits<double>::infinity()) {
    Ray ray;
    ray.origin = origin;
    ray.direction = direction;
    ray.tMax = tMax;
    return ray;
}

TEST(FarRays, AnOriginOrDirectionBeyondTheRangeMeetsNothingAndIsCounted) {
    const Scene scene = sceneOf({makeObject(Sphere{{0, 0, 0}, 1})});
    const Accelerator accel(scene);
    Hit hit;
    // In range: the sphere, and nothing counted.
    EXPECT_TRUE(accel.intersect(rayOf({0, 0, -1e17}, {0, 0, 1}), hit));
    EXPECT_EQ(accel.untraceableRays(), 0u);
    // The same line from beyond the range, pointing at the sphere.
    EXPECT_FALSE(accel.intersect(rayOf({0, 0, -1e19}, {0, 0, 1}), hit));
    EXPECT_EQ(accel.untraceableRays(), 1u);
    // A direction too long to trace, and one that is not a number.
    EXPECT_FALSE(accel.intersect(rayOf({0, 0, -5}, {0, 0, 1e30}), hit));
    EXPECT_FALSE(accel.intersect(rayOf({0, 0, -5}, {0, 0, std::nan("")}), hit));
    EXPECT_EQ(accel.untraceableRays(), 3u);
    // A shadow ray whose origin is out of range is not blocked, and counted.
    EXPECT_FALSE(accel.occluded(rayOf({0, 0, -1e19}, {0, 0, 2e19}, 1)));
    EXPECT_EQ(accel.untraceableRays(), 4u);
}

TEST(FarRays, AShadowRayTowardAVeryFarLightIsTracedScaledDown) {
    const Scene scene = sceneOf({makeObject(Sphere{{0, 0, 0}, 1})});
    const Accelerator accel(scene);
    // From below the sphere up to a light at 1e30 (the light at t = 1): blocked;
    // beside it: free. Nothing counted.
    EXPECT_TRUE(accel.occluded(rayOf({0, -5, 0}, {0, 1e30, 0}, 1)));
    EXPECT_FALSE(accel.occluded(rayOf({3, -5, 0}, {0, 1e30, 0}, 1)));
    // The sphere beyond the light's end of the segment does not block it.
    EXPECT_FALSE(accel.occluded(rayOf({0, -5, 0}, {0, 1e30, 0}, 1e-30)));
    EXPECT_EQ(accel.untraceableRays(), 0u);
}

TEST(FarRays, PacketsGiveWhatEachRayAloneGives) {
    const Scene scene = sceneOf({makeObject(Sphere{{0, 0, 0}, 1})});
    const Accelerator accel(scene);
    Ray rays[Accelerator::kPacketSize];
    for (int i = 0; i < Accelerator::kPacketSize; ++i) rays[i] = rayOf({0.1 * i, 0, -5}, {0, 0, 1});
    rays[3] = rayOf({0, 0, -1e19}, {0, 0, 1}); // out of range
    Hit hits[Accelerator::kPacketSize];
    bool found[Accelerator::kPacketSize];
    accel.intersectPacket(rays, Accelerator::kPacketSize, hits, found);
    for (int i = 0; i < Accelerator::kPacketSize; ++i) {
        Hit alone;
        EXPECT_EQ(found[i], accel.intersect(rays[i], alone)) << i;
        if (found[i]) {
            EXPECT_EQ(hits[i].t, alone.t) << i;
        }
    }
    EXPECT_FALSE(found[3]);
    EXPECT_TRUE(found[0]);
    // Shadow rays: one toward a far light among ordinary ones.
    Ray shadows[Accelerator::kPacketSize];
    for (int i = 0; i < Accelerator::kPacketSize; ++i) shadows[i] = rayOf({0.2 * i, -5, 0}, {0, 10, 0}, 1);
    shadows[5] = rayOf({0, -5, 0}, {0, 1e30, 0}, 1);
    bool blocked[Accelerator::kPacketSize];
    accel.occludedPacket(shadows, Accelerator::kPacketSize, blocked);
    for (int i = 0; i < Accelerator::kPacketSize; ++i) EXPECT_EQ(blocked[i], accel.occluded(shadows[i])) << i;
    EXPECT_TRUE(blocked[5]);
}

// The fuzzer's scene (a camera at 3e101) and a light at 1e30: both render, the
// first with a warning naming the rays and what to do, and --stats counts them.
TEST(FarRays, RendersWithAFarCameraWarnAndWithAFarLightCastShadows) {
    const std::string dir = test::tempDir();
    const std::string far = test::writeFile(dir + "/far.drt", "camera { location <0, 1, 1e30> look_at <0, 1, 0> }\n"
                                                              "light_source { <0, 5, 0>, rgb 1 }\n"
                                                              "sphere { 0, 1 pigment { rgb 1 } }\n");
    const auto r = test::runDrt("render " + far + " -o " + dir + "/far.png --width 16 --height 12 --spp 1 -q --stats " +
                                dir + "/far.json");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir + "/far.png"));
    EXPECT_NE(r.err.find("far.drt: warning: 192 rays started or pointed beyond"), std::string::npos) << r.err;
    const nlohmann::json stats = nlohmann::json::parse(test::readFile(dir + "/far.json"));
    EXPECT_EQ(stats.at("untraceable_rays"), 192);

    const std::string light = test::writeFile(dir + "/light.drt", "camera { location <0, 3, -6> look_at <0, 0, 0> }\n"
                                                                  "light_source { <0, 1e30, 0>, rgb 1 }\n"
                                                                  "sphere { 0, 1 pigment { rgb 1 } }\n"
                                                                  "plane { y, -1 pigment { rgb 1 } }\n");
    const auto lit = test::runDrt("render " + light + " -o " + dir + "/light.exr --width 16 --height 12 --spp 1 -q");
    EXPECT_EQ(lit.exitCode, 0) << lit.err;
    EXPECT_EQ(lit.err.find("warning"), std::string::npos) << lit.err;
}

} // namespace
} // namespace drt
