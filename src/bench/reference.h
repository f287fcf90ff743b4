// References made of independent renders: their mean, the variance of that
// mean from their spread, and the reference's own share of a measured relMSE.
#pragma once

#include "image/image.h"

#include <vector>

namespace drt::bench {

struct AveragedImage {
    Image mean;
    Image varianceOfMean; // sum_k (m_k - m)^2 / (K (K - 1)); zeros for one part
};

// The per-pixel mean of K same-sized independent renders and the variance of
// that mean from their spread. One stratified render's own sample variance / N
// over-states its mean's variance many times over; the spread of independent
// renders (different scrambling seeds) does not. Non-finite values become 0.
AveragedImage averageImages(const std::vector<Image>& parts);

// Mean over pixels and channels of Var(r) / (r^2 + 0.01): what a noisy
// reference adds to every candidate's expected relMSE, since
// E[(x - r_noisy)^2] = (x - r_true)^2 + Var(r) for independent x and r.
double referenceNoise(const Image& reference, const Image& varianceOfMean);

} // namespace drt::bench
