// POV-Ray's image_map pigment: an image file projected onto the unit square
// (planar), a sphere, a cylinder or a torus. The front end finds the file; its
// pixels are decoded once, after parsing (assets/assets.h); render/image_pattern.h
// evaluates the map.
#pragma once

#include "core/diagnostics.h"

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

    // Decoded texels, linear RGB and transmit (1 - alpha), rows top first;
    // empty until the assets are resolved.
    int width = 0;
    int height = 0;
    std::vector<float> rgbt; // 4 floats per texel
};

} // namespace drt
