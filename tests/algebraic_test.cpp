// The algebraic shapes in the accelerator: quadric, cubic, quartic, poly and
// superellipsoid against closed forms (drt's sphere and torus, the unit cube),
// the exactness of the polynomial's expansion along a ray, hits on the
// surface, CSG, and self-intersection of spawned rays.
#include "accel/accel.h"
#include "accel/algebraic_shapes.h"
#include "accel/polynomial.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace drt {
namespace {

using accel::Crossing;
using accel::kMaxCrossings;

Vec3 randomUnit(std::mt19937& rng) {
    std::normal_distribution<double> g;
    for (;;) {
        const Vec3 v{g(rng), g(rng), g(rng)};
        if (length(v) > 1e-6) return normalize(v);
    }
}

Algebraic quadric(std::vector<double> c) {
    Algebraic a;
    a.form = Algebraic::Form::Quadric;
    a.order = 2;
    a.coefficients = std::move(c);
    return a;
}

// The torus around y of major radius R, minor r, as POV-Ray's quartic (the
// sample scene objects/quartic/torus.pov has R^2 = 40, r^2 = 12):
// (x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2).
Algebraic torusQuartic(double R, double r) {
    const double k = R * R - r * r;
    Algebraic a;
    a.form = Algebraic::Form::Quartic;
    a.order = 4;
    a.coefficients.assign(35, 0.0);
    a.coefficients[0] = 1;                   // x^4
    a.coefficients[4] = 2;                   // x^2 y^2
    a.coefficients[7] = 2;                   // x^2 z^2
    a.coefficients[9] = 2 * k - 4 * R * R;   // x^2
    a.coefficients[20] = 1;                  // y^4
    a.coefficients[23] = 2;                  // y^2 z^2
    a.coefficients[25] = 2 * k;              // y^2
    a.coefficients[30] = 1;                  // z^4
    a.coefficients[32] = 2 * k - 4 * R * R;  // z^2
    a.coefficients[34] = k * k;              // 1
    return a;
}

int crossings(const Shape& shape, const Vec3& o, const Vec3& d, Crossing out[kMaxCrossings]) {
    const auto prepared = accel::prepareShape(shape);
    return accel::intersectShape(*prepared, o, d, out);
}

// Every crossing of `a` equals the one of `b` (t within tolerance, unit
// normals within tolerance) for rays from random origins at distance 3..10
// times `size` towards random points of a box of `size`.
void expectSameCrossings(const Shape& a, const Shape& b, double size, double tolerance, int rays, unsigned seed,
                         Vec3 centre = {}) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1), distance(3, 10);
    int compared = 0;
    for (int i = 0; i < rays; ++i) {
        const Vec3 target = centre + Vec3{u(rng) * size, u(rng) * size, u(rng) * size};
        const Vec3 origin = target + randomUnit(rng) * (distance(rng) * size);
        const Vec3 direction = (target - origin) * (0.5 + 0.5 * (u(rng) + 1)); // not unit length
        Crossing ca[kMaxCrossings], cb[kMaxCrossings];
        const int na = crossings(a, origin, direction, ca);
        const int nb = crossings(b, origin, direction, cb);
        ASSERT_EQ(na, nb) << "ray " << i;
        for (int k = 0; k < na; ++k) {
            EXPECT_NEAR(ca[k].t, cb[k].t, tolerance) << "ray " << i << " crossing " << k;
            const Vec3 diff = normalize(ca[k].normal) - normalize(cb[k].normal);
            EXPECT_LT(length(diff), tolerance) << "ray " << i << " crossing " << k;
            ++compared;
        }
    }
    EXPECT_GT(compared, rays / 2);
}

TEST(Algebraic, TermOrderIsPovRays) {
    // POV-Ray's documented order for a poly of order 2.
    const int expected[10][3] = {{2, 0, 0}, {1, 1, 0}, {1, 0, 1}, {1, 0, 0}, {0, 2, 0},
                                 {0, 1, 1}, {0, 1, 0}, {0, 0, 2}, {0, 0, 1}, {0, 0, 0}};
    for (int t = 0; t < 10; ++t) {
        int i, j, k;
        algebraicTermExponents(2, t, i, j, k);
        EXPECT_EQ(i, expected[t][0]);
        EXPECT_EQ(j, expected[t][1]);
        EXPECT_EQ(k, expected[t][2]);
    }
    EXPECT_EQ(algebraicTermCount(3), 20);
    EXPECT_EQ(algebraicTermCount(4), 35);
    EXPECT_EQ(algebraicTermCount(35), 8436);
    // Order 4: term 4 is x^2 y^2, term 23 is y^2 z^2, term 34 the constant.
    int i, j, k;
    algebraicTermExponents(4, 4, i, j, k);
    EXPECT_EQ(i * 100 + j * 10 + k, 220);
    algebraicTermExponents(4, 23, i, j, k);
    EXPECT_EQ(i * 100 + j * 10 + k, 22);
    algebraicTermExponents(4, 34, i, j, k);
    EXPECT_EQ(i * 100 + j * 10 + k, 0);
}

TEST(Algebraic, ExpansionAlongALineMatchesDirectEvaluation) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int order = 2; order <= 6; ++order) {
        for (int trial = 0; trial < 50; ++trial) {
            Algebraic a;
            a.order = order;
            for (int t = 0; t < algebraicTermCount(order); ++t) a.coefficients.push_back(u(rng));
            const accel::PolynomialSurface surface = accel::preparePolynomial(a);
            ASSERT_EQ(surface.order, order);
            const Vec3 p{u(rng) * 2, u(rng) * 2, u(rng) * 2};
            const Vec3 dir = randomUnit(rng);
            double c[accel::kMaxPolynomialDegree + 1];
            accel::expandAlongLine(surface, p, dir, c);
            for (double s : {-2.0, -0.7, 0.0, 0.3, 1.9}) {
                double expanded = 0;
                for (int k = order; k >= 0; --k) expanded = expanded * s + c[k];
                const Vec3 q = p + s * dir;
                const double direct = evaluateAlgebraic(algebraicTerms(a), q.x, q.y, q.z);
                // Sum of |terms| bounds the rounding of either evaluation.
                double magnitude = 0;
                for (const Monomial& m : algebraicTerms(a))
                    magnitude += std::fabs(m.coefficient) * std::pow(std::fabs(q.x), m.x) *
                                 std::pow(std::fabs(q.y), m.y) * std::pow(std::fabs(q.z), m.z);
                EXPECT_NEAR(expanded, direct, 1e-12 * (1 + magnitude)) << "order " << order << " s " << s;
            }
        }
    }
}

TEST(Algebraic, QuadricSphereAgreesWithSphere) {
    // x^2 + y^2 + z^2 - 4 = 0 and sphere { 0, 2 }, and an ellipsoid as a
    // quadric against a scaled sphere is covered by the transform code already.
    expectSameCrossings(quadric({1, 1, 1, 0, 0, 0, 0, 0, 0, -4}), Sphere{{0, 0, 0}, 2}, 2, 1e-9, 4000, 1);
    // Off-centre: (x-1)^2 + y^2 + (z+0.5)^2 = 0.25.
    expectSameCrossings(quadric({1, 1, 1, 0, 0, 0, -2, 0, 1, 1 + 0.25 - 0.25}), Sphere{{1, 0, -0.5}, 0.5}, 0.5, 1e-9,
                        4000, 2, {1, 0, -0.5});
}

TEST(Algebraic, QuarticTorusAgreesWithTorus) {
    expectSameCrossings(torusQuartic(std::sqrt(40.0), std::sqrt(12.0)), Torus{std::sqrt(40.0), std::sqrt(12.0)}, 10,
                        1e-9, 4000, 3);
    expectSameCrossings(torusQuartic(1, 0.25), Torus{1, 0.25}, 1.25, 1e-9, 4000, 4);
}

TEST(Algebraic, EllipsoidQuadricsAreBoundedOthersAreNot) {
    Vec3 lo, hi;
    // (x - 1)^2 + y^2 + z^2 = 4: the box [-1, 3] x [-2, 2] x [-2, 2].
    ASSERT_TRUE(accel::shapeBounds(*accel::prepareShape(quadric({1, 1, 1, 0, 0, 0, -2, 0, 0, -3})), lo, hi));
    EXPECT_NEAR(lo.x, -1, 1e-8);
    EXPECT_NEAR(hi.x, 3, 1e-8);
    EXPECT_NEAR(lo.y, -2, 1e-8);
    EXPECT_NEAR(hi.z, 2, 1e-8);
    // A tilted ellipsoid x^2 + y^2 + z^2 + xy + 0.5 yz = 1: every surface point
    // found by rays from the centre lies in the box, and the box is tight
    // (some point comes within 1e-3 of each face).
    const Algebraic tilted = quadric({1, 1, 1, 1, 0, 0.5, 0, 0, 0, -1});
    ASSERT_TRUE(accel::shapeBounds(*accel::prepareShape(tilted), lo, hi));
    Vec3 seenLo(INFINITY), seenHi(-INFINITY);
    std::mt19937 rng(6);
    for (int i = 0; i < 20000; ++i) {
        Crossing c[kMaxCrossings];
        const Vec3 d = randomUnit(rng);
        ASSERT_EQ(crossings(tilted, {0, 0, 0}, d, c), 2); // behind and ahead
        seenLo = min(seenLo, c[1].t * d);
        seenHi = max(seenHi, c[1].t * d);
    }
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_LE(lo[axis], seenLo[axis]);
        EXPECT_GE(hi[axis], seenHi[axis]);
        EXPECT_NEAR(lo[axis], seenLo[axis], 1e-3);
        EXPECT_NEAR(hi[axis], seenHi[axis], 1e-3);
    }
    // Hyperboloids, paraboloids, cylinders and the inside-out sphere are not.
    EXPECT_FALSE(accel::shapeBounds(*accel::prepareShape(quadric({1, -1, 1, 0, 0, 0, 0, 0, 0, -1})), lo, hi));
    EXPECT_FALSE(accel::shapeBounds(*accel::prepareShape(quadric({1, 0, 1, 0, 0, 0, 0, -1, 0, 0})), lo, hi));
    EXPECT_FALSE(accel::shapeBounds(*accel::prepareShape(quadric({1, 1, 0, 0, 0, 0, 0, 0, 0, -1})), lo, hi));
    EXPECT_FALSE(accel::shapeBounds(*accel::prepareShape(quadric({-1, -1, -1, 0, 0, 0, 0, 0, 0, 1})), lo, hi));
}

TEST(Algebraic, PolyOfOrderTwoEqualsTheSameQuadric) {
    // A tilted hyperboloid x^2 + 2 y^2 - z^2 + xy - 1 = 0 in both spellings.
    Algebraic poly;
    poly.order = 2;
    poly.coefficients = {1, 1, 0, 0, 2, 0, 0, -1, 0, -1}; // x^2, xy, xz, x, y^2, yz, y, z^2, z, 1
    expectSameCrossings(poly, quadric({1, 2, -1, 1, 0, 0, 0, 0, 0, -1}), 2, 1e-12, 1000, 5);
}

TEST(Algebraic, HitsLieOnTheSurface) {
    // |f| / |grad f| is the distance to the surface to first order.
    std::vector<Algebraic> shapes = {quadric({1, -1, 1, 0, 0, 0, 0, 0, 0, -1}), torusQuartic(2, 0.5)};
    Algebraic cubic; // x^3 + y^3 + z^3 - 0.5 xyz ... - 1 (a cubic blob)
    cubic.form = Algebraic::Form::Cubic;
    cubic.order = 3;
    cubic.coefficients.assign(20, 0.0);
    cubic.coefficients[0] = 1;   // x^3
    cubic.coefficients[4] = -0.5; // x y z
    cubic.coefficients[10] = 1;  // y^3
    cubic.coefficients[16] = 1;  // z^3
    cubic.coefficients[19] = -1; // 1
    shapes.push_back(cubic);
    Algebraic sextic; // x^6 + y^6 + z^6 - 1: a rounded cube
    sextic.order = 6;
    sextic.coefficients.assign(size_t(algebraicTermCount(6)), 0.0);
    for (int t = 0; t < algebraicTermCount(6); ++t) {
        int i, j, k;
        algebraicTermExponents(6, t, i, j, k);
        if (i == 6 || j == 6 || k == 6) sextic.coefficients[size_t(t)] = 1;
        if (i + j + k == 0) sextic.coefficients[size_t(t)] = -1;
    }
    shapes.push_back(sextic);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    for (size_t s = 0; s < shapes.size(); ++s) {
        const accel::PolynomialSurface surface = accel::preparePolynomial(shapes[s]);
        int hits = 0;
        double worst = 0;
        for (int i = 0; i < 3000; ++i) {
            const Vec3 target{u(rng) * 2, u(rng) * 2, u(rng) * 2};
            const Vec3 origin = target + randomUnit(rng) * 8;
            Crossing c[kMaxCrossings];
            const int n = accel::intersectPolynomial(surface, origin, target - origin, c, kMaxCrossings);
            for (int k = 0; k < n; ++k) {
                const Vec3 p = origin + c[k].t * (target - origin);
                const double f = evaluateAlgebraic(surface.terms, p.x, p.y, p.z);
                const Vec3 g = accel::polynomialGradient(surface, p);
                worst = std::max(worst, std::fabs(f) / length(g));
                ++hits;
            }
        }
        EXPECT_LT(worst, 1e-9) << "shape " << s;
        EXPECT_GT(hits, 1000) << "shape " << s;
    }
}

TEST(Algebraic, TangentRayIsNoCrossingAndRayThroughIsTwo) {
    // The plane y = 1 touches the unit sphere x^2 + y^2 + z^2 - 1 at (0, 1, 0):
    // a double root, no change of inside, so no crossing.
    const Algebraic sphere = quadric({1, 1, 1, 0, 0, 0, 0, 0, 0, -1});
    Crossing c[kMaxCrossings];
    EXPECT_EQ(crossings(sphere, {-5, 1, 0}, {1, 0, 0}, c), 0);
    ASSERT_EQ(crossings(sphere, {-5, 0.999, 0}, {1, 0, 0}, c), 2);
    EXPECT_NEAR(c[0].t, 5 - std::sqrt(1 - 0.999 * 0.999), 1e-12);
    // Far away: the hit at t ~ 1e5 is still exact to about 1e-16 relative.
    ASSERT_EQ(crossings(sphere, {-1e5, 0, 0}, {1, 0, 0}, c), 2);
    EXPECT_NEAR(c[0].t, 1e5 - 1, 1e-9);
    EXPECT_NEAR(c[1].t, 1e5 + 1, 1e-9);
}

TEST(Algebraic, InfiniteSurfacesAreFoundFarAway) {
    // The plane-like quadric x = 0 (G = 1) seen from 5e5 away along x.
    Crossing c[kMaxCrossings];
    ASSERT_EQ(crossings(quadric({0, 0, 0, 0, 0, 0, 1, 0, 0, 0}), {-5e5, 3, 4}, {1, 0.1, 0}, c), 1);
    EXPECT_NEAR(c[0].t, 5e5, 1e-6);
    // The paraboloid y = x^2 + z^2 hit near its vertex from far away.
    ASSERT_EQ(crossings(quadric({1, 0, 1, 0, 0, 0, 0, -1, 0, 0}), {0, 1000, 0}, {0, -1, 0}, c), 1);
    EXPECT_NEAR(c[0].t, 1000, 1e-9);
}

TEST(Superellipsoid, ExponentsOneAreTheUnitSphere) {
    const Superellipsoid super{1, 1};
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(-1, 1);
    const auto prepared = accel::prepareShape(Sphere{{0, 0, 0}, 1});
    int compared = 0;
    for (int i = 0; i < 4000; ++i) {
        const Vec3 target{u(rng), u(rng), u(rng)};
        const Vec3 origin = target + randomUnit(rng) * 5;
        const Vec3 d = target - origin;
        // Rays that clearly hit or clearly miss: a graze closer than the
        // sampling step may be missed, as in POV-Ray.
        const Vec3 closest = origin - (dot(origin, d) / dot(d, d)) * d;
        if (std::fabs(length(closest) - 1) < 1e-2) continue;
        Crossing a[kMaxCrossings], b[kMaxCrossings];
        const int na = crossings(super, origin, d, a);
        const int nb = accel::intersectShape(*prepared, origin, d, b);
        ASSERT_EQ(na, nb) << "ray " << i;
        for (int k = 0; k < na; ++k, ++compared) {
            EXPECT_NEAR(a[k].t, b[k].t, 1e-9);
            EXPECT_LT(length(normalize(a[k].normal) - normalize(b[k].normal)), 1e-9);
        }
    }
    EXPECT_GT(compared, 2000);
}

TEST(Superellipsoid, SmallExponentsApproachTheUnitCube) {
    // Rays at the middle of the faces: the surface is within 1e-3 of the cube
    // for <0.05, 0.05> and nearer still for smaller exponents.
    std::mt19937 rng(10);
    std::uniform_real_distribution<double> u(-0.8, 0.8);
    double previousWorst = INFINITY;
    for (double exponent : {0.2, 0.05, 0.01}) {
        double worst = 0;
        for (int i = 0; i < 1000; ++i) {
            const int axis = i % 3;
            Vec3 origin{u(rng), u(rng), u(rng)}, d{0, 0, 0};
            origin[axis] = -4;
            d[axis] = 1;
            Crossing c[kMaxCrossings];
            ASSERT_EQ(crossings(Superellipsoid{exponent, exponent}, origin, d, c), 2);
            worst = std::max({worst, std::fabs(c[0].t - 3), std::fabs(c[1].t - 5)});
            if (exponent <= 0.05) {
                EXPECT_GT(std::fabs(normalize(c[0].normal)[axis]), 0.99);
            }
        }
        EXPECT_LT(worst, previousWorst);
        if (exponent == 0.05) {
            EXPECT_LT(worst, 1e-3);
        }
        previousWorst = worst;
    }
}

TEST(Superellipsoid, HitsLieOnTheSurfaceAndInsideIsNegative) {
    std::mt19937 rng(12);
    std::uniform_real_distribution<double> u(-1, 1);
    for (const Superellipsoid s : {Superellipsoid{0.3, 0.7}, Superellipsoid{2.5, 0.5}, Superellipsoid{1, 3}}) {
        int hits = 0;
        for (int i = 0; i < 2000; ++i) {
            const Vec3 origin = randomUnit(rng) * 4;
            const Vec3 d = Vec3{u(rng), u(rng), u(rng)} * 0.7 - origin;
            Crossing c[kMaxCrossings];
            const int n = crossings(s, origin, d, c);
            EXPECT_EQ(n % 2, 0);
            for (int k = 0; k < n; ++k, ++hits) {
                const Vec3 p = origin + c[k].t * d;
                EXPECT_NEAR(accel::superellipsoidFunction(s.e, s.n, p), 0, 1e-12);
                // Entering crossings face the ray, leaving ones do not.
                EXPECT_EQ(dot(c[k].normal, d) < 0, k % 2 == 0);
            }
        }
        EXPECT_GT(hits, 1000);
        const auto prepared = accel::prepareShape(s);
        EXPECT_TRUE(accel::insideShape(*prepared, {0, 0, 0}));
        EXPECT_FALSE(accel::insideShape(*prepared, {0.99, 0.99, 0.99}));
    }
}

// ------------------------------------------------------------ through the Accelerator

using test::makeObject;
using test::buildAccelerator;
using test::sceneOf;

TEST(Algebraic, DifferenceWithASphereMatchesTheSphereVersion) {
    // difference { unit sphere as a quadric, sphere at (0.8, 0, 0) r 0.5 }
    // against the same with drt's sphere, and a superellipsoid <1,1> version.
    auto differenceOf = [](Shape first) {
        Csg csg;
        csg.op = Csg::Op::Difference;
        csg.children = {makeObject(std::move(first)), makeObject(Sphere{{0.8, 0, 0}, 0.5})};
        return makeObject(csg, Transform::rotate({10, 20, 30}).then(Transform::translate({1, 2, 3})));
    };
    const Scene quadricSceneScene = sceneOf({differenceOf(quadric({1, 1, 1, 0, 0, 0, 0, 0, 0, -1}))});
    const Accelerator quadricScene(quadricSceneScene);
    const Scene superSceneScene = sceneOf({differenceOf(Superellipsoid{1, 1})});
    const Accelerator superScene(superSceneScene);
    const Scene sphereSceneScene = sceneOf({differenceOf(Sphere{{0, 0, 0}, 1})});
    const Accelerator sphereScene(sphereSceneScene);
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> u(-1.2, 1.2);
    int hits = 0;
    const Transform place = Transform::rotate({10, 20, 30}).then(Transform::translate({1, 2, 3}));
    for (int i = 0; i < 3000; ++i) {
        Ray ray;
        const Vec3 target = place.point({u(rng), u(rng), u(rng)});
        ray.origin = target + randomUnit(rng) * 6;
        ray.direction = target - ray.origin;
        Hit a, b, c;
        const bool ha = quadricScene.intersect(ray, a), hb = sphereScene.intersect(ray, b);
        const bool hc = superScene.intersect(ray, c);
        // Skip grazes of either sphere, where a sampled superellipsoid may differ.
        ASSERT_EQ(ha, hb) << "ray " << i;
        if (!ha) continue;
        ++hits;
        EXPECT_NEAR(a.t, b.t, 1e-9);
        EXPECT_LT(length(a.geometricNormal - b.geometricNormal), 1e-9);
        if (hc) {
            EXPECT_NEAR(c.t, b.t, 1e-6);
        }
        // A ray entering the carved hole reaches the inner spherical surface,
        // whose normal points into the small sphere: both agree on that.
    }
    EXPECT_GT(hits, 1000);
}

TEST(Algebraic, SpawnedRaysDoNotReHitTheirSurface) {
    // As Accel.SpawnedRaysDoNotReHitTheirSurface for the convex shapes here:
    // a quadric ellipsoid, a superellipsoid and a quartic torus (not convex:
    // rays leaving outward may legitimately hit it again, so only hits back at
    // the spawn point count).
    std::mt19937 rng(14);
    std::uniform_real_distribution<double> u(-1, 1);
    const std::vector<Shape> shapes = {quadric({1, 2, 3, 0, 0, 0, 0, 0, 0, -1}), Superellipsoid{0.4, 0.8},
                                       torusQuartic(1, 0.3)};
    int rays = 0, selfHits = 0;
    for (double scale : {1e-3, 1.0, 1e3})
        for (double offset : {0.0, 1e4})
            for (const Shape& shape : shapes) {
                const Transform t = Transform::rotate({10, 20, 30}).then(Transform::scale(Vec3(scale))).then(
                    Transform::translate(Vec3(offset)));
                const Scene accelScene = sceneOf({makeObject(shape, t)});
                const Accelerator accel(accelScene);
                for (int i = 0; i < 300; ++i) {
                    Ray primary;
                    const Vec3 target = t.point({u(rng) * 0.8, u(rng) * 0.3, u(rng) * 0.8});
                    primary.origin = target + randomUnit(rng) * (4 * scale);
                    primary.direction = target - primary.origin;
                    Hit hit;
                    if (!accel.intersect(primary, hit)) continue;
                    for (int side : {1, -1}) {
                        const Vec3 outward = dot(hit.geometricNormal, primary.direction) < 0 ? hit.geometricNormal
                                                                                             : -hit.geometricNormal;
                        Vec3 dir = randomUnit(rng);
                        if (dot(dir, outward) * side < 0) dir = -dir;
                        Ray spawned;
                        spawned.direction = dir;
                        spawned.origin = Accelerator::offsetOrigin(hit, dir);
                        Hit again;
                        ++rays;
                        if (accel.intersect(spawned, again) && length(again.point - hit.point) < 1e-4 * scale)
                            ++selfHits;
                    }
                }
            }
    EXPECT_EQ(selfHits, 0) << "self-hits among " << rays << " spawned rays";
    EXPECT_GT(rays, 5000);
    std::printf("algebraic self-intersection: %d re-hits in %d spawned rays\n", selfHits, rays);
}

TEST(Algebraic, InvalidShapesAreRenderErrors) {
    Algebraic wrong;
    wrong.form = Algebraic::Form::Quartic;
    wrong.coefficients.assign(34, 1.0);
    EXPECT_THROW(buildAccelerator(sceneOf({makeObject(wrong)})), std::exception);
    EXPECT_THROW(buildAccelerator(sceneOf({makeObject(quadric({0, 0, 0, 0, 0, 0, 0, 0, 0, 1}))})), std::exception);
    EXPECT_THROW(buildAccelerator(sceneOf({makeObject(Superellipsoid{0, 1})})), std::exception);
}

} // namespace
} // namespace drt
