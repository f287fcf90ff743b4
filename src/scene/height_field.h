// POV-Ray's height_field as a triangle mesh: a grid of heights over the unit
// square in x-z, one vertex per sample, two triangles per cell.
#pragma once

#include "scene/scene.h"

#include <vector>

namespace drt {

// `heights` holds columns x = 0..columns-1 of rows z = 0..rows-1, row-major,
// z row 0 first; vertex (x, z) sits at (x / (columns-1), height, z / (rows-1)).
// Each cell is split along the diagonal from (x+1, z) to (x, z+1), as POV-Ray
// does. Triangles whose three corners all lie below `waterLevel` are left out
// (POV-Ray clips the surface at that height). `smooth` adds vertex normals:
// the area-weighted mean of the adjoining triangles' normals.
Mesh heightFieldMesh(const std::vector<double>& heights, int columns, int rows, bool smooth, double waterLevel);

} // namespace drt
