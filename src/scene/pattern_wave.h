#pragma once

#include <optional>
#include <string_view>
#include <utility>

namespace drt {

// POV-Ray's wave types: the shape given to a pattern value after frequency and phase.
enum class WaveKind {
    PatternDefault, // the pattern's own shape: ramp, or triangle for marble and wood
    Ramp,
    Triangle,
    Sine,
    Scallop,
    Cubic,
    Poly,
};

// POV-Ray's pattern value modifiers `frequency f`, `phase p` and the wave type:
// a value v becomes wave(fmod(v f + p, 1.00001)) (wrapped into [0, 1) when
// negative) before the colour-map lookup. The defaults leave v unchanged.
struct PatternWave {
    WaveKind kind = WaveKind::PatternDefault;
    double frequency = 1;
    double phase = 0;
    double exponent = 1; // poly_wave's exponent
    bool isIdentity() const { return kind == WaveKind::PatternDefault && frequency == 1 && phase == 0; }
};

// The keyword of each wave type, shared by both front ends and the writer.
inline constexpr std::pair<std::string_view, WaveKind> kWaveKeywords[] = {
    {"ramp_wave", WaveKind::Ramp},       {"triangle_wave", WaveKind::Triangle}, {"sine_wave", WaveKind::Sine},
    {"scallop_wave", WaveKind::Scallop}, {"cubic_wave", WaveKind::Cubic},       {"poly_wave", WaveKind::Poly}};

inline std::optional<WaveKind> waveKindNamed(std::string_view word) {
    for (const auto& [keyword, kind] : kWaveKeywords)
        if (keyword == word) return kind;
    return std::nullopt;
}

inline std::string_view waveKeyword(WaveKind kind) {
    for (const auto& [keyword, k] : kWaveKeywords)
        if (k == kind) return keyword;
    return {};
}

} // namespace drt
