// Lights over the shutter: each shading point sees every light as it is at
// its ray's own time.
//
// A light moves by keys (its position, point_at and area-light axes as
// written at several times, from an animated scene evaluated at several clock
// values over the shutter; interpolated linearly) and then by its motion
// chain (scene/motion.h): the position and point_at move as points, the area
// axes as vectors, so an area light turns with its motion.
#pragma once

#include "scene/scene.h"

namespace drt {

// True if the light changes over time.
inline bool lightMoves(const Light& light) { return light.motion != nullptr; }

// The light at `time` (a copy without motion). A zero-length shutter uses it
// once, at that time: the same arithmetic as a still light placed there.
Light lightAt(const Light& light, double time);

} // namespace drt
