// POV-Ray's projected_through (scene.h Light::projectedThrough,
// render/lighting.h lightTransmittance): the light reaches a point only along
// a ray that crosses the object, the object is never drawn, and only what lies
// between the point and the first crossing casts a shadow, so a placed copy of
// the object does not darken the light it shapes. Both dialects, the .drt
// writer, transforms, shadowless lights, located errors.
#include "lang/load.h"
#include "lang/writer.h"
#include "pov/load.h"
#include "render/render.h"
#include "test_support.h"

#include <gtest/gtest.h>

namespace drt {
namespace {

// The camera at the origin sees the centre of a white wall at z = 10 (ambient
// 0, diffuse 1) head-on. The light of colour 0.5 stands at L = <0, 6, 2>: the
// segment from the wall's centre P to it runs along <0, 6, -8> (length 10) and
// meets the wall at cos = 0.8, so a lit centre is 0.4. Ball is on that segment
// at its middle, <0, 3, 6>, away from the camera's view (3 units off its axis).
constexpr double kLit = 0.4;

std::string wallScene(const std::string& items) {
    return R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, 0> look_at <0, 0, 1> angle 0.5 }
plane { -z, -10 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
#declare Ball = sphere { <0, 3, 6>, 0.5 }
#declare Aside = sphere { <2, 3, 6>, 0.5 }
)" + items;
}

double centre(const std::string& text, bool pov = true) {
    Diagnostics diags;
    const std::optional<Scene> scene =
        pov ? loadPovSceneText(text, "p.pov", diags) : loadSceneText(text, "p.drt", diags, ".");
    EXPECT_TRUE(scene) << diags.formatAll();
    if (!scene) return -1;
    const Image image = render(*scene, test::tinyRenderOptions()).color;
    EXPECT_EQ(image.at(2, 2, 0), image.at(2, 2, 1));
    return image.at(2, 2, 0);
}

TEST(ProjectedThrough, TheLightShinesOnlyThroughTheObject) {
    for (const bool pov : {true, false}) {
        SCOPED_TRACE(pov ? "pov" : "drt");
        // An ordinary light, for scale.
        EXPECT_NEAR(centre(wallScene("light_source { <0, 6, 2>, rgb 0.5 }"), pov), kLit, 1e-4);
        // Through the ball on the way: lit, and the ball is not drawn nor casts a shadow.
        EXPECT_NEAR(centre(wallScene("light_source { <0, 6, 2>, rgb 0.5 projected_through { Ball } }"), pov), kLit,
                    1e-4);
        // Through a ball beside the way: dark.
        EXPECT_EQ(centre(wallScene("light_source { <0, 6, 2>, rgb 0.5 projected_through { Aside } }"), pov), 0.0);
        // The object beyond the light: the segment does not reach it, dark.
        EXPECT_EQ(centre(wallScene("light_source { <0, 6, 2>, rgb 0.5 projected_through { sphere { <0, 9, -2>, 1 } } }"),
                         pov),
                  0.0);
    }
}

TEST(ProjectedThrough, OnlyWhatLiesBeforeTheCrossingCastsAShadow) {
    for (const bool pov : {true, false}) {
        SCOPED_TRACE(pov ? "pov" : "drt");
        // The ball placed in the scene shadows an ordinary light...
        EXPECT_EQ(centre(wallScene("object { Ball }\nlight_source { <0, 6, 2>, rgb 0.5 }"), pov), 0.0);
        // ... but not the light projected through it.
        EXPECT_NEAR(centre(wallScene("object { Ball }\nlight_source { <0, 6, 2>, rgb 0.5 projected_through { Ball } }"),
                           pov),
                    kLit, 1e-4);
        // A blocker between the wall and the crossing (a quarter of the way) shadows it.
        EXPECT_EQ(centre(wallScene("sphere { <0, 1.5, 8>, 0.3 }\n"
                                   "light_source { <0, 6, 2>, rgb 0.5 projected_through { Ball } }"),
                         pov),
                  0.0);
        // One between the crossing and the light (three quarters of the way) does not.
        EXPECT_NEAR(centre(wallScene("sphere { <0, 4.5, 4>, 0.3 }\n"
                                     "light_source { <0, 6, 2>, rgb 0.5 projected_through { Ball } }"),
                           pov),
                    kLit, 1e-4);
    }
}

TEST(ProjectedThrough, AShadowlessLightIsStillShapedByTheObject) {
    for (const bool pov : {true, false}) {
        SCOPED_TRACE(pov ? "pov" : "drt");
        const std::string blocker = "sphere { <0, 1.5, 8>, 0.3 }\n";
        EXPECT_NEAR(centre(wallScene(blocker + "light_source { <0, 6, 2>, rgb 0.5 shadowless projected_through { Ball } }"),
                           pov),
                    kLit, 1e-4);
        EXPECT_EQ(centre(wallScene(blocker + "light_source { <0, 6, 2>, rgb 0.5 shadowless projected_through { Aside } }"),
                         pov),
                  0.0);
    }
}

TEST(ProjectedThrough, TheObjectMovesWithTheLightsLaterTransforms) {
    for (const bool pov : {true, false}) {
        SCOPED_TRACE(pov ? "pov" : "drt");
        // Written 2 units to the left, light and ball both: moved back together, lit.
        EXPECT_NEAR(centre(wallScene("light_source { <-2, 6, 2>, rgb 0.5 projected_through { Aside translate <-4, 0, 0> }"
                                     " translate <2, 0, 0> }"),
                           pov),
                    kLit, 1e-4);
        // The same inside a union that is moved: the light and its object move alike.
        EXPECT_NEAR(centre(wallScene("union { light_source { <-2, 6, 2>, rgb 0.5 projected_through { Aside translate "
                                     "<-4, 0, 0> } } sphere { <50, 50, 50>, 1 } translate <2, 0, 0> }"),
                           pov),
                    kLit, 1e-4);
        // A transform before projected_through does not move the object given after it.
        EXPECT_EQ(centre(wallScene("light_source { <-2, 6, 2>, rgb 0.5 translate <2, 0, 0> projected_through { Aside "
                                   "translate <-4, 0, 0> } }"),
                         pov),
                  0.0);
    }
}

TEST(DrtProjectedThrough, ReadsAndWritesBack) {
    const std::string text = wallScene("object { Ball }\nlight_source { <0, 6, 2>, rgb 0.5 projected_through { Ball } }")
                                 .substr(std::string("#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n").size());
    EXPECT_NEAR(centre(text, false), kLit, 1e-4);
    Diagnostics diags;
    const std::optional<Scene> scene = loadSceneText(text, "p.drt", diags, ".");
    ASSERT_TRUE(scene) << diags.formatAll();
    const std::string written = writeDrtScene(*scene);
    EXPECT_NE(written.find("projected_through {"), std::string::npos) << written;
    EXPECT_NEAR(centre(written, false), kLit, 1e-4) << written;
    Diagnostics again;
    const std::optional<Scene> reread = loadSceneText(written, "w.drt", again, ".");
    ASSERT_TRUE(reread) << again.formatAll() << written;
    EXPECT_EQ(writeDrtScene(*reread), written);
}

TEST(ProjectedThrough, BadUsesAreLocatedErrors) {
    struct Case {
        std::string light;
        std::string message;
        int column;
    };
    const Case cases[] = {
        {"light_source { <0, 6, 2>, rgb 0.5 projected_through { Ball } projected_through { Ball } }",
         "only one projected_through is allowed per light_source", 62},
        {"light_source { <0, 6, 2>, rgb 0.5 motion { translate <1, 0, 0> } projected_through { Ball } }",
         "'projected_through' after 'motion': a moving light cannot shine through an object", 66},
        {"light_source { <0, 6, 2>, rgb 0.5 projected_through { Ball } motion { translate <1, 0, 0> } }",
         "'motion' in a light with 'projected_through': a moving light cannot shine through an object", 62},
    };
    for (const bool pov : {true, false}) {
        for (const Case& c : cases) {
            SCOPED_TRACE(c.light);
            Diagnostics diags;
            const std::string text = "#declare Ball = sphere { <0, 3, 6>, 0.5 }\n" + c.light;
            const std::optional<Scene> scene =
                pov ? loadPovSceneText(text, "e.pov", diags) : loadSceneText(text, "e.drt", diags, ".");
            EXPECT_FALSE(scene);
            ASSERT_GE(diags.errorCount(), 1);
            EXPECT_EQ(diags.all()[0].message, c.message);
            EXPECT_EQ(diags.all()[0].loc.line, 2);
            EXPECT_EQ(diags.all()[0].loc.column, c.column);
        }
    }
}

} // namespace
} // namespace drt
