// Pixel reconstruction filters, applied by filter importance sampling: each
// camera sample's offset from the pixel centre is drawn with density equal to
// the normalised filter, and the sample counts with weight 1 in its own pixel
// only. Pixels stay independent (determinism, no splatting across tiles), and
// the pixel estimate is the filter-weighted average of the image.
//
//   name        support (pixels)         density of the offset (per axis, separable)
//   box         [-0.5, 0.5]              uniform (the default)
//   tent        [-1, 1]                  1 - |x|
//   gaussian    [-1.5, 1.5]              exp(-x^2 / (2 sigma^2)), sigma = 0.5, truncated
#pragma once

#include "core/vec.h"

#include <string>
#include <vector>

namespace drt {

enum class FilterType { Box, Tent, Gaussian };

struct Filter {
    FilterType type = FilterType::Box;
    double radius = 0.5; // half-width of the support in pixels
    double sigma = 0.5;  // Gaussian standard deviation in pixels
};

// Names accepted by the scene's and the command line's filter setting; throws
// std::invalid_argument naming the accepted values otherwise.
Filter makeFilter(const std::string& name);
const std::vector<std::string>& filterNames();
std::string defaultFilterName(); // "box"
std::string filterName(const Filter& filter);

// Offset from the pixel centre, in pixels, for a uniform u in [0, 1)^2.
// The offset from the pixel centre for uniform u in [0,1)^2, with the filter's
// density. The box filter, the default, is inline: every camera sample asks.
Vec2 sampleFilterShaped(const Filter& filter, Vec2 u); // tent, Gaussian (and box)
inline Vec2 sampleFilter(const Filter& filter, Vec2 u) {
    if (filter.type == FilterType::Box) return {(2.0 * u.x - 1.0) * filter.radius, (2.0 * u.y - 1.0) * filter.radius};
    return sampleFilterShaped(filter, u);
}
// The normalised filter: the density of sampleFilter's offsets (per pixel^2).
double filterPdf(const Filter& filter, Vec2 offset);

} // namespace drt
