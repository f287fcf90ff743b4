// Private to src/compare: the statistical tests and helpers they share with
// the metrics.
#pragma once

#include "compare/compare.h"

namespace drt {

// Channels compared: those both images have, at most 3.
int comparedChannels(const Image& a, const Image& b);
bool pixelIsFinite(const Image& image, int x, int y, int channels);

// Variance of (candidate - reference) at a pixel and channel: the sum of the
// given variance images (a one-channel variance image applies to every channel).
double differenceVariance(const VarianceImages& variance, int x, int y, int c);
bool varianceIsFinite(const VarianceImages& variance, int x, int y, int channels);

// Fills the statistical fields of `r` (globalZ, tile tests, outliers).
void runStatisticalTests(const Image& candidate, const Image& reference, const VarianceImages& variance,
                         const CompareOptions& options, CompareResult& r);

} // namespace drt
