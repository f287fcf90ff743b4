// The files a scene names besides its own text (image_map images, height field
// images), read after the front end has parsed the scene and before it is
// rendered or written: the front end finds each file and records where it is
// named; this stage decodes it into the scene model.
#pragma once

#include "core/diagnostics.h"
#include "scene/scene.h"

namespace drt {

// Decodes every image map and fills every mesh read from a file
// (Mesh::source). Each problem is reported to `diags` at the place the scene
// names the file; returns false if there was an error.
bool resolveAssets(Scene& scene, Diagnostics& diags);

// Whether resolveAssets has run on everything the scene names (the renderer
// refuses a scene with an unresolved file rather than render it wrong).
bool assetsResolved(const Scene& scene);

} // namespace drt
