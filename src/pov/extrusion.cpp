// POV-Ray's prism and text objects -> the scene model's Extrusion.
#include "outline/prism_outline.h"
#include "outline/text_outline.h"
#include "pov/parser.h"

#include <filesystem>
#include <stdexcept>

namespace drt::pov {

namespace {

// Sets a parser flag for one expression, cleared again even if it fails.
struct FlagFor {
    bool& flag;
    explicit FlagFor(bool& f) : flag(f) { flag = true; }
    ~FlagFor() { flag = false; }
};

} // namespace

// prism { [sweep] [spline] height1, height2, N, <u, v> ... } after '{'. The
// points are POV-Ray UV vectors: a float promotes to <f, f>.
Extrusion PovParser::prismShape(SourceLoc keyword) {
    Extrusion e;
    PrismSource source;
    using S = PrismSource::Spline;
    for (;;) {
        const Tok t = peek();
        if (t.isWord("linear_sweep") || t.isWord("conic_sweep")) e.conic = t.text == "conic_sweep";
        else if (t.isWord("linear_spline")) source.spline = S::Linear;
        else if (t.isWord("quadratic_spline")) source.spline = S::Quadratic;
        else if (t.isWord("cubic_spline")) source.spline = S::Cubic;
        else if (t.isWord("bezier_spline")) source.spline = S::Bezier;
        else break;
        next();
    }
    e.height1 = floatExpr();
    acceptSymbol(",");
    const SourceLoc heightLoc = peek().loc;
    e.height2 = floatExpr();
    if (e.height1 == e.height2) fail(heightLoc, "prism heights must differ");
    if (e.conic && e.height1 * e.height2 < 0)
        fail(heightLoc, "conic_sweep heights on both sides of the apex (0) are not supported");
    acceptSymbol(",");
    const SourceLoc countLoc = peek().loc;
    // `4 <1, 2>`: the '<' after the count starts the first point.
    const double count = [&] {
        FlagFor flag(countBeforeVector_);
        return floatExpr();
    }();
    if (!(count >= minimumPrismPoints(source.spline)))
        fail(countLoc, "this prism spline needs at least " + std::to_string(minimumPrismPoints(source.spline)) +
                           " points");
    const int points = countValue(count, countLoc, "prism point count", 0, double(diags_.limits().meshTriangles));
    for (int i = 0; i < points; ++i) {
        acceptSymbol(",");
        const Vec3 p = vectorExpr();
        source.points.push_back({p.x, p.y});
    }
    try {
        e.contours = prismContours(source.spline, source.points);
    } catch (const std::invalid_argument& ex) {
        fail(keyword, ex.what());
    }
    e.plane = Extrusion::Plane::XZ;
    e.fill = Extrusion::Fill::EvenOdd;
    e.prism = std::move(source);
    return e;
}

// text { ttf "font" "string" thickness, offset } after '{'. Fonts are found
// like include files (with .ttf added to a name without extension). Nothing
// for POV-Ray's internal fonts (a warning).
std::optional<Extrusion> PovParser::textShape() {
    const Tok kind = next();
    if (!kind.isWord("ttf") && !kind.isWord("internal")) failExpected(kind, "'ttf' and a font file name");
    const SourceLoc fontLoc = peek().loc;
    TextSource source;
    if (kind.isWord("ttf")) source.font = stringExpr();
    else floatExpr(); // the internal font's number
    acceptSymbol(",");
    source.string = stringExpr();
    acceptSymbol(",");
    const double thickness = [&] {
        FlagFor flag(countBeforeVector_); // `1 <0.1, 0, 0>`: the offset follows
        return floatExpr();
    }();
    acceptSymbol(",");
    source.offset = vectorExpr();
    if (kind.isWord("internal")) {
        warnOnce("text-internal", kind.loc, "POV-Ray's internal fonts are not supported; the text is left out");
        return std::nullopt;
    }
    if (thickness == 0) fail(fontLoc, "text thickness must not be zero");
    std::string fromDir = ".";
    for (auto it = frames_.rbegin(); it != frames_.rend(); ++it)
        if (!it->isMacro) {
            fromDir = it->dir;
            break;
        }
    source.fontPath = findInclude(source.font, fromDir);
    if (source.fontPath.empty() && !std::filesystem::path(source.font).has_extension())
        source.fontPath = findInclude(source.font + ".ttf", fromDir);
    if (source.fontPath.empty())
        fail(fontLoc, "cannot find font file \"" + source.font + "\" (searched the scene's folder and the -L paths)");
    try {
        return makeTextExtrusion(source, thickness);
    } catch (const FontError& ex) {
        fail(fontLoc, ex.what());
    }
}

} // namespace drt::pov
