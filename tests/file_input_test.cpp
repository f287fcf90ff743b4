// POV-Ray's file input in both dialects: #fopen ... read, #read (ID, vars),
// #fclose and defined(ID) at the end of the file; every error located in the
// scene (file, line, column, caret) with a note at the data; and files a scene
// writes (#fopen ... write/append, #write) are never created.
#include "lang/load.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace drt {
namespace {

namespace fs = std::filesystem;

struct Loaded {
    std::optional<Scene> scene;
    Diagnostics diags;
    std::vector<std::string> warnings; // the #warning texts
};

// The scene `text` as DIR/NAME beside a data file DIR/data.txt holding `data`.
std::unique_ptr<Loaded> loadWithData(const std::string& name, const std::string& text, const std::string& data) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/data.txt", data);
    const std::string path = test::writeFile(dir + "/" + name, text);
    auto l = std::make_unique<Loaded>();
    l->scene = loadScene(path, l->diags, LoadOptions{});
    for (const Diagnostic& d : l->diags.all())
        if (d.message.rfind("#warning: ", 0) == 0) l->warnings.push_back(d.message.substr(10));
    return l;
}

class FileInput : public ::testing::TestWithParam<const char*> {};

TEST_P(FileInput, ReadsStringsNumbersAndVectors) {
    auto l = loadWithData(GetParam(),
                          "#fopen F \"data.txt\" read\n"
                          "#read (F, S, X, V)\n"
                          "#read (F, Y, W)\n"
                          "#warning concat(S, \"|\", str(X, 0, 1), \"|\", vstr(3, V, \",\", 0, 1))\n"
                          "#warning concat(str(Y, 0, 2), \"|\", vstr(2, W, \",\", 0, 1), \"|\", str(defined(F), 0, 0))\n"
                          "sphere { V, X }\n",
                          "\"Testing, \\\"123\\\"\",5,<1,2,3>,\n  -2.5e1 , < 0.5, -1 >,\n");
    ASSERT_TRUE(l->scene) << l->diags.formatAll();
    ASSERT_EQ(l->warnings.size(), 2u) << l->diags.formatAll();
    EXPECT_EQ(l->warnings[0], "Testing, \"123\"|5.0|1.0,2.0,3.0");
    // Only separators left after the second #read: the file is closed and F undefined.
    EXPECT_EQ(l->warnings[1], "-25.00|0.5,-1.0|0");
    ASSERT_EQ(l->scene->objects.size(), 1u);
}

TEST_P(FileInput, WhileDefinedReadsToTheEnd) {
    auto l = loadWithData(GetParam(),
                          "#declare N = 0;\n#fopen F \"data.txt\" read\n"
                          "#while (defined(F))\n  #read (F, V)\n  sphere { <V, 0, 0>, 1 }\n  #declare N = N + 1;\n#end\n"
                          "#warning str(N, 0, 0)\n",
                          "1, 2,\n3,\n\n");
    ASSERT_TRUE(l->scene) << l->diags.formatAll();
    ASSERT_EQ(l->scene->objects.size(), 3u);
    EXPECT_EQ(l->warnings, std::vector<std::string>{"3"});
}

TEST_P(FileInput, FcloseUndefinesTheIdentifier) {
    auto l = loadWithData(GetParam(),
                          "#fopen F \"data.txt\" read\n#read (F, A)\n#warning str(defined(F), 0, 0)\n#fclose F\n"
                          "#warning str(defined(F), 0, 0)\n#warning str(A, 0, 0)\nsphere { 0, 1 }\n",
                          "7, 8, 9\n");
    ASSERT_TRUE(l->scene) << l->diags.formatAll();
    EXPECT_EQ(l->warnings, (std::vector<std::string>{"1", "0", "7"}));
}

TEST_P(FileInput, WritingNeverCreatesAFile) {
    const std::string dir = test::tempDir();
    const std::string path = test::writeFile(dir + "/" + GetParam(),
                                             "#fopen W \"out.txt\" write\n#write (W, \"x\", 1, <1, 2, 3>, \"\\n\")\n"
                                             "#fclose W\n#fopen A \"log.txt\" append\n#write (A, \"y\")\nsphere { 0, 1 }\n");
    Diagnostics diags;
    const auto s = loadScene(path, diags, LoadOptions{});
    ASSERT_TRUE(s) << diags.formatAll();
    EXPECT_FALSE(fs::exists(dir + "/out.txt"));
    EXPECT_FALSE(fs::exists(dir + "/log.txt"));
    EXPECT_FALSE(fs::exists("out.txt"));
    EXPECT_NE(diags.formatAll().find("note: #fopen ... write: drt does not create the files a scene writes"),
              std::string::npos)
        << diags.formatAll();
}

INSTANTIATE_TEST_SUITE_P(Dialects, FileInput, ::testing::Values("s.drt", "s.pov"),
                         [](const auto& info) { return std::string(info.param[2] == 'd' ? "Drt" : "Pov"); });

struct ReadError {
    const char* name;
    const char* scene;
    const char* data;
    const char* message;
    int line, column;   // in the scene
    int dataLine = 0;   // the note's place in data.txt; 0: no note
    int dataColumn = 0;
};

class FileInputErrors : public ::testing::TestWithParam<ReadError> {};

TEST_P(FileInputErrors, LocatedWithACaretAndANoteAtTheData) {
    const ReadError& c = GetParam();
    for (const char* name : {"e.drt", "e.pov"}) {
        auto l = loadWithData(name, c.scene, c.data);
        EXPECT_FALSE(l->scene) << name;
        EXPECT_EQ(l->diags.errorCount(), 1) << l->diags.formatAll();
        const Diagnostic* d = test::expectErrorAt(l->diags, name, c.line, c.column, c.message);
        if (!d || c.dataLine == 0) continue;
        const std::string text = l->diags.formatAll();
        ASSERT_EQ(d->notes.size(), 1u) << text;
        EXPECT_EQ(d->notes[0].message, "the data read is here");
        EXPECT_EQ(d->notes[0].loc.line, c.dataLine) << text;
        EXPECT_EQ(d->notes[0].loc.column, c.dataColumn) << text;
        EXPECT_NE(text.find("data.txt:" + std::to_string(c.dataLine) + ":" + std::to_string(c.dataColumn) +
                            ": note: the data read is here"),
                  std::string::npos)
            << text;
    }
}

// clang-format off
const ReadError kReadErrors[] = {
    {"MissingFile", "sphere { 0, 1 }\n#fopen F \"no_such_file.txt\" read\n", "",
     "cannot find the file \"no_such_file.txt\" to read (#fopen ... read)", 2, 10},
    {"NeverOpened", "#read (G, A)\n", "1",
     "'G' is not an open file: it was never opened, or closed, or read to its end", 1, 8},
    {"NotAFile", "#declare G = 1;\n#read (G, A)\n", "1",
     "'G' is not a file opened for reading (#fopen ... read)", 2, 8},
    {"WrittenFileIsNotRead", "#fopen G \"w.txt\" write\n#read (G, A)\n", "1",
     "'G' is not a file opened for reading (#fopen ... read)", 2, 8},
    {"PastTheEnd", "#fopen F \"data.txt\" read\n#read (F, A,\n  B)\n", "1, \n",
     "#read of 'B' from \"data.txt\" (line 2, column 1): reading past the end of the file", 3, 3, 2, 1},
    {"AfterTheEnd", "#fopen F \"data.txt\" read\n#read (F, A)\n#read (F, B)\n", "1",
     "'F' is not an open file: it was never opened, or closed, or read to its end", 3, 8},
    {"AfterFclose", "#fopen F \"data.txt\" read\n#fclose F\n#read (F, B)\n", "1, 2",
     "'F' is not an open file: it was never opened, or closed, or read to its end", 3, 8},
    {"BadWord", "#fopen F \"data.txt\" read\n#read (F, A, B)\n", "1,\n  abc, 2\n",
     "#read of 'B' from \"data.txt\" (line 2, column 3): expected a number, a \"string\" or a <vector>, found 'abc'",
     2, 14, 2, 3},
    {"UnclosedString", "#fopen F \"data.txt\" read\n#read (F, S)\n", "\"abc\n",
     "#read of 'S' from \"data.txt\" (line 1, column 1): the string is not closed", 2, 11, 1, 1},
    {"BadVector", "#fopen F \"data.txt\" read\n#read (F, V)\n", "<1, x, 3>",
     "#read of 'V' from \"data.txt\" (line 1, column 5): expected a number in the vector", 2, 11, 1, 5},
    {"OneComponentVector", "#fopen F \"data.txt\" read\n#read (F, V)\n", "<1>",
     "#read of 'V' from \"data.txt\" (line 1, column 1): a vector needs at least 2 components", 2, 11, 1, 1},
    {"SixComponents", "#fopen F \"data.txt\" read\n#read (F, V)\n", "<1,2,3,4,5,6>",
     "#read of 'V' from \"data.txt\" (line 1, column 12): a vector has at most 5 components", 2, 11, 1, 12},
    {"NoSeparator", "#fopen F \"data.txt\" read\n#read (F, V)\n", "12x",
     "#read of 'V' from \"data.txt\" (line 1, column 3): expected ',' after the value, found 'x'", 2, 11, 1, 3},
    {"MissingComma", "#fopen F \"data.txt\" read\n#read (F, A B)\n", "1, 2",
     "expected ',' between the identifiers of #read, found 'B'", 2, 13},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Cases, FileInputErrors, ::testing::ValuesIn(kReadErrors),
                         [](const auto& info) { return std::string(info.param.name); });

} // namespace
} // namespace drt
