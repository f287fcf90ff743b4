// The POV-Ray evaluator: expressions, directives, macros, arrays, loops and
// strings with known values, and error paths with their locations. Values are
// read back through #warning messages, which carry any string.
#include "pov/load.h"
#include "test_support.h"

#include <gtest/gtest.h>

namespace drt {
namespace {

std::unique_ptr<test::SceneRun> run(const std::string& text, PovOptions options = {}) {
    return test::readSceneText(text, true, options);
}

// The value of a float expression, printed by str() with 6 decimals.
std::string value(const std::string& expression) {
    auto r = run("#warning str(" + expression + ", 0, 6)\n");
    EXPECT_FALSE(r->diags.hasErrors()) << r->diags.formatAll();
    return r->messages.empty() ? "<none>" : r->messages[0];
}

TEST(PovEval, ArithmeticAndPrecedence) {
    EXPECT_EQ(value("1 + 2 * 3"), "7.000000");
    EXPECT_EQ(value("(1 + 2) * 3"), "9.000000");
    EXPECT_EQ(value("-2 * -3 - 1"), "5.000000");
    EXPECT_EQ(value("10 / 4"), "2.500000");
    EXPECT_EQ(value("1 < 2 & 3 >= 3"), "1.000000");
    EXPECT_EQ(value("1 = 2 | !(0)"), "1.000000");
    EXPECT_EQ(value("2 != 2"), "0.000000");
    EXPECT_EQ(value("1 > 2 ? 10 : 20"), "20.000000");
}

TEST(PovEval, Functions) {
    EXPECT_EQ(value("abs(-3) + sqrt(16) + pow(2, 3)"), "15.000000");
    EXPECT_EQ(value("mod(7, 3) + div(7, 2) + int(-2.5)"), "2.000000");
    EXPECT_EQ(value("floor(-1.5) + ceil(1.2)"), "0.000000");
    EXPECT_EQ(value("degrees(pi) + radians(180)"), "183.141593");
    EXPECT_EQ(value("max(1, 5, 3) - min(4, 2)"), "3.000000");
    EXPECT_EQ(value("atan2(1, 1) * 4"), "3.141593");
    EXPECT_EQ(value("vlength(<3, 4, 0>) + vdot(x, <2, 5, 7>)"), "7.000000");
    EXPECT_EQ(value("vcross(x, y).z + vnormalize(<0, 0, 9>).z"), "2.000000");
    EXPECT_EQ(value("vrotate(x, <0, 0, 90>).y"), "1.000000");
    EXPECT_EQ(value("vaxis_rotate(x, y, -90).z"), "1.000000");
    EXPECT_EQ(value("select(-1, 1, 2) + select(0, 10, 20, 30) + select(1, 100, 200)"), "221.000000");
    EXPECT_EQ(value("exp(ln(5)) + log(100)"), "7.000000");
}

TEST(PovEval, VectorsColoursAndSwizzles) {
    EXPECT_EQ(value("(<1, 2, 3> + 1).y"), "3.000000");
    EXPECT_EQ(value("(<1, 2, 3> * <2, 2, 2>).z"), "6.000000");
    EXPECT_EQ(value("(2 * x + 3 * y).x + (2 * x + 3 * y).v"), "5.000000");
    EXPECT_EQ(value("(rgb <0.5, 0.25, 1>).green"), "0.250000");
    EXPECT_EQ(value("(rgbt <1, 1, 1, 0.3>).transmit + (rgbf 0.5).filter"), "0.800000");
    EXPECT_EQ(value("(color red 0.2 blue 0.7).blue"), "0.700000");
    EXPECT_EQ(value("<4 0 2>.z"), "2.000000"); // components separated by blanks
    EXPECT_EQ(value("t.t + u.u"), "2.000000");
    EXPECT_EQ(value("(srgb 1).red + (srgb 0).blue"), "1.000000");
}

TEST(PovEval, Strings) {
    auto r = run("#declare S = concat(\"ab\", str(12.5, 0, 1), chr(65));\n"
                 "#warning S\n"
                 "#warning substr(\"hello\", 2, 3)\n"
                 "#warning str(strlen(\"four\") + val(\"2.5\"), 0, 1)\n"
                 "#warning str(3, -4, 0)\n"
                 "#warning strupr(\"aB\")\n");
    ASSERT_FALSE(r->diags.hasErrors()) << r->diags.formatAll();
    EXPECT_EQ(r->messages, (std::vector<std::string>{"ab12.5A", "ell", "6.5", "0003", "AB"}));
}

TEST(PovEval, ConditionalsAndSwitch) {
    auto r = run("#declare A = 2;\n"
                 "#if (A = 1) #warning \"one\" #elseif (A = 2) #warning \"two\" #else #warning \"other\" #end\n"
                 "#ifdef (A) #warning \"def\" #end\n"
                 "#ifndef (B) #warning \"undef\" #end\n"
                 "#switch (A)\n #case (1) #warning \"c1\" #break\n #range (2, 3) #warning \"r23\" #break\n"
                 " #else #warning \"else\"\n#end\n"
                 "#switch (7) #case (1) #warning \"no\" #else #warning \"fallback\" #end\n"
                 "#undef A\n#ifdef (A) #warning \"still\" #end\n");
    ASSERT_FALSE(r->diags.hasErrors()) << r->diags.formatAll();
    EXPECT_EQ(r->messages, (std::vector<std::string>{"two", "def", "undef", "r23", "fallback"}));
}

// An expression goes on after the #else / #elseif / #end of an #if branch
// (advanced/isocacti.pov: a macro picks an array element with #if, and the
// call is multiplied); #while's #end still ends it.
TEST(PovEval, ExpressionsGoOnAfterTheEndOfAnIfBranch) {
    auto r = run("#macro Pick(A) #if (A > 0) 2 #elseif (A = 0) 7 #else 3 #end #end\n"
                 "#declare X = Pick(1) * 5;\n#warning str(X, 0, 0)\n"
                 "#declare X = Pick(0) * 5;\n#warning str(X, 0, 0)\n"
                 "#declare X = Pick(-1) * 5;\n#warning str(X, 0, 0)\n"
                 "#declare C = array[2] {rgb <1, 0, 0>, rgb <0, 0, 1>}\n"
                 "#macro Item(I) #if (I = 0) C[0] #else C[1] #end #end\n"
                 "#declare D = Item(1) * 0.5;\n#warning str(D.blue, 0, 2)\n"
                 "#declare Y = #if (1) 4 #else 6 #end + 1;\n#warning str(Y, 0, 0)\n");
    ASSERT_FALSE(r->diags.hasErrors()) << r->diags.formatAll();
    EXPECT_EQ(r->messages, (std::vector<std::string>{"10", "35", "15", "0.50", "5"}));
}

TEST(PovEval, LoopsAndArrays) {
    auto r = run("#declare Sum = 0; #declare I = 1;\n"
                 "#while (I <= 10) #declare Sum = Sum + I; #declare I = I + 1; #end\n"
                 "#warning str(Sum, 0, 0)\n"
                 "#declare P = 1; #for (K, 1, 5) #declare P = P * K; #end\n"
                 "#warning str(P, 0, 0)\n"
                 "#declare Down = \"\"; #for (K, 3, 1, -1) #declare Down = concat(Down, str(K, 0, 0)); #end\n"
                 "#warning Down\n"
                 "#declare Arr = array[2][3] { {1, 2, 3}, {4, 5, 6} }\n"
                 "#declare Arr[1][2] = 60;\n"
                 "#warning str(Arr[0][1] + Arr[1][2] + dimension_size(Arr, 2) + dimensions(Arr), 0, 0)\n"
                 "#declare E = array[3]\n#declare E[0] = 1;\n"
                 "#ifdef (E[0]) #warning \"e0\" #end #ifndef (E[2]) #warning \"no e2\" #end\n"
                 "#declare N = 0; #while (1) #declare N = N + 1; #if (N = 4) #break #end #end\n"
                 "#warning str(N, 0, 0)\n");
    ASSERT_FALSE(r->diags.hasErrors()) << r->diags.formatAll();
    EXPECT_EQ(r->messages, (std::vector<std::string>{"55", "120", "321", "67", "e0", "no e2", "4"}));
}

TEST(PovEval, MacrosScopesAndReferenceParameters) {
    auto r = run("#macro Square(V) (V * V) #end\n"
                 "#warning str(Square(3) + 1, 0, 0)\n"
                 "#macro Bump(Counter) #declare Counter = Counter + 1; #end\n"
                 "#declare C = 5; Bump(C) Bump(C)\n"
                 "#warning str(C, 0, 0)\n"
                 "#declare L = 1;\n"
                 "#macro Shadow() #local L = 99; #warning str(L, 0, 0) #end\n"
                 "Shadow()\n#warning str(L, 0, 0)\n"
                 "#macro Fact(N) #if (N <= 1) 1 #else N * Fact(N - 1) #end #end\n"
                 "#warning str(Fact(5), 0, 0)\n");
    ASSERT_FALSE(r->diags.hasErrors()) << r->diags.formatAll();
    EXPECT_EQ(r->messages, (std::vector<std::string>{"10", "7", "99", "1", "120"}));
}

// A declaration without ';' ends before a macro call on the next line: the
// call must see the new identifier (portfolio scenes: `#declare Comment=""`).
TEST(PovEval, DeclarationWithoutSemicolonEndsBeforeAMacroCall) {
    auto r = run("#macro M(A, B) #warning concat(\"[\", A, B, \"]\") #end\n"
                 "#declare Comment=\"\"\n"
                 "M(\"x\", Comment)\n"
                 "#declare C2=\"y\"\n"
                 "M(\"x\", C2)\n"
                 "#declare F = 2\n"
                 "M(str(F, 0, 0), \"!\")\n"
                 "#declare V = <1, 2, 3>\n"
                 "M(str(V.y, 0, 0), \"\")\n");
    ASSERT_FALSE(r->diags.hasErrors()) << r->diags.formatAll();
    EXPECT_EQ(r->messages, (std::vector<std::string>{"[x]", "[xy]", "[2!]", "[2]"}));
}

TEST(PovEval, RandIsDeterministicAndInRange) {
    auto r = run("#declare S = seed(42); #declare T = seed(42);\n"
                 "#declare Ok = 1; #for (I, 1, 200) #declare A = rand(S); #declare B = rand(T);\n"
                 "#if (A != B | A < 0 | A > 1) #declare Ok = 0; #end #end\n"
                 "#warning str(Ok, 0, 0)\n"
                 "#declare U = seed(7); #warning str(rand(U) != rand(U), 0, 0)\n");
    ASSERT_FALSE(r->diags.hasErrors()) << r->diags.formatAll();
    EXPECT_EQ(r->messages, (std::vector<std::string>{"1", "1"}));
}

TEST(PovEval, ImageSizeAndClockComeFromOptions) {
    PovOptions o;
    o.imageWidth = 640;
    o.imageHeight = 480;
    o.frame.clock = 0.25;
    auto r = run("#warning str(image_width / image_height + clock, 0, 4)\n", o);
    ASSERT_EQ(r->messages.size(), 1u);
    EXPECT_EQ(r->messages[0], "1.5833");
}

TEST(PovEval, IncludeSearchPathAndLocalScope) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/lib/helper.inc", "#local Hidden = 1;\n#declare Shown = 2;\n");
    PovOptions o;
    o.includePaths = {dir + "/lib"};
    auto r = run("#include \"helper.inc\"\n#ifdef (Hidden) #warning \"leak\" #end\n#warning str(Shown, 0, 0)\n", o);
    ASSERT_FALSE(r->diags.hasErrors()) << r->diags.formatAll();
    EXPECT_EQ(r->messages, (std::vector<std::string>{"2"}));
}

TEST(PovEval, StandardIncludesLoad) {
    auto r = run("#include \"colors.inc\"\n#include \"textures.inc\"\n#include \"shapes.inc\"\n"
                 "#warning str(Orange.red + Orange.green, 0, 2)\n");
    ASSERT_FALSE(r->diags.hasErrors()) << r->diags.formatAll();
    ASSERT_EQ(r->messages.size(), 1u);
    EXPECT_EQ(r->messages[0], "1.50"); // colors.inc: Orange = rgb <1, 0.5, 0>
}

struct ErrorCase {
    const char* name;
    const char* source;
    const char* message; // a part of the first error
    int line, column;
};

std::ostream& operator<<(std::ostream& os, const ErrorCase& c) { return os << c.name; }

class PovErrors : public testing::TestWithParam<ErrorCase> {};

TEST_P(PovErrors, MessageAndLocation) {
    const ErrorCase& c = GetParam();
    auto r = run(c.source);
    EXPECT_FALSE(r->scene);
    ASSERT_GE(r->diags.errorCount(), 1);
    const Diagnostic* first = nullptr;
    for (const Diagnostic& d : r->diags.all())
        if (d.severity == Severity::Error && !first) first = &d;
    ASSERT_TRUE(first);
    EXPECT_NE(first->message.find(c.message), std::string::npos) << first->message;
    EXPECT_EQ(first->loc.line, c.line) << first->message;
    EXPECT_EQ(first->loc.column, c.column) << first->message;
}

INSTANTIATE_TEST_SUITE_P(
    All, PovErrors,
    testing::Values(
        ErrorCase{"Undeclared", "#declare A = 1;\n#declare B = A + Bogus;", "unknown identifier 'Bogus'", 2, 18},
        ErrorCase{"DivisionByZero", "#declare A = 1 / 0;", "division by zero", 1, 16},
        ErrorCase{"MissingEnd", "#if (1)\n#declare A = 1;\n", "no matching #end", 1, 1},
        ErrorCase{"StrayEnd", "\n  #end", "#end without", 2, 3},
        ErrorCase{"ErrorDirective", "#error \"stop here\"", "#error: stop here", 1, 1},
        ErrorCase{"ArrayIndex", "#declare A = array[2];\n#declare B = A[5];", "array index 5 is out of range (0 to 1)", 2, 16},
        ErrorCase{"UninitialisedElement", "#declare A = array[2];\n#declare B = A[1];", "used before", 2, 14},
        ErrorCase{"MacroArity", "#macro M(A, B) A #end\n#declare X = M(1);", "takes 2 parameters, given 1", 2, 14},
        ErrorCase{"RunawayRecursion", "#macro R() R() #end\nR()", "(runaway recursion?)", 1, 12},
        ErrorCase{"InfiniteLoop", "#while (1)\n#end", "over the limit of", 1, 1},
        ErrorCase{"BadSwizzle", "#declare A = <1, 2>.z;", "'.z' of a 2-component vector", 1, 21},
        ErrorCase{"WrongType", "#declare A = \"s\" + 1;", "strings are joined with concat()", 1, 18},
        ErrorCase{"MissingInclude", "#include \"nothere.inc\"", "cannot find include file", 1, 10},
        ErrorCase{"UnknownKeyword", "sphre { 0, 1 }", "did you mean 'sphere'", 1, 1},
        ErrorCase{"BadObjectItem", "sphere { 0, 1 pigmnt { rgb 1 } }", "unknown keyword 'pigmnt'; did you mean 'pigment'?", 1, 15},
        ErrorCase{"UnterminatedString", "#declare S = \"abc\n;", "unterminated string", 1, 14}),
    [](const testing::TestParamInfo<ErrorCase>& info) { return std::string(info.param.name); });

TEST(PovEval, ErrorInsideIncludeShowsTheChain) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/inner.inc", "#declare A = 1;\n#declare B = oops;\n");
    test::writeFile(dir + "/outer.inc", "#include \"inner.inc\"\n");
    const std::string scene = test::writeFile(dir + "/main.pov", "\n#include \"outer.inc\"\n");
    Diagnostics diags;
    EXPECT_FALSE(loadPovSceneFile(scene, diags));
    ASSERT_EQ(diags.errorCount(), 1);
    const Diagnostic& d = diags.all()[0];
    EXPECT_EQ(d.loc.line, 2);
    EXPECT_EQ(d.loc.column, 14);
    ASSERT_EQ(d.includedFrom.size(), 2u);
    const std::string text = diags.format(d);
    EXPECT_NE(text.find("In file included from " + scene + ":2:"), std::string::npos) << text;
    EXPECT_NE(text.find("outer.inc:1:"), std::string::npos) << text;
    EXPECT_NE(text.find("inner.inc:2:14: error: unknown identifier 'oops'"), std::string::npos) << text;
}

} // namespace
} // namespace drt
