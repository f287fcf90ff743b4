// Warnings for scenes that render but are most likely not what was meant
// (render/scene_warnings.h): no light, no camera, a camera inside a closed
// object. drt check and drt render print them; they never stop a render.
#include "lang/load.h"
#include "render/scene_warnings.h"
#include "test_support.h"

#include <gtest/gtest.h>

namespace drt {
namespace {

const char* kCamera = "camera { location <0, 1, -4> look_at <0, 0.5, 0> }\n";
const char* kLight = "light_source { <-3, 5, -4>, color rgb 1 }\n";

// The warnings for a scene text, formatted as drt prints them.
std::string warningsFor(const std::string& text) {
    Diagnostics diagnostics;
    const std::optional<Scene> scene = loadSceneText(text, "scene.drt", diagnostics);
    EXPECT_TRUE(scene && !diagnostics.hasErrors()) << diagnostics.formatAll();
    if (!scene)
        return "<no scene>";
    Diagnostics warnings(diagnostics.sharedFiles());
    warnAboutScene(*scene, "scene.drt", warnings);
    EXPECT_EQ(warnings.errorCount(), 0);
    return warnings.formatAll();
}

TEST(SceneWarnings, AnOrdinarySceneHasNone) {
    EXPECT_EQ(warningsFor(std::string(kCamera) + kLight + "sphere { <0, 0.5, 0>, 0.5 }\nplane { y, 0 }\n"), "");
}

TEST(SceneWarnings, NoLightAndNoCamera) {
    const std::string noLight = warningsFor(std::string(kCamera) + "sphere { <0, 0.5, 0>, 0.5 }\n");
    EXPECT_EQ(noLight, "drt: warning: scene.drt has no light_source: only ambient light and emission show\n");
    const std::string noCamera = warningsFor(std::string(kLight) + "sphere { <0, 0, 5>, 0.5 }\n");
    EXPECT_NE(noCamera.find("drt: warning: scene.drt has no camera: the default one at the origin"),
              std::string::npos)
        << noCamera;
}

TEST(SceneWarnings, CameraInsideAClosedObjectPointsAtTheObject) {
    const std::string text = std::string(kCamera) + kLight + "plane { y, 0 }\n  sphere { <0, 1, -4>, 2 }\n";
    EXPECT_EQ(warningsFor(text), "scene.drt:4:3: warning: the camera at <0, 1, -4> is inside this object: the picture "
                                 "shows it from inside (make it `hollow` if that is meant)\n"
                                 "    sphere { <0, 1, -4>, 2 }\n"
                                 "    ^\n");
    // In a box, in a CSG solid, in a closed cylinder.
    for (const char* enclosing : {"box { <-1, 0, -5>, <1, 2, -3> }",
                                  "difference { sphere { <0, 1, -4>, 2 } sphere { <0, 1, 0>, 0.5 } }",
                                  "cylinder { <0, 0, -4>, <0, 3, -4>, 0.5 }"})
        EXPECT_NE(warningsFor(std::string(kCamera) + kLight + enclosing + "\n").find("is inside this object"),
                  std::string::npos)
            << enclosing;
}

// Only objects whose bounds hold the camera are asked (so that checking a
// large scene builds no accelerator over it): the answer is the same with
// many objects around, one of them inside the enclosing one between the
// camera and its wall, and a moving one (whose bounds are not known) is asked.
TEST(SceneWarnings, TheEnclosingObjectIsFoundAmongManyAndWhenItMoves) {
    std::string many;
    for (int i = 0; i < 200; ++i)
        many += "sphere { <" + std::to_string(i % 20 - 10) + ", 0.3, " + std::to_string(i / 20 + 2) + ">, 0.3 }\n";
    const std::string text = std::string(kCamera) + kLight + "sphere { <0, 1, -4>, 2 }\n" +
                             "sphere { <0, 1, -3>, 0.4 }\n" + many;
    EXPECT_NE(warningsFor(text).find("scene.drt:3:1: warning: the camera at <0, 1, -4> is inside this object"),
              std::string::npos)
        << warningsFor(text);
    EXPECT_EQ(warningsFor(std::string(kCamera) + kLight + many), "");
    const std::string moving = std::string(kCamera) + kLight +
                               "sphere { <0, 1, -4>, 2 motion { translate <0.1, 0, 0> } }\n";
    EXPECT_NE(warningsFor(moving).find("is inside this object"), std::string::npos) << warningsFor(moving);
}

TEST(SceneWarnings, ObjectsMeantToBeEnteredOrWithoutAnInsideAreFine) {
    for (const char* around : {"sphere { <0, 1, -4>, 100 hollow }",            // a sky dome
                               "cylinder { <0, 0, -4>, <0, 3, -4>, 0.5 open }", // an open tube
                               "sphere { <0, 1, -4>, 2 inverse }",              // the camera is outside it
                               "plane { z, 2 }",                                // a wall: its inside holds the camera
                               "sphere { <0, 1, -4>, 2 clipped_by { plane { y, 1.5 } } }"})
        EXPECT_EQ(warningsFor(std::string(kCamera) + kLight + around + "\n"), "") << around;
    // An object behind or beside the camera is not around it.
    EXPECT_EQ(warningsFor(std::string(kCamera) + kLight + "sphere { <0, 1, -7>, 2 }\nbox { <-1, 0, 0>, <1, 1, 1> }\n"),
              "");
}

TEST(SceneWarnings, CheckAndRenderPrintThemAndStillSucceed) {
    const std::string dir = test::tempDir();
    const std::string scene = test::writeFile(dir + "/dark.drt", "render { width 8 height 6 }\n" + std::string(kCamera) +
                                                                     "sphere { <0, 0.5, 0>, 0.5 }\n");
    const auto check = test::runDrt("check '" + scene + "'");
    EXPECT_EQ(check.exitCode, 0);
    EXPECT_NE(check.err.find("has no light_source"), std::string::npos) << check.err;
    const auto render = test::runDrt("render '" + scene + "' -o '" + dir + "/dark.png' --quiet");
    EXPECT_EQ(render.exitCode, 0);
    EXPECT_NE(render.err.find("has no light_source"), std::string::npos) << render.err;
}

} // namespace
} // namespace drt
