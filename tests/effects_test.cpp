// Exact (bit-for-bit) limits of the distribution effects (docs/effects.md): each effect
// switched to its degenerate value renders the image without it. Plus the
// area-light estimators' exact cases and light decorrelation.
#include "accel/motion.h"
#include "render/lighting.h"
#include "render/render.h"

#include <gtest/gtest.h>

#include <set>

namespace drt {
namespace {

RenderOptions smallOptions(int spp = 4) {
    RenderOptions o;
    o.width = 24;
    o.height = 18;
    o.samplesPerPixel = spp;
    o.seed = 9;
    o.threads = 2;
    return o;
}

// Spheres over a checkered floor, a glossy and a glass ball, a point light.
Scene testScene() {
    Scene scene;
    Object floor;
    floor.shape = Plane{{0, 1, 0}, -1};
    floor.texture.edit().pigment.pattern = PatternKind::Checker;
    floor.texture.edit().pigment.children.resize(2);
    floor.texture.edit().pigment.children[0].color.rgb = {0.9, 0.9, 0.9};
    floor.texture.edit().pigment.children[1].color.rgb = {0.2, 0.3, 0.6};
    scene.objects.push_back(floor);
    Object mirror;
    mirror.shape = Sphere{{-0.8, 0, 1}, 0.9};
    mirror.texture.edit().pigment.color.rgb = {0.8, 0.4, 0.3};
    mirror.texture.edit().finish.reflectionMin = mirror.texture.edit().finish.reflectionMax = Color(0.6);
    scene.objects.push_back(mirror);
    Object glass;
    glass.shape = Sphere{{1, -0.2, 0}, 0.7};
    glass.texture.edit().pigment.color = ColorFT{Color(1), 0, 0.9};
    glass.texture.edit().finish.reflectionMin = Color(0.05);
    glass.texture.edit().finish.reflectionMax = Color(1);
    glass.texture.edit().finish.reflectionFresnel = true;
    glass.interior.ior = 1.5;
    scene.objects.push_back(glass);
    Light light;
    light.position = {-3, 5, -4};
    scene.lights.push_back(light);
    scene.background = {0.2, 0.3, 0.5};
    scene.camera.location = {0, 1, -5};
    scene.camera.lookAt = Vec3(0, 0, 0);
    return scene;
}

TEST(Effects, ApertureZeroIsThePinholeBitForBit) {
    const Scene pinhole = testScene();
    Scene zero = pinhole;
    zero.camera.aperture = 0;
    zero.camera.focalDistance = 3.0; // a focal plane without a lens changes nothing
    const RenderResult a = render(pinhole, smallOptions()), b = render(zero, smallOptions());
    EXPECT_EQ(a.color.pixels, b.color.pixels);
    EXPECT_EQ(a.variance.pixels, b.variance.pixels);
    // ...while a real aperture does change the image.
    zero.camera.aperture = 0.5;
    EXPECT_NE(render(zero, smallOptions()).color.pixels, a.color.pixels);
}

TEST(Effects, ZeroLengthShutterIsTheStaticSceneAtThatTime) {
    Scene moving = testScene();
    const MotionChain motion{MotionStage{motionTo({0.5, 0.3, 0}, {0, 40, 0}, {1.2, 1, 1}), {}}};
    moving.objects[1].motion = motion;
    moving.camera.shutterOpen = moving.camera.shutterClose = 0.5;
    // The static pose at time 1/2 as the scene model defines it
    // (scene/motion.h: scale, then rotate, then translate, each interpolated,
    // after the object's own identity transform), composed by the same
    // placementAt, so both scenes hold the same double-precision transform.
    Scene still = testScene();
    still.objects[1].transform = placementAt(Transform(), motion, 0.5);
    // (Accel.ZeroLengthShutterBakesMotionBitForBit checks the same per ray
    // with a motion whose float form Embree would round visibly.)
    const RenderOptions options = smallOptions();
    const RenderResult a = render(moving, options), b = render(still, options);
    EXPECT_EQ(a.color.pixels, b.color.pixels);
    EXPECT_EQ(a.variance.pixels, b.variance.pixels);
    // The same pose written by hand (translate 0.25, 0.15; rotate 20 about y;
    // scale by 1.1 in x) differs from it only by rounding in the last bits of
    // the transform, which may move an edge sample.
    Scene byHand = testScene();
    byHand.objects[1].transform =
        Transform::scale({1.1, 1, 1}).then(Transform::rotate({0, 20, 0})).then(Transform::translate({0.25, 0.15, 0}));
    const RenderResult c = render(byHand, options);
    double worst = 0;
    for (size_t i = 0; i < a.color.pixels.size(); ++i)
        worst = std::max(worst, double(std::fabs(a.color.pixels[i] - c.color.pixels[i])));
    EXPECT_LT(worst, 2e-3);
    moving.camera.shutterOpen = moving.camera.shutterClose = 0;
    EXPECT_EQ(render(moving, smallOptions()).color.pixels, render(testScene(), smallOptions()).color.pixels);
    // ...while an open shutter does blur the moving sphere.
    moving.camera.shutterClose = 1;
    EXPECT_NE(render(moving, smallOptions()).color.pixels, b.color.pixels);
}

TEST(Effects, ZeroBlurIsTheMirrorBitForBit) {
    const Scene mirror = testScene();
    Scene zero = mirror;
    zero.objects[1].texture.edit().finish.reflectionBlur = 0;
    zero.objects[2].texture.edit().finish.refractionBlur = 0;
    EXPECT_EQ(render(mirror, smallOptions()).color.pixels, render(zero, smallOptions()).color.pixels);
    zero.objects[1].texture.edit().finish.reflectionBlur = 0.2;
    EXPECT_NE(render(zero, smallOptions()).color.pixels, render(mirror, smallOptions()).color.pixels);
}

TEST(Effects, SingleCellAreaLightWithoutJitterIsThePointLight) {
    // A 1 x 1 POV-Ray grid sits on the centre: shadow-only or full
    // illumination, it is the point light exactly.
    const Scene point = testScene();
    for (bool illumination : {false, true}) {
        Scene area = point;
        area.lights[0].area = AreaLight{{1, 0, 0}, {0, 0, 1}, 1, 1};
        area.lights[0].area->sampling = AreaSampling::PovGrid;
        area.lights[0].areaIllumination = illumination;
        EXPECT_EQ(render(area, smallOptions()).color.pixels, render(point, smallOptions()).color.pixels);
    }
}

TEST(Effects, InverseSquarePointLightIsColourOverDistanceSquared) {
    // Needle view of a diffuse floor 4 below a light of colour 32: E = 32 / 16 = 2,
    // and without inverse_square the same light gives 1 (POV-Ray: no falloff).
    Scene scene;
    Object floor;
    floor.shape = Plane{{0, 1, 0}, 0};
    floor.texture.edit().pigment.color.rgb = Color(1);
    floor.texture.edit().finish.ambient = Color(0);
    floor.texture.edit().finish.diffuse = 1;
    scene.objects.push_back(floor);
    Light light;
    light.position = {0, 4, 0};
    light.color = Color(32);
    light.inverseSquare = true;
    scene.lights.push_back(light);
    scene.camera.location = {0, 1, 0};
    scene.camera.direction = {0, -1, 0};
    scene.camera.up = Vec3(0, 0, 1) * 1e-9;
    scene.camera.right = Vec3(1, 0, 0) * 1e-9;
    RenderOptions o = smallOptions(1);
    o.width = o.height = 1;
    EXPECT_NEAR(render(scene, o).color.at(0, 0, 0), 2.0, 1e-6);
    scene.lights[0].inverseSquare = false;
    scene.lights[0].color = Color(1);
    EXPECT_NEAR(render(scene, o).color.at(0, 0, 0), 1.0, 1e-6);
}

TEST(Effects, LightsUseDistinctSamplerDimensions) {
    std::set<int> seen;
    for (int light = 0; light < 8; ++light)
        for (int depth = 0; depth < 6; ++depth) {
            const int d = lightDimension(depth, light);
            EXPECT_TRUE(seen.insert(d).second) << light << ", " << depth;
            EXPECT_TRUE(seen.insert(d + 1).second) << light << ", " << depth; // 2D
        }
    EXPECT_EQ(lightDimension(2, 0), bounceDimension(2, kOffsetLight));
    EXPECT_GT(lightDimension(0, 1), bounceDimension(kMaxLightDepth - 1, kDimsPerBounce - 1));
}

} // namespace
} // namespace drt
