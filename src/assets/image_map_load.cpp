#include "assets/loaders.h"

#include "image/image.h"
#include "image/srgb.h"

#include <algorithm>
#include <cmath>

namespace drt {

namespace {

// The palette indices a material_map or a per-index amount needs (ImageMap::needsIndices).
std::string applyIndices(ImageMap& map, const Image& img, Diagnostics& diags) {
    std::vector<uint8_t> palette;
    if (std::string error = readPaletteIndices(map.path, img.width, img.height, palette); !error.empty()) return error;
    const size_t texels = size_t(img.width) * size_t(img.height);
    if (palette.empty() && (!map.indexFilter.empty() || !map.indexTransmit.empty()))
        diags.warning(map.loc, "'" + map.file +
                                   "' has no palette: its per-index filter and transmit amounts are left out");
    if (map.material) {
        if (!palette.empty()) {
            map.indices = palette;
        } else { // no palette: the 8-bit red value, as stored in the file
            map.indices.resize(texels);
            for (int y = 0; y < img.height; ++y)
                for (int x = 0; x < img.width; ++x) {
                    const double red = std::clamp(double(img.at(x, y, 0)), 0.0, 1.0);
                    map.indices[size_t(y) * img.width + x] = static_cast<uint8_t>(std::lround(red * 255));
                }
        }
    }
    if (palette.empty()) return "";
    if (!map.indexFilter.empty()) map.filter.assign(texels, 0.0f);
    for (size_t i = 0; i < texels; ++i) {
        for (const ImageMap::IndexAmount& a : map.indexFilter)
            if (a.index == palette[i]) map.filter[i] = static_cast<float>(a.amount);
        for (const ImageMap::IndexAmount& a : map.indexTransmit)
            if (a.index == palette[i]) map.rgbt[i * 4 + 3] = static_cast<float>(a.amount);
    }
    return "";
}

} // namespace

std::string loadImageMap(ImageMap& map, Diagnostics& diags) {
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
    if (map.needsIndices()) return applyIndices(map, img, diags);
    return "";
}

} // namespace drt
