// Normal patterns with POV-Ray 3.7's rules (declared in render/noise.h).
//
// The world normal n is carried into pattern space, n_p = normalize(T^t n)
// with T the pattern's transform (pattern -> world), where the pattern adds
// its perturbation; the result goes back by T^-t and is normalised. At the
// warped pattern-space point q, with amount a:
// - bumps     n_p += a D(q)                      (D: vector noise)
// - dents     n_p += a N(q)^3 D(q)               (N: noise in [0, 1])
// - wrinkles  n_p += a sum_{i<10} |D(2^i q)| / 2^i, per component
// - ripples   n_p += sum_i a sin(2 pi (d_i F + phase)) / (10 d_i) (q - s_i)
// - waves     n_p += sum_i a sin(2 pi (d_i F f_i + phase)) / (10 d_i f_i) (q - s_i)
//   (s_i, f_i: the ten wave sources; d_i = |q - s_i|; F the frequency)
// - any other pattern v: its slope, from the four vertices t_k of a regular
//   tetrahedron, n_p += sum_k v(q + delta t_k) (-5 a 0.02 / delta) t_k with
//   delta the accuracy; for small delta that is -(0.4 / 3) a grad v. With a
//   slope_map, v is replaced by the height the map gives it.
#include "render/noise.h"
#include "render/pattern_wave.h"
#include "render/pigment.h"

#include <cmath>

namespace drt {

namespace {

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The unit vectors to the vertices of a regular tetrahedron, one along +y.
constexpr double kTetraSide = 0.94280904158206336587; // sqrt(8) / 3
constexpr double kTetraDepth = 0.81649658092772603273; // sqrt(6) / 3
const Vec3 kTetrahedron[4] = {Vec3(kTetraSide, -1.0 / 3, 0), Vec3(-kTetraSide / 2, -1.0 / 3, kTetraDepth),
                              Vec3(-kTetraSide / 2, -1.0 / 3, -kTetraDepth), Vec3(0, 1, 0)};

Vec3 waveNormal(const Normal& bump, const Vec3& q, bool waves) {
    Vec3 sum(0.0);
    for (const WaveSource& s : povWaveSources()) {
        const Vec3 away = q - s.centre;
        double d = length(away);
        if (d == 0) d = 1;
        const double f = waves ? s.frequency : 1.0;
        const double scalar = bump.amount * std::sin(2 * kPi * (d * bump.wave.frequency * f + bump.wave.phase)) / f;
        sum += (scalar / (d * kWaveCount)) * away;
    }
    return sum;
}

// The pattern's value at pattern-space point q (already warped), as the
// slope method samples it.
double slopeValue(const Normal& bump, const Pigment& shape, const Vec3& q) {
    double v;
    if (isNoisePattern(bump.pattern)) {
        v = noisePatternAtWarped(bump.pattern, bump.turbulence, bump.wave, q);
    } else {
        const PatternSample s = samplePatternAt(shape, q);
        v = s.block ? applyPatternWave(bump.wave, s.index) : s.value;
    }
    return bump.slopeMap.empty() ? v : slopeMapHeight(bump.slopeMap, v);
}

Vec3 perturbation(const Normal& bump, const Vec3& q) {
    switch (bump.pattern) {
    case PatternKind::Bumps: return bump.amount * vectorNoise(q);
    case PatternKind::Dents: {
        const double n = noise01(q);
        return (bump.amount * n * n * n) * vectorNoise(q);
    }
    case PatternKind::Wrinkles: {
        Vec3 sum(0.0);
        double scale = 1;
        for (int i = 0; i < 10; ++i, scale *= 2) {
            const Vec3 d = vectorNoise(q * scale);
            sum += Vec3(std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)) / scale;
        }
        return bump.amount * sum;
    }
    case PatternKind::Ripples: return waveNormal(bump, q, false);
    case PatternKind::Waves: return waveNormal(bump, q, true);
    default: {
        Pigment shape; // the pattern as samplePatternAt reads it
        shape.pattern = bump.pattern;
        shape.gradientAxis = bump.gradientAxis;
        shape.wave = bump.wave;
        if (bump.pattern == PatternKind::Function) shape.function = bump.function;
        if (bump.pattern == PatternKind::Fractal) shape.fractal = bump.fractal;
        if (bump.pattern == PatternKind::DensityFile) shape.densityFile = bump.densityFile;
        const double delta = bump.accuracy > 0 && std::isfinite(bump.accuracy) ? bump.accuracy : 0.02;
        const double weight = -5 * bump.amount * 0.02 / delta;
        Vec3 sum(0.0);
        for (const Vec3& t : kTetrahedron) sum += (slopeValue(bump, shape, q + delta * t) * weight) * t;
        return sum;
    }
    }
}

} // namespace

double slopeMapHeight(const std::vector<SlopeMapEntry>& map, double v) {
    if (map.empty()) return v;
    if (!(v > map.front().value)) return map.front().height; // NaN too
    for (std::size_t i = 1; i < map.size(); ++i) {
        const SlopeMapEntry& hi = map[i];
        if (v > hi.value) continue;
        const SlopeMapEntry& lo = map[i - 1]; // lo.value < v <= hi.value
        const double t = (v - lo.value) / (hi.value - lo.value), t2 = t * t, t3 = t2 * t;
        return lo.height * (2 * t3 - 3 * t2 + 1) + lo.slope * (t3 - 2 * t2 + t) + hi.height * (3 * t2 - 2 * t3) +
               hi.slope * (t3 - t2);
    }
    return map.back().height;
}

Vec3 perturbNormal(const Normal& bump, const Vec3& worldPoint, const Vec3& normal) {
    if (!(bump.amount != 0) || !std::isfinite(bump.amount)) return normal;
    const Vec3 q = warpPatternPoint(bump.pattern, bump.turbulence, bump.toWorld.inversePoint(worldPoint));
    if (!finite(q)) return normal;
    const Vec3 inPattern = normalize(bump.toWorld.inverted().normal(normal));
    const Vec3 world = normalize(bump.toWorld.normal(inPattern + perturbation(bump, q)));
    return finite(world) ? world : normal;
}

Vec3 perturbNormalUv(const Normal& bump, const Vec3& uv, const Vec3& dpdu, const Vec3& dpdv, const Vec3& normal) {
    if (!(bump.amount != 0) || !std::isfinite(bump.amount)) return normal;
    // The frame L maps uv space to the surface: u to dpdu, v to dpdv, w to s n.
    const double s = std::sqrt(length(cross(dpdu, dpdv)));
    const Vec3 a = dpdu, b = dpdv, c = s * normal;
    const Vec3 bc = cross(b, c), ca = cross(c, a), ab = cross(a, b);
    const double det = dot(a, bc);
    if (!(std::fabs(det) > 0) || !std::isfinite(det) || !(s > 0)) return normal;
    const Vec3 q = warpPatternPoint(bump.pattern, bump.turbulence, bump.toWorld.inversePoint(uv));
    if (!finite(q)) return normal;
    // The normal in uv space is L^T n, then in pattern space; tilted there and
    // carried back by the inverse transposes (L^-T has columns bc, ca, ab over det).
    const Vec3 inUv(dot(a, normal), dot(b, normal), dot(c, normal));
    const Vec3 inPattern = normalize(bump.toWorld.inverted().normal(inUv));
    const Vec3 m = bump.toWorld.normal(inPattern + perturbation(bump, q));
    const Vec3 world = normalize((m.x * bc + m.y * ca + m.z * ab) / det);
    return finite(world) ? world : normal;
}

} // namespace drt
