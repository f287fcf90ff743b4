// The film: per-pixel running mean and variance of the mean (Welford's
// algorithm), with non-finite samples counted and dropped.
#pragma once

#include "core/color.h"
#include "core/vec.h"
#include "image/image.h"
#include "sampling/filter.h"
#include "sampling/sampler.h"

#include <cstdint>

namespace drt {

class PixelAccumulator {
public:
    // Returns false (and counts it) for a NaN or infinite sample, which is dropped.
    bool add(const Color& sample) {
        if (!isFinite(sample)) {
            ++nonFinite_;
            return false;
        }
        ++count_;
        // Welford: mean += (x - mean)/n; M2 += (x - mean_old)(x - mean_new).
        const Color delta = sample - mean_;
        mean_ += delta / count_;
        m2_ += delta * (sample - mean_);
        return true;
    }
    int count() const { return count_; }
    uint64_t nonFinite() const { return nonFinite_; }
    Color mean() const { return mean_; }
    // Unbiased sample variance / n; 0 with fewer than two samples.
    Color varianceOfMean() const;

private:
    int count_ = 0;
    uint64_t nonFinite_ = 0;
    Color mean_{0};
    Color m2_{0}; // sum of squared deviations from the mean
};

// The image position of a pixel sample of pixel (x, y) from its pixel
// dimensions (Sampler::getCameraDimensions): the one place the reconstruction
// filter enters. Filter importance sampling: the
// offset from the pixel centre has the filter's density and the sample counts
// with weight 1 in this pixel only (box: uniform over the pixel).
inline Vec2 pixelSamplePosition(const Filter& filter, Vec2 pixelDimensions, int x, int y) {
    const Vec2 offset = sampleFilter(filter, pixelDimensions);
    return {x + 0.5 + offset.x, y + 0.5 + offset.y};
}

// Writes a pixel's mean and variance of the mean into the two images.
void storePixel(const PixelAccumulator& pixel, int x, int y, Image& color, Image& variance);

// POV-Ray's assumed_gamma G: the renderer works on values v that are encoded
// with gamma G, and the image holds the linear values max(v, 0)^G (POV-Ray
// decodes its working colour space this way before writing a file). The
// variance of the mean follows by the delta method: (G v^(G-1))^2 var(v).
// G = 1 leaves both images untouched.
void decodeWorkingGamma(Image& color, Image& variance, double gamma);

} // namespace drt
