// Axis-aligned bounds of scene-model objects, as POV-Ray computes them for
// min_extent / max_extent: each shape's box in its own space, its eight
// corners taken through the object's transform; unions and merges join their
// members' boxes, intersections overlap them, a difference keeps its first
// member's box; clipped_by narrows the box to its bounded clips. Shapes with
// no finite box (planes, inverted objects, and shapes this file does not know)
// are unbounded: +-kUnboundedExtent on every axis, as POV-Ray's BOUND_HUGE / 2.
#pragma once

#include "core/vec.h"
#include "scene/scene.h"

namespace drt {

inline constexpr double kUnboundedExtent = 1e10;

// Bounds in the space Object::transform maps to (world for a top-level
// object). Returns false, with the unbounded box, when there is no finite box.
bool objectBounds(const Object& object, Vec3& lower, Vec3& upper);

} // namespace drt
