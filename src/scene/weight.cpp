#include "scene/weight.h"

namespace drt {

void addWeight(SceneWeight& weight, const Pigment& pigment, int64_t cap) {
    if (weight.total() > cap) return;
    weight.patterns += 1 + int64_t(pigment.colorMap.size()) / 16;
    for (const Pigment& child : pigment.children) addWeight(weight, child, cap);
    for (const Pigment::MapEntry& entry : pigment.pigmentMap) addWeight(weight, entry.pigment, cap);
}

void addWeight(SceneWeight& weight, const Texture& texture, int64_t cap) {
    if (weight.total() > cap) return;
    ++weight.patterns;
    addWeight(weight, texture.pigment, cap);
    for (const Texture::MapEntry& entry : texture.map) addWeight(weight, entry.texture, cap);
    for (const Texture& layer : texture.layersAbove) addWeight(weight, layer, cap);
}

void addWeight(SceneWeight& weight, const Interior& interior, int64_t cap) {
    for (const Media& media : interior.media) {
        if (weight.total() > cap) return;
        ++weight.patterns;
        for (const Pigment& density : media.densities) addWeight(weight, density, cap);
    }
}

void addWeight(SceneWeight& weight, const Object& object, int64_t cap) {
    if (weight.total() > cap) return;
    ++weight.objects;
    addWeight(weight, object.texture, cap);
    addWeight(weight, object.interior, cap);
    if (const Mesh* mesh = std::get_if<Mesh>(&object.shape)) {
        const size_t triangles = mesh->indexed ? mesh->indexed->triangleCount() : mesh->triangles.size();
        weight.patterns += int64_t(triangles) / 16;
        for (const Texture& own : mesh->textures) addWeight(weight, own, cap);
    }
    if (const Blob* blob = std::get_if<Blob>(&object.shape)) weight.objects += int64_t(blob->components.size());
    if (const Csg* csg = std::get_if<Csg>(&object.shape))
        for (const Object& child : csg->children) addWeight(weight, child, cap);
    for (const Object& clip : object.clippedBy) addWeight(weight, clip, cap);
}

} // namespace drt
