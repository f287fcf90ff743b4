// The golden-image runner: drt's own goldens in tests/golden must all pass,
// and the runner itself is tested on temporary folders: a changed scene fails
// the exact policy, --update rewrites, a missing golden is reported and not
// created, a biased render fails the statistical policy, the report is written.
#include "cli/commands.h"
#include "golden/golden.h"
#include "image/image.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

namespace fs = std::filesystem;

namespace drt {
namespace {

using golden::Outcome;

std::string describe(const golden::RunSummary& summary) {
    std::string text;
    for (const auto& r : summary.cases)
        text += std::string(golden::outcomeName(r.outcome)) + " " + r.name + ": " + r.message + "\n";
    return text;
}

const golden::CaseResult* findCase(const golden::RunSummary& summary, const std::string& name) {
    for (const auto& r : summary.cases)
        if (r.name == name)
            return &r;
    return nullptr;
}

// A temporary folder removed at the end of the test.
struct TempFolder {
    std::string path = test::tempDir();
    ~TempFolder() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

golden::RunSummary run(const std::string& folder, bool update = false) {
    golden::RunOptions options;
    options.update = update;
    std::string error;
    golden::RunSummary summary = golden::runGoldenTests(folder, options, error);
    EXPECT_EQ(error, "");
    return summary;
}

TEST(GoldenSuite, EveryExampleHasAnExactGoldenOfAtMost128Pixels) {
    for (const auto& entry : fs::directory_iterator(test::sourcePath("examples"))) {
        if (entry.path().extension() != ".drt")
            continue;
        const std::string name = entry.path().stem().string();
        const std::string sidecar = test::sourcePath("tests/golden/" + name + ".golden.json");
        golden::GoldenSettings settings;
        ASSERT_EQ(golden::readSettings(sidecar, settings), "") << "examples/" << name << ".drt has no golden";
        EXPECT_EQ(settings.policy, golden::Policy::Exact) << name;
        EXPECT_EQ(settings.scene, "../../examples/" + name + ".drt");
        ASSERT_TRUE(settings.width && settings.height) << name;
        EXPECT_LE(*settings.width, 128) << name;
        EXPECT_LE(*settings.height, 128) << name;
    }
}

// The suite itself is run by ctest through the command CI systems use
// (`drt test tests/golden --junit ...`, tests/CMakeLists.txt); here, its shape.
TEST(GoldenSuite, HoldsAStatisticalSuite) {
    std::vector<golden::GoldenCase> cases;
    ASSERT_EQ(golden::discoverCases(test::sourcePath("tests/golden"), cases), "");
    int statistical = 0;
    for (const auto& c : cases) {
        golden::GoldenSettings settings;
        ASSERT_EQ(golden::readSettings(c.sidecarPath, settings), "") << c.name;
        statistical += settings.policy == golden::Policy::Statistical;
        // Every EXR golden has its PNG preview for review, showing the golden's pixels.
        Image golden, preview, expected;
        ASSERT_EQ(readImage(c.exrPath, golden), "") << c.name;
        ASSERT_EQ(readImage(c.previewPath, preview), "")
            << c.name << ": run drt test tests/golden --update --only " << c.name;
        const std::string roundTrip = test::tempDir() + "/preview.png";
        ASSERT_EQ(writeImage(roundTrip, golden), "");
        ASSERT_EQ(readImage(roundTrip, expected), "");
        EXPECT_EQ(preview.pixels, expected.pixels) << c.previewPath << " does not show " << c.exrPath;
    }
    EXPECT_GE(statistical, 3) << "the statistical suite has shrunk";
}

TEST(GoldenSuite, FolderStaysWithinAFewMegabytes) {
    uintmax_t bytes = 0;
    for (const auto& entry : fs::directory_iterator(test::sourcePath("tests/golden")))
        if (entry.is_regular_file())
            bytes += entry.file_size();
    EXPECT_LT(bytes, uintmax_t(4) << 20);
}

TEST(GoldenSuite, TheSidecarInTheManualIsValid) {
    const std::string manual = test::readFile(test::sourcePath("docs/golden-tests.md"));
    const size_t open = manual.find("```json\n");
    ASSERT_NE(open, std::string::npos);
    const size_t close = manual.find("```", open + 8);
    ASSERT_NE(close, std::string::npos);
    const TempFolder folder;
    const std::string path =
        test::writeFile(folder.path + "/doc.golden.json", manual.substr(open + 8, close - open - 8));
    golden::GoldenSettings settings;
    EXPECT_EQ(golden::readSettings(path, settings), "");
    EXPECT_EQ(settings.scene, "../../examples/whitted.drt");
    EXPECT_EQ(settings.samplesPerPixel, 9);
}

// A tiny scene whose sphere colour is a parameter, so a test can "break" it.
std::string tinyScene(const std::string& sphereColour, const std::string& light = "1") {
    return "render { width 24 height 16 samples 2 seed 3 }\n"
           "camera { location <0, 1, -4> look_at <0, 0.5, 0> angle 50 }\n"
           "light_source { <-3, 5, -4>, color rgb " +
           light +
           " }\n"
           "background { color rgb <0.2, 0.3, 0.5> }\n"
           "sphere { <0, 0.5, 0>, 0.5 pigment { color rgb " +
           sphereColour +
           " } }\n"
           "plane { y, 0 pigment { color rgb 0.7 } }\n";
}

TEST(GoldenRunner, MissingGoldenIsReportedAndNotCreated) {
    const TempFolder folder;
    const std::string& dir = folder.path;
    test::writeFile(dir + "/ball.drt", tinyScene("<0.9, 0.2, 0.1>"));
    const golden::RunSummary summary = run(dir);
    ASSERT_EQ(summary.cases.size(), 1u);
    EXPECT_EQ(summary.cases[0].outcome, Outcome::Missing);
    EXPECT_NE(summary.cases[0].message.find("--update"), std::string::npos);
    EXPECT_FALSE(summary.allPassed());
    EXPECT_FALSE(fs::exists(dir + "/ball.golden.json"));
    EXPECT_FALSE(fs::exists(dir + "/ball.golden.exr"));

    // A sidecar without its image is missing too.
    test::writeFile(dir + "/ball.golden.json", R"({ "policy": "exact", "width": 16, "height": 12 })");
    const golden::RunSummary again = run(dir);
    EXPECT_EQ(again.cases[0].outcome, Outcome::Missing);
    EXPECT_FALSE(fs::exists(dir + "/ball.golden.exr"));
}

TEST(GoldenRunner, ExactPolicyCatchesAChangedSceneAndUpdateRewrites) {
    const TempFolder folder;
    const std::string& dir = folder.path;
    test::writeFile(dir + "/ball.drt", tinyScene("<0.9, 0.2, 0.1>"));
    const golden::RunSummary created = run(dir, true);
    ASSERT_EQ(created.updated, 1) << describe(created);
    ASSERT_TRUE(fs::exists(dir + "/ball.golden.exr"));
    golden::GoldenSettings settings;
    ASSERT_EQ(golden::readSettings(dir + "/ball.golden.json", settings), "");
    EXPECT_EQ(settings.width, 24); // the scene's settings, frozen in the sidecar
    EXPECT_EQ(settings.samplesPerPixel, 2);
    EXPECT_EQ(run(dir).passed, 1);

    // A barely different colour: 0.2 -> 0.21 in green.
    test::writeFile(dir + "/ball.drt", tinyScene("<0.9, 0.21, 0.1>"));
    const golden::RunSummary changed = run(dir);
    ASSERT_EQ(changed.cases.size(), 1u);
    EXPECT_EQ(changed.cases[0].outcome, Outcome::Fail) << describe(changed);
    ASSERT_TRUE(changed.cases[0].comparison);
    EXPECT_GT(changed.cases[0].comparison->failingPixels, 0);

    // The report shows candidate, golden and heatmap for the failure, embedded
    // in the page, and the figures an exact test has (no z-scores).
    const std::string report = dir + "/report";
    ASSERT_EQ(golden::writeReport(report, changed), "");
    const std::string html = test::readFile(report + "/index.html");
    for (const char* caption : {">candidate<", ">golden<", ">heatmap of |error|"})
        EXPECT_NE(html.find(caption), std::string::npos) << caption;
    size_t embedded = 0;
    for (size_t at = html.find("src=\"data:image/png;base64,"); at != std::string::npos;
         at = html.find("src=\"data:image/png;base64,", at + 1))
        ++embedded;
    EXPECT_EQ(embedded, 3u);
    EXPECT_NE(html.find("pixels that differ"), std::string::npos);
    EXPECT_NE(html.find("channels R/G/B"), std::string::npos);
    EXPECT_EQ(html.find("global z"), std::string::npos);
    Image candidate;
    EXPECT_EQ(readImage(report + "/ball.candidate.exr", candidate), "");
    EXPECT_EQ(candidate.width, 24);
    for (const auto& entry : fs::directory_iterator(report)) // nothing else is left in the folder
        EXPECT_TRUE(entry.path().filename() == "index.html" || entry.path().filename() == "ball.candidate.exr")
            << entry.path();

    // --update rewrites the golden, which then passes.
    const golden::RunSummary updated = run(dir, true);
    EXPECT_EQ(updated.updated, 1);
    EXPECT_EQ(run(dir).passed, 1);
}

TEST(GoldenRunner, ToleranceLetsSmallDifferencesPass) {
    const TempFolder folder;
    const std::string& dir = folder.path;
    test::writeFile(dir + "/ball.drt", tinyScene("<0.9, 0.2, 0.1>"));
    test::writeFile(dir + "/ball.golden.json", R"({ "fail": 0.05, "fail_percent": 0 })");
    ASSERT_EQ(run(dir, true).updated, 1);
    test::writeFile(dir + "/ball.drt", tinyScene("<0.9, 0.21, 0.1>"));
    EXPECT_EQ(run(dir).passed, 1);
    test::writeFile(dir + "/ball.drt", tinyScene("<0.9, 0.5, 0.1>"));
    EXPECT_EQ(run(dir).failed, 1);
}

TEST(GoldenRunner, PngGoldenComparesQuantisedPixels) {
    const TempFolder folder;
    const std::string& dir = folder.path;
    test::writeFile(dir + "/ball.drt", tinyScene("<0.9, 0.2, 0.1>"));
    test::writeFile(dir + "/ball.golden.json", R"({ "policy": "exact", "format": "png" })");
    const golden::RunSummary created = run(dir, true);
    ASSERT_EQ(created.updated, 1) << describe(created);
    EXPECT_FALSE(fs::exists(dir + "/ball.golden.exr"));
    Image png;
    ASSERT_EQ(readImage(dir + "/ball.golden.png", png), "");
    EXPECT_EQ(run(dir).passed, 1);
    test::writeFile(dir + "/ball.drt", tinyScene("<0.9, 0.3, 0.1>"));
    EXPECT_EQ(run(dir).failed, 1);
}

TEST(GoldenRunner, BrokenSidecarOrSceneIsAnError) {
    const TempFolder folder;
    const std::string& dir = folder.path;
    test::writeFile(dir + "/typo.golden.json", R"({ "scene": "ball.drt", "tolerance": 1 })");
    test::writeFile(dir + "/nojson.golden.json", "{ \"policy\": \"exact\", }");
    test::writeFile(dir + "/noscene.golden.json", R"({ "scene": "../nowhere/gone.drt" })");
    test::writeFile(dir + "/broken.drt", "camera { location <0, 1, -4> }\nspere { 0, 1 }\n");
    test::writeFile(dir + "/broken.golden.json", "{}");
    test::writeFile(dir + "/ball.drt", tinyScene("1"));
    const golden::RunSummary summary = run(dir);
    EXPECT_EQ(summary.errors, 4) << describe(summary);
    EXPECT_NE(findCase(summary, "typo")->message.find("unknown key 'tolerance'"), std::string::npos);
    EXPECT_NE(findCase(summary, "nojson")->message.find("not valid JSON"), std::string::npos);
    EXPECT_NE(findCase(summary, "noscene")->message.find("no such scene"), std::string::npos);
    EXPECT_NE(findCase(summary, "broken")->details.find("broken.drt:2:1"), std::string::npos)
        << findCase(summary, "broken")->details;
    EXPECT_EQ(findCase(summary, "ball")->outcome, Outcome::Missing);
}

TEST(GoldenRunner, StatisticalPolicyPassesNoiseAndFailsABias) {
    const TempFolder folder;
    const std::string& dir = folder.path;
    // Soft shadows from an area light: noisy at 8 spp.
    const std::string scene =
        "render { width 32 height 24 samples 8 seed 3 }\n"
        "camera { location <0, 2, -4> look_at <0, 0.5, 0> angle 50 }\n"
        "light_source { <0, 4, 0>, color rgb LIGHT area_light <2, 0, 0>, <0, 0, 2>, 2, 2 }\n"
        "sphere { <0, 0.6, 0>, 0.6 pigment { color rgb 0.8 } }\n"
        "plane { y, 0 pigment { color rgb 0.8 } }\n";
    auto withLight = [&scene](const std::string& light) {
        std::string text = scene;
        text.replace(text.find("LIGHT"), 5, light);
        return text;
    };
    test::writeFile(dir + "/shadow.drt", withLight("1"));
    test::writeFile(dir + "/shadow.golden.json", R"({ "policy": "statistical", "reference_spp": 256 })");
    ASSERT_EQ(run(dir, true).updated, 1);
    EXPECT_TRUE(fs::exists(dir + "/shadow.golden.var.exr"));

    // Other seeds: noise only, passes (alpha 0.01 per seed; these seeds are fixed).
    for (int seed : {4, 5, 6}) {
        test::writeFile(dir + "/shadow.golden.json",
                        R"({ "policy": "statistical", "reference_spp": 256, "seed": )" +
                            std::to_string(seed) + "}");
        const golden::RunSummary summary = run(dir);
        EXPECT_EQ(summary.passed, 1) << "seed " << seed << ": " << describe(summary);
    }
    // A 3% brighter light is a bias the z-tests must catch.
    test::writeFile(dir + "/shadow.drt", withLight("1.03"));
    const golden::RunSummary biased = run(dir);
    ASSERT_EQ(biased.failed, 1) << describe(biased);
    const std::string report = dir + "/report";
    ASSERT_EQ(golden::writeReport(report, biased), "");
    const std::string html = test::readFile(report + "/index.html");
    EXPECT_NE(html.find(">z-map of candidate - golden"), std::string::npos);
    EXPECT_NE(html.find("global z per channel</th><td>R "), std::string::npos) << html.substr(0, 4000);
    // Every pixel of a noisy render differs: the exact policy's pixel count means nothing here.
    EXPECT_EQ(html.find("pixels that differ"), std::string::npos);
    EXPECT_EQ(html.find("pixels over the fail threshold"), std::string::npos);
}

TEST(GoldenRunner, TestCommandExitStatuses) {
    const TempFolder folder;
    const std::string& dir = folder.path;
    test::writeFile(dir + "/ball.drt", tinyScene("<0.9, 0.2, 0.1>"));
    std::ostringstream out, err;
    cli::TestCommand command;
    command.folder = dir;
    EXPECT_EQ(cli::runTest(command, out, err), 1); // missing golden
    EXPECT_NE(out.str().find("MISSING"), std::string::npos);
    command.update = true;
    EXPECT_EQ(cli::runTest(command, out, err), 0);
    command.update = false;
    out.str("");
    EXPECT_EQ(cli::runTest(command, out, err), 0);
    EXPECT_NE(out.str().find("1 passed"), std::string::npos) << out.str();

    test::writeFile(dir + "/ball.drt", tinyScene("<0.9, 0.2, 0.2>"));
    command.reportDir = dir + "/report";
    EXPECT_EQ(cli::runTest(command, out, err), 1);
    EXPECT_TRUE(fs::exists(dir + "/report/index.html"));

    command.folder = dir + "/no-such-folder";
    EXPECT_EQ(cli::runTest(command, out, err), 3);
    command.folder = dir;
    command.only = {"nope"};
    EXPECT_EQ(cli::runTest(command, out, err), 3);
}

TEST(GoldenRunner, CommandLineRunsTheFolder) {
    const TempFolder folder;
    const std::string& dir = folder.path;
    test::writeFile(dir + "/ball.drt", tinyScene("<0.9, 0.2, 0.1>"));
    EXPECT_EQ(test::runDrt("test '" + dir + "'").exitCode, 1);
    EXPECT_EQ(test::runDrt("test --update '" + dir + "'").exitCode, 0);
    const test::CommandResult passed = test::runDrt("test '" + dir + "'");
    EXPECT_EQ(passed.exitCode, 0) << passed.out << passed.err;
    EXPECT_NE(passed.out.find("PASS"), std::string::npos);
}

} // namespace
} // namespace drt
