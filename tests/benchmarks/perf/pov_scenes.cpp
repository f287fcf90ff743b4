#include "pov_scenes.h"

#include "bench/stats.h"

#include <algorithm>
#include <filesystem>
#include <fmt/format.h>
#include <map>
#include <ostream>
#include <sstream>

namespace fs = std::filesystem;

namespace drt::perf {

namespace {

constexpr const char* kBenchmarkScene = "advanced/benchmark/benchmark.pov";

struct SceneTimes {
    std::string scene;
    std::map<std::string, std::vector<double>> wall, cpu; // by program
};

std::vector<std::string> allScenes(const std::string& root) {
    std::vector<std::string> paths;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(root, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
        if (it->is_regular_file() && it->path().extension() == ".pov")
            paths.push_back(fs::relative(it->path(), root).string());
    std::sort(paths.begin(), paths.end());
    return paths;
}

std::string fmtSeconds(const std::vector<double>& values) {
    return values.empty() ? "failed" : fmt::format("{:.2f}", bench::median(values));
}

} // namespace

uint64_t fnv1a64(const std::string& text) {
    uint64_t hash = 0xcbf29ce484222325ull;
    for (unsigned char c : text)
        hash = (hash ^ c) * 0x100000001b3ull;
    return hash;
}

std::vector<std::string> orderScenes(std::vector<std::string> paths) {
    std::sort(paths.begin(), paths.end(), [](const std::string& a, const std::string& b) {
        const bool benchA = a == kBenchmarkScene, benchB = b == kBenchmarkScene;
        if (benchA != benchB)
            return benchA;
        const uint64_t ha = fnv1a64(a), hb = fnv1a64(b);
        return ha != hb ? ha < hb : a < b;
    });
    return paths;
}

int runPovScenes(const PovScenesOptions& o, std::ostream& log) {
    if (povrayVersion().empty()) {
        log << "pov-scenes: POV-Ray is not installed (apt-get install povray povray-examples "
               "povray-includes)\n";
        return 3;
    }
    const fs::path out = fs::absolute(o.outputDir);
    std::error_code ec;
    fs::create_directories(out / "images", ec);
    if (ec) {
        log << fmt::format("pov-scenes: cannot create '{}': {}\n", out.string(), ec.message());
        return 3;
    }
    std::vector<std::string> candidates;
    const bool pinned = !o.scenesFile.empty();
    if (pinned) {
        std::istringstream lines(readTextFile(o.scenesFile));
        for (std::string line; std::getline(lines, line);)
            if (!line.empty() && line[0] != '#')
                candidates.push_back(line);
        if (candidates.empty()) {
            log << fmt::format("pov-scenes: no scenes in '{}'\n", o.scenesFile);
            return 3;
        }
    } else {
        for (const std::string& scene : orderScenes(allScenes(o.povExamples))) {
            const fs::path path = fs::path(o.povExamples) / scene;
            const bench::ProcessRun check = bench::runProcess(
                {o.drt.front().path, "check", path.filename().string()}, path.parent_path().string(), {}, 60);
            if (check.succeeded())
                candidates.push_back(scene);
        }
        log << fmt::format("pov-scenes: drt {} accepts {} scenes\n", o.drt.front().label, candidates.size());
    }

    std::vector<std::string> programs = {"POV-Ray"};
    for (const DrtBinary& drt : o.drt)
        programs.push_back("drt " + drt.label);
    const int repetitions = o.repetitions > 0 ? o.repetitions : 1;
    std::vector<SceneTimes> done;
    std::vector<std::pair<std::string, std::string>> skipped;
    Csv csv;
    csv.header = {"scene",        "program",     "repetition",  "exit_code",
                  "wall_seconds", "cpu_seconds", "peak_rss_mib"};

    // One render of `scene` by `program`; false if it failed.
    const auto render = [&](const std::string& scene, size_t program, int rep, SceneTimes& times,
                            std::string& why) {
        const fs::path path = fs::path(o.povExamples) / scene;
        const std::string stem = fmt::format("{}-{}", fs::path(scene).stem().string(), program);
        std::vector<std::string> argv;
        if (program == 0) {
            argv = {"povray",
                    "+I" + path.filename().string(),
                    "+O" + (out / "images" / (stem + ".png")).string(),
                    fmt::format("+W{}", o.width),
                    fmt::format("+H{}", o.height),
                    "-D",
                    "+A0.3",
                    fmt::format("+WT{}", o.threads)};
        } else {
            argv = {o.drt[program - 1].path,
                    "render",
                    path.filename().string(),
                    "-o",
                    (out / "images" / (stem + ".png")).string(),
                    "--width",
                    std::to_string(o.width),
                    "--height",
                    std::to_string(o.height),
                    "--spp",
                    std::to_string(o.spp),
                    "--threads",
                    std::to_string(o.threads),
                    "--quiet"};
        }
        const bench::ProcessRun run =
            bench::runProcess(argv, path.parent_path().string(), {}, o.timeoutSeconds);
        csv.rows.push_back({scene, programs[program], std::to_string(rep), std::to_string(run.exitCode),
                            fmt::format("{:.3f}", run.wallSeconds), fmt::format("{:.3f}", run.cpuSeconds()),
                            fmt::format("{:.1f}", run.peakRssMiB)});
        if (!run.succeeded()) {
            why = run.timedOut ? fmt::format("{} ran over {:.0f} s", programs[program], o.timeoutSeconds)
                               : fmt::format("{} failed (exit {})", programs[program], run.exitCode);
            return false;
        }
        times.wall[programs[program]].push_back(run.wallSeconds);
        times.cpu[programs[program]].push_back(run.cpuSeconds());
        return true;
    };

    for (const std::string& scene : candidates) {
        if (!pinned && int(done.size()) >= o.count)
            break;
        SceneTimes times;
        times.scene = scene;
        std::string why;
        bool ok = true;
        for (int rep = 1; rep <= repetitions && ok; ++rep)
            for (size_t p = 0; p < programs.size() && ok; ++p)
                ok = render(scene, p, rep, times, why);
        if (!ok) {
            skipped.emplace_back(scene, why);
            log << fmt::format("pov-scenes: {} skipped: {}\n", scene, why);
            continue;
        }
        std::string line = fmt::format("pov-scenes: {:>2}. {:<44}", done.size() + 1, scene);
        for (const std::string& p : programs)
            line += fmt::format(" {} {} s", p, fmtSeconds(times.wall[p]));
        log << line << "\n";
        done.push_back(std::move(times));
    }

    std::string md = fmt::format(
        "# POV-Ray's sample scenes, as a user runs them\n\n- Machine: {}.\n- {}x{}, {} threads; POV-Ray "
        "`+A0.3`, "
        "drt {} samples per pixel; PNG output; wall time of the whole process{}.\n- Scenes: {}.\n\n",
        machineDescription(), o.width, o.height, o.threads, o.spp,
        repetitions > 1 ? fmt::format(", median of {} runs", repetitions) : "",
        pinned ? fmt::format("the list in `{}`", o.scenesFile)
               : fmt::format("the first {} that render in every program, in the order of the rule in "
                             "docs/performance.md (list in scenes.txt)",
                             o.count));
    std::map<std::string, double> totalWall, totalCpu;
    std::map<std::string, int> povFaster;
    std::string table = "| scene |";
    for (const std::string& p : programs)
        table += fmt::format(" {} s |", p);
    table += "\n|---|";
    for (size_t i = 0; i < programs.size(); ++i)
        table += "---|";
    table += "\n";
    std::string list;
    for (const SceneTimes& t : done) {
        list += t.scene + "\n";
        table += "| " + t.scene + " |";
        const double pov = bench::median(t.wall.at("POV-Ray"));
        for (const std::string& p : programs) {
            const double wall = bench::median(t.wall.at(p));
            totalWall[p] += wall;
            totalCpu[p] += bench::median(t.cpu.at(p));
            if (p != "POV-Ray" && pov < wall)
                ++povFaster[p];
            table += fmt::format(" {:.2f} |", wall);
        }
        table += "\n";
    }
    md += fmt::format("| program | total wall s | total CPU s | scenes POV-Ray renders faster (of {}) |\n"
                      "|---|---|---|---|\n",
                      done.size());
    for (const std::string& p : programs)
        md += fmt::format("| {} | {:.1f} | {:.1f} | {} |\n", p, totalWall[p], totalCpu[p],
                          p == "POV-Ray" ? "-" : std::to_string(povFaster[p]));
    md += "\n" + table;
    if (!skipped.empty()) {
        md += "\nSkipped (a program failed on them):\n\n";
        for (const auto& [scene, why] : skipped)
            md += fmt::format("- {}: {}\n", scene, why);
    }
    writeTextFile((out / "scenes.txt").string(), list);
    writeTextFile((out / "pov-scenes.csv").string(), csv.text());
    writeTextFile((out / "pov-scenes.md").string(), md);
    log << md;
    return 0;
}

} // namespace drt::perf
