// drt_perf's own logic (tests/benchmarks/perf): the POV-Ray scene knobs keep
// the converged image, the renderers' reports are read correctly, and the
// summary's tables come from medians and best curves. Running the instruments
// themselves takes minutes and POV-Ray: that is `drt_perf`, not a test.
#include "pov/load.h"
#include "pov_scenes.h"
#include "test_support.h"
#include "versus.h"
#include "versus_report.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace drt;
using namespace drt::perf;

namespace {

const char* kAreaScene = R"(#version 3.7;
camera { location <0, 0, -10> look_at 0 }
light_source { <0, 4, -4> color rgb 1
    area_light <8, 0, 0>, <0, 8, 0>, 3, 3
    adaptive 0 jitter }
light_source { <0, 4, -4> color rgb 1 area_light <4, 0, 0>, <0, 2, 0>, 17, 9 jitter }
sphere { 0, 1 pigment { rgb 1 } }
)";

std::optional<Scene> loadPov(const std::string& text) {
    Diagnostics diagnostics;
    std::optional<Scene> scene = loadPovSceneText(text, "edited.pov", diagnostics);
    EXPECT_TRUE(scene) << diagnostics.formatAll();
    return scene;
}

// The rectangle POV-Ray's jittered edge-to-edge grid covers along one axis:
// n / (n - 1) times the axis.
double coveredLength(const AreaLight& area, bool first) {
    const int n = first ? area.size1 : area.size2;
    return length(first ? area.axis1 : area.axis2) * n / (n - 1);
}

} // namespace

TEST(PerfSceneKnobs, AreaGridsChangeTheirCountButNotTheCoveredRectangle) {
    const std::optional<Scene> original = loadPov(kAreaScene);
    for (double factor : {0.5, 2.0}) {
        const std::string edited = scaleAreaGrids(factor)(kAreaScene);
        EXPECT_NE(edited.find("adaptive 0 jitter"), std::string::npos) << edited; // the rest is kept
        const std::optional<Scene> scene = loadPov(edited);
        ASSERT_TRUE(scene && original);
        ASSERT_EQ(scene->lights.size(), 2u);
        for (size_t i = 0; i < 2; ++i) {
            const AreaLight& before = *original->lights[i].area;
            const AreaLight& after = *scene->lights[i].area;
            for (bool first : {true, false})
                EXPECT_NEAR(coveredLength(after, first), coveredLength(before, first), 1e-6)
                    << "factor " << factor << " light " << i;
        }
        const AreaLight& big = *scene->lights[1].area;
        EXPECT_EQ(big.size1, factor == 2.0 ? 33 : 9);
        EXPECT_EQ(big.size2, factor == 2.0 ? 17 : 5);
        EXPECT_EQ(scene->lights[0].area->size1, factor == 2.0 ? 5 : 2);
    }
    EXPECT_THROW(scaleAreaGrids(2)("sphere { 0, 1 }"), std::runtime_error);
}

TEST(PerfSceneKnobs, BlurSamplesAreReplacedAndCanBeForcedExact) {
    const std::string scene = "camera { location <0, 0, -5> look_at 0 blur_samples 120 aperture 1 "
                              "focal_point <0, 0, 0> }\nsphere { 0, 1 pigment { rgb 1 } }\n";
    const std::string fewer = blurSamples(37, false)(scene);
    EXPECT_NE(fewer.find("blur_samples 37 aperture"), std::string::npos) << fewer;
    const std::string exact = blurSamples(400, true)(scene);
    EXPECT_NE(exact.find("blur_samples 400 variance 0 aperture"), std::string::npos) << exact;
    const std::optional<Scene> parsed = loadPov(exact);
    ASSERT_TRUE(parsed);
    EXPECT_THROW(blurSamples(3, false)("sphere { 0, 1 }"), std::runtime_error);
}

TEST(PerfSceneKnobs, EverySettingOfTheShippedScenesApplies) {
    for (const VersusScene& scene : versusScenes()) {
        const std::string text = test::readFile(std::string(kPovExamples) + "/" + scene.file);
        ASSERT_FALSE(text.empty()) << scene.file << ": povray-examples is a dependency (.ci/setup)";
        for (const auto* list : {&scene.povSettings, &scene.quickPovSettings})
            for (const PovSetting& setting : *list)
                EXPECT_NO_THROW(setting.edit(text)) << setting.name;
        for (const PovSetting* reference : {&scene.povReference, &scene.povReferenceHalf})
            EXPECT_NO_THROW(reference->edit(text)) << reference->name;
        EXPECT_FALSE(scene.drtSpp.empty());
        EXPECT_GE(scene.drtReferenceSpp, 1);
    }
}

TEST(PerfReports, DrtSummaryLineAndPovRayTimesAreRead) {
    DrtRender render;
    ASSERT_TRUE(parseDrtSummary(
        "drt: out.exr 320x240 at 16 spp in 1.7 s (build 25 ms, trace 1.6 s): 1.23M samples, 1.25 Mrays/s "
        "(camera 1.23M, shadow 0.69M, secondary 0.19M), 0 NaN/Inf samples; effects: AA, DOF\n",
        render));
    EXPECT_DOUBLE_EQ(render.buildSeconds, 0.025);
    EXPECT_DOUBLE_EQ(render.traceSeconds, 1.6);
    EXPECT_DOUBLE_EQ(render.mraysPerSecond, 1.25);
    EXPECT_EQ(render.shadowRays, 690000u);
    EXPECT_EQ(render.secondaryRays, 190000u);
    DrtRender minutes;
    ASSERT_TRUE(parseDrtSummary("(build 1.2 s, trace 2 min 05 s): 9M samples, 3.00 Mrays/s (camera 9.00M, "
                                "shadow 0.00M, secondary 0.00M)",
                                minutes));
    EXPECT_DOUBLE_EQ(minutes.traceSeconds, 125);
    EXPECT_FALSE(parseDrtSummary("drt: something else", minutes));

    const std::string pov = "Parser Time\n  Parse Time:       0 hours  0 minutes  0 seconds (0.017 seconds)\n"
                            "  Bounding Time:    0 hours  0 minutes  0 seconds (0.000 seconds)\n"
                            "  Trace Time:       0 hours  1 minutes  9 seconds (69.991 seconds)\n";
    EXPECT_DOUBLE_EQ(parsePovSeconds(pov, "Parse Time"), 0.017);
    EXPECT_DOUBLE_EQ(parsePovSeconds(pov, "Trace Time"), 69.991);
    EXPECT_EQ(parsePovSeconds(pov, "Photon Time"), -1);
}

TEST(PerfReports, SummaryTablesUseMediansAndTheBestCurve) {
    SceneResult scene;
    scene.scene = "toy";
    const auto row = [&](const std::string& renderer, const std::string& setting, double seconds,
                         double error) {
        RunRow r;
        r.scene = "toy", r.renderer = renderer, r.setting = setting;
        r.process.started = true, r.process.exitCode = 0, r.process.wallSeconds = seconds;
        r.process.userSeconds = seconds / 2;
        r.reportedSeconds = seconds / 4;
        r.relMse = r.relMseRaw = error;
        scene.rows.push_back(r);
    };
    // POV-Ray: error = 1e-3 / t; drt: 4x faster at every error. One outlier run each.
    for (double noise : {1.0, 1.1, 50.0}) {
        row("POV-Ray", "low", 1 * noise, 1e-3);
        row("POV-Ray", "high", 100 * noise, 1e-5);
        row("drt after", "4 spp", 0.25 * noise, 1e-3);
        row("drt after", "64 spp", 25 * noise, 1e-5);
    }
    const std::vector<bench::SettingPoint> pov = settingPoints(scene, "POV-Ray", TimeBase::Wall);
    ASSERT_EQ(pov.size(), 2u);
    EXPECT_DOUBLE_EQ(pov[0].seconds, 1.1); // the median ignores the outlier
    EXPECT_DOUBLE_EQ(settingPoints(scene, "drt after", TimeBase::Cpu)[1].seconds, 25 * 1.1 / 2);
    EXPECT_EQ(renderersOf(scene), (std::vector<std::string>{"POV-Ray", "drt after"}));

    VersusReport report;
    report.options.drt = {{"after", "/bin/true"}};
    report.scenes = {scene};
    const std::string summary = formatVersusSummary(report);
    EXPECT_NE(summary.find("| toy | 4.00 | 4.00 |"), std::string::npos) << summary;
    const std::string csv = formatVersusCsv(report);
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 12);
    EXPECT_EQ(csv.rfind("scene,renderer,setting,repetition,exit_code,wall_seconds", 0), 0u) << csv;
}

TEST(PerfSceneRule, BenchmarkFirstThenByHash) {
    // FNV-1a 64: the offset basis for "", and the published value for "a".
    EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ull);
    EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cull);
    const std::vector<std::string> ordered =
        orderScenes({"b.pov", "a.pov", "advanced/benchmark/benchmark.pov", "c.pov"});
    ASSERT_EQ(ordered.size(), 4u);
    EXPECT_EQ(ordered[0], "advanced/benchmark/benchmark.pov");
    for (size_t i = 2; i < ordered.size(); ++i)
        EXPECT_LT(fnv1a64(ordered[i - 1]), fnv1a64(ordered[i]));
    EXPECT_EQ(orderScenes(ordered), ordered); // a fixed order, whatever the input order
}

namespace drt::perf {
namespace {

TEST(PerfAdaptive, AnAdaptiveDrtRendersItsSweepStepsAsErrorTargets) {
    std::vector<DrtBinary> binaries = {{"fixed", "/bin/true"}, {"adaptive", "/bin/true"}};
    EXPECT_EQ(drtSampleArgs(binaries[0], 16), (std::vector<std::string>{"--spp", "16"}));
    markAdaptive(binaries, "adaptive=8,512,0.2");
    EXPECT_FALSE(binaries[0].adaptive);
    EXPECT_EQ(drtSampleArgs(binaries[1], 16),
              (std::vector<std::string>{"--adaptive", "--adaptive-error", "0.05", "--min-spp", "8", "--max-spp", "512"}));
    markAdaptive(binaries, "fixed"); // the defaults: 4..1024, 0.05 / sqrt(N)
    EXPECT_EQ(drtSampleArgs(binaries[0], 4),
              (std::vector<std::string>{"--adaptive", "--adaptive-error", "0.025", "--min-spp", "4", "--max-spp", "1024"}));
    EXPECT_THROW(markAdaptive(binaries, "nobody"), std::invalid_argument);
    EXPECT_THROW(markAdaptive(binaries, "fixed=8"), std::invalid_argument);
    EXPECT_THROW(markAdaptive(binaries, "fixed=16,8"), std::invalid_argument);
}

} // namespace
} // namespace drt::perf
