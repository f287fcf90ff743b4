// The figure of the wide cross-check (wide.sh) and of the fidelity tests:
// both images are box-filtered 4x4 in linear values (so an edge that the two
// renderers anti-alias differently averages out), encoded to sRGB in [0, 1],
// and compared by the mean over pixels and the three colour channels of
// |a - b|. Partial blocks at the right and bottom edges average what they have.
#pragma once

#include "image/image.h"
#include "image/srgb.h"

#include <algorithm>
#include <cmath>

namespace drt::wide {

constexpr int kBlock = 4;

inline Image downsampleEncoded(const Image& in) {
    const int w = (in.width + kBlock - 1) / kBlock, h = (in.height + kBlock - 1) / kBlock;
    Image out(w, h, 3);
    for (int by = 0; by < h; ++by)
        for (int bx = 0; bx < w; ++bx)
            for (int c = 0; c < 3; ++c) {
                double sum = 0;
                int n = 0;
                for (int y = by * kBlock; y < std::min(in.height, (by + 1) * kBlock); ++y)
                    for (int x = bx * kBlock; x < std::min(in.width, (bx + 1) * kBlock); ++x, ++n)
                        sum += in.at(x, y, std::min(c, in.channels - 1));
                out.at(bx, by, c) = float(srgbEncode(sum / n));
            }
    return out;
}

// The figure; the images must have the same size. With `largest`, also the
// largest channel difference of each downsampled pixel (size w/4 x h/4).
inline double meanAbsoluteSrgbDifference(const Image& a, const Image& b, Image* largest = nullptr) {
    const Image da = downsampleEncoded(a), db = downsampleEncoded(b);
    if (largest) *largest = Image(da.width, da.height, 1);
    double sum = 0;
    for (int y = 0; y < da.height; ++y)
        for (int x = 0; x < da.width; ++x) {
            double most = 0;
            for (int c = 0; c < 3; ++c) {
                const double e = std::fabs(double(da.at(x, y, c)) - double(db.at(x, y, c)));
                sum += e;
                most = std::max(most, e);
            }
            if (largest) largest->at(x, y, 0) = float(most);
        }
    return sum / (double(da.width) * da.height * 3);
}

} // namespace drt::wide
