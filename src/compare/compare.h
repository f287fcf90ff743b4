// Image comparison for golden-image tests: error metrics, idiff-style
// thresholds, and a statistical test against per-pixel variance images.
// docs/accuracy.md says why each figure is here.
//
// Conventions: `candidate` is the image under test, `reference` the golden
// one; errors are candidate - reference, on linear values, per channel, over
// the channels both images have (at most 3: colour, not alpha).
#pragma once

#include "image/image.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace drt {

// Exit statuses of `drt compare`, the same as OpenImageIO's idiff.
enum class CompareStatus { Pass = 0, Warn = 1, Fail = 2, SizeMismatch = 3, FileError = 4 };
const char* compareStatusName(CompareStatus status); // "PASS", "WARNING", ...

struct CompareOptions {
    // idiff's thresholds: a pixel fails if its largest channel error exceeds
    // failThreshold; the image fails if more than failPercent % of its pixels
    // fail. The same for warnings (reported even when nothing fails, unlike idiff).
    double failThreshold = 1e-6;
    double failPercent = 0;
    double warnThreshold = 1e-6;
    double warnPercent = 0;
    // With a variance image the statistical tests decide, and the thresholds
    // above apply only if this is set (the user gave --fail/--warn explicitly).
    bool thresholdsWithVariance = false;
    // Family-wise false-alarm rate of the statistical tests, split evenly
    // between the global-mean tests and the tile tests (Sidak within each).
    double alpha = 0.01;
    int tileSize = 8;
};

// Per-pixel variance of the mean of either image (e.g. drt render --variance).
// Both may be given: their sum is the variance of the difference.
struct VarianceImages {
    const Image* reference = nullptr;
    const Image* candidate = nullptr;
    bool any() const { return reference || candidate; }
};

struct TileTest {
    int x0 = 0, y0 = 0; // top-left pixel of the tile
    int channel = 0;
    double meanError = 0;
    double z = 0;
};

struct CompareResult {
    CompareStatus status = CompareStatus::Pass;
    std::string message; // why the status is not Pass (one line), or a size/file error
    int width = 0, height = 0, channels = 0;
    int64_t pixelCount = 0;

    int64_t nonFinitePixels = 0; // a NaN or Inf in any channel of either image
    // Over the finite pixels, per channel value of e = candidate - reference:
    double rmse = 0;            // sqrt(mean e^2)
    double relMse = 0;          // mean e^2 / (reference^2 + 0.01)
    double robustRelMse = 0;    // relMse without the worst 0.1% of pixels
    double meanSignedError = 0; // mean e (bias)
    double meanAbsoluteError = 0;
    double maxError = 0; // max |e|
    int maxErrorX = -1, maxErrorY = -1, maxErrorChannel = -1;
    double psnr = 0; // dB, on clamped sRGB-encoded values; +inf if identical

    int64_t failingPixels = 0; // largest channel |e| > failThreshold
    int64_t warningPixels = 0; // largest channel |e| > warnThreshold

    // Statistical mode (only when variance images were given).
    bool statistical = false;
    std::vector<double> globalZ; // per channel: mean e / sqrt(sum var / n^2)
    double globalZThreshold = 0; // |z| above this rejects (Sidak over the channels)
    int tileTests = 0;
    int failingTiles = 0;
    double tileZThreshold = 0; // Sidak over every tile and channel
    TileTest worstTile;        // largest |z|
    int64_t outlierPixels = 0; // pixels with |z| above a Sidak per-pixel bound (information only)
};

// Compares `candidate` against `reference`. Sizes must match (else
// SizeMismatch); the variance images must match them too.
CompareResult compareImages(const Image& candidate, const Image& reference,
                            const CompareOptions& options = {}, const VarianceImages& variance = {});

// False-colour heatmap of the largest channel |error| per pixel, from black
// (0) to white (>= scale; scale <= 0 uses the largest finite error). Non-finite
// pixels are green.
Image errorHeatmap(const Image& candidate, const Image& reference, double scale = 0);

// Signed z-score per pixel (error summed over channels divided by its
// standard deviation), blue (-limit) - white (0) - red (+limit); green for
// non-finite values.
Image zScoreMap(const Image& candidate, const Image& reference, const VarianceImages& variance,
                double limit = 4);

// Two-sided normal threshold: the z with P(|Z| > z) = alpha.
double twoSidedNormalQuantile(double alpha);
// Per-test alpha that gives a family-wise rate `alpha` over `tests`
// independent tests (Sidak): 1 - (1 - alpha)^(1/tests).
double sidakAlpha(double alpha, int64_t tests);

// "R", "G", "B", "A" for channels 0-3 of an RGB(A) image, else "channel N".
std::string channelName(int channel);

// Plain-text report (idiff-like) and a JSON object with the same figures.
std::string formatCompareText(const CompareResult& result);
std::string formatCompareJson(const CompareResult& result, const std::string& candidatePath,
                              const std::string& referencePath);

} // namespace drt
