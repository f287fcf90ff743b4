// light_source { looks_like { object } } in the POV-Ray front end: the object
// is placed at the light, moves with the light's later transforms (and with an
// enclosing union), casts no shadow, and a declared light keeps its shape.
#include "pov/load.h"
#include "render/render.h"

#include <gtest/gtest.h>

namespace drt {
namespace {

Scene loadOk(const std::string& text) {
    Diagnostics diags;
    std::optional<Scene> scene = loadPovSceneText(text, "l.pov", diags, PovOptions{});
    EXPECT_TRUE(scene) << diags.formatAll();
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    return scene ? *scene : Scene{};
}

void expectNear(const Vec3& a, const Vec3& b) {
    EXPECT_NEAR(a.x, b.x, 1e-12);
    EXPECT_NEAR(a.y, b.y, 1e-12);
    EXPECT_NEAR(a.z, b.z, 1e-12);
}

TEST(PovLooksLike, ObjectSitsAtTheLightAndMovesWithIt) {
    const Scene s = loadOk("light_source { <1, 2, 3>, rgb 1 looks_like { sphere { 0, 0.2 } } rotate 90 * y }\n"
                           "union { light_source { <0, 1, 0>, rgb 1 looks_like { sphere { x, 0.1 } } } translate 5 * z }");
    ASSERT_EQ(s.lights.size(), 2u);
    ASSERT_EQ(s.objects.size(), 2u);
    // rotate 90 about y takes <1, 2, 3> to <3, 2, -1>.
    expectNear(s.lights[0].position, {3, 2, -1});
    expectNear(s.objects[0].transform.point({0, 0, 0}), s.lights[0].position);
    EXPECT_TRUE(s.objects[0].noShadow);
    // In the union: the shape (centred at x from the light) and the light move together.
    expectNear(s.lights[1].position, {0, 1, 5});
    const Object& member = std::get<Csg>(s.objects[1].shape).children.at(0);
    expectNear(member.transform.then(s.objects[1].transform).point({1, 0, 0}), {1, 1, 5});
    EXPECT_TRUE(member.noShadow);
}

TEST(PovLooksLike, DeclaredLightKeepsItsShape) {
    const Scene s = loadOk("#declare Lamp = light_source { <0, 3, 0>, rgb 1 looks_like { box { -0.1, 0.1 } } }\n"
                           "light_source { Lamp translate x }\nobject { Lamp translate -x }");
    ASSERT_EQ(s.lights.size(), 2u);
    ASSERT_EQ(s.objects.size(), 2u);
    expectNear(s.lights[0].position, {1, 3, 0});
    expectNear(s.objects[0].transform.point({0, 0, 0}), {1, 3, 0});
    expectNear(s.lights[1].position, {-1, 3, 0});
    expectNear(s.objects[1].transform.point({0, 0, 0}), {-1, 3, 0});
}

TEST(PovLooksLike, TwoShapesAreAnError) {
    Diagnostics diags;
    EXPECT_FALSE(loadPovSceneText("light_source { 0, 1 looks_like { sphere { 0, 1 } } looks_like { sphere { 0, 1 } } }",
                                  "l.pov", diags, PovOptions{}));
    ASSERT_GE(diags.errorCount(), 1);
    EXPECT_EQ(diags.all()[0].message, "only one looks_like is allowed per light_source");
    EXPECT_EQ(diags.all()[0].loc.column, 52);
}

// The floor straight below a light wrapped in an opaque looks_like sphere.
double floorBelowTheLight(const std::string& lamp) {
    Scene s = loadOk("camera { location <3, 5, 0> look_at 0 }\n"
                     "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n" + lamp);
    RenderOptions o;
    o.width = o.height = 9;
    o.threads = 1;
    return render(s, o).color.at(4, 4, 0);
}

TEST(PovLooksLike, ShapeCastsNoShadow) {
    // Diffuse 1 below a white point light (POV-Ray: no falloff) is cos theta;
    // the centre pixel spans under 1 unit of floor, so its sample lies within
    // 0.6 of the point straight below, 2 under the light: cos theta > 0.95
    // (measured 0.9971).
    const double lit = floorBelowTheLight("light_source { <0, 2, 0>, rgb 1 looks_like { sphere { 0, 0.3 } } }");
    EXPECT_GT(lit, 0.95);
    EXPECT_LE(lit, 1.0);
    // The same sphere as a plain object shadows the floor completely.
    const double shadowed = floorBelowTheLight("light_source { <0, 2, 0>, rgb 1 }\nsphere { <0, 2, 0>, 0.3 }");
    EXPECT_EQ(shadowed, 0.0);
}

} // namespace
} // namespace drt
