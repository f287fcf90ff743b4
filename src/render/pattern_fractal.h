// The value of POV-Ray 3.7's fractal patterns (scene/fractal_pattern.h) at a
// pattern-space point (x, y), before the pattern's wave and frequency.
//
// The orbit z_0, z_1, ... starts at z_0 = (x, y) (mandel, julia and the julia
// forms of magnet) or z_0 = 0 (the mandel forms of magnet). The point escapes
// at step i (0-based) when z_{i+1} leaves the bailout: |z|^2 > 4 for mandel and
// julia; |z|^2 > 10^4, or |z - 1|^2 < 10^-4 (the orbit has settled on 1), for
// magnet. An escaping point's value is its exterior colouring of i and
// z = z_{i+1}, with factor F:
//   0: F   1: i / ITERATIONS   2: Re z F   3: Im z F   4: (Re z)^2 F
//   5: (Im z)^2 F   6: |z| F   7: fmod(i, F) / F   8: fmod(i, F + 1) / F
// A point that does not escape within ITERATIONS steps takes its interior
// colouring of the last z and of m, the smallest |z_k|^2 (k >= 1, and |x + iy|^2):
//   0: F   1: sqrt(m) F   2-5: as the exterior's   6: (Re z)^2 + (Im z)^2 F
// (type 6 of the interior is POV-Ray's as it renders, not as documented).
#pragma once

#include "scene/fractal_pattern.h"

namespace drt {

double fractalValue(const FractalPattern& fractal, double x, double y);

} // namespace drt
