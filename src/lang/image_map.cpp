// pigment { image_map { [type] "file" [map_type n] [once] [interpolate n]
// [filter all f] [transmit all t] [filter i, f] [transmit i, t] [gamma g] ... } }
// and texture { material_map { [type] "file" [modifiers] texture {..}.. } }: the image is found here and
// decoded once after parsing (assets/assets.h), shared by every copy of the
// pigment. Files are found like include files (image extensions tried for a
// name without one).
#include "lang/evaluator.h"
#include "scene/density_file.h"
#include "scene/image_map.h"

#include <filesystem>

namespace fs = std::filesystem;

namespace drt::lang {

namespace {

bool isImageTypeWord(const Token& t) {
    static const std::set<std::string> words = {"gif", "tga",  "iff", "ppm", "pgm", "png",
                                                "jpeg", "tiff", "sys", "exr", "hdr", "pot"};
    return t.kind == TokenKind::Word && words.count(t.text);
}

} // namespace

std::string Evaluator::findDataFile(const std::string& name, bool imageExtensions) const {
    const std::string fromDir = currentDir();
    std::string path = findInclude(name, fromDir);
    if (path.empty() && fromDir != mainDir_) path = findInclude(name, mainDir_);
    // POV-Ray adds the image types' extensions to a name without one.
    if (path.empty() && imageExtensions && !fs::path(name).has_extension())
        for (const char* ext : {".png", ".tga", ".jpg", ".jpeg", ".gif", ".ppm", ".pgm", ".tiff", ".tif", ".exr",
                                ".hdr", ".bmp"})
            if (path = findInclude(name + ext, fromDir); !path.empty()) break;
    if (path.empty()) return path;
    std::error_code ec;
    return fs::absolute(path, ec).lexically_normal().string();
}

void Evaluator::dataFileName(const char* format, const char* kind, bool imageExtensions, std::string& file,
                             std::string& path, SourceLoc& loc) {
    const Token name = peek();
    if (syntax().kind == DialectKind::Drt && name.kind != TokenKind::String)
        failExpected(next(), std::string("the ") + format + " file name in quotes");
    file = stringExpr();
    loc = name.loc;
    path = findDataFile(file, imageExtensions);
    if (path.empty()) fail(name.loc, std::string("cannot find ") + kind + " file '" + file + "'");
}

std::shared_ptr<const DensityFile> Evaluator::densityFile(const Token& keyword) {
    if (!acceptWord("df3")) failExpected(peek(), "'df3' (the file's format) after '" + keyword.text + "'");
    auto d = std::make_shared<DensityFile>();
    dataFileName("df3", "density", false, d->file, d->path, d->loc);
    if (acceptWord("interpolate")) return densityInterpolate(d);
    return d;
}

std::shared_ptr<const DensityFile> Evaluator::densityInterpolate(const std::shared_ptr<const DensityFile>& d) {
    const SourceLoc at = peek().loc;
    const int type = intExpr("the interpolation");
    auto changed = std::make_shared<DensityFile>(*d);
    if (type >= 0 && type <= 2) changed->interpolation = DensityFile::Interpolation(type);
    else if (syntax().strictValues)
        error(at, "density_file interpolate must be 0 (none), 1 (trilinear) or 2 (tricubic)" + got(type));
    else warnOnce("density-interpolate", at, "interpolate " + std::to_string(type) + " is not known; no interpolation");
    return changed;
}

std::optional<Pigment> Evaluator::imageMapPigment(SourceLoc keyword, bool pattern) {
    const std::string name = pattern ? "image_pattern" : "image_map";
    expectSymbol("{", "after '", name, "'");
    BlockScope scope(*this, name, keyword);
    if (peek().isWord("function")) {
        unsupported(name + "-function", peek().loc,
                    name + " { function ... } is not supported; the pigment becomes mid grey");
        skipBlock();
        return std::nullopt;
    }
    Pigment p;
    p.pattern = pattern ? PatternKind::ImagePattern : PatternKind::ImageMap;
    p.imageMap = imageMapBody(nullptr, pattern);
    return p;
}

std::shared_ptr<ImageMap> Evaluator::imageMapBody(const std::function<bool(const Token&)>& item, bool pattern) {
    if (isImageTypeWord(peek())) next();
    auto map = std::make_shared<ImageMap>();
    dataFileName("image", "image", true, map->file, map->path, map->loc);
    for (;;) {
        const Token t = next();
        if (t.is("}")) break;
        const SourceLoc at = peek().loc;
        if (item && item(t)) continue;
        if (t.isWord("map_type")) {
            const int type = intExpr("the map type");
            if (type == 0 || type == 1 || type == 2 || type == 5) map->projection = ImageMap::Projection(type);
            else if (syntax().strictValues)
                error(at, "map_type must be 0 (planar), 1 (spherical), 2 (cylindrical) or 5 (torus)" + got(type));
            else warnOnce("map_type", at, "map_type " + std::to_string(type) + " is not supported; planar mapping is used");
        } else if (t.isWord("once")) {
            map->once = true;
        } else if (t.isWord("interpolate")) {
            const int type = intExpr("the interpolation");
            if (type == 0 || type == 2 || type == 3 || type == 4) map->interpolation = ImageMap::Interpolation(type);
            else if (syntax().strictValues)
                error(at, "interpolate must be 0 (none), 2 (bilinear), 3 (bicubic) or 4 (normalised distance)" +
                              got(type));
            else warnOnce("interpolate", at, "interpolate " + std::to_string(type) + " is not known; no interpolation");
        } else if (t.isWord("filter") || t.isWord("transmit")) {
            const bool filter = t.isWord("filter");
            if (acceptWord("all")) {
                (filter ? map->filterAll : map->transmitAll) = floatExpr("the amount");
            } else { // a palette index and its amount (assets/image_map_load.cpp)
                const int index = intExpr("the palette index");
                if (index < 0 || index > 255) error(at, "a palette index runs from 0 to 255" + got(index));
                if (syntax().kind == DialectKind::Drt) expectSymbol(",", "between the palette index and its amount");
                else acceptSymbol(",");
                const double amount = floatExpr("the amount");
                (filter ? map->indexFilter : map->indexTransmit).push_back({index, amount});
            }
        } else if (t.isWord("gamma")) {
            if (acceptWord("srgb")) {
                map->gamma = 0;
            } else {
                map->gamma = floatExpr("the file's gamma");
                if (!(map->gamma > 0)) error(at, "gamma must be positive" + got(map->gamma)), map->gamma = 0;
            }
        } else if (t.isWord("premultiplied")) {
            floatExpr();
        } else if (pattern && t.isWord("use_alpha")) {
            unsupported("image_pattern-use_alpha", t.loc,
                        "image_pattern's use_alpha is not supported; the pattern is the image's grey");
        } else if (t.isWord("use_color") || t.isWord("use_colour") || t.isWord("use_index") || t.isWord("use_alpha")) {
        } else if (t.kind == TokenKind::Word) {
            failUnknown(t, Block::ImageMap);
        } else {
            failInBlock(t, item ? "a material_map item (map_type once interpolate texture) or '}'"
                                : "an image_map item (map_type once interpolate filter transmit gamma) or '}'");
        }
    }
    map->workingGamma = scene().versionGammaRules ? workingGamma() : scene_.global.assumedGamma;
    if (pattern) map->fileValues = true, map->workingGamma = 1;
    return map;
}

// ------------------------------------------------------------ transforms

void Evaluator::requireNonZero(const Vec3& v, SourceLoc loc, const std::string& what) {
    if (v.x == 0 && v.y == 0 && v.z == 0) refuse(loc, what + " must not be a zero-length vector");
}

// translate v | rotate v | scale v | matrix <12 numbers> | transform { ... } | transform Name
std::optional<Transform> Evaluator::transformItem() {
    const Token t = peek();
    if (t.kind != TokenKind::Word) return std::nullopt;
    const std::string& w = t.text;
    if (w == "translate") {
        next();
        return Transform::translate(vectorExpr());
    }
    if (w == "rotate") {
        next();
        return Transform::rotate(vectorExpr());
    }
    if (w == "scale") {
        next();
        const SourceLoc loc = peek().loc;
        Vec3 s = vectorExpr();
        if (s.x != 0 && s.y != 0 && s.z != 0) return Transform::scale(s);
        if (syntax().strictValues) {
            error(loc, "scale has a zero component (the object would collapse)" + got(s));
            return Transform{};
        }
        // POV-Ray warns and uses 1 for a zero scale component.
        warnOnce("scale0", loc, "scale with a zero component; that component is left at 1 (as POV-Ray)");
        for (int i = 0; i < 3; ++i)
            if (s[i] == 0) s[i] = 1;
        return Transform::scale(s);
    }
    if (w == "matrix") {
        next();
        expectSymbol("<", "after 'matrix'");
        const bool saved = inVector_;
        inVector_ = true;
        std::array<double, 12> m{};
        int count = 0;
        for (;;) {
            const SourceLoc loc = peek().loc;
            const double v = floatExpr("a matrix entry");
            if (count == 12) fail(loc, "'matrix' takes exactly 12 numbers");
            m[size_t(count++)] = v;
            if (acceptSymbol(",")) continue;
            if (peek().is(">")) break;
            if (syntax().requireCommas) failExpected(peek(), "',' or '>' in the matrix");
        }
        inVector_ = saved;
        expectSymbol(">", "after the 12 matrix numbers");
        if (count != 12) fail(t.loc, "'matrix' takes exactly 12 numbers, got " + std::to_string(count));
        std::optional<Transform> tr = Transform::fromPovMatrix(m);
        if (!tr) {
            error(t.loc, "singular matrix (it has no inverse)");
            return Transform{};
        }
        return tr;
    }
    if (w == "transform") {
        next();
        return transformBlock();
    }
    return std::nullopt;
}

Transform Evaluator::transformBlock() {
    const Token t = next();
    if (t.kind == TokenKind::Word) {
        const Cell c = useIndexed(t);
        if (c && c->kind == Value::Kind::Transform) return *c->transform;
        failExpected(t, "'{' or a transform identifier after 'transform'");
    }
    if (!t.is("{")) failExpected(t, "'{' after 'transform'");
    Transform result;
    for (;;) {
        if (acceptSymbol("}")) return result;
        if (acceptWord("inverse")) {
            result = result.inverted();
            continue;
        }
        if (std::optional<Transform> item = transformItem()) {
            result = result.then(*item);
            continue;
        }
        const Token id = next();
        const Cell c = id.kind == TokenKind::Word ? useIndexed(id) : nullptr;
        if (c && c->kind == Value::Kind::Transform) {
            result = result.then(*c->transform);
            continue;
        }
        failInBlock(id, "a transform or '}'");
    }
}

} // namespace drt::lang
