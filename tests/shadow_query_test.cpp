// Accelerator::occludedOpaque: one occlusion query that tells a segment
// blocked by a surface that lets no light through from one that crosses only
// surfaces that may let light through, checked against the surfaces the
// segment crosses found one by one with intersect().
#include "accel/accel.h"
#include "mesh_generators.h"
#include "scene/light_through.h"
#include "scene/motion.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <random>

namespace drt {
namespace {

using test::makeObject;
using test::sceneOf;
using Occlusion = Accelerator::Occlusion;

Object withColor(Object object, const ColorFT& color) {
    object.texture.edit().pigment.color = color;
    return object;
}

const ColorFT kOpaque{Color(0.7), 0, 0};
const ColorFT kGlass{Color(0.9), 0.8, 0};
const ColorFT kVeil{Color(0.5), 0, 0.4};

Mesh compact(std::shared_ptr<IndexedMesh> indexed) {
    Mesh m;
    m.indexed = std::move(indexed);
    return m;
}

Mesh plainMesh(const IndexedMesh& indexed) {
    Mesh m;
    for (const Float3& p : indexed.positions) m.vertices.push_back(p.toVec3());
    for (size_t i = 0; i < indexed.triangleCount(); ++i) {
        const auto tri = indexed.triangle(i);
        m.triangles.push_back({int(tri[0]), int(tri[1]), int(tri[2])});
    }
    return m;
}

// Every kind of shadow caster the accelerator builds, each once opaque and
// once letting light through: analytic shapes (the short way's sphere and a
// transformed torus), CSG with a glass member, a union's members, boxes and
// meshes as triangles, a clipped mesh, placements of one compact mesh (the
// same shared level, opaque and glass), moving objects, and a no_shadow one.
Scene casters(bool withTransmitters) {
    const ColorFT see = withTransmitters ? kGlass : kOpaque;
    const ColorFT veil = withTransmitters ? kVeil : kOpaque;
    const auto sphere = test::sphereMesh(8, 16);
    std::vector<Object> objects;
    objects.push_back(withColor(makeObject(Sphere{{-3, 0, 0}, 0.8}), kOpaque));
    objects.push_back(withColor(makeObject(Sphere{{-1, 0, 0}, 0.8}), see));
    objects.push_back(withColor(makeObject(Torus{0.6, 0.2}, Transform::rotate({70, 0, 0}).then(Transform::translate({1, 0, 0}))), veil));
    Csg difference;
    difference.op = Csg::Op::Difference;
    difference.children = {withColor(makeObject(Box{{-0.7, -0.7, -0.7}, {0.7, 0.7, 0.7}}), kOpaque),
                           withColor(makeObject(Sphere{{0, 0, -0.7}, 0.5}), see)};
    objects.push_back(makeObject(difference, Transform::translate({3, 0, 0})));
    Csg union_;
    union_.children = {withColor(makeObject(Sphere{{0, 0, 0}, 0.5}), kOpaque),
                       withColor(makeObject(Sphere{{0, 1, 0}, 0.5}), see)};
    objects.push_back(makeObject(union_, Transform::translate({-3, 2.5, 0})));
    objects.push_back(withColor(makeObject(Box{{-0.6, -0.6, -0.6}, {0.6, 0.6, 0.6}}, Transform::translate({-1, 2.5, 0})), see));
    objects.push_back(withColor(makeObject(Box{{-0.6, -0.6, -0.6}, {0.6, 0.6, 0.6}}, Transform::translate({1, 2.5, 0})), kOpaque));
    Object clipped = withColor(makeObject(plainMesh(*sphere), Transform::scale(Vec3(0.7)).then(Transform::translate({3, 2.5, 0}))), veil);
    clipped.clippedBy.push_back(makeObject(Plane{{0, 1, 0}, 2.7})); // the top cut off
    objects.push_back(clipped);
    for (int i = 0; i < 4; ++i)
        objects.push_back(withColor(makeObject(compact(sphere), Transform::scale(Vec3(0.7)).then(Transform::translate({-3.0 + 2 * i, -2.5, 0}))),
                                    i % 2 ? see : kOpaque));
    Object movingGlass = withColor(makeObject(Sphere{{-2, 5, 0}, 0.6}), see);
    movingGlass.motion = {MotionStage{motionTo({1, 0, 0}), {}}};
    objects.push_back(movingGlass);
    Object movingBox = withColor(makeObject(Box{{-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}}, Transform::translate({1.5, 5, 0})), kOpaque);
    movingBox.motion = {MotionStage{motionTo({0.5, 0, 0}, {0, 40, 0}), {}}};
    objects.push_back(movingBox);
    Object shadowless = withColor(makeObject(Sphere{{0, -5, 0}, 0.8}), kOpaque);
    shadowless.noShadow = true;
    objects.push_back(shadowless);
    return sceneOf(std::move(objects));
}

// Which object judges a surface: a merge, difference or intersection is one
// primitive, which may let light through if any member may; a union's members
// and every other object are their own.
std::map<const Object*, const Object*> judges(const std::vector<Object>& objects) {
    std::map<const Object*, const Object*> by;
    const std::function<void(const Object&, const Object*)> visit = [&](const Object& object, const Object* root) {
        by[&object] = root ? root : &object;
        if (const auto* csg = std::get_if<Csg>(&object.shape))
            for (const Object& child : csg->children)
                visit(child, root ? root : (csg->op == Csg::Op::Union ? nullptr : &object));
    };
    for (const Object& object : objects) visit(object, nullptr);
    return by;
}

// The answer found surface by surface: every shadow-casting crossing of the
// segment, each judged by its object (judges).
Occlusion bySurfaces(const Accelerator& accel, const std::map<const Object*, const Object*>& judge, Ray ray) {
    Occlusion answer = Occlusion::Clear;
    const Vec3 end = ray.origin + ray.direction * ray.tMax;
    for (int crossed = 0; crossed < 100; ++crossed) {
        Hit hit;
        if (!accel.intersect(ray, hit)) return answer;
        if (!hit.object->noShadow) {
            if (!mayLetLightThrough(*judge.at(hit.object))) return Occlusion::Blocked;
            answer = Occlusion::ThroughTransmitters;
        }
        ray.origin = Accelerator::offsetOrigin(hit, ray.direction);
        ray.direction = end - ray.origin;
        ray.tMax = 1;
        ray.tMin = 0;
    }
    ADD_FAILURE() << "more than 100 crossings";
    return answer;
}

TEST(ShadowQuery, OneQueryTellsBlockersFromSurfacesThatLetLightThrough) {
    for (const bool withTransmitters : {true, false}) {
        const Scene scene = casters(withTransmitters);
        const Accelerator accel(scene);
        const auto judge = judges(scene.objects);
        std::mt19937 rng(withTransmitters ? 17 : 18);
        std::uniform_real_distribution<double> x(-4.5, 4.5), y(-6, 6.5), z(-2, 2), u(0, 1);
        int counts[3] = {0, 0, 0};
        int compared = 0;
        for (int i = 0; i < 6000; ++i) {
            Ray rays[Accelerator::kPacketSize];
            for (Ray& ray : rays) {
                ray.origin = {x(rng), y(rng), -6};
                ray.direction = Vec3{x(rng), y(rng), 6} - ray.origin;
                ray.tMin = 0;
                ray.tMax = u(rng) < 0.2 ? 0.5 : 1; // some stop at z = 0, inside the casters
                ray.time = u(rng);
            }
            Occlusion packet[Accelerator::kPacketSize];
            accel.occludedOpaquePacket(rays, Accelerator::kPacketSize, packet);
            for (int k = 0; k < Accelerator::kPacketSize; ++k, ++compared) {
                const Occlusion expected = bySurfaces(accel, judge, rays[k]);
                const Occlusion single = accel.occludedOpaque(rays[k]);
                ASSERT_EQ(single, expected) << "ray " << compared << " with transmitters " << withTransmitters;
                ASSERT_EQ(packet[k], expected) << "ray " << compared << " (packet)";
                ASSERT_EQ(accel.occluded(rays[k]), expected != Occlusion::Clear) << "ray " << compared;
                ++counts[int(expected)];
            }
        }
        // Each answer is given many times; without transmitters never the third.
        EXPECT_GT(counts[int(Occlusion::Clear)], 1000);
        EXPECT_GT(counts[int(Occlusion::Blocked)], 1000);
        if (withTransmitters) EXPECT_GT(counts[int(Occlusion::ThroughTransmitters)], 1000);
        else EXPECT_EQ(counts[int(Occlusion::ThroughTransmitters)], 0);
    }
}

// A surface that lets light through ahead of an opaque one on the same
// segment: the answer is the opaque one's, whichever Embree meets first.
TEST(ShadowQuery, AnOpaqueSurfaceBehindGlassBlocks) {
    const Scene scene = sceneOf({withColor(makeObject(Sphere{{0, 0, 0}, 1}), kGlass),
                                 withColor(makeObject(Box{{-1, -1, 3}, {1, 1, 4}}), kOpaque)});
    const Accelerator accel(scene);
    Ray ray;
    ray.origin = {0.2, 0.1, -5};
    ray.direction = {0, 0, 1};
    ray.tMax = 10;
    EXPECT_EQ(accel.occludedOpaque(ray), Occlusion::Blocked);
    ray.tMax = 7; // ends between the two
    EXPECT_EQ(accel.occludedOpaque(ray), Occlusion::ThroughTransmitters);
    ray.tMax = 3; // ends before both
    EXPECT_EQ(accel.occludedOpaque(ray), Occlusion::Clear);
}

} // namespace
} // namespace drt
