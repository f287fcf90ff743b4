// One evaluator, two dialects: the .drt dialect runs every directive of the
// POV-Ray one (#declare/#local scoping, #if, #ifdef, #while, #for, #switch,
// #macro, arrays), with errors at file:line:col and a caret; a .pov scene takes
// drt's effects (motion, reflection_blur, refraction_blur, the render block).
#include "lang/load.h"
#include "test_support.h"

#include <gtest/gtest.h>

namespace drt {
namespace {

struct Loaded {
    std::optional<Scene> scene;
    Diagnostics diags;
};

std::unique_ptr<Loaded> load(const std::string& text, const std::string& name) {
    auto l = std::make_unique<Loaded>();
    l->scene = loadSceneText(text, name, l->diags, LoadOptions{});
    return l;
}

Scene loadOk(const std::string& text, const std::string& name = "d.drt") {
    auto l = load(text, name);
    EXPECT_TRUE(l->scene) << l->diags.formatAll();
    EXPECT_FALSE(l->diags.hasErrors()) << l->diags.formatAll();
    return l->scene ? *l->scene : Scene{};
}

double radius(const Scene& s, size_t i) { return std::get<Sphere>(s.objects.at(i).shape).radius; }
Vec3 centre(const Scene& s, size_t i) { return std::get<Sphere>(s.objects.at(i).shape).center; }

TEST(DrtDirectives, ForLoopPlacesARowOfSpheres) {
    const Scene s = loadOk("#for (I, 0, 49)\n  sphere { <I, 0, 0>, 0.4 }\n#end\n");
    ASSERT_EQ(s.objects.size(), 50u);
    EXPECT_EQ(centre(s, 0), Vec3(0, 0, 0));
    EXPECT_EQ(centre(s, 49), Vec3(49, 0, 0));
}

TEST(DrtDirectives, ForLoopWithStepAndEmptyRange) {
    const Scene s = loadOk("#for (I, 3, 0, -1.5) sphere { 0, I + 1 } #end\n#for (J, 1, 0) sphere { 0, 9 } #end\n");
    ASSERT_EQ(s.objects.size(), 3u); // 3, 1.5, 0; the second loop runs no time
    EXPECT_DOUBLE_EQ(radius(s, 0), 4);
    EXPECT_DOUBLE_EQ(radius(s, 1), 2.5);
    EXPECT_DOUBLE_EQ(radius(s, 2), 1);
}

TEST(DrtDirectives, WhileLoopAndDeclareInsideIt) {
    const Scene s = loadOk("#declare N = 0;\n#while (N < 4)\n  sphere { y * N, 1 + N }\n  #declare N = N + 1;\n#end\n"
                           "sphere { 0, N }\n");
    ASSERT_EQ(s.objects.size(), 5u);
    EXPECT_DOUBLE_EQ(radius(s, 3), 4);
    EXPECT_DOUBLE_EQ(radius(s, 4), 4); // N kept its last value after the loop
}

TEST(DrtDirectives, IfElseifElseAndDefinedTests) {
    const Scene s = loadOk("#declare A = 2;\n"
                           "#if (A < 1) sphere { 0, 1 } #elseif (A < 3) sphere { 0, 2 } #else sphere { 0, 3 } #end\n"
                           "#ifdef (A) sphere { 0, 4 } #end\n"
                           "#ifndef (B) sphere { 0, 5 } #else sphere { 0, 6 } #end\n"
                           "#if (A = 2 & !(A > 5)) sphere { 0, 7 } #end\n");
    ASSERT_EQ(s.objects.size(), 4u);
    EXPECT_DOUBLE_EQ(radius(s, 0), 2);
    EXPECT_DOUBLE_EQ(radius(s, 1), 4);
    EXPECT_DOUBLE_EQ(radius(s, 2), 5);
    EXPECT_DOUBLE_EQ(radius(s, 3), 7);
}

TEST(DrtDirectives, SwitchWithCaseRangeBreakAndElse) {
    auto pick = [](double v) {
        const Scene s = loadOk("#switch (" + std::to_string(v) +
                               ")\n"
                               "  #case (1) sphere { 0, 1 } #break\n"
                               "  #range (2, 4) sphere { 0, 2 } #break\n"
                               "  #case (5) #case (6) sphere { 0, 3 } #break\n"
                               "  #else sphere { 0, 4 }\n"
                               "#end\n");
        return s.objects.size() == 1 ? radius(s, 0) : -1.0;
    };
    EXPECT_DOUBLE_EQ(pick(1), 1);
    EXPECT_DOUBLE_EQ(pick(3.5), 2);
    EXPECT_DOUBLE_EQ(pick(5), 3); // falls through from #case (5) to #case (6)
    EXPECT_DOUBLE_EQ(pick(6), 3);
    EXPECT_DOUBLE_EQ(pick(9), 4);
}

TEST(DrtDirectives, MacrosTakeArgumentsAndRecurse) {
    const Scene s = loadOk("#macro Ball(P, R) sphere { P, R pigment { rgb <1, 0, 0> } } #end\n"
                           "#macro Tower(N) #if (N > 0) Ball(<0, N, 0>, N) Tower(N - 1) #end #end\n"
                           "#macro Twice(X) (2 * X) #end\n"
                           "Tower(3)\n"
                           "sphere { 0, Twice(1.5) }\n");
    ASSERT_EQ(s.objects.size(), 4u);
    EXPECT_EQ(centre(s, 0), Vec3(0, 3, 0));
    EXPECT_DOUBLE_EQ(radius(s, 2), 1);
    EXPECT_EQ(s.objects[2].texture->pigment.color.rgb, Color(1, 0, 0));
    EXPECT_DOUBLE_EQ(radius(s, 3), 3);
}

TEST(DrtDirectives, LocalIsScopedToItsMacroAndDeclareIsGlobal) {
    const Scene s = loadOk("#declare R = 1;\n"
                           "#macro M() #local R = 5; sphere { 0, R } #declare G = R; #end\n"
                           "M()\nsphere { 0, R }\nsphere { 0, G }\n");
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_DOUBLE_EQ(radius(s, 0), 5);
    EXPECT_DOUBLE_EQ(radius(s, 1), 1); // the macro's #local did not touch the global R
    EXPECT_DOUBLE_EQ(radius(s, 2), 5);
}

TEST(DrtDirectives, ArraysOfNumbersVectorsAndObjects) {
    const Scene s = loadOk("#declare Radii = array[3] { 0.5, 1, 1.5 };\n"
                           "#declare Grid = array[2][2] { { <0, 0, 0>, <1, 0, 0> }, { <0, 1, 0>, <1, 1, 0> } };\n"
                           "#declare Things = array[2];\n"
                           "#declare Things[0] = sphere { <9, 9, 9>, 2 }\n"
                           "#declare Things[1] = sphere { 0, 3 }\n"
                           "#for (I, 0, dimension_size(Radii, 1) - 1) sphere { Grid[1][1] * I, Radii[I] } #end\n"
                           "object { Things[1] }\n"
                           "sphere { 0, dimensions(Grid) }\n");
    ASSERT_EQ(s.objects.size(), 5u);
    EXPECT_DOUBLE_EQ(radius(s, 2), 1.5);
    EXPECT_EQ(centre(s, 2), Vec3(2, 2, 0));
    EXPECT_DOUBLE_EQ(radius(s, 3), 3);
    EXPECT_DOUBLE_EQ(radius(s, 4), 2);
}

TEST(DrtDirectives, TheSameTextGivesTheSameSceneInBothDialects) {
    const std::string text = "#declare Rows = 3;\n"
                             "#macro Row(Z) #for (I, 0, Rows - 1) sphere { <I, 0, Z>, 0.25 } #end #end\n"
                             "#local J = 0;\n#while (J < 2) Row(J) #declare J = J + 1; #end\n";
    const Scene drt = loadOk(text, "a.drt");
    const Scene pov = loadOk(text, "a.pov");
    ASSERT_EQ(drt.objects.size(), 6u);
    ASSERT_EQ(pov.objects.size(), 6u);
    for (size_t i = 0; i < 6; ++i) EXPECT_EQ(centre(drt, i), centre(pov, i));
}

// ---------------------------------------------------------------- errors

struct DirectiveError {
    const char* name;
    const char* source;
    const char* message;
    int line, column;
};

std::ostream& operator<<(std::ostream& os, const DirectiveError& c) { return os << c.name; }

class DrtDirectiveErrors : public testing::TestWithParam<DirectiveError> {};

// Each error has its location and, printed, the source line with a caret under the column.
TEST_P(DrtDirectiveErrors, MessageLocationAndCaret) {
    const DirectiveError& c = GetParam();
    auto l = load(c.source, "e.drt");
    EXPECT_FALSE(l->scene);
    ASSERT_EQ(l->diags.errorCount(), 1) << l->diags.formatAll(); // no follow-on errors
    const Diagnostic& d = l->diags.all()[0];
    EXPECT_EQ(d.message, c.message);
    EXPECT_EQ(d.loc.line, c.line);
    EXPECT_EQ(d.loc.column, c.column);
    const std::string text = l->diags.formatAll();
    EXPECT_NE(text.find("e.drt:" + std::to_string(c.line) + ":" + std::to_string(c.column) + ": error: "),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("\n  " + std::string(c.column - 1, ' ') + "^\n"), std::string::npos) << text;
}

// clang-format off
const DirectiveError kDirectiveErrors[] = {
    {"WhileWithoutEnd", "sphere { 0, 1 }\n#while (1)\nsphere { 0, 1 }\n", "'#while' has no matching #end", 2, 1},
    {"IfWithoutEnd", "#if (1)\n  sphere { 0, 1 }\n", "'#if' has no matching #end", 1, 1},
    {"FalseIfWithoutEnd", "#if (0)\n  sphere { 0, 1 }\n", "'#if' has no matching #end", 1, 1},
    {"SwitchWithoutEnd", "#switch (1)\n#case (2)\n#break\n", "'#switch' has no matching #end", 1, 1},
    {"EndAlone", "sphere { 0, 1 }\n  #end\n", "#end without a matching #if, #while, #for, #switch or #macro", 2, 3},
    {"ElseAlone", "#else\n", "#else without #if", 1, 1},
    {"CaseOutsideSwitch", "#case (1)\n", "#case outside #switch", 1, 1},
    {"BreakOutsideLoop", "#break\n", "#break outside #switch, #while or #for", 1, 1},
    {"ForStepZero", "#for (I, 0, 10, 0)\n  sphere { 0, 1 }\n#end\n", "#for step is 0", 1, 1},
    {"ForNeedsName", "#for (1, 0, 10)\n#end\n", "expected the loop identifier, found '1'", 1, 7},
    {"WhileNeedsParen", "#while 1\n#end\n", "expected '(' after #while, found '1'", 1, 8},
    {"MacroArgumentCount", "#macro M(A) sphere { 0, A } #end\nM(1, 2)\n", "macro 'M' takes 1 parameter", 2, 1},
    {"ArrayIndexOutOfRange", "#declare A = array[2] { 1, 2 };\nsphere { 0, A[2] }\n", "array index 2 is out of range (0 to 1)", 2, 15},
    {"ArrayElementUnset", "#declare A = array[2];\nsphere { 0, A[1] }\n", "array element of 'A' used before it was given a value", 2, 13},
    {"UndefinedAfterUndef", "#declare Size = 1;\n#undef Size\nsphere { 0, Size }\n", "unknown identifier 'Size'", 3, 13},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(All, DrtDirectiveErrors, testing::ValuesIn(kDirectiveErrors),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(DrtDirectives, ARunawayLoopStopsWithOneError) {
    auto l = load("#declare I = 0;\n#while (1)\n  #declare I = I + 1;\n#end\n", "e.drt");
    EXPECT_FALSE(l->scene);
    ASSERT_EQ(l->diags.errorCount(), 1) << l->diags.formatAll();
    EXPECT_EQ(l->diags.all()[0].message, "this #while loop's pass 10000001 is over the limit of 10000000 (limit "
                                         "loop_iterations = 10000000; raise it with --limit loop_iterations=N)");
    EXPECT_EQ(l->diags.all()[0].loc.line, 2);
}

TEST(DrtDirectives, AnErrorInAMacroBodyNamesTheCall) {
    auto l = load("#macro Ball(R)\n  sphere { 0, R }\n#end\nBall(1)\n  Ball(-0.5)\n", "e.drt");
    EXPECT_FALSE(l->scene);
    ASSERT_EQ(l->diags.errorCount(), 1) << l->diags.formatAll();
    const Diagnostic& d = l->diags.all()[0];
    EXPECT_EQ(d.message, "sphere radius must be positive, got -0.5");
    EXPECT_EQ(d.loc.line, 2);
    ASSERT_EQ(d.notes.size(), 1u);
    EXPECT_EQ(d.notes[0].message, "in macro 'Ball' called here");
    EXPECT_EQ(d.notes[0].loc.line, 5);
    EXPECT_EQ(d.notes[0].loc.column, 3);
    EXPECT_NE(l->diags.formatAll().find("e.drt:5:3: note: in macro 'Ball' called here"), std::string::npos);
}

TEST(DrtDirectives, ErrorsAfterADirectiveErrorAreStillReported) {
    auto l = load("#for (I, 0, 3, 0) #end\nsphere { 0, -1 }\n", "e.drt");
    EXPECT_FALSE(l->scene);
    ASSERT_EQ(l->diags.errorCount(), 2) << l->diags.formatAll();
    EXPECT_EQ(l->diags.all()[1].message, "sphere radius must be positive, got -1");
    EXPECT_EQ(l->diags.all()[1].loc.line, 2);
}

// ---------------------------------------------------------------- drt's effects in .pov scenes

TEST(PovDialect, TakesDrtEffects) {
    const Scene s = loadOk("#version 3.7;\n"
                           "render { samples 16 sampler \"stratified\" filter \"gaussian\" seed 7 }\n"
                           "camera { location <0, 1, -5> look_at 0 }\n"
                           "light_source { <5, 5, -5> color rgb 1 }\n"
                           "sphere { 0, 1 pigment { rgb <1, 0, 0> } motion { translate <1, 0, 0> } }\n"
                           "plane { y, -1 pigment { rgb 1 } finish { reflection 0.5 reflection_blur 0.2 } }\n"
                           "sphere { x, 0.5 pigment { rgbf 0.9 } finish { refraction_blur 0.1 } interior { ior 1.5 } }\n",
                           "fx.pov");
    ASSERT_EQ(s.objects.size(), 3u);
    ASSERT_EQ(s.objects[0].motion.size(), 1u);
    ASSERT_EQ(s.objects[0].motion[0].motion.keys.size(), 2u);
    EXPECT_EQ(s.objects[0].motion[0].motion.keys[1].translate, Vec3(1, 0, 0));
    EXPECT_DOUBLE_EQ(s.objects[1].texture->finish.reflectionBlur, 0.2);
    EXPECT_DOUBLE_EQ(s.objects[2].texture->finish.refractionBlur, 0.1);
    EXPECT_EQ(s.render.samplesPerPixel, 16);
    EXPECT_EQ(s.render.sampler, "stratified");
    EXPECT_EQ(s.render.filter, "gaussian");
    EXPECT_EQ(s.render.seed, 7u);
}

TEST(PovDialect, DrtEffectErrorsKeepTheirMessages) {
    auto l = load("render { sampler \"sobl\" }\n", "e.pov");
    EXPECT_FALSE(l->scene);
    ASSERT_GE(l->diags.errorCount(), 1);
    EXPECT_EQ(l->diags.all()[0].message,
              "unknown sampler 'sobl'; did you mean 'sobol'? (the samplers are sobol, independent, stratified)");
}

TEST(PovDialect, MotionBlursAPovSceneWhenRendered) {
    const std::string dir = test::tempDir();
    const std::string still = "camera { location <0, 0, -4> look_at 0 shutter_open 0 shutter_close 1 }\n"
                              "light_source { <0, 0, -10> color rgb 1 }\n"
                              "render { samples 8 }\n"
                              "sphere { 0, 1 pigment { rgb 1 } finish { ambient 1 diffuse 0 } ";
    test::writeFile(dir + "/still.pov", still + "}\n");
    test::writeFile(dir + "/moving.pov", still + "motion { translate <1.5, 0, 0> } }\n");
    for (const char* name : {"still", "moving"}) {
        const test::CommandResult r = test::runDrt("render " + dir + "/" + name + ".pov -o " + dir + "/" + name +
                                                   ".exr --width 32 --height 24 --quiet");
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    const test::CommandResult same = test::runDrt("compare " + dir + "/moving.exr " + dir + "/still.exr");
    EXPECT_NE(same.exitCode, 0) << "motion left the image unchanged: " << same.out;
}

TEST(Dialects, TheDialectOptionOverridesTheExtension) {
    // Commas between a shape's arguments are required in the .drt dialect, optional in POV-Ray's.
    const std::string text = "sphere { 0 1 }\n";
    Diagnostics asDrt;
    LoadOptions drtOptions;
    drtOptions.dialect = DialectKind::Drt;
    EXPECT_FALSE(loadSceneText(text, "x.pov", asDrt, drtOptions));
    ASSERT_GE(asDrt.errorCount(), 1);
    EXPECT_EQ(asDrt.all()[0].message, "expected ',' after the centre, found '1'");
    Diagnostics asPov;
    LoadOptions povOptions;
    povOptions.dialect = DialectKind::Pov;
    const auto scene = loadSceneText(text, "x.drt", asPov, povOptions);
    ASSERT_TRUE(scene) << asPov.formatAll();
    EXPECT_DOUBLE_EQ(std::get<Sphere>(scene->objects.at(0).shape).radius, 1);
}

} // namespace
} // namespace drt
