// Fog and sky_sphere (scene.h Fog, Scene::sky; render/atmosphere.h): the
// transmittance formulas, the ground-fog depth integral against a numerical
// one, and rendered pixels against the closed forms.
#include "render/atmosphere.h"
#include "lang/load.h"
#include "render/render.h"
#include "test_support.h"

#include <cmath>
#include <gtest/gtest.h>

namespace drt {
namespace {

TEST(Fog, ConstantFogBlendsByExpMinusDistance) {
    Fog fog;
    fog.distance = 4;
    fog.color.rgb = {0.2, 0.4, 0.8};
    const FogEffect e = fogEffect({fog}, {0, 0, 0}, {0, 0, 1}, 3);
    const double t = std::exp(-3.0 / 4.0);
    EXPECT_NEAR(e.scale.r, t, 1e-12);
    EXPECT_NEAR(e.add.g, (1 - t) * 0.4, 1e-12);
    EXPECT_NEAR(e.add.b, (1 - t) * 0.8, 1e-12);
}

TEST(Fog, TransmitIsTheMinimumTransmittanceAndFilterTints) {
    Fog fog;
    fog.distance = 1;
    fog.color = ColorFT{Color(0.5, 1, 0), 0.4, 0.3};
    const FogEffect e = fogEffect({fog}, {0, 0, 0}, {1, 0, 0}, kFogMissDistance);
    // exp(-1e7) is 0, so T = transmit = 0.3; seen through, T ((1 - f) + f C).
    EXPECT_NEAR(e.scale.r, 0.3 * (0.6 + 0.4 * 0.5), 1e-12);
    EXPECT_NEAR(e.scale.b, 0.3 * 0.6, 1e-12);
    EXPECT_NEAR(e.add.r, 0.7 * 0.5, 1e-12);
    EXPECT_NEAR(e.add.b, 0.0, 1e-12);
}

TEST(Fog, GroundFogDepthMatchesTheDensityIntegral) {
    Fog fog;
    fog.type = Fog::Type::Ground;
    fog.offset = 1;
    fog.altitude = 2;
    const Vec3 origin{0, -1, 0};
    const Vec3 dir = normalize(Vec3{1, 0.5, 0});
    const double length = 12;
    // Midpoint rule over the density 1 below the offset, 1/(1+u^2) above.
    const int n = 200000;
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        const double h = origin.y + dir.y * (i + 0.5) * length / n - fog.offset;
        const double u = h / fog.altitude;
        sum += (h <= 0 ? 1.0 : 1.0 / (1 + u * u)) * length / n;
    }
    EXPECT_NEAR(fogDepth(fog, origin, dir, length), sum, 1e-6);
    // A level ray above the offset sees the density at its height.
    EXPECT_NEAR(fogDepth(fog, {0, 5, 0}, {1, 0, 0}, 3), 3 / (1 + 4.0), 1e-12);
    // Constant fog's depth is the length.
    EXPECT_EQ(fogDepth(Fog{}, origin, dir, length), length);
}

TEST(Fog, TurbulenceThinsTheFogWithinItsBound) {
    Fog fog;
    fog.distance = 5;
    fog.turbulence = Turbulence{Vec3(0.5, 0.5, 0.5)};
    fog.turbDepth = 0.5;
    // The depth shrinks by at most exp(-length / D) of itself, and never grows.
    bool thinner = false;
    for (int i = 0; i < 20; ++i) {
        const Vec3 origin{0.37 * i, 0.11 * i, -1.3 * i};
        const double z = fogDepth(fog, origin, {0, 0, 1}, 4);
        EXPECT_LE(z, 4.0);
        EXPECT_GE(z, 4.0 * (1 - std::exp(-4.0 / 5.0)) - 1e-12);
        thinner = thinner || z < 4.0 - 1e-9;
    }
    EXPECT_TRUE(thinner);
}

// A self-lit wall at z = 10 in front of a camera with a narrow view, so every
// ray travels 10 within 1e-4.
Scene wallScene() {
    Scene scene;
    Object wall;
    wall.shape = Plane{{0, 0, -1}, -10};
    wall.texture.edit().pigment.color.rgb = {0.9, 0.1, 0.1};
    wall.texture.edit().finish.ambient = Color(1);
    wall.texture.edit().finish.diffuse = 0;
    scene.objects.push_back(wall);
    scene.camera.angle = 0.5;
    return scene;
}

TEST(Fog, RenderedWallIsFoggedByItsDistance) {
    Scene scene = wallScene();
    Fog fog;
    fog.distance = 8;
    fog.color.rgb = {0.1, 0.2, 0.9};
    scene.fogs.push_back(fog);
    const Image image = render(scene, test::tinyRenderOptions()).color;
    const double t = std::exp(-10.0 / 8.0);
    EXPECT_NEAR(image.at(2, 2, 0), t * 0.9 + (1 - t) * 0.1, 1e-4);
    EXPECT_NEAR(image.at(2, 2, 2), t * 0.1 + (1 - t) * 0.9, 1e-4);
}

// A light's way to the surface goes through the fog too when the light has
// media_attenuation (POV-Ray's hollow1.pov: with it on, a light of 40000 at
// 800 units in fog of distance 80 lights the floor as one of about 2). The
// floor below the camera, the light straight above it: the pixel is
// exp(-camera distance / D) * exp(-light distance / D) with black fog; without
// media_attenuation (POV-Ray's default, not drt's) only the camera's part.
TEST(Fog, ALightWithMediaAttenuationIsDimmedByTheFogOnItsWay) {
    const std::string scene = "global_settings { assumed_gamma 1 }\n"
                              "camera { orthographic location <0, 10, 0> sky z look_at <0, 0, 0> right x * 0.01 up z * 0.01 }\n"
                              "fog { distance 10 color rgb 0 }\n"
                              "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n";
    struct Case {
        const char* name;
        const char* light;
        double expected;
    };
    const double camera = std::exp(-10.0 / 10.0), light = std::exp(-20.0 / 10.0);
    for (const Case& c : {Case{"f.pov", "light_source { <0, 20, 0>, rgb 1 media_attenuation on }", camera * light},
                          Case{"f.pov", "light_source { <0, 20, 0>, rgb 1 }", camera},
                          Case{"f.drt", "light_source { <0, 20, 0>, rgb 1 }", camera * light},
                          Case{"f.drt", "light_source { <0, 20, 0>, rgb 1 media_attenuation off }", camera}}) {
        Diagnostics diags;
        const auto s = loadSceneText(scene + c.light, c.name, diags);
        ASSERT_TRUE(s) << diags.formatAll();
        const Image image = render(*s, test::tinyRenderOptions()).color;
        for (int channel = 0; channel < 3; ++channel)
            EXPECT_NEAR(image.at(2, 2, channel), c.expected, 1e-4) << c.name << " " << c.light;
    }
}

TEST(Fog, BackgroundTakesTheFullFogColour) {
    Scene scene;
    scene.background = {1, 1, 0};
    Fog fog;
    fog.distance = 100;
    fog.color.rgb = {0.3, 0.6, 0.2};
    scene.fogs.push_back(fog);
    const Image image = render(scene, test::tinyRenderOptions()).color;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.at(4, 0, c), fog.color.rgb[c], 1e-6); // the image is float
}

TEST(SkySphere, GradientIsEvaluatedOnTheRayDirection) {
    Scene scene;
    Pigment sky;
    sky.pattern = PatternKind::Gradient;
    sky.colorMap = {{0, ColorFT{Color(0, 0, 0)}}, {1, ColorFT{Color(1, 1, 1)}}};
    scene.sky.push_back(sky);
    scene.camera.location = {0, 0, 0};
    scene.camera.lookAt = Vec3(0, 1, 1); // 45 degrees up: direction y = 0.7071 at the centre
    scene.camera.angle = 0.5;
    const Image image = render(scene, test::tinyRenderOptions()).color;
    EXPECT_NEAR(image.at(2, 2, 0), std::sqrt(0.5), 5e-3);
    // Direct: the colour map at the direction's y.
    EXPECT_NEAR(skyColor(scene, normalize(Vec3{0, 1, 3})).g, 1 / std::sqrt(10.0), 1e-9);
}

TEST(SkySphere, TransmitShowsTheBackgroundAndTheLastLayerIsOnTop) {
    Scene scene;
    scene.background = {0, 0, 1};
    Pigment bottom, top;
    bottom.color = ColorFT{Color(1, 0, 0), 0, 0.5};
    top.color = ColorFT{Color(0, 1, 0), 0, 0.25};
    scene.sky = {bottom, top};
    const Color c = skyColor(scene, {0, 0, 1});
    EXPECT_NEAR(c.g, 0.75, 1e-12);
    EXPECT_NEAR(c.r, 0.25 * 0.5, 1e-12);
    EXPECT_NEAR(c.b, 0.25 * 0.5, 1e-12);
}


// POV-Ray's ComputeFog: each fog acts on the whole segment; colours add and
// transmittances multiply, whatever the order (interior/foglyr2.pov's two
// saturated ground fogs, blue and orange, give pink, not the first fog's blue).
TEST(Fog, SeveralFogsAddTheirColoursAndMultiplyTransmittances) {
    Fog blue;
    blue.distance = 4;
    blue.color = ColorFT{Color(0, 0, 1), 0.25, 0};
    Fog orange;
    orange.distance = 2;
    orange.color.rgb = {1, 0.5, 0};
    const double length = 3;
    const double tBlue = std::exp(-length / 4), tOrange = std::exp(-length / 2);
    for (const auto& fogs : {std::vector<Fog>{blue, orange}, std::vector<Fog>{orange, blue}}) {
        const FogEffect e = fogEffect(fogs, {0, 0, 0}, {0, 0, 1}, length);
        const Color add = (1 - tBlue) * blue.color.rgb + (1 - tOrange) * orange.color.rgb;
        const Color scale = tBlue * (Color(0.75) + 0.25 * blue.color.rgb) * tOrange;
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(e.add[c], add[c], 1e-12);
            EXPECT_NEAR(e.scale[c], scale[c], 1e-12);
        }
    }
    // Both saturated (a miss): the sum of the two colours.
    const FogEffect far = fogEffect({blue, orange}, {0, 0, 0}, {0, 0, 1}, kFogMissDistance);
    EXPECT_NEAR(far.add.r, 1, 1e-12);
    EXPECT_NEAR(far.add.g, 0.5, 1e-12);
    EXPECT_NEAR(far.add.b, 1, 1e-12);
}

} // namespace
} // namespace drt
