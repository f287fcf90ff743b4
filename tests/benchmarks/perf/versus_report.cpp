#include "versus_report.h"

#include "bench/chart.h"
#include "bench/stats.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <map>
#include <sstream>

namespace fs = std::filesystem;

namespace drt::perf {

namespace {

double timeOf(const RunRow& row, TimeBase base) {
    switch (base) {
    case TimeBase::Wall:
        return row.process.wallSeconds;
    case TimeBase::Cpu:
        return row.process.cpuSeconds();
    case TimeBase::Reported:
        return row.reportedSeconds;
    }
    return NAN;
}

const char* baseName(TimeBase base) {
    switch (base) {
    case TimeBase::Wall:
        return "the wall time of the process";
    case TimeBase::Cpu:
        return "the CPU time of the process (user + system)";
    case TimeBase::Reported:
        return "the renderer's own report";
    }
    return "";
}

std::string targetLabel(double target) {
    return fmt::format("{:.0e}", target);
}

} // namespace

std::string loadAverage() {
    std::string text = readTextFile("/proc/loadavg");
    return text.empty() ? "?" : text.substr(0, text.find(' '));
}

std::vector<std::string> renderersOf(const SceneResult& scene) {
    std::vector<std::string> names;
    for (const RunRow& row : scene.rows)
        if (std::find(names.begin(), names.end(), row.renderer) == names.end())
            names.push_back(row.renderer);
    std::stable_partition(names.begin(), names.end(), [](const std::string& n) { return n == "POV-Ray"; });
    return names;
}

std::vector<bench::SettingPoint> settingPoints(const SceneResult& scene, const std::string& renderer,
                                               TimeBase base) {
    std::vector<std::string> order;
    std::map<std::string, std::pair<std::vector<double>, std::vector<double>>> runs;
    for (const RunRow& row : scene.rows) {
        if (row.renderer != renderer || !row.process.succeeded())
            continue;
        const double t = timeOf(row, base);
        if (!(t > 0) || !std::isfinite(row.relMse))
            continue;
        if (!runs.count(row.setting))
            order.push_back(row.setting);
        runs[row.setting].first.push_back(t);
        runs[row.setting].second.push_back(row.relMse);
    }
    std::vector<bench::SettingPoint> points;
    for (const std::string& setting : order)
        points.push_back(bench::medianPoint(setting, runs[setting].first, runs[setting].second));
    return points;
}

std::string formatVersusCsv(const VersusReport& report) {
    Csv csv;
    csv.header = {"scene",        "renderer",    "setting",      "repetition",       "exit_code",
                  "wall_seconds", "cpu_seconds", "peak_rss_mib", "reported_seconds", "relmse",
                  "relmse_raw"};
    for (const SceneResult& scene : report.scenes)
        for (const RunRow& r : scene.rows)
            csv.rows.push_back(
                {r.scene, r.renderer, r.setting, std::to_string(r.repetition),
                 std::to_string(r.process.exitCode), fmt::format("{:.4f}", r.process.wallSeconds),
                 fmt::format("{:.4f}", r.process.cpuSeconds()), fmt::format("{:.1f}", r.process.peakRssMiB),
                 fmt::format("{:.4f}", r.reportedSeconds), fmt::format("{:.6e}", r.relMse),
                 fmt::format("{:.6e}", r.relMseRaw)});
    return csv.text();
}

namespace {

// | renderer | time to each target (between which settings) | POV-Ray's time / this one's |
std::string timeTable(const SceneResult& scene, const std::vector<double>& targets, TimeBase base,
                      bool detail) {
    std::string out = "| renderer |";
    for (double t : targets)
        out += fmt::format(" time to relMSE {} |", targetLabel(t));
    for (double t : targets)
        out += fmt::format(" POV-Ray / this at {} |", targetLabel(t));
    out += "\n|---|";
    for (size_t i = 0; i < 2 * targets.size(); ++i)
        out += "---|";
    out += "\n";
    std::vector<bench::TimeToError> pov;
    for (double t : targets)
        pov.push_back(bench::timeToReach(settingPoints(scene, "POV-Ray", base), t));
    for (const std::string& renderer : renderersOf(scene)) {
        const std::vector<bench::SettingPoint> points = settingPoints(scene, renderer, base);
        out += fmt::format("| {} ({} settings) |", renderer, points.size());
        std::vector<bench::TimeToError> times;
        for (double t : targets) {
            const bench::TimeToError time = bench::timeToReach(points, t);
            times.push_back(time);
            out += fmt::format(" {}", bench::formatTime(time));
            if (detail && time.kind == bench::TimeToError::Kind::Interpolated)
                out += fmt::format(" ({} .. {})", time.above, time.below);
            out += " |";
        }
        for (size_t i = 0; i < targets.size(); ++i)
            out += fmt::format(" {} |", bench::formatRatio(bench::speedRatio(pov[i], times[i])));
        out += "\n";
    }
    return out;
}

std::string settingsTable(const SceneResult& scene) {
    std::string out =
        "| renderer | setting | median wall s | median CPU s | median relMSE | on the best curve |\n"
        "|---|---|---|---|---|---|\n";
    for (const std::string& renderer : renderersOf(scene)) {
        const std::vector<bench::SettingPoint> wall = settingPoints(scene, renderer, TimeBase::Wall);
        const std::vector<bench::SettingPoint> cpu = settingPoints(scene, renderer, TimeBase::Cpu);
        const std::vector<bench::SettingPoint> front = bench::bestCurve(wall);
        for (size_t i = 0; i < wall.size(); ++i) {
            const bool onFront = std::any_of(front.begin(), front.end(), [&](const bench::SettingPoint& p) {
                return p.setting == wall[i].setting;
            });
            out += fmt::format("| {} | {} | {:.2f} | {:.2f} | {:.2e} | {} |\n", renderer, wall[i].setting,
                               wall[i].seconds, i < cpu.size() ? cpu[i].seconds : NAN, wall[i].relMse,
                               onFront ? "yes" : "");
        }
    }
    return out;
}

bench::Chart sceneChart(const VersusReport& report, const SceneResult& scene) {
    bench::Chart chart;
    chart.title = fmt::format("{}: relMSE against wall time", scene.scene);
    chart.subtitle =
        fmt::format("{}x{}, {} threads, each renderer against its own reference; medians of {} runs",
                    report.options.width, report.options.height, report.options.threads,
                    report.options.repetitions > 0 ? report.options.repetitions : 3);
    chart.xLabel = "seconds (whole process, wall time)";
    chart.yLabel = "relMSE";
    for (const std::string& renderer : renderersOf(scene)) {
        const std::vector<bench::SettingPoint> points = settingPoints(scene, renderer, TimeBase::Wall);
        bench::ChartSeries all{
            renderer == "POV-Ray" ? "POV-Ray, every setting" : renderer, {}, renderer != "POV-Ray"};
        for (const bench::SettingPoint& p : points)
            all.points.push_back({p.seconds, p.relMse, 0, 0});
        chart.series.push_back(all);
        if (renderer == "POV-Ray") {
            bench::ChartSeries best{"POV-Ray, best curve", {}, true};
            for (const bench::SettingPoint& p : bench::bestCurve(points))
                best.points.push_back({p.seconds, p.relMse, 0, 0});
            chart.series.push_back(best);
        }
    }
    for (double t : report.options.targets)
        chart.levels.push_back({t, "relMSE " + targetLabel(t)});
    return chart;
}

} // namespace

std::string formatVersusSummary(const VersusReport& report) {
    const VersusOptions& o = report.options;
    const int repetitions = o.repetitions > 0 ? o.repetitions : 3;
    std::ostringstream md;
    md << "# drt against POV-Ray 3.7 at equal error\n\n";
    md << fmt::format("- Machine: {}; load average {} at the start, {} at the end.\n", report.machine,
                      report.loadBefore, report.loadAfter);
    md << fmt::format("- {}; drt: ", report.povray);
    for (size_t i = 0; i < o.drt.size(); ++i)
        md << (i ? ", " : "")
           << fmt::format("`{}` = {}{}", o.drt[i].label, o.drt[i].path, drtSamplingNote(o.drt[i]));
    md << fmt::format(
        ".\n- {}x{}, {} threads for both, {} runs of every setting{} (medians), renders interleaved.\n",
        o.width, o.height, o.threads, repetitions, o.quick ? ", quick settings" : "");
    md << "- Time: wall time of the whole process, parse included for both (start-up, parsing, bounding or "
          "BVH "
          "build, tracing, writing the EXR file). Error: relMSE mean((x - r)^2 / (r^2 + 0.01)) on linear "
          "values "
          "(POV-Ray writes OpenEXR: unclipped half floats), each renderer against its own converged "
          "reference.\n";
    md << "- Time to a target: on the renderer's best curve (the Pareto front of its settings), interpolated "
          "log-log between the two settings around the target. `<=`: the cheapest setting already beats the "
          "target; `not reached`: no setting gets there.\n\n";

    md << "## Summary: POV-Ray's time / drt's time at equal relMSE (wall time)\n\n| scene |";
    for (const std::string& r : renderersOf(report.scenes.empty() ? SceneResult{} : report.scenes.front()))
        if (r != "POV-Ray")
            for (double t : o.targets)
                md << fmt::format(" {} at {} |", r, targetLabel(t));
    md << "\n|---|";
    for (const std::string& r : renderersOf(report.scenes.empty() ? SceneResult{} : report.scenes.front()))
        if (r != "POV-Ray")
            for (size_t i = 0; i < o.targets.size(); ++i)
                md << "---|";
    md << "\n";
    for (const SceneResult& scene : report.scenes) {
        md << "| " << scene.scene << " |";
        const std::vector<bench::SettingPoint> pov = settingPoints(scene, "POV-Ray", TimeBase::Wall);
        for (const std::string& r : renderersOf(scene)) {
            if (r == "POV-Ray")
                continue;
            const std::vector<bench::SettingPoint> drt = settingPoints(scene, r, TimeBase::Wall);
            for (double t : o.targets)
                md << " "
                   << bench::formatRatio(
                          bench::speedRatio(bench::timeToReach(pov, t), bench::timeToReach(drt, t)))
                   << " |";
        }
        md << "\n";
    }
    md << "\n";

    for (const SceneResult& scene : report.scenes) {
        md << fmt::format("## {}\n\n", scene.scene);
        md << fmt::format("![relMSE against time]({}-error-vs-time.png)\n\n", scene.scene);
        md << timeTable(scene, o.targets, TimeBase::Wall, true) << "\n";
        for (TimeBase base : {TimeBase::Cpu, TimeBase::Reported}) {
            md << fmt::format("On {}:\n\n", baseName(base));
            md << timeTable(scene, o.targets, base, false) << "\n";
        }
        md << "References:\n\n";
        md << fmt::format(
            "- POV-Ray: {}; the same at half the budget ({}) differs from it by relMSE {:.2e}.\n",
            scene.povReferenceSetting, scene.povReferenceHalfSetting, scene.povReferenceSelfError);
        md << fmt::format("- drt: {}; its own noise, mean Var(r) / (r^2 + 0.01) = {:.2e}, is subtracted from "
                          "drt's relMSE.\n",
                          scene.drtReferenceSetting, scene.drtReferenceNoise);
        md << "- " << bench::formatAgreement(scene.agreement, "drt's reference", "POV-Ray's") << "\n\n";
        md << "<details><summary>Every setting</summary>\n\n" << settingsTable(scene) << "\n</details>\n\n";
    }
    md << "The POV-Ray time 'reported' is its Parse + Bounding + Trace Time; drt's is its load (parse and "
          "files) + BVH build + trace from `--stats` (a drt without `--stats`: build + trace from its "
          "summary "
          "line). Neither includes process start-up or writing the image.\n";
    return md.str();
}

void writeVersusReport(const VersusReport& report, const std::string& dir) {
    writeTextFile((fs::path(dir) / "results.csv").string(), formatVersusCsv(report));
    writeTextFile((fs::path(dir) / "summary.md").string(), formatVersusSummary(report));
    for (const SceneResult& scene : report.scenes) {
        const std::string base = (fs::path(dir) / (scene.scene + "-error-vs-time")).string();
        if (std::string problem = bench::writeChart(sceneChart(report, scene), base); !problem.empty())
            throw std::runtime_error(problem);
    }
}

} // namespace drt::perf
