// Solid noise for POV-Ray's noise patterns (bozo, granite, marble, wood, ...)
// and bump normals. drt's own gradient noise (Perlin 2002, "Improving noise":
// quintic fade, gradients on the 12 cube edges chosen by a lattice hash); its
// values differ from POV-Ray's noise tables, only the shapes are alike.
// Everything here is a pure function of its arguments: thread-safe and
// deterministic.
#pragma once

#include "core/vec.h"
#include "scene/scene.h"

namespace drt {

// Gradient noise in [0, 1], 0.5 on every lattice point, continuous with a
// continuous gradient.
double noise01(const Vec3& p);

// Three decorrelated noise values mapped to [-1, 1] (POV-Ray's DNoise).
Vec3 vectorNoise(const Vec3& p);

// POV-Ray's turbulence displacement: sum over octaves i of omega^i DNoise(lambda^i p),
// times the amount. Zero when the amount is zero.
Vec3 turbulenceOffset(const Turbulence& turbulence, const Vec3& p);

// True for the patterns of this header (the scalar-field patterns).
bool isNoisePattern(PatternKind kind);

// The pattern's scalar value in [0, 1] at pattern-space point p, after the
// turbulence warp. For non-noise kinds returns 0.
double noisePatternValue(PatternKind kind, const Turbulence& turbulence, const Vec3& p);

// noisePatternValue shaped by frequency, phase and wave type (render/pattern_wave.h).
// Marble and wood apply the wave to their unwrapped band coordinate, with
// triangle as their own default shape (POV-Ray's).
double wavedNoisePatternValue(PatternKind kind, const Turbulence& turbulence, const PatternWave& wave,
                              const Vec3& p);

// The shading normal tilted by the bump pattern: n' = normalize(n - amount g_t),
// g_t the tangential part of the world-space gradient of the pattern (central
// differences in pattern space, mapped by the inverse transpose). The tilt is
// bounded so n'.n > 0: n' stays on n's side. `normal` must be unit length.
Vec3 perturbNormal(const Normal& bump, const Vec3& worldPoint, const Vec3& normal);

} // namespace drt
