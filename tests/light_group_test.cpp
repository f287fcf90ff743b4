// POV-Ray's light_group (scene.h lightReaches, lang/light_groups.cpp): a
// group's light lights only the group's objects, the scene's other lights
// reach them only with global_lights, shadows are cast by every object,
// nested groups see their outer groups' lights; both dialects, the .drt
// writer, located errors. The render against POV-Ray's is
// pov_crosscheck/fidelity/light_group.pov.
#include "lang/load.h"
#include "lang/writer.h"
#include "pov/load.h"
#include "render/render.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace drt {
namespace {

// A white wall at z = 10 facing the camera (ambient 0, diffuse 1) seen through
// a narrow view; `lights` and `wall` are spliced in. A light at the origin
// lights the wall's centre head-on: the pixel is the light's colour.
std::string wallScene(const std::string& items) {
    return R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, 0> look_at <0, 0, 1> angle 0.5 }
#declare Wall = plane { -z, -10 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
)" + items;
}

Color centre(const std::string& text, bool pov = true) {
    Diagnostics diags;
    const std::optional<Scene> scene =
        pov ? loadPovSceneText(text, "g.pov", diags) : loadSceneText(text, "g.drt", diags, ".");
    EXPECT_TRUE(scene) << diags.formatAll();
    if (!scene) return Color(-1);
    const Image image = render(*scene, test::tinyRenderOptions()).color;
    return {image.at(2, 2, 0), image.at(2, 2, 1), image.at(2, 2, 2)};
}

void expectColor(const Color& c, double r, double g, double b) {
    EXPECT_NEAR(c.r, r, 1e-4);
    EXPECT_NEAR(c.g, g, 1e-4);
    EXPECT_NEAR(c.b, b, 1e-4);
}

TEST(LightGroup, GroupLightLightsOnlyItsObjects) {
    // The wall in the group: the group's red light only (global_lights is off by default).
    expectColor(centre(wallScene(R"(
light_source { <0, 0, 0> color rgb 0.25 }
light_group { light_source { <0, 0, 0> color rgb <0.5, 0, 0> } object { Wall } }
)")),
                0.5, 0, 0);
    // global_lights on: both.
    expectColor(centre(wallScene(R"(
light_source { <0, 0, 0> color rgb 0.25 }
light_group { light_source { <0, 0, 0> color rgb <0.5, 0, 0> } object { Wall } global_lights on }
)")),
                0.75, 0.25, 0.25);
    // The wall outside the group: the group's light does not reach it.
    expectColor(centre(wallScene(R"(
light_source { <0, 0, 0> color rgb 0.25 }
light_group { light_source { <0, 0, 0> color rgb <0.5, 0, 0> } sphere { <0, 5, 5>, 0.5 } }
object { Wall }
)")),
                0.25, 0.25, 0.25);
}

TEST(LightGroup, ObjectsOutsideTheGroupStillCastShadows) {
    // The group's light at <0, 8, 9> lights the wall's centre at cos = 1/sqrt(65);
    // a sphere of no group between them (out of the narrow view) shadows it.
    const double cosine = 1 / std::sqrt(65.0);
    const std::string lit = R"(
light_group { light_source { <0, 8, 9> color rgb 1 } object { Wall } }
)";
    expectColor(centre(wallScene(lit)), cosine, cosine, cosine);
    expectColor(centre(wallScene(lit + "sphere { <0, 4, 9.5>, 0.3 pigment { rgb 1 } }\n")), 0, 0, 0);
}

TEST(LightGroup, InnerGroupsSeeTheirOuterGroupsLights) {
    const std::string text = wallScene(R"(
light_group {
  light_source { <0, 0, 0> color rgb <0.5, 0, 0> }
  light_group { light_source { <0, 0, 0> color rgb <0, 0.25, 0> } object { Wall } }
  sphere { <0, 5, 5>, 0.5 }
}
)");
    expectColor(centre(text), 0.5, 0.25, 0);
    Diagnostics diags;
    const std::optional<Scene> scene = loadPovSceneText(text, "g.pov", diags);
    ASSERT_TRUE(scene) << diags.formatAll();
    ASSERT_EQ(scene->lightGroupParents.size(), 3u); // entry 0 unused, the outer group, the inner one
    ASSERT_EQ(scene->lights.size(), 2u);
    const Light& outerLight = scene->lights[0].group == 1 ? scene->lights[0] : scene->lights[1];
    const Light& innerLight = scene->lights[0].group == 2 ? scene->lights[0] : scene->lights[1];
    EXPECT_EQ(scene->lightGroupParents[2], 1);
    // The sphere is in the outer group only: the inner group's light does not reach it.
    for (const Object& o : scene->objects) {
        if (std::holds_alternative<Sphere>(o.shape)) {
            EXPECT_TRUE(lightReaches(*scene, outerLight, o));
            EXPECT_FALSE(lightReaches(*scene, innerLight, o));
        }
    }
}

TEST(DrtLightGroup, ReadsAndWritesBack) {
    const std::string text = R"(
camera { location <0, 0, 0> look_at <0, 0, 1> angle 0.5 }
light_source { <0, 0, 0>, color rgb 0.25 }
light_group {
  light_source { <0, 0, 0>, color rgb <0.5, 0, 0> }
  plane { -z, -10 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
  global_lights on
  translate <0, 0, 1>
}
)";
    expectColor(centre(text, false), 0.75, 0.25, 0.25);
    Diagnostics diags;
    const std::optional<Scene> scene = loadSceneText(text, "g.drt", diags, ".");
    ASSERT_TRUE(scene) << diags.formatAll();
    const std::string written = writeDrtScene(*scene);
    EXPECT_NE(written.find("light_group {"), std::string::npos) << written;
    EXPECT_NE(written.find("global_lights on"), std::string::npos) << written;
    expectColor(centre(written, false), 0.75, 0.25, 0.25);
    Diagnostics again;
    const std::optional<Scene> reread = loadSceneText(written, "w.drt", again, ".");
    ASSERT_TRUE(reread) << again.formatAll() << written;
    EXPECT_EQ(writeDrtScene(*reread), written);
}

TEST(LightGroup, BadItemsAreLocatedErrors) {
    for (const bool pov : {true, false}) {
        Diagnostics diags;
        const std::string text = "light_group {\n  sphere { 0, 1 }\n  pigment { rgb 1 } }";
        const std::optional<Scene> scene =
            pov ? loadPovSceneText(text, "e.pov", diags) : loadSceneText(text, "e.drt", diags, ".");
        EXPECT_FALSE(scene);
        ASSERT_GE(diags.errorCount(), 1);
        EXPECT_EQ(diags.all()[0].message,
                  "expected an object, a light_source, a transform, 'global_lights' or '}' in light_group, found "
                  "'pigment'");
        EXPECT_EQ(diags.all()[0].loc.line, 3);
        EXPECT_EQ(diags.all()[0].loc.column, 3);
    }
}

} // namespace
} // namespace drt
