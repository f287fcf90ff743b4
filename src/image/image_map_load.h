// Decoding the image file of an image_map pigment (scene/image_map.h).
#pragma once

#include "scene/image_map.h"

#include <string>

namespace drt {

// Reads `map.path` and fills the texels: integer files are decoded from sRGB,
// or with v^gamma when `map.gamma` > 0; float files (EXR, HDR) are linear
// (v^gamma when given). Alpha becomes transmit = 1 - alpha. Returns "" on
// success, else the reason.
std::string loadImageMap(ImageMap& map);

} // namespace drt
