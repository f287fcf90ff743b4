// drt_wide_compare DRT_IMAGE POV_IMAGE [DIFF_PNG]
//
// Prints the wide cross-check's figure (wide_figure.h: mean absolute sRGB
// difference after 4x4 downsampling) on one line; with DIFF_PNG also writes
// the largest channel difference of each downsampled pixel (white is 0.25 or
// more), scaled back up to the input size.
//
// Exit status: 0 the figure was printed, 3 an image could not be read or
// written or the sizes differ.
#include "pov_crosscheck/wide_figure.h"

#include <cstdio>
#include <string>
#include <utility>

int main(int argc, char** argv) {
    if (argc != 3 && argc != 4) {
        std::fprintf(stderr, "usage: drt_wide_compare DRT_IMAGE POV_IMAGE [DIFF_PNG]\n");
        return 2;
    }
    drt::Image drtImage, povImage;
    for (auto [path, image] : {std::pair{argv[1], &drtImage}, std::pair{argv[2], &povImage}}) {
        const std::string problem = drt::readImage(path, *image);
        if (!problem.empty()) {
            std::fprintf(stderr, "drt_wide_compare: %s: %s\n", path, problem.c_str());
            return 3;
        }
    }
    if (drtImage.width != povImage.width || drtImage.height != povImage.height) {
        std::fprintf(stderr, "drt_wide_compare: sizes differ: %dx%d and %dx%d\n", drtImage.width,
                     drtImage.height, povImage.width, povImage.height);
        return 3;
    }
    drt::Image largest;
    std::printf("%.5f\n", drt::wide::meanAbsoluteSrgbDifference(drtImage, povImage, &largest));
    if (argc == 4) {
        drt::Image diff(drtImage.width, drtImage.height, 3);
        for (int y = 0; y < diff.height; ++y)
            for (int x = 0; x < diff.width; ++x) {
                const double e = largest.at(x / drt::wide::kBlock, y / drt::wide::kBlock, 0);
                const float shade = float(drt::srgbDecode(std::min(1.0, e / 0.25)));
                for (int c = 0; c < 3; ++c) diff.at(x, y, c) = shade;
            }
        const std::string problem = drt::writeImage(argv[3], diff);
        if (!problem.empty()) {
            std::fprintf(stderr, "drt_wide_compare: %s: %s\n", argv[3], problem.c_str());
            return 3;
        }
    }
    return 0;
}
