// POV-Ray's image_map pigment: an image file projected onto the unit square
// (planar), a sphere, a cylinder or a torus. The front end finds the file; its
// pixels are decoded once, after parsing (assets/assets.h); render/image_pattern.h
// evaluates the map.
#pragma once

#include "core/diagnostics.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace drt {

struct ImageMap {
    enum class Projection { Planar = 0, Spherical = 1, Cylindrical = 2, Torus = 5 };
    enum class Interpolation { None = 0, Bilinear = 2, Bicubic = 3, NormalizedDistance = 4 };

    std::string file; // as written in the scene
    std::string path; // where it was found
    SourceLoc loc;    // the file name in the scene
    Projection projection = Projection::Planar;
    Interpolation interpolation = Interpolation::None;
    bool once = false;     // no repetition: outside the unit square the map is clear
    double filterAll = 0;  // added to every texel's filter
    double transmitAll = 0; // added to every texel's transmit (1 - alpha)
    double gamma = 0;      // the file's encoding exponent; 0: sRGB for integer files, linear for float files
    double workingGamma = 1; // the scene's assumed_gamma: texels are encoded with it (c^(1/g)) as scene colours are
    // image_pattern: the texels are the file's own numbers (0..1), not decoded
    // by any gamma (POV-Ray's pattern value is their grey; workingGamma 1).
    bool fileValues = false;

    // POV-Ray's per-index amounts of a palette image (`filter N, a`, `transmit N, a`): the texels whose palette
    // index is N get filter a (transmit a, in place of the file's alpha). An image without a palette has no
    // indices; the amounts are then left out with a warning.
    struct IndexAmount {
        int index = 0;
        double amount = 0;
    };
    std::vector<IndexAmount> indexFilter, indexTransmit;
    // A material_map's image: the texel picks a texture by its palette index, or without a palette by its
    // 8-bit red value, modulo the number of textures (render/image_pattern.h imageMapIndex).
    bool material = false;
    bool needsIndices() const { return material || !indexFilter.empty() || !indexTransmit.empty(); }

    // Decoded texels, linear RGB and transmit (1 - alpha), rows top first;
    // empty until the assets are resolved.
    int width = 0;
    int height = 0;
    std::vector<float> rgbt; // 4 floats per texel
    std::vector<uint8_t> indices; // per texel, for a material_map (palette index, or red value 0-255)
    std::vector<float> filter;    // per texel, only when a per-index filter is given (else filterAll alone)
};

} // namespace drt
