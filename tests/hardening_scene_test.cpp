// Bad and hostile scenes, as a careful user and a fuzzer write them: each ends
// in the expected exit status and a located error (file:line:col, with the
// limit's name where a limit stopped it), never a crash, a hang or all of the
// machine's memory. Run through the drt executable, as a user would.
#include "test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <sys/stat.h>

namespace drt {
namespace {

namespace fs = std::filesystem;
using test::runDrt;

struct Outcome {
    int exitCode;
    std::string err;
    std::string out;
};

// Writes `text` as `name` in a fresh folder and runs `drt <command> <file> <extra>`.
Outcome runOn(const std::string& name, const std::string& text, const std::string& command = "check",
              const std::string& extra = "") {
    const std::string dir = test::tempDir();
    const std::string path = test::writeFile(dir + "/" + name, text);
    const test::CommandResult r = runDrt(command + " '" + path + "' " + extra);
    fs::remove_all(dir);
    return {r.exitCode, r.err, r.out};
}

#define EXPECT_CONTAINS(haystack, needle) EXPECT_NE((haystack).find(needle), std::string::npos) << (haystack)

const char* const kCamera = "camera { location <0, 0, -4> look_at <0, 0, 0> }\n"
                            "light_source { <2, 4, -3> color 1 }\n";

// ------------------------------------------------------------ patterns at extreme scales

TEST(HardeningScene, PatternsScaledBy1eMinus20RenderWithoutUndefinedBehaviour) {
    for (const char* pattern : {"checker", "hexagon", "bozo", "granite", "crackle", "brick"}) {
        const std::string dir = test::tempDir();
        const std::string scene = test::writeFile(
            dir + "/p.drt", std::string(kCamera) + "sphere { <0, 0, 0>, 1 pigment { " + pattern +
                                " scale 1e-20 } }\nrender { width 8 height 6 }\n");
        const test::CommandResult r = runDrt("render '" + scene + "' -o '" + dir + "/p.png' --quiet");
        EXPECT_EQ(r.exitCode, 0) << pattern << "\n" << r.err;
        EXPECT_TRUE(fs::exists(dir + "/p.png")) << pattern;
        fs::remove_all(dir);
    }
}

// ------------------------------------------------------------ counts from floats (.drt)

TEST(HardeningScene, AreaLightGridPastTheLimitIsALocatedError) {
    const Outcome o = runOn("a.drt", "light_source { <0, 5, 0> color 1\n  area_light <1, 0, 0>, <0, 0, 1>, 65536, 65536 }\n");
    EXPECT_EQ(o.exitCode, 1);
    EXPECT_CONTAINS(o.err, "a.drt:2:36: error: the area_light's sample count 65536 x 65536 = 4294967296 is over "
                           "the limit of 65536 (limit area_light_samples = 65536; raise it with --limit "
                           "area_light_samples=N)");
    // Within a raised limit the same scene checks.
    const Outcome raised = runOn("a.drt", "light_source { <0, 5, 0> color 1 area_light x, z, 300, 300 }\n", "check",
                                 "--limit area_light_samples=100000");
    EXPECT_EQ(raised.exitCode, 0) << raised.err;
}

TEST(HardeningScene, MaxTraceLevelPastTheLimitIsALocatedError) {
    const Outcome o = runOn("m.drt", std::string(kCamera) + "global_settings { max_trace_level 1000000 }\n");
    EXPECT_EQ(o.exitCode, 1);
    EXPECT_CONTAINS(o.err, "m.drt:3:35: error: 'max_trace_level' 1000000 is over the limit of 256 (limit "
                           "trace_level = 256");
}

TEST(HardeningScene, HugeAndUndefinedNumbersInExpressionsAreLocatedErrors) {
    const Outcome huge = runOn("n.drt", "sphere { <0, 0, 0>, 1e400 }\n");
    EXPECT_EQ(huge.exitCode, 1);
    EXPECT_CONTAINS(huge.err, "n.drt:1:");
    EXPECT_CONTAINS(huge.err, ": error:");
    const Outcome nan = runOn("n.drt", "#declare R = 0 / 0;\nsphere { <0, 0, 0>, R }\n");
    EXPECT_EQ(nan.exitCode, 1);
    EXPECT_CONTAINS(nan.err, "n.drt:1:");
    EXPECT_CONTAINS(nan.err, "error: division by zero");
}

// ------------------------------------------------------------ unbounded work and output

TEST(HardeningScene, DeclareDoublingStopsAtTheObjectLimit) {
    std::string text = "#declare A0 = sphere { <0, 0, 0>, 1 }\n";
    for (int i = 1; i <= 40; ++i)
        text += "#declare A" + std::to_string(i) + " = union { object { A" + std::to_string(i - 1) + " } object { A" +
                std::to_string(i - 1) + " } }\n";
    text += "object { A40 }\n";
    // The default limit (4M) stops it the same way; a lower one keeps the test small.
    const Outcome o = runOn("laughs.drt", text, "check", "--limit objects=100000");
    EXPECT_EQ(o.exitCode, 1);
    EXPECT_CONTAINS(o.err, "error: the scene's objects and patterns number");
    EXPECT_CONTAINS(o.err, "is over the limit of 100000 (limit objects = 100000; raise it with --limit objects=N)");
    EXPECT_CONTAINS(o.err, "laughs.drt:");
}

// A loop that adds an object per pass and never ends (the fuzzer's first
// find): in .drt, which goes on after an error to report more, a resource limit
// still ends the read at once. Before, each later pass reported the limit again
// until the error limit (50 printed, 100 counted), after a minute of work.
TEST(HardeningScene, AWhileAddingObjectsForeverEndsAtTheObjectLimitWithOneError) {
    const std::string text = std::string(kCamera) +
                             "#declare L = 0;\n#while (L < 6)\n  sphere { <0, L, 0>, 1 }\n  #declare L = L + 0;\n#end\n"
                             "sphere { <0, 0, 0>, -1 }\n"; // a later error that the read no longer reaches
    const Outcome o = runOn("forever.drt", text, "check", "--limit objects=20000");
    EXPECT_EQ(o.exitCode, 1);
    EXPECT_CONTAINS(o.err, "forever.drt:5:3: error: the scene's objects and patterns number 20001 is over the limit of "
                           "20000 (limit objects = 20000; raise it with --limit objects=N)");
    EXPECT_CONTAINS(o.err, "1 error");
    EXPECT_EQ(o.err.find("more errors"), std::string::npos) << o.err;
    EXPECT_EQ(o.err.find("radius"), std::string::npos) << o.err;
    // An ordinary error does not end the .drt read: both are reported.
    const Outcome two = runOn("two.drt", std::string(kCamera) + "sphere { <0, 0, 0>, -1 }\nsphere { <0, 0, 0>, -2 }\n");
    EXPECT_EQ(two.exitCode, 1);
    EXPECT_CONTAINS(two.err, "2 errors");
}

// loop_iterations bounds one loop; passes_and_calls bounds the passes of all
// loops and the macro calls together, over the whole read, in both dialects.
// Each loop here stays under loop_iterations: nested loops multiply their
// passes, a loop that sets its counter back (a fuzzer's find: a mutated
// sort.pov ran for hours) never ends, and a macro calling itself twice makes
// 2^(N+1) - 1 calls at a depth of only N. The limit ends the read.
TEST(HardeningScene, LoopsAndMacroCallsStopAtTheLimitOfPassesAndCalls) {
    const std::string tree = "#macro Tree(N)\n  #if (N > 0)\n    Tree(N - 1)\n    Tree(N - 1)\n  #end\n#end\n";
    struct Case {
        std::string file, scene, limits;
        int limit;
        std::string at, quoted, note; // the error's place and quoted line, a note that follows it
    };
    const Case cases[] = {
        // 101 passes an outer pass: the 5001st is the inner loop's 52nd of the 50th.
        {"nested.pov", "#declare I = 0;\n#while (I < 100)\n  #declare J = 0;\n  #while (J < 100)\n"
                       "    #declare J = J + 1;\n  #end\n  #declare I = I + 1;\n#end\n",
         "", 5000, "4:3", "    #while (J < 100)\n    ^\n", "nested.pov:2:1: note: in pass 50 of this #while loop\n"},
        {"nested.drt", "#declare I = 0;\n#while (I < 100)\n  #for (J, 1, 100)\n    #declare K = J * 2;\n  #end\n"
                       "  #declare I = I + 1;\n#end\nsphere { <0, 0, 0>, -1 }\n",
         "", 5000, "3:3", "    #for (J, 1, 100)\n    ^\n", "nested.drt:2:1: note: in pass 50 of this #while loop\n"},
        // 21 passes an outer pass: the 10001st is the inner loop's 5th of the 477th.
        {"reset.pov", "#declare I = 0;\n#while (I < 20)\n  #declare J = 0;\n  #while (J < 20)\n"
                      "    #declare J = J + 1;\n  #end\n  #declare I = 0;\n#end\n",
         "--limit loop_iterations=1000", 10000, "4:3", "    #while (J < 20)\n    ^\n",
         "reset.pov:2:1: note: in pass 477 of this #while loop\n  #while (I < 20)\n  ^\n"},
        // 32767 calls in all, depth first: the 1001st is a Tree(1) of a first branch.
        {"tree.pov", tree + "Tree(14)\n", "", 1000, "3:5", "      Tree(N - 1)\n      ^\n",
         "tree.pov:7:1: note: in macro 'Tree' called here"},
        {"tree.drt", tree + "Tree(14)\n", "", 1000, "3:5", "      Tree(N - 1)\n      ^\n",
         "tree.drt:7:1: note: in macro 'Tree' called here"},
    };
    for (const Case& c : cases) {
        const std::string limit = std::to_string(c.limit);
        const Outcome o = runOn(c.file, c.scene, "check", c.limits + " --limit passes_and_calls=" + limit);
        EXPECT_EQ(o.exitCode, 1) << c.file;
        EXPECT_CONTAINS(o.err, c.file + ":" + c.at + ": error: the scene's loop passes and macro calls number " +
                                   std::to_string(c.limit + 1) + " is over the limit of " + limit +
                                   " (limit passes_and_calls = " + limit +
                                   "; raise it with --limit passes_and_calls=N)\n" + c.quoted);
        EXPECT_CONTAINS(o.err, c.note);
        EXPECT_CONTAINS(o.err, "1 error"); // in .drt too, where the read otherwise goes on after an error
    }
    // Under the limit: 70 x 70 + 70 passes, 511 calls.
    const std::string nestedFors = "#for (I, 1, 70)\n  #for (J, 1, 70)\n  #end\n#end\n";
    for (const std::string& scene : {nestedFors, tree + "Tree(8)\n"})
        EXPECT_EQ(runOn("under.pov", scene, "check", "--limit passes_and_calls=5000").exitCode, 0) << scene;
}

// A mesh given a triangle a pass by a loop that never ends (a misspelt
// counter) stops at the objects limit, each such triangle counted as an
// object, long before the passes_and_calls limit: its passes are heavy.
TEST(HardeningScene, MeshTrianglesMadeInALoopCountAsObjects) {
    const std::string scene = "#declare I = 0;\n"
                              "mesh {\n"
                              "  #while (I < 100)\n"
                              "    triangle { <I, 0, 0>, <I, 1, 0>, <I + 1, 0, 0> }\n"
                              "    #declare I = I + 1;\n"
                              "  #end\n"
                              "}\n";
    // The mesh is one object, so its 100th triangle is the 101st.
    for (const std::string file : {"loop.pov", "loop.drt"}) {
        const Outcome o = runOn(file, scene, "check", "--limit objects=100");
        EXPECT_EQ(o.exitCode, 1) << file;
        EXPECT_CONTAINS(o.err, file + ":4:5: error: the scene's objects and patterns number 101 is over the limit of "
                                      "100 (limit objects = 100; raise it with --limit objects=N)\n"
                                      "      triangle { <I, 0, 0>, <I, 1, 0>, <I + 1, 0, 0> }\n"
                                      "      ^\n");
        // The notes name the mesh and the loop (the paths before them are the scene's folder).
        EXPECT_CONTAINS(o.err, file + ":2:1: note: the triangles this mesh is given while a loop runs count as "
                                      "objects\n  mesh {\n  ^\n");
        EXPECT_CONTAINS(o.err, file + ":3:3: note: in pass 100 of this #while loop\n    #while (I < 100)\n    ^\n");
        EXPECT_CONTAINS(o.err, "1 error");
        EXPECT_EQ(runOn(file, scene, "check", "--limit objects=101").exitCode, 0) << file;
    }
    // Triangles written out are not counted: a mesh of 100 reads under a limit of 50 objects.
    std::string written = "mesh {\n";
    for (int i = 0; i < 100; ++i)
        written += "  triangle { <" + std::to_string(i) + ", 0, 0>, <" + std::to_string(i) + ", 1, 0>, <" +
                   std::to_string(i + 1) + ", 0, 0> }\n";
    written += "}\n";
    EXPECT_EQ(runOn("written.pov", written, "check", "--limit objects=50").exitCode, 0);
}

TEST(HardeningScene, PigmentDoublingStopsAtTheMemoryLimit) {
    std::string text = "#declare P0 = pigment { color rgb <1, 0, 0> }\n";
    for (int i = 1; i <= 40; ++i)
        text += "#declare P" + std::to_string(i) + " = pigment { checker pigment { P" + std::to_string(i - 1) +
                " }, pigment { P" + std::to_string(i - 1) + " } }\n";
    const Outcome o = runOn("pigments.drt", text, "check", "--limit memory_mb=300");
    EXPECT_EQ(o.exitCode, 1);
    EXPECT_CONTAINS(o.err, "pigments.drt:");
    EXPECT_CONTAINS(o.err, "over the limit of 300 MB (limit memory_mb = 300; raise it with --limit memory_mb=N)");
}

TEST(HardeningScene, BinaryGarbagePrintsABoundedNumberOfErrors) {
    std::string garbage;
    uint32_t state = 12345;
    for (int i = 0; i < 100'000; ++i) {
        state = state * 1664525u + 1013904223u;
        const char c = char(state >> 24);
        garbage += c == '\0' ? '\x01' : c; // no NUL: the binary-file check would catch it first
    }
    const Outcome o = runOn("garbage.drt", garbage);
    EXPECT_EQ(o.exitCode, 1);
    EXPECT_LT(o.err.size(), 100'000u);
    EXPECT_CONTAINS(o.err, "garbage.drt:1:");
    EXPECT_CONTAINS(o.err, "more errors not shown (limit errors = 50; raise it with --limit errors=N)");
}

TEST(HardeningScene, AnErrorOnATwoMegabyteLineQuotesAShortWindow) {
    const Outcome o = runOn("long.drt", std::string(2'000'000, ' ') + "oops\n");
    EXPECT_EQ(o.exitCode, 1);
    EXPECT_CONTAINS(o.err, "long.drt:1:2000001: error:");
    EXPECT_LT(o.err.size(), 2000u);
}

// ------------------------------------------------------------ includes

TEST(HardeningScene, IncludesReadOnlyRegularFiles) {
    const Outcome zero = runOn("z.drt", "#include \"/dev/zero\"\n");
    EXPECT_EQ(zero.exitCode, 1);
    EXPECT_CONTAINS(zero.err, "z.drt:1:10: error: cannot include '/dev/zero': '/dev/zero' is not a regular file (a device)");
    const Outcome folder = runOn("d.drt", "#include \"/tmp\"\n");
    EXPECT_EQ(folder.exitCode, 1);
    EXPECT_CONTAINS(folder.err, "d.drt:1:10: error: cannot include '/tmp': '/tmp' is not a regular file (a folder)");

    const std::string dir = test::tempDir();
    ASSERT_EQ(::mkfifo((dir + "/fifo.inc").c_str(), 0600), 0);
    const std::string scene = test::writeFile(dir + "/f.drt", "#include \"fifo.inc\"\n");
    const test::CommandResult fifo = runDrt("check '" + scene + "'");
    EXPECT_EQ(fifo.exitCode, 1);
    EXPECT_CONTAINS(fifo.err, "f.drt:1:10: error: cannot include 'fifo.inc':");
    EXPECT_CONTAINS(fifo.err, "is not a regular file (a pipe)");
    fs::remove_all(dir);
}

TEST(HardeningScene, AnIncludedFileOverTheSizeLimitIsRefused) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/big.inc", std::string(5000, ' '));
    const std::string scene = test::writeFile(dir + "/s.drt", "\n  #include \"big.inc\"\n");
    const test::CommandResult r = runDrt("check '" + scene + "' --limit include_bytes=4096");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_CONTAINS(r.err, "s.drt:2:12: error: cannot include 'big.inc':");
    EXPECT_CONTAINS(r.err, "is 5000 bytes, over the limit of 4096 (limit include_bytes = 4096; raise it with --limit "
                           "include_bytes=N)");
    fs::remove_all(dir);
}

TEST(HardeningScene, AnIncludedFileThatIsNoSceneIsNotQuoted) {
    const Outcome o = runOn("p.drt", "#include \"/etc/passwd\"\n");
    EXPECT_EQ(o.exitCode, 1);
    EXPECT_CONTAINS(o.err, "/etc/passwd:1:1: error:");
    EXPECT_CONTAINS(o.err, "In file included from");
    EXPECT_EQ(o.err.find("/bin/"), std::string::npos) << o.err; // no line of the file is printed
}

TEST(HardeningScene, IncludeDepthStopsAtTheLimit) {
    const std::string dir = test::tempDir();
    for (int i = 0; i < 10; ++i)
        test::writeFile(dir + "/i" + std::to_string(i) + ".inc", "#include \"i" + std::to_string(i + 1) + ".inc\"\n");
    test::writeFile(dir + "/i10.inc", "sphere { <0, 0, 0>, 1 }\n");
    const std::string scene = test::writeFile(dir + "/deep.drt", "#include \"i0.inc\"\n");
    EXPECT_EQ(runDrt("check '" + scene + "'").exitCode, 0);
    const test::CommandResult r = runDrt("check '" + scene + "' --limit include_depth=5");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_CONTAINS(r.err, "i4.inc:1:10: error: include depth 6 is over the limit of 5 (limit include_depth = 5;");
    fs::remove_all(dir);
}

// ------------------------------------------------------------ small inputs a user makes

TEST(HardeningScene, AByteOrderMarkIsSkipped) {
    const Outcome o = runOn("bom.drt", "\xEF\xBB\xBFsphere { <0, 0, 0>, 1 }\n");
    EXPECT_EQ(o.exitCode, 0) << o.err;
    const Outcome columns = runOn("bom.drt", "\xEF\xBB\xBFsphere { <0, 0, 0>, -1 }\n");
    EXPECT_EQ(columns.exitCode, 1);
    EXPECT_CONTAINS(columns.err, "bom.drt:1:21: error: sphere radius must be positive"); // columns count from after the mark
}

TEST(HardeningScene, CrlfLinesReadAsLines) {
    const Outcome ok = runOn("crlf.drt", "sphere {\r\n  <0, 0, 0>, 1\r\n}\r\n");
    EXPECT_EQ(ok.exitCode, 0) << ok.err;
    const Outcome bad = runOn("crlf.drt", "sphere {\r\n  <0, 0, 0>, -1\r\n}\r\n");
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_CONTAINS(bad.err, "crlf.drt:2:14: error:");
    EXPECT_EQ(bad.err.find('\r'), std::string::npos); // the quoted line has no stray carriage return
}

TEST(HardeningScene, EmptyFilesFoldersAndDevicesAsScenes) {
    const Outcome empty = runOn("empty.drt", "");
    EXPECT_EQ(empty.exitCode, 0) << empty.err; // an empty scene is valid: nothing in it
    const test::CommandResult folder = runDrt("check /tmp");
    EXPECT_EQ(folder.exitCode, 3);
    EXPECT_CONTAINS(folder.err, "drt: cannot read scene '/tmp': not a readable file");
    const test::CommandResult zero = runDrt("check /dev/zero");
    EXPECT_EQ(zero.exitCode, 3);
    EXPECT_CONTAINS(zero.err, "cannot read scene '/dev/zero'");
}

TEST(HardeningScene, ACameraLookingAlongItsSkyIsALocatedErrorInCheck) {
    const Outcome sky = runOn("cam.drt", "\ncamera { location <0, 0, 0> look_at <0, 5, 0> }\n");
    EXPECT_EQ(sky.exitCode, 1);
    EXPECT_CONTAINS(sky.err, "cam.drt:2:1: error: camera: sky is parallel to the look_at direction");
    const Outcome up = runOn("cam.drt", "camera { location <0, 0, 0> direction <0, 1, 0> }\n");
    EXPECT_EQ(up.exitCode, 1);
    EXPECT_CONTAINS(up.err, "cam.drt:1:1: error: camera: up is parallel to the direction");
    // render reports it the same way, before rendering.
    const Outcome render = runOn("cam.drt", "camera { location <0, 0, 0> look_at <0, -5, 0> }\n", "render",
                                 "-o /tmp/never-written.png");
    EXPECT_EQ(render.exitCode, 1);
    EXPECT_CONTAINS(render.err, "cam.drt:1:1: error: camera: sky is parallel to the look_at direction");
}

} // namespace
} // namespace drt
