// POV-Ray participating media: `media { }` in interiors and at scene level,
// and `density { }` (a pigment evaluated as a colour; without a pattern it is
// 1, POV-Ray's default). method, confidence, variance, ratio, jitter and
// aa_threshold/aa_level are read and dropped: drt samples each ray segment
// with intervals x samples stratified jittered points (render/media.h).
#include "pov/parser.h"

#include <algorithm>

namespace drt::pov {

using Kind = PovValue::Kind;

namespace {

Pigment unitDensity() {
    Pigment p;
    p.color = ColorFT{Color(1), 0, 0};
    return p;
}

} // namespace

Pigment PovParser::density(const Pigment& base) { return pigment(base); }

Pigment PovParser::density() { return density(unitDensity()); }

// scattering { type, colour [eccentricity g] [extinction x] }
void PovParser::scattering(Media& m) {
    expectSymbol("{", "after 'scattering'");
    const Tok typeTok = peek();
    const double type = floatExpr();
    if (!(type >= 1 && type <= 5) || type != std::floor(type))
        fail(typeTok.loc, "scattering type must be 1, 2, 3, 4 or 5");
    m.scatteringType = int(type);
    acceptSymbol(",");
    m.scattering = toColorFT(colorExpr()).rgb;
    for (;;) {
        const Tok t = next();
        if (t.is("}")) return;
        if (t.isWord("eccentricity")) m.eccentricity = floatExpr();
        else if (t.isWord("extinction")) m.extinction = floatExpr();
        else failExpected(t, "'eccentricity', 'extinction' or '}' in scattering");
    }
}

Media PovParser::media(const Media& base) {
    expectSymbol("{", "after 'media'");
    Media m = base;
    for (;;) {
        const Tok t = peek();
        if (t.is("}")) {
            next();
            return m;
        }
        if (std::optional<Transform> tr = transformItem()) {
            for (Pigment& d : m.densities) transformPigmentSpaces(d, *tr);
            continue;
        }
        next();
        if (t.kind != TokKind::Word) failExpected(t, "a media item or '}'");
        const Cell c = useIndexed(t);
        if (c && c->kind == Kind::Media) {
            m = *c->media;
            continue;
        }
        const std::string& w = t.text;
        if (w == "absorption") m.absorption = toColorFT(colorExpr()).rgb;
        else if (w == "emission") m.emission = toColorFT(colorExpr()).rgb;
        else if (w == "scattering") scattering(m);
        else if (w == "density") m.densities.push_back(density());
        else if (w == "intervals")
            m.intervals = countExpr("media intervals", 1, double(diags_.limits().mediaIntervals));
        else if (w == "samples") {
            m.samples = countExpr("media samples", 1, double(diags_.limits().mediaIntervals));
            if (acceptSymbol(",")) floatExpr(); // the maximum of methods 1 and 2
        } else if (w == "method" || w == "confidence" || w == "variance" || w == "ratio" || w == "jitter" ||
                   w == "aa_threshold" || w == "aa_level") {
            floatExpr();
        } else {
            failExpected(t, "a media item or '}'");
        }
    }
}

} // namespace drt::pov
