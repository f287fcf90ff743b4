// finish (the classic model and drt's blur and crand), interior, and
// participating media: `media { }` in interiors and at scene level, with
// `density { }` (a pigment evaluated as a colour; without a pattern it is 1,
// POV-Ray's default). A block starts from the one it modifies (POV-Ray).
#include "lang/evaluator.h"

#include <cmath>

namespace drt::lang {

using Kind = Value::Kind;

Finish Evaluator::finish(const Finish& base) {
    const Token keyword = lastToken();
    expectSymbol("{", "after 'finish'");
    BlockScope scope(*this, "finish", keyword.loc);
    Finish f = scene().modifyBlocks ? base : Finish{};
    for (;;) {
        const Token t = next();
        if (t.is("}")) return f;
        if (t.kind != TokenKind::Word) failInBlock(t, "a finish keyword or '}'");
        const std::string& w = t.text;
        const Cell c = useIndexed(t);
        if (c && c->kind == Kind::Finish) {
            f = *c->finish;
            continue;
        }
        if (c) fail(t.loc, "'" + w + "' is " + kindName(*c) + ", not a finish");
        const SourceLoc loc = peek().loc;
        auto nonNegative = [&](double& target) {
            target = floatExpr();
            if (target < 0) refuse(loc, "'" + w + "' must not be negative" + got(target));
        };
        if (w == "ambient") f.ambient = rgbExpr();
        else if (w == "emission") f.emission = rgbExpr();
        else if (w == "diffuse") {
            acceptWord("albedo");
            nonNegative(f.diffuse);
            if (acceptSymbol(",")) {
                floatExpr();
                unsupported("diffuse-back", t.loc, "diffuse's back-side value is not supported and is ignored");
            }
        } else if (w == "brilliance") nonNegative(f.brilliance);
        else if (w == "phong") {
            acceptWord("albedo");
            nonNegative(f.phong);
        } else if (w == "phong_size") nonNegative(f.phongSize);
        else if (w == "specular") {
            acceptWord("albedo");
            nonNegative(f.specular);
        } else if (w == "crand") nonNegative(f.crand);
        else if (w == "roughness") {
            f.roughness = floatExpr();
            if (!(f.roughness > 0)) refuse(loc, "'roughness' must be positive" + got(f.roughness));
        } else if (w == "metallic") {
            f.metallic = startsFloat(peekOperator()) ? floatExpr() : 1.0;
        } else if (w == "conserve_energy") {
            f.conserveEnergy = optionalBool(true);
        } else if (w == "reflection") {
            if (acceptSymbol("{")) reflectionBlock(f);
            else f.reflectionMin = f.reflectionMax = rgbExpr();
        } else if (w == "reflection_blur" || w == "refraction_blur") {
            const double b = floatExpr();
            if (b < 0 || b > 1) error(loc, "'" + w + "' must be between 0 and 1" + got(b));
            (w == "reflection_blur" ? f.reflectionBlur : f.refractionBlur) = std::clamp(b, 0.0, 1.0);
        } else if (w == "reflection_exponent") {
            floatExpr();
            unsupported("reflection-exponent", t.loc, "'reflection_exponent' is not supported and is ignored");
        } else if (w == "irid" || w == "subsurface") {
            unsupported(w, t.loc, "'" + w + "' is not supported and is ignored");
            expectSymbol("{", "after '", w, "'");
            skipBlock();
        } else if (syntax().legacySyntax &&
                   (w == "refraction" || w == "ior" || w == "caustics" || w == "fade_distance" || w == "fade_power")) {
            floatExpr();
            warnOnce("finish-" + w, t.loc, "'" + w + "' inside finish is POV-Ray 3.1 syntax; ignored (use interior)");
        } else {
            failUnknown(t, Block::Finish, declaredNames({Kind::Finish}));
        }
    }
}

// reflection { [colour [,] [colour]] { fresnel [bool] | falloff f | metallic [m] | exponent e } }
// One colour sets both min and max; two give min, then max.
void Evaluator::reflectionBlock(Finish& f) {
    auto atItem = [&](const Token& n) {
        return n.is("}") || n.isWord("fresnel") || n.isWord("falloff") || n.isWord("exponent") || n.isWord("metallic");
    };
    if (!atItem(peek())) {
        const Color a = rgbExpr();
        Color b = a;
        if (acceptSymbol(",")) b = rgbExpr();
        else if (!syntax().requireCommas && !atItem(peek())) b = rgbExpr(); // `{ min max }`
        f.reflectionMin = a;
        f.reflectionMax = b;
    }
    for (;;) {
        const Token r = next();
        if (r.is("}")) break;
        const SourceLoc loc = peek().loc;
        if (r.isWord("fresnel")) {
            f.reflectionFresnel = optionalBool(true);
        } else if (r.isWord("falloff")) {
            f.reflectionFalloff = floatExpr();
            if (!(f.reflectionFalloff > 0)) refuse(loc, "'falloff' must be positive" + got(f.reflectionFalloff));
        } else if (r.isWord("metallic")) {
            f.reflectionMetallic = startsFloat(peekOperator()) ? floatExpr() : 1.0;
        } else if (r.isWord("exponent")) {
            floatExpr();
            unsupported("reflection-exponent", r.loc, "reflection 'exponent' is not supported and is ignored");
        } else if (r.kind == TokenKind::Word) {
            failUnknown(r, Block::Reflection);
        } else {
            failInBlock(r, "'fresnel', 'falloff', 'metallic' or '}' in reflection");
        }
    }
}

Interior Evaluator::interior(const Interior& base) {
    const Token keyword = lastToken();
    expectSymbol("{", "after 'interior'");
    BlockScope scope(*this, "interior", keyword.loc);
    Interior in = scene().modifyBlocks ? base : Interior{};
    for (;;) {
        const Token t = next();
        if (t.is("}")) return in;
        if (t.kind != TokenKind::Word) failInBlock(t, "an interior keyword or '}'");
        const Cell c = useIndexed(t);
        if (c && c->kind == Kind::Interior) {
            in = *c->interior;
            continue;
        }
        if (c) fail(t.loc, "'" + t.text + "' is " + kindName(*c) + ", not an interior");
        const std::string& w = t.text;
        const SourceLoc loc = peek().loc;
        if (w == "ior") {
            in.ior = floatExpr();
            if (!(in.ior > 0)) refuse(loc, "'ior' must be positive" + got(in.ior));
        } else if (w == "fade_distance" || w == "fade_power") {
            double& target = w == "fade_distance" ? in.fadeDistance : in.fadePower;
            target = floatExpr();
            if (target < 0) refuse(loc, "'" + w + "' must not be negative" + got(target));
        } else if (w == "fade_color" || w == "fade_colour") {
            in.fadeColor = rgbExpr();
        } else if (w == "caustics" || w == "dispersion" || w == "dispersion_samples") {
            floatExpr();
            unsupported("interior-" + w, t.loc, "'" + w + "' is not supported and is ignored");
        } else if (w == "media") {
            in.media.push_back(media(Media{}));
        } else {
            failUnknown(t, Block::Interior, declaredNames({Kind::Interior}));
        }
    }
}

Pigment Evaluator::density(const Pigment& base) {
    const Token keyword = lastToken();
    DepthGuard guard(*this, keyword.loc);
    expectSymbol("{", "after 'density'");
    BlockScope scope(*this, "density", keyword.loc);
    return pigmentBody(base, "}", "'}' in density");
}

// scattering { type, colour [eccentricity g] [extinction x] }
void Evaluator::scattering(Media& m) {
    expectSymbol("{", "after 'scattering'");
    const SourceLoc typeLoc = peek().loc;
    const double type = floatExpr("the scattering type");
    if (!(type >= 1 && type <= 5 && type == std::floor(type)))
        fail(typeLoc, "the scattering type must be 1, 2, 3, 4 or 5" + got(type));
    m.scatteringType = int(type);
    acceptSymbol(",");
    m.scattering = rgbExpr();
    for (;;) {
        const Token t = next();
        if (t.is("}")) return;
        const SourceLoc loc = peek().loc;
        if (t.isWord("eccentricity")) {
            m.eccentricity = floatExpr();
            if (!(std::abs(m.eccentricity) < 1))
                refuse(loc, "'eccentricity' must lie strictly between -1 and 1" + got(m.eccentricity));
        } else if (t.isWord("extinction")) {
            m.extinction = floatExpr();
            if (m.extinction < 0) refuse(loc, "'extinction' must not be negative" + got(m.extinction));
        } else if (t.kind == TokenKind::Word) {
            failUnknown(t, Block::Scattering);
        } else {
            failInBlock(t, "'eccentricity', 'extinction' or '}' in scattering");
        }
    }
}

Media Evaluator::media(const Media& base) {
    const Token keyword = lastToken();
    DepthGuard guard(*this, keyword.loc);
    expectSymbol("{", "after 'media'");
    BlockScope scope(*this, "media", keyword.loc);
    Media m = base;
    for (;;) {
        const Token t = peek();
        if (t.is("}")) {
            next();
            return m;
        }
        if (std::optional<Transform> tr = transformItem()) { // moves the densities given so far
            for (Pigment& d : m.densities) transformPigmentSpaces(d, *tr);
            continue;
        }
        next();
        if (t.kind != TokenKind::Word) failInBlock(t, "a media keyword or '}'");
        const Cell c = useIndexed(t);
        if (c && c->kind == Kind::Media) {
            m = *c->media;
            continue;
        }
        const std::string& w = t.text;
        const SourceLoc loc = peek().loc;
        if (w == "absorption") m.absorption = rgbExpr();
        else if (w == "emission") m.emission = rgbExpr();
        else if (w == "scattering") scattering(m);
        else if (w == "density") {
            Pigment unit;
            unit.color = ColorFT{Color(1), 0, 0};
            m.densities.push_back(density(unit));
        } else if (w == "intervals" || w == "samples") {
            // A count past the limit (or not finite) is refused before it becomes an int.
            const int64_t most = diags_.limits().mediaIntervals;
            const double n = floatExpr(w == "intervals" ? "the number of intervals" : "the number of samples");
            int& target = w == "intervals" ? m.intervals : m.samples;
            if (syntax().strictValues) {
                if (!(n >= 1)) error(loc, "'" + w + "' must be at least 1" + got(n));
                else if (n > double(most))
                    error(loc, limitExceeded(diags_.limits(), &Limits::mediaIntervals, "'" + w + "'", n));
                else if (n != std::floor(n)) error(loc, "'" + w + "' must be a whole number" + got(n));
                target = n >= 1 && n <= double(most) ? int(n) : 1;
            } else {
                target = countValue(n, loc, ("media " + w).c_str(), 1, double(most));
            }
            if (w == "samples" && acceptSymbol(",")) floatExpr(); // the maximum of methods 1 and 2
        } else if (w == "method") {
            const int method = intExpr("the media method");
            if (method < 1 || method > 3) refuse(loc, "'method' must be 1, 2 or 3" + got(double(method)));
        } else if (w == "confidence" || w == "variance" || w == "ratio" || w == "jitter" || w == "aa_threshold" ||
                   w == "aa_level") {
            floatExpr(); // POV-Ray's adaptive sampling: accepted, drt samples its own way
        } else {
            failUnknown(t, Block::Media, declaredNames({Kind::Media}));
        }
    }
}

} // namespace drt::lang
