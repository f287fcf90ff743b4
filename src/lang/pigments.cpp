// pigment { }: solid colours, the block and colour-map patterns the scene
// model has, noise patterns, pigment_map, turbulence, waves and transforms;
// colour maps. A pigment block starts from the pigment it modifies (POV-Ray).
// POV-Ray patterns drt lacks are approximated by their average in the
// POV-Ray dialect (a warning says so) and refused in .drt.
#include "lang/evaluator.h"
#include "lang/quilted.h"

#include <fmt/format.h>

namespace drt::lang {

using Kind = Value::Kind;

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

// POV-Ray's default colours of the list patterns (parstxtr.cpp).
std::vector<ColorFT> listDefaults(PatternKind kind) {
    switch (kind) {
    case PatternKind::Checker: return {rgb(0, 0, 1), rgb(0, 1, 0)};
    case PatternKind::Hexagon: return {rgb(0, 0, 1), rgb(0, 1, 0), rgb(1, 0, 0)};
    default: return {rgb(0.5, 0.5, 0.5), rgb(0.6, 0.15, 0.15)}; // brick: mortar, brick
    }
}

// A colour-map pattern without a map uses POV-Ray's: the grey ramp (radial
// and wood have their own, set when the pigment ends).
void greyRamp(Pigment& p) {
    if (p.colorMap.empty() && p.pattern != PatternKind::Radial && p.pattern != PatternKind::Wood)
        p.colorMap = {{0.0, {Color(0), 0, 0}}, {1.0, {Color(1), 0, 0}}};
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

void Evaluator::noiseNote(const std::string& kind, SourceLoc loc) {
    // drt's noise is the .drt dialect's own; only POV-Ray scenes are approximated.
    if (isDrt()) return;
    if (kind == "leopard" || kind == "waves" || kind == "ripples") return; // POV-Ray's formulas, no noise
    noteOnce("note-" + kind, loc, "'" + kind + "' is approximated: drt's noise has POV-Ray's shapes but not its exact values");
}

// color_map { [value colour] ... } or the old form [v1, v2 colour1 colour2].
std::vector<ColorMapEntry> Evaluator::colorMap() {
    const SourceLoc keyword = lastLoc();
    const Token open = next();
    if (open.kind == TokenKind::Word) {
        const Cell c = useIndexed(open);
        if (c && c->kind == Kind::ColorMap) return *c->colorMap;
        failExpected(open, "'{' or a color_map identifier");
    }
    if (!open.is("{")) failExpected(open, "'{' after 'color_map'");
    BlockScope scope(*this, "color_map", keyword);
    std::vector<ColorMapEntry> map;
    if (peek().kind == TokenKind::Word) {
        const Token id = next();
        const Cell c = useIndexed(id);
        if (!c || c->kind != Kind::ColorMap) failExpected(id, "'[' or a color_map identifier");
        map = *c->colorMap;
    }
    for (;;) {
        const Token t = next();
        if (t.is("}")) break;
        if (!t.is("[")) failInBlock(t, "'[' to start a color_map entry, or '}'");
        const SourceLoc loc = peek().loc;
        const double v1 = floatExpr("the entry's value");
        if (!map.empty() && v1 < map.back().value) refuse(loc, "color_map values must not decrease");
        acceptSymbol(",");
        if (startsFloat(peek()) && !syntax().requireCommas) {
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
        expectSymbol("]", "to end the color_map entry");
    }
    if (map.empty()) refuse(keyword, "color_map has no entries");
    if (map.size() > 256) warnOnce("colormap256", keyword, "color_map has more than 256 entries (POV-Ray's limit)");
    return map;
}

Pigment Evaluator::pigment(const Pigment& base) {
    const Token keyword = lastToken();
    DepthGuard guard(*this, keyword.loc);
    expectSymbol("{", "after 'pigment'");
    BlockScope scope(*this, "pigment", keyword.loc);
    return pigmentBody(scene().modifyBlocks ? base : Pigment{}, "}", "'}' in pigment");
}

Pigment Evaluator::pigmentBody(const Pigment& base, const char* closer, const std::string& where) {
    Pigment p = base;
    std::string approximated; // a POV-Ray pattern drt lacks, approximated
    SourceLoc approximatedLoc;
    // uv_mapping anywhere in the block (or in the pigment it modifies): the
    // block's transforms, before and after it, act in uv space; the flag is
    // set on the whole pigment at the end, so the object's transforms leave it.
    bool uv = p.uvMapping;
    setUvMapping(p, false);
    for (;;) {
        const Token t = peek();
        if (t.is(closer)) {
            next();
            break;
        }
        if (t.isWord("uv_mapping")) {
            next();
            uv = true;
            continue;
        }
        if (pigmentItem(p, t)) {
            if (p.uvMapping) uv = true, setUvMapping(p, false); // a declared uv-mapped pigment
            continue;
        }
        next();
        if (t.kind == TokenKind::Word && isApproximatedPattern(t.text)) {
            if (syntax().unsupportedIsError) fail(t.loc, "pattern '" + t.text + "' is not supported");
            approximated = t.text;
            approximatedLoc = t.loc;
            if (t.text == "object" && peek().is("{")) next(), skipBlock();
            continue;
        }
        if (t.kind == TokenKind::Word) {
            if (const Cell c = lookup(t.text)) fail(t.loc, "'" + t.text + "' is " + kindName(*c) + ", not a pigment or colour");
            failUnknown(t, Block::Pigment, declaredNames({Kind::Pigment, Kind::Color, Kind::ColorMap}));
        }
        failInBlock(t, "a colour, a pattern or " + where);
    }
    if (p.pattern == PatternKind::Radial && p.colorMap.empty() && p.pigmentMap.empty()) // POV-Ray's default radial map
        p.colorMap = {{0.0, rgb(0, 1, 1)}, {0.333, rgb(1, 1, 0)}, {0.666, rgb(1, 0, 1)}, {1.0, rgb(0, 1, 1)}};
    if (p.pattern == PatternKind::Wood && p.colorMap.empty() && p.pigmentMap.empty()) // POV-Ray's, measured
        p.colorMap = {{0.6, rgb(0.666, 0.312, 0.2)}, {0.6, rgb(0.4, 0.1333, 0.0667)}};
    if (!approximated.empty() && !p.pigmentMap.empty()) {
        warnOnce("pattern-" + approximated, approximatedLoc,
                 "pattern '" + approximated + "' is approximated by the equally weighted average of its pigment_map");
        p.pattern = PatternKind::Average;
        for (Pigment::MapEntry& entry : p.pigmentMap) entry.value = 1;
    } else if (!approximated.empty()) {
        warnOnce("pattern-" + approximated, approximatedLoc,
                 "pattern '" + approximated + "' is approximated by the average colour of its colour map");
        const Transform keep = p.toWorld;
        const ColorFT avg = pigmentAverage(p.pattern == PatternKind::Solid && p.colorMap.empty() ? p : [&] {
            Pigment q = p;
            q.pattern = PatternKind::Gradient;
            return q;
        }());
        p = solid(avg);
        p.toWorld = keep;
    }
    if (uv) setUvMapping(p, true);
    return p;
}

// One pigment item at `t` (peeked): consumed with its arguments, or false.
bool Evaluator::pigmentItem(Pigment& p, const Token& t) {
    if (std::optional<Transform> tr = transformItem()) {
        transformPigmentSpaces(p, *tr);
        return true;
    }
    if (t.kind != TokenKind::Word && !t.is("<") && t.kind != TokenKind::Number) return false;
    const std::string w = t.text;
    Cell c = t.kind == TokenKind::Word ? use(w) : nullptr;
    const bool colourArray = c && arrayOfNumbers(*c); // an element is read as a colour expression below
    if (c && c->kind == Kind::Array && !colourArray) { // an array element: a pigment or a colour map
        next();
        c = indexArray(c, t);
        if (c->kind == Kind::Pigment) p = *c->pigment;
        else if (c->kind == Kind::ColorMap) p.colorMap = *c->colorMap;
        else if (c->isNumeric()) {
            const Transform keep = p.toWorld;
            p = solid(toColorFT(toColor(*c, t.loc)));
            p.toWorld = keep;
        } else fail(t.loc, "'" + t.text + "' is " + kindName(*c) + ", not a pigment or colour");
        return true;
    }
    if (c && c->kind == Kind::Pigment) {
        next();
        p = *c->pigment;
        return true;
    }
    if (c && c->kind == Kind::ColorMap) {
        next();
        p.colorMap = *c->colorMap;
        return true;
    }
    if (c && !c->isNumeric() && !colourArray) return false; // the caller names what it is
    if (startsColor(t) && !t.is("-") && !t.is("(")) {
        const Transform keep = p.toWorld;
        p = solid(toColorFT(colorExpr()));
        p.toWorld = keep;
        return true;
    }
    if (t.kind != TokenKind::Word) return false;
    // A list pattern takes its sub-pigments or colours, else POV-Ray's defaults.
    auto list = [&](PatternKind kind) {
        next();
        p.pattern = kind;
        std::vector<ColorFT> defaults = listDefaults(kind);
        std::vector<Pigment> children;
        for (size_t i = 0; i < defaults.size(); ++i) {
            const Token n = peek();
            const Cell named = n.kind == TokenKind::Word ? lookup(n.text) : nullptr;
            if (n.isWord("pigment")) {
                next();
                children.push_back(pigment(Pigment{}));
            } else if (named && named->kind == Kind::Pigment) {
                next();
                use(n.text);
                children.push_back(*named->pigment);
            } else if (const Value* item = named && named->kind == Kind::Array ? arrayItemSample(*named) : nullptr;
                       item && item->kind == Kind::Pigment) { // an element of an array of pigments
                next();
                const Cell element = indexArray(use(n.text), n);
                if (element->kind != Kind::Pigment)
                    fail(n.loc, "'" + n.text + "' element is " + kindName(*element) + ", not a pigment");
                children.push_back(*element->pigment);
            } else if (startsColor(n) && !n.is("(") && !n.is("-") && !n.isWord("filter")) {
                children.push_back(solid(toColorFT(colorExpr())));
            } else {
                break;
            }
            if (i + 1 < defaults.size()) {
                if (syntax().requireCommas) {
                    if (!acceptSymbol(",")) break;
                } else {
                    acceptSymbol(",");
                }
            }
        }
        for (size_t i = children.size(); i < defaults.size(); ++i) children.push_back(solid(defaults[i]));
        p.children = std::move(children);
    };
    if (w == "checker") list(PatternKind::Checker);
    else if (w == "hexagon") list(PatternKind::Hexagon);
    else if (w == "brick") list(PatternKind::Brick);
    else if (w == "brick_size") {
        next();
        const SourceLoc loc = peek().loc;
        p.brickSize = vectorExpr();
        if (!(p.brickSize.x > 0 && p.brickSize.y > 0 && p.brickSize.z > 0))
            refuse(loc, "'brick_size' components must be positive" + got(p.brickSize));
    } else if (w == "mortar") {
        next();
        const SourceLoc loc = peek().loc;
        p.mortar = floatExpr();
        if (p.mortar < 0) refuse(loc, "'mortar' must not be negative" + got(p.mortar));
    } else if (w == "gradient" || placePatternNamed(w)) {
        next();
        if (w == "gradient") {
            const SourceLoc loc = peek().loc;
            p.gradientAxis = vectorExpr("the gradient axis");
            requireNonZero(p.gradientAxis, loc, "gradient axis");
        }
        p.pattern = w == "gradient" ? PatternKind::Gradient : *placePatternNamed(w);
        p.children.clear();
        greyRamp(p);
    } else if (const std::optional<PatternKind> kind = noisePatternNamed(w)) {
        next();
        p.pattern = *kind;
        p.children.clear();
        greyRamp(p);
        noiseNote(w, t.loc);
    } else if (w == "function") {
        next();
        p.pattern = PatternKind::Function;
        p.function = patternFunction(t);
        p.children.clear();
        greyRamp(p);
    } else if (w == "density_file") {
        next();
        p.pattern = PatternKind::DensityFile;
        p.densityFile = densityFile(t);
        p.children.clear();
        greyRamp(p);
    } else if (w == "interpolate" && p.pattern == PatternKind::DensityFile && p.densityFile) {
        next();
        p.densityFile = densityInterpolate(p.densityFile);
    } else if (w == "pigment_pattern") {
        next();
        p.pattern = PatternKind::Function;
        p.function = pigmentPatternFunction(t);
        p.children.clear();
        greyRamp(p);
    } else if (w == "quilted") {
        next();
        p.pattern = PatternKind::Function;
        p.function = quiltedFunction(1, 1);
        p.children.clear();
        greyRamp(p);
    } else if (double c0, c1; (w == "control0" || w == "control1") && p.pattern == PatternKind::Function &&
                              p.function && quiltedControls(*p.function, c0, c1)) {
        next();
        (w == "control0" ? c0 : c1) = floatExpr();
        p.function = quiltedFunction(c0, c1);
    } else if (isFractalWord(w)) {
        next();
        p.pattern = PatternKind::Fractal;
        p.fractal = fractalPattern(t);
        p.children.clear();
        greyRamp(p);
    } else if (p.pattern == PatternKind::Fractal && fractalModifier(t, p.fractal)) {
    } else if (w == "average") {
        next();
        p.pattern = PatternKind::Average;
        p.children.clear();
    } else if (w == "color_map" || w == "colour_map") {
        next();
        p.colorMap = colorMap();
    } else if (w == "pigment_map" ||
               (w == "density_map" && !openBlocks_.empty() && openBlocks_.back().keyword == "density")) {
        // A density is evaluated as a pigment: its density_map is a pigment_map of densities.
        next();
        p.pigmentMap = pigmentMap(p.pattern == PatternKind::Average);
    } else if (turbulenceItem(t, p.turbulence) || waveItem(t, p.wave)) {
    } else if (p.pattern == PatternKind::Crackle && (w == "metric" || w == "form" || w == "offset" || w == "solid")) {
        // crackle's variants: drt has one cellular form (F2 - F1, Euclidean).
        next();
        unsupported("crackle-" + w, t.loc, "crackle '" + w + "' is not supported and is ignored");
        if (w != "solid") w == "form" ? (void)vectorExpr() : (void)floatExpr();
    } else if (w == "image_map") {
        next();
        const Transform keep = p.toWorld;
        std::optional<Pigment> image = imageMapPigment(t.loc);
        p = image ? *image : solid(rgb(0.5, 0.5, 0.5));
        p.toWorld = keep;
    } else if (w == "image_pattern") {
        next();
        const std::optional<Pigment> image = imageMapPigment(t.loc, true);
        if (image) {
            p.pattern = PatternKind::ImagePattern;
            p.imageMap = image->imageMap;
            p.children.clear();
            greyRamp(p);
        } else { // image_pattern { function ... }: mid grey, as for image_map
            const Transform keep = p.toWorld;
            p = solid(rgb(0.5, 0.5, 0.5));
            p.toWorld = keep;
        }
    } else if (w == "bump_map" || w == "material_map") {
        next();
        unsupported(w, t.loc, "'" + w + "' is not supported; the pigment becomes mid grey");
        expectSymbol("{", "after '", w, "'");
        skipBlock();
        const Transform keep = p.toWorld;
        p = solid(rgb(0.5, 0.5, 0.5));
        p.toWorld = keep;
    } else if (w == "density_map") {
        fail(t.loc, "'density_map' goes in a 'density' block; a pigment's map of pigments is 'pigment_map'");
    } else if (w == "normal_map") {
        next();
        unsupported(w, t.loc, "'" + w + "' is not supported; the pattern uses a grey ramp");
        expectSymbol("{", "after '", w, "'");
        skipBlock();
    } else if (w == "warp") {
        warpBlock(t, p);
    } else if (w == "noise_generator" || w == "agate_turb") {
        next();
        unsupported(w, t.loc, "'" + w + "' is not supported and is ignored");
        expression();
    } else if (w == "quick_color" || w == "quick_colour") {
        next();
        colorExpr();
    } else {
        return false;
    }
    return true;
}

// turbulence float|vector, octaves int, omega float, lambda float: consumed
// with their value when the peeked token `t` is one of them.
bool Evaluator::turbulenceItem(const Token& t, Turbulence& turbulence) {
    if (t.kind != TokenKind::Word) return false;
    const std::string& w = t.text;
    if (w != "turbulence" && w != "octaves" && w != "omega" && w != "lambda") return false;
    next();
    const SourceLoc loc = peek().loc;
    if (w == "turbulence") {
        turbulence.amount = vectorExpr("the turbulence amount");
        if (turbulence.amount.x < 0 || turbulence.amount.y < 0 || turbulence.amount.z < 0)
            refuse(loc, "'turbulence' must not be negative" + got(turbulence.amount));
    } else if (w == "octaves") {
        const int n = countExpr("octaves", -1e9, 1e9);
        if (n < 1 || n > 10) refuse(loc, "'octaves' must be between 1 and 10" + got(n));
        turbulence.octaves = std::clamp(n, 1, 10);
    } else if (w == "omega") {
        turbulence.omega = floatExpr();
    } else {
        turbulence.lambda = floatExpr();
    }
    noiseNote("turbulence", t.loc);
    return true;
}

// frequency float, phase float, ramp_wave, triangle_wave, sine_wave,
// scallop_wave, cubic_wave, poly_wave [float]: consumed with their value when
// the peeked token `t` is one of them.
bool Evaluator::waveItem(const Token& t, PatternWave& wave) {
    if (t.kind != TokenKind::Word) return false;
    const std::string& w = t.text;
    if (w == "frequency" || w == "phase") {
        next();
        (w == "frequency" ? wave.frequency : wave.phase) = floatExpr();
        return true;
    }
    const std::optional<WaveKind> named = waveKindNamed(w);
    if (!named) return false;
    next();
    wave.kind = *named;
    if (wave.kind == WaveKind::Poly) {
        wave.exponent = 1; // POV-Ray's default exponent
        const Token e = peek();
        if (e.kind == TokenKind::Number || e.is("(") || e.is("-")) {
            const double exponent = floatExpr("the poly_wave exponent");
            if (exponent > 0) wave.exponent = exponent;
            else if (syntax().strictValues) error(e.loc, "the 'poly_wave' exponent must be positive" + got(exponent));
            else
                warnOnce("poly_wave-exponent", e.loc,
                         "a 'poly_wave' exponent that is not positive is not supported; 1 is used");
        }
    }
    return true;
}

// After 'warp' (the peeked token `t`): `warp { turbulence ... }` before any
// transform of the pattern is the pattern's turbulence (both warp the
// untransformed pattern point first); other warps are not supported.
void Evaluator::warpBlock(const Token& t, Pigment& p) {
    next();
    expectSymbol("{", "after 'warp'");
    if (!peek().isWord("turbulence")) {
        unsupported("warp", t.loc, "'warp' is not supported and is ignored");
        skipBlock();
        return;
    }
    Turbulence turbulence;
    while (turbulenceItem(Token(peek()), turbulence)) {
    }
    expectSymbol("}", "to end 'warp { turbulence ... }'");
    if (p.toWorld.isIdentity() && p.turbulence.amount == Vec3(0, 0, 0)) {
        p.turbulence = turbulence;
    } else {
        unsupported("warp-turbulence", t.loc,
                    "'warp { turbulence }' after a transform or beside 'turbulence' is not supported and is ignored");
    }
}

} // namespace drt::lang
