#include "render/noise.h"

#include "render/pattern_wave.h"

#include "core/hash.h"
#include "core/limits.h"

#include <algorithm>
#include <cmath>

namespace drt {

namespace {

// Perlin's quintic fade 6t^5 - 15t^4 + 10t^3: zero first and second derivative at 0 and 1.
double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }

double lerp(double a, double b, double t) { return a + t * (b - a); }

// Dot product of the lattice point's gradient with the offset (x, y, z). The
// gradient is one of the 12 edge directions of the cube (+-1, +-1, 0) etc.,
// picked by a hash of the lattice coordinates and a seed.
double gradientDot(long long i, long long j, long long k, uint64_t seed, double x, double y, double z) {
    const uint64_t h = hashValues({uint64_t(i), uint64_t(j), uint64_t(k), seed}) % 12;
    switch (h) {
    case 0: return x + y;
    case 1: return -x + y;
    case 2: return x - y;
    case 3: return -x - y;
    case 4: return x + z;
    case 5: return -x + z;
    case 6: return x - z;
    case 7: return -x - z;
    case 8: return y + z;
    case 9: return -y + z;
    case 10: return y - z;
    default: return -y - z;
    }
}

// Signed gradient noise, roughly in [-1, 1].
double signedNoise(const Vec3& p, uint64_t seed) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return 0;
    const double fx = std::floor(p.x), fy = std::floor(p.y), fz = std::floor(p.z);
    const long long i = saturatingInteger(fx), j = saturatingInteger(fy), k = saturatingInteger(fz);
    const double x = p.x - fx, y = p.y - fy, z = p.z - fz;
    const double u = fade(x), v = fade(y), w = fade(z);
    auto g = [&](int a, int b, int c) { return gradientDot(i + a, j + b, k + c, seed, x - a, y - b, z - c); };
    const double x00 = lerp(g(0, 0, 0), g(1, 0, 0), u), x10 = lerp(g(0, 1, 0), g(1, 1, 0), u);
    const double x01 = lerp(g(0, 0, 1), g(1, 0, 1), u), x11 = lerp(g(0, 1, 1), g(1, 1, 1), u);
    return lerp(lerp(x00, x10, v), lerp(x01, x11, v), w);
}

double clamp01(double v) { return std::isfinite(v) ? std::clamp(v, 0.0, 1.0) : 0.0; }

// POV-Ray's triangle_wave: 0 -> 1 -> 0 over each period of 1.
double triangleWave(double v) {
    const double f = v - std::floor(v);
    return clamp01(f < 0.5 ? 2 * f : 2 - 2 * f);
}

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

// Ten fixed wave sources inside the unit cube, the same for every scene.
Vec3 waveCentre(int i) {
    const uint64_t h = hashValues({uint64_t(i), 991});
    return Vec3(unitFromHash(mix64(h)), unitFromHash(mix64(h + 1)), unitFromHash(mix64(h + 2))) * 2.0 - Vec3(1.0);
}

double wavesValue(const Vec3& p, bool damped) {
    double sum = 0;
    for (int i = 0; i < 10; ++i) {
        const double d = length(p - waveCentre(i));
        const double weight = damped ? 1.0 / (1.0 + d) : 1.0;
        sum += weight * (0.5 + 0.5 * std::cos(2 * kPi * d));
    }
    return clamp01(damped ? sum / 10.0 * 1.6 : sum / 10.0);
}

// Sum of |signed noise| octaves at doubling frequency, amplitude halving.
double absOctaves(const Vec3& p, int octaves) {
    double sum = 0, frequency = 1;
    for (int i = 0; i < octaves; ++i) {
        sum += std::fabs(signedNoise(p * frequency, 0)) / frequency;
        frequency *= 2;
    }
    return sum;
}

} // namespace

double noise01(const Vec3& p) { return clamp01(0.5 + 0.5 * signedNoise(p, 0)); }

Vec3 vectorNoise(const Vec3& p) {
    return Vec3(std::clamp(signedNoise(p, 1), -1.0, 1.0), std::clamp(signedNoise(p, 2), -1.0, 1.0),
                std::clamp(signedNoise(p, 3), -1.0, 1.0));
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

namespace {

// Marble's and wood's value before their built-in triangle wave: x, and the
// distance from the z axis.
double bandCoordinate(PatternKind kind, const Vec3& p) {
    return kind == PatternKind::Marble ? p.x : std::sqrt(p.x * p.x + p.y * p.y);
}

} // namespace

double noisePatternValue(PatternKind kind, const Turbulence& turbulence, const Vec3& point) {
    const Vec3 p = point + turbulenceOffset(turbulence, point);
    switch (kind) {
    case PatternKind::Bozo:
    case PatternKind::Bumps: return noise01(p);
    case PatternKind::Dents: { // POV-Ray: noise cubed, sharp dents among flat areas
        const double n = noise01(p);
        return n * n * n;
    }
    case PatternKind::Granite: return clamp01(absOctaves(p * 4.0, 6));
    case PatternKind::Wrinkles: return clamp01(absOctaves(p, 10));
    case PatternKind::Marble:
    case PatternKind::Wood: return triangleWave(bandCoordinate(kind, p));
    case PatternKind::Agate: { // sine bands along z, warped by built-in turbulence (agate_turb 1)
        const double bands = 0.5 + 0.5 * std::sin(2 * kPi * (p.z + absOctaves(p, 6)));
        return clamp01(std::pow(bands, 0.77));
    }
    case PatternKind::Leopard: { // POV-Ray: ((sin x + sin y + sin z) / 3)^2
        const double s = (std::sin(p.x) + std::sin(p.y) + std::sin(p.z)) / 3.0;
        return clamp01(s * s);
    }
    case PatternKind::Crackle: return crackleValue(p);
    case PatternKind::Ripples: return wavesValue(p, false);
    case PatternKind::Waves: return wavesValue(p, true);
    default: return 0;
    }
}

double wavedNoisePatternValue(PatternKind kind, const Turbulence& turbulence, const PatternWave& wave,
                              const Vec3& point) {
    if (wave.isIdentity()) return noisePatternValue(kind, turbulence, point);
    if (kind == PatternKind::Marble || kind == PatternKind::Wood)
        return applyPatternWave(wave, bandCoordinate(kind, point + turbulenceOffset(turbulence, point)),
                                WaveKind::Triangle);
    return applyPatternWave(wave, noisePatternValue(kind, turbulence, point));
}

Vec3 perturbNormal(const Normal& bump, const Vec3& worldPoint, const Vec3& normal) {
    if (!(bump.amount != 0) || !std::isfinite(bump.amount)) return normal;
    const Vec3 p = bump.toWorld.inversePoint(worldPoint);
    constexpr double h = 1e-3; // pattern-space step; the patterns vary over about 1 unit
    auto f = [&](const Vec3& q) { return wavedNoisePatternValue(bump.pattern, bump.turbulence, bump.wave, q); };
    const Vec3 gradient((f(p + Vec3(h, 0, 0)) - f(p - Vec3(h, 0, 0))) / (2 * h),
                        (f(p + Vec3(0, h, 0)) - f(p - Vec3(0, h, 0))) / (2 * h),
                        (f(p + Vec3(0, 0, h)) - f(p - Vec3(0, 0, h))) / (2 * h));
    const Vec3 world = bump.toWorld.normal(gradient); // gradients map by the inverse transpose
    Vec3 tangential = bump.amount * (world - dot(world, normal) * normal);
    if (!std::isfinite(tangential.x) || !std::isfinite(tangential.y) || !std::isfinite(tangential.z))
        return normal;
    // Bound the tilt to about 76 degrees so the bumped normal stays well on n's side.
    constexpr double maxTilt = 4.0;
    const double len = length(tangential);
    if (len > maxTilt) tangential = tangential * (maxTilt / len);
    return normalize(normal - tangential);
}

} // namespace drt
