// POV-Ray pigment patterns, evaluated at a world-space point.
#pragma once

#include "core/color.h"
#include "core/vec.h"
#include "scene/scene.h"

namespace drt {

// The pigment's colour (with filter and transmit) at world point p. Each
// pigment, sub-pigments included, is evaluated in its own pattern space
// Pigment::toWorld.inversePoint(p). Missing sub-pigments are black; an empty
// colour map ramps from black to white.
ColorFT evaluatePigment(const Pigment& pigment, const Vec3& worldPoint);

// Pattern values in pattern space, exposed for tests.
int checkerIndex(const Vec3& p);            // 0 or 1
int hexagonIndex(const Vec3& p);            // 0, 1 or 2
int brickIndex(const Vec3& p, const Vec3& brickSize, double mortar); // 0 mortar, 1 brick
double gradientValue(const Vec3& p, const Vec3& axis); // in [0, 1)
double radialValue(const Vec3& p);          // in [0, 1)
double onionValue(const Vec3& p);           // in [0, 1)
double sphericalValue(const Vec3& p);       // max(0, 1 - |p|), in [0, 1]
ColorFT lookupColorMap(const std::vector<ColorMapEntry>& map, double value);

} // namespace drt
