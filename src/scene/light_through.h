// Which surfaces may let light through: a shadow ray must find each such
// surface it crosses and filter the light by it, where a surface that lets
// none through only blocks (render/lighting.h, accel/accel.h occludedOpaque).
#pragma once

#include "scene/scene.h"

#include <vector>

namespace drt {

// Whether the texture can filter or transmit light anywhere: some colour of it
// has filter or transmit, or it holds an image map (whose alpha may). A
// texture for which this is false lets no light through at any point.
bool mayLetLightThrough(const Texture& texture);

// Whether a shadow ray may be let through by the object: it casts shadows and
// its texture, a mesh's own textures or a member of its CSG may let light
// through (a member with no_shadow casts none).
bool mayLetLightThrough(const Object& object);

// Whether any of the objects may let light through (as above).
bool anyMayLetLightThrough(const std::vector<Object>& objects);

} // namespace drt
