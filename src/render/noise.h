// Solid noise for POV-Ray's noise patterns (bozo, granite, marble, wood, ...)
// and bump normals (render/normal_pattern.h). drt's own gradient noise
// (Perlin 2002, "Improving noise": quintic fade, gradients on the 12 cube
// edges chosen by a lattice hash); its values differ from POV-Ray's noise
// tables, but its distribution matches (mean 0.5, standard deviation 0.13
// against POV-Ray's 0.126, measured over 20000 random points).
// Everything here is a pure function of its arguments: thread-safe and
// deterministic.
#pragma once

#include "core/vec.h"
#include "scene/scene.h"

#include <array>

namespace drt {

// Gradient noise in [0, 1], 0.5 on every lattice point, continuous with a
// continuous gradient.
double noise01(const Vec3& p);

// Three decorrelated noise values mapped to [-1, 1] (POV-Ray's DNoise).
Vec3 vectorNoise(const Vec3& p);

// POV-Ray's turbulence displacement: sum over octaves i of omega^i DNoise(lambda^i p),
// times the amount. Zero when the amount is zero.
Vec3 turbulenceOffset(const Turbulence& turbulence, const Vec3& p);

// POV-Ray's wave sources for the waves and ripples patterns and normals.
constexpr int kWaveCount = 10;
struct WaveSource {
    Vec3 centre;      // a unit vector
    double frequency; // waves only: the source's own frequency factor, in [0.01, 1.01]
};
const std::array<WaveSource, kWaveCount>& povWaveSources();

// True for the patterns of this header (the scalar-field patterns).
bool isNoisePattern(PatternKind kind);

// Where POV-Ray evaluates a pattern: p displaced by the turbulence, except
// for marble and wood, whose formulas take the turbulence themselves.
Vec3 warpPatternPoint(PatternKind kind, const Turbulence& turbulence, const Vec3& p);

// POV-Ray's scalar turbulence (marble, agate): the first octave
// clip(2 N(p) - 0.5, 0, 1), then omega^(i-1) (2 N(lambda^(i-1) p) - 0.5) for
// octaves i = 2..octaves (the amount is not applied).
double scalarTurbulence(const Turbulence& turbulence, const Vec3& p);

// The pattern's value at pattern-space point p as POV-Ray's pattern step
// gives it: the pattern's own formula (POV-Ray 3.7's; the noise is drt's),
// then fmod(v frequency + phase, 1.00001) and the wave type (triangle by
// default for marble and wood). Waves and ripples also use the frequency and
// phase inside their formula, as POV-Ray does. For non-noise kinds returns 0.
double wavedNoisePatternValue(PatternKind kind, const Turbulence& turbulence, const PatternWave& wave,
                              const Vec3& p);
// The same at a point already moved by warpPatternPoint.
double noisePatternAtWarped(PatternKind kind, const Turbulence& turbulence, const PatternWave& wave, const Vec3& q);
// wavedNoisePatternValue with the default frequency, phase and wave.
double noisePatternValue(PatternKind kind, const Turbulence& turbulence, const Vec3& p);

// The shading normal tilted by a normal pattern, as POV-Ray does it
// (render/normal_pattern.cpp): the unit normal is carried into pattern space
// (by the transpose of the pattern's transform) and normalised, the pattern
// adds its perturbation there, and the result is carried back and normalised.
// So scaling a pattern down makes its bumps smaller, not steeper. `normal`
// must be unit length; the result is unit length and never NaN.
Vec3 perturbNormal(const Normal& bump, const Vec3& worldPoint, const Vec3& normal);
// The height a slope_map gives pattern value v: below the first entry its
// height, above the last entry that one's, between two entries the cubic
// Hermite curve through their heights with their slopes per unit of the
// interval (POV-Ray's rule: [0 <0, 1>] [1 <1, 1>] is the straight ramp).
double slopeMapHeight(const std::vector<SlopeMapEntry>& map, double v);
// The same for a uv-mapped normal (Normal::uvMapping): the pattern at the
// surface's (u, v, 0), its tilt carried to the surface by the tangent frame
// dpdu, dpdv (Hit) with the normal as third axis, stretched by the frame's mean
// scale sqrt(|dpdu x dpdv|), so a uniformly scaled uv layout keeps the bumps'
// slopes as a uniformly scaled object does. Normals map by the frame's inverse
// transpose, so a pattern slope along u tilts the normal along the gradient of
// u on the surface. A degenerate frame leaves the normal as it is.
Vec3 perturbNormalUv(const Normal& bump, const Vec3& uv, const Vec3& dpdu, const Vec3& dpdv, const Vec3& normal);

} // namespace drt
