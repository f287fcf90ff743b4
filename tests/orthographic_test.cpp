// The orthographic camera: parallel rays, the image plane spanned by right and
// up, POV-Ray's angle rule, no lens; a rendered sphere has its exact projected
// radius; the .drt and POV-Ray front ends and the writer.
#include "lang/load.h"
#include "lang/writer.h"
#include "pov/load.h"
#include "render/camera.h"
#include "render/render.h"

#include <gtest/gtest.h>

#include <cmath>

namespace drt {
namespace {

CameraSpec orthoSpec() {
    CameraSpec spec;
    spec.orthographic = true;
    spec.location = {1, 2, -10};
    spec.right = Vec3(4, 0, 0);
    spec.up = {0, 3, 0};
    return spec;
}

TEST(Orthographic, RaysAreParallelAndStartOnTheImagePlane) {
    const ResolvedCamera cam = resolveCamera(orthoSpec(), 40, 30);
    for (int py : {0, 7, 29})
        for (int px : {0, 13, 39}) {
            const double x = px + 0.5, y = py + 0.5;
            const Ray ray = cam.generateRay(x, y, {0.3, 0.7}, 0);
            EXPECT_EQ(ray.direction, Vec3(0, 0, 1));
            EXPECT_NEAR(ray.origin.x, 1 + (x / 40 - 0.5) * 4, 1e-12);
            EXPECT_NEAR(ray.origin.y, 2 + (0.5 - y / 30) * 3, 1e-12);
            EXPECT_EQ(ray.origin.z, -10);
        }
    // A pixel's footprint is |right| / width by |up| / height: 0.1 x 0.1.
    const Ray a = cam.generateRay(10, 10, {}, 0), b = cam.generateRay(11, 11, {}, 0);
    EXPECT_NEAR(b.origin.x - a.origin.x, 0.1, 1e-12);
    EXPECT_NEAR(a.origin.y - b.origin.y, 0.1, 1e-12);
}

TEST(Orthographic, LookAtTurnsTheRaysAndAngleSetsTheWidthAtTheTarget) {
    CameraSpec spec = orthoSpec();
    spec.location = {0, 0, -10};
    spec.lookAt = Vec3(10, 0, 0); // 45 degrees to the right, at distance sqrt(200)
    spec.angle = 60;
    const ResolvedCamera cam = resolveCamera(spec, 40, 30);
    const Ray ray = cam.generateRay(20, 15, {}, 0);
    EXPECT_NEAR(ray.direction.x, ray.direction.z, 1e-12);
    EXPECT_NEAR(ray.direction.y, 0, 1e-12);
    // Width 2 d tan(30 deg), up scaled by the same factor (3/4 of it).
    const double width = 2 * std::sqrt(200.0) * std::tan(kPi / 6);
    EXPECT_NEAR(length(cam.right), width, 1e-12);
    EXPECT_NEAR(length(cam.up), width * 3 / 4, 1e-12);
    const Ray left = cam.generateRay(0, 15, {}, 0), right = cam.generateRay(40, 15, {}, 0);
    EXPECT_NEAR(length(right.origin - left.origin), width, 1e-9);
}

TEST(Orthographic, ApertureIsARenderError) {
    CameraSpec spec = orthoSpec();
    spec.aperture = 0.5;
    EXPECT_THROW(resolveCamera(spec, 10, 10), RenderError);
}

// Total emitted light over the image of a unit sphere that glows white.
double glowingSphereArea(double sphereZ, bool orthographic) {
    Scene scene;
    scene.camera.orthographic = orthographic;
    scene.camera.location = {0, 0, -10};
    scene.camera.right = Vec3(4, 0, 0);
    scene.camera.up = {0, 4, 0};
    scene.render.filter = "box";
    Object sphere;
    sphere.shape = Sphere{{0, 0, sphereZ}, 1};
    sphere.texture.edit().pigment.color = ColorFT{Color(1)};
    sphere.texture.edit().finish.ambient = Color(0);
    sphere.texture.edit().finish.diffuse = 0;
    sphere.texture.edit().finish.emission = Color(1);
    scene.objects.push_back(sphere);
    RenderOptions o;
    o.width = o.height = 80;
    o.samplesPerPixel = 64;
    o.threads = 1;
    const RenderResult r = render(scene, o);
    double sum = 0;
    for (int y = 0; y < 80; ++y)
        for (int x = 0; x < 80; ++x) sum += r.color.at(x, y, 0);
    return sum;
}

TEST(Orthographic, SphereHasItsExactProjectedRadiusAtAnyDistance) {
    // 80 pixels span 4 units: the unit sphere's disc has radius 20 pixels,
    // area 400 pi pixels, whatever its distance. 64 stratified samples per
    // pixel leave an error of well under 0.2% on the radius (measured 0.025%).
    for (double z : {0.0, 50.0}) {
        const double radius = std::sqrt(glowingSphereArea(z, true) / kPi);
        EXPECT_NEAR(radius, 20, 0.04) << z;
    }
    // The perspective camera with the same vectors shrinks it with distance.
    EXPECT_LT(glowingSphereArea(50, false), 0.5 * glowingSphereArea(0, false));
}

TEST(Orthographic, DrtLanguageAndWriter) {
    Diagnostics diags;
    const auto scene = loadSceneText("camera { orthographic location <0, 0, -5> right 4 * x up 3 * y }", "o.drt",
                                     diags);
    ASSERT_TRUE(scene) << diags.formatAll();
    EXPECT_TRUE(scene->camera.orthographic);
    const std::string text = writeDrtScene(*scene);
    EXPECT_NE(text.find("orthographic"), std::string::npos) << text;
    Diagnostics again;
    const auto back = loadSceneText(text, "back.drt", again);
    ASSERT_TRUE(back) << again.formatAll();
    EXPECT_TRUE(back->camera.orthographic);
    EXPECT_EQ(back->camera.right, scene->camera.right);
}

std::optional<Scene> loadPov(const std::string& text, Diagnostics& diags) {
    return loadPovSceneText(text, "o.pov", diags, PovOptions{});
}

TEST(Orthographic, PovRaysScalingRule) {
    // Neither up nor right: both scaled by |look_at - location| / |direction| = 10.
    Diagnostics d1;
    auto s = loadPov("camera { orthographic location <0, 0, -10> look_at 0 }", d1);
    ASSERT_TRUE(s) << d1.formatAll();
    EXPECT_TRUE(s->camera.orthographic);
    EXPECT_NEAR(length(*s->camera.right), 13.3, 1e-12);
    EXPECT_NEAR(length(s->camera.up), 10, 1e-12);
    // Up and right given, no angle: kept as written.
    Diagnostics d2;
    s = loadPov("camera { orthographic location <0, 0, -10> up 3 * y right 4 * x look_at 0 }", d2);
    ASSERT_TRUE(s) << d2.formatAll();
    EXPECT_NEAR(length(*s->camera.right), 4, 1e-12);
    EXPECT_NEAR(length(s->camera.up), 3, 1e-12);
    // With angle: the width is 2 d tan(angle / 2) even when up and right are given.
    Diagnostics d3;
    s = loadPov("camera { orthographic location <0, 0, -10> up 3 * y right 4 * x angle 60 look_at 0 }", d3);
    ASSERT_TRUE(s) << d3.formatAll();
    EXPECT_NEAR(length(*s->camera.right), 20 * std::tan(kPi / 6), 1e-12);
    EXPECT_NEAR(length(s->camera.up), 15 * std::tan(kPi / 6), 1e-12);
    // The angle is optional for the orthographic camera (it only asks for the scaling).
    Diagnostics d4;
    s = loadPov("camera { orthographic angle location <0, 0, -10> up 3 * y right 4 * x look_at 0 }", d4);
    ASSERT_TRUE(s) << d4.formatAll();
    EXPECT_NEAR(length(*s->camera.right), 40, 1e-12);
    EXPECT_EQ(d1.warningCount() + d2.warningCount() + d3.warningCount() + d4.warningCount(), 0);
}

// A camera straight above its look_at point (looking along the sky vector):
// POV-Ray keeps right as it is and turns up square to it and to the new
// direction (textures/pigments/transmitfx.pov); the renderer's look_at,
// which needs sky and direction apart, never sees such a camera.
TEST(Orthographic, PovCameraLookingAlongTheSkyKeepsRight) {
    Diagnostics d1;
    auto s = loadPov("camera { orthographic location 6 * y look_at 0 }", d1);
    ASSERT_TRUE(s) << d1.formatAll();
    EXPECT_FALSE(s->camera.lookAt);
    EXPECT_NEAR(length(normalize(s->camera.direction) - Vec3(0, -1, 0)), 0, 1e-12);
    EXPECT_NEAR(length(*s->camera.right - Vec3(1.33 * 6, 0, 0)), 0, 1e-12); // scaled by the distance 6
    EXPECT_NEAR(length(s->camera.up - Vec3(0, 0, 6)), 0, 1e-12);
    // A perspective camera too: it renders, with z up in the image.
    Diagnostics d2;
    s = loadPov("camera { location <0, 5, 0> look_at 0 angle 60 }\nsphere { <0, 0, 1>, 0.5 }", d2);
    ASSERT_TRUE(s) << d2.formatAll();
    const ResolvedCamera cam = resolveCamera(s->camera, 40, 30);
    const Ray centre = cam.generateRay(20, 15, {}, 0);
    EXPECT_NEAR(length(normalize(centre.direction) - Vec3(0, -1, 0)), 0, 1e-12);
    const Ray top = cam.generateRay(20, 0, {}, 0), rightEdge = cam.generateRay(40, 15, {}, 0);
    EXPECT_GT(top.direction.z, 0.1);
    EXPECT_GT(rightEdge.direction.x, 0.1);
}

TEST(Orthographic, PovFocalBlurIsIgnoredWithAWarning) {
    Diagnostics diags;
    auto s = loadPov("camera { orthographic location -10 * z look_at 0 aperture 0.4 blur_samples 10 }", diags);
    ASSERT_TRUE(s) << diags.formatAll();
    EXPECT_EQ(s->camera.aperture, 0);
    ASSERT_EQ(diags.warningCount(), 1);
    EXPECT_NE(diags.all()[0].message.find("orthographic"), std::string::npos);
    EXPECT_EQ(diags.all()[0].loc.line, 1);
}

} // namespace
} // namespace drt
