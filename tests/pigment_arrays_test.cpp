// Colours and pigments taken from arrays inside a pigment, in both dialects:
// `pigment { Colors[2] }`, `color Colors[I]`, an element in a colour
// expression (`Colors[I] * 0.5`, also as a macro's result), in a list pattern
// (`checker Colors[0], Colors[1]`, `checker Pigments[0], Pigments[1]`) and in
// a colour map.
#include "lang/load.h"
#include "render/pigment.h"
#include "test_support.h"

#include <gtest/gtest.h>

namespace drt {
namespace {

class PigmentArrays : public ::testing::TestWithParam<const char*> {};

Color colourOf(const Scene& s, size_t i, const Vec3& at = Vec3(0.5, 0.5, 0.5)) {
    return evaluatePigment(s.objects.at(i).texture->pigment, at).rgb;
}

TEST_P(PigmentArrays, ElementsAreColoursAndPigments) {
    Diagnostics diags;
    const auto s = loadSceneText(
        "#declare Colors = array[3] { rgb <1, 0, 0>, rgb <0, 1, 0>, rgb <0, 0, 1> };\n"
        "#declare Pigments = array[2] { pigment { rgb 0.25 }, pigment { rgb 0.75 } };\n"
        "#declare I = 1;\n"
        "#macro Pick(A, K) A[K] #end\n"
        "sphere { 0, 1 pigment { Colors[2] } }\n"
        "sphere { 0, 1 pigment { color Colors[I] } }\n"
        "sphere { 0, 1 pigment { Colors[I] * 0.5 } }\n"
        "sphere { 0, 1 pigment { Pick(Colors, 0) * 0.5 + Colors[2] } }\n"
        "sphere { 0, 1 pigment { checker Colors[0], Colors[1] } }\n"
        "sphere { 0, 1 pigment { checker Pigments[0], Pigments[1] } }\n"
        "sphere { 0, 1 pigment { gradient x color_map { [0 Colors[0]] [1 color Colors[I + 1]] } } }\n"
        "sphere { 0, 1 pigment { Pigments[1] } }\n",
        GetParam(), diags, LoadOptions{});
    ASSERT_TRUE(s) << diags.formatAll();
    EXPECT_EQ(colourOf(*s, 0), Color(0, 0, 1));
    EXPECT_EQ(colourOf(*s, 1), Color(0, 1, 0));
    EXPECT_EQ(colourOf(*s, 2), Color(0, 0.5, 0));
    EXPECT_EQ(colourOf(*s, 3), Color(0.5, 0, 1));
    // checker: cell (0, 0, 0) takes the first entry, (1, 0, 0) the second.
    EXPECT_EQ(colourOf(*s, 4, Vec3(0.5, 0.5, 0.5)), Color(1, 0, 0));
    EXPECT_EQ(colourOf(*s, 4, Vec3(1.5, 0.5, 0.5)), Color(0, 1, 0));
    EXPECT_EQ(colourOf(*s, 5, Vec3(0.5, 0.5, 0.5)), Color(0.25));
    EXPECT_EQ(colourOf(*s, 5, Vec3(1.5, 0.5, 0.5)), Color(0.75));
    EXPECT_EQ(colourOf(*s, 6, Vec3(0.25, 0, 0)), Color(0.75, 0, 0.25));
    EXPECT_EQ(colourOf(*s, 7), Color(0.75));
}

TEST_P(PigmentArrays, AnElementOfTheWrongKindIsAnError) {
    Diagnostics diags;
    const auto s = loadSceneText("#declare P = array[2] { pigment { rgb 1 }, finish { ambient 1 } };\n"
                                 "sphere { 0, 1 pigment { checker P[0], P[1] } }\n",
                                 GetParam(), diags, LoadOptions{});
    EXPECT_FALSE(s);
    EXPECT_NE(diags.formatAll().find(std::string(GetParam()) + ":2:39: error: 'P' element is a finish, not a pigment"),
              std::string::npos)
        << diags.formatAll();
}

INSTANTIATE_TEST_SUITE_P(Dialects, PigmentArrays, ::testing::Values("a.drt", "a.pov"),
                         [](const auto& info) { return std::string(info.param[2] == 'd' ? "Drt" : "Pov"); });

} // namespace
} // namespace drt
