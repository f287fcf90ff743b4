// height_field { [type] "file" [smooth] [water_level w] [hierarchy b] } as a
// triangle mesh (scene/height_field.h). Image files are found like include files.
#include "image/image.h"
#include "pov/parser.h"
#include "scene/height_field.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace drt::pov {

namespace {

const std::set<std::string>& imageTypeWords() {
    static const std::set<std::string> w = {"gif", "tga", "iff", "ppm", "pgm", "png", "jpeg",
                                            "tiff", "sys", "exr", "hdr", "pot"};
    return w;
}

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

} // namespace

bool PovParser::isImageTypeWord(const Tok& t) { return t.kind == TokKind::Word && imageTypeWords().count(t.text); }

std::string PovParser::findDataFile(const std::string& name) const {
    std::string fromDir = ".";
    for (auto it = frames_.rbegin(); it != frames_.rend(); ++it)
        if (!it->isMacro) {
            fromDir = it->dir;
            break;
        }
    std::string path = findInclude(name, fromDir);
    // POV-Ray adds the image types' extensions to a name without one.
    if (path.empty() && !std::filesystem::path(name).has_extension())
        for (const char* ext : {".png", ".tga", ".jpg", ".jpeg", ".gif", ".ppm", ".pgm", ".tiff", ".tif", ".exr",
                                ".hdr", ".bmp"})
            if (path = findInclude(name + ext, fromDir); !path.empty()) break;
    return path;
}

std::optional<Mesh> PovParser::heightFieldShape(SourceLoc keyword) {
    if (peek().isWord("function")) {
        warnOnce("height_field-function", peek().loc,
                 "height_field { function ... } is not supported; the object is left out");
        next();
        floatExpr();
        acceptSymbol(",");
        floatExpr();
        expectSymbol("{", "after the function's resolution");
        skipBlock();
        while (peek().isWord("smooth") || peek().isWord("water_level") || peek().isWord("hierarchy")) {
            const Tok w = next();
            if (!w.isWord("smooth")) floatExpr();
        }
        return std::nullopt;
    }
    if (isImageTypeWord(peek())) {
        const Tok type = next();
        if (type.isWord("pot"))
            warnOnce("height_field-pot", type.loc,
                     "Fractint 'pot' files are read as plain GIF images, not as 16-bit heights (approximate)");
    }
    const SourceLoc fileLoc = peek().loc;
    const std::string name = stringExpr();
    const std::string path = findDataFile(name);
    if (path.empty())
        fail(fileLoc, "cannot find image file \"" + name + "\" (searched the scene's folder and the -L paths)");
    Image img;
    ImageFileInfo info;
    if (const std::string error = readImageEncoded(path, img, info); !error.empty()) fail(fileLoc, error);
    if (img.width < 2 || img.height < 2) fail(fileLoc, "a height_field image needs at least 2x2 pixels");
    bool smooth = false;
    double waterLevel = 0;
    for (;;) {
        const Tok t = peek();
        if (t.isWord("smooth")) next(), smooth = true;
        else if (t.isWord("water_level")) next(), waterLevel = floatExpr();
        else if (t.isWord("hierarchy")) next(), floatExpr(); // only POV-Ray's bounding
        else if (t.isWord("gamma") || t.isWord("premultiplied")) next(), floatExpr();
        else break;
    }
    // Palette images: POV-Ray's height is the palette index times 256, but
    // OpenImageIO (drt's one image reader) expands palettes, so their colours'
    // rule applies (docs/pov.md).
    // POV-Ray puts image row 0 (the top) at z = 1 and scales heights by 1/65536.
    std::vector<double> heights(size_t(img.width) * img.height);
    for (int z = 0; z < img.height; ++z)
        for (int x = 0; x < img.width; ++x) {
            const int row = img.height - 1 - z;
            const double value = povHeightValue(img, info, x, row);
            heights[size_t(z) * img.width + x] = value / 65536.0;
        }
    Mesh m = heightFieldMesh(heights, img.width, img.height, smooth, waterLevel);
    if (m.triangles.empty()) {
        warn(keyword, "the height_field lies entirely below its water_level; it is left out");
        return std::nullopt;
    }
    return m;
}

} // namespace drt::pov
