// Object bounds (scene/bounds.h) against exact boxes: shapes, transforms, CSG
// rules, clips, and the unbounded fallback.
#include "scene/bounds.h"

#include <gtest/gtest.h>

namespace drt {
namespace {

Object make(Shape shape, Transform transform = {}) {
    Object o;
    o.shape = std::move(shape);
    o.transform = transform;
    return o;
}

void expectBox(const Object& o, const Vec3& lower, const Vec3& upper) {
    Vec3 lo, hi;
    EXPECT_TRUE(objectBounds(o, lo, hi));
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(lo[i], lower[i], 1e-12) << i;
        EXPECT_NEAR(hi[i], upper[i], 1e-12) << i;
    }
}

TEST(Bounds, ShapesAndTransforms) {
    expectBox(make(Box{{4, 5, 6}, {1, 2, 3}}), {1, 2, 3}, {4, 5, 6});
    expectBox(make(Sphere{{1, 0, 0}, 2}, Transform::scale({1, 3, 1}).then(Transform::translate({0, 0, 5}))),
              {-1, -6, 3}, {3, 6, 7});
    // A box turned 90 degrees about z: x and y swap (x' = -y).
    expectBox(make(Box{{0, 0, 0}, {1, 2, 3}}, Transform::rotate({0, 0, 90})), {-2, 0, 0}, {0, 1, 3});
    expectBox(make(Torus{2, 0.5}), {-2.5, -0.5, -2.5}, {2.5, 0.5, 2.5});
    expectBox(make(Cylinder{{0, 0, 0}, {0, 4, 0}, 1, false}), {-1, -1, -1}, {1, 5, 1});
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {2, -1, 0}, {1, 3, 4}};
    mesh.triangles = {{0, 1, 2}};
    expectBox(make(mesh), {0, -1, 0}, {2, 3, 4});
}

TEST(Bounds, CsgFollowsPovRay) {
    const Object a = make(Box{{0, 0, 0}, {2, 2, 2}}), b = make(Sphere{{2, 2, 2}, 1});
    expectBox(make(Csg{Csg::Op::Union, {a, b}}), {0, 0, 0}, {3, 3, 3});
    expectBox(make(Csg{Csg::Op::Merge, {a, b}}), {0, 0, 0}, {3, 3, 3});
    expectBox(make(Csg{Csg::Op::Intersection, {a, b}}), {1, 1, 1}, {2, 2, 2});
    expectBox(make(Csg{Csg::Op::Difference, {a, b}}), {0, 0, 0}, {2, 2, 2});
    // Members' transforms are inside the CSG's, which applies last.
    expectBox(make(Csg{Csg::Op::Union, {make(Sphere{{0, 0, 0}, 1}, Transform::translate({3, 0, 0}))}},
                   Transform::scale({2, 2, 2})),
              {4, -2, -2}, {8, 2, 2});
    // An unbounded member: a union is unbounded, an intersection ignores it.
    const Object floor = make(Plane{{0, 1, 0}, 0});
    Vec3 lo, hi;
    EXPECT_FALSE(objectBounds(make(Csg{Csg::Op::Union, {a, floor}}), lo, hi));
    expectBox(make(Csg{Csg::Op::Intersection, {floor, a}}), {0, 0, 0}, {2, 2, 2});
}

TEST(Bounds, ClipsNarrowAndUnboundedIsHuge) {
    Object clippedPlane = make(Plane{{0, 1, 0}, 0});
    clippedPlane.clippedBy.push_back(make(Box{{-1, -1, -1}, {1, 1, 1}}));
    expectBox(clippedPlane, {-1, -1, -1}, {1, 1, 1});
    Object inverted = make(Sphere{{0, 0, 0}, 1});
    inverted.inverse = true;
    for (const Object& o : {make(Plane{{0, 1, 0}, 0}), inverted}) {
        Vec3 lo, hi;
        EXPECT_FALSE(objectBounds(o, lo, hi));
        EXPECT_EQ(lo, Vec3(-kUnboundedExtent));
        EXPECT_EQ(hi, Vec3(kUnboundedExtent));
    }
}

} // namespace
} // namespace drt
