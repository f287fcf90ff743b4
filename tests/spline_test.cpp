// Splines as values (both dialects): `spline { ... }` read, called as S(t) and
// S(t, kind), copied, and wrapped as functions (`function { spline { ... } }`,
// F(t).y inside other functions). The expected values are POV-Ray 3.7's own,
// printed by its #debug at the same parameters.
#include "lang/load.h"
#include "lang/writer.h"
#include "scene/function.h"
#include "scene/spline.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>

namespace drt {
namespace {

const char* kSplines = "#declare L = spline { linear_spline 0, <0,0,0>, 1, <1,2,0>, 3, <2,0,4>, 4, <0,1,1> }\n"
                       "#declare Q = spline { quadratic_spline 0, <0,0,0>, 1, <1,2,0>, 3, <2,0,4>, 4, <0,1,1> }\n"
                       "#declare C = spline { cubic_spline 0, <0,0,0>, 1, <1,2,0>, 3, <2,0,4>, 4, <0,1,1>, 6, <3,3,3> }\n"
                       "#declare N = spline { natural_spline 0, <0,0,0>, 1, <1,2,0>, 3, <2,0,4>, 4, <0,1,1>, 6, <3,3,3> }\n";

class SplineDialects : public ::testing::TestWithParam<bool> {};

// The value of a vector expression after the splines above, printed with 9 decimals.
std::string value(bool pov, const std::string& expression, const std::string& before = "") {
    auto r = test::readSceneText(std::string(kSplines) + before + "#warning vstr(3, " + expression + ", \",\", 0, 9)\n", pov);
    EXPECT_FALSE(r->diags.hasErrors()) << r->diags.formatAll();
    return r->messages.empty() ? "<none>" : r->messages[0];
}

TEST_P(SplineDialects, ValuesAreTheSameAsPovRaysAtItsOwnSamplePoints) {
    const bool pov = GetParam();
    EXPECT_EQ(value(pov, "L(0.3)"), "0.300000000,0.600000000,0.000000000");
    EXPECT_EQ(value(pov, "L(1.5)"), "1.250000000,1.500000000,1.000000000");
    EXPECT_EQ(value(pov, "L(-1)"), "0.000000000,0.000000000,0.000000000");
    EXPECT_EQ(value(pov, "L(7)"), "0.000000000,1.000000000,1.000000000");
    EXPECT_EQ(value(pov, "Q(0.3)"), "0.335000000,0.810000000,-0.140000000");
    EXPECT_EQ(value(pov, "Q(1.5)"), "1.375000000,2.250000000,0.500000000");
    EXPECT_EQ(value(pov, "Q(2.2)"), "1.760000000,1.760000000,1.760000000");
    EXPECT_EQ(value(pov, "Q(3.7)"), "0.775000000,0.560000000,2.250000000");
    EXPECT_EQ(value(pov, "C(-1)"), "1.000000000,2.000000000,0.000000000");
    EXPECT_EQ(value(pov, "C(0.3)"), "1.000000000,2.000000000,0.000000000");
    EXPECT_EQ(value(pov, "C(1.5)"), "1.437500000,1.828125000,0.953125000");
    EXPECT_EQ(value(pov, "C(2.2)"), "2.008000000,0.800000000,2.928000000");
    EXPECT_EQ(value(pov, "C(3.7)"), "0.421500000,0.637000000,1.763500000");
    EXPECT_EQ(value(pov, "C(5)"), "0.000000000,1.000000000,1.000000000");
    EXPECT_EQ(value(pov, "N(0.3)"), "0.271379032,0.789338710,-0.202548387");
    EXPECT_EQ(value(pov, "N(1.5)"), "1.641633065,1.865927419,1.175403226");
    EXPECT_EQ(value(pov, "N(2.2)"), "2.326193548,0.840258065,3.285677419");
    EXPECT_EQ(value(pov, "N(3.7)"), "0.512274194,0.576032258,1.923709677");
    EXPECT_EQ(value(pov, "N(5)"), "0.483870968,2.145161290,0.693548387");
    EXPECT_EQ(value(pov, "N(7)"), "3.000000000,3.000000000,3.000000000");
    // Another kind at the call; a copy; a copy with another kind.
    EXPECT_EQ(value(pov, "C(2, linear_spline)"), "1.500000000,1.000000000,2.000000000");
    EXPECT_EQ(value(pov, "C(2, natural_spline)"), "2.189516129,1.169354839,2.725806452");
    EXPECT_EQ(value(pov, "C2(2)", "#declare C2 = spline { C }\n"), "1.875000000,1.125000000,2.375000000");
    EXPECT_EQ(value(pov, "C3(2)", "#declare C3 = spline { C linear_spline }\n"), "1.500000000,1.000000000,2.000000000");
    // Linear by default; entries sorted by their parameter; in arithmetic as in Spline_Trans.
    EXPECT_EQ(value(pov, "D(1.5)", "#declare D = spline { 0, <0,0,0> 1, <1,1,1> 2, <4,4,4> }\n"),
              "2.500000000,2.500000000,2.500000000");
    EXPECT_EQ(value(pov, "U(1.5)", "#declare U = spline { 2, <4,4,4>, 0, <0,0,0>, 1, <1,1,1> }\n"),
              "2.500000000,2.500000000,2.500000000");
    EXPECT_EQ(value(pov, "<0, 0, 0> + L(1) * 2"), "2.000000000,4.000000000,0.000000000");
}

TEST_P(SplineDialects, NumbersGiveTwoComponentsAndVectorsTheirOwn) {
    const bool pov = GetParam();
    auto r = test::readSceneText("#declare F = spline { linear_spline 0, 1, 1, 3 }\n"
                                 "#declare S2 = spline { linear_spline 0, <1, 2>, 2, <3, 6> }\n"
                                 "#warning vstr(2, F(0.5), \",\", 0, 6)\n#warning vstr(2, S2(1), \",\", 0, 6)\n"
                                 "#warning str(F(0.5).y, 0, 6)\n",
                                 pov);
    ASSERT_FALSE(r->diags.hasErrors()) << r->diags.formatAll();
    ASSERT_EQ(r->messages.size(), 3u);
    EXPECT_EQ(r->messages[0], "2.000000,2.000000");
    EXPECT_EQ(r->messages[1], "2.000000,4.000000");
    EXPECT_EQ(r->messages[2], "2.000000");
    auto bad = test::readSceneText("#declare F = spline { 0, 1, 1, 3 }\n#declare V = F(0.5).z;\n", pov);
    test::expectErrorAt(bad->diags, pov ? "t.pov" : "t.drt", 2, 21, "'.z' of a 2-component vector");
}

// splinefunction.pov's form: a spline function, called in the scene and inside a pigment's function.
TEST_P(SplineDialects, SplineFunctionsAreCalledInTheSceneAndInFunctions) {
    const bool pov = GetParam();
    const std::string name = pov ? "f.pov" : "f.drt";
    Diagnostics diags;
    const auto scene = loadSceneText(
        "#declare Spl = function { spline { cubic_spline -0.001, <0, 0, 0>, 0.25, <0.25, 0.5, 0>,\n"
        "  0.5, <0.5, 0.1, 0>, 0.75, <0.75, 0.9, 0>, 1.001, <1, 0, 0> } }\n"
        "#declare P = function { pigment { function { Spl(x).y } } }\n"
        "#declare Mid = Spl(0.5);\n"
        "sphere { Mid, 0.01 }\n"
        "box { 0, 1 pigment { function { P(x, y, z).gray } } }\n"
        "box { 0, 1 pigment { function { (spline { linear_spline 0, <0, 1>, 1, <1, 0> }(x).v) } } }\n",
        name, diags, LoadOptions{});
    ASSERT_TRUE(scene) << diags.formatAll();
    const Sphere& s = std::get<Sphere>(scene->objects.at(0).shape);
    EXPECT_EQ(s.center, Vec3(0.5, 0.1, 0));
    const Function& f = *scene->objects.at(1).texture->pigment.function;
    const Function& inlined = *scene->objects.at(2).texture->pigment.function;
    EXPECT_DOUBLE_EQ(inlined.at(Vec3(0.25, 0, 0)), 0.75);
    EXPECT_DOUBLE_EQ(inlined.at(Vec3(2, 0, 0)), 0);

    // drt convert writes both back; read back they give the same values.
    const std::string written = writeDrtScene(*scene);
    Diagnostics backDiags;
    const auto back = loadSceneText(written, "back.drt", backDiags, LoadOptions{});
    ASSERT_TRUE(back) << backDiags.formatAll() << "\n" << written;
    const Function& inlinedBack = *back->objects.at(2).texture->pigment.function;
    EXPECT_TRUE(inlinedBack == inlined) << written;
    // The pigment function's call is written out in place: the same values (the gray of a grey
    // ramp at Spl(x).y: POV-Ray's 0.281125498 at x = 0.375).
    const Function& fBack = *back->objects.at(1).texture->pigment.function;
    EXPECT_NEAR(f.at(Vec3(0.375, 0, 0)), 0.281125498, 1e-6);
    for (const double x : {0.1, 0.375, 0.6, 0.9}) EXPECT_DOUBLE_EQ(fBack.at(Vec3(x, 0, 0)), f.at(Vec3(x, 0, 0))) << written;
}

INSTANTIATE_TEST_SUITE_P(Dialects, SplineDialects, ::testing::Values(false, true),
                         [](const auto& info) { return std::string(info.param ? "Pov" : "Drt"); });

TEST(Spline, SplineFunctionValueIsTheCallsComponent) {
    Diagnostics diags;
    const auto scene = loadSceneText(
        "#declare Spl = function { spline { cubic_spline -0.001, <0, 0, 0>, 0.25, <0.25, 0.5, 0>,\n"
        "  0.5, <0.5, 0.1, 0>, 0.75, <0.75, 0.9, 0>, 1.001, <1, 0, 0> } }\n"
        "box { 0, 1 pigment { function { Spl(x).y } } }\n",
        "f.pov", diags, LoadOptions{});
    ASSERT_TRUE(scene) << diags.formatAll();
    const Function& f = *scene->objects.at(0).texture->pigment.function;
    // POV-Ray's #debug of G(0.375, 0, 0) and G(0.6, 0, 0), G = function { Spl(x).y }.
    EXPECT_NEAR(f.at(Vec3(0.375, 0, 0)), 0.281125498, 1e-9);
    EXPECT_NEAR(f.at(Vec3(0.6, 0, 0)), 0.415027888, 1e-9);
}

// The entries one at a time, as a scene gives them: each goes in order of t,
// and one of a t already there replaces that entry's value (keeping its t).
std::vector<Spline::Entry> insertedOneByOne(const std::vector<Spline::Entry>& start,
                                            const std::vector<Spline::Entry>& added) {
    std::vector<Spline::Entry> e = start;
    for (const Spline::Entry& a : added) {
        size_t i = 0;
        while (i < e.size() && e[i].t < a.t) ++i;
        if (i < e.size() && e[i].t == a.t) e[i].v = a.v;
        else e.insert(e.begin() + std::ptrdiff_t(i), a);
    }
    return e;
}

// Insert takes a block's entries in one go (sorted once, curvatures solved
// once); the result is that of inserting them one by one, to the bit: order,
// replaced values, the t kept for an equal t (0 and -0), and the natural
// spline's values.
TEST(Spline, EntriesInsertedInOneGoAreThoseInsertedOneByOne) {
    std::mt19937 random(7);
    std::uniform_int_distribution<int> tick(-6, 6), count(0, 40);
    for (int trial = 0; trial < 300; ++trial) {
        const auto some = [&](int n) {
            std::vector<Spline::Entry> v;
            for (int i = 0; i < n; ++i) {
                const int k = tick(random);
                // Few distinct t, so that many repeat; -0 beside 0.
                const double t = k == 6 ? -0.0 : k * 0.5;
                v.push_back({t, {double(random() % 100), double(trial), double(i), 0, 1}});
            }
            return v;
        };
        Spline start;
        start.insert(some(count(random) % 5));
        const std::vector<Spline::Entry> added = some(count(random));
        Spline s = start;
        s.insert(added);
        const std::vector<Spline::Entry> expected = insertedOneByOne(start.entries, added);
        ASSERT_EQ(s.entries.size(), expected.size()) << trial;
        for (size_t i = 0; i < expected.size(); ++i) {
            EXPECT_EQ(std::bit_cast<uint64_t>(s.entries[i].t), std::bit_cast<uint64_t>(expected[i].t)) << trial;
            EXPECT_EQ(s.entries[i].v, expected[i].v) << trial << " entry " << i;
        }
        Spline one = start;
        for (const Spline::Entry& a : added) one.insert(a.t, a.v);
        for (double t = -3.25; t <= 3.25; t += 0.37)
            EXPECT_EQ(s.at(t, Spline::Kind::Natural), one.at(t, Spline::Kind::Natural)) << trial << " at " << t;
    }
}

// A loop that adds entries one by one (a fuzzer's find: such a spline inside a
// #while took over ten minutes for 300,000 entries, each insert scanning the
// entries and solving the natural curvatures again).
TEST(Spline, AScenesLoopOfAHundredThousandEntriesIsReadInOneSolve) {
    for (const bool pov : {false, true}) {
        const std::string loop = pov ? "#declare I = 0;\n#while (I < 100000)\n  I, <2 * I, 0, 0>\n  #declare I = I + 1;\n#end\n"
                                     : "#for (I, 0, 99999)\n  I, <2 * I, 0, 0>\n#end\n";
        auto r = test::readSceneText("#declare S = spline { natural_spline\n" + loop +
                                         "}\n#warning vstr(3, S(54321.5), \",\", 0, 3)\n",
                                     pov);
        ASSERT_FALSE(r->diags.hasErrors()) << r->diags.formatAll();
        ASSERT_EQ(r->messages.size(), 1u);
        EXPECT_EQ(r->messages[0], "108643.000,0.000,0.000") << pov;
    }
}

struct SplineError {
    const char* name;
    const char* source;
    const char* message;
    int line, column;
};

class SplineErrors : public ::testing::TestWithParam<SplineError> {};

TEST_P(SplineErrors, MessageLocationAndCaret) {
    const SplineError& c = GetParam();
    for (const char* file : {"e.drt", "e.pov"}) {
        Diagnostics diags;
        EXPECT_FALSE(loadSceneText(c.source, file, diags, LoadOptions{})) << file;
        test::expectErrorAt(diags, file, c.line, c.column, c.message);
    }
}

// clang-format off
const SplineError kSplineErrors[] = {
    {"NoEntries", "#declare S = spline { cubic_spline }", "spline has no entries", 1, 14},
    {"NoBrace", "#declare S = spline 0, 1", "expected '{' after 'spline', found '0'", 1, 21},
    {"EntryNotAValue", "#declare S = spline { 0, \"a\" }",
     "a spline entry's value must be a number or a vector, not a string", 1, 26},
    {"UnknownKindAtTheCall", "#declare S = spline { 0, 1 1, 2 }\n#declare V = S(0.5, cubic);",
     "unknown spline kind 'cubic'; did you mean 'cubic_spline'?", 2, 21},
    {"UnclosedCall", "#declare S = spline { 0, 1 1, 2 }\n#declare V = S(0.5;",
     "expected ')' to close the spline's parameter, found ';'", 2, 19},
    {"ComponentInAFunction", "#declare S = function { spline { 0, <1, 2> 1, <2, 3> } }\n"
     "#declare F = function { S(x).z }", "'.z' of a 2-component spline", 2, 30},
    {"CalledAtTheStartOfABody", "#declare F = function { spline { 0, 1 1, 2 }(x) }",
     "a body that starts with 'spline { }' is that spline; to call it at a point, write (spline { ... }(t))", 1, 45},
    {"TwoParameters", "#declare S = function(a, b) { spline { 0, 1 1, 2 } }",
     "a spline function has one parameter", 1, 31},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Cases, SplineErrors, ::testing::ValuesIn(kSplineErrors),
                         [](const auto& info) { return std::string(info.param.name); });

} // namespace
} // namespace drt
