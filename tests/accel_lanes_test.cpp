// The Embree callbacks take a short way for a packet of 8 rays, and for a
// single ray, at the top level meeting a sphere or a plane without a
// transform (what most camera, shadow and secondary rays meet): each lane
// must get the crossing the general way gives it, so a full packet's hits and
// shadow answers must be those of each ray traced alone, and a ray traced
// alone must get what it gets as the one valid lane of a packet of 4 (which
// takes the general way).
#include "accel/accel.h"
#include "accel/accel_impl.h"
#include "accel/built_scene.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <random>

namespace drt {
namespace {

using test::makeObject;
using test::sceneOf;

void expectSameBits(const Vec3& a, const Vec3& b, const char* what, int ray) {
    for (int k = 0; k < 3; ++k)
        EXPECT_EQ(std::bit_cast<uint64_t>(a[k]), std::bit_cast<uint64_t>(b[k])) << what << " of ray " << ray;
}

// Spheres and planes with no transform (the short way), one that is inverted,
// one that casts no shadow, and a transformed sphere beside them (the
// general way, in the same packets); all moved by `shift`, the untransformed
// ones in their own coordinates.
Scene spheresAndPlanes(const Vec3& shift = {}) {
    std::vector<Object> objects;
    const auto plane = [&](const Vec3& normal, double distance) {
        return makeObject(Plane{normal, distance + dot(normal, shift)});
    };
    objects.push_back(plane({0, 1, 0}, 0));
    objects.push_back(plane(normalize(Vec3{1, 0.2, -0.3}), 6));
    for (int i = 0; i < 5; ++i) objects.push_back(makeObject(Sphere{shift + Vec3{-4.0 + 2 * i, 0.8, 0}, 0.8}));
    Object inverted = makeObject(Sphere{shift + Vec3{0, 0.5, 3}, 0.5});
    inverted.inverse = true;
    objects.push_back(inverted);
    Object shadowless = makeObject(Sphere{shift + Vec3{-2, 1.5, -2}, 0.6});
    shadowless.noShadow = true;
    objects.push_back(shadowless);
    objects.push_back(makeObject(Sphere{{0, 0, 0}, 1},
                                 Transform::scale({1, 0.5, 1}).then(Transform::translate(shift + Vec3{3, 2, 2}))));
    return sceneOf(std::move(objects));
}

void expectFullPacketsGetTheHitsOfRaysAlone() {
    const Scene scene = spheresAndPlanes();
    const Accelerator accel(scene);
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> u(0, 1);
    constexpr int kN = Accelerator::kPacketSize;
    int hits = 0, blocked = 0, rays = 0;
    for (int packet = 0; packet < 500; ++packet) {
        // Camera-like packets, some from inside a sphere (its far root), some
        // starting past tMin > 0, some with a short tMax.
        const Vec3 eye = packet % 7 == 0 ? Vec3{-2 + 0.2 * u(rng), 0.8, 0.1 * u(rng)}
                                         : Vec3{-3 + 6 * u(rng), 0.5 + 4 * u(rng), -9 + 2 * u(rng)};
        const Vec3 aim{-5 + 10 * u(rng), -1 + 3 * u(rng), 2 * u(rng)};
        Ray batch[kN];
        for (Ray& r : batch) {
            r.origin = eye;
            r.direction = aim + Vec3{0.2 * u(rng), 0.2 * u(rng), 0} - eye;
            r.tMin = packet % 3 == 0 ? 0.25 : 0;
            r.tMax = packet % 5 == 0 ? 6 : r.tMax;
            r.time = 0;
        }
        Hit packed[kN];
        bool found[kN];
        accel.intersectPacket(batch, kN, packed, found);
        // Shadow rays from the hits toward a light, as the renderer makes them.
        const Vec3 light{-6 + 12 * u(rng), 3 + 6 * u(rng), -6 + 6 * u(rng)};
        Ray shadows[kN];
        int shadowCount = 0;
        for (int i = 0; i < kN; ++i, ++rays) {
            Hit alone;
            ASSERT_EQ(accel.intersect(batch[i], alone), found[i]) << "ray " << rays;
            if (!found[i]) continue;
            ++hits;
            EXPECT_EQ(std::bit_cast<uint64_t>(alone.t), std::bit_cast<uint64_t>(packed[i].t)) << "ray " << rays;
            expectSameBits(alone.point, packed[i].point, "point", rays);
            expectSameBits(alone.geometricNormal, packed[i].geometricNormal, "normal", rays);
            EXPECT_EQ(alone.object, packed[i].object) << "ray " << rays;
            const Vec3 toLight = light - packed[i].point;
            Ray& s = shadows[shadowCount++];
            s.origin = Accelerator::offsetOrigin(packed[i], toLight);
            s.direction = light - s.origin;
            s.tMax = 1;
        }
        // Fill the packet up so that Embree traces all 8 lanes.
        for (int i = shadowCount; i < kN && shadowCount > 0; ++i) shadows[i] = shadows[i % shadowCount];
        if (shadowCount == 0) continue;
        bool shadowed[kN];
        accel.occludedPacket(shadows, kN, shadowed);
        for (int i = 0; i < kN; ++i) {
            ASSERT_EQ(accel.occluded(shadows[i]), shadowed[i]) << "shadow ray " << i << " of packet " << packet;
            blocked += shadowed[i];
        }
    }
    EXPECT_GT(hits, rays / 2);
    EXPECT_GT(blocked, 100);
}

// Both packet kernels for shadow rays are checked: two lanes an instruction,
// and four where the processor has AVX.
TEST(AccelLanes, FullPacketsOfSpheresAndPlanesGetTheHitsOfRaysAlone) {
    const bool avx = accel::avxLanes;
    for (const bool four : {false, true}) {
        if (four && !__builtin_cpu_supports("avx")) continue;
        SCOPED_TRACE(four ? "four lanes an instruction" : "two lanes an instruction");
        accel::avxLanes = four;
        expectFullPacketsGetTheHitsOfRaysAlone();
    }
    accel::avxLanes = avx;
}

// A single ray (Embree's N = 1: shadow and secondary rays) takes the short
// way; the same ray as the one valid lane of a packet of 4 takes the general
// way. Both must find the same crossing to the bit (t, normal, primitive) and
// the same shadow answer, in a scene at the origin and in one traced in a
// shifted frame (which takes the general way alone too).
TEST(AccelLanes, SingleRaysGetTheGeneralWaysCrossings) {
    for (const Vec3 shift : {Vec3{}, Vec3{1e5, -3e4, 2e5}}) {
        const Scene scene = spheresAndPlanes(shift);
        accel::AcceleratorState state;
        accel::buildScene(scene, state);
        std::mt19937 rng(29);
        std::uniform_real_distribution<double> u(0, 1);
        int hits = 0, blocked = 0, shortWay = 0;
        for (int k = 0; k < 20000; ++k) {
            const Vec3 origin = shift + (k % 5 == 0 ? Vec3{-2 + 0.3 * u(rng), 0.8, 0.2 * u(rng)} // inside a sphere
                                                    : Vec3{-6 + 12 * u(rng), 0.2 + 5 * u(rng), -9 + 3 * u(rng)});
            const Vec3 direction = shift + Vec3{-5 + 10 * u(rng), -1 + 4 * u(rng), 2 * u(rng)} - origin;
            const Vec3 o = origin - state.frameOrigin;
            const float tnear = k % 3 == 0 ? 0.25f : 0.0f, tfar = k % 7 == 0 ? 0.5f : INFINITY;
            // Alone.
            accel::RayQuery single(state, origin, direction);
            RTCRayHit rayhit;
            rayhit.ray = {float(o.x), float(o.y), float(o.z), tnear, float(direction.x), float(direction.y),
                          float(direction.z), 0, tfar, 0xFFFFFFFFu, 0, 0};
            rayhit.hit.geomID = rayhit.hit.primID = rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(state.top.scene, &single.context, &rayhit);
            // Lane 0 of a packet of 4.
            accel::RayQuery laned(state, origin, direction);
            alignas(16) RTCRayHit4 packet{};
            alignas(16) const int valid[4] = {-1, 0, 0, 0};
            packet.ray.org_x[0] = float(o.x), packet.ray.org_y[0] = float(o.y), packet.ray.org_z[0] = float(o.z);
            packet.ray.dir_x[0] = float(direction.x), packet.ray.dir_y[0] = float(direction.y);
            packet.ray.dir_z[0] = float(direction.z);
            packet.ray.tnear[0] = tnear, packet.ray.tfar[0] = tfar, packet.ray.mask[0] = 0xFFFFFFFFu;
            for (int i = 0; i < 4; ++i) packet.hit.geomID[i] = packet.hit.primID[i] = packet.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect4(valid, state.top.scene, &laned.context, &packet);
            ASSERT_EQ(rayhit.hit.geomID, packet.hit.geomID[0]) << "ray " << k;
            if (rayhit.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
                ++hits;
                ASSERT_EQ(rayhit.hit.primID, packet.hit.primID[0]) << "ray " << k;
                ASSERT_EQ(std::bit_cast<uint32_t>(rayhit.ray.tfar), std::bit_cast<uint32_t>(packet.ray.tfar[0])) << k;
                ASSERT_EQ(std::bit_cast<uint32_t>(rayhit.hit.Ng_y), std::bit_cast<uint32_t>(packet.hit.Ng_y[0])) << k;
                ASSERT_EQ(single.hasCrossing, laned.hasCrossing) << "ray " << k;
                if (single.hasCrossing) {
                    ASSERT_EQ(single.objectSpace, laned.objectSpace) << "ray " << k;
                    const double ts = single.objectSpace ? single.objectCrossing.t : single.crossing.t;
                    const double tl = laned.objectSpace ? laned.objectCrossing.t : laned.crossing.t;
                    ASSERT_EQ(std::bit_cast<uint64_t>(ts), std::bit_cast<uint64_t>(tl)) << "ray " << k;
                    if (single.objectSpace)
                        expectSameBits(single.objectCrossing.normal, laned.objectCrossing.normal, "normal", k);
                    const accel::Primitive& p = state.top.primitives[rayhit.hit.primID];
                    shortWay += p.plain && p.identity;
                }
            }
            // The same ray as a shadow ray.
            accel::RayQuery shadowAlone(state, origin, direction), shadowLaned(state, origin, direction);
            RTCRay shadow = rayhit.ray;
            shadow.tfar = tfar;
            rtcOccluded1(state.top.scene, &shadowAlone.context, &shadow);
            RTCRay4 shadows = packet.ray;
            shadows.tfar[0] = tfar;
            rtcOccluded4(valid, state.top.scene, &shadowLaned.context, &shadows);
            ASSERT_EQ(shadow.tfar == -INFINITY, shadows.tfar[0] == -INFINITY) << "shadow ray " << k;
            blocked += shadow.tfar == -INFINITY;
        }
        EXPECT_GT(hits, 10000);
        // In a shifted frame every primitive carries the frame's translation:
        // both take the general way there.
        EXPECT_GT(shortWay, shift.x == 0 ? 5000 : -1);
        EXPECT_GT(blocked, 5000);
    }
}

// A packet is handed to Embree only if every ray's origin (in the top level's
// frame) and direction lie within Accelerator::kLargestCoordinate, checked as
// the packet is filled: each coordinate of each lane, just within and just
// beyond the range, infinite or not a number, must give every ray what it
// gets alone (and count what alone is counted), in a scene at the origin and
// in one traced in a frame re-centred far away (the range is the frame's).
TEST(AccelLanes, PacketsCheckEveryCoordinateOfEveryLaneForEmbreesRange) {
    constexpr double kLargest = Accelerator::kLargestCoordinate;
    const double values[] = {kLargest, -kLargest, std::nextafter(kLargest, INFINITY), -1e19,
                             std::numeric_limits<double>::infinity(), std::nan("")};
    // The far scene's spheres are as large as its coordinates' ulps allow.
    for (const double centre : {0.0, 2e18}) {
        const double r = centre > 0 ? 1e4 : 1;
        const Scene scene = sceneOf({makeObject(Sphere{{centre, 0, 0}, r}), makeObject(Sphere{{centre, 3 * r, 0}, r})});
        const Accelerator accel(scene);
        int outOfRange = 0;
        for (int lane = 0; lane < Accelerator::kPacketSize; ++lane)
            for (int coordinate = 0; coordinate < 6; ++coordinate)
                for (const double value : values) {
                    Ray rays[Accelerator::kPacketSize];
                    for (int i = 0; i < Accelerator::kPacketSize; ++i) {
                        rays[i].origin = {centre, 0.1 * r * i, -5 * r};
                        rays[i].direction = {0, 0, 1};
                        rays[i].tMax = 1e30;
                    }
                    Ray& odd = rays[lane];
                    // A coordinate at `value` in the top level's frame.
                    if (coordinate < 3) {
                        odd.origin[coordinate] = (coordinate == 0 ? centre : 0) + value;
                    } else {
                        odd.direction[coordinate - 3] = value;
                    }
                    const uint64_t before = accel.untraceableRays();
                    Hit hits[Accelerator::kPacketSize];
                    bool found[Accelerator::kPacketSize], blocked[Accelerator::kPacketSize];
                    accel.intersectPacket(rays, Accelerator::kPacketSize, hits, found);
                    accel.occludedPacket(rays, Accelerator::kPacketSize, blocked);
                    const uint64_t byPackets = accel.untraceableRays() - before;
                    // Alone, each ray is checked by itself; a packet with a ray out of
                    // range is traced ray by ray, so the answers are those alone. (A
                    // packet in range is Embree's packet kernel, whose float traversal
                    // at 1e18 may differ from its single-ray one: only its count is
                    // compared there.)
                    const bool traced = byPackets == 0;
                    for (int i = 0; i < Accelerator::kPacketSize; ++i) {
                        Hit alone;
                        const bool foundAlone = accel.intersect(rays[i], alone);
                        const bool blockedAlone = accel.occluded(rays[i]);
                        if (traced) continue;
                        ASSERT_EQ(foundAlone, found[i])
                            << "lane " << i << " of a packet with " << value << " at coordinate " << coordinate;
                        if (found[i]) {
                            EXPECT_EQ(std::bit_cast<uint64_t>(alone.t), std::bit_cast<uint64_t>(hits[i].t)) << i;
                        }
                        ASSERT_EQ(blockedAlone, blocked[i])
                            << "shadow lane " << i << " of a packet with " << value << " at coordinate " << coordinate;
                    }
                    EXPECT_EQ(byPackets, accel.untraceableRays() - before - byPackets)
                        << value << " at coordinate " << coordinate << " of lane " << lane;
                    outOfRange += !traced;
                    EXPECT_TRUE(found[lane == 0 ? 1 : 0]); // the ordinary rays still meet the sphere
                }
        EXPECT_GT(outOfRange, 100);
    }
}

} // namespace
} // namespace drt
