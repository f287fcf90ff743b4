// Compact meshes (scene/indexed_mesh.h) through the C++ API: validation,
// hits against closed forms (a tessellated sphere's silhouette area and
// normals), uv coordinates, per-triangle textures, instancing, robustness
// (degenerate triangles, scales from 1e-4 to 1e4) and uv_mapping.
#include "accel/accel.h"
#include "mesh_generators.h"
#include "render/pigment.h"
#include "render/render.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace drt {
namespace {

using test::makeObject;
using test::sceneOf;
using test::trace;


Mesh compact(std::shared_ptr<IndexedMesh> indexed) {
    Mesh m;
    m.indexed = std::move(indexed);
    return m;
}

// The unit square in x-y at z = 0 as two triangles, facing -z (toward a
// camera at negative z), uv = (x, y).
std::shared_ptr<IndexedMesh> unitSquare() {
    auto m = std::make_shared<IndexedMesh>();
    m->positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    m->indices = {0, 2, 1, 0, 3, 2};
    m->uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    padForEmbree(*m);
    return m;
}

Texture solid(Color rgb) {
    Texture t;
    t.pigment.color = ColorFT{rgb, 0, 0};
    t.finish.ambient = Color(1);
    t.finish.diffuse = 0;
    return t;
}

// ---------------------------------------------------------------- validation

TEST(IndexedMesh, ValidationNamesTheProblem) {
    IndexedMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.indices = {0, 1, 2};
    EXPECT_EQ(validateIndexedMesh(m, 0), "");
    m.indices = {0, 1, 3};
    EXPECT_NE(validateIndexedMesh(m, 0).find("vertex index 3 is out of range"), std::string::npos);
    m.indices = {0, 1};
    EXPECT_NE(validateIndexedMesh(m, 0).find("multiple of 3"), std::string::npos);
    m.indices = {0, 1, 2};
    m.positions[1].x = NAN;
    EXPECT_NE(validateIndexedMesh(m, 0).find("not finite"), std::string::npos);
    m.positions[1].x = 1;
    m.uvs = {{0, 0}};
    EXPECT_NE(validateIndexedMesh(m, 0).find("uv vectors"), std::string::npos);
    m.uvs.clear();
    m.faceTextures = {0, 0, 1};
    EXPECT_NE(validateIndexedMesh(m, 1).find("texture index 1 is out of range"), std::string::npos);
    m.faceTextures = {0, 0, kObjectTexture};
    EXPECT_EQ(validateIndexedMesh(m, 1), "");
}

TEST(IndexedMesh, InvalidMeshIsARenderErrorNamingTheObject) {
    auto m = unitSquare();
    m->indices[4] = 7;
    Object o = makeObject(compact(m));
    o.loc = {0, 3, 5};
    const Scene scene = sceneOf({o});
    try {
        test::buildAccelerator(scene);
        FAIL() << "no error";
    } catch (const RenderError& e) {
        EXPECT_NE(std::string(e.what()).find("line 3, column 5"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("vertex index 7"), std::string::npos) << e.what();
    }
}

// ---------------------------------------------------------------- hits

TEST(IndexedMesh, HitPointNormalAndUvMatchTheSquare) {
    const Scene scene = sceneOf({makeObject(compact(unitSquare()), Transform::translate({2, 0, 0}))});
    const Accelerator accel(scene);
    const auto hit = trace(accel, {2.25, 0.625, -3}, {0, 0, 1});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 3, 1e-12);
    EXPECT_NEAR(hit->point.x, 2.25, 1e-12);
    EXPECT_NEAR(hit->point.y, 0.625, 1e-12);
    EXPECT_NEAR(hit->point.z, 0, 1e-12);
    EXPECT_NEAR(hit->geometricNormal.z, -1, 1e-12); // wound to face -z
    ASSERT_TRUE(hit->hasUv);
    EXPECT_NEAR(hit->uv.x, 0.25, 1e-7);
    EXPECT_NEAR(hit->uv.y, 0.625, 1e-7);
    EXPECT_EQ(hit->object, &scene.objects[0]);
    EXPECT_FALSE(trace(accel, {0.5, 0.5, -3}, {0, 0, 1})); // the square moved away from here
}

TEST(IndexedMesh, MirroredAndInvertedPlacementsKeepTheWindingNormal) {
    Object mirrored = makeObject(compact(unitSquare()), Transform::scale({-1, 1, 1}));
    Object inverted = makeObject(compact(unitSquare()), Transform::translate({0, 0, 5}));
    inverted.inverse = true;
    const Scene scene = sceneOf({mirrored, inverted});
    const Accelerator accel(scene);
    const auto a = trace(accel, {-0.3, 0.4, -3}, {0, 0, 1});
    ASSERT_TRUE(a);
    EXPECT_NEAR(a->geometricNormal.z, -1, 1e-12);
    EXPECT_NEAR(a->uv.x, 0.3, 1e-7); // uv follows the object, not the mirror image
    const auto b = trace(accel, {0.3, 0.4, 10}, {0, 0, -1});
    ASSERT_TRUE(b);
    EXPECT_NEAR(b->point.z, 5, 1e-12);
    EXPECT_NEAR(b->geometricNormal.z, 1, 1e-12); // inverse flips it
}

TEST(IndexedMesh, CompactAndTextMeshesHitTheSamePoints) {
    // The same triangles as POV-Ray text would give them (double vertices)
    // and as a compact mesh: the hits agree to float rounding of the vertices.
    const auto sphere = test::sphereMesh(12, 24);
    Mesh text;
    for (const Float3& p : sphere->positions)
        text.vertices.push_back(p.toVec3());
    for (size_t i = 0; i < sphere->triangleCount(); ++i) {
        const auto t = sphere->triangle(i);
        text.triangles.push_back({int(t[0]), int(t[1]), int(t[2])});
    }
    const Transform place = Transform::scale({2, 1, 1}).then(Transform::rotate({10, 20, 30}));
    const Scene a = sceneOf({makeObject(compact(sphere), place)});
    const Scene b = sceneOf({makeObject(text, place)});
    const Accelerator ca(a), cb(b);
    std::mt19937 rng(7);
    for (int i = 0; i < 200; ++i) {
        const Vec3 origin = 5.0 * test::randomUnitVector(rng);
        const Vec3 dir = -origin + 0.5 * test::randomUnitVector(rng);
        const auto ha = trace(ca, origin, dir), hb = trace(cb, origin, dir);
        ASSERT_EQ(ha.has_value(), hb.has_value());
        if (!ha)
            continue;
        EXPECT_NEAR(ha->t, hb->t, 1e-6);
        EXPECT_GT(dot(ha->geometricNormal, hb->geometricNormal), 1 - 1e-9);
    }
}

// A tessellated unit sphere seen along z by a grid of parallel rays. Its
// silhouette is the convex hull of the projected vertices: the regular
// polygon of 2 rings sides through the meridians at x = +-cos(latitude), of
// area rings sin(pi / rings) (pi for the analytic sphere).
TEST(IndexedMesh, SphereSilhouetteAreaIsTheInscribedPolygons) {
    const int rings = 16;
    const Scene scene = sceneOf({makeObject(compact(test::sphereMesh(rings, 2 * rings)))});
    const Accelerator accel(scene);
    const int n = 500;
    const double half = 1.05, cell = 2 * half / n;
    int covered = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            if (trace(accel, {-half + (i + 0.5) * cell, -half + (j + 0.37) * cell, -5}, {0, 0, 1}))
                ++covered;
    const double polygon = rings * std::sin(kPi / rings); // 3.1214
    const double area = covered * cell * cell;
    // The grid's error: ~1500 boundary cells of area 1.8e-5 with errors of
    // either sign; 2e-3 is several times their spread, and ten times less
    // than the polygon's 0.020 shortfall from pi.
    EXPECT_NEAR(area, polygon, 2e-3);
    EXPECT_GT(kPi - area, 0.015);
}

// Smooth normals: interpolated from exact unit vertex normals, they stay within
// a triangle's angular size (2 pi / segments here) of the radial direction.
// Flat normals are the face's own, exactly.
TEST(IndexedMesh, SphereNormalsAreRadialWhenSmoothAndExactWhenFlat) {
    const int rings = 64, segments = 128;
    const auto smooth = test::sphereMesh(rings, segments, true);
    const auto flat = test::sphereMesh(rings, segments, false);
    const Scene a = sceneOf({makeObject(compact(smooth), Transform::scale(Vec3(3)))});
    const Scene b = sceneOf({makeObject(compact(flat), Transform::scale(Vec3(3)))});
    const Accelerator smoothAccel(a), flatAccel(b);
    std::mt19937 rng(5);
    double worstSmooth = 0, worstFlat = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3 origin = 10.0 * test::randomUnitVector(rng);
        const Vec3 dir = -origin + 2.0 * test::randomUnitVector(rng);
        const auto hs = trace(smoothAccel, origin, dir), hf = trace(flatAccel, origin, dir);
        ASSERT_EQ(hs.has_value(), hf.has_value());
        if (!hs)
            continue;
        worstSmooth = std::max(worstSmooth, length(hs->shadingNormal - normalize(hs->point)));
        const auto t = flat->triangle(hf->primitive);
        const Vec3 p0 = flat->positions[t[0]].toVec3(), p1 = flat->positions[t[1]].toVec3(),
                   p2 = flat->positions[t[2]].toVec3();
        const Vec3 face = normalize(cross(p1 - p0, p2 - p0));
        worstFlat = std::max(worstFlat, length(hf->shadingNormal - face));
        worstFlat = std::max(worstFlat, length(hf->geometricNormal - face));
        EXPECT_GT(dot(face, hf->point), 0); // wound outward
    }
    EXPECT_LT(worstSmooth, 2 * kPi / segments);
    EXPECT_LT(worstFlat, 1e-12);
}

TEST(IndexedMesh, DegenerateAndDuplicateTrianglesGiveNoNaN) {
    auto m = std::make_shared<IndexedMesh>();
    m->positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 2, 0}, {0, 0, 0}};
    // a proper triangle twice, a zero-area line, a point (three equal corners)
    m->indices = {0, 2, 1, 0, 2, 1, 0, 3, 3, 4, 4, 0};
    m->normals = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}}; // zero normals: flat fallback
    padForEmbree(*m);
    const Scene scene = sceneOf({makeObject(compact(m))});
    const Accelerator accel(scene);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-0.5, 2.5);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const auto hit = trace(accel, {u(rng), u(rng), -1}, {0, 0, 1});
        if (!hit)
            continue;
        ++hits;
        ASSERT_TRUE(isFinite(hit->point) && isFinite(hit->geometricNormal) && isFinite(hit->shadingNormal));
        EXPECT_NEAR(std::fabs(hit->shadingNormal.z), 1, 1e-12);
    }
    EXPECT_GT(hits, 100);
}

// Secondary rays leave a sphere mesh cleanly at every scale: reflected rays
// from outside miss everything (the sphere is convex), refracted ones cross
// to the far side.
TEST(IndexedMesh, NoSelfIntersectionFrom1eMinus4To1e4) {
    for (double scale : {1e-4, 1e-2, 1.0, 1e2, 1e4}) {
        const Vec3 centre{3 * scale, -2 * scale, 5 * scale};
        const Scene scene =
            sceneOf({makeObject(compact(test::sphereMesh(48, 96)),
                                Transform::scale(Vec3(scale)).then(Transform::translate(centre)))});
        const Accelerator accel(scene);
        std::mt19937 rng(11);
        int rays = 0, selfHits = 0;
        for (int i = 0; i < 300; ++i) {
            const Vec3 origin = centre + 4 * scale * test::randomUnitVector(rng);
            const auto hit =
                trace(accel, origin, centre + 0.5 * scale * test::randomUnitVector(rng) - origin);
            ASSERT_TRUE(hit) << "scale " << scale;
            test::countSelfHits(accel, *hit, origin, scale, rng, rays, selfHits);
        }
        EXPECT_EQ(selfHits, 0) << "scale " << scale << ": " << selfHits << " of " << rays;
    }
}

// ---------------------------------------------------------------- instancing

TEST(IndexedMesh, ObjectsSharingAMeshShareOneBvh) {
    const auto sphere = test::sphereMesh(16, 32);
    std::vector<Object> objects;
    for (int i = 0; i < 100; ++i)
        objects.push_back(makeObject(compact(sphere), Transform::translate({3.0 * i, 0, 0})));
    const Scene scene = sceneOf(objects);
    const Accelerator accel(scene);
    EXPECT_EQ(accel.meshStats().sharedMeshes, 1u);
    EXPECT_EQ(accel.meshStats().placements, 100u);
    for (int i : {0, 37, 99}) {
        const auto hit = trace(accel, {3.0 * i, 0, -5}, {0, 0, 1});
        ASSERT_TRUE(hit);
        EXPECT_EQ(hit->object, &scene.objects[size_t(i)]);
        EXPECT_NEAR(hit->point.z, -1, 1e-3);
        EXPECT_NEAR(hit->point.x, 3.0 * i, 1e-9);
    }
}

TEST(IndexedMesh, NoShadowPlacementIsSkippedByShadowRays) {
    Object a = makeObject(compact(unitSquare()));
    a.noShadow = true;
    const Scene scene = sceneOf({a});
    const Accelerator accel(scene);
    Ray ray;
    ray.origin = {0.5, 0.5, -1};
    ray.direction = {0, 0, 1};
    EXPECT_FALSE(accel.occluded(ray));
    Hit hit;
    EXPECT_TRUE(accel.intersect(ray, hit));
}

TEST(IndexedMesh, MovingCompactMeshIsCopiedAndStillHasUvs) {
    Object o = makeObject(compact(unitSquare()));
    o.motion = {MotionStage{motionTo({2, 0, 0}), Transform()}};
    const Scene scene = sceneOf({o});
    const Accelerator accel(scene);
    EXPECT_EQ(accel.meshStats().sharedMeshes, 0u);
    Ray ray;
    ray.origin = {1.25, 0.5, -1};
    ray.direction = {0, 0, 1};
    ray.time = 0.5; // the square has moved by 1
    Hit hit;
    ASSERT_TRUE(accel.intersect(ray, hit));
    ASSERT_TRUE(hit.hasUv);
    EXPECT_NEAR(hit.uv.x, 0.25, 1e-6);
}

// ---------------------------------------------------------------- textures and uv_mapping

TEST(IndexedMesh, TrianglesShowTheirOwnTextures) {
    auto m = unitSquare();
    m->faceTextures = {0, 0, 0, kObjectTexture, kObjectTexture, kObjectTexture};
    Mesh mesh = compact(m);
    mesh.textures = {solid({1, 0, 0})};
    Object o = makeObject(mesh);
    o.texture = solid({0, 0, 1});
    Scene scene = sceneOf({o});
    scene.camera.location = {0.5, 0.5, -2};
    scene.camera.direction = {0, 0, 1};
    scene.camera.right = Vec3{1e-9, 0, 0};
    scene.camera.up = Vec3{0, 1e-9, 0};
    RenderOptions options;
    options.width = options.height = 1;
    options.samplesPerPixel = 1;
    // Triangle 0 (0, 2, 1) is below the diagonal x = y, triangle 1 above it.
    scene.camera.location = {0.7, 0.2, -2};
    const RenderResult below = render(scene, options);
    EXPECT_NEAR(below.color.at(0, 0, 0), 1, 1e-6);
    EXPECT_NEAR(below.color.at(0, 0, 2), 0, 1e-6);
    scene.camera.location = {0.2, 0.7, -2};
    const RenderResult above = render(scene, options);
    EXPECT_NEAR(above.color.at(0, 0, 0), 0, 1e-6);
    EXPECT_NEAR(above.color.at(0, 0, 2), 1, 1e-6);
}

TEST(IndexedMesh, CornerTexturesBlendByBarycentricWeight) {
    auto m = unitSquare();
    m->faceTextures = {0, 1, 1, 0, 0, 0}; // corner 0 (0,0) red, corners (1,1) and (1,0) green
    Mesh mesh = compact(m);
    mesh.textures = {solid({1, 0, 0}), solid({0, 1, 0})};
    Scene scene = sceneOf({makeObject(mesh)});
    scene.camera.direction = {0, 0, 1};
    scene.camera.right = Vec3{1e-9, 0, 0};
    scene.camera.up = Vec3{0, 1e-9, 0};
    scene.camera.location = {0.75, 0.25, -2}; // weights: (0,0) 0.25, (1,1) 0.25, (1,0) 0.5
    RenderOptions options;
    options.width = options.height = 1;
    const RenderResult r = render(scene, options);
    EXPECT_NEAR(r.color.at(0, 0, 0), 0.25, 1e-6);
    EXPECT_NEAR(r.color.at(0, 0, 1), 0.75, 1e-6);
}

TEST(UvMapping, CheckerFollowsUvNotSpace) {
    Pigment checker;
    checker.pattern = PatternKind::Checker;
    checker.uvMapping = true;
    checker.children.resize(2);
    checker.children[0].color = ColorFT{Color(1, 0, 0), 0, 0};
    checker.children[1].color = ColorFT{Color(0, 0, 1), 0, 0};
    checker.toWorld = Transform::scale(Vec3(0.5));
    transformPigmentSpaces(checker, Transform::translate({0.5, 7, 3})); // the object's move: ignored
    const Vec3 a{0.25, 0.25, 0}, b{0.75, 0.25, 0};
    EXPECT_EQ(evaluatePigment(checker, {100, 100, 100}, &a).rgb.r, 1);
    EXPECT_EQ(evaluatePigment(checker, {100, 100, 100}, &b).rgb.b, 1);
    // No uv on the surface: evaluated at uv (0, 0).
    EXPECT_EQ(evaluatePigment(checker, {100, 100, 100}).rgb.r, 1);
}

TEST(UvMapping, UvMappedCheckerOnAMeshHasItsKnownColourAtAPixel) {
    Texture t = solid({0, 0, 0});
    Pigment& p = t.pigment;
    p.pattern = PatternKind::Checker;
    p.uvMapping = true;
    p.children.resize(2);
    p.children[0].color = ColorFT{Color(1, 0, 0), 0, 0};
    p.children[1].color = ColorFT{Color(0, 0, 1), 0, 0};
    p.toWorld = Transform::scale(Vec3(0.25)); // 4 x 4 squares over the mesh
    Object o =
        makeObject(compact(unitSquare()), Transform::scale({4, 2, 1}).then(Transform::rotate({0, 0, 30})));
    o.texture = t;
    transformTextureSpaces(o.texture.edit(), o.transform);
    Scene scene = sceneOf({o});
    // Aim at uv (0.375, 0.125): cell (1, 0), odd: blue. (0.125, 0.125): red.
    const auto aim = [&](double u, double v) {
        scene.camera.location = o.transform.point({u, v, -1});
        scene.camera.direction = o.transform.vector({0, 0, 1});
        scene.camera.right = Vec3{1e-9, 0, 0};
        scene.camera.up = Vec3{0, 1e-9, 0};
        RenderOptions options;
        options.width = options.height = 1;
        return render(scene, options);
    };
    const RenderResult blue = aim(0.375, 0.125), red = aim(0.125, 0.125);
    EXPECT_NEAR(blue.color.at(0, 0, 2), 1, 1e-6);
    EXPECT_NEAR(blue.color.at(0, 0, 0), 0, 1e-6);
    EXPECT_NEAR(red.color.at(0, 0, 0), 1, 1e-6);
}

} // namespace
} // namespace drt
