// clipped_by and bounded_by in the POV-Ray front end: clips reach the scene
// model in the right space, `clipped_by { bounded_by }` clips by the bounding
// objects, bounded_by alone changes nothing, and bad blocks are errors.
#include "pov/load.h"

#include <gtest/gtest.h>

namespace drt {
namespace {

std::optional<Scene> load(const std::string& text, Diagnostics& diags) {
    return loadPovSceneText(text, "s.pov", diags, PovOptions{});
}

Scene loadOk(const std::string& text) {
    Diagnostics diags;
    std::optional<Scene> scene = load(text, diags);
    EXPECT_TRUE(scene) << diags.formatAll();
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    return scene ? *scene : Scene{};
}

TEST(PovClip, ClipsMoveOnlyWithLaterTransforms) {
    const Scene s = loadOk("sphere { 0, 1 translate x clipped_by { box { -1, <0, 1, 1> } plane { y, 0 } } scale 2 }");
    ASSERT_EQ(s.objects.size(), 1u);
    const Object& o = s.objects[0];
    ASSERT_EQ(o.clippedBy.size(), 2u);
    EXPECT_TRUE(std::holds_alternative<Box>(o.clippedBy[0].shape));
    EXPECT_TRUE(std::holds_alternative<Plane>(o.clippedBy[1].shape));
    EXPECT_EQ(o.clippedBy[0].transform, Transform::scale({2, 2, 2}));
    EXPECT_EQ(o.transform, Transform::translate({1, 0, 0}).then(Transform::scale({2, 2, 2})));
}

TEST(PovClip, ClippedByBoundedByUsesTheBoundingObjects) {
    const Scene s = loadOk("sphere { 0, 1 bounded_by { box { -1, <1, 0.5, 1> } } clipped_by { bounded_by } }\n"
                           "sphere { 0, 1 clipped_by { box { -1, <1, 0.5, 1> } } bounded_by { clipped_by } }\n"
                           "sphere { 0, 1 bounded_by { box { -1, <1, 0.5, 1> } } translate y }");
    ASSERT_EQ(s.objects.size(), 3u);
    ASSERT_EQ(s.objects[0].clippedBy.size(), 1u);
    EXPECT_EQ(std::get<Box>(s.objects[0].clippedBy[0].shape).corner2, Vec3(1, 0.5, 1));
    EXPECT_EQ(s.objects[1].clippedBy.size(), 1u);
    // bounded_by alone is only a hint: no clip, nothing else changes.
    EXPECT_TRUE(s.objects[2].clippedBy.empty());
    EXPECT_EQ(s.objects[2].transform, Transform::translate({0, 1, 0}));
}

TEST(PovClip, CsgMembersAndDeclaredObjectsKeepTheirClips) {
    const Scene s = loadOk("#declare Half = sphere { 0, 1 clipped_by { plane { x, 0 } } }\n"
                           "difference { box { -1, 1 } object { Half translate y } }\n"
                           "union { object { Half } sphere { 0, 1 } clipped_by { plane { z, 0 } } translate 2 * x }");
    ASSERT_EQ(s.objects.size(), 2u);
    const Csg& difference = std::get<Csg>(s.objects[0].shape);
    ASSERT_EQ(difference.children.size(), 2u);
    ASSERT_EQ(difference.children[1].clippedBy.size(), 1u);
    // The declared clip moves with the translate written after the declaration.
    EXPECT_EQ(difference.children[1].clippedBy[0].transform, Transform::translate({0, 1, 0}));
    ASSERT_EQ(s.objects[1].clippedBy.size(), 1u);
    EXPECT_EQ(s.objects[1].clippedBy[0].transform, Transform::translate({2, 0, 0}));
}

TEST(PovClip, UnsupportedClipShapeIsLeftOutWithItsWarning) {
    Diagnostics diags;
    const auto s = load("sphere { 0, 1 clipped_by { ovus { 1, 0.5 } } }", diags);
    ASSERT_TRUE(s) << diags.formatAll();
    ASSERT_EQ(s->objects.size(), 1u);
    EXPECT_TRUE(s->objects[0].clippedBy.empty());
    EXPECT_EQ(diags.warningCount(), 1) << diags.formatAll();
}

TEST(PovClip, EmptyOrWrongBlocksAreErrors) {
    struct Case {
        const char* text;
        const char* message;
        int column;
    };
    for (const Case& c : {Case{"sphere { 0, 1 clipped_by { } }", "'clipped_by' needs at least one object", 15},
                          Case{"sphere { 0, 1 clipped_by { pigment { rgb 1 } } }",
                               "expected an object or '}' in clipped_by", 28},
                          Case{"sphere { 0, 1 bounded_by { 1 } }", "expected an object or '}' in bounded_by", 28}}) {
        Diagnostics diags;
        EXPECT_FALSE(load(c.text, diags)) << c.text;
        ASSERT_GE(diags.errorCount(), 1) << c.text;
        EXPECT_NE(diags.all()[0].message.find(c.message), std::string::npos) << diags.formatAll();
        EXPECT_EQ(diags.all()[0].loc.line, 1);
        EXPECT_EQ(diags.all()[0].loc.column, c.column) << c.text;
    }
}

} // namespace
} // namespace drt
