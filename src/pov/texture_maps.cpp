// Patterned textures (texture_map; checker, hexagon, brick and tiles of
// textures) and pigment_map. Map entries hold a texture / pigment *body*:
// `[0.5 T_Stone scale 2]`, `[0.3 checker Red White]`.
#include "pov/parser.h"
#include "pov/pattern_words.h"

namespace drt::pov {

bool PovParser::isTexturePatternWord(const std::string& w) {
    return w == "texture_map" || w == "material_map" || w == "tiles" || w == "checker" || w == "hexagon" ||
           w == "brick" || w == "gradient" || w == "radial" || w == "onion" || w == "average" ||
           noisePatterns().count(w) > 0 || noiseKind(w).has_value();
}

void PovParser::layerOnTop(Texture& below, Texture top, SourceLoc loc) {
    if (hasPatternedLayer(below)) fail(loc, "cannot layer over a patterned texture (as POV-Ray)");
    if (hasPatternedLayer(top)) fail(loc, "cannot layer a patterned texture over another texture (as POV-Ray)");
    addLayerOnTop(below, std::move(top));
}

// `[value, body]`; in an `average` map the value (the weight) may be left out: 1.
double PovParser::mapEntryValue() {
    const Tok t = peek();
    if (t.isWord("function") || !startsFloat(t)) return 1;
    const double v = floatExpr();
    acceptSymbol(",");
    return v;
}

std::vector<Texture::MapEntry> PovParser::textureMap() {
    expectSymbol("{", "after 'texture_map'");
    std::vector<Texture::MapEntry> map;
    while (!acceptSymbol("}")) {
        expectSymbol("[", "to start a texture_map entry");
        Texture::MapEntry entry;
        entry.value = mapEntryValue();
        entry.texture = textureBody(defaultTexture_, "]");
        map.push_back(std::move(entry));
    }
    return map;
}

std::vector<Pigment::MapEntry> PovParser::pigmentMap() {
    expectSymbol("{", "after 'pigment_map'");
    std::vector<Pigment::MapEntry> map;
    while (!acceptSymbol("}")) {
        expectSymbol("[", "to start a pigment_map entry");
        Pigment::MapEntry entry;
        entry.value = mapEntryValue();
        entry.pigment = pigmentBody(Pigment{}, "]");
        map.push_back(std::move(entry));
    }
    return map;
}

// After the pattern word of `texture { PATTERN ... }`, up to `closer`. The
// texture's pigment carries the pattern; its entries are the map (block
// patterns: their textures in order).
Texture PovParser::patternedTexture(const Tok& word, const char* closer) {
    Texture tex;
    Pigment& pattern = tex.pigment;
    const std::string& w = word.text;
    std::string approximated; // a pattern drt lacks: the entries are averaged
    // checker / hexagon / brick: up to `count` textures, commas optional.
    auto blockTextures = [&](int count) {
        for (int i = 0; i < count && peek().isWord("texture"); ++i) {
            next();
            tex.map.push_back({double(i), texture(defaultTexture_)});
            acceptSymbol(",");
        }
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
            Texture stack;
            bool any = false;
            while (peek().isWord("texture")) {
                const Tok keyword = next();
                Texture layer = texture(defaultTexture_);
                if (any) layerOnTop(stack, std::move(layer), keyword.loc);
                else stack = std::move(layer);
                any = true;
            }
            if (!any) failExpected(peek(), "'texture' in tiles");
            tex.map.push_back({double(tile), std::move(stack)});
            if (tile == 0 && !acceptWord("tile2")) failExpected(peek(), "'tile2' in tiles");
        }
        expectSymbol("}", "to end tiles");
        // Measured against POV-Ray 3.7: tile2 lies where `checker` puts its first texture.
        std::swap(tex.map[0].texture, tex.map[1].texture);
    } else if (w == "gradient") {
        pattern.pattern = PatternKind::Gradient;
        pattern.gradientAxis = vectorExpr();
    } else if (w == "radial") {
        pattern.pattern = PatternKind::Radial;
    } else if (w == "onion") {
        pattern.pattern = PatternKind::Onion;
    } else if (w == "average") {
        pattern.pattern = PatternKind::Average;
    } else if (const std::optional<PatternKind> kind = noiseKind(w)) {
        pattern.pattern = *kind;
        noiseNote(w, word.loc);
    } else if (w == "material_map") {
        // An image-indexed material: drt has no image maps; the first texture inside stands in.
        warnOnce("material_map", word.loc, "'material_map' is not supported; its first texture is used");
        expectSymbol("{", "after 'material_map'");
        Texture first = defaultTexture_;
        bool taken = false;
        for (int depth = 1; depth > 0;) {
            const Tok s = next();
            if (s.kind == TokKind::EndOfFile) fail(word.loc, "unbalanced '{' in material_map");
            if (!taken && s.isWord("texture")) {
                first = texture(defaultTexture_);
                taken = true;
                continue;
            }
            depth += s.is("{") ? 1 : s.is("}") ? -1 : 0;
        }
        tex = first;
        // transforms after the map still apply; no entries to average
        for (;;) {
            const Tok t = next();
            if (t.is(closer)) return tex;
            pushBack(t);
            if (std::optional<Transform> tr = transformItem()) transformTextureSpaces(tex, *tr);
            else failExpected(t, "a transform or '" + std::string(closer) + "'");
        }
    } else if (w == "texture_map") {
        pushBack(word); // a map without a pattern: POV-Ray's default pattern is none; averaged below
        approximated = "(none)";
    } else {
        approximated = w;
        if (w == "function" || w == "pigment_pattern" || w == "object") {
            if (peek().is("{")) next(), skipBlock();
        } else if (w == "mandel" || w == "magnet" || w == "spiral1" || w == "spiral2") {
            floatExpr();
        } else if (w == "julia") {
            vectorExpr(), acceptSymbol(","), floatExpr();
        } else if (w == "slope" || w == "aoi") { // slope <v> or slope { <v> [, lo, hi] [altitude ..] }
            if (peek().is("{")) next(), skipBlock();
            else if (w == "slope") vectorExpr();
        }
    }
    for (;;) {
        const Tok t = peek();
        if (t.is(closer)) {
            next();
            break;
        }
        if (std::optional<Transform> tr = transformItem()) {
            transformTextureSpaces(tex, *tr);
            continue;
        }
        if (t.kind != TokKind::Word) failExpected(t, "'texture_map', a pattern modifier or '" + std::string(closer) + "'");
        if (patternModifier(t, pattern.turbulence) || waveModifier(t, pattern.wave)) continue;
        next();
        if (t.text == "texture_map") {
            tex.map = textureMap();
        } else if (t.text == "brick_size") {
            pattern.brickSize = vectorExpr();
        } else if (t.text == "mortar") {
            pattern.mortar = floatExpr();
        } else if (ignoredPatternModifiers().count(t.text)) {
            warnOnce(t.text, t.loc, "'" + t.text + "' is not supported and is ignored");
            if (t.text == "warp") expectSymbol("{", "after 'warp'"), skipBlock();
            else expression();
        } else if (pattern.pattern == PatternKind::Crackle &&
                   (t.text == "metric" || t.text == "form" || t.text == "offset" || t.text == "solid")) {
            warnOnce("crackle-" + t.text, t.loc, "crackle '" + t.text + "' is not supported and is ignored");
            if (t.text == "form") vectorExpr();
            else if (t.text != "solid") floatExpr();
        } else if (t.text == "uv_mapping") {
            warnOnce(t.text, t.loc, "'uv_mapping' is not supported; the pattern uses object coordinates");
        } else {
            failExpected(t, "'texture_map', a pattern modifier or '" + std::string(closer) + "'");
        }
    }
    if (!approximated.empty()) {
        warnOnce("texture-pattern-" + approximated, word.loc,
                 "texture pattern '" + approximated + "' is approximated by the equally weighted average of its texture_map");
        pattern.pattern = PatternKind::Average;
        for (Texture::MapEntry& entry : tex.map) entry.value = 1;
    }
    return tex;
}

} // namespace drt::pov
