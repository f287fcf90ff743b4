// image-map = "image_map" "{" string { image-map-item } "}" inside a pigment.
// The file is found beside the including file, then beside the scene.
#include "lang/parser.h"
#include "scene/image_map.h"

#include <filesystem>

namespace fs = std::filesystem;

namespace drt {

// image-map-item = "map_type" ( 0 | 1 | 2 | 5 ) | "once" | "interpolate" ( 0 | 2 | 3 | 4 )
//                | "filter" "all" float | "transmit" "all" float | "gamma" float
void Parser::imageMap(Pigment& p) {
    advance(); // image_map
    expect(TokenKind::LeftBrace, "'{' after 'image_map'");
    const Token file = expect(TokenKind::String, "the image file name in quotes");
    auto map = std::make_shared<ImageMap>();
    map->file = file.text;
    map->loc = file.loc;
    std::error_code ec;
    for (const std::string& dir : {sources_.back().dir, sources_.front().dir}) {
        const fs::path candidate = fs::path(file.text).is_absolute() ? fs::path(file.text) : fs::path(dir) / file.text;
        if (fs::is_regular_file(candidate, ec)) {
            map->path = fs::absolute(candidate, ec).lexically_normal().string();
            break;
        }
    }
    if (map->path.empty()) fail(file.loc, "cannot find image file '" + file.text + "'");
    while (!match(TokenKind::RightBrace)) {
        if (matchWord("map_type")) {
            const SourceLoc at = current_.loc;
            const int type = intExpr("the map type");
            if (type != 0 && type != 1 && type != 2 && type != 5)
                error(at, "map_type must be 0 (planar), 1 (spherical), 2 (cylindrical) or 5 (torus)");
            else map->projection = ImageMap::Projection(type);
        } else if (matchWord("once")) {
            map->once = true;
        } else if (matchWord("interpolate")) {
            const SourceLoc at = current_.loc;
            const int type = intExpr("the interpolation");
            if (type != 0 && type != 2 && type != 3 && type != 4)
                error(at, "interpolate must be 0 (none), 2 (bilinear), 3 (bicubic) or 4 (normalised distance)");
            else map->interpolation = ImageMap::Interpolation(type);
        } else if (checkWord("filter") || checkWord("transmit")) {
            const bool filter = checkWord("filter");
            advance();
            if (!matchWord("all")) failExpected("'all' and an amount");
            (filter ? map->filterAll : map->transmitAll) = floatExpr("the amount");
        } else if (matchWord("gamma")) {
            const SourceLoc vloc = current_.loc;
            map->gamma = floatExpr("the file's gamma");
            if (!(map->gamma > 0)) error(vloc, "gamma must be positive"), map->gamma = 0;
        } else {
            failExpected("an image_map item (map_type once interpolate filter transmit gamma) or '}'");
        }
    }
    map->workingGamma = scene_.global.assumedGamma;
    // The pixels are decoded after parsing (assets/assets.h).
    p.pattern = PatternKind::ImageMap;
    p.imageMap = std::move(map);
    p.children.clear();
}

} // namespace drt
