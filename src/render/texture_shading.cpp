#include "render/texture_shading.h"

#include "render/pigment.h"

#include <algorithm>
#include <memory>

namespace drt {

namespace {

void collectBottomFirst(const Texture& texture, std::vector<const Texture*>& out) {
    out.push_back(&texture);
    for (const Texture& layer : texture.layersAbove) collectBottomFirst(layer, out);
}

// The buffers of the TextureLayers alive on this thread, innermost last; on
// the heap, one each, so that adding one never moves another's list.
struct LayerBuffers {
    std::vector<std::unique_ptr<std::vector<const Texture*>>> buffers;
    size_t inUse = 0;
};

} // namespace

std::unique_ptr<InstalledScratch> installTextureScratch() { return ThreadScratch<LayerBuffers>::install(); }

TextureLayers::TextureLayers(const Texture& texture) {
    LayerBuffers& b = ThreadScratch<LayerBuffers>::get();
    if (b.inUse == b.buffers.size()) b.buffers.push_back(std::make_unique<std::vector<const Texture*>>());
    layers_ = b.buffers[b.inUse].get();
    ++b.inUse;
    layers_->clear();
    layersTopFirst(texture, *layers_);
}

TextureLayers::~TextureLayers() { --ThreadScratch<LayerBuffers>::get().inUse; }

void layersTopFirst(const Texture& texture, std::vector<const Texture*>& out) {
    const size_t start = out.size();
    collectBottomFirst(texture, out);
    std::reverse(out.begin() + std::ptrdiff_t(start), out.end());
    // A patterned layer shades all below it by itself.
    for (size_t i = start; i < out.size(); ++i)
        if (!out[i]->map.empty()) {
            out.resize(i + 1);
            break;
        }
}

namespace {

Color patternedFilter(const Texture& patterned, const Vec3& worldPoint, const Vec3* uv) {
    Color sum(0);
    forEachPickedEntry(patterned, worldPoint, uv,
                       [&](const Texture& entry, double w) { sum += textureFilter(entry, worldPoint, uv) * w; });
    return sum;
}

} // namespace

Color textureFilter(const Texture& texture, const Vec3& worldPoint, const Vec3* uv) {
    if (texture.plain()) {
        const ColorFT p = evaluatePigment(texture.pigment, worldPoint, uv);
        return p.rgb * p.filter + Color(p.transmit);
    }
    if (texture.layersAbove.empty()) return patternedFilter(texture, worldPoint, uv);
    const TextureLayers layers(texture);
    Color filter(1);
    for (const Texture* layer : layers) {
        if (!layer->map.empty()) {
            filter *= patternedFilter(*layer, worldPoint, uv);
            break;
        }
        const ColorFT p = evaluatePigment(layer->pigment, worldPoint, uv);
        filter *= p.rgb * p.filter + Color(p.transmit);
    }
    return filter;
}

bool anyFinish(const Texture& texture, const std::function<bool(const Finish&)>& predicate) {
    if (texture.map.empty() && predicate(texture.finish)) return true;
    for (const Texture::MapEntry& entry : texture.map)
        if (anyFinish(entry.texture, predicate)) return true;
    for (const Texture& layer : texture.layersAbove)
        if (anyFinish(layer, predicate)) return true;
    return false;
}

} // namespace drt
