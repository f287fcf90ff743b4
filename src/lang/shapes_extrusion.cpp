// The extrusion shapes (scene/extrusion.h):
//   prism { [linear_sweep | conic_sweep] [linear_spline | quadratic_spline | cubic_spline | bezier_spline]
//           height1, height2, N, <x, z> ... [open] }
//   text { font "file" string "text" thickness t [offset <x, y>] }    (.drt's words)
//   text { ttf "file" "text" thickness, <offset> }                     (POV-Ray's)
// Both are written back as their source (spline points, font and string),
// which the reader turns into the same outline.
#include "lang/evaluator.h"
#include "lang/shape_syntax.h"
#include "lang/writer_detail.h"
#include "outline/prism_outline.h"
#include "outline/text_outline.h"

#include <filesystem>
#include <stdexcept>

namespace drt::lang {

using writer::number;
using writer::vector;

namespace fs = std::filesystem;

namespace {

struct FlagFor {
    bool& flag;
    explicit FlagFor(bool& f) : flag(f) { flag = true; }
    ~FlagFor() { flag = false; }
};

const std::pair<const char*, PrismSource::Spline> kSplines[] = {{"linear_spline", PrismSource::Spline::Linear},
                                                                {"quadratic_spline", PrismSource::Spline::Quadratic},
                                                                {"cubic_spline", PrismSource::Spline::Cubic},
                                                                {"bezier_spline", PrismSource::Spline::Bezier}};

const char* splineWord(PrismSource::Spline s) {
    for (const auto& [word, spline] : kSplines)
        if (spline == s) return word;
    return "linear_spline";
}

// A font in POV-Ray's include folder is written by name (the reader looks
// there too); any other by its absolute path.
std::string fontName(const TextSource& t) {
    const fs::path path = fs::absolute(t.fontPath).lexically_normal();
    if (path.parent_path() == fs::path(kPovFontDir)) return path.filename().string();
    return path.string();
}

std::string point(Vec2 p) {
    std::string text = "<"; // appended piece by piece: GCC 12 warns (-Wrestrict) on "<" + string
    text += number(p.x);
    text += ", ";
    text += number(p.y);
    text += ">";
    return text;
}

void readPrism(Evaluator& e, const Token& keyword, ObjectValue& o) {
    Extrusion x;
    PrismSource source;
    bool sweepSeen = false, splineSeen = false;
    for (;;) {
        const Token t = e.peek();
        bool spline = false;
        for (const auto& [word, kind] : kSplines)
            if (t.isWord(word) && !splineSeen) source.spline = kind, spline = true;
        if (spline) splineSeen = true;
        else if ((t.isWord("linear_sweep") || t.isWord("conic_sweep")) && !sweepSeen)
            x.conic = t.text == "conic_sweep", sweepSeen = true;
        else break;
        e.next();
    }
    x.height1 = e.floatExpr("the first height");
    e.comma("first height");
    const SourceLoc heightLoc = e.peek().loc;
    x.height2 = e.floatExpr("the second height");
    if (x.height1 == x.height2) e.error(heightLoc, "prism heights must differ");
    if (x.conic && x.height1 * x.height2 < 0)
        e.error(heightLoc, "conic_sweep heights must not lie on both sides of the apex at 0");
    e.comma("second height");
    const SourceLoc countLoc = e.peek().loc;
    // `4 <1, 2>`: the '<' after the count starts the first point.
    const double count = [&] {
        FlagFor flag(e.countBeforeVector_);
        return e.floatExpr("the number of points");
    }();
    const int minimum = minimumPrismPoints(source.spline);
    if (count != std::floor(count) && e.syntax().strictValues)
        e.fail(countLoc, "the number of points must be a whole number" + e.got(count));
    if (!(count >= minimum))
        e.fail(countLoc, "this prism spline needs at least " + std::to_string(minimum) + " points");
    const int points =
        e.countValue(count, countLoc, "prism point count", 0, double(e.diags().limits().meshTriangles));
    for (int i = 0; i < points; ++i) {
        if (e.syntax().requireCommas)
            e.expectSymbol(",", i == 0 ? "after the number of points" : "between prism points");
        else e.acceptSymbol(",");
        const SourceLoc loc = e.peek().loc;
        const Value v = e.expression();
        // A POV-Ray UV vector: a number promotes to <n, n>.
        if (v.kind == Value::Kind::Float && !e.syntax().strictValues) {
            source.points.push_back({v.number, v.number});
            continue;
        }
        if (!(v.kind == Value::Kind::Vector && v.size == 2) &&
            !(!e.syntax().strictValues && (v.kind == Value::Kind::Vector || v.kind == Value::Kind::Color)))
            e.fail(loc, "expected a prism point <x, z>, found " + kindName(v));
        source.points.push_back({v.v[0], v.v[1]});
    }
    try {
        x.contours = prismContours(source.spline, source.points);
    } catch (const std::invalid_argument& ex) {
        e.fail(keyword.loc, ex.what());
    }
    x.plane = Extrusion::Plane::XZ;
    x.fill = Extrusion::Fill::EvenOdd;
    x.prism = std::move(source);
    o.object.shape = std::move(x);
}

void readText(Evaluator& e, ObjectValue& o) {
    TextSource source;
    double thickness = 0;
    SourceLoc fontLoc;
    const Token first = e.peek();
    if (first.isWord("ttf") || first.isWord("internal")) {
        // POV-Ray: text { ttf "font" "string" thickness, offset }
        e.next();
        fontLoc = e.peek().loc;
        if (first.isWord("ttf")) source.font = e.stringExpr();
        else e.floatExpr(); // the internal font's number
        e.acceptSymbol(",");
        source.string = e.stringExpr();
        e.acceptSymbol(",");
        const SourceLoc thicknessLoc = e.peek().loc;
        thickness = [&] {
            FlagFor flag(e.countBeforeVector_); // `1 <0.1, 0, 0>`: the offset follows
            return e.floatExpr("the thickness");
        }();
        e.acceptSymbol(",");
        source.offset = e.vectorExpr("the offset <x, y>");
        if (first.isWord("internal")) {
            e.warnOnce("text-internal", first.loc, "POV-Ray's internal fonts are not supported; the text is left out");
            o.lightOnly = true;
            return;
        }
        if (thickness == 0) e.fail(thicknessLoc, "text thickness must not be zero");
    } else {
        // drt: text { font "file" string "text" thickness t [offset v] }
        if (!e.acceptWord("font")) e.failExpected(e.peek(), "'font' and the font file name in quotes");
        const Token font = e.next();
        if (font.kind != TokenKind::String) e.failExpected(font, "the font file name in quotes");
        fontLoc = font.loc;
        source.font = font.text;
        if (!e.acceptWord("string")) e.failExpected(e.peek(), "'string' and the text in quotes");
        const Token text = e.next();
        if (text.kind != TokenKind::String) e.failExpected(text, "the text in quotes");
        source.string = text.text;
        if (!e.acceptWord("thickness")) e.failExpected(e.peek(), "'thickness' and the depth of the letters");
        const SourceLoc thicknessLoc = e.peek().loc;
        thickness = e.floatExpr("the thickness");
        if (thickness == 0) {
            e.error(thicknessLoc, "text thickness must not be zero");
            thickness = 1;
        }
        if (e.acceptWord("offset")) source.offset = e.vectorExpr("the offset <x, y>");
    }
    // Fonts are found like POV-Ray's: beside the file, beside the scene, on
    // the include path, then in POV-Ray's include folder.
    std::vector<std::string> dirs{e.currentDir()};
    std::vector<std::string> more{e.mainDir()};
    more.insert(more.end(), e.options().includePaths.begin(), e.options().includePaths.end());
    more.push_back(kPovFontDir);
    for (const std::string& dir : more)
        if (std::find(dirs.begin(), dirs.end(), dir) == dirs.end()) dirs.push_back(dir);
    if (fs::path(source.font).is_absolute()) dirs = {""};
    source.fontPath = findFontFile(source.font, dirs);
    if (source.fontPath.empty()) {
        std::string looked;
        for (const std::string& d : dirs) looked += (looked.empty() ? "" : ", ") + (d.empty() ? "." : d);
        e.fail(fontLoc, "cannot find font '" + source.font + "' (looked in " + looked + ")");
    }
    try {
        o.object.shape = makeTextExtrusion(source, thickness);
    } catch (const FontError& ex) {
        e.fail(fontLoc, ex.what());
    }
}

} // namespace

template <>
const std::vector<std::string>& ShapeSyntax<Extrusion>::keywords() {
    static const std::vector<std::string> w{"prism", "text"};
    return w;
}

template <>
void ShapeSyntax<Extrusion>::read(Evaluator& e, const Token& keyword, ObjectValue& o) {
    if (keyword.text == "text") readText(e, o);
    else readPrism(e, keyword, o);
}

template <>
std::string ShapeSyntax<Extrusion>::head(const Extrusion& x, ShapeText& out) {
    if (x.text) {
        std::string text = "text { font " + writer::quoted(fontName(*x.text)) + " string " + writer::quoted(x.text->string) +
                           " thickness " + number(x.height2);
        if (!(x.text->offset == Vec3(0))) text += " offset " + vector(x.text->offset);
        return text;
    }
    PrismSource source;
    if (x.prism) {
        source = *x.prism;
    } else {
        // An outline with no source: each contour as a closed linear sub-polygon.
        if (x.plane != Extrusion::Plane::XZ || x.fill != Extrusion::Fill::EvenOdd)
            out.problems.insert("an extrusion with no prism or text source (written as an even-odd prism)");
        for (const auto& contour : x.contours) {
            source.points.insert(source.points.end(), contour.begin(), contour.end());
            if (!contour.empty()) source.points.push_back(contour.front());
        }
    }
    std::string text = std::string("prism { ") + (x.conic ? "conic_sweep " : "") + splineWord(source.spline) + " " +
                       number(x.height1) + ", " + number(x.height2) + ", " + std::to_string(source.points.size());
    const std::string pad(size_t(out.indent + 1) * 2, ' ');
    for (size_t i = 0; i < source.points.size(); ++i)
        text += std::string(",") + (i % 6 == 0 ? "\n" + pad : " ") + point(source.points[i]);
    if (x.open) text += "\n" + pad + "open";
    return text;
}

} // namespace drt::lang
