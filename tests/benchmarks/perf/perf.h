// Shared pieces of drt_perf, the performance instruments of the project
// (docs/performance.md): the programs under test, how each is run and timed,
// and the files every instrument writes.
#pragma once

#include "bench/process.h"
#include "image/image.h"

#include <cstdint>
#include <string>
#include <vector>

namespace drt::perf {

// A drt executable under test, named for the tables ("before", "after").
struct DrtBinary {
    std::string label;
    std::string path;
    // Measured with adaptive sampling (--drt-adaptive): a sweep step of N
    // samples per pixel renders with these bounds and the error adaptiveScale / sqrt(N).
    bool adaptive = false;
    int adaptiveMinSpp = 4, adaptiveMaxSpp = 1024;
    double adaptiveScale = 0.05; // drt aims at relMSE error^2 or less: 0.05 / sqrt(N) spans 2.5e-3 to 1e-5
    // --light-samples of every render of this drt (--drt-light-samples); 1: not given.
    int lightSamples = 1;
};
// The render arguments of one sweep step of N samples per pixel: "--spp N", or
// for an adaptive drt "--adaptive --adaptive-error E --min-spp A --max-spp B".
std::vector<std::string> drtSampleArgs(const DrtBinary& drt, int spp);
// "LABEL", "LABEL=MIN,MAX" or "LABEL=MIN,MAX,SCALE" of --drt-adaptive: marks
// that drt of `binaries` adaptive. Throws std::invalid_argument for an
// unknown label or bad values.
void markAdaptive(std::vector<DrtBinary>& binaries, const std::string& text);
// "LABEL=K" of --drt-light-samples: that drt renders with --light-samples K.
// Throws std::invalid_argument for an unknown label or a bad K.
void markLightSamples(std::vector<DrtBinary>& binaries, const std::string& text);
// " (adaptive, ...; K light samples)" or "": how a drt of the sweeps samples, for reports.
std::string drtSamplingNote(const DrtBinary& drt);
// "LABEL=PATH", or a bare PATH (labelled "drt"). Throws std::invalid_argument
// if the file is not an executable.
DrtBinary parseDrtBinary(const std::string& text);
// The drt built beside this tool.
DrtBinary builtDrt();

// One `drt render`: the process as measured from outside, plus what drt says
// about itself (from --stats when the binary has it, else from its summary line).
struct DrtRender {
    bench::ProcessRun process;
    bool reported = false;     // the figures below were found
    double loadSeconds = -1;   // parse + files (--stats only)
    double buildSeconds = 0;   // Embree build
    double traceSeconds = 0;   // tracing
    double traceCpuSeconds = -1; // the render threads' CPU time, summed (--stats of a drt that has it)
    double mraysPerSecond = 0; // all rays / trace time
    uint64_t cameraRays = 0, shadowRays = 0, secondaryRays = 0;
    double renderSeconds() const { return buildSeconds + traceSeconds; }
};
DrtRender runDrtRender(const DrtBinary& drt, const std::string& scene, const std::string& output,
                       const std::vector<std::string>& options, const std::string& workDir);
// Parses drt's one-line render summary ("... (build 25 ms, trace 1.7 s): ...
// 1.25 Mrays/s (camera 1.23M, shadow 0.69M, secondary 0.19M)"). False if absent.
bool parseDrtSummary(const std::string& output, DrtRender& render);
// True if `drt render --help` lists `option`.
bool drtRenderHas(const DrtBinary& drt, const std::string& option);

// One POV-Ray run, with the times POV-Ray reports (seconds; -1 if absent).
struct PovRender {
    bench::ProcessRun process;
    double parseSeconds = -1, boundingSeconds = -1, traceSeconds = -1;
    double reportedSeconds() const; // parse + bounding + trace (what POV-Ray itself times)
};
PovRender runPovray(const std::vector<std::string>& arguments, const std::string& workDir);
// The seconds in POV-Ray's "<label>: 0 hours 0 minutes 9 seconds (9.991 seconds)" line; -1 if absent.
double parsePovSeconds(const std::string& output, const std::string& label);
std::string povrayVersion(); // first line of `povray --version`, "" if POV-Ray is missing

// The folder of POV-Ray's sample scenes (Debian's povray-examples).
inline constexpr const char* kPovExamples = "/usr/share/doc/povray/examples";

// Text written through a temporary file renamed over `path`. Throws std::runtime_error.
void writeTextFile(const std::string& path, const std::string& text);
std::string readTextFile(const std::string& path); // "" if unreadable
// An image through image/image.h. Throws std::runtime_error with its reason.
Image readImageOrThrow(const std::string& path);
// The last `lines` lines of a program's output, for error messages.
std::string lastLines(const std::string& text, size_t lines = 6);

// A CSV table: a header, then rows of already formatted cells.
struct Csv {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
    std::string text() const;
};

// "lscpu"'s model name and the core count, for report headers.
std::string machineDescription();

} // namespace drt::perf
