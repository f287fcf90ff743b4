#include "scene/texture_sharing.h"

#include "scene/density_file.h"
#include "scene/image_map.h"

#include <bit>
#include <cstring>

namespace drt {

// Every field of these types is compared below: a field added to one of them
// must be added here too, or objects that differ only in it would be given
// one texture. These sizes (x86-64, libstdc++) catch the addition.
static_assert(sizeof(Pigment) == 584, "a Pigment field was added or removed: compare it in samePigment");
static_assert(sizeof(Finish) == 208, "a Finish field was added or removed: compare it in sameFinish");
static_assert(sizeof(Normal) == 464, "a Normal field was added or removed: compare it in sameNormal");
static_assert(sizeof(Texture) == 848, "a Texture field was added or removed: compare it in sameTexture");

namespace {

bool same(double a, double b) { return std::bit_cast<uint64_t>(a) == std::bit_cast<uint64_t>(b); }
bool same(const Vec3& a, const Vec3& b) { return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z); }
bool same(const Color& a, const Color& b) { return same(a.r, b.r) && same(a.g, b.g) && same(a.b, b.b); }
bool same(const ColorFT& a, const ColorFT& b) {
    return same(a.rgb, b.rgb) && same(a.filter, b.filter) && same(a.transmit, b.transmit);
}
bool same(const Mat4& a, const Mat4& b) { return std::memcmp(&a, &b, sizeof(Mat4)) == 0; }
bool same(const Transform& a, const Transform& b) {
    return same(a.matrix(), b.matrix()) && same(a.inverseMatrix(), b.inverseMatrix());
}
bool same(const Turbulence& a, const Turbulence& b) {
    return same(a.amount, b.amount) && a.octaves == b.octaves && same(a.omega, b.omega) && same(a.lambda, b.lambda);
}
bool same(const PatternWave& a, const PatternWave& b) {
    return a.kind == b.kind && same(a.frequency, b.frequency) && same(a.phase, b.phase) &&
           same(a.exponent, b.exponent);
}

template <class T, class Same>
bool sameList(const std::vector<T>& a, const std::vector<T>& b, Same&& sameItem) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (!sameItem(a[i], b[i])) return false;
    return true;
}

bool samePigment(const Pigment& a, const Pigment& b) {
    return a.pattern == b.pattern && a.imageMap == b.imageMap && a.function == b.function &&
           a.fractal == b.fractal && a.densityFile == b.densityFile && same(a.color, b.color) &&
           sameList(a.children, b.children, samePigment) &&
           sameList(a.colorMap, b.colorMap,
                    [](const ColorMapEntry& x, const ColorMapEntry& y) {
                        return same(x.value, y.value) && same(x.color, y.color);
                    }) &&
           same(a.gradientAxis, b.gradientAxis) && same(a.brickSize, b.brickSize) && same(a.mortar, b.mortar) &&
           same(a.turbulence, b.turbulence) && same(a.wave, b.wave) && same(a.toWorld, b.toWorld) &&
           sameList(a.pigmentMap, b.pigmentMap,
                    [](const Pigment::MapEntry& x, const Pigment::MapEntry& y) {
                        return same(x.value, y.value) && samePigment(x.pigment, y.pigment);
                    }) &&
           a.uvMapping == b.uvMapping;
}

bool sameFinish(const Finish& a, const Finish& b) {
    return same(a.ambient, b.ambient) && same(a.emission, b.emission) && same(a.diffuse, b.diffuse) &&
           same(a.brilliance, b.brilliance) && same(a.phong, b.phong) && same(a.phongSize, b.phongSize) &&
           same(a.specular, b.specular) && same(a.roughness, b.roughness) && same(a.metallic, b.metallic) &&
           same(a.reflectionMin, b.reflectionMin) && same(a.reflectionMax, b.reflectionMax) &&
           a.reflectionFresnel == b.reflectionFresnel && same(a.reflectionFalloff, b.reflectionFalloff) &&
           same(a.reflectionMetallic, b.reflectionMetallic) && a.conserveEnergy == b.conserveEnergy &&
           same(a.reflectionBlur, b.reflectionBlur) && same(a.refractionBlur, b.refractionBlur) &&
           same(a.crand, b.crand);
}

bool sameNormal(const Normal& a, const Normal& b) {
    return a.pattern == b.pattern && same(a.amount, b.amount) && same(a.turbulence, b.turbulence) &&
           same(a.wave, b.wave) && same(a.toWorld, b.toWorld) && same(a.gradientAxis, b.gradientAxis) &&
           a.function == b.function && a.fractal == b.fractal && a.densityFile == b.densityFile &&
           same(a.accuracy, b.accuracy) &&
           sameList(a.slopeMap, b.slopeMap,
                    [](const SlopeMapEntry& x, const SlopeMapEntry& y) {
                        return same(x.value, y.value) && same(x.height, y.height) && same(x.slope, y.slope);
                    }) &&
           a.uvMapping == b.uvMapping;
}

// A hash of the numbers that most often tell textures apart; sameTexture decides.
uint64_t hashOf(const Texture& t) {
    uint64_t h = 1469598103934665603ull;
    const auto mix = [&h](uint64_t v) { h = (h ^ v) * 1099511628211ull + (h >> 29); };
    const auto mixDouble = [&mix](double v) { mix(std::bit_cast<uint64_t>(v)); };
    mix(uint64_t(t.pigment.pattern));
    mixDouble(t.pigment.color.rgb.r);
    mixDouble(t.pigment.color.rgb.g);
    mixDouble(t.pigment.color.rgb.b);
    mixDouble(t.pigment.color.filter);
    mixDouble(t.pigment.color.transmit);
    mixDouble(t.pigment.toWorld.matrix().m[0][3]);
    mixDouble(t.pigment.toWorld.matrix().m[1][3]);
    mixDouble(t.pigment.toWorld.matrix().m[2][3]);
    mixDouble(t.finish.diffuse);
    mixDouble(t.finish.ambient.r);
    mix(t.pigment.children.size() + 7 * t.pigment.colorMap.size() + 49 * t.map.size() + 343 * t.layersAbove.size());
    mix(t.normal ? 1 : 0);
    return h;
}

} // namespace

bool sameTexture(const Texture& a, const Texture& b) {
    if (&a == &b) return true;
    if (!samePigment(a.pigment, b.pigment) || !sameFinish(a.finish, b.finish)) return false;
    if (bool(a.normal) != bool(b.normal) || (a.normal && !sameNormal(*a.normal, *b.normal))) return false;
    return sameList(a.map, b.map,
                    [](const Texture::MapEntry& x, const Texture::MapEntry& y) {
                        return same(x.value, y.value) && sameTexture(x.texture, y.texture);
                    }) &&
           sameList(a.layersAbove, b.layersAbove, sameTexture);
}

void TextureSharing::share(SharedTexture& texture) {
    std::vector<SharedTexture>& candidates = byHash_[hashOf(*texture)];
    for (const SharedTexture& seen : candidates) {
        if (seen.sharedWith(texture)) return;
        if (sameTexture(*seen, *texture)) {
            texture = seen;
            return;
        }
    }
    candidates.push_back(texture);
    ++distinct_;
}

// ---------------------------------------------------------------- SharedTexture

SharedTexture::SharedTexture() {
    static const std::shared_ptr<Texture> defaultTexture = std::make_shared<Texture>();
    texture_ = defaultTexture;
}

Texture& SharedTexture::edit() {
    if (texture_.use_count() != 1) texture_ = std::make_shared<Texture>(std::as_const(*texture_));
    return *texture_;
}

} // namespace drt
