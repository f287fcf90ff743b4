// Do two renderers' converged references show the same picture? Two
// references with negligible noise differ only by bias: a different estimator
// limit (a light sampled on another grid, another pixel filter) or a
// different reading of the scene. The check is the mean signed difference
// over the whole image and over tiles. Neither image needs a variance image:
// a tile's standard error comes from the spread of its per-pixel differences,
// so a tile is flagged only when its mean difference is both significant
// (|t| above a Sidak-corrected two-sided normal bound over all tiles) and
// material (above `tolerance`, relative to the tile's brightness, in the
// normalisation of relMSE: |mean(a - b)| / sqrt(mean(b)^2 + 0.01)).
#pragma once

#include "image/image.h"

#include <string>

namespace drt::bench {

struct AgreementOptions {
    int tileSize = 16;
    double alpha = 0.01;     // family-wise false-alarm rate over the tiles
    double tolerance = 0.01; // relative mean difference that counts as material
};

struct TileDifference {
    int x0 = 0, y0 = 0;      // top-left pixel
    double relativeMean = 0; // mean(a - b) / sqrt(mean(b)^2 + 0.01), channels pooled
    double t = 0;            // mean(a - b) / (sd(a - b) / sqrt(n))
};

struct ReferenceAgreement {
    bool sizesMatch = true;
    double relMse = 0;                 // of a against b: mean (a - b)^2 / (b^2 + 0.01)
    double meanSignedDifference = 0;   // mean (a - b) over pixels and channels
    double relativeMeanDifference = 0; // that, / sqrt(mean(b)^2 + 0.01)
    int tiles = 0;
    int significantTiles = 0; // |t| above the bound
    int materialTiles = 0;    // significant and |relativeMean| > tolerance
    double tThreshold = 0;
    TileDifference worstTile; // largest |relativeMean| among significant tiles (else overall)
    bool agree() const;       // sizes match, |relative mean| <= tolerance and no material tile
    double tolerance = 0;
    int tileSize = 0;
};

ReferenceAgreement compareReferences(const Image& a, const Image& b, const AgreementOptions& options = {});

// One paragraph for a report.
std::string formatAgreement(const ReferenceAgreement& agreement, const std::string& nameA,
                            const std::string& nameB);

} // namespace drt::bench
