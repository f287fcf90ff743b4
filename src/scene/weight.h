// How many nodes a part of the scene model holds: objects (CSG members and
// clips included) and pattern nodes (pigments, textures, map entries, media).
// The front ends count what a scene builds and copies against Limits::objects
// (core/limits.h) with these, so a doubling of declared values ("billion
// laughs") stops at the limit instead of filling the machine's memory.
// Counting stops early once it passes `cap`, so it costs at most O(cap).
#pragma once

#include "scene/scene.h"

#include <cstdint>

namespace drt {

struct SceneWeight {
    int64_t objects = 0;  // Object nodes and blob components
    int64_t patterns = 0; // Pigment, Texture, map-entry and Media nodes, mesh triangles / 16
    int64_t total() const { return objects + patterns; }
};

void addWeight(SceneWeight& weight, const Pigment& pigment, int64_t cap);
void addWeight(SceneWeight& weight, const Texture& texture, int64_t cap);
void addWeight(SceneWeight& weight, const Interior& interior, int64_t cap);
void addWeight(SceneWeight& weight, const Object& object, int64_t cap);

template <class T>
SceneWeight weightOf(const T& part, int64_t cap) {
    SceneWeight weight;
    addWeight(weight, part, cap);
    return weight;
}

} // namespace drt
