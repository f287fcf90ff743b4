// drt_perf startup: what a command costs before and around its real work.
// Each program runs each command many times, interleaved; the table gives the
// medians of wall time, CPU time (user + system) and peak resident memory, and
// how many shared libraries the dynamic loader maps at start-up.
#include "startup.h"

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

// A tiny POV-Ray scene both programs render: the fixed cost of a render.
const char* kTinyPovScene = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -4> look_at <0, 0.5, 0> angle 50 right x*image_width/image_height }
light_source { <-3, 5, -4>, color rgb 1 }
background { color rgb <0.2, 0.3, 0.5> }
plane { y, 0 pigment { checker color rgb 0.9, color rgb 0.2 } }
sphere { <0, 0.6, 0>, 0.6 pigment { color rgb <0.8, 0.3, 0.2> } finish { phong 0.5 } }
)";

struct Command {
    std::string name;    // row
    std::string program; // column: "POV-Ray" or "drt LABEL"
    std::vector<std::string> argv;
    std::string workDir;
};

struct Samples {
    std::vector<double> wall, cpu, rss;
    int failures = 0;
};

// Shared libraries the loader maps for `path` (its DT_NEEDED closure, by ldd).
int sharedLibraries(const std::string& path) {
    const bench::ProcessRun run = bench::runProcess({"ldd", path});
    if (!run.succeeded())
        return -1;
    int count = 0;
    std::istringstream lines(run.output);
    for (std::string line; std::getline(lines, line);)
        count += line.find("=>") != std::string::npos;
    return count;
}

// The absolute path of a program found in PATH, "" if none.
std::string programPath(const std::string& name) {
    std::string path = bench::runProcess({"sh", "-c", "command -v " + name}).output;
    while (!path.empty() && (path.back() == '\n' || path.back() == ' '))
        path.pop_back();
    return path;
}

// "total startup time in dynamic loader: N cycles" and the relocation count, from LD_DEBUG=statistics.
std::string loaderStatistics(const std::string& path) {
    const bench::ProcessRun run = bench::runProcess({path, "--version"}, "", {"LD_DEBUG=statistics"});
    std::string cycles = "?", relocations = "?";
    std::istringstream lines(run.output);
    for (std::string line; std::getline(lines, line);) {
        const auto after = [&](const std::string& label) {
            std::string v = line.substr(line.find(label) + label.size());
            v.erase(0, v.find_first_not_of(" \t"));
            return v.substr(0, v.find_first_of(" \t"));
        };
        if (line.find("total startup time in dynamic loader:") != std::string::npos && cycles == "?")
            cycles = after("total startup time in dynamic loader:");
        if (line.find("number of relocations:") != std::string::npos && relocations == "?")
            relocations = after("number of relocations:");
    }
    return fmt::format("{} cycles in the dynamic loader, {} symbol relocations", cycles, relocations);
}

} // namespace

int runStartup(const StartupOptions& o, std::ostream& log) {
    const fs::path work = fs::path(o.outputDir) / "work";
    std::error_code ec;
    fs::create_directories(work, ec);
    if (ec) {
        log << fmt::format("startup: cannot create '{}': {}\n", work.string(), ec.message());
        return 3;
    }
    const std::string scene = (work / "tiny.pov").string();
    writeTextFile(scene, kTinyPovScene);
    const std::string minimal = std::string(DRT_SOURCE_DIR) + "/examples/minimal.drt";
    const bool povray = !povrayVersion().empty();

    std::vector<Command> commands;
    std::vector<std::string> programs;
    if (povray) {
        programs.push_back("POV-Ray");
        commands.push_back({"--version", "POV-Ray", {"povray", "--version"}, work.string()});
        commands.push_back({"render tiny.pov 32x24, 2 threads",
                            "POV-Ray",
                            {"povray", "+Itiny.pov", "+Opov.png", "+W32", "+H24", "-D", "-A", "+WT2"},
                            work.string()});
    }
    for (const DrtBinary& drt : o.drt) {
        const std::string program = "drt " + drt.label;
        programs.push_back(program);
        commands.push_back({"--version", program, {drt.path, "--version"}, work.string()});
        commands.push_back(
            {"check examples/minimal.drt", program, {drt.path, "check", minimal}, work.string()});
        commands.push_back({"render tiny.pov 32x24, 2 threads",
                            program,
                            {drt.path, "render", "tiny.pov", "-o", "drt.png", "--width", "32", "--height",
                             "24", "--spp", "1", "--threads", "2", "--quiet"},
                            work.string()});
    }
    const int repetitions = o.repetitions > 0 ? o.repetitions : 10;
    std::map<std::pair<std::string, std::string>, Samples> samples;
    const std::vector<std::string> rows = {"--version", "check examples/minimal.drt",
                                           "render tiny.pov 32x24, 2 threads"};
    Csv csv;
    csv.header = {"command",      "program",     "repetition",  "exit_code",
                  "wall_seconds", "cpu_seconds", "peak_rss_mib"};
    for (int rep = 1; rep <= repetitions; ++rep) {
        for (const Command& c : commands) {
            const bench::ProcessRun run = bench::runProcess(c.argv, c.workDir);
            Samples& s = samples[{c.name, c.program}];
            if (!run.succeeded()) {
                ++s.failures;
                log << fmt::format("startup: {} {} failed:\n{}\n", c.program, c.name, run.output);
            } else {
                s.wall.push_back(run.wallSeconds), s.cpu.push_back(run.cpuSeconds()),
                    s.rss.push_back(run.peakRssMiB);
            }
            csv.rows.push_back({c.name, c.program, std::to_string(rep), std::to_string(run.exitCode),
                                fmt::format("{:.4f}", run.wallSeconds),
                                fmt::format("{:.4f}", run.cpuSeconds()),
                                fmt::format("{:.1f}", run.peakRssMiB)});
        }
    }

    std::string md =
        fmt::format("# Start-up costs\n\n- Machine: {}.\n- Medians of {} runs, interleaved: wall "
                    "time, CPU time (user + system), peak resident memory (from wait4).\n\n",
                    machineDescription(), repetitions);
    md += "| command |";
    for (const std::string& p : programs)
        md += fmt::format(" {} |", p);
    md += "\n|---|";
    for (size_t i = 0; i < programs.size(); ++i)
        md += "---|";
    md += "\n";
    for (const std::string& row : rows) {
        md += "| " + row + " |";
        for (const std::string& p : programs) {
            const auto it = samples.find({row, p});
            if (it == samples.end() || it->second.wall.empty()) {
                md += it == samples.end() ? " - |" : " failed |";
                continue;
            }
            const Samples& s = it->second;
            md += fmt::format(" {:.3f} s wall, {:.3f} s CPU, {:.1f} MiB |", bench::median(s.wall),
                              bench::median(s.cpu), bench::median(s.rss));
        }
        md += "\n";
    }
    md += "| shared libraries at start-up |";
    if (povray)
        md += fmt::format(" {} |", sharedLibraries(programPath("povray")));
    for (const DrtBinary& drt : o.drt)
        md += fmt::format(" {} |", sharedLibraries(drt.path));
    md += "\n\nThe dynamic loader, `drt --version` (LD_DEBUG=statistics):\n\n";
    for (const DrtBinary& drt : o.drt)
        md += fmt::format("- drt {}: {}\n", drt.label, loaderStatistics(drt.path));
    const std::string module = (fs::path(o.drt.front().path).parent_path() / "libdrt_oiio.so").string();
    if (fs::exists(module))
        md += fmt::format(
            "\ndrt's OpenImageIO module `{}` maps {} shared libraries when an image is first read or "
            "written.\n",
            fs::path(module).filename().string(), sharedLibraries(module));
    writeTextFile((fs::path(o.outputDir) / "startup.csv").string(), csv.text());
    writeTextFile((fs::path(o.outputDir) / "startup.md").string(), md);
    log << md;
    return 0;
}

} // namespace drt::perf
