// pigment { image_map { [type] "file" [map_type n] [once] [interpolate n]
// [filter all f] [transmit all t] [gamma g] ... } }: the image is found here and
// decoded once after parsing (assets/assets.h), shared by every copy of the pigment.
#include "pov/parser.h"
#include "scene/image_map.h"

namespace drt::pov {

std::optional<Pigment> PovParser::imageMapPigment(SourceLoc keyword) {
    expectSymbol("{", "after 'image_map'");
    if (peek().isWord("function")) {
        warnOnce("image_map-function", peek().loc, "image_map { function ... } is not supported; the pigment becomes mid grey");
        skipBlock();
        return std::nullopt;
    }
    if (isImageTypeWord(peek())) next();
    auto map = std::make_shared<ImageMap>();
    const SourceLoc fileLoc = peek().loc;
    map->file = stringExpr();
    map->loc = fileLoc;
    map->path = findDataFile(map->file);
    if (map->path.empty())
        fail(fileLoc, "cannot find image file \"" + map->file + "\" (searched the scene's folder and the -L paths)");
    for (;;) {
        const Tok t = next();
        if (t.is("}")) break;
        if (t.isWord("map_type")) {
            const SourceLoc at = peek().loc;
            const int type = countExpr("map_type", -1e9, 1e9);
            if (type == 0 || type == 1 || type == 2 || type == 5) map->projection = ImageMap::Projection(type);
            else warnOnce("map_type", at, "map_type " + std::to_string(type) + " is not supported; planar mapping is used");
        } else if (t.isWord("once")) {
            map->once = true;
        } else if (t.isWord("interpolate")) {
            const SourceLoc at = peek().loc;
            const int type = countExpr("interpolate", -1e9, 1e9);
            if (type == 2) map->interpolation = ImageMap::Interpolation::Bilinear;
            else if (type == 3) map->interpolation = ImageMap::Interpolation::Bicubic;
            else if (type == 4) map->interpolation = ImageMap::Interpolation::NormalizedDistance;
            else if (type != 0) warnOnce("interpolate", at, "interpolate " + std::to_string(type) + " is not known; no interpolation");
        } else if (t.isWord("filter") || t.isWord("transmit")) {
            const bool filter = t.isWord("filter");
            if (acceptWord("all")) {
                (filter ? map->filterAll : map->transmitAll) = floatExpr();
            } else { // a palette index: OpenImageIO expands palettes, so indices are unknown
                floatExpr();
                acceptSymbol(",");
                floatExpr();
                warnOnce("image_map-index", t.loc, "per-index filter/transmit in an image_map is not supported and is ignored");
            }
        } else if (t.isWord("gamma")) {
            if (acceptWord("srgb")) map->gamma = 0;
            else {
                const SourceLoc at = peek().loc;
                map->gamma = floatExpr();
                if (!(map->gamma > 0)) fail(at, "image_map gamma must be positive");
            }
        } else if (t.isWord("premultiplied")) {
            floatExpr();
        } else if (t.isWord("use_color") || t.isWord("use_colour") || t.isWord("use_index") || t.isWord("use_alpha")) {
        } else {
            failExpected(t, "an image_map item or '}'");
        }
    }
    map->workingGamma = workingGamma();
    Pigment p;
    p.pattern = PatternKind::ImageMap;
    p.imageMap = std::move(map);
    (void)keyword;
    return p;
}

} // namespace drt::pov
