// The sRGB transfer curve (IEC 61966-2-1), used by every 8-bit and 16-bit
// image drt writes or reads, and by the tonemapped metrics of `drt compare`.
#pragma once

#include <algorithm>
#include <cmath>

namespace drt {

// Linear [0, 1] -> encoded [0, 1]:
//   12.92 v                     if v <= 0.0031308
//   1.055 v^(1/2.4) - 0.055     otherwise
// Values outside [0, 1] are clamped first; NaN encodes as 0.
inline double srgbEncode(double linear) {
    if (!(linear > 0))
        return 0; // also catches NaN
    if (linear >= 1)
        return 1;
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

// Encoded [0, 1] -> linear [0, 1], the exact inverse of srgbEncode:
//   v / 12.92                   if v <= 0.04045
//   ((v + 0.055) / 1.055)^2.4   otherwise
inline double srgbDecode(double encoded) {
    if (!(encoded > 0))
        return 0;
    if (encoded >= 1)
        return 1;
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

} // namespace drt
