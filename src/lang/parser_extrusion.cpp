// The extrusion shapes: prism (POV-Ray's syntax) and text (drt's own words).
#include "lang/parser.h"
#include "outline/prism_outline.h"
#include "outline/text_outline.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

namespace drt {

namespace fs = std::filesystem;

// prism-body = [ "linear_sweep" | "conic_sweep" ]
//              [ "linear_spline" | "quadratic_spline" | "cubic_spline" | "bezier_spline" ]
//              expression "," expression "," expression { "," vector2 }
void Parser::prismBody(const Token& keyword, ParsedObject& po) {
    Extrusion e;
    PrismSource source;
    using S = PrismSource::Spline;
    bool sweepSeen = false, splineSeen = false;
    while (check(TokenKind::Identifier)) {
        const std::string& w = current_.text;
        if (!sweepSeen && (w == "linear_sweep" || w == "conic_sweep")) {
            e.conic = w == "conic_sweep";
            sweepSeen = true;
        } else if (!splineSeen && (w == "linear_spline" || w == "quadratic_spline" || w == "cubic_spline" ||
                                   w == "bezier_spline")) {
            source.spline = w == "linear_spline" ? S::Linear
                            : w == "quadratic_spline" ? S::Quadratic
                            : w == "cubic_spline" ? S::Cubic
                                                  : S::Bezier;
            splineSeen = true;
        } else {
            break;
        }
        advance();
    }
    e.height1 = floatExpr("the first height");
    expect(TokenKind::Comma, "',' after the first height");
    const SourceLoc heightLoc = current_.loc;
    e.height2 = floatExpr("the second height");
    if (e.height1 == e.height2) error(heightLoc, "prism heights must differ");
    if (e.conic && e.height1 * e.height2 < 0)
        error(heightLoc, "conic_sweep heights must not lie on both sides of the apex at 0");
    expect(TokenKind::Comma, "',' after the second height");
    const SourceLoc countLoc = current_.loc;
    const int count = intExpr("the number of points");
    const int minimum = minimumPrismPoints(source.spline);
    if (count < minimum) fail(countLoc, "this prism spline needs at least " + std::to_string(minimum) + " points");
    for (int i = 0; i < count; ++i) {
        expect(TokenKind::Comma, i == 0 ? "',' after the number of points" : "',' between prism points");
        const SourceLoc loc = current_.loc;
        Value v = expression();
        const VectorValue* p = std::get_if<VectorValue>(&v);
        if (!p || p->size != 2) fail(loc, "expected a prism point <x, z>, found " + kindName(v));
        source.points.push_back({p->c[0], p->c[1]});
    }
    try {
        e.contours = prismContours(source.spline, source.points);
    } catch (const std::invalid_argument& ex) {
        fail(keyword.loc, ex.what());
    }
    e.plane = Extrusion::Plane::XZ;
    e.fill = Extrusion::Fill::EvenOdd;
    e.prism = std::move(source);
    po.object.shape = std::move(e);
}

// text-body = "font" string "string" string "thickness" expression [ "offset" expression ]
void Parser::textBody(ParsedObject& po) {
    TextSource source;
    if (!matchWord("font")) failExpected("'font' and the font file name in quotes");
    const Token font = expect(TokenKind::String, "the font file name in quotes");
    source.font = font.text;
    if (!matchWord("string")) failExpected("'string' and the text in quotes");
    source.string = expect(TokenKind::String, "the text in quotes").text;
    if (!matchWord("thickness")) failExpected("'thickness' and the depth of the letters");
    const SourceLoc thicknessLoc = current_.loc;
    double thickness = floatExpr("the thickness");
    if (thickness == 0) {
        error(thicknessLoc, "text thickness must not be zero");
        thickness = 1;
    }
    if (matchWord("offset")) source.offset = vectorExpr("the offset <x, y>");
    // Fonts are found like POV-Ray's: beside the file, beside the scene, then
    // in POV-Ray's include folder.
    std::vector<std::string> dirs{sources_.back().dir};
    for (const std::string& dir : {sources_.front().dir, std::string(kPovFontDir)})
        if (std::find(dirs.begin(), dirs.end(), dir) == dirs.end()) dirs.push_back(dir);
    source.fontPath = findFontFile(source.font, dirs);
    if (source.fontPath.empty()) {
        std::string looked;
        for (const std::string& d : dirs) looked += (looked.empty() ? "" : ", ") + (d.empty() ? "." : d);
        fail(font.loc, "cannot find font '" + source.font + "' (looked in " + looked + ")");
    }
    Extrusion e;
    try {
        e = makeTextExtrusion(source, thickness);
    } catch (const FontError& ex) {
        fail(font.loc, ex.what());
    }
    po.object.shape = std::move(e);
}

} // namespace drt
