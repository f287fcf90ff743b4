#include "render/film.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace drt {

Color PixelAccumulator::varianceOfMean() const {
    if (count_ < 2) return Color(0);
    return m2_ / (double(count_ - 1) * count_);
}

namespace {

// A finite double beyond float range would become infinite in the image.
float toFiniteFloat(double v) {
    constexpr double limit = std::numeric_limits<float>::max();
    return static_cast<float>(std::clamp(v, -limit, limit));
}

} // namespace

void storePixel(const PixelAccumulator& pixel, int x, int y, Image& color, Image& variance) {
    const Color mean = pixel.mean();
    const Color var = pixel.varianceOfMean();
    for (int c = 0; c < 3; ++c) {
        color.at(x, y, c) = toFiniteFloat(mean[c]);
        variance.at(x, y, c) = toFiniteFloat(var[c]);
    }
}

void decodeWorkingGamma(Image& color, Image& variance, double gamma) {
    if (gamma == 1.0 || !(gamma > 0) || !std::isfinite(gamma)) return;
    for (int y = 0; y < color.height; ++y)
        for (int x = 0; x < color.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const double v = std::max(0.0, double(color.at(x, y, c)));
                const double slope = v > 0 ? gamma * std::pow(v, gamma - 1) : (gamma > 1 ? 0.0 : gamma);
                color.at(x, y, c) = toFiniteFloat(std::pow(v, gamma));
                variance.at(x, y, c) = toFiniteFloat(slope * slope * double(variance.at(x, y, c)));
            }
}

} // namespace drt
