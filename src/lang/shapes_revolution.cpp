// The surfaces of revolution (POV-Ray's syntax):
//   lathe { [linear_spline | quadratic_spline | cubic_spline | bezier_spline] N, <r, y> ... }
//   sor { N, <r, y> ... }
// `open` and `sturm` are object modifiers (objects.cpp). The checks are POV-Ray's parse errors.
#include "lang/evaluator.h"
#include "lang/shape_syntax.h"
#include "lang/writer_detail.h"

#include <cmath>

namespace drt::lang {

using writer::number;

namespace {

const std::pair<const char*, Revolution::Spline> kSplines[] = {{"linear_spline", Revolution::Spline::Linear},
                                                               {"quadratic_spline", Revolution::Spline::Quadratic},
                                                               {"cubic_spline", Revolution::Spline::Cubic},
                                                               {"bezier_spline", Revolution::Spline::Bezier}};

const char* splineWord(Revolution::Spline s) {
    for (const auto& [word, spline] : kSplines)
        if (spline == s) return word;
    return "linear_spline";
}

} // namespace

template <>
const std::vector<std::string>& ShapeSyntax<Revolution>::keywords() {
    static const std::vector<std::string> w{"lathe", "sor"};
    return w;
}

template <>
void ShapeSyntax<Revolution>::read(Evaluator& e, const Token& keyword, ObjectValue& o) {
    Revolution rev;
    rev.kind = keyword.text == "sor" ? Revolution::Kind::Sor : Revolution::Kind::Lathe;
    if (rev.kind == Revolution::Kind::Lathe) {
        const Token t = e.peek();
        for (const auto& [word, spline] : kSplines)
            if (t.isWord(word)) {
                rev.spline = spline;
                e.next();
                break;
            }
    }
    const SourceLoc countLoc = e.peek().loc;
    e.countBeforeVector_ = true; // `4 <1, 2>`: the '<' after the count starts the first point
    double count = 0;
    try {
        count = e.floatExpr("the number of points");
    } catch (...) {
        e.countBeforeVector_ = false;
        throw;
    }
    e.countBeforeVector_ = false;
    if (count != std::floor(count) && e.syntax().strictValues)
        e.fail(countLoc, "the number of points must be a whole number" + e.got(count));
    const int minimum = minimumRevolutionPoints(rev.kind, rev.spline);
    if (!(count >= minimum))
        e.fail(countLoc, std::string(rev.kind == Revolution::Kind::Sor ? "a sor" : "this lathe spline") +
                             " needs at least " + std::to_string(minimum) + " points");
    const int n = e.countValue(count, countLoc, "point count", 0, double(e.diags().limits().meshTriangles));
    if (rev.spline == Revolution::Spline::Bezier && n % 4 != 0)
        e.fail(countLoc, "a bezier_spline lathe needs 4 points per segment (a multiple of 4)");
    for (int i = 0; i < n; ++i) {
        if (e.syntax().requireCommas) e.expectSymbol(",", i == 0 ? "after the number of points" : "between points");
        else e.acceptSymbol(",");
        const SourceLoc loc = e.peek().loc;
        const Value v = e.expression();
        Vec2 p;
        if (v.kind == Value::Kind::Vector && (v.size == 2 || !e.syntax().strictValues)) p = {v.v[0], v.v[1]};
        else if (v.kind == Value::Kind::Float && !e.syntax().strictValues) p = {v.number, v.number};
        else e.fail(loc, "expected a point <radius, height>, found " + kindName(v));
        if (rev.kind == Revolution::Kind::Sor) {
            if (p.x < 0) e.fail(loc, "a sor point needs a radius >= 0");
            if (i > 1 && i < n - 1 && !(p.y > rev.points.back().y))
                e.fail(loc, "sor heights must increase (this point is not above the one before)");
            if (i == n - 1 && !(p.y != rev.points[size_t(i) - 2].y))
                e.fail(loc, "the last sor point must not be level with the last but one");
            if (i == 2 && !(p.y != rev.points[0].y)) e.fail(loc, "the third sor point must not be level with the first");
        } else if (p.x < 0 && i > 0 && i < n - 1) {
            e.fail(loc, "a lathe point needs a radius >= 0 (only the end points may be negative)");
        }
        rev.points.push_back(p);
    }
    o.object.shape = std::move(rev);
}

template <>
std::string ShapeSyntax<Revolution>::head(const Revolution& r, ShapeText& out) {
    const bool sor = r.kind == Revolution::Kind::Sor;
    std::string text = sor ? "sor { " : std::string("lathe { ") + splineWord(r.spline) + " ";
    text += std::to_string(r.points.size());
    const std::string pad(size_t(out.indent + 1) * 2, ' ');
    for (size_t i = 0; i < r.points.size(); ++i) {
        text += i % 6 == 0 ? ",\n" + pad : ", ";
        text += "<";
        text += number(r.points[i].x);
        text += ", ";
        text += number(r.points[i].y);
        text += ">";
    }
    if (r.sturm) text += " sturm";
    if (sor && r.open) text += "\n" + pad + "open";
    return text;
}

} // namespace drt::lang
