// The surfaces of revolution of the .drt language (POV-Ray's syntax):
//   lathe { [linear_spline | quadratic_spline | cubic_spline | bezier_spline] N, <r, y> ... [sturm] }
//   sor { N, <r, y> ... [open] [sturm] }
// (`open` is read with the object modifiers.)
#include "lang/parser.h"

namespace drt {

bool Parser::isRevolutionWord(const std::string& word) { return word == "lathe" || word == "sor"; }

void Parser::revolutionBody(const Token& keyword, ParsedObject& po) {
    Revolution rev;
    using S = Revolution::Spline;
    rev.kind = keyword.text == "sor" ? Revolution::Kind::Sor : Revolution::Kind::Lathe;
    if (rev.kind == Revolution::Kind::Lathe && check(TokenKind::Identifier)) {
        const std::string& w = current_.text;
        if (w == "linear_spline" || w == "quadratic_spline" || w == "cubic_spline" || w == "bezier_spline") {
            rev.spline = w == "linear_spline"      ? S::Linear
                         : w == "quadratic_spline" ? S::Quadratic
                         : w == "cubic_spline"     ? S::Cubic
                                                   : S::Bezier;
            advance();
        }
    }
    const SourceLoc countLoc = current_.loc;
    const int count = intExpr("the number of points");
    const int minimum = minimumRevolutionPoints(rev.kind, rev.spline);
    if (count < minimum)
        fail(countLoc, std::string(rev.kind == Revolution::Kind::Sor ? "a sor" : "this lathe spline") +
                           " needs at least " + std::to_string(minimum) + " points");
    if (rev.spline == S::Bezier && count % 4 != 0)
        fail(countLoc, "a bezier_spline lathe needs 4 points per segment (a multiple of 4)");
    for (int i = 0; i < count; ++i) {
        expect(TokenKind::Comma, i == 0 ? "',' after the number of points" : "',' between points");
        const SourceLoc loc = current_.loc;
        Value v = expression();
        const VectorValue* p = std::get_if<VectorValue>(&v);
        if (!p || p->size != 2) fail(loc, "expected a point <radius, height>, found " + kindName(v));
        const Vec2 point{p->c[0], p->c[1]};
        // POV-Ray's checks: no negative radius (a lathe's end points may be),
        // and a sor's heights increase from the second point to the last but one.
        if (rev.kind == Revolution::Kind::Sor) {
            if (point.x < 0) fail(loc, "a sor point needs a radius >= 0");
            if (i > 1 && i < count - 1 && !(point.y > rev.points.back().y))
                fail(loc, "sor heights must increase (this point is not above the one before)");
            if (i == count - 1 && !(point.y != rev.points[size_t(i) - 2].y))
                fail(loc, "the last sor point must not be level with the last but one");
            if (i == 2 && !(point.y != rev.points[0].y))
                fail(loc, "the third sor point must not be level with the first");
        } else if (point.x < 0 && i > 0 && i < count - 1) {
            fail(loc, "a lathe point needs a radius >= 0 (only the end points may be negative)");
        }
        rev.points.push_back(point);
    }
    if (matchWord("sturm")) rev.sturm = true;
    po.object.shape = std::move(rev);
}

} // namespace drt
