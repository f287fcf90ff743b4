// drt bench reads POV-Ray scenes as render does (drt test's are in
// golden_ci_test.cpp): the front end is chosen by the file's extension.
#include "lang/load.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace fs = std::filesystem;

namespace drt {
namespace {

TEST(PovCommands, FrontEndIsChosenByTheExtension) {
    EXPECT_EQ(dialectForPath("a/b.pov"), DialectKind::Pov);
    EXPECT_EQ(dialectForPath("B.POV"), DialectKind::Pov);
    EXPECT_EQ(dialectForPath("colors.inc"), DialectKind::Pov);
    EXPECT_EQ(dialectForPath("scene.drt"), DialectKind::Drt);
    EXPECT_EQ(dialectForPath("pov"), DialectKind::Drt);
    const std::string dir = test::tempDir();
    // `#declare X = 1` without ';' is POV-Ray syntax the .drt parser rejects.
    test::writeFile(dir + "/s.pov", "#declare R = 1\nsphere { 0, R }\n");
    test::writeFile(dir + "/s.drt", "#declare R = 1\nsphere { 0, R }\n");
    Diagnostics pov, drt;
    EXPECT_TRUE(loadScene(dir + "/s.pov", pov)) << pov.formatAll();
    EXPECT_FALSE(loadScene(dir + "/s.drt", drt));
}

TEST(PovCommands, BenchReadsAPovScene) {
    const std::string dir = test::tempDir();
    const std::string scene = test::writeFile(dir + "/ball.pov", "camera { location <0, 1, -4> look_at <0, 0.5, 0> }\n"
                                                                 "light_source { <-3, 5, -4> color rgb 1 }\n"
                                                                 "sphere { <0, 0.5, 0>, 0.5 pigment { rgb 1 } }\n");
    const auto r = test::runDrt("bench '" + scene + "' -o '" + dir + "/bench' --spp 1,2 --seeds 1 --methods sobol "
                                "--width 12 --reference-spp 8 --threads 2");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir + "/bench/results.csv")) << r.out << r.err;
    EXPECT_NE(test::readFile(dir + "/bench/summary.md").find("ball.pov"), std::string::npos);
}

} // namespace
} // namespace drt
