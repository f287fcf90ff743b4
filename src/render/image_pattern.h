// Evaluating an image_map pigment (scene/image_map.h) at a pattern-space point.
#pragma once

#include "core/color.h"
#include "core/vec.h"
#include "scene/image_map.h"

namespace drt {

// POV-Ray's image_map: the point is projected to image coordinates (planar:
// x, y in the unit square, image bottom at y = 0; spherical, cylindrical and
// torus around the y axis), repeated unless `once`, and looked up without
// interpolation, bilinearly, bicubically (Catmull-Rom) or by normalised distance. Off the map (once, or
// a point on the projection's axis) the colour is clear: white, transmit 1.
ColorFT imageMapColor(const ImageMap& map, const Vec3& p);

// POV-Ray's image_pattern: the grey 0.297 r + 0.589 g + 0.114 b of the texel
// imageMapColor finds (the file's own numbers: ImageMap::fileValues), alpha
// ignored; 0 off the map (measured on POV-Ray 3.7).
double imagePatternValue(const ImageMap& map, const Vec3& p);

// A material_map's index at a pattern-space point: the nearest texel's palette
// index (ImageMap::indices), projected as imageMapColor projects; 0 off the map.
int imageMapIndex(const ImageMap& map, const Vec3& p);

} // namespace drt
