// POV-Ray's blob: a single component against the closed-form sphere, the
// field value at hits of overlapping components, carving by negative
// strength, cylinder components, component transforms, CSG, self-hits of
// spawned rays, the .drt language (errors in parser_errors_test.cpp) and the
// POV front end.
#include "accel/accel.h"
#include "accel/blob_shape.h"
#include "accel/shapes.h"
#include "lang/load.h"
#include "lang/writer.h"
#include "pov/load.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>

namespace drt {
namespace {

using accel::BlobGeometry;
using accel::Crossing;

Vec3 randomUnit(std::mt19937& rng) {
    std::normal_distribution<double> g;
    for (;;) {
        const Vec3 v{g(rng), g(rng), g(rng)};
        if (length(v) > 1e-6) return normalize(v);
    }
}

BlobComponent ball(Vec3 centre, double radius, double strength, Transform t = {}) {
    BlobComponent c;
    c.center = centre;
    c.radius = radius;
    c.strength = strength;
    c.transform = t;
    return c;
}

BlobComponent capsule(Vec3 a, Vec3 b, double radius, double strength) {
    BlobComponent c = ball(a, radius, strength);
    c.kind = BlobComponent::Kind::Cylinder;
    c.end = b;
    return c;
}

Blob blobOf(double threshold, std::vector<BlobComponent> components) {
    Blob b;
    b.threshold = threshold;
    b.components = std::move(components);
    return b;
}

// The field written out directly from the definition, for comparison.
double closedFormField(const std::vector<BlobComponent>& cs, const Vec3& p) {
    double sum = 0;
    for (const BlobComponent& c : cs) {
        const Vec3 q = c.transform.inversePoint(p);
        double d2;
        if (c.kind == BlobComponent::Kind::Sphere) {
            d2 = dot(q - c.center, q - c.center);
        } else {
            const Vec3 axis = c.end - c.center;
            const double h = std::clamp(dot(q - c.center, axis) / dot(axis, axis), 0.0, 1.0);
            const Vec3 nearest = c.center + h * axis;
            d2 = dot(q - nearest, q - nearest);
        }
        const double u = 1 - d2 / (c.radius * c.radius);
        if (u > 0) sum += c.strength * u * u;
    }
    return sum;
}

TEST(BlobIntersect, SingleComponentIsTheClosedFormSphere) {
    // s (1 - (d/r)^2)^2 = t  <=>  d = r sqrt(1 - sqrt(t / s)).
    std::mt19937 rng(21);
    std::uniform_real_distribution<double> u(-1, 1);
    const struct { Vec3 centre; double radius, strength, threshold; } cases[] = {
        {{0, 0, 0}, 1, 1, 0.5}, {{1, -2, 3}, 2.5, 3, 0.2}, {{-0.5, 0.25, 4}, 0.3, 0.7, 0.6}};
    int hits = 0;
    for (const auto& c : cases) {
        const BlobGeometry blob(blobOf(c.threshold, {ball(c.centre, c.radius, c.strength)}));
        const double R = c.radius * std::sqrt(1 - std::sqrt(c.threshold / c.strength));
        for (int i = 0; i < 2000; ++i) {
            const Vec3 target = c.centre + Vec3{u(rng), u(rng), u(rng)} * (1.2 * R);
            const Vec3 origin = target + randomUnit(rng) * (3 + 5 * (u(rng) + 1)) * c.radius;
            const Vec3 d = (target - origin) * (0.5 + u(rng) * 0.25);
            std::vector<Crossing> out;
            blob.intersect(origin, d, out);
            // Closed form: |o + t d - c|^2 = R^2.
            const Vec3 w = origin - c.centre;
            const double a = dot(d, d), b = dot(w, d), disc = b * b - a * (dot(w, w) - R * R);
            if (disc <= 1e-12 * a * R * R) { // graze or miss: no robust comparison
                if (disc < -1e-9 * a * R * R) {
                    EXPECT_TRUE(out.empty()) << i;
                }
                continue;
            }
            ASSERT_EQ(out.size(), 2u) << i;
            const double root = std::sqrt(disc);
            const double t0 = (-b - root) / a, t1 = (-b + root) / a;
            EXPECT_NEAR(out[0].t, t0, 1e-9 * std::fabs(t0) + 1e-12);
            EXPECT_NEAR(out[1].t, t1, 1e-9 * std::fabs(t1) + 1e-12);
            for (int k = 0; k < 2; ++k) {
                const Vec3 expected = normalize(origin + out[size_t(k)].t * d - c.centre);
                EXPECT_LT(length(normalize(out[size_t(k)].normal) - expected), 1e-9) << i;
            }
            EXPECT_TRUE(blob.inside(c.centre + Vec3{0.99 * R, 0, 0}));
            EXPECT_FALSE(blob.inside(c.centre + Vec3{0, 1.01 * R, 0}));
            ++hits;
        }
    }
    EXPECT_GT(hits, 3000);
}

// Hits of overlapping components (spheres, a cylinder, a transformed one, a
// negative one) lie where the closed-form field equals the threshold, the
// crossings alternate inside and outside, and normals are minus the gradient
// (compared with central differences of the closed form).
TEST(BlobIntersect, HitsLieOnTheThresholdAndAlternateInsideOutside) {
    const std::vector<BlobComponent> cs = {
        ball({0, 0, 0}, 1.5, 1), ball({1, 0.2, 0}, 1.2, 1.5), capsule({-1, -1, 0}, {1, -1.2, 0.5}, 0.9, 1.2),
        ball({0, 0, 0}, 1, 1, Transform::scale({2, 0.5, 1}).then(Transform::rotate({0, 0, 30})).then(
                                    Transform::translate({0, 1.2, 0}))),
        ball({0.3, 0.1, -0.6}, 0.8, -1.5)};
    const double threshold = 0.4;
    const BlobGeometry blob(blobOf(threshold, cs));
    std::mt19937 rng(22);
    std::uniform_real_distribution<double> u(-1, 1);
    int hits = 0;
    double worst = 0;
    for (int i = 0; i < 3000; ++i) {
        const Vec3 target{u(rng) * 2, u(rng) * 2, u(rng) * 1.5};
        const Vec3 origin = target + randomUnit(rng) * 8;
        const Vec3 d = target - origin;
        std::vector<Crossing> out;
        blob.intersect(origin, d, out);
        ASSERT_EQ(out.size() % 2, 0u) << i; // a bounded solid is entered as often as left
        for (size_t k = 0; k < out.size(); ++k) {
            const Vec3 p = origin + out[k].t * d;
            worst = std::max(worst, std::fabs(closedFormField(cs, p) - threshold));
            if (k > 0) {
                ASSERT_GT(out[k].t, out[k - 1].t);
            }
            // Midway to the next crossing: inside after an entry.
            if (k + 1 < out.size()) {
                const Vec3 mid = origin + 0.5 * (out[k].t + out[k + 1].t) * d;
                EXPECT_EQ(blob.inside(mid), k % 2 == 0) << i << " " << k;
            }
            const double h = 1e-6;
            Vec3 g;
            for (int axis = 0; axis < 3; ++axis) {
                Vec3 e(0);
                e[axis] = h;
                g[axis] = (closedFormField(cs, p + e) - closedFormField(cs, p - e)) / (2 * h);
            }
            if (length(g) > 1e-3) {
                EXPECT_LT(length(normalize(out[k].normal) + normalize(g)), 1e-5) << i << " " << k;
            }
            EXPECT_EQ(dot(out[k].normal, d) < 0, k % 2 == 0) << i << " " << k; // entries face the ray
            ++hits;
        }
    }
    EXPECT_LT(worst, 1e-9);
    EXPECT_GT(hits, 2000);
    std::printf("blob: largest |field - threshold| at %d hits: %g\n", hits, worst);
}

TEST(BlobIntersect, NegativeComponentCarvesAHole) {
    // Unit-strength sphere of radius 2, threshold 0.25: surface at
    // d = 2 sqrt(1 - 0.5) = sqrt(2). A strength -1 component of radius 0.5 at the
    // centre makes the field there 1 - 1 = 0 < 0.25: a hollow.
    const BlobGeometry blob(blobOf(0.25, {ball({0, 0, 0}, 2, 1), ball({0, 0, 0}, 0.5, -1)}));
    EXPECT_FALSE(blob.inside({0, 0, 0}));
    EXPECT_TRUE(blob.inside({1, 0, 0}));
    std::vector<Crossing> out;
    blob.intersect({-5, 0, 0}, {1, 0, 0}, out);
    ASSERT_EQ(out.size(), 4u);
    EXPECT_NEAR(out[0].t, 5 - std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(out[3].t, 5 + std::sqrt(2.0), 1e-12);
    // Inner wall: (1 - x^2/4)^2 - (1 - 4 x^2)^2 = 0.25, symmetric about 0.
    const double x = 5 - out[1].t;
    EXPECT_NEAR(std::pow(1 - x * x / 4, 2) - std::pow(1 - 4 * x * x, 2), 0.25, 1e-12);
    EXPECT_NEAR(out[2].t - 5, x, 1e-12);
    EXPECT_GT(out[1].normal.x, 0); // the hollow's wall faces into the hollow
}

TEST(BlobIntersect, CylinderComponentIsACapsule) {
    // One cylinder component: the surface is the capsule of radius
    // r sqrt(1 - sqrt(t/s)) around the segment.
    const double r = 1, s = 1, t = 0.5625; // R = sqrt(1 - 0.75) = 0.5
    const BlobGeometry blob(blobOf(t, {capsule({0, 0, 0}, {0, 3, 0}, r, s)}));
    std::vector<Crossing> out;
    blob.intersect({-4, 1.5, 0}, {1, 0, 0}, out); // across the body
    ASSERT_EQ(out.size(), 2u);
    EXPECT_NEAR(out[0].t, 3.5, 1e-12);
    EXPECT_NEAR(out[1].t, 4.5, 1e-12);
    blob.intersect({0.3, -4, 0}, {0, 1, 0}, out); // along the axis through both ends
    ASSERT_EQ(out.size(), 2u);
    EXPECT_NEAR(out[0].t, 4 - std::sqrt(0.25 - 0.09), 1e-12);
    EXPECT_NEAR(out[1].t, 7 + std::sqrt(0.25 - 0.09), 1e-12);
    EXPECT_LT(length(normalize(out[1].normal) - normalize(Vec3{0.3, std::sqrt(0.16), 0})), 1e-9);
    blob.intersect({0.6, -4, 0}, {0, 1, 0}, out); // parallel, outside
    EXPECT_TRUE(out.empty());
}

TEST(BlobIntersect, TranslatedAndScaledComponentsMatchMovedOnes) {
    const std::vector<BlobComponent> moved = {ball({1, 2, 3}, 2, 1), ball({1, 3, 3}, 2, 1)};
    const Transform shift = Transform::translate({1, 2, 3});
    const std::vector<BlobComponent> viaTransform = {ball({0, 0, 0}, 1, 1, Transform::scale(Vec3(2)).then(shift)),
                                                     ball({0, 0.5, 0}, 1, 1, Transform::scale(Vec3(2)).then(shift))};
    const BlobGeometry a(blobOf(0.6, moved)), b(blobOf(0.6, viaTransform));
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> u(-1, 1);
    int compared = 0;
    for (int i = 0; i < 1000; ++i) {
        const Vec3 target = Vec3{1, 2.5, 3} + Vec3{u(rng), u(rng), u(rng)} * 2;
        const Vec3 origin = target + randomUnit(rng) * 10;
        std::vector<Crossing> ca, cb;
        a.intersect(origin, target - origin, ca);
        b.intersect(origin, target - origin, cb);
        ASSERT_EQ(ca.size(), cb.size()) << i;
        for (size_t k = 0; k < ca.size(); ++k, ++compared) {
            EXPECT_NEAR(ca[k].t, cb[k].t, 1e-9);
            EXPECT_LT(length(normalize(ca[k].normal) - normalize(cb[k].normal)), 1e-9);
        }
    }
    EXPECT_GT(compared, 500);
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool sameBits(const Vec3& a, const Vec3& b) { return sameBits(a.x, b.x) && sameBits(a.y, b.y) && sameBits(a.z, b.z); }

// A blob of many components takes only those a line or point may meet from a
// bounding-box hierarchy; the crossings, field and gradient must be those of
// testing every component, to the bit, for lines near and far (where the
// hierarchy's margin for rounding grows), grazing ones and points on and off
// the surface.
TEST(BlobIntersect, SpatialIndexGivesTheResultsOfTestingEveryComponent) {
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> u(-1, 1);
    Blob blob;
    blob.threshold = 0.6;
    for (int i = 0; i < 300; ++i) // a cloud of small spheres, POV-Ray's logo blob's kind
        blob.components.push_back(ball(Vec3(u(rng), u(rng), 0.3 * u(rng)) * 2, 0.08 + 0.1 * (u(rng) + 1), 1));
    blob.components.push_back(ball(Vec3(0.5, 0, 0), 0.5, -0.5, Transform::scale(Vec3(1, 2, 0.5))));
    BlobComponent rod;
    rod.kind = BlobComponent::Kind::Cylinder;
    rod.center = Vec3(-2, -1, 0);
    rod.end = Vec3(2, 1, 0.2);
    rod.radius = 0.15;
    blob.components.push_back(rod);
    const BlobGeometry indexed(blob), every(blob, false);
    std::vector<Crossing> got, expected;
    int crossings = 0;
    for (int ray = 0; ray < 3000; ++ray) {
        const double distance = ray % 10 == 1 ? 1e3 : ray % 10 == 2 ? 1e6 : 5;
        const Vec3 target = Vec3(u(rng), u(rng), 0.3 * u(rng)) * 2;
        Vec3 o = target + randomUnit(rng) * distance;
        Vec3 d = target - o;
        if (ray % 10 == 3) d = Vec3(0, d.y, d.z); // across the x slabs
        if (ray % 10 == 4) { // grazing a component: through a point at its radius
            const BlobComponent& c = blob.components[size_t(ray) % 300];
            o = c.center + Vec3(0, c.radius, 0) - Vec3(5, 0, 0) + Vec3(0, 0, 1e-9 * u(rng));
            d = Vec3(1, 0, 0);
        }
        indexed.intersect(o, d, got);
        every.intersect(o, d, expected);
        ASSERT_EQ(got.size(), expected.size()) << "ray " << ray;
        for (size_t i = 0; i < got.size(); ++i) {
            ASSERT_TRUE(sameBits(got[i].t, expected[i].t)) << "ray " << ray;
            ASSERT_TRUE(sameBits(got[i].normal, expected[i].normal)) << "ray " << ray;
        }
        crossings += int(got.size());
        const Vec3 p = ray % 2 == 0 && !got.empty() ? o + got[0].t * d : target + randomUnit(rng) * 0.1;
        ASSERT_TRUE(sameBits(indexed.field(p), every.field(p)));
        ASSERT_TRUE(sameBits(indexed.gradient(p), every.gradient(p)));
        ASSERT_EQ(indexed.inside(p), every.inside(p));
    }
    EXPECT_GT(crossings, 3000);
}

TEST(BlobIntersect, BadBlobsAreRejected) {
    EXPECT_THROW(BlobGeometry(blobOf(1, {})), std::invalid_argument);
    EXPECT_THROW(BlobGeometry(blobOf(0, {ball({}, 1, 1)})), std::invalid_argument);
    EXPECT_THROW(BlobGeometry(blobOf(1, {ball({}, 0, 1)})), std::invalid_argument);
    EXPECT_THROW(BlobGeometry(blobOf(1, {capsule({1, 1, 1}, {1, 1, 1}, 1, 1)})), std::invalid_argument);
}

// ------------------------------------------------------------ through the Accelerator

using test::makeObject;
using test::sceneOf;

TEST(BlobAccel, DifferenceWithABoxMatchesTheClosedFormSphere) {
    // difference { single-component blob (a sphere of radius 1), box x > 0 }:
    // against the same with drt's sphere.
    auto differenceOf = [](Shape first) {
        Csg csg;
        csg.op = Csg::Op::Difference;
        csg.children = {makeObject(std::move(first)), makeObject(Box{{0, -2, -2}, {2, 2, 2}})};
        return makeObject(csg, Transform::rotate({10, 20, 30}).then(Transform::translate({1, 2, 3})));
    };
    const double R = 2 * std::sqrt(1 - std::sqrt(0.25 / 1)); // radius 2, threshold 0.25: sqrt(2)
    const Scene blobSceneScene = sceneOf({differenceOf(blobOf(0.25, {ball({0, 0, 0}, 2, 1)}))});
    const Accelerator blobScene(blobSceneScene);
    const Scene sphereSceneScene = sceneOf({differenceOf(Sphere{{0, 0, 0}, R})});
    const Accelerator sphereScene(sphereSceneScene);
    const Transform place = Transform::rotate({10, 20, 30}).then(Transform::translate({1, 2, 3}));
    std::mt19937 rng(24);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        Ray ray;
        const Vec3 target = place.point({u(rng), u(rng), u(rng)});
        ray.origin = target + randomUnit(rng) * 8;
        ray.direction = target - ray.origin;
        Hit a, b;
        const bool ha = blobScene.intersect(ray, a), hb = sphereScene.intersect(ray, b);
        ASSERT_EQ(ha, hb) << i;
        if (!ha) continue;
        ++hits;
        EXPECT_NEAR(a.t, b.t, 1e-9);
        EXPECT_LT(length(a.geometricNormal - b.geometricNormal), 1e-9);
    }
    EXPECT_GT(hits, 1000);
}

TEST(BlobAccel, SpawnedRaysDoNotReHitTheirSurface) {
    std::mt19937 rng(25);
    std::uniform_real_distribution<double> u(-1, 1);
    const Blob shape = blobOf(0.5, {ball({-0.5, 0, 0}, 1, 1), ball({0.5, 0, 0}, 1, 1),
                                    capsule({0, -0.6, 0}, {0, 0.6, 0.3}, 0.6, 1)});
    int rays = 0, selfHits = 0;
    for (double scale : {1e-3, 1.0, 1e3})
        for (double offset : {0.0, 1e4}) {
            const Transform t =
                Transform::rotate({10, 20, 30}).then(Transform::scale(Vec3(scale))).then(Transform::translate(Vec3(offset)));
            const Scene accelScene = sceneOf({makeObject(shape, t)});
            const Accelerator accel(accelScene);
            for (int i = 0; i < 400; ++i) {
                Ray primary;
                const Vec3 target = t.point({u(rng), u(rng) * 0.7, u(rng) * 0.7});
                primary.origin = target + randomUnit(rng) * (4 * scale);
                primary.direction = target - primary.origin;
                Hit hit;
                if (!accel.intersect(primary, hit)) continue;
                for (int side : {1, -1}) {
                    const Vec3 outward =
                        dot(hit.geometricNormal, primary.direction) < 0 ? hit.geometricNormal : -hit.geometricNormal;
                    Vec3 dir = randomUnit(rng);
                    if (dot(dir, outward) * side < 0) dir = -dir;
                    Ray spawned;
                    spawned.direction = dir;
                    spawned.origin = Accelerator::offsetOrigin(hit, dir);
                    Hit again;
                    ++rays;
                    if (accel.intersect(spawned, again) && length(again.point - hit.point) < 1e-4 * scale) ++selfHits;
                }
            }
        }
    EXPECT_EQ(selfHits, 0) << "self-hits among " << rays << " spawned rays";
    EXPECT_GT(rays, 3000);
    std::printf("blob self-intersection: %d re-hits in %d spawned rays\n", selfHits, rays);
}

// ------------------------------------------------------------ front ends

TEST(DrtBlob, ParsesAndRoundTripsBitIdentically) {
    const std::string text = R"(
camera { location <0, 2, -8> look_at <0, 0, 0> }
light_source { <5, 10, -10>, rgb 1 }
blob { threshold 0.6
  sphere { <0, 0, 0>, 1, 1 }
  sphere { <0.75, 0, 0>, 1 / 3, strength -0.7 translate <0, 0.1, 0> scale <1, 2, 1> }
  cylinder { <-1, 0, 0>, <1, 0.5, 0.1>, 0.45, 2 rotate <10, 20, 30> }
  sturm hierarchy off
  pigment { rgb <1, 0.4, 0.3> } translate x }
blob { sphere { 0, 1, 1 } }
)";
    Diagnostics diags;
    const std::optional<Scene> scene = loadSceneText(text, "a.drt", diags, ".");
    ASSERT_TRUE(scene) << diags.formatAll();
    ASSERT_EQ(scene->objects.size(), 2u);
    const Blob& b = std::get<Blob>(scene->objects[0].shape);
    EXPECT_EQ(b.threshold, 0.6);
    ASSERT_EQ(b.components.size(), 3u);
    EXPECT_EQ(b.components[1].radius, 1.0 / 3);
    EXPECT_EQ(b.components[1].strength, -0.7);
    EXPECT_EQ(b.components[1].transform.point({0, 0, 0}), Vec3(0, 0.2, 0));
    EXPECT_EQ(b.components[2].kind, BlobComponent::Kind::Cylinder);
    EXPECT_TRUE(b.sturm);
    EXPECT_FALSE(b.hierarchy);
    EXPECT_EQ(std::get<Blob>(scene->objects[1].shape).threshold, 1.0); // POV-Ray's default
    const std::string written = writeDrtScene(*scene);
    Diagnostics again;
    const std::optional<Scene> reread = loadSceneText(written, "b.drt", again, ".");
    ASSERT_TRUE(reread) << again.formatAll() << written;
    EXPECT_EQ(writeDrtScene(*reread), written);
    for (size_t i = 0; i < scene->objects.size(); ++i) {
        const Blob& x = std::get<Blob>(scene->objects[i].shape);
        const Blob& y = std::get<Blob>(reread->objects[i].shape);
        EXPECT_EQ(x.threshold, y.threshold);
        EXPECT_EQ(x.sturm, y.sturm);
        EXPECT_EQ(x.hierarchy, y.hierarchy);
        ASSERT_EQ(x.components.size(), y.components.size());
        for (size_t k = 0; k < x.components.size(); ++k) {
            const BlobComponent &p = x.components[k], &q = y.components[k];
            EXPECT_EQ(p.kind, q.kind);
            EXPECT_EQ(p.center, q.center);
            EXPECT_EQ(p.end, q.end);
            EXPECT_EQ(p.radius, q.radius);
            EXPECT_EQ(p.strength, q.strength);
            EXPECT_TRUE(p.transform.matrix() == q.transform.matrix() &&
                        p.transform.inverseMatrix() == q.transform.inverseMatrix());
        }
    }
}

TEST(PovBlob, ComponentsTransformsAndOldSyntaxAreRead) {
    const std::string text = R"(
camera { location <0, 2, -8> look_at <0, 0, 0> }
blob {
  threshold 0.65
  sphere { <0, 0, 0>, 1, strength 1 translate <1, 0, 0> }
  sphere { <0, 1, 0>, 1.5, 1 pigment { rgb 1 } }
  cylinder { <-1, 0, 0>, <1, 0, 0>, 0.5, -2 }
  component 1, 0.8, <0, 0, 2>
  sturm
  pigment { rgb <1, 0, 0> }
}
)";
    Diagnostics diags;
    const std::optional<Scene> scene = loadPovSceneText(text, "s.pov", diags);
    ASSERT_TRUE(scene) << diags.formatAll();
    ASSERT_EQ(scene->objects.size(), 1u);
    const Blob& b = std::get<Blob>(scene->objects[0].shape);
    EXPECT_EQ(b.threshold, 0.65);
    ASSERT_EQ(b.components.size(), 4u);
    EXPECT_EQ(b.components[0].transform.point({0, 0, 0}), Vec3(1, 0, 0));
    EXPECT_EQ(b.components[2].kind, BlobComponent::Kind::Cylinder);
    EXPECT_EQ(b.components[2].strength, -2);
    EXPECT_EQ(b.components[3].center, Vec3(0, 0, 2));
    EXPECT_EQ(b.components[3].radius, 0.8);
    EXPECT_TRUE(b.sturm);
    // The component's pigment: one warning naming where it is.
    ASSERT_EQ(diags.warningCount(), 1) << diags.formatAll();
    EXPECT_NE(diags.formatAll().find("s.pov:6:"), std::string::npos) << diags.formatAll();
    EXPECT_NE(diags.formatAll().find("textures of blob components are ignored"), std::string::npos);
}

TEST(PovBlob, BadBlobsAreErrorsWithLocations) {
    const struct { const char* source; const char* message; int line; } cases[] = {
        {"blob { threshold 1 }", "a blob needs at least one sphere or cylinder component", 1},
        {"blob {\n sphere { 0, -1, 1 } }", "blob component radius must be positive, got -1", 2},
        {"blob { threshold -1 sphere { 0, 1, 1 } }", "the blob threshold must be positive, got -1", 1},
        {"blob {\n\n cylinder { 0, 0, 1, 1 } }", "a blob cylinder needs two different end points", 3},
    };
    for (const auto& c : cases) {
        Diagnostics diags;
        EXPECT_FALSE(loadPovSceneText(c.source, "e.pov", diags)) << c.source;
        ASSERT_GE(diags.errorCount(), 1) << c.source;
        EXPECT_EQ(diags.all()[0].message, c.message) << c.source;
        EXPECT_EQ(diags.all()[0].loc.line, c.line) << c.source;
    }
}

} // namespace
} // namespace drt
