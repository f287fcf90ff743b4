// Layered and patterned textures (scene.h Texture), following POV-Ray 3.7:
// - Layers are shaded top first with an accumulated filter F (start rgb 1). A
//   layer of pigment P (filter f, transmit t) adds F x (its ambient, emission,
//   diffuse and highlights, with its own finish and bumped normal) and spawns
//   its own reflected ray of weight reflectivity (not scaled by F); then
//   F *= P.rgb f + t, and with conserve_energy F *= 1 - reflectivity. Layers
//   stop once min(1, |grey(F)|) < adc_bailout. The transmitted ray has weight F
//   and bends at the top layer's normal.
// - A patterned texture (texture_map, block patterns of textures) shades the entries its pattern picks (one for block
//   patterns, the two around the value for texture_map, all for Average), each
//   fully (lights and rays) with its blend weight.
// - A shadow ray through a surface is filtered by the product over layers of
//   P.rgb f + t (blended by weight for patterned textures).
#pragma once

#include "accel/accel.h"
#include "core/color.h"
#include "core/vec.h"
#include "render/pigment.h"
#include "scene/scene.h"

#include <functional>
#include <vector>

namespace drt {

// POV-Ray's grey value of a colour: 0.297 r + 0.589 g + 0.114 b.
inline double greyValue(const Color& c) { return 0.297 * c.r + 0.589 * c.g + 0.114 * c.b; }

// Calls visit(entry, weight) for the entries of a patterned texture (!map.empty())
// that the pattern picks at worldPoint (uv: the surface's, for uv_mapping; may
// be null), skipping weight-0 entries. A template:
// it runs for every shaded point of a patterned texture, and a std::function
// would add an indirect call (and possibly an allocation) each time.
template <class Visit>
void forEachPickedEntry(const Texture& patterned, const Vec3& worldPoint, const Vec3* uv, Visit&& visit) {
    const std::vector<Texture::MapEntry>& map = patterned.map;
    if (map.empty()) return;
    if (patterned.pigment.pattern == PatternKind::Average) {
        double total = 0;
        for (const Texture::MapEntry& entry : map) total += entry.value;
        if (!(total != 0)) return;
        for (const Texture::MapEntry& entry : map)
            if (entry.value != 0) visit(entry.texture, entry.value / total);
        return;
    }
    const PatternSample s = samplePattern(patterned.pigment, worldPoint, uv);
    if (s.block) {
        // A material_map's palette index counts round its textures.
        const size_t i = patterned.pigment.pattern == PatternKind::ImageMap ? size_t(s.index) % map.size()
                                                                             : size_t(s.index);
        if (s.index >= 0 && i < map.size()) visit(map[i].texture, 1.0);
        return;
    }
    const MapBlend b = blendMapEntries(map.size(), [&](size_t i) { return map[i].value; }, s.value);
    if (b.t != 1) visit(map[b.lower].texture, 1 - b.t);
    if (b.t != 0) visit(map[b.upper].texture, b.t);
}

// Calls visit(texture, weight) for the textures a hit shows: the object's, or
// a mesh triangle's own (Hit::cornerTextures, null corners meaning the
// object's), each distinct one once with its corners' summed weights.
template <class Visit>
void forEachSurfaceTexture(const Hit& hit, Visit&& visit) {
    const Texture& own = hit.object->texture;
    const auto& corners = hit.cornerTextures;
    if (corners[0] == corners[1] && corners[1] == corners[2]) { // one texture: exactly its shading
        visit(corners[0] ? *corners[0] : own, 1.0);
        return;
    }
    for (int k = 0; k < 3; ++k) {
        const Texture* t = corners[k] ? corners[k] : &own;
        bool seen = false;
        double weight = 0;
        for (int j = 0; j < 3; ++j) {
            const Texture* other = corners[j] ? corners[j] : &own;
            if (other != t) continue;
            if (j < k) seen = true;
            weight += hit.cornerWeights[j];
        }
        if (!seen && weight > 0) visit(*t, weight);
    }
}

// The layers of a layered texture, top first, appended to `out`. A patterned
// layer (the front ends refuse them, as POV-Ray does; the model allows them)
// ends the list: its entries are whole textures, seen through the layers
// above it, and the layers below it are not shaded.
void layersTopFirst(const Texture& texture, std::vector<const Texture*>& out);

// layersTopFirst's list for a shading or a shadow ray, in a per-thread buffer
// reused from hit to hit (no allocation per hit once it has grown). Each live
// TextureLayers has its own buffer, so a patterned layer whose entries are
// layered again can list them while its caller still reads its own list.
class TextureLayers {
public:
    explicit TextureLayers(const Texture& texture);
    ~TextureLayers();
    TextureLayers(const TextureLayers&) = delete;
    TextureLayers& operator=(const TextureLayers&) = delete;
    const Texture* const* data() const { return layers_->data(); }
    size_t size() const { return layers_->size(); }
    const Texture* const* begin() const { return data(); }
    const Texture* const* end() const { return data() + size(); }

private:
    std::vector<const Texture*>* layers_;
};

// Installs the calling thread's TextureLayers buffers (accel/thread_scratch.h).
std::unique_ptr<InstalledScratch> installTextureScratch();

// What a shadow ray keeps after crossing the surface at worldPoint.
Color textureFilter(const Texture& texture, const Vec3& worldPoint, const Vec3* uv = nullptr);

// True if any finish in the texture (layers, map entries) satisfies the predicate.
bool anyFinish(const Texture& texture, const std::function<bool(const Finish&)>& predicate);

} // namespace drt
