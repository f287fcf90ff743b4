// Smaller POV-Ray front-end features: finish crand, the bounds behind
// min_extent / max_extent, and files a scene writes.
#include "pov/load.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace drt {
namespace {

std::optional<Scene> load(const std::string& text, Diagnostics& diags) {
    return loadPovSceneText(text, "f.pov", diags, PovOptions{});
}

TEST(PovFeatures, CrandIsReadWithoutAWarning) {
    Diagnostics diags;
    const auto s = load("sphere { 0, 1 finish { crand 0.25 diffuse 0.7 } }", diags);
    ASSERT_TRUE(s) << diags.formatAll();
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    EXPECT_EQ(s->objects.at(0).texture.finish.crand, 0.25);
    EXPECT_EQ(s->objects.at(0).texture.finish.diffuse, 0.7);
}

TEST(PovFeatures, MinAndMaxExtent) {
    Diagnostics diags;
    const auto s = load("#declare B = box { <1, 2, 3>, <4, 5, 6> translate x }\n"
                        "#declare D = difference { object { B } sphere { 0, 10 } }\n"
                        "#warning vstr(3, min_extent(B), \",\", 0, 0)\n"
                        "#warning vstr(3, max_extent(D), \",\", 0, 0)\n"
                        "#warning vstr(3, max_extent(plane { y, 0 }), \",\", 0, 0)\n"
                        "#declare T = isosurface { function { x * x + y * y + z * z - 1 } }\n"
                        "#warning vstr(3, min_extent(T) + max_extent(T), \",\", 0, 0)\n",
                        diags);
    ASSERT_TRUE(s) << diags.formatAll();
    std::vector<std::string> messages;
    for (const Diagnostic& d : diags.all())
        if (d.message.rfind("#warning: ", 0) == 0) messages.push_back(d.message.substr(10));
    // A shape the front end leaves out (with its own warning) is unbounded, as
    // POV-Ray's infinite objects: the centring idiom min + (max - min) / 2 gives 0.
    EXPECT_EQ(messages, (std::vector<std::string>{"2,2,3", "5,5,6", "10000000000,10000000000,10000000000", "0,0,0"}));
    Diagnostics light;
    EXPECT_FALSE(load("#declare L = light_source { 0, 1 }\n#declare M = min_extent(L);", light));
    EXPECT_NE(light.formatAll().find("'min_extent' needs an object"), std::string::npos) << light.formatAll();
}

TEST(PovFeatures, WrittenFilesAreDroppedAndReadingIsAnError) {
    // The portfolio scenes write HTML through html_gen.inc.
    Diagnostics diags;
    const auto s = load("#declare Name = \"drt_pov_features_test.html\";\n"
                        "#fopen Out Name write\n#write(Out \"<p>\", str(2, 0, 0) \"</p>\\n\")\n"
                        "#write (Out, Name)\n#fclose Out\n#fopen Log \"drt_pov_features_test.log\" append\n"
                        "#warning \"done\"\n",
                        diags);
    ASSERT_TRUE(s) << diags.formatAll();
    EXPECT_EQ(diags.warningCount(), 1) << diags.formatAll(); // the #warning only
    EXPECT_FALSE(std::filesystem::exists("drt_pov_features_test.html"));
    struct Case {
        const char* text;
        const char* message;
        int column;
    };
    for (const Case& c : {Case{"#fopen In \"data.txt\" read", "#fopen ... read (file input) is not supported", 22},
                          Case{"#read (In, V)", "#read (file input) is not supported", 1},
                          Case{"#fopen In \"data.txt\" writ", "expected 'read', 'write' or 'append' after the file name", 22}}) {
        Diagnostics bad;
        EXPECT_FALSE(load(c.text, bad)) << c.text;
        ASSERT_GE(bad.errorCount(), 1);
        EXPECT_NE(bad.all()[0].message.find(c.message), std::string::npos) << bad.formatAll();
        EXPECT_EQ(bad.all()[0].loc.column, c.column) << c.text;
    }
}

} // namespace
} // namespace drt
