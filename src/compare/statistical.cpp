// Statistical comparison against per-pixel variance images (the
// "statistical" policy of docs/golden-tests.md). For independent pixel errors
// e_i with variances v_i, the mean error of a region has variance sum(v_i) / n^2, so under "no bias"
//   z = sum(e_i) / sqrt(sum(v_i))
// is close to standard normal. A global z per channel catches a small bias
// everywhere; z per 8x8 tile and channel catches a larger bias in one place.
// Each family is held to alpha/2 with Sidak's correction, so the whole
// comparison raises a false alarm with probability at most alpha.
#include "compare/statistical.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace drt {

double sidakAlpha(double alpha, int64_t tests) {
    if (tests <= 1)
        return alpha;
    // 1 - (1 - alpha)^(1/m), written to keep precision for tiny results.
    return -std::expm1(std::log1p(-alpha) / double(tests));
}

double twoSidedNormalQuantile(double alpha) {
    // Solve erfc(z / sqrt 2) = alpha by bisection: erfc is monotone and
    // P(|Z| > z) = erfc(z / sqrt 2).
    if (!(alpha > 0))
        return std::numeric_limits<double>::infinity();
    if (alpha >= 1)
        return 0;
    double lo = 0, hi = 40;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (std::erfc(mid / std::sqrt(2.0)) > alpha ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

namespace {

double channelOf(const Image& image, int x, int y, int c) {
    return image.at(x, y, std::min(c, image.channels - 1));
}

// z of a sum of errors with a summed variance; 0/0 (identical noiseless
// regions) is no evidence of bias, e/0 is certain bias.
double zScore(double sumError, double sumVariance) {
    if (sumVariance > 0)
        return sumError / std::sqrt(sumVariance);
    if (sumError == 0)
        return 0;
    return std::copysign(std::numeric_limits<double>::infinity(), sumError);
}

} // namespace

double differenceVariance(const VarianceImages& variance, int x, int y, int c) {
    double v = 0;
    if (variance.reference)
        v += std::max(0.0, channelOf(*variance.reference, x, y, c));
    if (variance.candidate)
        v += std::max(0.0, channelOf(*variance.candidate, x, y, c));
    return v;
}

bool varianceIsFinite(const VarianceImages& variance, int x, int y, int channels) {
    for (const Image* v : {variance.reference, variance.candidate})
        if (v)
            for (int c = 0; c < channels; ++c)
                if (!std::isfinite(channelOf(*v, x, y, c)))
                    return false;
    return true;
}

void runStatisticalTests(const Image& candidate, const Image& reference, const VarianceImages& variance,
                         const CompareOptions& options, CompareResult& r) {
    r.statistical = true;
    const int nc = r.channels;
    const int tile = std::max(1, options.tileSize);
    const int tilesX = (r.width + tile - 1) / tile, tilesY = (r.height + tile - 1) / tile;
    r.tileTests = tilesX * tilesY * nc;
    r.globalZThreshold = twoSidedNormalQuantile(sidakAlpha(options.alpha / 2, nc));
    r.tileZThreshold = twoSidedNormalQuantile(sidakAlpha(options.alpha / 2, r.tileTests));
    const double pixelZThreshold = twoSidedNormalQuantile(sidakAlpha(options.alpha, r.pixelCount * nc));

    // Per tile and channel: sums of errors and variances (non-finite pixels
    // are left out: they fail on their own).
    std::vector<double> tileError(size_t(r.tileTests), 0), tileVariance(size_t(r.tileTests), 0);
    std::vector<double> globalError(nc, 0), globalVariance(nc, 0);
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x) {
            if (!pixelIsFinite(candidate, x, y, nc) || !pixelIsFinite(reference, x, y, nc) ||
                !varianceIsFinite(variance, x, y, nc))
                continue;
            bool outlier = false;
            for (int c = 0; c < nc; ++c) {
                const double e = double(candidate.at(x, y, c)) - reference.at(x, y, c);
                const double v = differenceVariance(variance, x, y, c);
                const size_t t = (size_t(y / tile) * tilesX + x / tile) * nc + c;
                tileError[t] += e, tileVariance[t] += v;
                globalError[c] += e, globalVariance[c] += v;
                outlier = outlier || !(std::abs(zScore(e, v)) <= pixelZThreshold);
            }
            if (outlier)
                ++r.outlierPixels;
        }

    r.globalZ.assign(nc, 0);
    for (int c = 0; c < nc; ++c)
        r.globalZ[c] = zScore(globalError[c], globalVariance[c]);

    r.failingTiles = 0;
    double worst = -1;
    for (int t = 0; t < r.tileTests; ++t) {
        const double z = zScore(tileError[t], tileVariance[t]);
        if (!(std::abs(z) <= r.tileZThreshold))
            ++r.failingTiles;
        if (std::abs(z) > worst) {
            worst = std::abs(z);
            const int index = t / nc;
            const int x0 = (index % tilesX) * tile, y0 = (index / tilesX) * tile;
            const int w = std::min(tile, r.width - x0), h = std::min(tile, r.height - y0);
            r.worstTile = TileTest{x0, y0, t % nc, tileError[t] / (double(w) * h), z};
        }
    }
}

} // namespace drt
