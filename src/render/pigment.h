// POV-Ray pigment patterns, evaluated at a world-space point.
#pragma once

#include "core/color.h"
#include "core/vec.h"
#include "scene/scene.h"

namespace drt {

// The pigment's colour (with filter and transmit) at world point p. Each
// pigment, sub-pigments included, is evaluated in its own pattern space
// Pigment::toWorld.inversePoint(p), or, with uv_mapping, at
// toWorld.inversePoint(uv) where `uv` is the surface's (u, v, 0) (null: the
// surface has none, (0, 0, 0) is used). Missing sub-pigments are black; an
// empty colour map ramps from black to white.
ColorFT evaluatePigment(const Pigment& pigment, const Vec3& worldPoint, const Vec3* uv = nullptr);

// Pattern values in pattern space, exposed for tests.
int checkerIndex(const Vec3& p);            // 0 or 1
int hexagonIndex(const Vec3& p);            // 0, 1 or 2
int brickIndex(const Vec3& p, const Vec3& brickSize, double mortar); // 0 mortar, 1 brick
double gradientValue(const Vec3& p, const Vec3& axis); // in [0, 1]
double radialValue(const Vec3& p);          // in [0, 1)
double onionValue(const Vec3& p);           // in [0, 1)
double sphericalValue(const Vec3& p);       // max(0, 1 - |p|), in [0, 1]
double planarValue(const Vec3& p);          // max(0, 1 - |y|)
double cylindricalValue(const Vec3& p);     // max(0, 1 - distance from the y axis)
double boxedValue(const Vec3& p);           // max(0, 1 - max(|x|, |y|, |z|))
ColorFT lookupColorMap(const std::vector<ColorMapEntry>& map, double value);

// Where a pattern puts a world point: a block pattern (checker, hexagon,
// brick) gives the index of its sub-pigment / sub-texture, the others a value
// for a colour, pigment or texture map. Average gives neither (block false,
// value 0): it uses every map entry.
struct PatternSample {
    bool block = false;
    int index = 0;
    double value = 0;
};
PatternSample samplePattern(const Pigment& pattern, const Vec3& worldPoint, const Vec3* uv = nullptr);
// The same in two steps: where the pattern is evaluated (pattern space, after
// the turbulence warp), and the pattern there (also used for the slopes of
// normal patterns, render/normal_pattern.h).
Vec3 patternPoint(const Pigment& pattern, const Vec3& worldPoint, const Vec3* uv = nullptr);
PatternSample samplePatternAt(const Pigment& pattern, const Vec3& patternSpacePoint);

// A map lookup as colour maps do it: the result is (1 - t) entry[lower] +
// t entry[upper]; values outside the map take its end entries (t = 0, lower ==
// upper). `count` must be positive; valueAt(i) is entry i's value.
struct MapBlend {
    size_t lower = 0;
    size_t upper = 0;
    double t = 0;
};
template <class ValueAt>
MapBlend blendMapEntries(size_t count, ValueAt valueAt, double value) {
    if (value <= valueAt(0)) return {0, 0, 0};
    for (size_t i = 1; i < count; ++i) {
        if (value <= valueAt(i)) {
            const double span = valueAt(i) - valueAt(i - 1);
            if (!(span > 0)) return {i, i, 0};
            return {i - 1, i, (value - valueAt(i - 1)) / span};
        }
    }
    return {count - 1, count - 1, 0};
}

} // namespace drt
