// False-colour pictures of a comparison: the error heatmap and the signed
// z-score map. Colours are chosen in sRGB-encoded space (what a viewer shows)
// and decoded to linear, since writeImage encodes 8-bit files.
#include "compare/compare.h"

#include "compare/statistical.h"
#include "image/srgb.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace drt {

namespace {

using Rgb = std::array<double, 3>;

constexpr Rgb kNonFinite{0.0, 1.0, 0.0};

// Piecewise-linear ramp through evenly spaced key colours, t in [0, 1].
template <size_t N> Rgb ramp(const std::array<Rgb, N>& keys, double t) {
    t = std::clamp(t, 0.0, 1.0) * double(N - 1);
    const size_t i = std::min(size_t(t), N - 2);
    const double f = t - double(i);
    Rgb out;
    for (int c = 0; c < 3; ++c)
        out[c] = keys[i][c] + f * (keys[i + 1][c] - keys[i][c]);
    return out;
}

void put(Image& image, int x, int y, const Rgb& encoded) {
    for (int c = 0; c < 3; ++c)
        image.at(x, y, c) = static_cast<float>(srgbDecode(encoded[c]));
}

} // namespace

Image errorHeatmap(const Image& candidate, const Image& reference, double scale) {
    // black -> purple -> red -> orange -> pale yellow
    static const std::array<Rgb, 5> keys{Rgb{0, 0, 0}, Rgb{0.25, 0.05, 0.55}, Rgb{0.85, 0.2, 0.35},
                                         Rgb{1.0, 0.6, 0.1}, Rgb{1.0, 1.0, 0.85}};
    const int w = std::min(candidate.width, reference.width),
              h = std::min(candidate.height, reference.height);
    const int nc = comparedChannels(candidate, reference);
    Image out(w, h, 3);
    std::vector<double> error(size_t(w) * h, -1); // -1: non-finite
    double largest = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (!pixelIsFinite(candidate, x, y, nc) || !pixelIsFinite(reference, x, y, nc))
                continue;
            double e = 0;
            for (int c = 0; c < nc; ++c)
                e = std::max(e, std::abs(double(candidate.at(x, y, c)) - reference.at(x, y, c)));
            error[size_t(y) * w + x] = e;
            largest = std::max(largest, e);
        }
    if (!(scale > 0))
        scale = largest > 0 ? largest : 1;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double e = error[size_t(y) * w + x];
            // The square root spreads small errors over more of the ramp.
            put(out, x, y, e < 0 ? kNonFinite : ramp(keys, std::sqrt(e / scale)));
        }
    return out;
}

Image zScoreMap(const Image& candidate, const Image& reference, const VarianceImages& variance,
                double limit) {
    // -limit blue, 0 white, +limit red
    static const std::array<Rgb, 3> keys{Rgb{0.1, 0.25, 0.9}, Rgb{1, 1, 1}, Rgb{0.9, 0.1, 0.1}};
    const int w = std::min(candidate.width, reference.width),
              h = std::min(candidate.height, reference.height);
    const int nc = comparedChannels(candidate, reference);
    Image out(w, h, 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double sumError = 0, sumVariance = 0;
            for (int c = 0; c < nc; ++c) {
                sumError += double(candidate.at(x, y, c)) - reference.at(x, y, c);
                sumVariance += differenceVariance(variance, x, y, c);
            }
            if (!std::isfinite(sumError) || !std::isfinite(sumVariance)) {
                put(out, x, y, kNonFinite);
                continue;
            }
            double z =
                sumVariance > 0 ? sumError / std::sqrt(sumVariance) : (sumError == 0 ? 0 : sumError * 1e300);
            put(out, x, y, ramp(keys, 0.5 + 0.5 * std::clamp(z / limit, -1.0, 1.0)));
        }
    return out;
}

} // namespace drt
