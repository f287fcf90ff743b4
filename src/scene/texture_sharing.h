// Sharing equal textures between objects (Object::texture, a SharedTexture).
// Two textures are the same when every number in them has the same bits and
// they point to the same images, functions and files, so an object rendered
// with another's equal texture gives the same pixels to the bit.
#pragma once

#include "scene/scene.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace drt {

bool sameTexture(const Texture& a, const Texture& b);

// The textures of the objects placed so far, by a hash of their numbers: a
// texture equal to one seen before is replaced by that one, so that a scene of
// many objects with few textures keeps one copy of each.
class TextureSharing {
public:
    void share(SharedTexture& texture);
    size_t distinct() const { return distinct_; }

private:
    std::unordered_map<uint64_t, std::vector<SharedTexture>> byHash_;
    size_t distinct_ = 0;
};

} // namespace drt
