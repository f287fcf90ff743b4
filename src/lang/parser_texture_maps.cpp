// Patterned textures and the pigment / texture maps of .drt:
//   texture { gradient x texture_map { [0 pigment {..}] [1 T finish {..}] } scale 2 }
//   texture { checker texture {..} texture {..} }   texture { tiles { texture {..} tile2 texture {..} } }
//   pigment { gradient y pigment_map { [0 P1] [1 checker rgb 1, rgb 0] } }
//   pigment { average pigment_map { [1 P1] [2 P2] } }   (the map values are weights)
// Map entries hold a texture / pigment body, as in POV-Ray.
#include "lang/parser.h"

namespace drt {

std::optional<PatternKind> noisePatternKind(const std::string& w); // parser_textures.cpp
extern const std::vector<std::string> kNoiseWords;

namespace {

const std::vector<std::string>& texturePatternWords() {
    static const std::vector<std::string> words = [] {
        std::vector<std::string> w{"checker", "hexagon", "brick", "tiles", "gradient", "radial", "onion", "average"};
        w.insert(w.end(), kNoiseWords.begin(), kNoiseWords.end());
        return w;
    }();
    return words;
}

} // namespace

// POV-Ray layers only plain textures; so does .drt (the scene model could do more).
void Parser::layerTexture(Texture& below, SourceLoc loc) {
    Texture top = texture();
    if (hasPatternedLayer(below)) fail(loc, "cannot layer over a patterned texture (as POV-Ray)");
    if (hasPatternedLayer(top)) fail(loc, "cannot layer a patterned texture over another texture (as POV-Ray)");
    addLayerOnTop(below, std::move(top));
}

bool Parser::atTexturePattern() const {
    if (!check(TokenKind::Identifier) || lookup(current_.text)) return false;
    for (const std::string& w : texturePatternWords())
        if (current_.text == w) return true;
    return false;
}

// texture-pattern = ( block-pattern { "texture" "{" texture-body "}" [ "," ] }
//                   | "tiles" "{" texture+ "tile2" texture+ "}"
//                   | map-pattern )
//                   { texture-map | "brick_size" vector | "mortar" float | turbulence-item | transform }
// The pattern lives in the texture's pigment (scene.h Texture).
Texture Parser::patternedTexture(TokenKind closer, const char* where) {
    const Token word = current_;
    const std::string w = word.text;
    advance();
    Texture tex;
    Pigment& pattern = tex.pigment;
    auto blockTextures = [&](int count) {
        for (int i = 0; i < count && checkWord("texture"); ++i) {
            tex.map.push_back({double(i), texture()});
            match(TokenKind::Comma);
        }
        if (tex.map.size() != size_t(count))
            error(word.loc, "'" + w + "' needs " + std::to_string(count) + " textures");
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
    } else if (w == "tiles") { // a checker of two (possibly layered) textures
        pattern.pattern = PatternKind::Checker;
        expect(TokenKind::LeftBrace, "'{' after 'tiles'");
        for (int tile = 0; tile < 2; ++tile) {
            if (!checkWord("texture")) failExpected(tile == 0 ? "'texture' in tiles" : "'texture' after 'tile2'");
            Texture stack = texture();
            while (checkWord("texture")) layerTexture(stack, current_.loc);
            tex.map.push_back({double(tile), std::move(stack)});
            if (tile == 0) {
                if (!checkWord("tile2")) failExpected("'tile2' or another 'texture' in tiles");
                advance();
            }
        }
        expect(TokenKind::RightBrace, "'}' to end tiles");
        // As POV-Ray 3.7 (measured): tile2 lies where `checker` puts its first texture.
        std::swap(tex.map[0].texture, tex.map[1].texture);
    } else if (w == "gradient") {
        pattern.pattern = PatternKind::Gradient;
        const SourceLoc vloc = current_.loc;
        pattern.gradientAxis = vectorExpr("the gradient axis");
        requireNonZero(pattern.gradientAxis, vloc, "gradient axis");
    } else if (w == "radial") {
        pattern.pattern = PatternKind::Radial;
    } else if (w == "onion") {
        pattern.pattern = PatternKind::Onion;
    } else if (w == "average") {
        pattern.pattern = PatternKind::Average;
    } else {
        pattern.pattern = *noisePatternKind(w);
    }
    const bool block = w == "checker" || w == "hexagon" || w == "brick" || w == "tiles";
    while (!match(closer)) {
        if (std::optional<Transform> tr = transformItem()) {
            transformTextureSpaces(tex, *tr);
        } else if (turbulenceItem(pattern.turbulence)) {
        } else if (!block && waveItem(pattern.wave)) {
        } else if (checkWord("texture_map")) {
            if (block) fail(current_.loc, "'" + w + "' takes its textures directly, not a texture_map");
            tex.map = textureMap(pattern.pattern == PatternKind::Average);
        } else if (checkWord("brick_size")) {
            advance();
            const SourceLoc vloc = current_.loc;
            pattern.brickSize = vectorExpr();
            if (pattern.brickSize.x <= 0 || pattern.brickSize.y <= 0 || pattern.brickSize.z <= 0)
                error(vloc, "'brick_size' components must be positive");
        } else if (checkWord("mortar")) {
            advance();
            const SourceLoc vloc = current_.loc;
            pattern.mortar = floatExpr();
            if (pattern.mortar < 0) error(vloc, "'mortar' must not be negative");
        } else if (check(TokenKind::Identifier)) {
            std::vector<std::string> known{"texture_map", "brick_size", "mortar", "turbulence", "octaves", "omega",
                                           "lambda", "translate", "rotate", "scale", "matrix"};
            if (!block) known.insert(known.end(), waveWords().begin(), waveWords().end());
            failUnknown(current_, known);
        } else {
            failExpected((std::string("'texture_map', a pattern modifier, a transform or ") + where).c_str());
        }
    }
    if (!block && tex.map.empty()) error(word.loc, "a '" + w + "' texture needs a texture_map");
    return tex;
}

namespace {

// Map values: not decreasing (any finite value, as POV-Ray: the pattern's
// values lie in [0, 1], below the first entry its colour holds, above the
// last the last one's), except for `average`, whose values are non-negative weights.
template <class Report>
void checkMapValue(bool average, double value, const double* previous, const SourceLoc& loc, const char* map,
                   const Report& error) {
    if (average) {
        if (value < 0) error(loc, std::string(map) + " weights (with 'average') must not be negative");
        return;
    }
    if (previous && value < *previous) error(loc, std::string(map) + " values must not decrease");
}

} // namespace

// texture-map = "texture_map" "{" { "[" float [ "," ] ( texture-body | texture { texture } ) "]" } "}"
std::vector<Texture::MapEntry> Parser::textureMap(bool average) {
    const Token keyword = current_;
    advance();
    DepthGuard guard(*this, keyword.loc);
    expect(TokenKind::LeftBrace, "'{' after 'texture_map'");
    std::vector<Texture::MapEntry> entries;
    auto report = [&](const SourceLoc& loc, const std::string& message) { error(loc, message); };
    while (!match(TokenKind::RightBrace)) {
        expect(TokenKind::LeftBracket, "'[' to start a texture_map entry, or '}'");
        Texture::MapEntry e;
        const SourceLoc loc = current_.loc;
        e.value = floatExpr("the entry's value");
        checkMapValue(average, e.value, entries.empty() ? nullptr : &entries.back().value, loc, "texture_map",
                      report);
        match(TokenKind::Comma);
        if (checkWord("texture")) { // whole textures: a layered entry, `[v texture {A} texture {B}]`
            e.texture = texture();
            while (checkWord("texture")) layerTexture(e.texture, current_.loc);
            expect(TokenKind::RightBracket, "']' to end the texture_map entry");
        } else {
            e.texture = textureBody(TokenKind::RightBracket, "']' to end the texture_map entry");
        }
        entries.push_back(std::move(e));
    }
    if (entries.empty()) error(keyword.loc, "texture_map has no entries");
    return entries;
}

// pigment-map = "pigment_map" "{" { "[" float [ "," ] pigment-body "]" } "}"
void Parser::pigmentMap(Pigment& p) {
    const Token keyword = current_;
    advance();
    DepthGuard guard(*this, keyword.loc);
    expect(TokenKind::LeftBrace, "'{' after 'pigment_map'");
    const bool average = p.pattern == PatternKind::Average;
    std::vector<Pigment::MapEntry> entries;
    auto report = [&](const SourceLoc& loc, const std::string& message) { error(loc, message); };
    while (!match(TokenKind::RightBrace)) {
        expect(TokenKind::LeftBracket, "'[' to start a pigment_map entry, or '}'");
        Pigment::MapEntry e;
        const SourceLoc loc = current_.loc;
        e.value = floatExpr("the entry's value");
        checkMapValue(average, e.value, entries.empty() ? nullptr : &entries.back().value, loc, "pigment_map",
                      report);
        match(TokenKind::Comma);
        e.pigment = pigmentBody(TokenKind::RightBracket, "']' to end the pigment_map entry");
        entries.push_back(std::move(e));
    }
    if (entries.empty()) error(keyword.loc, "pigment_map has no entries");
    else p.pigmentMap = std::move(entries);
}

} // namespace drt
