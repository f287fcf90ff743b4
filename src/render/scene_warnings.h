// Warnings about scenes that render but are most likely not what was meant:
// no light source, no camera, a camera inside a closed object. `drt render`
// and `drt check` print them with the scene's other diagnostics.
#pragma once

#include "core/diagnostics.h"
#include "scene/scene.h"

#include <string>

namespace drt {

// Adds a warning to `diagnostics` for each problem found in `scene` (read
// from `scenePath`, named in the warnings that have no source location).
// Builds an accelerator over the scene's closed objects to test the camera.
void warnAboutScene(const Scene& scene, const std::string& scenePath, Diagnostics& diagnostics);

} // namespace drt
