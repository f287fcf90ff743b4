// POV-Ray's density_file pattern: a block of voxels read from a df3 file and
// laid over the unit cube from <0, 0, 0> to <1, 1, 1>; outside it the pattern
// is 0. The front end finds the file; its voxels are read once, after parsing
// (assets/assets.h); render/density_file_pattern.h evaluates it.
#pragma once

#include "core/diagnostics.h"

#include <string>
#include <vector>

namespace drt {

struct DensityFile {
    enum class Interpolation { None = 0, Trilinear = 1, Tricubic = 2 };

    std::string file; // as written in the scene
    std::string path; // where it was found
    SourceLoc loc;    // the file name in the scene
    Interpolation interpolation = Interpolation::None;

    // The voxels in [0, 1], x fastest, then y, then z; empty until the assets
    // are resolved.
    int nx = 0;
    int ny = 0;
    int nz = 0;
    std::vector<float> values;
};

} // namespace drt
