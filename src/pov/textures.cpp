// Textures: pigment (solid colours and the block and colour-map patterns the
// scene model has; noise patterns approximated), finish (the classic model),
// interior, material, normal (bump patterns), colour maps and transforms.
#include "pov/parser.h"
#include "pov/pattern_words.h"

#include <fmt/format.h>

#include <map>

namespace drt::pov {

using Kind = PovValue::Kind;

ColorFT toColorFT(const std::array<double, 5>& c) { return ColorFT{Color(c[0], c[1], c[2]), c[3], c[4]}; }

namespace {

Pigment solid(const ColorFT& c) {
    Pigment p;
    p.color = c;
    return p;
}

ColorFT rgb(double r, double g, double b) { return ColorFT{Color(r, g, b), 0, 0}; }

// The mean colour of a colour map over [0, 1] (piecewise linear, constant
// beyond its ends): the stand-in for patterns drt does not have.
ColorFT mapAverage(const std::vector<ColorMapEntry>& map) {
    if (map.empty()) return rgb(0.5, 0.5, 0.5);
    ColorFT sum{Color(0), 0, 0};
    auto add = [&](const ColorFT& c, double w) {
        sum.rgb += c.rgb * w;
        sum.filter += c.filter * w;
        sum.transmit += c.transmit * w;
    };
    const double first = std::clamp(map.front().value, 0.0, 1.0);
    add(map.front().color, first);
    for (size_t i = 1; i < map.size(); ++i) {
        const double a = std::clamp(map[i - 1].value, 0.0, 1.0), b = std::clamp(map[i].value, 0.0, 1.0);
        ColorFT mid{(map[i - 1].color.rgb + map[i].color.rgb) * 0.5, (map[i - 1].color.filter + map[i].color.filter) * 0.5,
                    (map[i - 1].color.transmit + map[i].color.transmit) * 0.5};
        add(mid, b - a);
    }
    add(map.back().color, 1 - std::clamp(map.back().value, 0.0, 1.0));
    return sum;
}

} // namespace

ColorFT pigmentAverage(const Pigment& p) {
    if (p.pattern == PatternKind::Solid) return p.color;
    if (!p.children.empty()) {
        ColorFT sum{Color(0), 0, 0};
        for (const Pigment& c : p.children) {
            const ColorFT a = pigmentAverage(c);
            sum.rgb += a.rgb;
            sum.filter += a.filter;
            sum.transmit += a.transmit;
        }
        const double n = double(p.children.size());
        return ColorFT{sum.rgb / n, sum.filter / n, sum.transmit / n};
    }
    return mapAverage(p.colorMap);
}

// Pattern words shared with texture_maps.cpp (pattern_words.h).

const std::set<std::string>& noisePatterns() {
    static const std::set<std::string> words = {
        "agate", "bozo", "granite", "marble", "wood", "spotted", "leopard", "crackle", "ripples", "waves",
        "wrinkles", "bumps", "dents", "spiral1", "spiral2", "mandel", "julia", "cells", "planar",
        "cylindrical", "boxed", "quilted", "average", "cubic", "tiling", "pavement", "facets", "function",
        "density_file", "object", "aoi", "slope", "pigment_pattern", "magnet", "fractal", "wave", "noise"};
    return words;
}

// POV-Ray's noise patterns that the scene model approximates (render/noise.h).
std::optional<PatternKind> noiseKind(const std::string& w) {
    static const std::map<std::string, PatternKind> kinds = {
        {"bozo", PatternKind::Bozo},         {"spotted", PatternKind::Bozo},     {"granite", PatternKind::Granite},
        {"marble", PatternKind::Marble},     {"wood", PatternKind::Wood},        {"agate", PatternKind::Agate},
        {"leopard", PatternKind::Leopard},   {"crackle", PatternKind::Crackle},  {"wrinkles", PatternKind::Wrinkles},
        {"dents", PatternKind::Dents},       {"bumps", PatternKind::Bumps},      {"ripples", PatternKind::Ripples},
        {"waves", PatternKind::Waves}};
    const auto it = kinds.find(w);
    if (it == kinds.end()) return std::nullopt;
    return it->second;
}

const std::set<std::string>& ignoredPatternModifiers() {
    static const std::set<std::string> words = {"turbulence", "octaves", "omega", "lambda", "noise_generator",
                                                "warp", "agate_turb"};
    return words;
}

std::optional<Transform> PovParser::transformItem() {
    const Tok t = peek();
    if (t.kind != TokKind::Word) return std::nullopt;
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
        for (int i = 0; i < 3; ++i)
            if (s[i] == 0) {
                // POV-Ray warns and uses 1 for a zero scale component.
                warnOnce("scale0", loc, "scale with a zero component; that component is left at 1 (as POV-Ray)");
                s[i] = 1;
            }
        return Transform::scale(s);
    }
    if (w == "matrix") {
        next();
        expectSymbol("<", "after 'matrix'");
        const bool saved = inVector_;
        inVector_ = true;
        std::array<double, 12> m{};
        for (int i = 0; i < 12; ++i) {
            if (i) expectSymbol(",", "between the 12 matrix numbers");
            m[size_t(i)] = floatExpr();
        }
        inVector_ = saved;
        expectSymbol(">", "after the 12 matrix numbers");
        const std::optional<Transform> tr = Transform::fromPovMatrix(m);
        if (!tr) fail(t.loc, "singular matrix");
        return tr;
    }
    if (w == "transform") {
        next();
        return transformBlock();
    }
    return std::nullopt;
}

Transform PovParser::transformBlock() {
    const Tok t = next();
    if (t.kind == TokKind::Word) {
        const Cell c = useIndexed(t);
        if (c && c->kind == Kind::Transform) return *c->transform;
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
        const Tok id = next();
        const Cell c = id.kind == TokKind::Word ? useIndexed(id) : nullptr;
        if (c && c->kind == Kind::Transform) {
            result = result.then(*c->transform);
            continue;
        }
        failExpected(id, "a transform or '}'");
    }
}

// color_map { [value colour] ... } or the old form [v1, v2 colour1 colour2].
std::vector<ColorMapEntry> PovParser::colorMap() {
    const Tok open = next();
    if (open.kind == TokKind::Word) {
        const Cell c = useIndexed(open);
        if (c && c->kind == Kind::ColorMap) return *c->colorMap;
        failExpected(open, "'{' or a color_map identifier");
    }
    if (!open.is("{")) failExpected(open, "'{' after 'color_map'");
    std::vector<ColorMapEntry> map;
    if (peek().kind == TokKind::Word) {
        const Tok id = next();
        const Cell c = useIndexed(id);
        if (!c || c->kind != Kind::ColorMap) failExpected(id, "'[' or a color_map identifier");
        map = *c->colorMap;
    }
    while (!acceptSymbol("}")) {
        expectSymbol("[", "to start a color_map entry");
        const double v1 = floatExpr();
        acceptSymbol(",");
        if (startsFloat(peek())) {
            // The old range form: [v1, v2 colour1 colour2].
            const double v2 = floatExpr();
            acceptSymbol(",");
            const auto c1 = colorExpr();
            const auto c2 = colorExpr();
            map.push_back({v1, toColorFT(c1)});
            map.push_back({v2, toColorFT(c2)});
        } else {
            map.push_back({v1, toColorFT(colorExpr())});
        }
        expectSymbol("]", "to end a color_map entry");
    }
    if (map.size() > 256) warnOnce("colormap256", open.loc, "color_map has more than 256 entries (POV-Ray's limit)");
    return map;
}

Pigment PovParser::pigment(const Pigment& base) {
    expectSymbol("{", "after 'pigment'");
    return pigmentBody(base, "}");
}

Pigment PovParser::pigmentBody(const Pigment& base, const char* closer) {
    Pigment p = base;
    std::string pattern; // the approximated noise pattern, if any
    SourceLoc patternLoc;
    bool first = true;
    auto patternColors = [&](int count, std::vector<ColorFT> defaults) {
        // checker/hexagon/brick: up to `count` colours or pigments, commas optional.
        p.children.clear();
        for (int i = 0; i < count; ++i) {
            const Tok t = peek();
            if (t.isWord("pigment")) {
                next();
                p.children.push_back(pigment(Pigment{}));
            } else if (t.kind == TokKind::Word &&
                       (t.text == "color" || t.text == "colour" || t.text.rfind("rgb", 0) == 0 ||
                        t.text.rfind("srgb", 0) == 0 ||
                        (lookup(t.text) && lookup(t.text)->isNumeric()))) {
                p.children.push_back(solid(toColorFT(colorExpr())));
            } else if (t.is("<") || t.kind == TokKind::Number) {
                p.children.push_back(solid(toColorFT(colorExpr())));
            } else {
                break;
            }
            if (i + 1 < count) acceptSymbol(",");
        }
        for (size_t i = p.children.size(); i < defaults.size(); ++i) p.children.push_back(solid(defaults[i]));
    };
    for (;;) {
        const Tok t = peek();
        if (t.is(closer)) {
            next();
            break;
        }
        if (std::optional<Transform> tr = transformItem()) {
            transformPigmentSpaces(p, *tr);
            first = false;
            continue;
        }
        if (t.kind != TokKind::Word && !t.is("<") && t.kind != TokKind::Number) failExpected(t, "a pigment item or '}'");
        const std::string w = t.text;
        Cell c = t.kind == TokKind::Word ? use(w) : nullptr;
        if (c && c->kind == Kind::Array) {
            // An array element: a pigment, a colour map or a colour.
            next();
            c = indexArray(c, t);
            const Transform keep = p.toWorld;
            if (c->kind == Kind::Pigment) p = *c->pigment;
            else if (c->kind == Kind::ColorMap) p.colorMap = *c->colorMap;
            else if (c->isNumeric()) p = solid(toColorFT(toColor(*c, t.loc))), p.toWorld = keep;
            else fail(t.loc, std::string("a ") + kindName(c->kind) + " cannot be used in a pigment");
            continue;
        }
        if (c && c->kind == Kind::Pigment) {
            next();
            p = *c->pigment;
        } else if (c && c->kind == Kind::ColorMap) {
            next();
            p.colorMap = *c->colorMap;
        } else if ((c && c->isNumeric()) || w == "color" || w == "colour" || w.rfind("rgb", 0) == 0 || w == "red" ||
                   w == "green" || w == "blue" || w == "filter" || w == "transmit" ||
                   w.rfind("srgb", 0) == 0 || t.is("<") || t.kind == TokKind::Number) {
            const Transform keep = p.toWorld;
            p = solid(toColorFT(colorExpr()));
            p.toWorld = keep;
        } else if (w == "checker") {
            next();
            p.pattern = PatternKind::Checker;
            patternColors(2, {rgb(0, 0, 1), rgb(0, 1, 0)});
        } else if (w == "hexagon") {
            next();
            p.pattern = PatternKind::Hexagon;
            patternColors(3, {rgb(0, 0, 1), rgb(0, 1, 0), rgb(1, 0, 0)});
        } else if (w == "brick") {
            next();
            p.pattern = PatternKind::Brick;
            patternColors(2, {rgb(1, 1, 1), rgb(1, 0, 0)});
        } else if (w == "brick_size") {
            next();
            p.brickSize = vectorExpr();
        } else if (w == "mortar") {
            next();
            p.mortar = floatExpr();
        } else if (w == "gradient") {
            next();
            p.pattern = PatternKind::Gradient;
            p.gradientAxis = vectorExpr();
        } else if (w == "radial") {
            next();
            p.pattern = PatternKind::Radial;
        } else if (w == "onion") {
            next();
            p.pattern = PatternKind::Onion;
        } else if (w == "spherical") {
            next();
            p.pattern = PatternKind::Spherical;
        } else if (w == "color_map" || w == "colour_map") {
            next();
            p.colorMap = colorMap();
        } else if (const std::optional<PatternKind> kind = noiseKind(w)) {
            next();
            p.pattern = *kind;
            p.children.clear();
            noiseNote(w, t.loc);
        } else if (w == "average") {
            next();
            p.pattern = PatternKind::Average;
            p.children.clear();
        } else if (w == "pigment_map") {
            next();
            p.pigmentMap = pigmentMap();
        } else if (patternModifier(t, p.turbulence) || waveModifier(t, p.wave)) {
        } else if (p.pattern == PatternKind::Crackle && (w == "metric" || w == "form" || w == "offset" || w == "solid")) {
            // crackle's variants: drt has one cellular form (F2 - F1, Euclidean).
            next();
            warnOnce("crackle-" + w, t.loc, "crackle '" + w + "' is not supported and is ignored");
            if (w != "solid") w == "form" ? (void)vectorExpr() : (void)floatExpr();
        } else if (noisePatterns().count(w)) {
            next();
            pattern = w;
            patternLoc = t.loc;
            if (w == "function" || w == "pigment_pattern" || w == "object") {
                if (peek().is("{")) next(), skipBlock();
            } else if (w == "density_file") { // density_file df3 "file" [interpolate n]
                if (peek().isWord("df3")) next();
                stringExpr();
                if (peek().isWord("interpolate")) next(), floatExpr();
            } else if (w == "wave") {
                // followed by a type word: skipped with the rest
            }
            if (w == "mandel" || w == "julia" || w == "magnet") {
                // julia <c>, n; mandel n
                if (w == "julia") vectorExpr(), acceptSymbol(",");
                floatExpr();
            }
        } else if (w == "image_map") {
            next();
            const Transform keep = p.toWorld;
            std::optional<Pigment> image = imageMapPigment(t.loc);
            p = image ? *image : solid(rgb(0.5, 0.5, 0.5));
            p.toWorld = keep;
        } else if (w == "bump_map" || w == "material_map") {
            next();
            warnOnce(w, t.loc, "'" + w + "' is not supported; the pigment becomes mid grey");
            expectSymbol("{", ("after '" + w + "'").c_str());
            skipBlock();
            const Transform keep = p.toWorld;
            p = solid(rgb(0.5, 0.5, 0.5));
            p.toWorld = keep;
        } else if (w == "density_map" || w == "normal_map") {
            next();
            warnOnce(w, t.loc, "'" + w + "' is not supported; the pattern uses a grey ramp");
            expectSymbol("{", "");
            skipBlock();
        } else if (w == "warp") {
            warpBlock(t, p);
        } else if (ignoredPatternModifiers().count(w)) {
            next();
            warnOnce(w, t.loc, "'" + w + "' is not supported and is ignored");
            if (w == "warp") {
                expectSymbol("{", "after 'warp'");
                skipBlock();
            } else {
                expression();
            }
        } else if (w == "quick_color" || w == "quick_colour") {
            next();
            colorExpr();
        } else if (w == "uv_mapping") {
            next();
            warnOnce(w, t.loc, "'uv_mapping' is not supported; the pattern uses object coordinates");
        } else {
            failExpected(t, "a pigment item or '}'");
        }
        first = false;
    }
    (void)first;
    if (p.pattern == PatternKind::Radial && p.colorMap.empty() && p.pigmentMap.empty()) // POV-Ray's default radial map
        p.colorMap = {{0.0, rgb(0, 1, 1)}, {0.333, rgb(1, 1, 0)}, {0.666, rgb(1, 0, 1)}, {1.0, rgb(0, 1, 1)}};
    if (!pattern.empty() && !p.pigmentMap.empty()) {
        warnOnce("pattern-" + pattern, patternLoc,
                 "pattern '" + pattern + "' is approximated by the equally weighted average of its pigment_map");
        p.pattern = PatternKind::Average;
        for (Pigment::MapEntry& entry : p.pigmentMap) entry.value = 1;
    } else if (!pattern.empty()) {
        warnOnce("pattern-" + pattern, patternLoc,
                 "pattern '" + pattern + "' is approximated by the average colour of its colour map");
        const Transform keep = p.toWorld;
        const ColorFT avg = pigmentAverage(p.pattern == PatternKind::Solid && p.colorMap.empty() ? p : [&] {
            Pigment q = p;
            q.pattern = PatternKind::Gradient;
            return q;
        }());
        p = solid(avg);
        p.toWorld = keep;
    }
    return p;
}

Finish PovParser::finish(const Finish& base) {
    expectSymbol("{", "after 'finish'");
    Finish f = base;
    auto colorOrFloat = [&]() { return toColorFT(colorExpr()).rgb; };
    for (;;) {
        const Tok t = next();
        if (t.is("}")) return f;
        if (t.kind != TokKind::Word) failExpected(t, "a finish item or '}'");
        const std::string& w = t.text;
        const Cell c = useIndexed(t);
        if (c && c->kind == Kind::Finish) {
            f = *c->finish;
            continue;
        }
        if (w == "ambient") f.ambient = colorOrFloat();
        else if (w == "emission") f.emission = colorOrFloat();
        else if (w == "diffuse") {
            acceptWord("albedo");
            f.diffuse = floatExpr();
            if (acceptSymbol(",")) {
                floatExpr();
                warnOnce("diffuse-back", t.loc, "diffuse's back-side value is not supported and is ignored");
            }
        } else if (w == "brilliance") f.brilliance = floatExpr();
        else if (w == "phong") {
            acceptWord("albedo");
            f.phong = floatExpr();
        } else if (w == "phong_size") f.phongSize = floatExpr();
        else if (w == "specular") {
            acceptWord("albedo");
            f.specular = floatExpr();
        } else if (w == "roughness") f.roughness = floatExpr();
        else if (w == "metallic") {
            f.metallic = startsFloat(peekOperator()) ? floatExpr() : 1.0;
        } else if (w == "conserve_energy") {
            f.conserveEnergy = true;
            if (startsFloat(peekOperator())) f.conserveEnergy = floatExpr() != 0;
        } else if (w == "reflection") {
            if (acceptSymbol("{")) {
                Color a = colorOrFloat();
                Color b = a;
                acceptSymbol(","); // `{ min, max }` or `{ min max }`
                const Tok n = peek();
                if (!(n.is("}") || n.isWord("fresnel") || n.isWord("falloff") || n.isWord("exponent") ||
                      n.isWord("metallic")))
                    b = colorOrFloat();
                f.reflectionMin = a;
                f.reflectionMax = b;
                for (;;) {
                    const Tok r = next();
                    if (r.is("}")) break;
                    if (r.isWord("fresnel")) {
                        f.reflectionFresnel = startsFloat(peekOperator()) ? floatExpr() != 0 : true;
                    } else if (r.isWord("falloff")) f.reflectionFalloff = floatExpr();
                    else if (r.isWord("metallic")) {
                        f.reflectionMetallic = startsFloat(peekOperator()) ? floatExpr() : 1.0;
                    } else if (r.isWord("exponent")) {
                        floatExpr();
                        warnOnce("reflection-exponent", r.loc, "reflection 'exponent' is not supported and is ignored");
                    } else {
                        failExpected(r, "'fresnel', 'falloff', 'exponent', 'metallic' or '}' in reflection");
                    }
                }
            } else {
                f.reflectionMin = f.reflectionMax = colorOrFloat();
            }
        } else if (w == "reflection_exponent") {
            floatExpr();
            warnOnce("reflection-exponent", t.loc, "'reflection_exponent' is not supported and is ignored");
        } else if (w == "irid") {
            warnOnce("irid", t.loc, "'irid' (iridescence) is not supported and is ignored");
            expectSymbol("{", "after 'irid'");
            skipBlock();
        } else if (w == "subsurface") {
            warnOnce("subsurface", t.loc, "'subsurface' is not supported and is ignored");
            expectSymbol("{", "after 'subsurface'");
            skipBlock();
        } else if (w == "crand") {
            f.crand = floatExpr();
        } else if (w == "refraction" || w == "ior" || w == "caustics" || w == "fade_distance" || w == "fade_power") {
            floatExpr();
            warnOnce("finish-" + w, t.loc, "'" + w + "' inside finish is POV-Ray 3.1 syntax; ignored (use interior)");
        } else {
            failExpected(t, "a finish item or '}'");
        }
    }
}

Interior PovParser::interior(const Interior& base) {
    expectSymbol("{", "after 'interior'");
    Interior in = base;
    for (;;) {
        const Tok t = next();
        if (t.is("}")) return in;
        if (t.kind != TokKind::Word) failExpected(t, "an interior item or '}'");
        const Cell c = useIndexed(t);
        if (c && c->kind == Kind::Interior) {
            in = *c->interior;
            continue;
        }
        const std::string& w = t.text;
        if (w == "ior") in.ior = floatExpr();
        else if (w == "fade_distance") in.fadeDistance = floatExpr();
        else if (w == "fade_power") in.fadePower = floatExpr();
        else if (w == "fade_color" || w == "fade_colour") in.fadeColor = toColorFT(colorExpr()).rgb;
        else if (w == "caustics" || w == "dispersion" || w == "dispersion_samples") {
            floatExpr();
            warnOnce("interior-" + w, t.loc, "'" + w + "' is not supported and is ignored");
        } else if (w == "media") {
            in.media.push_back(media(Media{}));
        } else {
            failExpected(t, "an interior item or '}'");
        }
    }
}

void PovParser::noiseNote(const std::string& kind, SourceLoc loc) {
    if (kind == "leopard" || kind == "waves" || kind == "ripples") return; // POV-Ray's formulas, no noise
    if (!warned_.insert("note-" + kind).second) return;
    note(loc, "'" + kind + "' is approximated: drt's noise has POV-Ray's shapes but not its exact values");
}

// turbulence float|vector, octaves int, omega float, lambda float: consumed
// with their value when the peeked token `t` is one of them.
bool PovParser::patternModifier(const Tok& t, Turbulence& turbulence) {
    if (t.kind != TokKind::Word) return false;
    const std::string& w = t.text;
    if (w != "turbulence" && w != "octaves" && w != "omega" && w != "lambda") return false;
    next();
    if (w == "turbulence") turbulence.amount = vectorExpr();
    else if (w == "octaves") turbulence.octaves = std::clamp(countExpr("octaves", -1e9, 1e9), 1, 10);
    else if (w == "omega") turbulence.omega = floatExpr();
    else turbulence.lambda = floatExpr();
    noiseNote("turbulence", t.loc);
    return true;
}

// normal { [pattern [amount]] { modifier | transform } }
std::optional<Normal> PovParser::normalBlock(SourceLoc keyword) {
    expectSymbol("{", "after 'normal'");
    Normal n;
    bool known = false;
    for (;;) {
        const Tok t = peek();
        if (t.is("}")) {
            next();
            break;
        }
        if (std::optional<Transform> tr = transformItem()) {
            n.toWorld = n.toWorld.then(*tr);
            continue;
        }
        if (t.kind == TokKind::Word) {
            std::optional<PatternKind> kind = noiseKind(t.text);
            if (kind) noiseNote(t.text, t.loc);
            else if (t.text == "gradient") kind = PatternKind::Gradient;
            else if (t.text == "radial") kind = PatternKind::Radial;
            else if (t.text == "onion") kind = PatternKind::Onion;
            else if (t.text == "spherical") kind = PatternKind::Spherical;
            if (kind) { // a pattern, then its own parameters, then the amount
                next();
                n.pattern = *kind;
                known = true;
                if (*kind == PatternKind::Gradient) n.gradientAxis = vectorExpr(), acceptSymbol(",");
                if (peek().kind == TokKind::Number || peek().is("(") || peek().is("-")) n.amount = floatExpr();
                continue;
            }
            if (patternModifier(t, n.turbulence) || waveModifier(t, n.wave)) continue;
            if (t.text == "accuracy") { // the slope's sample spacing
                next();
                n.accuracy = floatExpr();
                continue;
            }
            if (t.text == "bump_size") {
                next();
                n.amount = floatExpr();
                continue;
            }
        }
        warnOnce("normal", keyword, "'normal' with '" + t.text + "' is not supported and is ignored");
        skipBlock();
        return std::nullopt;
    }
    if (!known) {
        warnOnce("normal", keyword, "'normal' without a bump pattern is not supported and is ignored");
        return std::nullopt;
    }
    return n;
}

Texture PovParser::texture(const Texture& base) {
    expectSymbol("{", "after 'texture'");
    // A new texture starts from the base's bottom layer; a patterned base gives only its defaults.
    Texture start = base.map.empty() ? base : Texture{};
    start.layersAbove.clear();
    return textureBody(start, "}");
}

Texture PovParser::textureBody(const Texture& base, const char* closer) {
    Texture tex = base;
    for (;;) {
        const Tok t = next();
        if (t.is(closer)) return tex;
        if (t.kind != TokKind::Word) failExpected(t, "a texture item or '" + std::string(closer) + "'");
        const Cell c = useIndexed(t);
        if (c && c->kind == Kind::Texture) {
            tex = *c->texture;
            continue;
        }
        const std::string& w = t.text;
        if (w == "pigment") tex.pigment = pigment(tex.pigment);
        else if (w == "finish") tex.finish = finish(tex.finish);
        else if (w == "normal") {
            if (std::optional<Normal> n = normalBlock(t.loc)) tex.normal = std::move(n);
        } else if (w == "translate" || w == "rotate" || w == "scale" || w == "matrix" || w == "transform") {
            pushBack(t);
            transformTextureSpaces(tex, *transformItem());
        } else if (isTexturePatternWord(w)) {
            return patternedTexture(t, closer);
        } else if (w == "uv_mapping") {
            warnOnce(w, t.loc, "'uv_mapping' is not supported; the pattern uses object coordinates");
        } else if (ignoredPatternModifiers().count(w) || w == "quick_color") {
            warnOnce(w, t.loc, "'" + w + "' is not supported and is ignored");
            if (w == "warp") expectSymbol("{", ""), skipBlock();
            else expression();
        } else {
            failExpected(t, "'pigment', 'finish', 'normal', a transform or '" + std::string(closer) + "'");
        }
    }
}

PovMaterial PovParser::material(const PovMaterial& base) {
    expectSymbol("{", "after 'material'");
    PovMaterial m = base;
    for (;;) {
        const Tok t = next();
        if (t.is("}")) return m;
        if (t.kind != TokKind::Word) failExpected(t, "a material item or '}'");
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
        } else {
            failExpected(t, "'texture', 'interior', a transform or '}'");
        }
    }
}

} // namespace drt::pov
