// drt bench: statistics with known answers, the CSV, the charts, and a tiny
// end-to-end run.
#include "bench/bench.h"
#include "bench/chart.h"
#include "bench/stats.h"
#include "cli/commands.h"
#include "image/image.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

namespace fs = std::filesystem;
using namespace drt;
using namespace drt::bench;

namespace {

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::stringstream stream(text);
    for (std::string line; std::getline(stream, line);)
        if (!line.empty()) lines.push_back(line);
    return lines;
}

std::vector<std::string> splitCommas(const std::string& line) {
    std::vector<std::string> fields;
    std::stringstream stream(line);
    for (std::string field; std::getline(stream, field, ',');) fields.push_back(field);
    return fields;
}

// A sphere over a plane under one point light: edges and smooth shading.
const char* kTinyScene = R"(
render { width 32 height 24 }
camera { location <0, 1.5, -4> look_at <0, 0.5, 0> angle 50 }
light_source { <-3, 5, -4>, color rgb <1, 1, 1> }
background { color rgb <0.2, 0.3, 0.5> }
plane { y, 0 pigment { checker color rgb <0.9, 0.9, 0.9>, color rgb <0.2, 0.2, 0.2> } }
sphere { <0, 0.8, 0>, 0.8 pigment { color rgb <0.8, 0.3, 0.2> } finish { phong 0.5 } }
)";

} // namespace

TEST(BenchStats, QuantilesInterpolateBetweenOrderStatistics) {
    EXPECT_DOUBLE_EQ(median({5, 1, 3}), 3);
    EXPECT_DOUBLE_EQ(median({4, 1, 3, 2}), 2.5);
    // Type 7: h = (n-1) q = 0.75 for n = 4, q = 0.25 -> 1 + 0.75 (2 - 1).
    EXPECT_DOUBLE_EQ(quantile({4, 1, 3, 2}, 0.25), 1.75);
    EXPECT_DOUBLE_EQ(quantile({4, 1, 3, 2}, 1.0), 4);
    EXPECT_TRUE(std::isnan(median({})));
}

TEST(BenchStats, LogLogSlopeRecoversAPowerLaw) {
    // y = 3 x^-1.5 exactly, plus points the fit must ignore (non-positive).
    std::vector<double> x = {1, 4, 16, 64, 256, 0, 8}, y;
    for (double v : x) y.push_back(v > 0 ? 3 * std::pow(v, -1.5) : 1);
    y.back() = -1;
    const SlopeFit fit = fitLogLogSlope(x, y);
    EXPECT_EQ(fit.points, 5);
    EXPECT_NEAR(fit.slope, -1.5, 1e-12);
    EXPECT_NEAR(fit.intercept, std::log10(3.0), 1e-12);
    EXPECT_NEAR(fit.r2, 1, 1e-12);
}

TEST(BenchStats, LogLogSlopeOfNoisyDataIsTheLeastSquaresLine) {
    // log10 x = 0, 1, 2 and log10 y = 0, -1.2, -1.8: slope = Sxy / Sxx = -1.8 / 2 = -0.9.
    const SlopeFit fit = fitLogLogSlope({1, 10, 100}, {1, std::pow(10.0, -1.2), std::pow(10.0, -1.8)});
    EXPECT_NEAR(fit.slope, -0.9, 1e-12);
    EXPECT_NEAR(fit.intercept, -0.1, 1e-12); // mean log y - slope * mean log x = -1 + 0.9
    EXPECT_LT(fit.r2, 1);
}

TEST(BenchStats, ParetoFrontKeepsOnlyUndominatedPoints) {
    const std::vector<CostError> points = {
        {1, 10}, // cheapest: on the front
        {2, 5},  // on the front
        {3, 6},  // dominated by (2, 5)
        {4, 1},  // on the front
        {2, 5.5}, // dominated by (2, 5)
        {5, 1},  // dominated by (4, 1): same error, more cost
        {0, 0.1}, // not positive: ignored
        {0.5, 20}, // cheaper than everything: on the front
    };
    EXPECT_EQ(paretoFront(points), (std::vector<size_t>{7, 0, 1, 3}));
    EXPECT_TRUE(paretoFront({}).empty());
}

TEST(BenchStats, LogLogInterpolationIsExactForPowerLawsAndNeverExtrapolates) {
    std::vector<CurvePoint> curve;
    for (double x : {1.0, 10.0, 100.0}) curve.push_back({x, 2 / x});
    EXPECT_NEAR(*interpolateLogLog(curve, 3.0), 2 / 3.0, 1e-12);
    EXPECT_NEAR(*interpolateLogLog(curve, 100.0), 0.02, 1e-12);
    EXPECT_FALSE(interpolateLogLog(curve, 0.5));
    EXPECT_FALSE(interpolateLogLog(curve, 101));
}

TEST(BenchCsv, HasTheDocumentedColumnsAndOneLinePerRow) {
    BenchRow a;
    a.scene = "a.drt", a.method = "sobol", a.sampler = "sobol", a.filter = "box", a.spp = 4, a.relMse = 0.01;
    BenchRow b = a;
    b.method = "independent", b.spp = 16;
    const std::vector<std::string> lines = splitLines(formatResultsCsv({a, b}));
    ASSERT_EQ(lines.size(), 3u);
    const std::vector<std::string> header = splitCommas(lines[0]);
    for (const char* column :
         {"scene", "method", "sampler", "spp", "seed", "threads", "render_seconds", "parse_seconds",
          "build_seconds", "rays", "mrays_per_second", "mse", "relmse", "robust_relmse", "mean_signed_error",
          "bias_z", "nonfinite"})
        EXPECT_NE(std::find(header.begin(), header.end(), column), header.end()) << column;
    for (size_t i = 1; i < lines.size(); ++i) EXPECT_EQ(splitCommas(lines[i]).size(), header.size());
    EXPECT_EQ(splitCommas(lines[2])[1], "independent");
}

TEST(BenchSppList, ParsesSortsAndRejects) {
    EXPECT_EQ(parseSppList("16,1,4,4"), (std::vector<int>{1, 4, 16}));
    EXPECT_THROW(parseSppList("1,x"), std::invalid_argument);
    EXPECT_THROW(parseSppList("0"), std::invalid_argument);
    EXPECT_THROW(parseSppList(""), std::invalid_argument);
}

TEST(BenchChart, WritesValidSvgAndPng) {
    const std::string dir = test::tempDir();
    Chart chart;
    chart.title = "Error against render time";
    chart.xLabel = "seconds";
    chart.yLabel = "relMSE";
    chart.guide = true;
    chart.guideLabel = "slope -1";
    chart.series.push_back({"a", {{0.01, 0.1, 0.08, 0.12}, {0.1, 0.01, 0.009, 0.011}}});
    chart.series.push_back({"b", {{0.02, 0.2, 0, 0}, {0.2, 0.05, 0, 0}}});
    chart.paretoFront = {{0.01, 0.1}, {0.1, 0.01}};
    const std::string base = (fs::path(dir) / "chart").string();
    ASSERT_EQ(writeChart(chart, base), "");

    const std::string svg = test::readFile(base + ".svg");
    EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
    EXPECT_NE(svg.find("<svg"), std::string::npos);
    EXPECT_NE(svg.find("</svg>"), std::string::npos);

    Image png;
    ASSERT_EQ(readImage(base + ".png", png), "");
    EXPECT_EQ(png.width, chart.width);
    EXPECT_EQ(png.height, chart.height);
    // Mostly white background, with dark ink (axes, text) and coloured series.
    int dark = 0, white = 0, coloured = 0;
    for (int y = 0; y < png.height; ++y)
        for (int x = 0; x < png.width; ++x) {
            const float r = png.at(x, y, 0), g = png.at(x, y, 1), b = png.at(x, y, 2);
            dark += r + g + b < 0.3f;
            white += r + g + b > 2.95f;
            coloured += std::max({r, g, b}) - std::min({r, g, b}) > 0.4f;
        }
    EXPECT_GT(white, png.width * png.height / 2);
    EXPECT_GT(dark, 500);
    EXPECT_GT(coloured, 100);
    EXPECT_FALSE(fs::exists(base + ".svg.tmp"));
    EXPECT_FALSE(fs::exists(base + ".png.tmp"));
}

TEST(BenchChart, UnconnectedSeriesDrawOnlyMarkersAndLevelsDrawALine) {
    const std::string dir = test::tempDir();
    const auto colouredPixels = [&](bool connected, bool level) {
        Chart chart;
        chart.series.push_back({"a", {{0.01, 0.1, 0, 0}, {0.1, 0.01, 0, 0}, {1, 0.001, 0, 0}}, connected});
        if (level) chart.levels.push_back({0.003, "target"});
        const std::string base = (fs::path(dir) / "chart").string();
        EXPECT_EQ(writeChart(chart, base), "");
        Image png;
        EXPECT_EQ(readImage(base + ".png", png), "");
        int coloured = 0, grey = 0;
        for (int y = 0; y < png.height; ++y)
            for (int x = 0; x < png.width; ++x) {
                const float r = png.at(x, y, 0), g = png.at(x, y, 1), b = png.at(x, y, 2);
                coloured += std::max({r, g, b}) - std::min({r, g, b}) > 0.4f;
                grey += std::max({r, g, b}) - std::min({r, g, b}) < 0.02f && r > 0.05f && r < 0.3f;
            }
        return std::pair{coloured, grey};
    };
    const auto [line, lineGrey] = colouredPixels(true, false);
    const auto [markers, markersGrey] = colouredPixels(false, false);
    EXPECT_GT(markers, 20);           // the markers are drawn...
    EXPECT_GT(line, markers + 200);   // ...but only the connected series has its line
    const auto [withLevel, levelGrey] = colouredPixels(false, true);
    EXPECT_EQ(withLevel, markers);
    EXPECT_GT(levelGrey, markersGrey + 50); // the dotted level line (and its label)
}

TEST(BenchChart, UnwritableFolderIsReported) {
    Chart chart;
    chart.series.push_back({"a", {{1, 1, 0, 0}, {2, 0.5, 0, 0}}});
    EXPECT_NE(writeChart(chart, "/nonexistent-folder/chart"), "");
}

TEST(BenchRun, QuickBenchOnATinySceneConverges) {
    const std::string dir = test::tempDir();
    const std::string scene = test::writeFile((fs::path(dir) / "tiny.drt").string(), kTinyScene);
    BenchOptions options;
    options.scenePath = scene;
    options.outputDir = (fs::path(dir) / "out").string();
    options.quick = true;
    options.width = 32;
    options.height = 24;
    options.methods = {"independent", "sobol"};
    std::ostringstream log;
    const BenchReport report = runBench(options, log);

    // --quick: spp 1, 4, 16 and one seed, so 2 methods x 3 rows.
    ASSERT_EQ(report.rows.size(), 6u);
    const std::vector<std::string> lines = splitLines(test::readFile(options.outputDir + "/results.csv"));
    EXPECT_EQ(lines.size(), 7u);
    for (const char* file : {"error-vs-time.svg", "error-vs-time.png", "error-vs-spp.svg", "error-vs-spp.png",
                             "summary.md", "reference.exr", "reference.variance.exr"})
        EXPECT_TRUE(fs::exists(fs::path(options.outputDir) / file)) << file;

    std::map<int, double> sobol;
    for (const BenchRow& row : report.rows) {
        EXPECT_EQ(row.nonFinite, 0);
        EXPECT_GT(row.rays, 0u);
        EXPECT_GE(row.renderSeconds, 0);
        if (row.method == "sobol") sobol[row.spp] = row.relMse;
    }
    ASSERT_EQ(sobol.size(), 3u);
    EXPECT_LT(sobol[4], sobol[1]);
    EXPECT_LT(sobol[16], sobol[4]);
    EXPECT_GT(sobol[16], 0);
    EXPECT_NE(log.str().find("[6/6]"), std::string::npos) << log.str();

    const std::string summary = test::readFile(options.outputDir + "/summary.md");
    for (const char* heading : {"Equal time", "Equal quality", "efficiency", "bias z"})
        EXPECT_NE(summary.find(heading), std::string::npos) << heading;

    // A second run reuses the reference it made.
    std::ostringstream again;
    options.methods = {"sobol"};
    runBench(options, again);
    EXPECT_NE(again.str().find("reusing reference"), std::string::npos) << again.str();
    EXPECT_EQ(again.str().find("rendering reference"), std::string::npos);
}

// A bench of `scene` into dir/out at one sample count and seed.
BenchOptions smallBench(const std::string& dir, const std::string& scene, int width, int height, int spp,
                        int referenceSpp, std::vector<std::string> methods) {
    BenchOptions options;
    options.scenePath = scene;
    options.outputDir = (fs::path(dir) / "out").string();
    options.width = width, options.height = height, options.spp = {spp}, options.seeds = 1;
    options.referenceSpp = referenceSpp;
    options.methods = std::move(methods);
    return options;
}

TEST(BenchRun, SkipsMethodsThatDoNotApplyAndRejectsBadInput) {
    const std::string dir = test::tempDir();
    const std::string scene = test::writeFile((fs::path(dir) / "tiny.drt").string(), kTinyScene);
    BenchOptions options = smallBench(dir, scene, 8, 6, 1, 4, {"sobol", "light-grid", "light-split-4"});
    std::ostringstream log;
    const BenchReport report = runBench(options, log);
    ASSERT_EQ(report.skipped.size(), 2u);
    EXPECT_EQ(report.skipped[0].name, "light-grid");
    EXPECT_EQ(report.skipped[1].name, "light-split-4");
    EXPECT_EQ(report.methods, std::vector<std::string>{"sobol"});

    options.methods = {"no-such-method"};
    try {
        runBench(options, log);
        FAIL() << "an unknown method must be rejected";
    } catch (const BenchError& e) {
        EXPECT_FALSE(e.ioError);
        EXPECT_NE(std::string(e.what()).find("no-such-method"), std::string::npos);
    }
    options.methods = {};
    options.scenePath = dir + "/missing.drt";
    try {
        runBench(options, log);
        FAIL() << "a missing scene must be an I/O error";
    } catch (const BenchError& e) {
        EXPECT_TRUE(e.ioError);
    }
}

TEST(BenchRun, SplitLightSamplesRunOnAreaLightsAndAgreeWithTheReference) {
    // light-split-4 renders the scene as written with 4 points on each area
    // light per camera sample (SkipsMethods... above: only with an area light); it traces
    // more rays than sobol at the same spp (4 shadow rays a lit hit, not 1),
    // and estimates the same image (no bias flag: |z| < 4).
    const std::string dir = test::tempDir();
    const std::string scene = test::writeFile(
        (fs::path(dir) / "soft.drt").string(),
        std::string(kTinyScene) + "light_source { <2, 4, -2>, color rgb 0.6 area_light <1, 0, 0>, <0, 0, 1>, 3, 3 }\n");
    std::ostringstream log;
    const BenchReport report = runBench(smallBench(dir, scene, 16, 12, 4, 64, {"sobol", "light-split-4"}), log);
    ASSERT_EQ(report.methods, (std::vector<std::string>{"sobol", "light-split-4"})) << log.str();
    ASSERT_EQ(report.rows.size(), 2u);
    const BenchRow& one = report.rows[0].method == "sobol" ? report.rows[0] : report.rows[1];
    const BenchRow& split = report.rows[0].method == "sobol" ? report.rows[1] : report.rows[0];
    EXPECT_GT(split.rays, one.rays);
    EXPECT_LT(std::fabs(split.biasZ), 4.0);
}

// cairo is the chart module's (bench/chart_module.h), not drt's: drt starts
// without loading it, and drt bench without the module stops with a clear I/O
// error naming where it looked.
TEST(BenchCommand, ChartsComeFromAModuleThatDrtDoesNotLink) {
    struct Environment { // drt children inherit it; this test process loads no module meanwhile
        const char* name;
        Environment(const char* n, const std::string& value) : name(n) { setenv(n, value.c_str(), 1); }
        ~Environment() { unsetenv(name); }
    };
    const std::string libraries = test::librariesDrtLoads("--version");
    EXPECT_NE(libraries.find("libembree3"), std::string::npos) << "the listing works";
    EXPECT_EQ(libraries.find("libcairo"), std::string::npos) << libraries;
    const std::string dir = test::tempDir();
    const Environment missing("DRT_CHARTS_MODULE", dir + "/no-such-module.so");
    const test::CommandResult bench =
        test::runDrt("bench " + test::sourcePath("examples/minimal.drt") + " -o " + dir + "/bench --spp 1 --seeds 1 " +
                     "--methods sobol --width 8 --reference-spp 2 --threads 1");
    EXPECT_EQ(bench.exitCode, cli::kIoError) << bench.err;
    EXPECT_NE(bench.err.find("cannot load drt's chart module libdrt_charts.so"), std::string::npos) << bench.err;
    EXPECT_NE(bench.err.find("no-such-module.so: no such file"), std::string::npos) << bench.err;
    EXPECT_EQ(bench.err.find("spp seed"), std::string::npos) << "stopped before rendering: " << bench.err;
}

TEST(BenchCommand, BadSampleListIsAUsageErrorAndAMissingSceneAnIoError) {
    cli::BenchCommand command;
    command.options.scenePath = test::sourcePath("examples/minimal.drt");
    command.options.outputDir = test::tempDir();
    command.sppList = "1,x";
    std::ostringstream out, err;
    EXPECT_EQ(cli::runBenchCommand(command, out, err), cli::kUsageError);
    EXPECT_NE(err.str().find("--spp"), std::string::npos);

    const test::CommandResult missing = test::runDrt("bench /nonexistent/scene.drt -o " + test::tempDir());
    EXPECT_EQ(missing.exitCode, cli::kIoError) << missing.err;
    EXPECT_NE(missing.err.find("drt bench"), std::string::npos);
}
