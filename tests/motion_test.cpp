// Motion as a transform over time (scene/motion.h) and its Embree form
// (accel/motion.h): keyed paths, pivots, the affine decomposition, and moving
// objects hit where the exact path puts them at each ray's time.
#include "accel/accel.h"
#include "accel/motion.h"
#include "scene/motion.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <fmt/format.h>

#include <cmath>
#include <random>

namespace drt {
namespace {

using test::makeObject;
using test::sceneOf;

void expectNear(const Vec3& a, const Vec3& b, double tolerance = 1e-9) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

void expectSameTransform(const Transform& a, const Transform& b, double tolerance = 1e-9) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_NEAR(a.matrix().m[i][j], b.matrix().m[i][j], tolerance) << i << "," << j;
}

MotionChain chainOf(Motion m, Transform after = {}) { return {MotionStage{std::move(m), after}}; }

// ---------------------------------------------------------------- keyed paths

TEST(Motion, KeysInterpolateEachComponentLinearly) {
    Motion m;
    m.keys = {MotionKey{0}, MotionKey{0.25, {1, 0, 0}, {0, 90, 0}, {1, 1, 1}},
              MotionKey{1, {1, 2, 0}, {0, 720, 0}, {2, 2, 2}}};
    expectSameTransform(m.at(0), Transform());
    expectSameTransform(m.at(-1), Transform()); // holds before the first key
    expectSameTransform(m.at(0.125), Transform::rotate({0, 45, 0}).then(Transform::translate({0.5, 0, 0})));
    // Angles, not matrices: from 90 to 720 degrees is 630 degrees of turning.
    const double s = (0.625 - 0.25) / 0.75;
    expectSameTransform(m.at(0.625), Transform::scale(Vec3(1 + s))
                                         .then(Transform::rotate({0, 90 + 630 * s, 0}))
                                         .then(Transform::translate({1, 2 * s, 0})));
    expectSameTransform(m.at(1), m.at(7)); // holds after the last key
    // A key's transform is exact at its time (the same arithmetic as writing it).
    EXPECT_EQ(m.at(0.25).matrix(), Transform::scale({1, 1, 1})
                                       .then(Transform::rotate({0, 90, 0}))
                                       .then(Transform::translate({1, 0, 0}))
                                       .matrix());
}

TEST(Motion, SplinePassesThroughTheKeysSmoothly) {
    Motion m;
    m.spline = true;
    m.keys = {MotionKey{0}, MotionKey{0.5, {1, 1, 0}}, MotionKey{1, {2, 0, 0}}};
    expectNear(m.at(0.5).point({0, 0, 0}), {1, 1, 0});
    expectNear(m.at(1).point({0, 0, 0}), {2, 0, 0});
    // The middle key's slope is (2 - 0) / 1 in x and 0 in y: the path is
    // level there, and rises on both sides of it.
    const Vec3 before = m.at(0.49).point({0, 0, 0}), after = m.at(0.51).point({0, 0, 0});
    EXPECT_NEAR((after.y - before.y) / 0.02, 0, 1e-3);
    EXPECT_NEAR((after.x - before.x) / 0.02, 2, 1e-3);
    EXPECT_LT(before.y, 1);
    EXPECT_LT(after.y, 1);
    // Linear keys would cut the corner's chord: the spline passes above it at t = 0.25.
    m.spline = false;
    const double chord = m.at(0.25).point({0, 0, 0}).y;
    m.spline = true;
    EXPECT_GT(m.at(0.25).point({0, 0, 0}).y, chord);
}

TEST(Motion, PlacementChainsStandWhereTheyAreWritten) {
    // translate -c, spin, translate c: the centre stays, a rim point turns about it.
    const Vec3 c{3, 1, -2};
    MotionChain chain = chainOf(motionTo({}, {0, 360, 0}), Transform::translate(c));
    const Transform before = Transform::translate(-c);
    for (double t : {0.0, 0.1, 0.5, 0.9, 1.0}) {
        const Transform at = placementAt(before, chain, t);
        expectNear(at.point(c), c);
        expectNear(at.point(c + Vec3{1, 0, 0}), c + Transform::rotate({0, 360 * t, 0}).point({1, 0, 0}));
    }
    expectSameTransform(restPlacement(before, chain), Transform());
    // Appending an outer placement (a moving union around it).
    Transform inner = Transform::scale(Vec3(2));
    MotionChain innerChain;
    appendPlacement(inner, innerChain, Transform::translate({1, 0, 0}), chainOf(motionTo({0, 5, 0})));
    expectNear(placementAt(inner, innerChain, 0.5).point({1, 1, 1}), {3, 4.5, 2});
}

// ---------------------------------------------------------------- affine parts

TEST(Motion, AffinePartsRebuildTheTransform) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-2, 2);
    for (int i = 0; i < 200; ++i) {
        Transform a = Transform::scale({u(rng), u(rng), u(rng)})
                          .then(Transform::rotate({90 * u(rng), 90 * u(rng), 90 * u(rng)}))
                          .then(Transform::translate({u(rng), u(rng), u(rng)}));
        if (i % 3 == 0) a = Transform::fromPovMatrix({1, u(rng), 0, 0, 1, u(rng), u(rng), 0, 1, 0, 0, 0})->then(a);
        const Vec3 pivot{u(rng), u(rng), u(rng)};
        const AffineParts parts = decomposeAbout(a, pivot);
        expectSameTransform(composeParts(parts), a, 1e-9);
        expectNear(parts.translation, a.point(pivot), 1e-12); // the pivot's image
        EXPECT_NEAR(std::hypot(std::hypot(parts.rotation[0], parts.rotation[1]),
                               std::hypot(parts.rotation[2], parts.rotation[3])),
                    1, 1e-12);
    }
}

// composeParts writes the inverse in closed form; it must be the inverse the
// general elimination finds, for scales, skews, mirrors and interpolated steps.
TEST(Motion, ComposedPartsCarryTheirExactInverse) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-2, 2);
    for (int i = 0; i < 200; ++i) {
        Transform a = Transform::scale({u(rng), u(rng), u(rng)})
                          .then(Transform::rotate({180 * u(rng), 180 * u(rng), 180 * u(rng)}))
                          .then(Transform::translate({u(rng), u(rng), u(rng)}));
        if (i % 2 == 0) a = Transform::fromPovMatrix({1, u(rng), 0, 0, 1, u(rng), u(rng), 0, 1, 0, 0, 0})->then(a);
        const Transform b = Transform::rotate({90 * u(rng), 0, 0}).then(a);
        const Vec3 pivot{u(rng), u(rng), u(rng)};
        AffineParts first = decomposeAbout(a, pivot), last = decomposeAbout(b, pivot);
        alignRotation(first, last);
        const Transform composed = composeParts(interpolateParts(first, last, (i % 7) / 6.0));
        const std::optional<Mat4> general = inverse(composed.matrix());
        ASSERT_TRUE(general.has_value());
        double scale = 0;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 4; ++c) scale = std::max(scale, std::fabs((*general).m[r][c]));
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c)
                EXPECT_NEAR(composed.inverseMatrix().m[r][c], (*general).m[r][c], 1e-12 * scale) << i << ": " << r << "," << c;
    }
    AffineParts flat;
    flat.upper[3] = 0; // a scale through zero has no inverse: the identity stands in
    EXPECT_TRUE(composeParts(flat).isIdentity());
}

TEST(Motion, InterpolationAboutThePivotFollowsTheArc) {
    // A rotation by 80 degrees about the axis through c: interpolated about c
    // it is exact at every fraction; about another point it cuts the chord.
    const Vec3 c{2, 0, 1};
    const auto spin = [&](double degrees) {
        return Transform::translate(-c).then(Transform::rotate({0, degrees, 0})).then(Transform::translate(c));
    };
    const AffineParts a = decomposeAbout(spin(0), c), b = decomposeAbout(spin(80), c);
    for (double s : {0.25, 0.5, 0.75}) expectSameTransform(composeParts(interpolateParts(a, b, s)), spin(80 * s), 1e-12);
    const AffineParts a0 = decomposeAbout(spin(0), {}), b0 = decomposeAbout(spin(80), {});
    EXPECT_GT(length(composeParts(interpolateParts(a0, b0, 0.5)).point(c + Vec3{1, 0, 0}) -
                     spin(40).point(c + Vec3{1, 0, 0})),
              0.1);
    EXPECT_NEAR(rotationBetween(a, b), 80, 1e-9);
}

TEST(Motion, BestPivotFindsTheAxisOfATurn) {
    const Vec3 c{-1, 4, 2};
    const auto turn = [&](double degrees) {
        return Transform::translate(-c).then(Transform::rotate({0, 0, degrees})).then(Transform::translate(c));
    };
    // Fallback near the axis: the pivot lands on the axis (the z line through c).
    const Vec3 p = bestPivot({{turn(0), turn(30), turn(60), 0.5}, {turn(60), turn(90), turn(120), 0.5}}, {0, 0, 7});
    EXPECT_NEAR(p.x, c.x, 1e-6);
    EXPECT_NEAR(p.y, c.y, 1e-6);
    EXPECT_NEAR(p.z, 7, 1e-3); // free along the axis: kept at the fallback's z
    // A rolling wheel (turning about its centre while the centre moves on a
    // line) pivots on its centre, whose path is straight.
    const auto roll = [&](double t) {
        return Transform::translate(-c).then(Transform::rotate({0, 0, -360 * t})).then(Transform::translate(c + Vec3{6.28 * t, 0, 0}));
    };
    const Vec3 q = bestPivot({{roll(0), roll(0.1), roll(0.2), 0.5}, {roll(0.2), roll(0.3), roll(0.4), 0.5}}, {0, 0, 0});
    EXPECT_NEAR(q.x, c.x, 1e-6);
    EXPECT_NEAR(q.y, c.y, 1e-6);
    // Nothing turns: the fallback.
    expectNear(bestPivot({{Transform(), Transform::translate({1, 0, 0}), Transform::translate({2, 0, 0}), 0.5}}, {5, 5, 5}),
               {5, 5, 5});
}

TEST(Motion, SampledPathsInterpolateAboutTheirStraightestPoint) {
    // Samples of an orbit of radius 3 about the y axis, 40 degrees apart.
    std::vector<double> times;
    std::vector<Transform> samples;
    for (int k = 0; k <= 4; ++k) {
        times.push_back(k * 0.25);
        samples.push_back(Transform::rotate({0, 40.0 * k, 0}));
    }
    const Motion m = sampledMotion(times, samples, {3, 0, 0});
    EXPECT_NEAR(m.pivot.x, 0, 1e-6);
    EXPECT_NEAR(m.pivot.z, 0, 1e-6);
    expectNear(m.at(0.125).point({3, 0, 0}), Transform::rotate({0, 20, 0}).point({3, 0, 0}), 1e-9);
    expectSameTransform(m.at(0.5), samples[2]);
    expectSameTransform(m.at(-1), samples[0]);
}

// ---------------------------------------------------------------- Embree steps

TEST(InstanceMotion, StepsAlignWithKeysAndTurnAtMost90Degrees) {
    const Vec3 lo{-1, -1, -1}, hi{1, 1, 1};
    EXPECT_EQ(accel::InstanceMotion(Transform(), chainOf(motionTo({5, 0, 0})), lo, hi).timeStepCount(), 2);
    // 720 degrees: at least 8 steps of 90.
    EXPECT_GE(accel::InstanceMotion(Transform(), chainOf(motionTo({}, {0, 720, 0})), lo, hi).timeStepCount(), 9);
    // A key at 0.25 lies on a step.
    Motion keyed;
    keyed.keys = {MotionKey{0}, MotionKey{0.25, {1, 0, 0}}, MotionKey{1, {1, 3, 0}}};
    const int steps = accel::InstanceMotion(Transform(), chainOf(keyed), lo, hi).timeStepCount() - 1;
    EXPECT_EQ(steps % 4, 0);
    // A piecewise-linear path with steps on its keys is followed exactly.
    const accel::InstanceMotion path(Transform(), chainOf(keyed), lo, hi);
    for (double t : {0.1, 0.25, 0.4, 0.9}) expectNear(path.at(t).point({0.5, 0.5, 0.5}), keyed.at(t).point({0.5, 0.5, 0.5}), 1e-12);
}

TEST(InstanceMotion, PivotedSpinsAndOrbitsAreExact) {
    const Vec3 c{3, 1, -2};
    // Spin about the object's own centre, 360 degrees.
    const accel::InstanceMotion spin(Transform::translate(-c), chainOf(motionTo({}, {0, 0, 360}), Transform::translate(c)),
                                     c - Vec3(0.5), c + Vec3(0.5));
    expectNear(spin.pivot(), c, 1e-6);
    // Orbit: the object at radius 3 about the origin.
    const accel::InstanceMotion orbit(Transform::translate({3, 0, 0}), chainOf(motionTo({}, {0, 270, 0})),
                                      {2.5, -0.5, -0.5}, {3.5, 0.5, 0.5});
    for (int i = 0; i <= 40; ++i) {
        const double t = i / 40.0;
        const Transform exactSpin = Transform::translate(-c).then(Transform::rotate({0, 0, 360 * t})).then(Transform::translate(c));
        expectNear(spin.at(t).point(c + Vec3{0.5, 0.5, 0}), exactSpin.point(c + Vec3{0.5, 0.5, 0}), 1e-9);
        expectNear(orbit.at(t).point({3.5, 0, 0}), Transform::rotate({0, 270 * t, 0}).point({3.5, 0, 0}), 1e-9);
    }
}

// A motion that only translates (whatever the object's own rotation and
// scale) is handed to Embree as matrices, which it interpolates linearly: the
// same motion, cheaper per ray than its quaternion steps. Each step's rows are
// the exact path at the step's time, in the frame's coordinates; a motion
// that turns or scales keeps its quaternion steps.
TEST(InstanceMotion, TranslationsAloneAreLinearMatrixSteps) {
    const Vec3 lo{-1, -1, -1}, hi{1, 1, 1};
    const Transform rest = Transform::scale({1, 2, 0.5}).then(Transform::rotate({30, -20, 10}));
    Motion keyed; // a piecewise-linear translation with a key inside the shutter
    keyed.keys = {MotionKey{0}, MotionKey{0.3, {1, 2, 0}}, MotionKey{1, {-1, 3, 4}}};
    for (const Motion& m : {motionTo({5, 0, -2}), keyed}) {
        const accel::InstanceMotion path(rest, chainOf(m), lo, hi);
        ASSERT_TRUE(path.translationOnly());
        const int steps = path.timeStepCount();
        for (const Vec3 f : {Vec3{}, Vec3{5e4, -2e3, 1e4}}) // the frame origin of a far scene
            for (int i = 0; i < steps; ++i) {
                float rows[12];
                path.stepRows(i, f, rows);
                const Transform exact = path.at(double(i) / (steps - 1));
                for (const Vec3 x : {Vec3{0.5, -0.25, 1}, Vec3{-1, 1, 0}}) { // rest-world points
                    const Vec3 level = x - f; // what Embree's rows take, and give back minus f
                    const Vec3 mapped{rows[0] * level.x + rows[1] * level.y + rows[2] * level.z + rows[3],
                                      rows[4] * level.x + rows[5] * level.y + rows[6] * level.z + rows[7],
                                      rows[8] * level.x + rows[9] * level.y + rows[10] * level.z + rows[11]};
                    expectNear(mapped + f, exact.point(x), 1e-6 * (1 + length(f)));
                }
            }
    }
    EXPECT_FALSE(accel::InstanceMotion(rest, chainOf(motionTo({1, 0, 0}, {0, 90, 0})), lo, hi).translationOnly());
    Motion grows; // a scale between the keys
    grows.keys = {MotionKey{0}, MotionKey{1, {}, {}, {2, 2, 2}}};
    EXPECT_FALSE(accel::InstanceMotion(rest, chainOf(grows), lo, hi).translationOnly());
}

TEST(InstanceMotion, CurvedPathsStayWithinTheTolerance) {
    // A spline translation with a multi-axis turn: not representable exactly,
    // so steps are added until the midpoints are within 1e-4 of the size.
    Motion m;
    m.spline = true;
    m.keys = {MotionKey{0}, MotionKey{0.5, {1, 1, 0}, {30, 60, 0}}, MotionKey{1, {2, 0, 0.5}, {0, 120, 45}}};
    const accel::InstanceMotion path(Transform(), chainOf(m), {-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5});
    double worst = 0;
    for (int i = 0; i <= 997; ++i) {
        const double t = i / 997.0;
        worst = std::max(worst, length(path.at(t).point({0.5, 0.5, 0.5}) - m.at(t).point({0.5, 0.5, 0.5})));
    }
    EXPECT_LT(worst, 2e-4 * std::sqrt(3.0));
    EXPECT_GT(path.timeStepCount(), 9);
}

// ---------------------------------------------------------------- traced

Ray rayAt(const Vec3& origin, const Vec3& direction, double time) {
    Ray r;
    r.origin = origin;
    r.direction = direction;
    r.time = time;
    return r;
}

// The same objects placed still at `time` (placementAt), with no motion.
Scene stillAt(const Scene& moving, double time) {
    Scene still = moving;
    for (Object& o : still.objects) {
        o.transform = placementAt(o.transform, o.motion, time);
        o.motion.clear();
    }
    return still;
}

// Random rays at `time` through the objects' box at that time: the moving scene answers as
// the still scene at that time (hit or miss, distance within `tolerance`,
// normal), but for rays grazing a silhouette within Embree's float precision
// (or, for paths Embree's steps only approximate, within their 1e-4 of the size).
void expectTracesAsStillAt(const Scene& moving, double time, int seed, double tolerance = 1e-5) {
    const Scene stillScene = stillAt(moving, time);
    const Accelerator interpolated(moving), still(stillScene);
    Vec3 lower, upper; // where the objects are at `time`
    still.bounds(lower, upper);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    int hits = 0, disagreements = 0;
    for (int i = 0; i < 4000; ++i) {
        const Vec3 target{lower.x + (upper.x - lower.x) * u(rng), lower.y + (upper.y - lower.y) * u(rng),
                          lower.z + (upper.z - lower.z) * u(rng)};
        const Vec3 origin = target + Vec3{0.3, 0.4, -10};
        const Ray ray = rayAt(origin, target - origin, time);
        Hit a, b;
        const bool ha = interpolated.intersect(ray, a), hb = still.intersect(ray, b);
        if (ha != hb) {
            ++disagreements;
            continue;
        }
        if (!ha) continue;
        ++hits;
        EXPECT_NEAR(a.t, b.t, tolerance) << i;
        expectNear(a.geometricNormal, b.geometricNormal, std::max(1e-4, 10 * tolerance));
    }
    EXPECT_GT(hits, 1000);
    EXPECT_LE(disagreements, 4) << "of 4000 rays";
}

TEST(MovingObjects, SpinAboutTheirOwnCentreAtEveryTime) {
    const Vec3 c{-1.5, 0.5, 0};
    std::vector<Object> objects = {makeObject(Box{c - Vec3{0.8, 0.3, 0.3}, c + Vec3{0.8, 0.3, 0.3}}),
                                   makeObject(Cylinder{c + Vec3{2.5, -0.5, 0}, c + Vec3{2.5, 0.5, 0}, 0.4})};
    objects[0].transform = Transform::translate(-c);
    objects[0].motion = chainOf(motionTo({}, {0, 0, 360}), Transform::translate(c));
    const Vec3 d = c + Vec3{2.5, 0, 0};
    objects[1].transform = Transform::translate(-d);
    objects[1].motion = chainOf(motionTo({}, {0, 0, -540}), Transform::translate(d));
    const Scene scene = sceneOf(objects);
    for (double t : {0.0, 0.13, 0.37, 0.5, 0.81, 1.0})
        expectTracesAsStillAt(scene, t, int(t * 100));
}

TEST(MovingObjects, OrbitsFollowTheirArcAtEveryTime) {
    Object ball = makeObject(Sphere{{0, 0, 0}, 0.5}, Transform::translate({2, 0, 0}));
    ball.motion = chainOf(motionTo({}, {0, 0, 300}));
    const Scene scene = sceneOf({ball});
    for (double t : {0.05, 0.3, 0.4, 0.66, 0.95}) expectTracesAsStillAt(scene, t, int(t * 1000));
}

TEST(MovingObjects, CurvedKeysAtEveryTime) {
    Motion curved;
    curved.spline = true;
    curved.keys = {MotionKey{0}, MotionKey{0.4, {1, 1, 0}, {0, 0, 90}}, MotionKey{1, {2, -1, 0}, {0, 0, 200}, {1.5, 1, 1}}};
    Object bar = makeObject(Box{{-0.6, -0.2, -0.2}, {0.6, 0.2, 0.2}}, Transform::translate({-1, -1, 0}));
    bar.motion = chainOf(curved);
    const Scene scene = sceneOf({bar});
    for (double t : {0.05, 0.3, 0.4, 0.66, 0.95})
        expectTracesAsStillAt(scene, t, int(t * 1000), 3e-4);
}

TEST(MovingObjects, MembersOfTransformedUnionsMoveInTheUnionsSpace) {
    // A union as the POV-Ray front end keeps it: the members inside, the
    // union's transform on the union. One member turns within it.
    Object still = makeObject(Sphere{{-1, 0, 0}, 0.4});
    Object turning = makeObject(Box{{0.5, -0.2, -0.2}, {1.5, 0.2, 0.2}});
    turning.motion = chainOf(motionTo({}, {0, 0, 90}));
    Csg csg;
    csg.children = {still, turning};
    Object group = makeObject(std::move(csg), Transform::scale(Vec3(1.5)).then(Transform::translate({0, 1, 0})));
    Object groupMoving = group;
    groupMoving.motion = chainOf(motionTo({1, 0, 0}));
    for (const Object& g : {group, groupMoving}) {
        const Scene scene = sceneOf({g});
        const Accelerator accel(scene);
        for (double t : {0.0, 0.5, 1.0}) {
            // The exact place of the turning bar's tip at time t.
            const Transform outer = placementAt(g.transform, g.motion, t);
            const Vec3 tip = outer.point(Transform::rotate({0, 0, 90 * t}).point({1.4, 0, 0}));
            Hit hit;
            ASSERT_TRUE(accel.intersect(rayAt(tip + Vec3{0, 0, -5}, {0, 0, 1}, t), hit)) << t;
            EXPECT_EQ(hit.object, &std::get<Csg>(scene.objects[0].shape).children[1]);
            EXPECT_NEAR(hit.point.z, -0.2 * 1.5, 1e-5);
            // The still member stays where the union puts it.
            ASSERT_TRUE(accel.intersect(rayAt(outer.point({-1, 0, 0}) + Vec3{0, 0, -5}, {0, 0, 1}, t), hit));
            EXPECT_EQ(hit.object, &std::get<Csg>(scene.objects[0].shape).children[0]);
        }
    }
}

// Every kind of shape moving by translation alone (Embree's linear matrix
// steps), with its own rotation and scale, near the origin and far from it:
// hit where the still placement at the ray's time puts it.
TEST(MovingObjects, EveryShapeKindTranslates) {
    std::vector<Object> kinds = {
        makeObject(Sphere{{0, 0, 0}, 0.5}),        makeObject(Box{{-0.4, -0.4, -0.4}, {0.4, 0.4, 0.4}}),
        makeObject(Cylinder{{0, -0.4, 0}, {0, 0.4, 0}, 0.4}), makeObject(Torus{0.4, 0.1}),
        makeObject(Mesh{nullptr, {{-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0, 0.5, 0}}, {{0, 1, 2}}, {}, {}, {}, {}, {}})};
    for (const double far : {0.0, 2e4})
        for (size_t i = 0; i < kinds.size(); ++i) {
            Object o = kinds[i];
            o.transform = o.transform.then(Transform::scale({1, 1.5, 1}))
                              .then(Transform::rotate({-20, 10, 0}))
                              .then(Transform::translate({1.5 + far, 0, 0}));
            o.motion = chainOf(motionTo({0.8, 0.3, -0.1}));
            for (const double time : {0.0, 0.35, 1.0}) expectTracesAsStillAt(sceneOf({o}), time, int(i));
        }
}

TEST(MovingObjects, EveryShapeKindMoves) {
    // Each kind alone, moving on a quarter orbit: hit where the still placement is.
    std::vector<Object> kinds = {
        makeObject(Sphere{{0, 0, 0}, 0.5}),        makeObject(Box{{-0.4, -0.4, -0.4}, {0.4, 0.4, 0.4}}),
        makeObject(Cylinder{{0, -0.4, 0}, {0, 0.4, 0}, 0.4}), makeObject(Cone{{0, -0.4, 0}, 0.5, {0, 0.4, 0}, 0.1}),
        makeObject(Disc{{0, 0, 0}, {0, 0, 1}, 0.5}), makeObject(Torus{0.4, 0.1}),
        makeObject(Mesh{nullptr, {{-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0, 0.5, 0}}, {{0, 1, 2}}, {}, {}, {}, {}, {}})};
    Csg difference;
    difference.op = Csg::Op::Difference;
    difference.children = {makeObject(Sphere{{0, 0, 0}, 0.5}), makeObject(Sphere{{0, 0, -0.5}, 0.3})};
    kinds.push_back(makeObject(std::move(difference)));
    for (size_t i = 0; i < kinds.size(); ++i) {
        Object o = kinds[i];
        o.transform = o.transform.then(Transform::rotate({-20, 10, 0})).then(Transform::translate({1.5, 0, 0}));
        o.motion = chainOf(motionTo({0, 0.3, 0}, {0, 0, 90}));
        expectTracesAsStillAt(sceneOf({o}), 0.6, int(i));
    }
}

// A scene with one moving object gives it a mask bit of its own, and a ray
// carries it only where its segment may meet the box the object sweeps over
// the shutter (Embree tests no bounds above a level of one primitive).
// Skipping must never lose a hit or a shadow: every query (one ray or a
// packet, intersect or occluded) answers as the still scene at the ray's time,
// for an object that translates, orbits a far pivot, shrinks, or is a triangle
// placed by Embree's own transform, near the origin and far from it (a shifted
// frame); and the same with two to eight moving objects (one casting no
// shadow), which take Embree's culling alone.
TEST(MovingObjects, RaysSkipOnlyTheMovingObjectsTheyCannotMeet) {
    // Object k of a row of them, `far` along x: motions of four kinds, each about the object's own place.
    const auto movingObject = [](int k, double far) {
        const Vec3 at{1.5 * (k % 3) + far, 1.5 * (k / 3), 0};
        Object o = k % 4 == 3 ? makeObject(Mesh{nullptr, {{-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0, 0.5, 0}}, {{0, 1, 2}},
                                                {}, {}, {}, {}, {}})
                              : makeObject(k % 2 ? Shape(Box{{-0.4, -0.3, -0.2}, {0.4, 0.3, 0.2}})
                                                 : Shape(Sphere{{0, 0, 0}, 0.4}));
        if (k % 4 == 0) o.motion = chainOf(motionTo({0.9, -0.2, 0.3}), Transform::translate(at));
        if (k % 4 == 1) { // 200 degrees about a pivot 3 units away
            o.transform = Transform::translate({0, -3, 0});
            o.motion = chainOf(motionTo({}, {0, 0, 200}), Transform::translate(at + Vec3{0, 3, 0}));
        }
        if (k % 4 == 2) o.motion = chainOf(motionTo({0, 0.5, 0}, {}, {0.3, 0.3, 0.3}), Transform::translate(at));
        if (k % 4 == 3) o.motion = chainOf(motionTo({-0.6, 0, 0}, {40, 0, 0}), Transform::translate(at));
        o.noShadow = k == 6;
        return o;
    };
    // Packets of 8 rays at each object's box at each time, and shadow rays
    // back along them: the moving scene answers as the still one.
    const auto expectSameAsStill = [](const Scene& scene, int seed, const std::string& what) {
        const Accelerator moving(scene);
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> u(0, 1);
        int rays = 0, hits = 0, blocked = 0, disagreements = 0;
        for (const double time : {0.0, 0.2, 0.55, 0.9, 1.0}) {
            const Scene stillScene = stillAt(scene, time);
            const Accelerator still(stillScene);
            for (const Object& target : stillScene.objects) {
                const Scene single = sceneOf({target});
                const Accelerator alone(single);
                Vec3 lower, upper; // where this object is at `time`
                alone.bounds(lower, upper);
                for (int packet = 0; packet < 20; ++packet) {
                    Ray camera[8], shadow[8];
                    for (int i = 0; i < 8; ++i) {
                        const Vec3 aim{lower.x + (upper.x - lower.x) * u(rng), lower.y + (upper.y - lower.y) * u(rng),
                                       lower.z + (upper.z - lower.z) * u(rng)};
                        const Vec3 origin = aim + Vec3{0.7 * u(rng) - 0.35, 0.7 * u(rng) - 0.35, -8};
                        camera[i] = rayAt(origin, aim - origin, time);
                        // From beyond the aim back towards the camera ray's origin.
                        shadow[i] = rayAt(origin + 2 * (aim - origin), origin - aim, time);
                        shadow[i].tMin = 1e-6;
                        shadow[i].tMax = 2;
                    }
                    Hit packetHits[8];
                    bool found[8], packetBlocked[8];
                    moving.intersectPacket(camera, 8, packetHits, found);
                    moving.occludedPacket(shadow, 8, packetBlocked);
                    for (int i = 0; i < 8; ++i) {
                        Hit a, b;
                        const bool ha = moving.intersect(camera[i], a), hb = still.intersect(camera[i], b);
                        const bool oa = moving.occluded(shadow[i]), ob = still.occluded(shadow[i]);
                        EXPECT_EQ(found[i], ha) << what;
                        EXPECT_EQ(packetBlocked[i], oa) << what;
                        ++rays;
                        if (ha != hb || oa != ob) {
                            ++disagreements;
                            continue;
                        }
                        hits += ha;
                        blocked += oa;
                        if (ha) {
                            EXPECT_NEAR(a.t, b.t, 1e-4) << what << " at " << time;
                        }
                    }
                }
            }
        }
        // Rays aim at points of each object's box: most meet it, a few graze
        // a silhouette within the motion's tolerance.
        EXPECT_GT(hits, rays * 2 / 5) << what;
        EXPECT_GT(blocked, rays / 4) << what;
        EXPECT_LE(disagreements, rays / 150) << what << " of " << rays;
    };
    for (const double far : {0.0, 3e4}) {
        for (int k = 0; k < 4; ++k) // alone: the one moving object has its bit
            expectSameAsStill(sceneOf({movingObject(k, far)}), k, fmt::format("object {} alone, {} away", k, far));
        for (const int count : {2, 3, 8}) {
            std::vector<Object> objects;
            for (int k = 0; k < count; ++k) objects.push_back(movingObject(k, far));
            expectSameAsStill(sceneOf(objects), count, fmt::format("{} objects, {} away", count, far));
        }
    }
}

} // namespace
} // namespace drt
