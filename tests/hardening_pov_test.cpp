// Bad and hostile POV-Ray scenes: every number that becomes a count or an
// index is range-checked before it is converted, and loops, recursion, objects
// and strings stop at a documented limit with a located error. Through the drt
// executable (`drt check`), for the exit status a user sees.
#include "test_support.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace drt {
namespace {

namespace fs = std::filesystem;
using test::runDrt;

#define EXPECT_CONTAINS(haystack, needle) EXPECT_NE((haystack).find(needle), std::string::npos) << (haystack)

struct Outcome {
    int exitCode;
    std::string err;
};

Outcome checkPov(const std::string& text, const std::string& extra = "") {
    const std::string dir = test::tempDir();
    const std::string path = test::writeFile(dir + "/s.pov", text);
    const test::CommandResult r = runDrt("check '" + path + "' " + extra);
    fs::remove_all(dir);
    return {r.exitCode, r.err};
}

// One line per case: the scene, then the located message expected (s.pov:line:col: error: ...).
struct Case {
    const char* scene;
    const char* message;
};

TEST(HardeningPov, FloatsThatBecomeCountsOrIndicesAreRangeChecked) {
    const Case cases[] = {
        {"camera { cylinder 1e10 }", "s.pov:1:19: error: invalid cylinder camera type: valid are types 1 to 4"},
        {"#declare A = array[3];\n#declare B = A[1e10];", "s.pov:2:16: error: array index 10000000000 is out of range (0 to 2)"},
        {"#declare A = array[3];\n#ifdef (A[1e10]) #end", "s.pov:2:11: error: array index 10000000000 is out of range (0 to 2)"},
        {"#declare A = array[3];\n#declare A[-1] = 1;", "s.pov:2:12: error: array index -1 is out of range (0 to 2)"},
        {"#declare A = array[1e10];", "s.pov:1:20: error: array size 10000000000 is out of range (1 to 10000000)"},
        {"sphere { 0, 1 hollow interior { media { intervals 1e10 } } }",
         "s.pov:1:51: error: media intervals 10000000000 is out of range (1 to 4096)"},
        {"mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0, 1, 1e10> } }",
         "s.pov:1:75: error: vertex index 10000000000 is out of range (0 to 2)"},
        {"mesh2 { vertex_vectors { 1e10, <0,0,0> } }", "s.pov:1:26: error: mesh2 vector count 10000000000 is out of range"},
        {"polygon { 1e10, <0, 0>, <1, 0>, <0, 1> }", "s.pov:1:11: error: polygon point count 10000000000 is out of range"},
        {"light_source { 0, 1 area_light x, z, 1e10, 2 }",
         "s.pov:1:38: error: area_light size 10000000000 is out of range (1 to 65536)"},
        {"light_source { 0, 1 area_light x, z, 300, 300 }",
         "s.pov:1:38: error: the area_light's sample count 300 x 300 = 90000 is over the limit of 65536 (limit "
         "area_light_samples = 65536; raise it with --limit area_light_samples=N)"},
        {"sphere { 0, 1 pigment { bozo turbulence 1 octaves 1e10 } }",
         "s.pov:1:51: error: octaves 10000000000 is out of range"},
        {"#declare S = str(1, 1e10, 0);", "s.pov:1:21: error: str() width 10000000000 is out of range"},
        {"#declare C = chr(1e10);", "s.pov:1:18: error: chr() code 10000000000 is out of range (0 to 255)"},
        {"#declare B = bitwise_and(1e30, 1);", "s.pov:1:26: error: bitwise operand 1e+30 is out of range"},
        {"#declare R = seed(1e30);", "s.pov:1:19: error: seed 1e+30 is out of range"},
    };
    for (const Case& c : cases) {
        const Outcome o = checkPov(c.scene);
        EXPECT_EQ(o.exitCode, 1) << c.scene;
        EXPECT_CONTAINS(o.err, c.message);
    }
}

TEST(HardeningPov, MaxTraceLevelAboveTheLimitIsUsedAtTheLimitWithAWarning) {
    const Outcome o = checkPov("global_settings { max_trace_level 1e10 }\nsphere { 0, 1 }");
    EXPECT_EQ(o.exitCode, 0) << o.err;
    EXPECT_CONTAINS(o.err, "s.pov:1:35: warning: max_trace_level 10000000000 is above drt's 256; 256 is used");
    const Outcome mirrors = checkPov("global_settings { max_trace_level 1000000 }\nsphere { 0, 1 }");
    EXPECT_EQ(mirrors.exitCode, 0) << mirrors.err;
    EXPECT_CONTAINS(mirrors.err, "warning: max_trace_level 1000000 is above drt's 256");
    EXPECT_EQ(checkPov("global_settings { max_trace_level 1e10 }", "--strict").exitCode, 1);
}

TEST(HardeningPov, AWhileLoopWithoutProgressStopsAtTheIterationLimit) {
    const Outcome o = checkPov("#declare I = 0;\n#while (I < 1)\n#end\n", "--limit loop_iterations=100000");
    EXPECT_EQ(o.exitCode, 1);
    EXPECT_CONTAINS(o.err, "s.pov:2:1: error: this #while loop's pass 100001 is over the limit of 100000 (limit "
                           "loop_iterations = 100000; raise it with --limit loop_iterations=N)");
}

// Directives met while another directive reads its tokens run inside it; the fuzzer's
// `#declare A = #if ( #declare A = #if ( ...` recursed until the stack overflowed (a
// segfault). The nesting limit now stops it with a located error.
TEST(HardeningPov, DirectivesNestedInDirectivesStopAtTheNestingLimit) {
    std::string text;
    for (int i = 0; i < 5000; ++i) text += "#declare A = #if (";
    const Outcome o = checkPov(text);
    EXPECT_EQ(o.exitCode, 1) << o.err;
    EXPECT_CONTAINS(o.err, "s.pov:1:");
    EXPECT_CONTAINS(o.err, "error: nesting depth 201 is over the limit of 200 (limit nesting_depth = 200");
}

TEST(HardeningPov, InfiniteMacroRecursionStopsAtTheCallDepth) {
    const Outcome o = checkPov("#macro M(N)\n  M(N + 1)\n#end\nM(0)\n");
    EXPECT_EQ(o.exitCode, 1);
    EXPECT_CONTAINS(o.err, "s.pov:2:3: error: macro calls and includes nested 401 is over the limit of 400 (limit "
                           "call_depth = 400; raise it with --limit call_depth=N) (runaway recursion?)");
}

TEST(HardeningPov, ALoopAddingSpheresForeverStopsAtTheObjectLimit) {
    const Outcome o = checkPov("#declare I = 0;\n#while (1)\n  sphere { <I, 0, 0>, 0.5 }\n  #declare I = I + 1;\n#end\n",
                               "--limit objects=20000");
    EXPECT_EQ(o.exitCode, 1);
    EXPECT_CONTAINS(o.err, "s.pov:3:3: error: the scene's objects and patterns number 20001 is over the limit of "
                           "20000 (limit objects = 20000; raise it with --limit objects=N)");
}

// A fuzzer's find: a blob whose #while adds components forever ran to the
// loop limit (10M passes, 145 s and 5.4 GB) because components were not
// counted as the objects they cost. Each is now one node of the object limit.
TEST(HardeningPov, ALoopAddingBlobComponentsForeverStopsAtTheObjectLimit) {
    const Outcome o = checkPov("blob { threshold 0.5\n#while (1)\n  sphere { 0, 1, 1 }\n  component 1, 1, <1, 0, 0>\n"
                               "#end\n}\n",
                               "--limit objects=20000");
    EXPECT_EQ(o.exitCode, 1);
    // 1 for the blob, then two components a pass: the 20001st node is a `component`.
    EXPECT_CONTAINS(o.err, "s.pov:4:3: error: the scene's objects and patterns number 20001 is over the limit of "
                           "20000 (limit objects = 20000; raise it with --limit objects=N)");
    // Copies of a declared blob count its components too.
    std::string copies = "#declare B = blob { threshold 0.5\n#for (I, 1, 1000)\n  sphere { <I, 0, 0>, 1, 1 }\n#end\n}\n";
    copies += "#for (I, 1, 30)\n  object { B }\n#end\n";
    const Outcome c = checkPov(copies, "--limit objects=20000");
    EXPECT_EQ(c.exitCode, 1);
    EXPECT_CONTAINS(c.err, "s.pov:7:12: error: the scene's objects and patterns number");
}

TEST(HardeningPov, ConcatDoublingStopsAtTheStringLimit) {
    const Outcome o = checkPov("#declare S = \"ab\";\n#while (1)\n  #declare S = concat(S, S);\n#end\n");
    EXPECT_EQ(o.exitCode, 1);
    EXPECT_CONTAINS(o.err, "s.pov:3:16: error: the string's length 2097152 is over the limit of 1048576");
}

TEST(HardeningPov, ObjectDoublingStopsAtALimit) {
    std::string text = "#declare A0 = sphere { 0, 1 }\n";
    for (int i = 1; i <= 40; ++i)
        text += "#declare A" + std::to_string(i) + " = union { object { A" + std::to_string(i - 1) + " } object { A" +
                std::to_string(i - 1) + " } }\n";
    text += "object { A40 }\n";
    const Outcome o = checkPov(text, "--limit memory_mb=400");
    EXPECT_EQ(o.exitCode, 1);
    EXPECT_CONTAINS(o.err, "s.pov:");
    EXPECT_CONTAINS(o.err, "(limit memory_mb = 400; raise it with --limit memory_mb=N)");
}

TEST(HardeningPov, FileDirectivesNeverWriteAFile) {
    const std::string dir = test::tempDir();
    const std::string scene = test::writeFile(
        dir + "/w.pov", "#fopen Out \"" + dir + "/written.txt\" write\n#write (Out, \"data\")\n#fclose Out\n"
                        "#fopen Log \"appended.txt\" append\n#write (Log, \"x\")\n#fclose Log\nsphere { 0, 1 }\n");
    const test::CommandResult r = runDrt("check '" + scene + "'");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_CONTAINS(r.err, "w.pov:1:1: note:");
    EXPECT_FALSE(fs::exists(dir + "/written.txt"));
    EXPECT_FALSE(fs::exists(dir + "/appended.txt"));
    EXPECT_FALSE(fs::exists("appended.txt"));
    fs::remove_all(dir);
}

TEST(HardeningPov, IncludesOfDevicesAndPrivateFilesAreBounded) {
    const Outcome zero = checkPov("#include \"/dev/zero\"\n");
    EXPECT_EQ(zero.exitCode, 1);
    EXPECT_CONTAINS(zero.err, "s.pov:1:10: error: cannot find include file \"/dev/zero\"");
    const Outcome passwd = checkPov("#include \"/etc/passwd\"\n");
    EXPECT_EQ(passwd.exitCode, 1);
    EXPECT_CONTAINS(passwd.err, "/etc/passwd:1:");
    EXPECT_EQ(passwd.err.find("/bin/"), std::string::npos) << passwd.err;
}

TEST(HardeningPov, AByteOrderMarkIsSkipped) {
    const Outcome o = checkPov("\xEF\xBB\xBFsphere { 0, 1 }\n");
    EXPECT_EQ(o.exitCode, 0) << o.err;
}

} // namespace
} // namespace drt
