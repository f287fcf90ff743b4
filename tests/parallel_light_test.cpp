// POV-Ray's `parallel` light: every point it lights sees it along the one
// direction point_at - position, as from the point's projection onto the plane
// through the light square to that direction (scene.h parallelLightPosition);
// a point behind that plane sees it from the same direction.
// Closed forms on a floor and a shadow, in both dialects; the cross-check
// against POV-Ray's own render is tests/pov_crosscheck/fidelity/parallel_light.pov.
#include "lang/writer.h"
#include "render/render.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace drt {
namespace {

TEST(ParallelLight, StandsAtThePointsProjectionOntoItsPlane) {
    Light l;
    l.position = {0, 10, 0};
    l.pointAt = {0, 0, 0};
    l.parallel = true;
    // Straight down: the light stands right above every point, at its height.
    const Vec3 above = parallelLightPosition(l, {3, 1, -7});
    EXPECT_NEAR(above.x, 3, 1e-12);
    EXPECT_NEAR(above.y, 10, 1e-12);
    EXPECT_NEAR(above.z, -7, 1e-12);
    // Slanted: the point to its light is along position - point_at, and the
    // light lies in the plane through position square to it.
    l.pointAt = {4, 0, 3};
    const Vec3 p{-2, 0.5, 8};
    const Vec3 at = parallelLightPosition(l, p);
    const Vec3 d = normalize(l.pointAt - l.position);
    EXPECT_NEAR(dot(at - l.position, d), 0, 1e-12);
    EXPECT_NEAR(length(normalize(at - p) + d), 0, 1e-12);
    // Behind the plane (POV-Ray lights such a point from the same direction):
    // as far from the point as the plane, towards -d.
    const Vec3 behind = l.position - d * 2 + Vec3(1, 2, 3) - d * dot(Vec3(1, 2, 3), d);
    const Vec3 seen = parallelLightPosition(l, behind);
    EXPECT_NEAR(length(seen - behind), 2, 1e-12);
    EXPECT_NEAR(length(normalize(seen - behind) + d), 0, 1e-12);
    // point_at on the light: no direction, the light stays where it is.
    l.pointAt = l.position;
    EXPECT_EQ(parallelLightPosition(l, p), l.position);
}

// A floor lit by a parallel light at 60 degrees from the vertical, seen by a
// needle camera at three places: each pixel is diffuse * cos 60, wherever it
// is (a point light at the same place gives each its own angle), and a post
// casts its shadow along the light's direction.
const char* kFloorPov = R"(
camera { location <X, 1, Z> direction <0, -1, 0> up <0, 0, 1e-9> right <1e-9, 0, 0> }
light_source { <0, 5, 0> color rgb 1 parallel point_at <5 * sqrt(3), 0, 0> }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
cylinder { <3, 0, 0>, <3, 3, 0>, 0.2 pigment { rgb 1 } }
)";

double floorPixel(double x, double z, bool pov) {
    std::string text = kFloorPov;
    text.replace(text.find("X"), 1, std::to_string(x));
    text.replace(text.find("Z"), 1, std::to_string(z));
    const auto run = test::readSceneText(text, pov);
    EXPECT_TRUE(run->scene) << run->diags.formatAll();
    if (!run->scene) return -1;
    RenderOptions o;
    o.width = 1;
    o.height = 1;
    o.samplesPerPixel = 1;
    o.threads = 1;
    const RenderResult r = render(*run->scene, o);
    return r.color.at(0, 0, 0);
}

TEST(ParallelLight, LightsAFloorAtOneAngleAndShadowsAlongIt) {
    for (const bool pov : {true, false}) {
        SCOPED_TRACE(pov ? ".pov" : ".drt");
        // The light's direction is 60 degrees from the vertical: N.L = 1/2.
        for (const double x : {-20.0, 0.0, 1.0, 20.0}) EXPECT_NEAR(floorPixel(x, 4, pov), 0.5, 1e-6) << x;
        // The post (x = 3, height 3) shades the floor from x = 3 to 3 + 3 tan 60 = 8.2 along the light.
        EXPECT_NEAR(floorPixel(5, 0, pov), 0, 1e-9);
        EXPECT_NEAR(floorPixel(8, 0, pov), 0, 1e-9);
        EXPECT_NEAR(floorPixel(8.5, 0, pov), 0.5, 1e-6);
        EXPECT_NEAR(floorPixel(2.5, 0, pov), 0.5, 1e-6);
    }
}

TEST(ParallelLight, ConvertKeepsIt) {
    const auto run = test::readSceneText("light_source { <1, 2, 3> color rgb 1 parallel point_at <0, 0, 0> }", true);
    ASSERT_TRUE(run->scene) << run->diags.formatAll();
    EXPECT_EQ(run->diags.warningCount(), 0) << run->diags.formatAll();
    ASSERT_EQ(run->scene->lights.size(), 1u);
    EXPECT_TRUE(run->scene->lights[0].parallel);
    const std::string drt = writeDrtScene(*run->scene);
    EXPECT_NE(drt.find("parallel"), std::string::npos) << drt;
    const auto back = test::readSceneText(drt, false);
    ASSERT_TRUE(back->scene) << back->diags.formatAll();
    ASSERT_EQ(back->scene->lights.size(), 1u);
    EXPECT_TRUE(back->scene->lights[0].parallel);
}

} // namespace
} // namespace drt
