#include "bench/report.h"

#include "bench/chart.h"
#include "compare/compare.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <limits>
#include <map>

namespace drt::bench {

namespace {

// Family-wise false-alarm rate of the per-method bias flags.
constexpr double kBiasAlpha = 0.01;

double positiveOrNan(double v) { return v > 0 && std::isfinite(v) ? v : std::numeric_limits<double>::quiet_NaN(); }

// Two significant digits, for table headings.
double roundTwoDigits(double v) {
    if (!(v > 0)) return v;
    const double scale = std::pow(10.0, std::floor(std::log10(v)) - 1);
    return std::round(v / scale) * scale;
}

// Three values spread over [lo, hi] in log space (the overlap of every
// method's range, so that each column compares as many methods as possible).
std::vector<double> spreadLog(double lo, double hi) {
    if (!(lo > 0) || !(hi > 0)) return {};
    std::vector<double> values;
    for (double f : {0.15, 0.5, 0.85}) values.push_back(roundTwoDigits(std::exp((1 - f) * std::log(lo) + f * std::log(hi))));
    values.erase(std::unique(values.begin(), values.end()), values.end());
    return values;
}

// The common range of a quantity over methods: [largest minimum, smallest
// maximum], or every method's union if they do not overlap.
template <typename Get>
std::pair<double, double> commonRange(const std::vector<MethodCurve>& curves, Get get) {
    double maxOfMins = 0, minOfMaxes = std::numeric_limits<double>::infinity();
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    for (const MethodCurve& c : curves) {
        double cmin = std::numeric_limits<double>::infinity(), cmax = 0;
        for (const CurveStep& s : c.steps)
            if (double v = get(s); v > 0 && std::isfinite(v)) cmin = std::min(cmin, v), cmax = std::max(cmax, v);
        if (cmax <= 0) continue;
        maxOfMins = std::max(maxOfMins, cmin), minOfMaxes = std::min(minOfMaxes, cmax);
        lo = std::min(lo, cmin), hi = std::max(hi, cmax);
    }
    if (maxOfMins > 0 && maxOfMins < minOfMaxes) return {maxOfMins, minOfMaxes};
    return {lo, hi};
}

std::string formatSeconds(double s) {
    if (!(s > 0)) return "-";
    return s < 1 ? fmt::format("{:.3g} ms", s * 1e3) : fmt::format("{:.3g} s", s);
}

std::string formatError(double e) { return e > 0 && std::isfinite(e) ? fmt::format("{:.3g}", e) : "-"; }

double biasThreshold(size_t methods) {
    return twoSidedNormalQuantile(sidakAlpha(kBiasAlpha, int64_t(std::max<size_t>(1, methods))));
}

std::string subtitle(const BenchReport& report) {
    return fmt::format("{}, {}x{}, median of {} seed{} (bars: interquartile range), {} thread{}", report.sceneName,
                       report.width, report.height, report.seeds, report.seeds == 1 ? "" : "s", report.threads,
                       report.threads == 1 ? "" : "s");
}

} // namespace

std::vector<MethodCurve> methodCurves(const BenchReport& report) {
    std::vector<MethodCurve> curves;
    for (const std::string& method : report.methods) {
        MethodCurve curve;
        curve.method = method;
        std::map<int, std::vector<const BenchRow*>> bySpp;
        for (const BenchRow& row : report.rows)
            if (row.method == method) bySpp[row.spp].push_back(&row);
        std::vector<double> fitX, fitY;
        for (const auto& [spp, rows] : bySpp) {
            std::vector<double> meanSpp, seconds, relMse, efficiency;
            CurveStep step;
            step.spp = spp;
            double zSum = 0;
            for (const BenchRow* r : rows) {
                meanSpp.push_back(r->meanSpp);
                seconds.push_back(r->seconds());
                relMse.push_back(r->relMse);
                efficiency.push_back(r->relMse > 0 && r->seconds() > 0 ? 1 / (r->relMse * r->seconds()) : 0);
                zSum += r->biasZ;
                step.nonFinite += r->nonFinite;
            }
            step.meanSpp = median(meanSpp);
            step.seconds = median(seconds);
            step.relMse = median(relMse);
            step.relMseQ1 = quantile(relMse, 0.25);
            step.relMseQ3 = quantile(relMse, 0.75);
            step.efficiency = median(efficiency);
            // Independent seeds: the sum of K N(0,1) z-scores over sqrt(K) is N(0,1).
            step.biasZ = zSum / std::sqrt(double(rows.size()));
            curve.steps.push_back(step);
            fitX.push_back(step.meanSpp);
            fitY.push_back(step.relMse);
        }
        curve.sppFit = fitLogLogSlope(fitX, fitY);
        curves.push_back(std::move(curve));
    }
    return curves;
}

std::string writeCharts(const BenchReport& report, const std::string& dir) {
    const std::vector<MethodCurve> curves = methodCurves(report);

    Chart time;
    time.title = "Error against render time";
    time.subtitle = subtitle(report);
    time.xLabel = "seconds (BVH build + render)";
    time.yLabel = "relMSE";
    time.guide = true;
    time.guideSlope = -1;
    time.guideLabel = "slope -1";
    std::vector<CostError> all;
    std::vector<ChartPoint> allPoints;
    for (const MethodCurve& c : curves) {
        ChartSeries series{c.method, {}};
        for (const CurveStep& s : c.steps) {
            const ChartPoint p{s.seconds, positiveOrNan(s.relMse), s.relMseQ1, s.relMseQ3};
            series.points.push_back(p);
            all.push_back({p.x, p.y});
            allPoints.push_back(p);
        }
        time.series.push_back(std::move(series));
    }
    for (size_t i : paretoFront(all)) time.paretoFront.push_back(allPoints[i]);

    Chart spp;
    spp.title = "Error against samples per pixel";
    spp.subtitle = subtitle(report);
    spp.xLabel = "samples per pixel (mean taken)";
    spp.yLabel = "relMSE";
    spp.guide = true;
    spp.guideSlope = -1;
    spp.guideLabel = "slope -1";
    for (const MethodCurve& c : curves) {
        ChartSeries series{c.sppFit.points >= 2 ? fmt::format("{} (slope {:.2f})", c.method, c.sppFit.slope)
                                                : c.method,
                           {}};
        for (const CurveStep& s : c.steps)
            series.points.push_back({s.meanSpp, positiveOrNan(s.relMse), s.relMseQ1, s.relMseQ3});
        spp.series.push_back(std::move(series));
    }

    const std::filesystem::path base(dir);
    if (std::string problem = writeChart(time, (base / "error-vs-time").string()); !problem.empty()) return problem;
    return writeChart(spp, (base / "error-vs-spp").string());
}

std::string formatSummary(const BenchReport& report) {
    const std::vector<MethodCurve> curves = methodCurves(report);
    const double threshold = biasThreshold(curves.size());
    // The table columns are placed where the unbiased methods overlap (a
    // biased method's error floor would otherwise pull the targets up).
    std::vector<MethodCurve> unbiased;
    for (const MethodCurve& c : curves)
        if (!c.steps.empty() && !(std::abs(c.steps.back().biasZ) > threshold)) unbiased.push_back(c);
    const std::vector<MethodCurve>& placing = unbiased.empty() ? curves : unbiased;
    std::string out = fmt::format("# Bench: {}\n\n", report.sceneName);
    std::string spps;
    for (int s : report.spp) spps += (spps.empty() ? "" : ", ") + std::to_string(s);
    out += fmt::format("- Image {}x{}, samples per pixel {}, {} seed{} each, {} thread{}.\n", report.width,
                       report.height, spps, report.seeds, report.seeds == 1 ? "" : "s", report.threads,
                       report.threads == 1 ? "" : "s");
    out += fmt::format("- Parse: {} (once). Time below is BVH build + render, the median over seeds.\n",
                       formatSeconds(report.parseSeconds));
    for (const std::string& note : report.referenceNotes) out += fmt::format("- Reference for {}\n", note);
    out += "- relMSE = mean (x - r)^2 / (r^2 + 0.01) over pixels and RGB, minus the reference's own noise.\n\n";

    out += "## Methods at the largest sample count\n\n";
    out += fmt::format("Efficiency is 1 / (relMSE x seconds): higher is better, constant along an unbiased "
                       "method's curve once it converges. Slope: least-squares fit of log relMSE against log "
                       "samples per pixel (-1: independent samples; -2: smooth and stratified). Bias z: global "
                       "z-score of the mean error at the largest count, seeds combined; flagged when |z| > {:.2f} "
                       "(false-alarm rate {} over all methods, Sidak).\n\n",
                       threshold, kBiasAlpha);
    out += "| method | spp | mean spp | seconds | relMSE | efficiency | slope | bias z | bias | NaN/Inf |\n";
    out += "|---|---:|---:|---:|---:|---:|---:|---:|---|---:|\n";
    for (const MethodCurve& c : curves) {
        if (c.steps.empty()) continue;
        const CurveStep& s = c.steps.back();
        const bool hasZ = std::isfinite(s.biasZ);
        out += fmt::format("| {} | {} | {:.1f} | {} | {} | {:.4g} | {} | {} | {} | {} |\n", c.method, s.spp,
                           s.meanSpp, formatSeconds(s.seconds), formatError(s.relMse), s.efficiency,
                           c.sppFit.points >= 2 ? fmt::format("{:.2f}", c.sppFit.slope) : "-",
                           hasZ ? fmt::format("{:+.2f}", s.biasZ) : "-",
                           !hasZ ? "-" : std::abs(s.biasZ) > threshold ? "**biased**" : "ok", s.nonFinite);
    }

    // Equal time: relMSE each method reaches within a time budget.
    const auto [timeLo, timeHi] = commonRange(placing, [](const CurveStep& s) { return s.seconds; });
    const std::vector<double> budgets = spreadLog(timeLo, timeHi);
    out += "\n## Equal time: relMSE within a time budget\n\nBudgets spread over the times every unbiased method "
           "covers, interpolated in log-log between measured sample counts; `-` where a method did not cover the "
           "budget. Lowest error in bold.\n\n| method |";
    for (double t : budgets) out += fmt::format(" {} |", formatSeconds(t));
    out += "\n|---|";
    for (size_t i = 0; i < budgets.size(); ++i) out += "---:|";
    out += "\n";
    {
        std::vector<std::vector<std::optional<double>>> table;
        for (const MethodCurve& c : curves) {
            std::vector<CurvePoint> curve;
            for (const CurveStep& s : c.steps) curve.push_back({s.seconds, s.relMse});
            std::vector<std::optional<double>> row;
            for (double t : budgets) row.push_back(interpolateLogLog(curve, t));
            table.push_back(row);
        }
        for (size_t m = 0; m < curves.size(); ++m) {
            out += "| " + curves[m].method + " |";
            for (size_t b = 0; b < budgets.size(); ++b) {
                double best = std::numeric_limits<double>::infinity();
                for (const auto& row : table)
                    if (row[b]) best = std::min(best, *row[b]);
                const std::optional<double>& v = table[m][b];
                out += v ? (*v == best ? fmt::format(" **{}** |", formatError(*v)) : " " + formatError(*v) + " |")
                         : " - |";
            }
            out += "\n";
        }
    }
    // Equal quality: time each method needs to reach a relMSE.
    const auto [errorLo, errorHi] = commonRange(placing, [](const CurveStep& s) { return s.relMse; });
    const std::vector<double> targets = spreadLog(errorLo, errorHi);
    out += "\n## Equal quality: time to reach a relMSE\n\nTargets spread over the errors every unbiased method "
           "reaches, interpolated in log-log; `-` where a method did not reach the target within its largest sample "
           "count. Fastest in bold.\n\n| method |";
    for (double e : targets) out += fmt::format(" relMSE {} |", formatError(e));
    out += "\n|---|";
    for (size_t i = 0; i < targets.size(); ++i) out += "---:|";
    out += "\n";
    {
        std::vector<std::vector<std::optional<double>>> table;
        for (const MethodCurve& c : curves) {
            std::vector<CurvePoint> curve;
            for (const CurveStep& s : c.steps) curve.push_back({s.relMse, s.seconds});
            std::vector<std::optional<double>> row;
            for (double e : targets) row.push_back(interpolateLogLog(curve, e));
            table.push_back(row);
        }
        for (size_t m = 0; m < curves.size(); ++m) {
            out += "| " + curves[m].method + " |";
            for (size_t t = 0; t < targets.size(); ++t) {
                double best = std::numeric_limits<double>::infinity();
                for (const auto& row : table)
                    if (row[t]) best = std::min(best, *row[t]);
                const std::optional<double>& v = table[m][t];
                out += v ? (*v == best ? fmt::format(" **{}** |", formatSeconds(*v)) : " " + formatSeconds(*v) + " |")
                         : " - |";
            }
            out += "\n";
        }
    }

    // Adaptive against fixed: the samples sobol needs for the relMSE adaptive
    // reached, over the samples adaptive took: what adaptive sampling saves.
    const auto findCurve = [&](const std::string& name) -> const MethodCurve* {
        for (const MethodCurve& c : curves)
            if (c.method == name) return &c;
        return nullptr;
    };
    if (const MethodCurve *adaptive = findCurve("adaptive"), *fixed = findCurve("sobol"); adaptive && fixed) {
        std::vector<CurvePoint> fixedSamples; // relMSE -> samples per pixel
        for (const CurveStep& s : fixed->steps) fixedSamples.push_back({s.relMse, s.meanSpp});
        out += "\n## Adaptive against fixed sampling\n\nSamples per pixel the fixed sobol method needs for the "
               "relMSE adaptive reached (log-log interpolation along its curve), over the samples adaptive took: "
               "above 1, adaptive saves samples.\n\n| budget | adaptive mean spp | relMSE | sobol spp for it | "
               "factor |\n|---:|---:|---:|---:|---:|\n";
        for (const CurveStep& s : adaptive->steps) {
            const std::optional<double> needed = interpolateLogLog(fixedSamples, s.relMse);
            out += fmt::format("| {} | {:.1f} | {} | {} | {} |\n", s.spp, s.meanSpp, formatError(s.relMse),
                               needed ? fmt::format("{:.1f}", *needed) : "-",
                               needed ? fmt::format("{:.2f}", *needed / s.meanSpp) : "-");
        }
    }

    if (!report.skipped.empty()) {
        out += "\n## Skipped methods\n\n";
        for (const SkippedMethod& s : report.skipped) out += fmt::format("- {}: {}\n", s.name, s.reason);
    }
    out += "\nCharts: `error-vs-time.svg` (Pareto front ringed) and `error-vs-spp.svg`; every render in "
           "`results.csv`.\n";
    return out;
}

} // namespace drt::bench
