// Golden-image tests: a folder of scenes, each with a stored golden image and
// a small JSON sidecar of render settings and tolerances, rendered and compared
// by `drt test DIR` (docs/golden-tests.md is the user's manual).
//
// File conventions, for a test named NAME in the folder:
//   NAME.golden.json     the sidecar (required; its presence makes NAME a test)
//   NAME.drt             the scene, unless the sidecar's "scene" names another
//                        file (relative to the sidecar)
//   NAME.golden.exr      the golden image (linear floats), and/or
//   NAME.golden.png      an 8-bit sRGB golden (exact policy only), as the
//                        sidecar's "format" says ("exr", "png" or "both")
//   NAME.golden.var.exr  per-pixel variance of the golden's mean (statistical)
//   NAME.preview.png     an 8-bit sRGB view of the EXR golden, written by
//                        --update so a reviewer sees the picture in a code
//                        review (not compared: the EXR is the golden)
// A NAME.drt with no sidecar is reported as a missing golden, never created
// unless --update is given.
#pragma once

#include "compare/compare.h"
#include "image/image.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace drt::golden {

enum class Policy {
    Exact,       // same seed, same decoded pixel values, bit for bit
    Statistical, // the candidate's own seed; compare's z-tests against the golden's variance
};
const char* policyName(Policy policy); // "exact" / "statistical"

// The sidecar NAME.golden.json. Every field has a default; --update writes them all.
struct GoldenSettings {
    std::string scene; // as written in the sidecar ("" : NAME.drt beside it)
    Policy policy = Policy::Exact;
    std::string format = "exr";                        // golden image files: "exr", "png" or "both"
    std::optional<int> width, height, samplesPerPixel; // unset: the scene's own
    std::optional<uint64_t> seed;
    std::optional<std::string> sampler;
    int threads = 0; // per render; 0: all cores
    // Exact policy: a pixel fails if a channel differs by more than failThreshold,
    // the scene fails if more than failPercent % of pixels fail. With both 0 (the
    // default) the decoded pixels must be bit-identical.
    double failThreshold = 0;
    double failPercent = 0;
    // Statistical policy: compare's family-wise false-alarm rate and tile edge;
    // the reference is rendered at referenceSamplesPerPixel (default 64x the
    // test's, see docs/accuracy.md) with referenceSeed (default seed + 1, so the
    // two estimates are independent).
    double alpha = 0.01;
    int tileSize = 8;
    std::optional<int> referenceSamplesPerPixel;
    std::optional<uint64_t> referenceSeed;
};

// Parses a sidecar; unknown keys are errors (a misspelt tolerance must not be
// ignored). Returns "" on success, else "path: reason".
std::string readSettings(const std::string& path, GoldenSettings& settings);
// Writes every field (temporary file, then rename). Returns "" or the reason.
std::string writeSettings(const std::string& path, const GoldenSettings& settings);

// One test found in a folder, with every path resolved.
struct GoldenCase {
    std::string name;
    std::string sidecarPath; // "" : no sidecar (a scene without a golden)
    std::string scenePath;
    std::string exrPath, pngPath, variancePath; // the conventional names, whether or not they exist
    std::string previewPath; // NAME.preview.png: an 8-bit view of an EXR golden for code review
};

// The tests in `folder`, sorted by name: every NAME.golden.json, and every
// NAME.drt without one. Returns "" or the reason the folder cannot be read.
std::string discoverCases(const std::string& folder, std::vector<GoldenCase>& cases);

enum class Outcome {
    Pass,
    Fail,    // the images differ beyond the policy's tolerance
    Missing, // no sidecar, golden image or variance image: run with --update
    Error,   // the scene or sidecar is broken, or an image cannot be read or written
    Updated, // --update rewrote the golden
};
const char* outcomeName(Outcome outcome); // "PASS", "FAIL", "MISSING", "ERROR", "UPDATED"

struct CaseResult {
    std::string name;
    std::string scenePath; // as resolved ("" : not known, e.g. a broken sidecar)
    std::string previewPath; // the golden's PNG view (preview or PNG golden) if it exists, else ""
    GoldenSettings settings; // the sidecar's (defaults when it could not be read)
    Policy policy = Policy::Exact;
    std::string format = "exr"; // golden image files: "exr", "png" or "both"
    Outcome outcome = Outcome::Error;
    std::string message; // one line: why it failed, or what was written
    std::string details; // more lines, e.g. a scene's diagnostics with carets
    std::optional<CompareResult> comparison;
    double seconds = 0; // render (and comparison) time of this case
    // Kept for the report when the case failed a comparison.
    Image candidate, golden, candidateVariance, goldenVariance;
};

struct RunOptions {
    bool update = false;           // rewrite goldens (and variance images) instead of comparing
    std::vector<std::string> only; // test names to run; empty: all
    // Called once per finished case, from the thread that ran it (serialise
    // output yourself); may be empty.
    std::function<void(const CaseResult&)> onCaseDone;
};

struct RunSummary {
    std::string folder;
    std::vector<CaseResult> cases; // sorted by name
    int passed = 0, failed = 0, missing = 0, errors = 0, updated = 0;
    double seconds = 0; // wall time of the whole run
    bool allPassed() const { return failed == 0 && missing == 0 && errors == 0; }
};

// Runs (or with update, rewrites) every test in the folder, several scenes at
// once. If the folder cannot be read, `error` says why and there are no cases.
RunSummary runGoldenTests(const std::string& folder, const RunOptions& options, std::string& error);

// The figures a reader needs to judge a failed comparison, on one line, with
// only those that mean something under the case's policy: RMSE, bias, max
// error and where, NaN/Inf pixels, then the exact policy's differing pixels or
// the statistical policy's z-scores and failing tiles. "" without a comparison.
std::string failureFigures(const CaseResult& result);

// For CI systems (ci_report.cpp): JUnit XML, one <testcase> per scene in one
// <testsuite> named after the folder, a FAIL or MISSING as <failure>, an ERROR
// as <error>, each with the one-line message and the figures; and JSON with the
// same figures as numbers.
std::string junitReport(const RunSummary& summary);
// Text for XML or HTML: & < > " ' escaped, control characters other than tab
// and newline (not allowed in XML 1.0) dropped.
std::string escapeMarkup(const std::string& text);
std::string jsonReport(const RunSummary& summary);
// Writes text to a temporary file beside `path`, then renames it over `path`.
// Returns "" or the reason.
std::string writeTextFile(const std::string& path, const std::string& text);

// Writes reportDir/index.html with candidate, golden and heatmap (and z-map
// for statistical tests) side by side for every failed case and the golden
// previews of the passed ones, every picture embedded in the page, and each
// failed candidate as NAME.candidate.exr beside it. Returns "" or the reason.
std::string writeReport(const std::string& reportDir, const RunSummary& summary);

} // namespace drt::golden
