// texture { }, layered and patterned textures (texture_map; checker, hexagon,
// brick and tiles of textures), pigment_map, material and normal. Map entries
// hold a texture / pigment *body*: `[0.5 T_Stone scale 2]`, `[0.3 checker Red White]`.
#include "lang/evaluator.h"
#include "scene/image_map.h"
#include "lang/quilted.h"
#include "lang/mesh_syntax.h"

#include <fmt/format.h>

namespace drt::lang {

namespace {
// Layers of one texture (POV-Ray scenes use a handful; 10,000 take about 0.1 s to read).
constexpr size_t kMaxTextureLayers = 10000;
} // namespace

using Kind = Value::Kind;

void Evaluator::layerOnTop(Texture& below, Texture top, SourceLoc loc) {
    // Each layer added copies the layers below it, so a loop adding layers
    // without end would take time quadratic in their number: stop it.
    const size_t layers = below.layersAbove.size() + top.layersAbove.size() + 2;
    if (layers > kMaxTextureLayers)
        failLimit(loc, fmt::format("a texture of {} layers is over drt's maximum of {} (a loop adding layers?)",
                                   layers, kMaxTextureLayers));
    if (hasPatternedLayer(below)) fail(loc, "cannot layer over a patterned texture (as POV-Ray)");
    if (hasPatternedLayer(top)) fail(loc, "cannot layer a patterned texture over another texture (as POV-Ray)");
    addLayerOnTop(below, std::move(top));
}

Texture Evaluator::texture(const Texture& base) {
    const Token keyword = lastToken();
    DepthGuard guard(*this, keyword.loc);
    expectSymbol("{", "after 'texture'");
    BlockScope scope(*this, "texture", keyword.loc);
    // A new texture starts from the base's bottom layer; a patterned base gives only its defaults.
    Texture start = !scene().modifyBlocks ? defaultTexture_ : base.map.empty() ? base : Texture{};
    start.layersAbove.clear();
    return textureBody(start, "}", "'}' in texture");
}

Texture Evaluator::textureBody(const Texture& base, const char* closer, const std::string& where) {
    Texture tex = base;
    bool uv = false; // uv_mapping in the texture: its pigment and normal read the surface's uv
    for (;;) {
        const Token t = peek();
        if (t.is(closer)) {
            next();
            if (uv) {
                setUvMapping(tex.pigment, true);
                if (tex.normal) tex.normal->uvMapping = true;
            }
            return tex;
        }
        if (std::optional<Transform> tr = transformItem()) {
            transformTextureSpaces(tex, *tr);
            continue;
        }
        next();
        if (t.kind != TokenKind::Word) failInBlock(t, "'pigment', 'finish', 'normal', a transform or " + where);
        const Cell c = useIndexed(t);
        if (c && c->kind == Kind::Texture) {
            tex = *c->texture;
            continue;
        }
        if (c) fail(t.loc, "'" + t.text + "' is " + kindName(*c) + ", not a texture");
        const std::string& w = t.text;
        if (w == "pigment") tex.pigment = pigment(tex.pigment);
        else if (w == "finish") tex.finish = finish(tex.finish);
        else if (w == "normal") {
            if (std::optional<Normal> n = normalBlock(t.loc, tex.normal)) tex.normal = std::move(n);
        } else if (isTexturePatternWord(t)) {
            Texture patterned = patternedTexture(t, closer, where);
            if (uv) patterned.pigment.uvMapping = true; // the pattern; its entries keep their own mapping
            return patterned;
        } else if (w == "uv_mapping") {
            uv = true;
        } else if (w == "quick_color" || w == "quick_colour") {
            colorExpr();
        } else {
            failUnknown(t, Block::Texture, declaredNames({Kind::Texture}));
        }
    }
}

bool Evaluator::isTexturePatternWord(const Token& t) const {
    if (t.kind != TokenKind::Word || lookup(t.text)) return false;
    const std::string& w = t.text;
    return w == "texture_map" || w == "material_map" || w == "tiles" || w == "checker" || w == "hexagon" ||
           w == "brick" || w == "gradient" || w == "average" || w == "function" || w == "quilted" ||
           w == "pigment_pattern" || w == "density_file" || placePatternNamed(w).has_value() || noisePatternNamed(w).has_value() || isFractalWord(w) || isApproximatedPattern(w);
}

// `[value, body]` of a map; in an `average` map the value (the weight) may be left out: 1.
double Evaluator::mapEntryValue(bool average, const char* map, const double* previous) {
    const Token t = peek();
    if (average && (t.isWord("function") || !startsFloat(t))) return 1;
    const double v = floatExpr("the entry's value");
    // Map values do not decrease (POV-Ray: below the first entry its value holds,
    // above the last the last one's); `average` has non-negative weights instead.
    if (average && v < 0) refuse(t.loc, std::string(map) + " weights (with 'average') must not be negative");
    if (!average && previous && v < *previous) refuse(t.loc, std::string(map) + " values must not decrease");
    acceptSymbol(",");
    return v;
}

std::vector<Texture::MapEntry> Evaluator::textureMap(bool average) {
    const Token keyword = lastToken();
    DepthGuard guard(*this, keyword.loc);
    expectSymbol("{", "after 'texture_map'");
    BlockScope scope(*this, "texture_map", keyword.loc);
    std::vector<Texture::MapEntry> map;
    for (;;) {
        const Token t = next();
        if (t.is("}")) break;
        if (!t.is("[")) failInBlock(t, "'[' to start a texture_map entry, or '}'");
        Texture::MapEntry entry;
        entry.value = mapEntryValue(average, "texture_map", map.empty() ? nullptr : &map.back().value);
        if (peek().isWord("texture")) { // whole textures: a layered entry, `[v texture {A} texture {B}]`
            next();
            entry.texture = texture(defaultTexture_);
            while (peek().isWord("texture")) {
                const Token layer = next();
                layerOnTop(entry.texture, texture(defaultTexture_), layer.loc);
            }
            expectSymbol("]", "to end the texture_map entry");
        } else {
            entry.texture = textureBody(defaultTexture_, "]", "']' to end the texture_map entry");
        }
        map.push_back(std::move(entry));
    }
    if (map.empty()) refuse(keyword.loc, "texture_map has no entries");
    return map;
}

std::vector<Pigment::MapEntry> Evaluator::pigmentMap(bool average) {
    const Token keyword = lastToken();
    const std::string name = keyword.text; // pigment_map, or density_map (its entries densities)
    DepthGuard guard(*this, keyword.loc);
    expectSymbol("{", "after '", name, "'");
    BlockScope scope(*this, name, keyword.loc);
    std::vector<Pigment::MapEntry> map;
    for (;;) {
        const Token t = next();
        if (t.is("}")) break;
        if (!t.is("[")) failInBlock(t, "'[' to start a " + name + " entry, or '}'");
        Pigment::MapEntry entry;
        entry.value = mapEntryValue(average, name.c_str(), map.empty() ? nullptr : &map.back().value);
        entry.pigment = pigmentBody(Pigment{}, "]", "']' to end the " + name + " entry");
        map.push_back(std::move(entry));
    }
    if (map.empty()) refuse(keyword.loc, name + " has no entries");
    return map;
}

// After the pattern word of `texture { PATTERN ... }`, up to `closer`. The
// texture's pigment carries the pattern; its entries are the map (block
// patterns: their textures in order).
Texture Evaluator::patternedTexture(const Token& word, const char* closer, const std::string& where) {
    Texture tex;
    Pigment& pattern = tex.pigment;
    const std::string& w = word.text;
    std::string approximated; // a pattern drt lacks: the entries are averaged
    bool uvPattern = false;   // uv_mapping among the pattern's modifiers
    const bool block = w == "checker" || w == "hexagon" || w == "brick" || w == "tiles" || w == "material_map";
    // checker / hexagon / brick: `count` textures, commas optional.
    auto blockTextures = [&](int count) {
        for (int i = 0; i < count && peek().isWord("texture"); ++i) {
            next();
            tex.map.push_back({double(i), texture(defaultTexture_)});
            acceptSymbol(",");
        }
        if (tex.map.size() != size_t(count))
            refuse(word.loc, "'" + w + "' needs " + std::to_string(count) + " textures");
    };
    if (w == "checker") {
        pattern.pattern = PatternKind::Checker;
        blockTextures(2);
    } else if (w == "hexagon") {
        pattern.pattern = PatternKind::Hexagon;
        blockTextures(3);
    } else if (w == "brick") {
        pattern.pattern = PatternKind::Brick;
        blockTextures(2);
    } else if (w == "tiles") {
        // tiles { texture.. tile2 texture.. }: a checker of (possibly layered) textures.
        pattern.pattern = PatternKind::Checker;
        expectSymbol("{", "after 'tiles'");
        for (int tile = 0; tile < 2; ++tile) {
            if (!peek().isWord("texture"))
                failExpected(peek(), tile == 0 ? "'texture' in tiles" : "'texture' after 'tile2'");
            next();
            Texture stack = texture(defaultTexture_);
            while (peek().isWord("texture")) {
                const Token keyword = next();
                layerOnTop(stack, texture(defaultTexture_), keyword.loc);
            }
            tex.map.push_back({double(tile), std::move(stack)});
            if (tile == 0 && !acceptWord("tile2")) failExpected(peek(), "'tile2' or another 'texture' in tiles");
        }
        expectSymbol("}", "to end tiles");
        // Measured against POV-Ray 3.7: tile2 lies where `checker` puts its first texture.
        std::swap(tex.map[0].texture, tex.map[1].texture);
    } else if (w == "gradient") {
        pattern.pattern = PatternKind::Gradient;
        const SourceLoc loc = peek().loc;
        pattern.gradientAxis = vectorExpr("the gradient axis");
        requireNonZero(pattern.gradientAxis, loc, "gradient axis");
    } else if (const std::optional<PatternKind> place = placePatternNamed(w)) {
        pattern.pattern = *place;
    } else if (w == "average") {
        pattern.pattern = PatternKind::Average;
    } else if (w == "function") {
        pattern.pattern = PatternKind::Function;
        pattern.function = patternFunction(word);
    } else if (w == "density_file") {
        pattern.pattern = PatternKind::DensityFile;
        pattern.densityFile = densityFile(word);
    } else if (w == "pigment_pattern") {
        pattern.pattern = PatternKind::Function;
        pattern.function = pigmentPatternFunction(word);
    } else if (w == "quilted") {
        pattern.pattern = PatternKind::Function;
        pattern.function = quiltedFunction(1, 1);
    } else if (isFractalWord(w)) {
        pattern.pattern = PatternKind::Fractal;
        pattern.fractal = fractalPattern(word);
    } else if (const std::optional<PatternKind> kind = noisePatternNamed(w)) {
        pattern.pattern = *kind;
        noiseNote(w, word.loc);
    } else if (w == "material_map") {
        // material_map { FILE "file" [modifiers] texture {..}.. }: the texture numbered by the texel's palette
        // index (modulo their count; render/image_pattern.h).
        expectSymbol("{", "after 'material_map'");
        BlockScope scope(*this, "material_map", word.loc);
        pattern.pattern = PatternKind::ImageMap;
        std::shared_ptr<ImageMap> map = imageMapBody([&](const Token& t) {
            if (!t.isWord("texture")) return false;
            tex.map.push_back({double(tex.map.size()), texture(defaultTexture_)});
            return true;
        });
        if (tex.map.empty()) refuse(word.loc, "a material_map needs at least one texture", true);
        map->material = true;
        pattern.imageMap = std::move(map);
    } else if (w == "texture_map") {
        // A map without a pattern: POV-Ray's default pattern is none; averaged below.
        if (syntax().unsupportedIsError) fail(word.loc, "a texture_map needs a pattern before it");
        pushBack(word);
        approximated = "(none)";
    } else {
        if (syntax().unsupportedIsError) fail(word.loc, "texture pattern '" + w + "' is not supported");
        approximated = w;
        if (w == "object") {
            if (peek().is("{")) next(), skipBlock();
        } else if (w == "spiral1" || w == "spiral2") {
            floatExpr();
        } else if (w == "slope" || w == "aoi") { // slope <v> or slope { <v> [, lo, hi] [altitude ..] }
            if (peek().is("{")) next(), skipBlock();
            else if (w == "slope") vectorExpr();
        }
    }
    for (;;) {
        const Token t = peek();
        if (t.is(closer)) {
            next();
            break;
        }
        if (std::optional<Transform> tr = transformItem()) {
            transformTextureSpaces(tex, *tr);
            continue;
        }
        if (turbulenceItem(t, pattern.turbulence)) continue;
        if (!block && waveItem(t, pattern.wave)) continue;
        if (fractalModifier(t, pattern.fractal)) continue;
        if (t.isWord("interpolate") && pattern.pattern == PatternKind::DensityFile && pattern.densityFile) {
            next();
            pattern.densityFile = densityInterpolate(pattern.densityFile);
            continue;
        }
        if (double c0, c1; (t.isWord("control0") || t.isWord("control1")) &&
                           pattern.pattern == PatternKind::Function && pattern.function &&
                           quiltedControls(*pattern.function, c0, c1)) { // after quilted
            next();
            (t.text == "control0" ? c0 : c1) = floatExpr();
            pattern.function = quiltedFunction(c0, c1);
            continue;
        }
        next();
        if (t.kind != TokenKind::Word)
            failInBlock(t, "'texture_map', a pattern modifier, a transform or " + where);
        if (t.text == "texture_map") {
            if (block) fail(t.loc, "'" + w + "' takes its textures directly, not a texture_map");
            tex.map = textureMap(pattern.pattern == PatternKind::Average);
        } else if (t.text == "brick_size") {
            const SourceLoc loc = peek().loc;
            pattern.brickSize = vectorExpr();
            if (!(pattern.brickSize.x > 0 && pattern.brickSize.y > 0 && pattern.brickSize.z > 0))
                refuse(loc, "'brick_size' components must be positive" + got(pattern.brickSize));
        } else if (t.text == "mortar") {
            const SourceLoc loc = peek().loc;
            pattern.mortar = floatExpr();
            if (pattern.mortar < 0) refuse(loc, "'mortar' must not be negative" + got(pattern.mortar));
        } else if (t.text == "warp" || t.text == "noise_generator" || t.text == "agate_turb") {
            unsupported(t.text, t.loc, "'" + t.text + "' is not supported and is ignored");
            if (t.text == "warp") expectSymbol("{", "after 'warp'"), skipBlock();
            else expression();
        } else if (pattern.pattern == PatternKind::Crackle &&
                   (t.text == "metric" || t.text == "form" || t.text == "offset" || t.text == "solid")) {
            unsupported("crackle-" + t.text, t.loc, "crackle '" + t.text + "' is not supported and is ignored");
            if (t.text == "form") vectorExpr();
            else if (t.text != "solid") floatExpr();
        } else if (t.text == "uv_mapping") {
            uvPattern = true; // the pattern in uv space; its entries keep their own mapping
        } else {
            std::vector<std::string> known = blockKeywords(Block::TexturePattern);
            if (!block)
                for (const std::string& wave : blockKeywords(Block::Normal))
                    if (wave.find("wave") != std::string::npos || wave == "frequency" || wave == "phase")
                        known.push_back(wave);
            failUnknownIn(t, known);
        }
    }
    if (!approximated.empty()) {
        warnOnce("texture-pattern-" + approximated, word.loc,
                 "texture pattern '" + approximated +
                     "' is approximated by the equally weighted average of its texture_map");
        pattern.pattern = PatternKind::Average;
        for (Texture::MapEntry& entry : tex.map) entry.value = 1;
    } else if (!block && tex.map.empty()) {
        refuse(word.loc, "a '" + w + "' texture needs a texture_map");
    }
    if (uvPattern) pattern.uvMapping = true; // after its own transforms, which act in uv space
    return tex;
}

Material Evaluator::material(const Material& base) {
    expectSymbol("{", "after 'material'");
    Material m = base;
    for (;;) {
        const Token t = next();
        if (t.is("}")) return m;
        if (t.kind != TokenKind::Word) failInBlock(t, "'texture', 'interior', a transform or '}' in material");
        const Cell c = useIndexed(t);
        if (c && c->kind == Kind::Material) {
            m = *c->material;
            continue;
        }
        if (t.text == "texture") {
            if (m.texture) layerOnTop(*m.texture, texture(Texture{}), t.loc); // a layer on top
            else m.texture = texture(Texture{});
        } else if (t.text == "interior") {
            m.interior = interior(m.interior.value_or(Interior{}));
        } else if (t.text == "translate" || t.text == "rotate" || t.text == "scale" || t.text == "matrix" ||
                   t.text == "transform") {
            pushBack(t);
            const Transform tr = *transformItem();
            if (m.texture) transformTextureSpaces(*m.texture, tr);
            if (m.interior) transformInteriorSpaces(*m.interior, tr);
        } else {
            failExpected(t, "'texture', 'interior', a transform or '}' in material");
        }
    }
}

// normal { [pattern [amount]] { modifier | transform } }: the bump pattern.
namespace {

// Patterns that perturb a POV-Ray normal by their slope (render/normal_pattern.cpp).
std::optional<PatternKind> normalOnlyPattern(const std::string& word) {
    if (word == "gradient") return PatternKind::Gradient;
    return placePatternNamed(word);
}

} // namespace

// slope_map { [value, <height, slope>] ... }: values from 0 to 1, not decreasing.
std::vector<SlopeMapEntry> Evaluator::slopeMap(SourceLoc keyword) {
    expectSymbol("{", "after 'slope_map'");
    BlockScope scope(*this, "slope_map", keyword);
    std::vector<SlopeMapEntry> map;
    for (;;) {
        const Token t = next();
        if (t.is("}")) break;
        if (!t.is("[")) failInBlock(t, "'[' to start a slope_map entry, or '}'");
        const SourceLoc loc = peek().loc;
        SlopeMapEntry e;
        {
            FlagFor flag(countBeforeVector_); // [0 <1, 0>]: '<' starts the vector, not a comparison
            e.value = floatExpr("the entry's value");
        }
        if (!map.empty() && e.value < map.back().value) refuse(loc, "slope_map values must not decrease" + got(e.value));
        acceptSymbol(",");
        const Vec3 hs = vectorExpr("the entry's <height, slope>");
        e.height = hs.x;
        e.slope = hs.y;
        expectSymbol("]", "to end the slope_map entry");
        map.push_back(e);
    }
    if (map.empty()) fail(keyword, "slope_map has no entries");
    return map;
}

std::optional<Normal> Evaluator::normalBlock(SourceLoc keyword, const std::optional<Normal>& base) {
    DepthGuard guard(*this, keyword);
    expectSymbol("{", "after 'normal'");
    BlockScope scope(*this, "normal", keyword);
    const bool modify = base.has_value() && scene().modifyBlocks;
    Normal n = modify ? *base : Normal{};
    bool known = modify;
    bool first = true;
    // uv_mapping anywhere in the block: the normal's own transforms act in uv space.
    bool uv = n.uvMapping;
    n.uvMapping = false;
    for (;;) {
        const Token t = peek();
        if (t.is("}")) {
            next();
            break;
        }
        if (t.isWord("uv_mapping")) {
            next();
            uv = true;
            continue;
        }
        if (std::optional<Transform> tr = transformItem()) {
            n.toWorld = n.toWorld.then(*tr);
            first = false;
            continue;
        }
        if (t.kind == TokenKind::Word) {
            if (const Cell c = lookup(t.text); c && c->kind == Kind::Normal && first) {
                next();
                use(t.text);
                if (c->normal) n = *c->normal, known = true;
                if (n.uvMapping) uv = true, n.uvMapping = false; // a declared uv-mapped normal
                first = false;
                continue;
            }
            if (double c0, c1; (t.text == "control0" || t.text == "control1") &&
                               n.pattern == PatternKind::Function && n.function &&
                               quiltedControls(*n.function, c0, c1)) { // after quilted
                next();
                (t.text == "control0" ? c0 : c1) = floatExpr();
                n.function = quiltedFunction(c0, c1);
                continue;
            }
            if (t.text == "function" || t.text == "quilted" || t.text == "pigment_pattern") { // normal { function { ... } [amount] }
                next();
                n.pattern = PatternKind::Function;
                n.function = t.text == "quilted"           ? quiltedFunction(1, 1)
                             : t.text == "pigment_pattern" ? pigmentPatternFunction(t)
                                                           : patternFunction(t);
                known = true;
                const Token a = peek();
                if (a.kind == TokenKind::Number || a.is("(") || a.is("-")) n.amount = floatExpr();
                first = false;
                continue;
            }
            // After a pattern with arguments of its own: [,] [amount].
            const auto patternWithAmount = [&](PatternKind kind) {
                n.pattern = kind;
                known = true;
                acceptSymbol(",");
                const Token a = peek();
                if (a.kind == TokenKind::Number || a.is("(") || a.is("-")) n.amount = floatExpr();
                first = false;
            };
            if (t.text == "density_file") { // normal { density_file df3 "file" [interpolate n] [,] [amount] }
                next();
                n.densityFile = densityFile(t);
                patternWithAmount(PatternKind::DensityFile);
                continue;
            }
            if (t.text == "interpolate" && n.pattern == PatternKind::DensityFile && n.densityFile) {
                next();
                n.densityFile = densityInterpolate(n.densityFile);
                continue;
            }
            if (isFractalWord(t.text)) { // normal { mandel ITERATIONS [,] [amount] }
                next();
                n.fractal = fractalPattern(t);
                patternWithAmount(PatternKind::Fractal);
                continue;
            }
            if (n.pattern == PatternKind::Fractal && fractalModifier(t, n.fractal)) continue;
            std::optional<PatternKind> kind = noisePatternNamed(t.text);
            if (kind) noiseNote(t.text, t.loc);
            else if (!isDrt()) kind = normalOnlyPattern(t.text); // POV-Ray's normals by a pattern's slope
            if (kind) { // a pattern, then its own parameters, then the amount
                next();
                n.pattern = *kind;
                known = true;
                if (*kind == PatternKind::Gradient) {
                    n.gradientAxis = vectorExpr("the gradient direction");
                    acceptSymbol(",");
                }
                const Token a = peek();
                if (a.kind == TokenKind::Number || a.is("(") || a.is("-")) n.amount = floatExpr();
                first = false;
                continue;
            }
            if (turbulenceItem(t, n.turbulence) || waveItem(t, n.wave)) {
                first = false;
                continue;
            }
            if (t.text == "slope_map") {
                next();
                n.slopeMap = slopeMap(t.loc);
                first = false;
                continue;
            }
            if (t.text == "accuracy") { // the slope's sample spacing
                next();
                n.accuracy = floatExpr("the normal's accuracy");
                continue;
            }
            if (t.text == "bump_size") {
                next();
                n.amount = floatExpr();
                continue;
            }
        }
        if (syntax().unsupportedIsError) {
            next();
            if (t.kind != TokenKind::Word)
                failInBlock(t, first ? "a bump pattern (such as 'bumps') after 'normal {'"
                                     : "'turbulence', a transform or '}' in normal");
            failUnknown(t, Block::Normal, declaredNames({Kind::Normal}));
        }
        warnOnce("normal", keyword, "'normal' with '" + t.text + "' is not supported and is ignored");
        skipBlock();
        return std::nullopt;
    }
    if (!known) {
        unsupported("normal", keyword, "'normal' without a bump pattern is not supported and is ignored");
        return std::nullopt;
    }
    n.uvMapping = uv;
    return n;
}

} // namespace drt::lang
