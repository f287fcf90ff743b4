// From the renders of the drt-against-POV-Ray benchmark to what a reader
// sees: results.csv (one row per render), one error-against-time chart per
// scene, and summary.md (times to the targets, ratios, reference checks).
#pragma once

#include "bench/agreement.h"
#include "bench/equal_error.h"
#include "bench/process.h"
#include "versus.h"

#include <string>
#include <vector>

namespace drt::perf {

struct RunRow {
    std::string scene, renderer, setting; // renderer: "POV-Ray" or "drt LABEL"
    int spp = 0;                          // drt only
    int repetition = 0;
    bench::ProcessRun process;
    double reportedSeconds = -1;       // what the renderer itself reports (see summary.md)
    bool reportedIncludesParse = true; // false for a drt without --stats (build + trace only)
    double relMse = 0;                 // against the renderer's own reference, its noise taken out (drt)
    double relMseRaw = 0;
};

struct SceneResult {
    std::string scene;
    std::string povReferenceSetting, povReferenceHalfSetting, drtReferenceSetting;
    double povReferenceSelfError = 0;    // relMSE of the half-budget reference against the reference
    double drtReferenceNoise = 0;        // mean Var(r) / (r^2 + 0.01) of drt's reference
    bench::ReferenceAgreement agreement; // drt's reference against POV-Ray's
    std::vector<RunRow> rows;
};

struct VersusReport {
    VersusOptions options;
    std::string machine, povray;
    std::string loadBefore, loadAfter;
    std::vector<SceneResult> scenes;
};

// Which time a table uses.
enum class TimeBase { Wall, Cpu, Reported };

// The median point of every setting of `renderer` in `scene`, on `base`.
std::vector<bench::SettingPoint> settingPoints(const SceneResult& scene, const std::string& renderer,
                                               TimeBase base);
std::vector<std::string> renderersOf(const SceneResult& scene); // POV-Ray first, then drt binaries in order

std::string formatVersusCsv(const VersusReport& report);
std::string formatVersusSummary(const VersusReport& report);
// Writes results.csv, summary.md and <scene>-error-vs-time.{svg,png}. Throws std::runtime_error.
void writeVersusReport(const VersusReport& report, const std::string& dir);

std::string loadAverage(); // the 1-minute load average from /proc/loadavg, "?" if unknown

} // namespace drt::perf
