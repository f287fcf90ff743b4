// The geometry behind POV-Ray's trace() and inside() at parse time
// (accel/geometry_query.h): answers, and what it keeps between questions.
#include "accel/geometry_query.h"

#include <gtest/gtest.h>

#include <memory>

namespace drt {
namespace {

Object sphereAt(const Vec3& centre, double radius) {
    Object o;
    o.shape = Sphere{centre, radius};
    return o;
}

// A question about a sphere whose `make` counts how often it is asked for the object.
QueriedObject counted(std::shared_ptr<const void> identity, Object object, int& made) {
    return {std::move(identity), [object, &made] {
                ++made;
                return object;
            }};
}

TEST(GeometryQuery, TraceAndInsideAnswerForTheObject) {
    const std::unique_ptr<SceneGeometryQuery> query = makeGeometryQuery();
    int made = 0;
    const QueriedObject ball = counted(std::make_shared<int>(1), sphereAt({0, 0, 5}, 1), made);
    const std::optional<SurfaceHit> hit = query->trace(ball, {0, 0, 0}, {0, 0, 1});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->point.z, 4, 1e-9);
    EXPECT_NEAR(hit->normal.z, -1, 1e-9);
    EXPECT_FALSE(query->trace(ball, {0, 0, 0}, {0, 1, 0}));
    EXPECT_TRUE(query->inside(ball, {0, 0, 5.5}));
    EXPECT_FALSE(query->inside(ball, {0, 0, 6.5}));
}

// A scene that traces one terrain from a loop (POV-Ray's advanced/landscape.pov:
// a 500 x 500 height_field, 625 times) builds the object, and its
// accelerator, once: it took minutes when every trace() built them anew.
TEST(GeometryQuery, AnObjectAskedAboutAgainIsBuiltOnce) {
    const std::unique_ptr<SceneGeometryQuery> query = makeGeometryQuery();
    int made = 0;
    const QueriedObject ball = counted(std::make_shared<int>(1), sphereAt({0, 0, 5}, 1), made);
    for (int i = 0; i < 100; ++i) {
        const std::optional<SurfaceHit> hit = query->trace(ball, {0.01 * i, 0, 0}, {0, 0, 1});
        ASSERT_TRUE(hit) << i;
        EXPECT_NEAR(hit->point.z, 5 - std::sqrt(1 - 0.0001 * i * i), 1e-9) << i;
        EXPECT_TRUE(query->inside(ball, {0, 0.01 * i, 5}));
    }
    EXPECT_EQ(made, 1);
}

// Another identity is another object, even one at the same address later
// (the query holds the identity, so its address cannot be reused meanwhile).
TEST(GeometryQuery, AnotherIdentityIsAnotherObject) {
    const std::unique_ptr<SceneGeometryQuery> query = makeGeometryQuery();
    int madeNear = 0, madeFar = 0;
    const QueriedObject near = counted(std::make_shared<int>(1), sphereAt({0, 0, 5}, 1), madeNear);
    const QueriedObject far = counted(std::make_shared<int>(2), sphereAt({0, 0, 50}, 1), madeFar);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(query->trace(near, {0, 0, 0}, {0, 0, 1})->point.z, 4, 1e-9);
        EXPECT_NEAR(query->trace(far, {0, 0, 0}, {0, 0, 1})->point.z, 49, 1e-9);
    }
    EXPECT_EQ(madeNear, 1);
    EXPECT_EQ(madeFar, 1);
}

// Without an identity nothing is kept: each question builds its object.
TEST(GeometryQuery, AnObjectWithoutIdentityIsBuiltForEachQuestion) {
    const std::unique_ptr<SceneGeometryQuery> query = makeGeometryQuery();
    int made = 0;
    const QueriedObject ball = counted(nullptr, sphereAt({0, 0, 5}, 1), made);
    for (int i = 0; i < 5; ++i) EXPECT_TRUE(query->trace(ball, {0, 0, 0}, {0, 0, 1}));
    EXPECT_EQ(made, 5);
}

// A bounded number of objects is kept (each may hold a large mesh's
// hierarchy): after many others, the first is built again, and still right.
TEST(GeometryQuery, OnlyTheLastFewObjectsAreKept) {
    const std::unique_ptr<SceneGeometryQuery> query = makeGeometryQuery();
    int madeFirst = 0, madeOthers = 0;
    const QueriedObject first = counted(std::make_shared<int>(0), sphereAt({0, 0, 5}, 1), madeFirst);
    EXPECT_TRUE(query->trace(first, {0, 0, 0}, {0, 0, 1}));
    for (int i = 1; i <= 20; ++i)
        EXPECT_TRUE(query->trace(counted(std::make_shared<int>(i), sphereAt({0, 0, 5.0 + i}, 1), madeOthers),
                                 {0, 0, 0}, {0, 0, 1}));
    EXPECT_EQ(madeOthers, 20);
    EXPECT_NEAR(query->trace(first, {0, 0, 0}, {0, 0, 1})->point.z, 4, 1e-9);
    EXPECT_EQ(madeFirst, 2);
}

} // namespace
} // namespace drt
