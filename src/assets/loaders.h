// Private to src/assets: one decoder per kind of file.
#pragma once

#include "core/diagnostics.h"
#include "scene/image_map.h"
#include "scene/scene.h"

#include <string>

namespace drt {

// Reads `map.path` and fills the texels, decoded with v^gamma when
// `map.gamma` > 0, else with the gamma the file states (a PNG gAMA chunk,
// a linear file), else from sRGB for integer files; float files (EXR, HDR)
// are linear. Alpha becomes transmit = 1 - alpha. Returns "" on success,
// else the reason.
std::string loadImageMap(ImageMap& map);

// Fills `mesh` from `source`; warnings go to `diags`. Returns "" on success,
// else the reason.
std::string loadMeshSource(const MeshSource& source, Mesh& mesh, Diagnostics& diags);

} // namespace drt
