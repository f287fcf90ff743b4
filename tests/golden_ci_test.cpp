// drt test for CI systems: JUnit XML and JSON reports (golden/ci_report.cpp),
// PNG previews beside EXR goldens, POV-Ray scenes as tests, and report files
// checked before the run. tests/ci/junit_consumer.sh has a real JUnit reader
// (python3-junitparser) read the XML.
#include "cli/commands.h"
#include "golden/golden.h"
#include "image/image.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <regex>

namespace fs = std::filesystem;

namespace drt {
namespace {

using golden::Outcome;

int count(const std::string& text, const std::string& what) {
    int n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

// A run with one case of every outcome, the failures with figures.
golden::RunSummary syntheticRun() {
    golden::RunSummary summary;
    summary.folder = "suite/";
    summary.seconds = 2.5;
    golden::CaseResult pass;
    pass.name = "pass";
    pass.outcome = Outcome::Pass;
    pass.seconds = 0.25;
    golden::CaseResult exact;
    exact.name = "exact<&>";
    exact.outcome = Outcome::Fail;
    exact.message = "exact.golden.exr: 12 pixels (3%) differ by more than 0";
    exact.scenePath = "suite/exact.drt";
    CompareResult e;
    e.width = 20, e.height = 20, e.channels = 3, e.pixelCount = 400;
    e.rmse = 0.5, e.meanSignedError = -0.125, e.maxError = 0.75, e.maxErrorX = 3, e.maxErrorY = 4;
    e.maxErrorChannel = 1, e.failingPixels = 12, e.psnr = std::numeric_limits<double>::infinity();
    exact.comparison = e;
    golden::CaseResult statistical;
    statistical.name = "noisy";
    statistical.policy = golden::Policy::Statistical;
    statistical.outcome = Outcome::Fail;
    statistical.message = "biased: the mean error of channel B has z = 5.00 (|z| > 3.14)\x01";
    CompareResult s = e;
    s.statistical = true;
    s.globalZ = {0.5, -1.0, 5.0};
    s.globalZThreshold = 3.14, s.tileTests = 100, s.failingTiles = 7, s.tileZThreshold = 4.2;
    s.worstTile.channel = 2, s.worstTile.z = 6.5;
    statistical.comparison = s;
    golden::CaseResult missing;
    missing.name = "missing";
    missing.outcome = Outcome::Missing;
    missing.message = "no missing.golden.json (create the golden with drt test --update)";
    golden::CaseResult error;
    error.name = "broken";
    error.outcome = Outcome::Error;
    error.message = "broken.drt: the scene has 1 error";
    error.details = "broken.drt:2:1: error: unknown keyword 'spere'\n  spere { 0, 1 }\n  ^\n";
    summary.cases = {error, exact, missing, statistical, pass};
    summary.passed = 1, summary.failed = 2, summary.missing = 1, summary.errors = 1;
    return summary;
}

TEST(GoldenCi, JUnitHasOneTestcasePerSceneWithTheFigures) {
    const std::string xml = golden::junitReport(syntheticRun());
    EXPECT_EQ(xml.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites>\n", 0), 0u) << xml;
    EXPECT_EQ(count(xml, "<testsuite "), 1);
    EXPECT_EQ(count(xml, "<testcase "), 5);
    // The Ant JUnit format's required testsuite attributes (a FAIL and a MISSING are failures).
    std::smatch suite;
    ASSERT_TRUE(std::regex_search(xml, suite, std::regex("<testsuite ([^>]*)>")));
    const std::string attributes = suite[1];
    for (const char* attribute : {"package=\"drt\"", "id=\"0\"", "name=\"suite\"", "tests=\"5\"",
                                  "failures=\"3\"", "errors=\"1\"", "skipped=\"0\"", "time=\"2.500\""})
        EXPECT_NE(attributes.find(attribute), std::string::npos) << attribute << " in " << attributes;
    EXPECT_TRUE(std::regex_search(attributes, std::regex(R"(timestamp="\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d")")));
    EXPECT_TRUE(std::regex_search(attributes, std::regex(R"(hostname="[^"]+")")));
    // Children in the schema's order, each present.
    const size_t properties = xml.find("<properties>"), firstCase = xml.find("<testcase "),
                 out = xml.find("<system-out>"), err = xml.find("<system-err>");
    EXPECT_TRUE(properties < firstCase && firstCase < out && out < err) << xml;

    EXPECT_NE(xml.find("<testcase name=\"pass\" classname=\"suite\" time=\"0.250\"/>"), std::string::npos);
    // A failure: one-line message, the figures in the text, markup escaped, control characters dropped.
    EXPECT_NE(xml.find("<testcase name=\"exact&lt;&amp;&gt;\""), std::string::npos);
    EXPECT_NE(xml.find("<failure message=\"exact.golden.exr: 12 pixels (3%) differ by more than 0\" type=\"FAIL\">"),
              std::string::npos);
    EXPECT_NE(xml.find("RMSE 0.5, bias -0.125, max error 0.75 at (3, 4) G, NaN/Inf pixels 0; 12 pixels differ"),
              std::string::npos);
    EXPECT_NE(xml.find("scene: suite/exact.drt"), std::string::npos);
    EXPECT_NE(xml.find("(|z| &gt; 3.14)\" type=\"FAIL\">"), std::string::npos);
    EXPECT_EQ(xml.find('\x01'), std::string::npos);
    EXPECT_NE(xml.find("global z B +5.00 (limit 3.14), 7 of 100 tiles fail"), std::string::npos);
    EXPECT_NE(xml.find("<failure message=\"no missing.golden.json"), std::string::npos);
    EXPECT_NE(xml.find("type=\"MISSING\""), std::string::npos);
    EXPECT_NE(xml.find("<error message=\"broken.drt: the scene has 1 error\" type=\"ERROR\">"), std::string::npos);
    EXPECT_NE(xml.find("unknown keyword &apos;spere&apos;"), std::string::npos);
}

TEST(GoldenCi, JsonHasTheFiguresThatMeanSomethingForThePolicy) {
    const auto report = nlohmann::json::parse(golden::jsonReport(syntheticRun()));
    EXPECT_EQ(report.at("tests"), 5);
    EXPECT_EQ(report.at("failed"), 2);
    EXPECT_EQ(report.at("missing"), 1);
    EXPECT_EQ(report.at("errors"), 1);
    EXPECT_EQ(report.at("all_passed"), false);
    EXPECT_EQ(report.at("drt_version"), DRT_VERSION);
    const auto& cases = report.at("cases");
    ASSERT_EQ(cases.size(), 5u);
    EXPECT_EQ(cases[0].at("outcome"), "ERROR");
    EXPECT_NE(cases[0].at("details").get<std::string>().find("spere"), std::string::npos);
    const auto& exact = cases[1].at("figures");
    EXPECT_EQ(exact.at("differing_pixels"), 12);
    EXPECT_EQ(exact.at("max_error").at("channel"), "G");
    EXPECT_TRUE(exact.at("psnr_db").is_null()); // identical pixels: infinite PSNR
    EXPECT_FALSE(exact.contains("global_z"));
    const auto& noisy = cases[3].at("figures");
    EXPECT_EQ(noisy.at("global_z").at("B"), 5.0);
    EXPECT_EQ(noisy.at("failing_tiles"), 7);
    EXPECT_EQ(noisy.at("worst_tile").at("channel"), "B");
    EXPECT_FALSE(noisy.contains("differing_pixels"));
    EXPECT_FALSE(cases[2].contains("figures"));
}

std::string ballScene(const std::string& colour) {
    return "render { width 24 height 16 samples 2 seed 3 }\n"
           "camera { location <0, 1, -4> look_at <0, 0.5, 0> angle 50 }\n"
           "light_source { <-3, 5, -4>, color rgb 1 }\n"
           "sphere { <0, 0.5, 0>, 0.5 pigment { color rgb " +
           colour + " } }\nplane { y, 0 pigment { color rgb 0.7 } }\n";
}

TEST(GoldenCi, CommandWritesJUnitAndJsonAndChecksTheirFolderFirst) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/suite/ball.drt", ballScene("<0.9, 0.2, 0.1>"));
    ASSERT_EQ(test::runDrt("test '" + dir + "/suite' --update").exitCode, 0);
    test::writeFile(dir + "/suite/ball.drt", ballScene("<0.9, 0.3, 0.1>"));
    test::writeFile(dir + "/suite/new.drt", ballScene("1"));
    const auto r = test::runDrt("test '" + dir + "/suite' --junit '" + dir + "/junit.xml' --json '" + dir + "/r.json'");
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    const std::string xml = test::readFile(dir + "/junit.xml");
    EXPECT_EQ(count(xml, "<testcase "), 2);
    EXPECT_NE(xml.find("<testsuite package=\"drt\" id=\"0\" name=\"" + dir + "/suite\""), std::string::npos) << xml;
    EXPECT_NE(xml.find("pixels differ"), std::string::npos);
    EXPECT_EQ(nlohmann::json::parse(test::readFile(dir + "/r.json")).at("cases").size(), 2u);

    // A report file in a folder that does not exist: an I/O error before anything is rendered.
    const auto early = test::runDrt("test '" + dir + "/suite' --junit '" + dir + "/nowhere/junit.xml'");
    EXPECT_EQ(early.exitCode, 3);
    EXPECT_NE(early.err.find("--junit " + dir + "/nowhere/junit.xml: folder"), std::string::npos) << early.err;
    EXPECT_EQ(early.out, "");
}

TEST(GoldenCi, UpdateWritesAPngPreviewBesideAnExrGolden) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/ball.drt", ballScene("<0.9, 0.2, 0.1>"));
    test::writeFile(dir + "/flat.drt", ballScene("0.5"));
    test::writeFile(dir + "/flat.golden.json", R"({ "format": "png" })");
    std::string error;
    golden::RunOptions update;
    update.update = true;
    const golden::RunSummary created = golden::runGoldenTests(dir, update, error);
    ASSERT_EQ(created.updated, 2) << error;
    Image preview, golden;
    Metadata metadata;
    ASSERT_EQ(readImage(dir + "/ball.preview.png", preview, &metadata), "");
    ASSERT_EQ(readImage(dir + "/ball.golden.exr", golden), "");
    EXPECT_EQ(preview.width, golden.width);
    EXPECT_EQ(preview.height, golden.height);
    EXPECT_NE(created.cases[0].message.find("ball.preview.png"), std::string::npos) << created.cases[0].message;
    EXPECT_FALSE(fs::exists(dir + "/flat.preview.png")); // a PNG golden is its own preview
    // Goldens and previews carry reproducible metadata: rewriting them changes no byte.
    const std::string exrBytes = test::readFile(dir + "/ball.golden.exr");
    const std::string pngBytes = test::readFile(dir + "/ball.preview.png");
    golden::runGoldenTests(dir, update, error);
    EXPECT_EQ(test::readFile(dir + "/ball.golden.exr"), exrBytes);
    EXPECT_EQ(test::readFile(dir + "/ball.preview.png"), pngBytes);
    // The report of a passing run shows the previews.
    const golden::RunSummary passed = golden::runGoldenTests(dir, {}, error);
    ASSERT_EQ(passed.passed, 2);
    EXPECT_EQ(passed.cases[0].previewPath, dir + "/ball.preview.png");
    EXPECT_EQ(passed.cases[1].previewPath, dir + "/flat.golden.png");
    ASSERT_EQ(golden::writeReport(dir + "/report", passed), "");
    EXPECT_EQ(count(test::readFile(dir + "/report/index.html"), "class=\"thumb\" src=\"data:image/png;base64,"), 2);
}

TEST(GoldenCi, PovRayScenesAreTestsToo) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/pov.pov", "#version 3.7;\n"
                                      "camera { location <0, 1, -4> look_at <0, 0.5, 0> }\n"
                                      "light_source { <-3, 5, -4> color rgb 1 }\n"
                                      "sphere { <0, 0.5, 0>, 0.5 pigment { color rgb <1, image_width / 100, 0> } }\n");
    std::string error;
    const golden::RunSummary missing = golden::runGoldenTests(dir, {}, error);
    ASSERT_EQ(missing.cases.size(), 1u) << error;
    EXPECT_EQ(missing.cases[0].outcome, Outcome::Missing);
    test::writeFile(dir + "/pov.golden.json", R"({ "width": 20, "height": 15, "spp": 1 })");
    golden::RunOptions update;
    update.update = true;
    ASSERT_EQ(golden::runGoldenTests(dir, update, error).updated, 1);
    const golden::RunSummary passed = golden::runGoldenTests(dir, {}, error);
    EXPECT_EQ(passed.passed, 1) << (passed.cases.empty() ? error : passed.cases[0].message);
    EXPECT_EQ(passed.cases[0].scenePath, dir + "/pov.pov");
    // The scene saw the sidecar's image size: its sphere's green is image_width / 100 = 0.2.
    Image golden;
    ASSERT_EQ(readImage(dir + "/pov.golden.exr", golden), "");
    EXPECT_EQ(golden.width, 20);
}

} // namespace
} // namespace drt
