#include "render/pattern_wave.h"

#include "core/vec.h"

#include <cmath>

namespace drt {

double waveShape(WaveKind kind, double t, double exponent) {
    switch (kind) {
    case WaveKind::PatternDefault:
    case WaveKind::Ramp: return t;
    case WaveKind::Triangle: {
        const double f = t - std::floor(t);
        return f < 0.5 ? 2 * f : 2 * (1 - f);
    }
    case WaveKind::Sine: return 0.5 * (1 + std::sin(2 * kPi * t));
    case WaveKind::Scallop: return std::fabs(std::sin(kPi * t));
    case WaveKind::Cubic: return t * t * (3 - 2 * t);
    case WaveKind::Poly: return std::pow(t, exponent);
    }
    return t;
}

double applyPatternWave(const PatternWave& wave, double v, WaveKind patternDefault) {
    if (!std::isfinite(v)) return 0;
    constexpr double kPovPeriod = 1.00001;
    if (wave.frequency != 0) v = std::fmod(v * wave.frequency + wave.phase, kPovPeriod);
    if (v < 0) v -= std::floor(v);
    if (!std::isfinite(v)) return 0;
    const WaveKind kind = wave.kind == WaveKind::PatternDefault ? patternDefault : wave.kind;
    const double shaped = waveShape(kind, v, wave.exponent);
    return std::isfinite(shaped) ? shaped : 1.0;
}

} // namespace drt
