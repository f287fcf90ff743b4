// POV-Ray's pattern value modifiers (frequency, phase, wave types) applied to
// a pattern value before the colour-map, pigment-map or texture-map lookup.
#pragma once

#include "scene/pattern_wave.h"

namespace drt {

// The wave shape at t in [0, 1]:
//   ramp t, triangle 2t below 1/2 and 2 - 2t above, sine (1 + sin 2 pi t) / 2,
//   scallop |sin pi t|, cubic 3t^2 - 2t^3, poly t^exponent.
double waveShape(WaveKind kind, double t, double exponent);

// POV-Ray's order: t = fmod(v frequency + phase, 1.00001) (skipped when the
// frequency is 0), plus 1 - floor(t) when negative, then the wave shape.
// The period 1.00001 is POV-Ray's: it keeps a value of exactly 1 at 1.
// `patternDefault` is the shape used for WaveKind::PatternDefault.
// Non-finite v gives 0; a non-finite shape (0 to a negative power) gives 1.
double applyPatternWave(const PatternWave& wave, double v, WaveKind patternDefault = WaveKind::Ramp);

} // namespace drt
