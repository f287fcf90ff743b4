// POV-Ray's height_field image as a mesh (scene/height_field.h).
#include "assets/loaders.h"
#include "image/image.h"
#include "scene/height_field.h"

#include <algorithm>
#include <cmath>

namespace drt {

namespace {

// POV-Ray's height of one pixel, in [0, 65535] (HF_VAL), from the values as
// stored in the file (scaled to [0, 1]): greyscale files use the grey value,
// colour files deeper than 8 bits their grey (0.297 r + 0.589 g + 0.114 b)
// and 8-bit colour files red as the high byte and green as the low byte.
// Palette PNGs use their index instead (below); palette GIFs, which
// OpenImageIO expands, use the colour rule.
// Integer samples are read back exactly by rounding (POV-Ray truncates a float
// product, which can land one step of 1/65536 lower).
double povHeightValue(const Image& img, const ImageFileInfo& info, int x, int y) {
    auto clamp16 = [](double v) { return std::clamp(std::round(v), 0.0, 65535.0); };
    const int c = img.channels;
    const double r = img.at(x, y, 0);
    if (c <= 2) return clamp16(r * 65535.0);
    const double g = img.at(x, y, 1), b = img.at(x, y, 2);
    if (info.isFloat || info.bitsPerChannel > 8) return clamp16((0.297 * r + 0.589 * g + 0.114 * b) * 65535.0);
    return clamp16(std::round(r * 255.0) * 256.0 + std::round(g * 255.0));
}

std::string loadPovHeightField(const MeshSource& source, Mesh& mesh, Diagnostics& diags) {
    Image img;
    ImageFileInfo info;
    if (std::string error = readImageEncoded(source.path, img, info); !error.empty()) return error;
    if (img.width < 2 || img.height < 2) return "a height_field image needs at least 2x2 pixels";
    // Palette images: POV-Ray's height is the palette index times 256, but
    // OpenImageIO (drt's one image reader) expands palettes, so their colours'
    // rule applies (docs/pov.md).
    // POV-Ray puts image row 0 (the top) at z = 1 and scales heights by 1/65536.
    std::vector<double> heights(size_t(img.width) * img.height);
    for (int z = 0; z < img.height; ++z)
        for (int x = 0; x < img.width; ++x) {
            const int row = img.height - 1 - z;
            heights[size_t(z) * img.width + x] = povHeightValue(img, info, x, row) / 65536.0;
        }
    Mesh built = heightFieldMesh(heights, img.width, img.height, source.smooth, source.waterLevel);
    if (built.triangles.empty())
        diags.warning(source.loc, "the height_field lies entirely below its water_level; it is left out");
    mesh.vertices = std::move(built.vertices);
    mesh.triangles = std::move(built.triangles);
    mesh.normals = std::move(built.normals);
    mesh.normalIndices = std::move(built.normalIndices);
    return "";
}

} // namespace

std::string loadMeshSource(const MeshSource& source, Mesh& mesh, Diagnostics& diags) {
    switch (source.kind) {
    case MeshSource::Kind::PovHeightField: return loadPovHeightField(source, mesh, diags);
    case MeshSource::Kind::ModelFile: break; // loadModelFile
    }
    return "unknown mesh source";
}

} // namespace drt
