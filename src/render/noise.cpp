#include "render/noise.h"

#include "render/pattern_wave.h"

#include "core/hash.h"
#include "core/limits.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

namespace drt {

namespace {

// Perlin's quintic fade 6t^5 - 15t^4 + 10t^3: zero first and second derivative at 0 and 1.
double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }

double lerp(double a, double b, double t) { return a + t * (b - a); }

// The gradient of a lattice point is one of the 12 edge directions of the cube,
// (+-1, +-1, 0) etc., picked by hashValues({i, j, k, seed}) % 12 of the point's
// integer coordinates and a seed. hashValues is a chain, h <- step(h, value), so
// the 8 corners of a cell share their first three steps: a cell is hashed once
// (2 + 4 + 8 steps instead of 24) and each seed adds one step per corner.
constexpr uint64_t kHashStart = 0x9e3779b97f4a7c15ULL;
constexpr uint64_t hashStep(uint64_t h, uint64_t value) {
    return mix64(h ^ (value + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2)));
}
static_assert(hashStep(hashStep(hashStep(hashStep(kHashStart, 3), 5), 7), 2) == hashValues({3, 5, 7, 2}));

// Dot product of gradient h (0..11) with the offset (x, y, z): h / 4 picks the
// pair of axes (x y, x z, y z), bit 0 negates the first, bit 1 the second, by
// flipping the sign bit (without branches: h is random, a branch on it
// mispredicts half the time). `-x + y` and `x - y` are the same IEEE operations
// as (-x) + y and x + (-y).
double gradientDot(uint64_t h, double x, double y, double z) {
    const double axes[3] = {x, y, z};
    const uint64_t first = std::bit_cast<uint64_t>(axes[h >> 3]) ^ ((h & 1) << 63);
    const uint64_t second = std::bit_cast<uint64_t>(axes[1 + ((h + 4) >> 3)]) ^ ((h & 2) << 62);
    return std::bit_cast<double>(first) + std::bit_cast<double>(second);
}

// A point's lattice cell: the offsets from its lower corner, their fades, and
// the corners' hashes before the seed, corner (a, b, c) at index 4a + 2b + c.
struct NoiseCell {
    bool finite = false;
    double x = 0, y = 0, z = 0, u = 0, v = 0, w = 0;
    uint64_t corner[8] = {};
};

NoiseCell noiseCell(const Vec3& p) {
    NoiseCell cell;
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return cell;
    cell.finite = true;
    const double fx = std::floor(p.x), fy = std::floor(p.y), fz = std::floor(p.z);
    const uint64_t i = uint64_t(saturatingInteger(fx)), j = uint64_t(saturatingInteger(fy)),
                   k = uint64_t(saturatingInteger(fz));
    cell.x = p.x - fx, cell.y = p.y - fy, cell.z = p.z - fz;
    cell.u = fade(cell.x), cell.v = fade(cell.y), cell.w = fade(cell.z);
    for (uint64_t a = 0; a < 2; ++a) {
        const uint64_t hi = hashStep(kHashStart, i + a);
        for (uint64_t b = 0; b < 2; ++b) {
            const uint64_t hij = hashStep(hi, j + b);
            cell.corner[4 * a + 2 * b] = hashStep(hij, k);
            cell.corner[4 * a + 2 * b + 1] = hashStep(hij, k + 1);
        }
    }
    return cell;
}

// Signed gradient noise, roughly in [-1, 1], of the cell's point for one seed.
double cellNoise(const NoiseCell& cell, uint64_t seed) {
    if (!cell.finite) return 0;
    const double x = cell.x, y = cell.y, z = cell.z;
    auto g = [&](int a, int b, int c) {
        return gradientDot(hashStep(cell.corner[4 * a + 2 * b + c], seed) % 12, x - a, y - b, z - c);
    };
    const double x00 = lerp(g(0, 0, 0), g(1, 0, 0), cell.u), x10 = lerp(g(0, 1, 0), g(1, 1, 0), cell.u);
    const double x01 = lerp(g(0, 0, 1), g(1, 0, 1), cell.u), x11 = lerp(g(0, 1, 1), g(1, 1, 1), cell.u);
    return lerp(lerp(x00, x10, cell.v), lerp(x01, x11, cell.v), cell.w);
}

double clamp01(double v) { return std::isfinite(v) ? std::clamp(v, 0.0, 1.0) : 0.0; }

// Cellular (Worley) F2 - F1 distance with one jittered feature point per unit cell.
double crackleValue(const Vec3& p) {
    const double fx = std::floor(p.x), fy = std::floor(p.y), fz = std::floor(p.z);
    double f1 = 1e9, f2 = 1e9;
    for (int a = -1; a <= 1; ++a)
        for (int b = -1; b <= 1; ++b)
            for (int c = -1; c <= 1; ++c) {
                const Vec3 cell(fx + a, fy + b, fz + c);
                const uint64_t h = hashValues({static_cast<uint64_t>(saturatingInteger(cell.x)),
                                               static_cast<uint64_t>(saturatingInteger(cell.y)),
                                               static_cast<uint64_t>(saturatingInteger(cell.z)), 77});
                const Vec3 feature = cell + Vec3(unitFromHash(mix64(h)), unitFromHash(mix64(h + 1)),
                                                 unitFromHash(mix64(h + 2)));
                const double d = length(feature - p);
                if (d < f1) f2 = f1, f1 = d;
                else if (d < f2) f2 = d;
            }
    return clamp01(f2 - f1);
}

// POV-Ray's waves and ripples, with the pattern's frequency F and phase
// phi (used here and again by the general frequency step): with d_i the
// distance to source i (1 when 0),
//   ripples 0.5 (1 + sum sin(2 pi (d_i F + phi)) / 10),
//   waves   0.2 (2.5 + sum sin(2 pi (d_i F f_i + phi)) / f_i / 10).
double wavesValue(const Vec3& p, bool waves, double frequency, double phase) {
    double sum = 0;
    for (const WaveSource& s : povWaveSources()) {
        double d = length(p - s.centre);
        if (d == 0) d = 1;
        const double f = waves ? s.frequency : 1.0;
        sum += std::sin(2 * kPi * (d * frequency * f + phase)) / f;
    }
    return waves ? 0.2 * (2.5 + sum / kWaveCount) : 0.5 * (1 + sum / kWaveCount);
}

} // namespace

// POV-Ray's ten wave sources for waves and ripples: unit vectors in the
// directions of its vector noise at (i, 0, 0), i = 0..9 (measured with
// POV-Ray 3.7's vturbulence(2, 0.5, 1, <i, 0, 0>), which is that noise).
namespace {
constexpr double kWaveNoise[kWaveCount][3] = {
    {-0.4434195, 0.3610055, -0.459716},  {-0.301068, -0.1340735, -0.4338675}, {-0.33151, 0.464828, 0.479721},
    {0.31178, 0.419997, 0.347257},       {-0.0367056, -0.4595635, -0.3355535}, {0.1271155, -0.4722135, -0.16569},
    {-0.4418325, -0.392607, -0.301068},  {-0.1168915, -0.086694, -0.171046},  {0.0881745, -0.450393, -0.4448845},
    {0.3295565, 0.421233, -0.233028}};
} // namespace

// The frequencies come from POV-Ray's linear congruential generator
// x' = 1812433253 x + 12345 (32 bits), started at -560851967: each source
// takes ((x' >> 16) & 0x7FFF) / 32767 + 0.01.
const std::array<WaveSource, kWaveCount>& povWaveSources() {
    static const std::array<WaveSource, kWaveCount> sources = [] {
        std::array<WaveSource, kWaveCount> s{};
        uint32_t next = static_cast<uint32_t>(-560851967);
        for (int i = 0; i < kWaveCount; ++i) {
            s[i].centre = normalize(Vec3(kWaveNoise[i][0], kWaveNoise[i][1], kWaveNoise[i][2]));
            next = next * 1812433253u + 12345u;
            s[i].frequency = double((next >> 16) & 0x7FFF) * 0.000030518509476 + 0.01;
        }
        return s;
    }();
    return sources;
}

double noise01(const Vec3& p) { return clamp01(0.5 + 0.5 * cellNoise(noiseCell(p), 0)); }

Vec3 vectorNoise(const Vec3& p) {
    const NoiseCell cell = noiseCell(p);
    return Vec3(std::clamp(cellNoise(cell, 1), -1.0, 1.0), std::clamp(cellNoise(cell, 2), -1.0, 1.0),
                std::clamp(cellNoise(cell, 3), -1.0, 1.0));
}

Vec3 turbulenceOffset(const Turbulence& t, const Vec3& p) {
    if (t.amount.x == 0 && t.amount.y == 0 && t.amount.z == 0) return Vec3(0.0);
    Vec3 sum(0.0);
    double weight = 1, frequency = 1;
    const int octaves = std::clamp(t.octaves, 1, 10); // POV-Ray's range
    for (int i = 0; i < octaves; ++i) {
        sum += weight * vectorNoise(p * frequency);
        weight *= t.omega;
        frequency *= t.lambda;
    }
    return Vec3(t.amount.x * sum.x, t.amount.y * sum.y, t.amount.z * sum.z);
}

bool isNoisePattern(PatternKind kind) {
    switch (kind) {
    case PatternKind::Bozo:
    case PatternKind::Granite:
    case PatternKind::Marble:
    case PatternKind::Wood:
    case PatternKind::Agate:
    case PatternKind::Leopard:
    case PatternKind::Crackle:
    case PatternKind::Wrinkles:
    case PatternKind::Dents:
    case PatternKind::Bumps:
    case PatternKind::Ripples:
    case PatternKind::Waves: return true;
    default: return false;
    }
}

Vec3 warpPatternPoint(PatternKind kind, const Turbulence& turbulence, const Vec3& p) {
    // Marble and wood take the turbulence into their formulas instead.
    if (kind == PatternKind::Marble || kind == PatternKind::Wood) return p;
    return p + turbulenceOffset(turbulence, p);
}

double scalarTurbulence(const Turbulence& t, const Vec3& p) {
    // POV-Ray's range-corrected noise generator: each octave is 2 N - 0.5,
    // the first one clipped to [0, 1].
    double value = std::clamp(2 * noise01(p) - 0.5, 0.0, 1.0);
    double l = t.lambda, o = t.omega;
    const int octaves = std::clamp(t.octaves, 1, 10);
    for (int i = 2; i <= octaves; ++i) {
        value += o * (2 * noise01(p * l) - 0.5);
        l *= t.lambda;
        o *= t.omega;
    }
    return value;
}

namespace {

// POV-Ray's patterns before the frequency, phase and wave step, at the
// already warped pattern-space point q (POV-Ray 3.7's formulas; N is noise01).
double rawNoisePattern(PatternKind kind, const Turbulence& turbulence, const PatternWave& wave, const Vec3& q) {
    switch (kind) {
    case PatternKind::Bozo:
    case PatternKind::Bumps: return noise01(q);
    case PatternKind::Dents: { // noise cubed: sharp dents among flat areas
        const double n = noise01(q);
        return n * n * n;
    }
    case PatternKind::Granite: { // sum over 6 octaves of min(|1 - 2 N(4 q 2^i)|, 0.5) / 2^i
        double sum = 0, frequency = 1;
        for (int i = 0; i < 6; ++i, frequency *= 2)
            sum += std::min(std::fabs(1 - 2 * noise01(q * (4 * frequency))), 0.5) / frequency;
        return sum;
    }
    case PatternKind::Wrinkles: { // (c(N(q)) + sum_{i=1..9} c(N(2^i q)) / 2^i) / 2, c(n) = clip(2n - 0.5)
        auto octave = [](double n) { return std::clamp(2 * n - 0.5, 0.0, 1.0); };
        double value = octave(noise01(q)), lambda = 2, omega = 0.5;
        for (int i = 1; i < 10; ++i, lambda *= 2, omega *= 0.5) value += omega * octave(noise01(q * lambda));
        return value / 2;
    }
    case PatternKind::Marble: // x + turbulence.x T(q), triangle wave by default
        return turbulence.amount.x == 0 ? q.x : q.x + turbulence.amount.x * scalarTurbulence(turbulence, q);
    case PatternKind::Wood: { // distance from the z axis, turbulence bending the rings
        double x = q.x, y = q.y;
        if (!(turbulence.amount == Vec3(0.0))) {
            Turbulence unit = turbulence;
            unit.amount = Vec3(1.0);
            const Vec3 t = turbulenceOffset(unit, q);
            x += std::sin(2 * kPi * (q.x + t.x) * turbulence.amount.x);
            y += std::sin(2 * kPi * (q.y + t.y) * turbulence.amount.y);
        }
        return std::sqrt(x * x + y * y);
    }
    case PatternKind::Agate: { // (sin(2 pi (1.3 T(q) + 1.1 z)) + 1) / 2, to the power 0.77
        const double bands = 0.5 * (std::sin(2 * kPi * (1.3 * scalarTurbulence(turbulence, q) + 1.1 * q.z)) + 1);
        return std::pow(std::clamp(bands, 0.0, 1.0), 0.77);
    }
    case PatternKind::Leopard: { // ((sin x + sin y + sin z) / 3)^2
        const double s = (std::sin(q.x) + std::sin(q.y) + std::sin(q.z)) / 3.0;
        return s * s;
    }
    case PatternKind::Crackle: return crackleValue(q);
    case PatternKind::Ripples: return wavesValue(q, false, wave.frequency, wave.phase);
    case PatternKind::Waves: return wavesValue(q, true, wave.frequency, wave.phase);
    default: return 0;
    }
}

} // namespace

double noisePatternAtWarped(PatternKind kind, const Turbulence& turbulence, const PatternWave& wave, const Vec3& q) {
    const bool bands = kind == PatternKind::Marble || kind == PatternKind::Wood;
    return applyPatternWave(wave, rawNoisePattern(kind, turbulence, wave, q),
                            bands ? WaveKind::Triangle : WaveKind::Ramp);
}

double wavedNoisePatternValue(PatternKind kind, const Turbulence& turbulence, const PatternWave& wave,
                              const Vec3& point) {
    return noisePatternAtWarped(kind, turbulence, wave, warpPatternPoint(kind, turbulence, point));
}

double noisePatternValue(PatternKind kind, const Turbulence& turbulence, const Vec3& point) {
    return wavedNoisePatternValue(kind, turbulence, PatternWave{}, point);
}

} // namespace drt
