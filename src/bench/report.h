// From bench rows to what a reader sees: per-method curves (medians and
// quartiles over seeds), the two charts and summary.md.
#pragma once

#include "bench/bench.h"
#include "bench/stats.h"

#include <string>
#include <vector>

namespace drt::bench {

// One sample count of one method, over its seeds.
struct CurveStep {
    int spp = 0;
    double meanSpp = 0;             // median samples per pixel taken
    double seconds = 0;             // median build + render seconds
    double relMse = 0;              // median
    double relMseQ1 = 0, relMseQ3 = 0;
    double biasZ = 0;               // seeds combined: sum z / sqrt(seeds)
    double efficiency = 0;          // median of 1 / (relMSE x seconds)
    int64_t nonFinite = 0;          // summed over seeds
};

struct MethodCurve {
    std::string method;
    std::vector<CurveStep> steps; // by increasing spp
    SlopeFit sppFit;              // relMSE against mean samples per pixel
};

std::vector<MethodCurve> methodCurves(const BenchReport& report);

// error-vs-time.{svg,png} and error-vs-spp.{svg,png} in `dir`. Returns "" or the problem.
std::string writeCharts(const BenchReport& report, const std::string& dir);

// summary.md: settings, per-method table (relMSE, time, efficiency, slope,
// bias flag), equal-time and equal-quality tables, skipped methods.
std::string formatSummary(const BenchReport& report);

} // namespace drt::bench
