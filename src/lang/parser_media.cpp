// Participating media: `media { }` inside `interior { }` and at scene level.
// The model and its meaning are in scene.h (Media) and render/media.h.
#include "lang/parser.h"

#include <cmath>

namespace drt {

// media = "media" "{" { media-item } "}"
// media-item = "absorption" colour | "emission" colour | scattering | density
//            | "intervals" int | "samples" int [ "," int ] | "method" int
//            | "confidence" float | "variance" float | "ratio" float | "jitter" float | transform
Media Parser::media() {
    static const std::vector<std::string> known{"absorption", "emission", "scattering", "density", "intervals",
                                                "samples",    "method",   "confidence", "variance", "ratio",
                                                "jitter",     "translate", "rotate",    "scale",    "matrix"};
    const Token keyword = current_;
    advance();
    DepthGuard guard(*this, keyword.loc);
    expect(TokenKind::LeftBrace, "'{' after 'media'");
    Media m;
    while (!match(TokenKind::RightBrace)) {
        if (std::optional<Transform> t = transformItem()) { // moves the densities given so far
            for (Pigment& d : m.densities) transformPigmentSpaces(d, *t);
            continue;
        }
        if (!check(TokenKind::Identifier)) failExpected("a media keyword or '}'");
        if (checkWord("density")) {
            m.densities.push_back(density());
            continue;
        }
        const Token word = current_;
        const std::string& w = word.text;
        advance();
        const SourceLoc loc = current_.loc;
        if (w == "absorption") m.absorption = rgbExpr();
        else if (w == "emission") m.emission = rgbExpr();
        else if (w == "scattering") scattering(m);
        else if (w == "intervals" || w == "samples") {
            const int n = intExpr(w == "intervals" ? "the number of intervals" : "the number of samples");
            const int64_t most = diags_.limits().mediaIntervals;
            if (n < 1) error(loc, "'" + w + "' must be at least 1");
            else if (n > most) error(loc, limitExceeded(diags_.limits(), &Limits::mediaIntervals, "'" + w + "'", n));
            (w == "intervals" ? m.intervals : m.samples) = int(std::clamp<int64_t>(n, 1, most));
            if (w == "samples" && match(TokenKind::Comma)) intExpr("the maximum number of samples");
        } else if (w == "method") {
            const int method = intExpr("the media method");
            if (method < 1 || method > 3) error(loc, "'method' must be 1, 2 or 3");
        } else if (w == "confidence" || w == "variance" || w == "ratio" || w == "jitter") {
            floatExpr(); // POV-Ray's adaptive sampling: accepted, drt samples its own way
        } else {
            failUnknown(word, known);
        }
    }
    return m;
}

// scattering = "scattering" "{" int [ "," ] colour { "eccentricity" float | "extinction" float } "}"
void Parser::scattering(Media& m) {
    expect(TokenKind::LeftBrace, "'{' after 'scattering'");
    const SourceLoc typeLoc = current_.loc;
    const int type = intExpr("the scattering type");
    if (type < 1 || type > 5) error(typeLoc, "the scattering type must be 1, 2, 3, 4 or 5");
    m.scatteringType = std::clamp(type, 1, 5);
    match(TokenKind::Comma);
    m.scattering = rgbExpr();
    while (!match(TokenKind::RightBrace)) {
        if (!check(TokenKind::Identifier)) failExpected("'eccentricity', 'extinction' or '}' in scattering");
        const Token word = current_;
        advance();
        const SourceLoc loc = current_.loc;
        if (word.text == "eccentricity") {
            m.eccentricity = floatExpr();
            if (!(std::abs(m.eccentricity) < 1)) error(loc, "'eccentricity' must lie strictly between -1 and 1");
        } else if (word.text == "extinction") {
            m.extinction = floatExpr();
            if (m.extinction < 0) error(loc, "'extinction' must not be negative");
        } else {
            failUnknown(word, {"eccentricity", "extinction"});
        }
    }
}

// density = "density" "{" [ pigment-name ] { pigment-item } "}": a pigment
// evaluated as a colour; without a colour or pattern it is 1.
Pigment Parser::density() {
    const Token keyword = current_;
    advance();
    DepthGuard guard(*this, keyword.loc);
    expect(TokenKind::LeftBrace, "'{' after 'density'");
    Pigment p;
    p.color = ColorFT{Color(1), 0, 0};
    if (check(TokenKind::Identifier)) {
        if (const Value* v = lookup(current_.text); v && std::holds_alternative<Pigment>(*v)) {
            p = std::get<Pigment>(*v);
            advance();
        }
    }
    while (!match(TokenKind::RightBrace)) {
        if (pigmentItem(p)) continue;
        if (check(TokenKind::Identifier)) {
            if (const Value* v = lookup(current_.text))
                fail(current_.loc, "'" + current_.text + "' is " + kindName(*v) + ", not a pigment or colour");
            failUnknown(current_, {"color", "rgb", "gradient", "radial", "onion", "color_map", "checker",
                                   "bozo", "granite", "wrinkles", "translate", "rotate", "scale"});
        }
        failExpected("a colour, a pattern or '}' in density");
    }
    return p;
}

} // namespace drt
