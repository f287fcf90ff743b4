// The POV-Ray front end's prism and text objects: syntax variants, font
// search, errors, extents, and POV-Ray's shipped scenes that use them.
#include "outline/prism_outline.h"
#include "outline/text_outline.h"
#include "pov/load.h"

#include <gtest/gtest.h>

#include <functional>

namespace drt {
namespace {

constexpr const char* kExamples = "/usr/share/doc/povray/examples/";

std::optional<Scene> load(const std::string& text, Diagnostics& diags) {
    return loadPovSceneText(text, "s.pov", diags);
}

const Extrusion& onlyExtrusion(const Scene& scene) {
    EXPECT_EQ(scene.objects.size(), 1u);
    return std::get<Extrusion>(scene.objects.at(0).shape);
}

bool sameContours(const std::vector<std::vector<Vec2>>& a, const std::vector<std::vector<Vec2>>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        if (a[i].size() != b[i].size()) return false;
        for (size_t k = 0; k < a[i].size(); ++k)
            if (a[i][k].x != b[i][k].x || a[i][k].y != b[i][k].y) return false;
    }
    return true;
}

TEST(PovExtrusion, TextWithAndWithoutCommasAndExtension) {
    for (const char* source : {"text { ttf \"timrom.ttf\" \"Hi\", 0.5, <0.1, 0.02, 0> }",
                               "text { ttf \"timrom\" \"Hi\" 0.5 <0.1, 0.02, 0> }"}) {
        SCOPED_TRACE(source);
        Diagnostics diags;
        const auto scene = load(source, diags);
        ASSERT_TRUE(scene) << diags.formatAll();
        EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
        const Extrusion& e = onlyExtrusion(*scene);
        ASSERT_TRUE(e.text);
        EXPECT_EQ(e.text->fontPath, std::string(kPovFontDir) + "/timrom.ttf");
        EXPECT_EQ(e.plane, Extrusion::Plane::XY);
        EXPECT_EQ(e.fill, Extrusion::Fill::NonZero);
        EXPECT_EQ(e.height1, 0);
        EXPECT_EQ(e.height2, 0.5);
        EXPECT_TRUE(sameContours(e.contours, textContours(e.text->fontPath, "Hi", {0.1, 0.02})));
    }
}

TEST(PovExtrusion, TextExtentsFollowTheGlyphBoxes) {
    // A text of one space has no outline: POV-Ray's box is a point (width 0),
    // which shapes.inc's Text_Width relies on.
    const char* source = R"(
#declare W = max_extent(text { ttf "timrom.ttf" " " 1, 0 }).x - min_extent(text { ttf "timrom.ttf" " " 1, 0 }).x;
#declare T = text { ttf "timrom.ttf" "H" 1, 0 }
sphere { <max_extent(T).x, min_extent(T).y, max_extent(T).z>, 1 + W }
)";
    Diagnostics diags;
    const auto scene = load(source, diags);
    ASSERT_TRUE(scene) << diags.formatAll();
    const Sphere& s = std::get<Sphere>(scene->objects.at(0).shape);
    EXPECT_EQ(s.radius, 1);
    Vec2 lo, hi;
    textContours(std::string(kPovFontDir) + "/timrom.ttf", "H", {0, 0}, &lo, &hi);
    EXPECT_EQ(s.center.x, hi.x);
    EXPECT_EQ(s.center.y, 0); // H sits on the baseline
    EXPECT_EQ(s.center.z, 1);
}

TEST(PovExtrusion, PrismVariants) {
    // The count may be followed by the first point without a comma: '<' starts the point.
    const char* source = R"(
prism { -0.5, 0.5, 4
  <-1, -0.3>, <1, 0>, <-1, 0.3>, <-1, -0.3> }
prism { cubic_spline conic_sweep 0, 1, 6, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <1, 0>, <1, 1> open sturm }
)";
    Diagnostics diags;
    const auto scene = load(source, diags);
    ASSERT_TRUE(scene) << diags.formatAll();
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    ASSERT_EQ(scene->objects.size(), 2u);
    const Extrusion& a = std::get<Extrusion>(scene->objects[0].shape);
    ASSERT_EQ(a.contours.size(), 1u);
    EXPECT_EQ(a.contours[0].size(), 3u);
    EXPECT_EQ(a.height1, -0.5);
    EXPECT_FALSE(a.conic);
    const Extrusion& b = std::get<Extrusion>(scene->objects[1].shape);
    EXPECT_TRUE(b.conic);
    EXPECT_TRUE(b.open);
    EXPECT_EQ(b.prism->spline, PrismSource::Spline::Cubic);
    EXPECT_TRUE(sameContours(b.contours, prismContours(PrismSource::Spline::Cubic, b.prism->points)));
}

TEST(PovExtrusion, MissingFontIsAnErrorWithItsLocation) {
    Diagnostics diags;
    EXPECT_FALSE(load("#declare F = \"nofont.ttf\";\ntext { ttf F \"a\" 1, 0 }", diags));
    ASSERT_EQ(diags.errorCount(), 1);
    const Diagnostic& d = diags.all().back();
    EXPECT_EQ(d.message.rfind("cannot find font 'nofont.ttf' (looked in ", 0), 0u) << d.message;
    EXPECT_EQ(d.loc.line, 2);
    EXPECT_EQ(d.loc.column, 12);
}

TEST(PovExtrusion, PrismErrorsAndInternalFontWarning) {
    Diagnostics diags;
    EXPECT_FALSE(load("prism { 0, 1, 2, <0, 0>, <1, 0> }", diags));
    EXPECT_EQ(diags.all().back().message, "this prism spline needs at least 3 points");
    EXPECT_EQ(diags.all().back().loc.column, 15);
    Diagnostics quadratic;
    EXPECT_FALSE(load("prism { quadratic_spline 0, 1, 6, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 2>, <5, 5> }", quadratic));
    EXPECT_EQ(quadratic.all().back().message,
              "too few points in prism: a sub-polygon is not closed or control points are missing");
    Diagnostics internal;
    const auto scene = load("text { internal 1 \"abc\" 1, 0 }\nsphere { 0, 1 }", internal);
    ASSERT_TRUE(scene) << internal.formatAll();
    EXPECT_EQ(scene->objects.size(), 1u);
    ASSERT_EQ(internal.warningCount(), 1);
    EXPECT_EQ(internal.all().back().message, "POV-Ray's internal fonts are not supported; the text is left out");
}

// POV-Ray's own scenes that use text and prism load without a word about them.
TEST(PovExtrusion, ShippedScenesWithTextAndPrismLoad) {
    for (const char* name : {"advanced/float5.pov", "interior/atten2.pov", "incdemo/circletext.pov",
                             "advanced/blocks/stackerday.pov"}) {
        SCOPED_TRACE(name);
        Diagnostics diags;
        PovOptions options;
        const auto scene = loadPovSceneFile(std::string(kExamples) + name, diags, options);
        ASSERT_TRUE(scene) << diags.formatAll();
        for (const Diagnostic& d : diags.all()) {
            EXPECT_EQ(d.message.find("'text'"), std::string::npos) << d.message;
            EXPECT_EQ(d.message.find("'prism'"), std::string::npos) << d.message;
        }
        int extrusions = 0;
        std::function<void(const Object&)> count = [&](const Object& o) {
            extrusions += std::holds_alternative<Extrusion>(o.shape);
            if (const Csg* csg = std::get_if<Csg>(&o.shape))
                for (const Object& child : csg->children) count(child);
        };
        for (const Object& o : scene->objects) count(o);
        EXPECT_GT(extrusions, 0);
    }
}

} // namespace
} // namespace drt
