// clipped_by in the accelerator: hits on a clipped object only inside its
// clips, the open cut, shadows, clips on unions and CSG members, and bounds.
#include "accel/accel.h"
#include "render/render.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <optional>

namespace drt {
namespace {

using test::makeObject;
using test::buildAccelerator;
using test::sceneOf;
using test::trace;


void expectHit(const std::optional<Hit>& hit, double t, const Vec3& point, const Vec3& normal) {
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->t, t, 1e-9);
    EXPECT_NEAR(hit->point.x, point.x, 1e-9);
    EXPECT_NEAR(hit->point.y, point.y, 1e-9);
    EXPECT_NEAR(hit->point.z, point.z, 1e-9);
    EXPECT_NEAR(hit->geometricNormal.x, normal.x, 1e-9);
    EXPECT_NEAR(hit->geometricNormal.y, normal.y, 1e-9);
    EXPECT_NEAR(hit->geometricNormal.z, normal.z, 1e-9);
}

// The unit sphere keeping only its x < 0 half (the box -2 < x < 0).
Object leftHalfSphere(Transform transform = {}) {
    Object sphere = makeObject(Sphere{{0, 0, 0}, 1}, transform);
    sphere.clippedBy.push_back(makeObject(Box{{-2, -2, -2}, {0, 2, 2}}));
    return sphere;
}

TEST(Clip, SphereClippedByBoxHitsOnlyInsideTheBox) {
    const Scene accelScene = sceneOf({leftHalfSphere()});
    Accelerator accel(accelScene);
    // From -x: the kept half's outside at x = -1.
    expectHit(trace(accel, {-5, 0, 0}, {1, 0, 0}), 4, {-1, 0, 0}, {-1, 0, 0});
    // Straight down at x = -0.6: the top at y = 0.8.
    expectHit(trace(accel, {-0.6, 5, 0}, {0, -1, 0}), 5 - 0.8, {-0.6, 0.8, 0}, {-0.6, 0.8, 0});
    // Straight down at x = 0.6: both crossings are outside the box.
    EXPECT_FALSE(trace(accel, {0.6, 5, 0}, {0, -1, 0}));
    // From +x through the open cut (no surface at x = 0): the inner back surface at x = -1.
    expectHit(trace(accel, {5, 0, 0}, {-1, 0, 0}), 6, {-1, 0, 0}, {-1, 0, 0});
    // A clipped object's every hit is inside the clip: a fan of rays.
    for (int i = -20; i <= 20; ++i) {
        const auto hit = trace(accel, {0, 0, -5}, {i / 20.0, 0.3, 5});
        if (hit) {
            EXPECT_LE(hit->point.x, 1e-12) << i;
        }
    }
}

TEST(Clip, ClippedBoxAndPlaneAreFilteredAndBounded) {
    // A box cut by a sphere: only its parts inside the sphere remain.
    Object box = makeObject(Box{{-1, -1, -1}, {1, 1, 1}});
    box.clippedBy.push_back(makeObject(Sphere{{0, 0, 0}, 1.2}));
    // A plane y = 0 clipped to a 2 x 2 square at y = 10 (after a translate).
    Object floor = makeObject(Plane{{0, 1, 0}, 0}, Transform::translate({0, 10, 0}));
    floor.clippedBy.push_back(makeObject(Box{{-1, 9, -1}, {1, 11, 1}}));
    const Scene accelScene = sceneOf({box, floor});
    Accelerator accel(accelScene);
    expectHit(trace(accel, {0, 0, -5}, {0, 0, 1}), 4, {0, 0, -1}, {0, 0, -1});
    // At x = y = 0.9 both faces (z = -1 and z = 1) are 1.62 from the centre: outside the clip.
    EXPECT_FALSE(trace(accel, {0.9, 0.9, -5}, {0, 0, 1}));
    expectHit(trace(accel, {0.5, 20, 0.5}, {0, -1, 0}), 10, {0.5, 10, 0.5}, {0, 1, 0});
    EXPECT_FALSE(trace(accel, {3, 20, 0}, {0, -1, 0}));
    // The clipped plane is bounded by its clip box; the box's bounds are its
    // own (narrower than the sphere's): the scene spans y -1..11, x -1..1.
    Vec3 lower, upper;
    accel.bounds(lower, upper);
    EXPECT_EQ(lower, Vec3(-1, -1, -1));
    EXPECT_EQ(upper, Vec3(1, 11, 1));
}

TEST(Clip, ShadowRaysSeeOnlyTheKeptSurface) {
    const Scene accelScene = sceneOf({leftHalfSphere()});
    Accelerator accel(accelScene);
    Ray ray;
    ray.direction = {0, -1, 0};
    ray.tMax = 10;
    ray.origin = {-0.5, 5, 0};
    EXPECT_TRUE(accel.occluded(ray));
    ray.origin = {0.5, 5, 0};
    EXPECT_FALSE(accel.occluded(ray));
}

TEST(Clip, ClipMovesWithTheObjectsParentSpace) {
    // The clip lives in the object's parent space: the sphere's transform
    // (translate x = 1) does not move the box, so the sphere, now spanning
    // 0 < x < 2, lies wholly outside the box (x < 0) and nothing is left.
    const Scene movedScene = sceneOf({leftHalfSphere(Transform::translate({1, 0, 0}))});
    Accelerator moved(movedScene);
    EXPECT_FALSE(trace(moved, {-5, 0, 0}, {1, 0, 0}));
    EXPECT_FALSE(trace(moved, {1, 5, 0}, {0, -1, 0}));
}

TEST(Clip, UnionClipAppliesToEveryMember) {
    Csg csg{Csg::Op::Union, {makeObject(Sphere{{0, 0, 0}, 1}), makeObject(Sphere{{0, 5, 0}, 1})}};
    Object both = makeObject(csg, Transform::translate({0, 0, 10}));
    both.clippedBy.push_back(makeObject(Box{{-2, -2, 8}, {0, 8, 12}}));
    const Scene accelScene = sceneOf({both});
    Accelerator accel(accelScene);
    for (double y : {0.0, 5.0}) {
        expectHit(trace(accel, {-0.6, y, 0}, {0, 0, 1}), 10 - 0.8, {-0.6, y, 9.2}, {-0.6, 0, -0.8});
        EXPECT_FALSE(trace(accel, {0.6, y, 0}, {0, 0, 1}));
    }
}

TEST(Clip, ClippedMemberOfAnIntersectionLeavesItOpen) {
    // intersection { sphere clipped to x < 0, big box }: the inside is the
    // half ball, but the cut at x = 0 has no surface (it belongs to the clip).
    Object half = leftHalfSphere();
    Csg csg{Csg::Op::Intersection, {half, makeObject(Box{{-3, -3, -3}, {3, 3, 3}})}};
    const Scene accelScene = sceneOf({makeObject(csg)});
    Accelerator accel(accelScene);
    expectHit(trace(accel, {5, 0, 0}, {-1, 0, 0}), 6, {-1, 0, 0}, {-1, 0, 0});
    expectHit(trace(accel, {-5, 0, 0}, {1, 0, 0}), 4, {-1, 0, 0}, {-1, 0, 0});
    EXPECT_FALSE(trace(accel, {0.6, 5, 0}, {0, -1, 0}));
}

TEST(Clip, InvertedMemberOfAnIntersectionIsAShell) {
    // intersection { sphere 1, sphere 0.5 inverse }: a hollow ball. The
    // inverted member's inside is the outside of the small sphere.
    Object hole = makeObject(Sphere{{0, 0, 0}, 0.5});
    hole.inverse = true;
    Csg csg{Csg::Op::Intersection, {makeObject(Sphere{{0, 0, 0}, 1}), hole}};
    const Scene accelScene = sceneOf({makeObject(csg)});
    Accelerator accel(accelScene);
    expectHit(trace(accel, {-5, 0, 0}, {1, 0, 0}), 4, {-1, 0, 0}, {-1, 0, 0});
    // From the centre (outside the shell): the inner wall, facing the centre.
    expectHit(trace(accel, {0, 0, 0}, {1, 0, 0}), 0.5, {0.5, 0, 0}, {-1, 0, 0});
}

TEST(Clip, ClippedMeshIsFilteredAndCastsShadowsOnlyWhereKept) {
    Mesh mesh;
    mesh.vertices = {{-2, -2, 0}, {2, -2, 0}, {0, 2, 0}};
    mesh.triangles = {{0, 1, 2}};
    Object tri = makeObject(mesh);
    tri.clippedBy.push_back(makeObject(Sphere{{0, 0, 0}, 1}));
    // The same triangle unclipped at z = 1, behind it: seen through the cut.
    const Scene scene = sceneOf({tri, makeObject(mesh, Transform::translate({0, 0, 1}))});
    Accelerator accel(scene);
    auto inside = trace(accel, {0, 0.5, -5}, {0, 0, 1});
    ASSERT_TRUE(inside);
    EXPECT_NEAR(inside->t, 5, 1e-9);
    EXPECT_EQ(inside->object, &scene.objects[0]);
    auto cut = trace(accel, {0, 1.5, -5}, {0, 0, 1}); // in the triangle, outside the sphere
    ASSERT_TRUE(cut);
    EXPECT_NEAR(cut->t, 6, 1e-9);
    EXPECT_EQ(cut->object, &scene.objects[1]);
    Ray shadow;
    shadow.direction = {0, 0, 1};
    shadow.tMax = 5.5; // stops before the back triangle
    shadow.origin = {0, 0.5, -5};
    EXPECT_TRUE(accel.occluded(shadow));
    shadow.origin = {0, 1.5, -5};
    EXPECT_FALSE(accel.occluded(shadow));
}

TEST(Clip, MovingClippedMeshIsARenderError) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 2}};
    Object tri = makeObject(mesh);
    tri.clippedBy.push_back(makeObject(Sphere{{0, 0, 0}, 1}));
    tri.motion = {MotionStage{motionTo({1, 0, 0}), {}}};
    EXPECT_THROW(buildAccelerator(sceneOf({tri})), RenderError);
}

} // namespace
} // namespace drt
