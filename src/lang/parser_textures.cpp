// texture, pigment, finish and interior blocks. Defaults are POV-Ray 3.7's
// (scene.h); pattern defaults follow POV-Ray's built-in colour lists.
#include "lang/parser.h"

#include <utility>

#include <algorithm>
#include <map>

namespace drt {

static Pigment solid(const ColorFT& c) {
    Pigment p;
    p.color = c;
    return p;
}

static Pigment solidRgb(double r, double g, double b) { return solid(ColorFT{Color(r, g, b), 0, 0}); }

// The noise patterns (render/noise.h), usable both as pigments and as normals.
std::optional<PatternKind> noisePatternKind(const std::string& w) {
    static const std::map<std::string, PatternKind> kinds = {
        {"bozo", PatternKind::Bozo},         {"granite", PatternKind::Granite},   {"marble", PatternKind::Marble},
        {"wood", PatternKind::Wood},         {"agate", PatternKind::Agate},       {"leopard", PatternKind::Leopard},
        {"crackle", PatternKind::Crackle},   {"wrinkles", PatternKind::Wrinkles}, {"dents", PatternKind::Dents},
        {"bumps", PatternKind::Bumps},       {"ripples", PatternKind::Ripples},   {"waves", PatternKind::Waves}};
    const auto it = kinds.find(w);
    if (it == kinds.end()) return std::nullopt;
    return it->second;
}

extern const std::vector<std::string> kNoiseWords;
const std::vector<std::string> kNoiseWords{"bozo",    "granite",  "marble", "wood",  "agate",   "leopard",
                                                  "crackle", "wrinkles", "dents",  "bumps", "ripples", "waves"};

// texture = "texture" "{" texture-body "}"
// texture-body = [ texture-name ] { pigment | finish | normal | transform } | texture-pattern
Texture Parser::texture() {
    const Token keyword = current_;
    advance();
    DepthGuard guard(*this, keyword.loc);
    expect(TokenKind::LeftBrace, "'{' after 'texture'");
    return textureBody(TokenKind::RightBrace, "'}' in texture");
}

Texture Parser::textureBody(TokenKind closer, const char* where) {
    if (atTexturePattern()) return patternedTexture(closer, where);
    Texture t;
    if (check(TokenKind::Identifier)) {
        if (const Value* v = lookup(current_.text)) {
            if (!std::holds_alternative<Texture>(*v))
                fail(current_.loc, "'" + current_.text + "' is " + kindName(*v) + ", not a texture");
            t = std::get<Texture>(*v);
            advance();
        }
    }
    while (!match(closer)) {
        if (std::optional<Transform> tr = transformItem()) {
            transformTextureSpaces(t, *tr);
        } else if (checkWord("pigment")) {
            t.pigment = pigment();
        } else if (checkWord("finish")) {
            t.finish = finish();
        } else if (checkWord("normal")) {
            t.normal = normal();
        } else if (check(TokenKind::Identifier)) {
            failUnknown(current_, {"pigment", "finish", "normal", "translate", "rotate", "scale", "matrix",
                                   "texture_map", "tiles", "checker", "gradient", "average"});
        } else {
            failExpected((std::string("'pigment', 'finish', 'normal', a transform or ") + where).c_str());
        }
    }
    return t;
}

// pigment = "pigment" "{" pigment-body "}"
// pigment-body = [ pigment-name ] { pigment-item }
Pigment Parser::pigment() {
    const Token keyword = current_;
    advance();
    DepthGuard guard(*this, keyword.loc);
    expect(TokenKind::LeftBrace, "'{' after 'pigment'");
    return pigmentBody(TokenKind::RightBrace, "'}' in pigment");
}

Pigment Parser::pigmentBody(TokenKind closer, const char* where) {
    Pigment p;
    if (check(TokenKind::Identifier)) {
        if (const Value* v = lookup(current_.text); v && std::holds_alternative<Pigment>(*v)) {
            p = std::get<Pigment>(*v);
            advance();
        }
    }
    while (!match(closer)) {
        if (pigmentItem(p)) continue;
        if (check(TokenKind::Identifier)) {
            if (const Value* v = lookup(current_.text))
                fail(current_.loc, "'" + current_.text + "' is " + kindName(*v) + ", not a pigment or colour");
            std::vector<std::string> known{"color",    "rgb",       "checker", "hexagon",   "brick",
                                           "brick_size", "mortar", "gradient", "radial",  "onion", "spherical",
                                           "color_map", "pigment_map", "average", "image_map", "turbulence", "octaves", "omega", "lambda",
                                           "uv_mapping", "translate", "rotate",   "scale",   "matrix"};
            known.insert(known.end(), kNoiseWords.begin(), kNoiseWords.end());
            known.insert(known.end(), waveWords().begin(), waveWords().end());
            failUnknown(current_, known);
        }
        failExpected((std::string("a colour, a pattern or ") + where).c_str());
    }
    return p;
}

// pigment-item = colour | "checker" [ list ] | "hexagon" [ list ] | "brick" [ list ]
//              | "brick_size" vector | "mortar" float | "gradient" vector | "radial" | "onion"
//              | noise-pattern | turbulence-item | wave-item | colour-map | transform
bool Parser::pigmentItem(Pigment& p) {
    const SourceLoc loc = current_.loc;
    if (std::optional<Transform> t = transformItem()) {
        // In a uv-mapped pigment its own transforms move the pattern in uv
        // space (transformPigmentSpaces leaves uv-mapped pigments alone).
        const bool uv = std::exchange(p.uvMapping, false);
        transformPigmentSpaces(p, *t);
        p.uvMapping = uv;
        return true;
    }
    const bool declaredColor = check(TokenKind::Identifier) && lookup(current_.text) &&
                               std::holds_alternative<VectorValue>(*lookup(current_.text));
    if (checkWord("color") || checkWord("colour") || atColorWord() || declaredColor || check(TokenKind::LeftAngle)) {
        const Transform keep = p.toWorld;
        p = solid(colorExpr());
        p.toWorld = keep;
        return true;
    }
    if (!check(TokenKind::Identifier)) return false;
    const std::string w = current_.text;
    if (w == "uv_mapping") {
        advance();
        p.uvMapping = true;
        return true;
    }
    // A list pattern takes its sub-pigments (or colours), else POV-Ray's defaults.
    auto list = [&](PatternKind kind, std::vector<Pigment> defaults) {
        advance();
        p.pattern = kind;
        const bool given = checkWord("pigment") || checkWord("color") || checkWord("colour") || atColorWord() ||
                           check(TokenKind::LeftAngle) ||
                           (check(TokenKind::Identifier) && lookup(current_.text) &&
                            (std::holds_alternative<VectorValue>(*lookup(current_.text)) ||
                             std::holds_alternative<Pigment>(*lookup(current_.text))));
        if (given) {
            std::vector<Pigment> children;
            children.push_back(pigmentOrColor());
            while (children.size() < defaults.size() && match(TokenKind::Comma)) children.push_back(pigmentOrColor());
            for (size_t i = children.size(); i < defaults.size(); ++i) children.push_back(defaults[i]);
            defaults = std::move(children);
        }
        // Children live in the parent's pattern space: give them its transform so far.
        for (Pigment& child : defaults) transformPigmentSpaces(child, p.toWorld);
        p.children = std::move(defaults);
    };
    if (w == "checker") list(PatternKind::Checker, {solidRgb(0, 0, 1), solidRgb(0, 1, 0)});
    else if (w == "hexagon") list(PatternKind::Hexagon, {solidRgb(0, 0, 1), solidRgb(0, 1, 0), solidRgb(1, 0, 0)});
    else if (w == "brick") list(PatternKind::Brick, {solidRgb(0.5, 0.5, 0.5), solidRgb(0.6, 0.15, 0.15)});
    else if (w == "brick_size") {
        advance();
        const SourceLoc vloc = current_.loc;
        p.brickSize = vectorExpr();
        if (p.brickSize.x <= 0 || p.brickSize.y <= 0 || p.brickSize.z <= 0)
            error(vloc, "'brick_size' components must be positive");
    } else if (w == "mortar") {
        advance();
        const SourceLoc vloc = current_.loc;
        p.mortar = floatExpr();
        if (p.mortar < 0) error(vloc, "'mortar' must not be negative");
    } else if (w == "gradient" || w == "radial" || w == "onion" || w == "spherical") {
        advance();
        if (w == "gradient") {
            const SourceLoc vloc = current_.loc;
            p.gradientAxis = vectorExpr("the gradient axis");
            requireNonZero(p.gradientAxis, vloc, "gradient axis");
        }
        p.pattern = w == "gradient"   ? PatternKind::Gradient
                    : w == "radial"   ? PatternKind::Radial
                    : w == "onion"    ? PatternKind::Onion
                                      : PatternKind::Spherical;
        p.children.clear();
        if (p.colorMap.empty()) {
            if (w == "radial") {
                // POV-Ray's default radial map.
                p.colorMap = {{0.0, {Color(0, 1, 1), 0, 0}},
                              {0.333, {Color(1, 1, 0), 0, 0}},
                              {0.666, {Color(1, 0, 1), 0, 0}},
                              {1.0, {Color(0, 1, 1), 0, 0}}};
            } else {
                p.colorMap = {{0.0, {Color(0), 0, 0}}, {1.0, {Color(1), 0, 0}}}; // POV-Ray's grey ramp
            }
        }
    } else if (const std::optional<PatternKind> kind = noisePatternKind(w)) {
        advance();
        p.pattern = *kind;
        p.children.clear();
        if (p.colorMap.empty()) p.colorMap = {{0.0, {Color(0), 0, 0}}, {1.0, {Color(1), 0, 0}}}; // grey ramp
    } else if (turbulenceItem(p.turbulence)) {
    } else if (waveItem(p.wave)) {
    } else if (w == "color_map" || w == "colour_map") {
        colorMap(p);
    } else if (w == "pigment_map") {
        pigmentMap(p);
    } else if (w == "average") {
        advance();
        p.pattern = PatternKind::Average;
        p.children.clear();
    } else if (w == "image_map") {
        imageMap(p);
    } else {
        return false;
    }
    (void)loc;
    return true;
}

Pigment Parser::pigmentOrColor() {
    if (checkWord("pigment")) return pigment();
    if (check(TokenKind::Identifier)) {
        if (const Value* v = lookup(current_.text); v && std::holds_alternative<Pigment>(*v)) {
            advance();
            return std::get<Pigment>(*v);
        }
    }
    return solid(colorExpr());
}

// colour-map = ("color_map" | "colour_map") "{" { "[" float colour "]" } "}"
void Parser::colorMap(Pigment& p) {
    const Token keyword = current_;
    advance();
    expect(TokenKind::LeftBrace, "'{' after 'color_map'");
    std::vector<ColorMapEntry> entries;
    while (!match(TokenKind::RightBrace)) {
        expect(TokenKind::LeftBracket, "'[' to start a color_map entry, or '}'");
        ColorMapEntry e;
        const SourceLoc loc = current_.loc;
        e.value = floatExpr("the entry's value");
        if (!entries.empty() && e.value < entries.back().value)
            error(loc, "color_map values must not decrease");
        match(TokenKind::Comma);
        e.color = colorExpr();
        expect(TokenKind::RightBracket, "']' to end the color_map entry");
        entries.push_back(e);
    }
    if (entries.empty()) error(keyword.loc, "color_map has no entries");
    else p.colorMap = std::move(entries);
}

// turbulence-item = "turbulence" (vector | float) | "octaves" int | "omega" float | "lambda" float
// Returns false, consuming nothing, at any other token.
bool Parser::turbulenceItem(Turbulence& t) {
    if (!check(TokenKind::Identifier)) return false;
    const std::string w = current_.text;
    if (w != "turbulence" && w != "octaves" && w != "omega" && w != "lambda") return false;
    advance();
    const SourceLoc loc = current_.loc;
    if (w == "turbulence") {
        t.amount = vectorExpr("the turbulence amount");
        if (t.amount.x < 0 || t.amount.y < 0 || t.amount.z < 0) error(loc, "'turbulence' must not be negative");
    } else if (w == "octaves") {
        t.octaves = intExpr("the number of octaves");
        if (t.octaves < 1 || t.octaves > 10) error(loc, "'octaves' must be between 1 and 10");
    } else if (w == "omega") {
        t.omega = floatExpr();
    } else {
        t.lambda = floatExpr();
    }
    return true;
}

// normal = "normal" "{" noise-pattern [ float ] { turbulence-item | wave-item | transform } "}"
// The float is the bump amount (default 0.5).
Normal Parser::normal() {
    const Token keyword = current_;
    advance();
    expect(TokenKind::LeftBrace, "'{' after 'normal'");
    Normal n;
    if (!check(TokenKind::Identifier)) failExpected("a bump pattern (such as 'bumps') after 'normal {'");
    const std::optional<PatternKind> kind = noisePatternKind(current_.text);
    if (!kind) failUnknown(current_, kNoiseWords);
    n.pattern = *kind;
    advance();
    if (check(TokenKind::Number) || check(TokenKind::LeftParen) || check(TokenKind::Minus)) n.amount = floatExpr();
    while (!match(TokenKind::RightBrace)) {
        if (std::optional<Transform> tr = transformItem()) {
            n.toWorld = n.toWorld.then(*tr);
        } else if (turbulenceItem(n.turbulence)) {
        } else if (waveItem(n.wave)) {
        } else if (check(TokenKind::Identifier)) {
            std::vector<std::string> known{"turbulence", "octaves", "omega", "lambda", "translate", "rotate", "scale", "matrix"};
            known.insert(known.end(), waveWords().begin(), waveWords().end());
            failUnknown(current_, known);
        } else {
            failExpected("'turbulence', a transform or '}' in normal");
        }
    }
    (void)keyword;
    return n;
}

// finish = "finish" "{" [ finish-name ] { finish-item } "}"
Finish Parser::finish() {
    static const std::vector<std::string> known{
        "ambient",  "diffuse",  "brilliance", "phong",    "phong_size", "specular",        "roughness",
        "metallic", "emission", "reflection", "conserve_energy", "reflection_blur", "refraction_blur", "crand"};
    advance();
    expect(TokenKind::LeftBrace, "'{' after 'finish'");
    Finish f;
    if (check(TokenKind::Identifier)) {
        if (const Value* v = lookup(current_.text)) {
            if (!std::holds_alternative<Finish>(*v))
                fail(current_.loc, "'" + current_.text + "' is " + kindName(*v) + ", not a finish");
            f = std::get<Finish>(*v);
            advance();
        }
    }
    while (!match(TokenKind::RightBrace)) {
        if (!check(TokenKind::Identifier)) failExpected("a finish keyword or '}'");
        const Token word = current_;
        const std::string& w = word.text;
        advance();
        const SourceLoc loc = current_.loc;
        auto nonNegative = [&](double& target) {
            target = floatExpr();
            if (target < 0) error(loc, "'" + w + "' must not be negative");
        };
        if (w == "ambient") f.ambient = rgbExpr();
        else if (w == "emission") f.emission = rgbExpr();
        else if (w == "diffuse") nonNegative(f.diffuse);
        else if (w == "brilliance") nonNegative(f.brilliance);
        else if (w == "phong") nonNegative(f.phong);
        else if (w == "phong_size") nonNegative(f.phongSize);
        else if (w == "specular") nonNegative(f.specular);
        else if (w == "crand") nonNegative(f.crand);
        else if (w == "roughness") {
            f.roughness = floatExpr();
            if (f.roughness <= 0) error(loc, "'roughness' must be positive");
        } else if (w == "metallic") {
            f.metallic = (check(TokenKind::Number) || check(TokenKind::LeftParen)) ? floatExpr() : 1.0;
        } else if (w == "reflection") {
            if (check(TokenKind::LeftBrace)) {
                reflectionBlock(f);
            } else {
                f.reflectionMin = f.reflectionMax = rgbExpr();
            }
        } else if (w == "conserve_energy") f.conserveEnergy = booleanOr(true);
        else if (w == "reflection_blur" || w == "refraction_blur") {
            const double b = floatExpr();
            if (b < 0 || b > 1) error(loc, "'" + w + "' must be between 0 and 1");
            (w == "reflection_blur" ? f.reflectionBlur : f.refractionBlur) = b;
        } else failUnknown(word, known);
    }
    return f;
}

// reflection-block = "{" [ colour [ "," colour ] ] { "fresnel" [bool] | "falloff" float | "metallic" [float] } "}"
// One colour sets both min and max; two give min, then max.
void Parser::reflectionBlock(Finish& f) {
    advance(); // {
    auto atItem = [&] { return checkWord("fresnel") || checkWord("falloff") || checkWord("metallic"); };
    if (!check(TokenKind::RightBrace) && !atItem()) {
        const Color first = rgbExpr();
        f.reflectionMin = f.reflectionMax = first;
        if (match(TokenKind::Comma)) f.reflectionMax = rgbExpr();
    }
    while (!match(TokenKind::RightBrace)) {
        if (!check(TokenKind::Identifier)) failExpected("'fresnel', 'falloff', 'metallic' or '}' in reflection");
        const Token word = current_;
        advance();
        const SourceLoc loc = current_.loc;
        if (word.text == "fresnel") f.reflectionFresnel = booleanOr(true);
        else if (word.text == "falloff") {
            f.reflectionFalloff = floatExpr();
            if (f.reflectionFalloff <= 0) error(loc, "'falloff' must be positive");
        } else if (word.text == "metallic") {
            f.reflectionMetallic = (check(TokenKind::Number) || check(TokenKind::LeftParen)) ? floatExpr() : 1.0;
        } else failUnknown(word, {"fresnel", "falloff", "metallic"});
    }
}

// interior = "interior" "{" [ interior-name ] { interior-item } "}"
Interior Parser::interior() {
    advance();
    expect(TokenKind::LeftBrace, "'{' after 'interior'");
    Interior in;
    if (check(TokenKind::Identifier)) {
        if (const Value* v = lookup(current_.text)) {
            if (!std::holds_alternative<Interior>(*v))
                fail(current_.loc, "'" + current_.text + "' is " + kindName(*v) + ", not an interior");
            in = std::get<Interior>(*v);
            advance();
        }
    }
    while (!match(TokenKind::RightBrace)) {
        if (!check(TokenKind::Identifier)) failExpected("an interior keyword or '}'");
        if (checkWord("media")) {
            in.media.push_back(media());
            continue;
        }
        const Token word = current_;
        advance();
        const SourceLoc loc = current_.loc;
        if (word.text == "ior") {
            in.ior = floatExpr();
            if (in.ior <= 0) error(loc, "'ior' must be positive");
        } else if (word.text == "fade_distance") {
            in.fadeDistance = floatExpr();
            if (in.fadeDistance < 0) error(loc, "'fade_distance' must not be negative");
        } else if (word.text == "fade_power") {
            in.fadePower = floatExpr();
            if (in.fadePower < 0) error(loc, "'fade_power' must not be negative");
        } else if (word.text == "fade_color" || word.text == "fade_colour") {
            in.fadeColor = rgbExpr();
        } else {
            failUnknown(word, {"ior", "fade_distance", "fade_power", "fade_color", "media"});
        }
    }
    return in;
}

} // namespace drt
