#include "perf.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace fs = std::filesystem;

namespace drt::perf {

DrtBinary parseDrtBinary(const std::string& text) {
    DrtBinary binary{"drt", text};
    if (const size_t eq = text.find('='); eq != std::string::npos) {
        binary.label = text.substr(0, eq);
        binary.path = text.substr(eq + 1);
    }
    std::error_code ec;
    binary.path = fs::absolute(binary.path, ec).string();
    if (binary.label.empty() || access(binary.path.c_str(), X_OK) != 0)
        throw std::invalid_argument(fmt::format("'{}' is not LABEL=PATH with an executable PATH", text));
    return binary;
}

std::vector<std::string> drtSampleArgs(const DrtBinary& drt, int spp) {
    std::vector<std::string> split;
    if (drt.lightSamples != 1) split = {"--light-samples", std::to_string(drt.lightSamples)};
    if (!drt.adaptive) {
        std::vector<std::string> args{"--spp", std::to_string(spp)};
        args.insert(args.end(), split.begin(), split.end());
        return args;
    }
    std::vector<std::string> args{"--adaptive",
            "--adaptive-error",
            fmt::format("{:.6g}", drt.adaptiveScale / std::sqrt(double(std::max(1, spp)))),
            "--min-spp",
            std::to_string(drt.adaptiveMinSpp),
            "--max-spp",
            std::to_string(drt.adaptiveMaxSpp)};
    args.insert(args.end(), split.begin(), split.end());
    return args;
}

void markLightSamples(std::vector<DrtBinary>& binaries, const std::string& text) {
    const size_t eq = text.find('=');
    int k = 0;
    char rest = 0;
    if (eq == std::string::npos || std::sscanf(text.c_str() + eq + 1, "%d%c", &k, &rest) != 1 || k < 1 || k > 1024)
        throw std::invalid_argument(fmt::format("'{}' is not LABEL=K with K from 1 to 1024", text));
    const std::string label = text.substr(0, eq);
    for (DrtBinary& binary : binaries)
        if (binary.label == label) {
            binary.lightSamples = k;
            return;
        }
    throw std::invalid_argument(fmt::format("--drt-light-samples {}: no --drt labelled '{}'", text, label));
}

std::string drtSamplingNote(const DrtBinary& drt) {
    std::vector<std::string> parts;
    if (drt.adaptive)
        parts.push_back(fmt::format("adaptive, {}..{} spp, a setting of N spp: error {}/sqrt(N)", drt.adaptiveMinSpp,
                                    drt.adaptiveMaxSpp, drt.adaptiveScale));
    if (drt.lightSamples != 1) parts.push_back(fmt::format("--light-samples {}", drt.lightSamples));
    if (parts.empty()) return "";
    std::string joined;
    for (const std::string& part : parts) joined += (joined.empty() ? "" : "; ") + part;
    return " (" + joined + ")";
}

void markAdaptive(std::vector<DrtBinary>& binaries, const std::string& text) {
    const size_t eq = text.find('=');
    const std::string label = text.substr(0, eq);
    int low = 4, high = 1024;
    double scale = 0.05;
    if (eq != std::string::npos) {
        const int read = std::sscanf(text.c_str() + eq + 1, "%d,%d,%lf", &low, &high, &scale);
        if (read < 2 || low < 1 || high < low || !(scale > 0 && scale < 1))
            throw std::invalid_argument(fmt::format("'{}' is not LABEL, LABEL=MIN,MAX or LABEL=MIN,MAX,SCALE", text));
    }
    for (DrtBinary& binary : binaries)
        if (binary.label == label) {
            binary.adaptive = true;
            binary.adaptiveMinSpp = low;
            binary.adaptiveMaxSpp = high;
            binary.adaptiveScale = scale;
            return;
        }
    throw std::invalid_argument(fmt::format("--drt-adaptive {}: no --drt labelled '{}'", text, label));
}

DrtBinary builtDrt() {
    return DrtBinary{"drt", DRT_EXECUTABLE};
}

bool drtRenderHas(const DrtBinary& drt, const std::string& option) {
    const bench::ProcessRun help = bench::runProcess({drt.path, "render", "--help"});
    return help.output.find(option) != std::string::npos;
}

namespace {

// "25 ms", "1.7 s", "2 min 05 s": drt's formatDuration.
double parseDuration(const std::string& text) {
    std::smatch m;
    if (std::regex_match(text, m, std::regex(R"(\s*([0-9.]+) ms\s*)")))
        return std::stod(m[1]) / 1000;
    if (std::regex_match(text, m, std::regex(R"(\s*([0-9.]+) s\s*)")))
        return std::stod(m[1]);
    if (std::regex_match(text, m, std::regex(R"(\s*([0-9]+) min ([0-9]+) s\s*)")))
        return 60 * std::stod(m[1]) + std::stod(m[2]);
    if (std::regex_match(text, m, std::regex(R"(\s*([0-9]+) h ([0-9]+) min\s*)")))
        return 3600 * std::stod(m[1]) + 60 * std::stod(m[2]);
    return -1;
}

} // namespace

bool parseDrtSummary(const std::string& output, DrtRender& render) {
    static const std::regex summary(
        R"(\(build ([^,]+), trace ([^)]+)\): [^,]*, ([0-9.]+) Mrays/s \(camera ([0-9.]+)M, shadow ([0-9.]+)M, )"
        R"(secondary ([0-9.]+)M\))");
    std::smatch m;
    if (!std::regex_search(output, m, summary))
        return false;
    render.buildSeconds = parseDuration(m[1]);
    render.traceSeconds = parseDuration(m[2]);
    render.mraysPerSecond = std::stod(m[3]);
    render.cameraRays = uint64_t(std::stod(m[4]) * 1e6);
    render.shadowRays = uint64_t(std::stod(m[5]) * 1e6);
    render.secondaryRays = uint64_t(std::stod(m[6]) * 1e6);
    render.reported = render.buildSeconds >= 0 && render.traceSeconds >= 0;
    return render.reported;
}

DrtRender runDrtRender(const DrtBinary& drt, const std::string& scene, const std::string& output,
                       const std::vector<std::string>& options, const std::string& workDir) {
    static std::vector<std::pair<std::string, bool>> statsSupport; // per binary path
    bool hasStats = false, known = false;
    for (const auto& [path, has] : statsSupport)
        if (path == drt.path)
            hasStats = has, known = true;
    if (!known) {
        hasStats = drtRenderHas(drt, "--stats");
        statsSupport.emplace_back(drt.path, hasStats);
    }
    std::vector<std::string> argv = {drt.path, "render", scene, "-o", output};
    argv.insert(argv.end(), options.begin(), options.end());
    const std::string statsPath = output + ".stats.json";
    if (hasStats)
        argv.insert(argv.end(), {"--stats", statsPath});

    DrtRender render;
    render.process = bench::runProcess(argv, workDir);
    if (hasStats && render.process.succeeded()) {
        try {
            const nlohmann::json stats = nlohmann::json::parse(readTextFile(statsPath));
            render.loadSeconds = stats.at("load_seconds");
            render.buildSeconds = stats.at("build_seconds");
            render.traceSeconds = stats.at("trace_seconds");
            render.traceCpuSeconds = stats.value("trace_cpu_seconds", -1.0);
            render.mraysPerSecond = stats.at("mrays_per_second");
            render.cameraRays = stats.at("camera_rays");
            render.shadowRays = stats.at("shadow_rays");
            render.secondaryRays = stats.at("secondary_rays");
            render.reported = true;
        } catch (const nlohmann::json::exception&) {
        }
        std::error_code ec;
        fs::remove(statsPath, ec);
    }
    if (!render.reported)
        parseDrtSummary(render.process.output, render);
    return render;
}

double PovRender::reportedSeconds() const {
    if (parseSeconds < 0 || traceSeconds < 0)
        return -1;
    return parseSeconds + std::max(0.0, boundingSeconds) + traceSeconds;
}

double parsePovSeconds(const std::string& output, const std::string& label) {
    const std::regex line(label +
                          R"(:\s+[0-9]+ hours\s+[0-9]+ minutes\s+[0-9]+ seconds \(([0-9.]+) seconds\))");
    std::smatch m;
    return std::regex_search(output, m, line) ? std::stod(m[1]) : -1;
}

PovRender runPovray(const std::vector<std::string>& arguments, const std::string& workDir) {
    std::vector<std::string> argv = {"povray"};
    argv.insert(argv.end(), arguments.begin(), arguments.end());
    PovRender render;
    render.process = bench::runProcess(argv, workDir);
    render.parseSeconds = parsePovSeconds(render.process.output, "Parse Time");
    render.boundingSeconds = parsePovSeconds(render.process.output, "Bounding Time");
    render.traceSeconds = parsePovSeconds(render.process.output, "Trace Time");
    return render;
}

std::string povrayVersion() {
    const bench::ProcessRun run = bench::runProcess({"povray", "--version"});
    if (!run.started)
        return "";
    std::istringstream lines(run.output);
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("POV-Ray ", 0) == 0)
            return line;
    return "";
}

void writeTextFile(const std::string& path, const std::string& text) {
    const std::string temporary = path + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary);
        out << text;
        if (!out.flush())
            throw std::runtime_error(fmt::format("cannot write '{}'", path));
    }
    std::error_code ec;
    fs::rename(temporary, path, ec);
    if (ec)
        throw std::runtime_error(fmt::format("cannot write '{}': {}", path, ec.message()));
}

std::string readTextFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

Image readImageOrThrow(const std::string& path) {
    Image image;
    if (std::string problem = readImage(path, image); !problem.empty())
        throw std::runtime_error(problem);
    return image;
}

std::string lastLines(const std::string& text, size_t lines) {
    size_t position = text.size();
    for (size_t i = 0; i <= lines && position != std::string::npos && position > 0; ++i)
        position = text.rfind('\n', position - 1);
    return position == std::string::npos ? text : text.substr(position + 1);
}

std::string Csv::text() const {
    const auto line = [](const std::vector<std::string>& row) {
        std::string out;
        for (size_t i = 0; i < row.size(); ++i) {
            const std::string& cell = row[i];
            std::string quoted = cell;
            if (cell.find_first_of(",\"\n") != std::string::npos) {
                quoted = "\"";
                for (char c : cell)
                    quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
                quoted += "\"";
            }
            out += (i ? "," : "") + quoted;
        }
        return out + "\n";
    };
    std::string out = line(header);
    for (const std::vector<std::string>& row : rows)
        out += line(row);
    return out;
}

std::string machineDescription() {
    const bench::ProcessRun run = bench::runProcess({"lscpu"});
    std::string model = "unknown CPU", cpus = "?";
    std::istringstream lines(run.output);
    for (std::string line; std::getline(lines, line);) {
        const auto value = [&] {
            std::string v = line.substr(line.find(':') + 1);
            v.erase(0, v.find_first_not_of(" \t"));
            return v;
        };
        if (line.rfind("Model name:", 0) == 0)
            model = value();
        if (line.rfind("CPU(s):", 0) == 0)
            cpus = value();
    }
    return fmt::format("{}, {} logical CPUs", model, cpus);
}

} // namespace drt::perf
