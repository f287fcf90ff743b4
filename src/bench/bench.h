// `drt bench`: renders a scene with each method (bench/methods.h) at each
// sample count over several seeds, times every render, measures its error
// against a high-sample reference, and writes results.csv, the charts
// (error-vs-time, error-vs-spp; bench/chart.h) and summary.md into a folder.
//
// Error metrics (docs/accuracy.md), on linear RGB:
//   relmse_raw  compareImages' relMSE, mean (x - r)^2 / (r^2 + 0.01)
//   relmse      relmse_raw minus the reference's own noise, mean Var(r) / (r^2
//               + 0.01), since E[(x - r_noisy)^2] = (x - r_true)^2 + Var(r); this
//               is what the charts show (it may be <= 0 when the candidate is
//               as good as the reference: such points are left off the charts).
//               A reference the bench renders is the mean of 8 independent
//               sobol renders and Var(r) comes from their spread, which stays
//               honest for stratified samples (bench.cpp, makeReference).
//   bias z      sum of (x - r) over pixels and channels / sqrt(sum of Var(x) +
//               Var(r)): a global z-score, N(0, 1) for an unbiased method
//               (NaN below 2 samples per pixel: no variance estimate). The
//               sample variance over-states the variance of a stratified
//               mean, so for stratified samplers |z| errs on the small side.
#pragma once

#include "bench/methods.h"

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace drt::bench {

// A problem that stops the bench. `ioError` separates unreadable or unwritable
// files (exit 3) from scene and render problems (exit 1).
class BenchError : public std::runtime_error {
public:
    BenchError(const std::string& message, bool ioError) : std::runtime_error(message), ioError(ioError) {}
    bool ioError;
};

struct BenchOptions {
    std::string scenePath;
    std::string outputDir;
    std::vector<int> spp; // empty: 1,4,16,64,256 (quick: 1,4,16)
    int seeds = 0;        // 0: 3 (quick: 1)
    std::vector<std::string> methods; // empty: every method that applies
    std::string referencePath;        // a given reference image (.exr); its variance from <stem>.variance.exr if present
    int referenceSpp = 0;             // 0: 16 x the largest spp (quick: 256)
    int width = 0, height = 0;        // 0: 96 wide (quick: 48), height by the scene's aspect
    int threads = 0;                  // 0: all cores
    bool quick = false;
};

struct BenchRow {
    std::string scene, method, sampler, filter;
    int spp = 0;
    double meanSpp = 0; // samples per pixel actually taken (adaptive differs from spp)
    uint64_t seed = 0;
    int threads = 0;
    int width = 0, height = 0;
    double parseSeconds = 0, buildSeconds = 0, renderSeconds = 0;
    uint64_t rays = 0;
    double mraysPerSecond = 0;
    double mse = 0, relMse = 0, relMseRaw = 0, robustRelMse = 0;
    double meanSignedError = 0;
    double biasZ = 0;
    int64_t nonFinite = 0; // NaN/Inf samples dropped by the renderer + non-finite pixels
    double seconds() const { return buildSeconds + renderSeconds; } // the cost the charts use
};

struct SkippedMethod {
    std::string name;
    std::string reason;
};

struct BenchReport {
    std::string sceneName;
    int width = 0, height = 0, threads = 0;
    std::vector<int> spp;
    int seeds = 0;
    double parseSeconds = 0;
    std::vector<std::string> methods; // run, in order
    std::vector<SkippedMethod> skipped;
    std::vector<std::string> referenceNotes; // one line per reference: file, spp, reused or made
    std::vector<BenchRow> rows;
};

// Runs the bench and writes every output into options.outputDir (created if
// missing). Progress goes to `log`. Throws BenchError.
BenchReport runBench(const BenchOptions& options, std::ostream& log);

// The CSV header and rows (results.csv).
std::string formatResultsCsv(const std::vector<BenchRow>& rows);

// Parses "1,4,16" (positive integers); throws std::invalid_argument.
std::vector<int> parseSppList(const std::string& text);

} // namespace drt::bench
