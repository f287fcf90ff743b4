#include "assets/loaders.h"

#include "image/image.h"
#include "image/srgb.h"

#include <cmath>

namespace drt {

std::string loadImageMap(ImageMap& map) {
    Image img;
    ImageFileInfo info;
    if (std::string error = readImageEncoded(map.path, img, info); !error.empty()) return error;
    if (img.width < 1 || img.height < 1) return "cannot read '" + map.path + "': empty image";
    // The scene's gamma wins, then the file's own (a PNG gAMA chunk), then sRGB for integer files.
    const double gamma = map.gamma > 0 ? map.gamma : info.fileGamma;
    auto decode = [&](float v) -> float {
        if (map.fileValues) return v;
        if (gamma > 0) return static_cast<float>(std::pow(std::max(0.0f, v), gamma));
        return info.srgbEncoded ? static_cast<float>(srgbDecode(v)) : v;
    };
    map.width = img.width;
    map.height = img.height;
    map.rgbt.assign(size_t(img.width) * img.height * 4, 0.0f);
    const int c = img.channels;
    const bool hasAlpha = c == 2 || c >= 4;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            float* out = &map.rgbt[(size_t(y) * img.width + x) * 4];
            if (c <= 2) {
                out[0] = out[1] = out[2] = decode(img.at(x, y, 0));
            } else {
                for (int k = 0; k < 3; ++k) out[k] = decode(img.at(x, y, k));
            }
            out[3] = hasAlpha ? 1.0f - img.at(x, y, c == 2 ? 1 : 3) : 0.0f;
        }
    return "";
}

} // namespace drt
