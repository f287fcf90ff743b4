// The value of POV-Ray's density_file pattern (scene/density_file.h) at a
// pattern-space point.
#pragma once

#include "core/vec.h"
#include "scene/density_file.h"

namespace drt {

// 0 outside [0, 1)^3 and while the voxels are not read. Inside, the grid
// coordinate is t = p * (nx, ny, nz) and voxel i sits at t = i:
// - None: the voxel floor(t);
// - Trilinear: the voxels floor(t) and floor(t) + 1 on each axis, blended
//   linearly; an index past the last wraps to the first;
// - Tricubic: Catmull-Rom through the voxels floor(t) - 1 .. floor(t) + 2 on each
//   axis, indices wrapping, a negative result 0 (the curve may overshoot 1).
// These are POV-Ray 3.7's rules, measured on its renders of small df3 files.
double densityFileValue(const DensityFile& file, const Vec3& p);

} // namespace drt
