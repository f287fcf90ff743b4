#include "bench/reference.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace drt::bench {

AveragedImage averageImages(const std::vector<Image>& parts) {
    AveragedImage result;
    if (parts.empty())
        return result;
    const Image& first = parts.front();
    result.mean = Image(first.width, first.height, first.channels);
    result.varianceOfMean = Image(first.width, first.height, first.channels);
    const double k = double(parts.size());
    for (size_t i = 0; i < first.pixels.size(); ++i) {
        double mean = 0, squares = 0;
        for (const Image& part : parts)
            mean += part.pixels[i] / k;
        for (const Image& part : parts)
            squares += (part.pixels[i] - mean) * (part.pixels[i] - mean);
        const double variance = parts.size() > 1 ? squares / (k * (k - 1)) : 0.0;
        result.mean.pixels[i] = std::isfinite(mean) ? float(mean) : 0.0f;
        result.varianceOfMean.pixels[i] = std::isfinite(variance) ? float(variance) : 0.0f;
    }
    return result;
}

double referenceNoise(const Image& reference, const Image& varianceOfMean) {
    if (varianceOfMean.width != reference.width || varianceOfMean.height != reference.height)
        return 0;
    double sum = 0;
    int64_t count = 0;
    const int channels = std::min(3, reference.channels);
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x)
            for (int c = 0; c < channels; ++c) {
                const double r = reference.at(x, y, c);
                const double v = varianceOfMean.at(x, y, std::min(c, varianceOfMean.channels - 1));
                if (std::isfinite(r) && std::isfinite(v))
                    sum += v / (r * r + 0.01), ++count;
            }
    return count ? sum / double(count) : 0;
}

} // namespace drt::bench
