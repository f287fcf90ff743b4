#include "bench/agreement.h"

#include "compare/compare.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace drt::bench {

bool ReferenceAgreement::agree() const {
    return sizesMatch && std::fabs(relativeMeanDifference) <= tolerance && materialTiles == 0;
}

ReferenceAgreement compareReferences(const Image& a, const Image& b, const AgreementOptions& options) {
    ReferenceAgreement result;
    result.tolerance = options.tolerance;
    result.tileSize = std::max(1, options.tileSize);
    if (a.width != b.width || a.height != b.height || a.pixels.empty() || b.pixels.empty()) {
        result.sizesMatch = false;
        return result;
    }
    const int channels = std::min({3, a.channels, b.channels});
    const int tile = std::max(1, options.tileSize);
    const int tilesX = (a.width + tile - 1) / tile, tilesY = (a.height + tile - 1) / tile;
    result.tiles = tilesX * tilesY;
    result.tThreshold = twoSidedNormalQuantile(sidakAlpha(options.alpha, result.tiles));

    double sumDifference = 0, sumReference = 0, sumRelSquares = 0;
    int64_t count = 0;
    bool worstIsSignificant = false;
    for (int ty = 0; ty < tilesY; ++ty)
        for (int tx = 0; tx < tilesX; ++tx) {
            // Per pixel: the difference averaged over channels, so one pixel
            // is one observation of the tile's mean difference.
            double sum = 0, squares = 0, reference = 0;
            int n = 0;
            for (int y = ty * tile; y < std::min(a.height, (ty + 1) * tile); ++y)
                for (int x = tx * tile; x < std::min(a.width, (tx + 1) * tile); ++x) {
                    double d = 0, r = 0;
                    bool finite = true;
                    for (int c = 0; c < channels; ++c) {
                        const double av = a.at(x, y, c), bv = b.at(x, y, c);
                        finite = finite && std::isfinite(av) && std::isfinite(bv);
                        d += (av - bv) / channels;
                        r += bv / channels;
                    }
                    if (!finite)
                        continue;
                    for (int c = 0; c < channels; ++c) {
                        const double e = double(a.at(x, y, c)) - b.at(x, y, c);
                        const double bv = b.at(x, y, c);
                        sumRelSquares += e * e / (bv * bv + 0.01);
                    }
                    sum += d, squares += d * d, reference += r, ++n;
                }
            if (n == 0)
                continue;
            sumDifference += sum, sumReference += reference, count += n;
            TileDifference t;
            t.x0 = tx * tile, t.y0 = ty * tile;
            const double mean = sum / n, meanReference = reference / n;
            t.relativeMean = mean / std::sqrt(meanReference * meanReference + 0.01);
            const double variance = n > 1 ? std::max(0.0, (squares - n * mean * mean) / (n - 1)) : 0.0;
            const double standardError = std::sqrt(variance / n);
            t.t =
                standardError > 0 ? mean / standardError : (mean != 0 ? std::copysign(INFINITY, mean) : 0.0);
            const bool significant = std::fabs(t.t) > result.tThreshold;
            if (significant)
                ++result.significantTiles;
            if (significant && std::fabs(t.relativeMean) > options.tolerance)
                ++result.materialTiles;
            // The worst tile: the largest relative difference, preferring significant ones.
            const bool better =
                significant && !worstIsSignificant
                    ? true
                    : significant == worstIsSignificant &&
                          std::fabs(t.relativeMean) > std::fabs(result.worstTile.relativeMean);
            if (better)
                result.worstTile = t, worstIsSignificant = significant;
        }
    if (count > 0) {
        result.meanSignedDifference = sumDifference / double(count);
        const double meanReference = sumReference / double(count);
        result.relativeMeanDifference =
            result.meanSignedDifference / std::sqrt(meanReference * meanReference + 0.01);
        result.relMse = sumRelSquares / double(count * channels);
    }
    return result;
}

std::string formatAgreement(const ReferenceAgreement& r, const std::string& nameA, const std::string& nameB) {
    if (!r.sizesMatch)
        return fmt::format("{} and {} differ in size: not compared.", nameA, nameB);
    return fmt::format(
        "{} against {}: relMSE {:.2e}, mean signed difference {:+.2e} ({:+.2f}% of the mean), {} of {} "
        "{}-pixel tiles with a significant mean difference (|t| > {:.2f}), {} of them above {:.1f}%; worst "
        "tile "
        "at ({}, {}): {:+.2f}% (t = {:.1f}). Verdict: {}.",
        nameA, nameB, r.relMse, r.meanSignedDifference, 100 * r.relativeMeanDifference, r.significantTiles,
        r.tiles, r.tileSize, r.tThreshold, r.materialTiles, 100 * r.tolerance, r.worstTile.x0, r.worstTile.y0,
        100 * r.worstTile.relativeMean, r.worstTile.t, r.agree() ? "agree" : "DISAGREE");
}

} // namespace drt::bench
