// Surfaces of revolution (lathe, sor): ray crossings (accel/revolution_shape.h)
// against cylinders and cones on random lines, hits on the surface, inside vs
// crossing parity, CSG through Embree, spawned rays, and both front ends
// (errors with locations, bit-identical .drt round trip, POV-Ray scenes).
#include "accel/accel.h"
#include "accel/revolution_shape.h"
#include "accel/shapes.h"
#include "lang/load.h"
#include "lang/writer.h"
#include "pov/load.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace drt {
namespace {

Vec3 unit(const Vec3& v) { return v / length(v); }

Revolution lathe(Revolution::Spline spline, std::vector<Vec2> points) {
    Revolution r;
    r.spline = spline;
    r.points = std::move(points);
    return r;
}

Revolution sor(std::vector<Vec2> points, bool open = false) {
    Revolution r;
    r.kind = Revolution::Kind::Sor;
    r.points = std::move(points);
    r.open = open;
    return r;
}

Object object(Shape shape, Transform t = {}) {
    Object o;
    o.shape = std::move(shape);
    o.transform = t;
    return o;
}

// Compares every crossing of random lines with a reference shape: same count,
// t within a relative tolerance, same outward normal direction. Lines that
// graze an edge of the reference (two crossings closer than 1e-9) are skipped.
void expectSameCrossings(const accel::AnalyticShape& a, const accel::AnalyticShape& b, unsigned seed,
                         double tolerance, int& compared) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-2.5, 2.5);
    std::normal_distribution<double> g;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 o{u(rng), u(rng), u(rng)};
        Vec3 d{g(rng), g(rng), g(rng)};
        if (i % 10 == 0) d = {0, 0, 0}, d[i % 3] = 1; // axis-aligned lines too (horizontal ones included)
        accel::Crossing fixed[accel::kMaxCrossings], ref[accel::kMaxCrossings];
        std::vector<accel::Crossing> many;
        const accel::Crossing* c = nullptr;
        const int n = accel::allCrossings(a, o, d, fixed, many, c);
        const int m = accel::intersectShape(b, o, d, ref);
        bool graze = false;
        for (int k = 0; k + 1 < m; ++k) graze |= ref[k + 1].t - ref[k].t < 1e-9;
        if (graze) continue;
        ASSERT_EQ(n, m) << "line " << i;
        for (int k = 0; k < n; ++k) {
            EXPECT_NEAR(c[k].t, ref[k].t, tolerance * (1 + std::fabs(ref[k].t))) << "line " << i;
            EXPECT_NEAR(dot(unit(c[k].normal), unit(ref[k].normal)), 1.0, 1e-9) << "line " << i;
        }
        compared += n;
        const Vec3 p{u(rng), u(rng), u(rng)};
        EXPECT_EQ(accel::insideShape(a, p), accel::insideShape(b, p)) << p.x << " " << p.y << " " << p.z;
    }
}

TEST(RevolutionIntersect, LinearLatheOfARectangleIsTheCylinder) {
    // The outline (0,-0.5) (1,-0.5) (1,1) (0,1) with both ends on the axis.
    const auto l = *accel::prepareShape(lathe(Revolution::Spline::Linear, {{0, -0.5}, {1, -0.5}, {1, 1}, {0, 1}}));
    const auto cyl = *accel::prepareShape(Cylinder{{0, -0.5, 0}, {0, 1, 0}, 1, false});
    EXPECT_TRUE(accel::isSolidShape(l));
    int compared = 0;
    expectSameCrossings(l, cyl, 3, 1e-11, compared);
    EXPECT_GT(compared, 5000);
}

TEST(RevolutionIntersect, ClosedClockwiseLinearLatheIsTheCone) {
    // A closed outline running clockwise (up the axis first): the frustum from
    // radius 1.5 at y = 0 to 0.5 at y = 1; the normals must still face out.
    const auto l = *accel::prepareShape(
        lathe(Revolution::Spline::Linear, {{0, 0}, {0, 1}, {0.5, 1}, {1.5, 0}, {0, 0}}));
    const auto cone = *accel::prepareShape(Cone{{0, 0, 0}, 1.5, {0, 1, 0}, 0.5, false});
    EXPECT_TRUE(accel::isSolidShape(l));
    int compared = 0;
    expectSameCrossings(l, cone, 4, 1e-11, compared);
    EXPECT_GT(compared, 5000);
}

TEST(RevolutionIntersect, SorOfConstantRadiusIsTheCylinder) {
    // r = 0.8 at every point: r^2 is constant, the caps are at the second and
    // last but one heights.
    const auto s = *accel::prepareShape(sor({{0.8, -1}, {0.8, -0.5}, {0.8, 0.2}, {0.8, 1}, {0.8, 1.5}}));
    const auto cyl = *accel::prepareShape(Cylinder{{0, -0.5, 0}, {0, 1, 0}, 0.8, false});
    int compared = 0;
    expectSameCrossings(s, cyl, 5, 1e-11, compared);
    EXPECT_GT(compared, 4000);
    const auto open = *accel::prepareShape(sor({{0.8, -1}, {0.8, -0.5}, {0.8, 0.2}, {0.8, 1}, {0.8, 1.5}}, true));
    const auto openCyl = *accel::prepareShape(Cylinder{{0, -0.5, 0}, {0, 1, 0}, 0.8, true});
    EXPECT_FALSE(accel::isSolidShape(open));
    compared = 0;
    expectSameCrossings(open, openCyl, 6, 1e-11, compared);
    EXPECT_GT(compared, 2500);
}

// Curved splines: walking along a line, the inside test flips at each
// crossing (checked midway between crossings), the normal faces against the
// line when entering, and the point just before the first crossing is outside.
void expectHitsOnSurfaceAndParity(const Revolution& rev, unsigned seed) {
    const auto s = *accel::prepareShape(rev);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-3, 3);
    std::normal_distribution<double> g;
    int hits = 0, parityChecks = 0;
    for (int i = 0; i < 5000; ++i) {
        const Vec3 o{u(rng), u(rng) + 1, u(rng)};
        const Vec3 d = unit(Vec3{g(rng), g(rng), g(rng)});
        accel::Crossing fixed[accel::kMaxCrossings];
        std::vector<accel::Crossing> many;
        const accel::Crossing* c = nullptr;
        const int n = accel::allCrossings(s, o, d, fixed, many, c);
        hits += n;
        // Parity: walking along the line, inside flips at each crossing.
        for (int k = 0; k + 1 < n; ++k) {
            if (c[k + 1].t - c[k].t < 1e-6) continue;
            const double mid = 0.5 * (c[k].t + c[k + 1].t);
            const bool expectInside = (k % 2) == 0;
            EXPECT_EQ(accel::insideShape(s, o + mid * d), expectInside) << "line " << i << " crossing " << k;
            EXPECT_EQ(dot(c[k].normal, d) < 0, expectInside) << "line " << i << " crossing " << k;
            ++parityChecks;
        }
        if (n > 0) {
            EXPECT_FALSE(accel::insideShape(s, o + (c[0].t - 1e-3) * d));
        }
    }
    EXPECT_GT(hits, 1000);
    EXPECT_GT(parityChecks, 500);
}

TEST(RevolutionIntersect, CurvedSplinesHaveInsideConsistentWithCrossings) {
    using S = Revolution::Spline;
    expectHitsOnSurfaceAndParity(lathe(S::Quadratic, {{0, 0}, {0, 0}, {1, 0.3}, {0.6, 1.2}, {0.9, 2}, {0, 2.4}, {0, 2.4}}), 11);
    expectHitsOnSurfaceAndParity(
        lathe(S::Cubic, {{0, 0}, {0, 0}, {1, 0.2}, {0.6, 1}, {0.8, 1.8}, {0.2, 2.4}, {0, 2.5}, {0, 2.5}}), 12);
    expectHitsOnSurfaceAndParity(lathe(S::Bezier, {{0, 0}, {1.5, 0}, {1.5, 1}, {0.5, 1.5}, {0.5, 1.5}, {0, 2}, {0, 2}, {0, 2}}), 13);
    expectHitsOnSurfaceAndParity(sor({{0, 0}, {0.8, 0}, {0.4, 0.8}, {0.9, 1.6}, {0.5, 2.2}, {0.6, 3}}), 14);
}

// Two cubic Bezier quarter circles revolved: each hit lies on the revolved
// curve (distance in (r, y) below 1e-9, found by sampling and ternary
// search), within 3e-4 of the unit sphere the curve approximates, with an
// outward normal.
TEST(RevolutionIntersect, BezierLatheHitsLieOnTheCurve) {
    const double k = 0.5522847498;
    const Revolution rev = lathe(Revolution::Spline::Bezier, {{0, -1}, {k, -1}, {1, -k}, {1, 0}, {1, 0}, {1, k}, {k, 1}, {0, 1}});
    const auto s = *accel::prepareShape(rev);
    std::mt19937 rng(21);
    std::uniform_real_distribution<double> u(-2, 2);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3 o{u(rng), u(rng), -4};
        const Vec3 d = unit(Vec3{u(rng) * 0.2, u(rng) * 0.2, 1});
        accel::Crossing c[accel::kMaxCrossings];
        const int n = accel::intersectShape(s, o, d, c);
        for (int j = 0; j < n; ++j) {
            const Vec3 p = o + c[j].t * d;
            const double r = std::sqrt(p.x * p.x + p.z * p.z);
            // Distance to the curve in (r, y): the nearest of dense samples,
            // refined by ternary search around it.
            auto distance = [&](int seg, double t) {
                const double w = 1 - t;
                const Vec2* q = &rev.points[size_t(4 * seg)];
                const double cr = w * w * w * q[0].x + 3 * w * w * t * q[1].x + 3 * w * t * t * q[2].x + t * t * t * q[3].x;
                const double cy = w * w * w * q[0].y + 3 * w * w * t * q[1].y + 3 * w * t * t * q[2].y + t * t * t * q[3].y;
                return std::hypot(cr - r, cy - p.y);
            };
            double best = 1e9;
            for (int seg = 0; seg < 2; ++seg) {
                int bestM = 0;
                for (int m = 0; m <= 2000; ++m)
                    if (distance(seg, m / 2000.0) < distance(seg, bestM / 2000.0)) bestM = m;
                double lo = std::max(0.0, (bestM - 1) / 2000.0), hi = std::min(1.0, (bestM + 1) / 2000.0);
                for (int it = 0; it < 100; ++it) {
                    const double a = lo + (hi - lo) / 3, b = hi - (hi - lo) / 3;
                    if (distance(seg, a) < distance(seg, b)) hi = b;
                    else lo = a;
                }
                best = std::min(best, distance(seg, 0.5 * (lo + hi)));
            }
            EXPECT_LT(best, 1e-9) << i;
            // The Bezier circle is within 3e-4 of the unit sphere.
            EXPECT_NEAR(length(p), 1, 3e-4);
            EXPECT_GT(dot(unit(c[j].normal), p), 0.99);
            ++hits;
        }
    }
    EXPECT_GT(hits, 500);
}

TEST(RevolutionIntersect, OpenOutlinesHaveNoInsideAndBadInputIsRejected) {
    const auto open = *accel::prepareShape(lathe(Revolution::Spline::Linear, {{1, 0}, {1, 1}}));
    EXPECT_FALSE(accel::isSolidShape(open));
    EXPECT_FALSE(accel::insideShape(open, {0, 0.5, 0}));
    accel::Crossing c[accel::kMaxCrossings];
    EXPECT_EQ(accel::intersectShape(open, {-3, 0.5, 0}, {1, 0, 0}, c), 2); // an open tube
    EXPECT_THROW(accel::prepareShape(lathe(Revolution::Spline::Bezier, {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 2}})),
                 std::invalid_argument);
    EXPECT_THROW(accel::prepareShape(sor({{1, 0}, {1, 1}, {1, 0.5}, {1, 2}})), std::invalid_argument);
    EXPECT_THROW(accel::prepareShape(lathe(Revolution::Spline::Cubic, {{0, 0}, {1, 0}, {1, 1}})),
                 std::invalid_argument);
}

TEST(RevolutionAccel, DifferenceWithALatheCutsTheHole) {
    Csg csg;
    csg.op = Csg::Op::Difference;
    csg.children.push_back(object(Box{{-2, -1, -2}, {2, 1, 2}}));
    csg.children.push_back(object(lathe(Revolution::Spline::Linear, {{0, -3}, {1, -3}, {1, 3}, {0, 3}})));
    Object csgObject;
    csgObject.shape = csg;
    Scene scene;
    scene.objects.push_back(csgObject);
    Accelerator accel(scene);
    Ray ray;
    Hit hit;
    ray.origin = {0.5, 5, 0.2};
    ray.direction = {0, -1, 0};
    EXPECT_FALSE(accel.intersect(ray, hit)); // down the hole
    ray.origin = {1.5, 5, 0.2};
    ASSERT_TRUE(accel.intersect(ray, hit));
    EXPECT_NEAR(hit.t, 4, 1e-9);
    ray.origin = {-5, 0, 0};
    ray.direction = {1, 0, 0};
    ASSERT_TRUE(accel.intersect(ray, hit));
    EXPECT_NEAR(hit.t, 3, 1e-9);
    ray.origin = Accelerator::offsetOrigin(hit, {1, 0, 0});
    ASSERT_TRUE(accel.intersect(ray, hit)); // leaves the box at the hole's wall x = -1
    EXPECT_NEAR(hit.point.x, -1, 1e-9);
    EXPECT_NEAR(dot(hit.geometricNormal, Vec3(1, 0, 0)), 1, 1e-9);
}

using test::randomUnitVector;

TEST(RevolutionAccel, SpawnedRaysDoNotReHitTheirSurface) {
    using S = Revolution::Spline;
    const std::vector<Shape> shapes = {
        lathe(S::Cubic, {{0, 0}, {0, 0}, {1, 0.2}, {0.6, 1}, {0.8, 1.8}, {0.2, 2.4}, {0, 2.5}, {0, 2.5}}),
        sor({{0, 0}, {0.8, 0}, {0.4, 0.8}, {0.9, 1.6}, {0.5, 2.2}, {0.6, 3}})};
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    int rays = 0, selfHits = 0;
    for (double scale : {1e-3, 1.0, 1e3})
        for (const Shape& shape : shapes) {
            const Transform t = Transform::rotate({10, 20, 30}).then(Transform::scale(Vec3(scale)));
            Scene scene;
            scene.objects.push_back(object(shape, t));
            Accelerator accel(scene);
            for (int i = 0; i < 1500; ++i) {
                const Vec3 target = t.point({u(rng) * 0.8, 1.2 + u(rng), u(rng) * 0.8});
                const Vec3 origin = target + randomUnitVector(rng) * (4 * scale);
                Ray ray;
                ray.origin = origin;
                ray.direction = target - origin;
                Hit hit;
                if (!accel.intersect(ray, hit)) continue;
                test::countSelfHits(accel, hit, origin, scale, rng, rays, selfHits);
            }
        }
    EXPECT_EQ(selfHits, 0) << "among " << rays;
    EXPECT_GT(rays, 5000);
}

// ------------------------------------------------------------ front ends

struct BadInput {
    const char* source;
    const char* message;
    int line, column;
};

TEST(DrtRevolution, ErrorsNameTheLineAndColumn) {
    const BadInput cases[] = {
        {"lathe { linear_spline 1, <0, 0> }", "this lathe spline needs at least 2 points", 1, 23},
        {"lathe { cubic_spline 3, <0, 0>, <1, 0>, <1, 1> }", "this lathe spline needs at least 4 points", 1, 22},
        {"lathe { bezier_spline 6, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 2>, <0, 3> }",
         "a bezier_spline lathe needs 4 points per segment (a multiple of 4)", 1, 23},
        {"lathe { 3, <0, 0>, <-1, 0>, <0, 1> }", "a lathe point needs a radius >= 0 (only the end points may be negative)",
         1, 20},
        {"sor { 3, <0, 0>, <1, 1>, <1, 2> }", "a sor needs at least 4 points", 1, 7},
        {"sor { 5, <0, 0>, <1, 1>, <1, 2>,\n  <1, 1.5>, <1, 3> }", "sor heights must increase (this point is not above the one before)", 2,
         3},
        {"sor { 4, <0, 0>, <1, 1>, <1, 2>, <-1, 3> }", "a sor point needs a radius >= 0", 1, 34},
        {"lathe { 2, <0, 0>, 1 }", "expected a point <radius, height>, found a number", 1, 20},
        {"lathe { 2, <0, 0>, <1, 1> open }", "'open' applies only to cylinder, cone and prism, and to sor and isosurface", 1, 27},
    };
    for (const BadInput& c : cases) {
        Diagnostics diags;
        EXPECT_FALSE(loadSceneText(c.source, "e.drt", diags)) << c.source;
        ASSERT_GE(diags.errorCount(), 1) << c.source;
        const Diagnostic& d = diags.all()[0];
        EXPECT_EQ(d.message, c.message) << c.source;
        EXPECT_EQ(d.loc.line, c.line) << c.source;
        EXPECT_EQ(d.loc.column, c.column) << c.source;
    }
}

TEST(DrtRevolution, ShapesParseAndRoundTripBitIdentically) {
    const std::string text = R"(
camera { location <0, 2, -8> look_at <0, 1, 0> }
light_source { <5, 10, -10>, rgb 1 }
lathe { cubic_spline 8, <0, 0>, <0, 0>, <1, 0.2>, <0.6, 1>, <0.8, 1.8>, <0.2, 2.4>, <0, 2.5>, <0, 2.5> sturm
        pigment { rgb <1, 0.4, 0.3> } translate x * -1.5 }
lathe { 5, <0.2, 0>, <0.6, 0>, <0.6, 0.6>, <0.2, 0.6>, <0.2, 0> pigment { rgb 0.7 } }
lathe { quadratic_spline 4, <0, 0>, <1, 0.1>, <0.3, 1.3>, <0, 1.7> }
lathe { bezier_spline 4, <0, 0>, <1.1, 0.1>, <0.7, 1.3>, <0, 1.7> }
sor { 6, <0, 0>, <0.8, 0>, <0.4, 0.8>, <0.9, 1.6>, <0.5, 2.2>, <0.6, 3> open pigment { rgb <0.3, 1, 0.4> } translate x * 1.5 }
sor { 4, <1 / 3, 0>, <0.1, 0.1>, <0.7, 1.1>, <0.2, 1.7> }
)";
    Diagnostics diags;
    const std::optional<Scene> scene = loadSceneText(text, "a.drt", diags, ".");
    ASSERT_TRUE(scene) << diags.formatAll();
    ASSERT_EQ(scene->objects.size(), 6u);
    const auto& cubic = std::get<Revolution>(scene->objects[0].shape);
    EXPECT_EQ(cubic.spline, Revolution::Spline::Cubic);
    EXPECT_TRUE(cubic.sturm);
    EXPECT_EQ(cubic.points.size(), 8u);
    EXPECT_EQ(std::get<Revolution>(scene->objects[1].shape).spline, Revolution::Spline::Linear);
    EXPECT_TRUE(std::get<Revolution>(scene->objects[4].shape).open);
    EXPECT_EQ(std::get<Revolution>(scene->objects[5].shape).points[0].x, 1.0 / 3);
    const std::string written = writeDrtScene(*scene);
    Diagnostics again;
    const std::optional<Scene> reread = loadSceneText(written, "b.drt", again, ".");
    ASSERT_TRUE(reread) << again.formatAll() << written;
    EXPECT_EQ(writeDrtScene(*reread), written);
    for (size_t i = 0; i < scene->objects.size(); ++i) {
        const auto& a = std::get<Revolution>(scene->objects[i].shape);
        const auto& b = std::get<Revolution>(reread->objects[i].shape);
        EXPECT_EQ(a.kind, b.kind);
        EXPECT_EQ(a.spline, b.spline);
        EXPECT_EQ(a.open, b.open);
        EXPECT_EQ(a.sturm, b.sturm);
        ASSERT_EQ(a.points.size(), b.points.size());
        for (size_t k = 0; k < a.points.size(); ++k) {
            EXPECT_EQ(a.points[k].x, b.points[k].x);
            EXPECT_EQ(a.points[k].y, b.points[k].y);
        }
    }
}

TEST(PovRevolution, LatheAndSorAreReadWithoutWarnings) {
    const std::string text = R"(
camera { location <0, 2, -8> look_at <0, 1, 0> }
lathe { bezier_spline 4 <0, 0>, <1.1, 0.1>, <0.7, 1.3>, <0, 1.7> sturm }
sor { 5, <0, 0>, <0.5, 0>, <0.4, 1>, <0.5, 2>, <0.1, 3> open }
)";
    Diagnostics diags;
    const std::optional<Scene> scene = loadPovSceneText(text, "s.pov", diags);
    ASSERT_TRUE(scene) << diags.formatAll();
    EXPECT_EQ(diags.all().size(), 0u) << diags.formatAll();
    ASSERT_EQ(scene->objects.size(), 2u);
    const auto& l = std::get<Revolution>(scene->objects[0].shape);
    EXPECT_EQ(l.spline, Revolution::Spline::Bezier);
    EXPECT_TRUE(l.sturm);
    EXPECT_EQ(l.points[2].x, 0.7);
    const auto& s = std::get<Revolution>(scene->objects[1].shape);
    EXPECT_EQ(s.kind, Revolution::Kind::Sor);
    EXPECT_TRUE(s.open);
    EXPECT_EQ(s.points.size(), 5u);
}

TEST(PovRevolution, BadPointsAreErrorsWithLocations) {
    const BadInput cases[] = {
        {"lathe { quadratic_spline 2, <0, 0>, <1, 1> }", "this lathe spline needs at least 3 points", 1, 26},
        {"sor { 4, <0, 0>, <1, 1>,\n <1, 0.5>, <1, 3> }", "sor heights must increase (this point is not above the one before)", 2, 2},
    };
    for (const BadInput& c : cases) {
        Diagnostics diags;
        EXPECT_FALSE(loadPovSceneText(c.source, "e.pov", diags)) << c.source;
        ASSERT_GE(diags.errorCount(), 1) << c.source;
        const Diagnostic& d = diags.all()[0];
        EXPECT_EQ(d.message, c.message) << c.source;
        EXPECT_EQ(d.loc.line, c.line) << c.source;
        EXPECT_EQ(d.loc.column, c.column) << c.source;
    }
}

} // namespace
} // namespace drt
