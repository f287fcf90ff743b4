#include "scene/light_through.h"

namespace drt {
namespace {

bool mayLetLightThrough(const ColorFT& c) { return c.filter != 0 || c.transmit != 0; }

bool mayLetLightThrough(const Pigment& p) {
    if (p.imageMap || mayLetLightThrough(p.color)) return true;
    for (const Pigment& child : p.children)
        if (mayLetLightThrough(child)) return true;
    for (const ColorMapEntry& entry : p.colorMap)
        if (mayLetLightThrough(entry.color)) return true;
    for (const Pigment::MapEntry& entry : p.pigmentMap)
        if (mayLetLightThrough(entry.pigment)) return true;
    return false;
}

} // namespace

bool mayLetLightThrough(const Texture& t) {
    if (mayLetLightThrough(t.pigment)) return true;
    for (const Texture::MapEntry& entry : t.map)
        if (mayLetLightThrough(entry.texture)) return true;
    for (const Texture& layer : t.layersAbove)
        if (mayLetLightThrough(layer)) return true;
    return false;
}

bool mayLetLightThrough(const Object& object) {
    if (object.noShadow) return false;
    if (mayLetLightThrough(object.texture)) return true;
    if (const auto* mesh = std::get_if<Mesh>(&object.shape))
        for (const Texture& own : mesh->textures)
            if (mayLetLightThrough(own)) return true;
    if (const auto* csg = std::get_if<Csg>(&object.shape)) return anyMayLetLightThrough(csg->children);
    return false;
}

bool anyMayLetLightThrough(const std::vector<Object>& objects) {
    for (const Object& object : objects)
        if (mayLetLightThrough(object)) return true;
    return false;
}

} // namespace drt
