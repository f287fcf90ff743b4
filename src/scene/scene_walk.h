// Visiting every object and every pigment of a scene model, wherever it sits
// (CSG members, clips, texture layers and maps, media densities, the sky).
#pragma once

#include "scene/scene.h"

#include <type_traits>
#include <unordered_set>

namespace drt {

// Calls fn(object) for every object, members of CSGs and clip objects included,
// parents before their members.
template <class SceneT, class Fn>
void forEachObject(SceneT& scene, Fn&& fn) {
    using ObjectT = std::conditional_t<std::is_const_v<SceneT>, const Object, Object>;
    auto visit = [&](auto& self, ObjectT& object) -> void {
        fn(object);
        if (auto* csg = std::get_if<Csg>(&object.shape))
            for (ObjectT& child : csg->children) self(self, child);
        for (ObjectT& clip : object.clippedBy) self(self, clip);
    };
    for (ObjectT& object : scene.objects) visit(visit, object);
}

namespace detail {
// Calls fn(texture) for every texture of one object: its own and its mesh
// triangles', each before its map entries and its layers. An object's own
// texture may be shared with other objects (SharedTexture): a walk that may
// change textures passes `seen`, and visits a shared texture once, changing it
// for every object that has it.
template <class ObjectT, class Fn>
void forEachTextureOf(ObjectT& object, Fn&& fn, std::unordered_set<const Texture*>* seen = nullptr) {
    constexpr bool isConst = std::is_const_v<ObjectT>;
    using TextureT = std::conditional_t<isConst, const Texture, Texture>;
    using MeshT = std::conditional_t<isConst, const Mesh, Mesh>;
    auto texture = [&](auto& self, TextureT& t) -> void {
        fn(t);
        for (auto& entry : t.map) self(self, entry.texture);
        for (TextureT& layer : t.layersAbove) self(self, layer);
    };
    if constexpr (isConst) {
        texture(texture, *object.texture);
    } else {
        Texture& own = object.texture.editForEverySharer();
        if (!seen || seen->insert(&own).second) texture(texture, own);
    }
    if (MeshT* mesh = std::get_if<Mesh>(&object.shape))
        for (TextureT& own : mesh->textures) texture(texture, own);
}
} // namespace detail

// Calls fn(pigment) for every pigment, sub-pigments and pigment-map entries included.
template <class SceneT, class Fn>
void forEachPigment(SceneT& scene, Fn&& fn) {
    constexpr bool isConst = std::is_const_v<SceneT>;
    using PigmentT = std::conditional_t<isConst, const Pigment, Pigment>;
    using TextureT = std::conditional_t<isConst, const Texture, Texture>;
    using MediaT = std::conditional_t<isConst, const Media, Media>;
    using ObjectT = std::conditional_t<isConst, const Object, Object>;
    auto pigment = [&](auto& self, PigmentT& p) -> void {
        fn(p);
        for (PigmentT& child : p.children) self(self, child);
        for (auto& entry : p.pigmentMap) self(self, entry.pigment);
    };
    auto media = [&](MediaT& m) {
        for (PigmentT& density : m.densities) pigment(pigment, density);
    };
    std::unordered_set<const Texture*> seen;
    forEachObject(scene, [&](ObjectT& object) {
        detail::forEachTextureOf(object, [&](TextureT& t) { pigment(pigment, t.pigment); }, &seen);
        for (MediaT& m : object.interior.media) media(m);
    });
    for (PigmentT& sky : scene.sky) pigment(pigment, sky);
    for (MediaT& m : scene.media) media(m);
}

// Calls fn(normal) for every texture's normal, wherever the texture sits (as
// forEachPigment's textures).
template <class SceneT, class Fn>
void forEachNormal(SceneT& scene, Fn&& fn) {
    using ObjectT = std::conditional_t<std::is_const_v<SceneT>, const Object, Object>;
    std::unordered_set<const Texture*> seen;
    forEachObject(scene, [&](ObjectT& object) {
        detail::forEachTextureOf(
            object,
            [&](auto& texture) {
                if (texture.normal) fn(*texture.normal);
            },
            &seen);
    });
}

} // namespace drt
