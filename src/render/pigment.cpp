#include "render/pigment.h"

#include "core/limits.h"

#include "render/density_file_pattern.h"
#include "render/function_hooks.h"
#include "render/image_pattern.h"
#include "render/noise.h"
#include "render/pattern_fractal.h"
#include "render/pattern_wave.h"

#include <cmath>

namespace drt {

namespace {

// POV-Ray nudges block patterns by its EPSILON (1e-10) so that surfaces lying
// exactly on a cell boundary (a plane at y = 0) pick the cell above; a point
// a millionth below the boundary is in the cell below.
constexpr double kBlockTolerance = 1e-10;

// POV-Ray's ramp_wave: the fractional part, in [0, 1).
double rampWave(double v) {
    const double f = v - std::floor(v);
    return f < 1.0 ? f : 0.0;
}

// Fractional position of v within a period of 1, in [0, 1).
double cellFraction(double v) { return v - std::floor(v); }

ColorFT child(const Pigment& pigment, size_t index, const Vec3& worldPoint, const Vec3* uv) {
    if (index >= pigment.children.size()) return ColorFT{};
    return evaluatePigment(pigment.children[index], worldPoint, uv);
}

ColorFT mix(const ColorFT& a, const ColorFT& b, double t) {
    ColorFT c;
    c.rgb = a.rgb * (1 - t) + b.rgb * t;
    c.filter = a.filter * (1 - t) + b.filter * t;
    c.transmit = a.transmit * (1 - t) + b.transmit * t;
    return c;
}

} // namespace

int checkerIndex(const Vec3& p) {
    // Parity of the cell coordinates' sum, added modulo 2 so that no sum overflows.
    const long long sum = (saturatingInteger(std::floor(p.x + kBlockTolerance)) & 1) +
                          (saturatingInteger(std::floor(p.y + kBlockTolerance)) & 1) +
                          (saturatingInteger(std::floor(p.z + kBlockTolerance)) & 1);
    return static_cast<int>(sum & 1);
}

int hexagonIndex(const Vec3& p) {
    // POV-Ray's hexagon: regular hexagons of side 1 in the x-z plane with corners
    // on the x axis, one centred at the origin. Centres lie at
    // (1.5 q, sqrt(3) (r + q/2)) for integer axial coordinates (q, r); the three
    // colours are (r - q) mod 3 (colour 0 at the origin, 1 at (0, sqrt 3), 2 at (1.5, sqrt(3)/2)).
    const double q = p.x * (2.0 / 3.0);
    const double r = -p.x / 3.0 + p.z / std::sqrt(3.0);
    // Round the cube coordinates (q, r, -q-r) to the nearest hexagon centre.
    const double s = -q - r;
    double rq = std::round(q), rr = std::round(r), rs = std::round(s);
    const double dq = std::fabs(rq - q), dr = std::fabs(rr - r), ds = std::fabs(rs - s);
    if (dq > dr && dq > ds)
        rq = -rr - rs;
    else if (dr > ds)
        rr = -rq - rs;
    const long long k = (saturatingInteger(rr) % 3 - saturatingInteger(rq) % 3) % 3;
    return static_cast<int>(k < 0 ? k + 3 : k);
}

int brickIndex(const Vec3& p, const Vec3& brickSize, double mortar) {
    // POV-Ray's brick: courses of height brickSize.y separated by mortar; odd
    // and even courses are offset by half a brick in x and z.
    const double shift = kBlockTolerance + mortar;
    const Vec3 q = p + Vec3(shift);
    if (cellFraction(q.y / brickSize.y) <= mortar / brickSize.y) return 0;
    const bool lowerCourse = cellFraction(q.y / brickSize.y * 0.5) <= 0.5;
    const double mortarX = mortar / brickSize.x, mortarZ = mortar / brickSize.z;
    const double fx = cellFraction(q.x / brickSize.x + (lowerCourse ? 0.0 : 0.5));
    if (fx <= mortarX) return 0;
    const double fz = cellFraction(q.z / brickSize.z + (lowerCourse ? 0.5 : 0.0));
    if (fz <= mortarZ) return 0;
    return 1;
}

double gradientValue(const Vec3& p, const Vec3& axis) {
    const double len = length(axis);
    if (!(len > 0) || !std::isfinite(len)) return 0;
    const double v = dot(p, axis / len); // POV-Ray normalises the axis
    return v > 1 ? std::fmod(v, 1.0) : v < 0 ? rampWave(v) : v; // 1 stays 1, as in POV-Ray
}

double radialValue(const Vec3& p) {
    // POV-Ray: 0.25 + (atan2(x, z) + pi) / (2 pi), wrapped; the axis itself gets 0.25.
    if (std::fabs(p.x) < 1e-3 && std::fabs(p.z) < 1e-3) return 0.25;
    return rampWave(0.25 + (std::atan2(p.x, p.z) + kPi) / (2 * kPi));
}

double onionValue(const Vec3& p) { return rampWave(length(p)); }

double sphericalValue(const Vec3& p) { return std::max(0.0, 1.0 - length(p)); }
double planarValue(const Vec3& p) { return std::max(0.0, 1.0 - std::fabs(p.y)); }
double cylindricalValue(const Vec3& p) { return std::max(0.0, 1.0 - std::sqrt(p.x * p.x + p.z * p.z)); }
double boxedValue(const Vec3& p) {
    return std::max(0.0, 1.0 - std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}));
}

namespace {
// Links render/function_hooks.cpp (and its start-up installation) into every program that shades.
[[maybe_unused]] const bool kFunctionHooks = installFunctionHooks();
} // namespace

ColorFT lookupColorMap(const std::vector<ColorMapEntry>& map, double value) {
    if (map.empty()) return ColorFT{Color(value), 0, 0};
    if (value <= map.front().value) return map.front().color;
    for (size_t i = 1; i < map.size(); ++i) {
        if (value <= map[i].value) {
            const double span = map[i].value - map[i - 1].value;
            if (!(span > 0)) return map[i].color;
            return mix(map[i - 1].color, map[i].color, (value - map[i - 1].value) / span);
        }
    }
    return map.back().color;
}

Vec3 patternPoint(const Pigment& pattern, const Vec3& worldPoint, const Vec3* uv) {
    const Vec3& at = pattern.uvMapping ? (uv ? *uv : Vec3{}) : worldPoint;
    return warpPatternPoint(pattern.pattern, pattern.turbulence, pattern.toWorld.inversePoint(at));
}

PatternSample samplePatternAt(const Pigment& pigment, const Vec3& p) {
    PatternSample s;
    if (isNoisePattern(pigment.pattern)) {
        s.value = noisePatternAtWarped(pigment.pattern, pigment.turbulence, pigment.wave, p);
        return s;
    }
    double value = 0;
    switch (pigment.pattern) {
    case PatternKind::Solid:
    case PatternKind::Average: return s;
    case PatternKind::ImageMap: // a material_map's texture number; an image_map has a colour, not a value
        if (pigment.imageMap && pigment.imageMap->material) s.block = true, s.index = imageMapIndex(*pigment.imageMap, p);
        return s;
    case PatternKind::Checker: s.block = true, s.index = checkerIndex(p); return s;
    case PatternKind::Hexagon: s.block = true, s.index = hexagonIndex(p); return s;
    case PatternKind::Brick: s.block = true, s.index = brickIndex(p, pigment.brickSize, pigment.mortar); return s;
    case PatternKind::Gradient: value = gradientValue(p, pigment.gradientAxis); break;
    case PatternKind::Radial: value = radialValue(p); break;
    case PatternKind::Onion: value = onionValue(p); break;
    case PatternKind::Spherical: value = sphericalValue(p); break;
    case PatternKind::Planar: value = planarValue(p); break;
    case PatternKind::Cylindrical: value = cylindricalValue(p); break;
    case PatternKind::Boxed: value = boxedValue(p); break;
    case PatternKind::Function: value = pigment.function ? pigment.function->at(p) : 0.0; break; // see installFunctionHooks
    case PatternKind::Fractal: value = pigment.fractal ? fractalValue(*pigment.fractal, p.x, p.y) : 0.0; break;
    case PatternKind::DensityFile: value = pigment.densityFile ? densityFileValue(*pigment.densityFile, p) : 0.0; break;
    case PatternKind::ImagePattern: value = pigment.imageMap ? imagePatternValue(*pigment.imageMap, p) : 0.0; break;
    default: break;
    }
    // POV-Ray's pattern step: fmod(v frequency + phase, 1.00001), then the wave.
    s.value = applyPatternWave(pigment.wave, value);
    return s;
}

PatternSample samplePattern(const Pigment& pigment, const Vec3& worldPoint, const Vec3* uv) {
    if (pigment.pattern == PatternKind::Solid || pigment.pattern == PatternKind::Average) return PatternSample{};
    return samplePatternAt(pigment, patternPoint(pigment, worldPoint, uv));
}

namespace {

// pigment_map with `average`: sum w_i P_i / sum w_i over all entries.
ColorFT averagePigmentMap(const std::vector<Pigment::MapEntry>& map, const Vec3& worldPoint, const Vec3* uv) {
    ColorFT sum{Color(0), 0, 0};
    double total = 0;
    for (const Pigment::MapEntry& entry : map) {
        if (entry.value == 0) continue;
        const ColorFT c = evaluatePigment(entry.pigment, worldPoint, uv);
        sum.rgb += c.rgb * entry.value;
        sum.filter += c.filter * entry.value;
        sum.transmit += c.transmit * entry.value;
        total += entry.value;
    }
    if (!(total != 0)) return ColorFT{};
    return ColorFT{sum.rgb / total, sum.filter / total, sum.transmit / total};
}

ColorFT lookupPigmentMap(const std::vector<Pigment::MapEntry>& map, double value, const Vec3& worldPoint,
                         const Vec3* uv) {
    const MapBlend b = blendMapEntries(map.size(), [&](size_t i) { return map[i].value; }, value);
    const ColorFT lower = evaluatePigment(map[b.lower].pigment, worldPoint, uv);
    if (b.t == 0) return lower;
    return mix(lower, evaluatePigment(map[b.upper].pigment, worldPoint, uv), b.t);
}

} // namespace

ColorFT evaluatePigment(const Pigment& pigment, const Vec3& worldPoint, const Vec3* uv) {
    if (pigment.pattern == PatternKind::Solid) return pigment.color;
    if (pigment.pattern == PatternKind::Average) return averagePigmentMap(pigment.pigmentMap, worldPoint, uv);
    if (pigment.pattern == PatternKind::ImageMap) { // a colour of its own, not a pattern value
        if (!pigment.imageMap) return ColorFT{};
        return imageMapColor(*pigment.imageMap, patternPoint(pigment, worldPoint, uv));
    }
    const PatternSample s = samplePattern(pigment, worldPoint, uv);
    if (s.block) return child(pigment, size_t(s.index), worldPoint, uv);
    if (!pigment.pigmentMap.empty()) return lookupPigmentMap(pigment.pigmentMap, s.value, worldPoint, uv);
    return lookupColorMap(pigment.colorMap, s.value);
}

} // namespace drt
