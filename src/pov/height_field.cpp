// height_field { [type] "file" [smooth] [water_level w] [hierarchy b] }: a
// mesh whose triangles come from the image after parsing (Mesh::source,
// assets/assets.h). Image files are found like include files.
#include "pov/parser.h"

#include <filesystem>

namespace drt::pov {

namespace {

const std::set<std::string>& imageTypeWords() {
    static const std::set<std::string> w = {"gif", "tga", "iff", "ppm", "pgm", "png", "jpeg",
                                            "tiff", "sys", "exr", "hdr", "pot"};
    return w;
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
    auto source = std::make_shared<MeshSource>();
    source->kind = MeshSource::Kind::PovHeightField;
    source->path = path;
    source->loc = fileLoc;
    bool& smooth = source->smooth;
    double& waterLevel = source->waterLevel;
    for (;;) {
        const Tok t = peek();
        if (t.isWord("smooth")) next(), smooth = true;
        else if (t.isWord("water_level")) next(), waterLevel = floatExpr();
        else if (t.isWord("hierarchy")) next(), floatExpr(); // only POV-Ray's bounding
        else if (t.isWord("gamma") || t.isWord("premultiplied")) next(), floatExpr();
        else break;
    }
    // The image is decoded after parsing (assets/assets.h).
    Mesh m;
    m.source = std::move(source);
    (void)keyword;
    return m;
}

} // namespace drt::pov
