// POV-Ray's lathe and sor objects -> the scene model's Revolution. `open` and
// `sturm` are object modifiers (objects.cpp).
#include "pov/parser.h"

#include <algorithm>
#include <cmath>

namespace drt::pov {

// lathe { [spline] N, <r, y> ... } or sor { N, <r, y> ... } after '{'. Points
// are UV vectors; the checks are POV-Ray's parse errors.
Revolution PovParser::revolutionShape(const Tok& keyword) {
    Revolution rev;
    using S = Revolution::Spline;
    rev.kind = keyword.text == "sor" ? Revolution::Kind::Sor : Revolution::Kind::Lathe;
    if (rev.kind == Revolution::Kind::Lathe) {
        const Tok t = peek();
        if (t.isWord("linear_spline")) rev.spline = S::Linear, next();
        else if (t.isWord("quadratic_spline")) rev.spline = S::Quadratic, next();
        else if (t.isWord("cubic_spline")) rev.spline = S::Cubic, next();
        else if (t.isWord("bezier_spline")) rev.spline = S::Bezier, next();
    }
    const SourceLoc countLoc = peek().loc;
    const double count = [&] {
        countBeforeVector_ = true;
        try {
            const double v = floatExpr();
            countBeforeVector_ = false;
            return v;
        } catch (...) {
            countBeforeVector_ = false;
            throw;
        }
    }();
    const int minimum = minimumRevolutionPoints(rev.kind, rev.spline);
    if (!(count >= minimum))
        fail(countLoc, std::string(rev.kind == Revolution::Kind::Sor ? "a sor" : "this lathe spline") +
                           " needs at least " + std::to_string(minimum) + " points");
    const int n = countValue(count, countLoc, "point count", 0, double(diags_.limits().meshTriangles));
    if (rev.spline == S::Bezier && n % 4 != 0)
        fail(countLoc, "a bezier_spline lathe needs 4 points per segment (a multiple of 4)");
    for (int i = 0; i < n; ++i) {
        acceptSymbol(",");
        const SourceLoc loc = peek().loc;
        const Vec3 v = vectorExpr();
        const Vec2 p{v.x, v.y};
        if (rev.kind == Revolution::Kind::Sor) {
            if (p.x < 0) fail(loc, "a sor point needs a radius >= 0");
            if (i > 1 && i < n - 1 && !(p.y > rev.points.back().y))
                fail(loc, "sor heights must increase (this point is not above the one before)");
            if ((i == n - 1 && !(p.y != rev.points[size_t(i) - 2].y)) || (i == 2 && !(p.y != rev.points[0].y)))
                fail(loc, "sor heights must increase (a control point is level with its neighbour's neighbour)");
        } else if (p.x < 0 && i > 0 && i < n - 1) {
            fail(loc, "a lathe point needs a radius >= 0 (only the end points may be negative)");
        }
        rev.points.push_back(p);
    }
    return rev;
}

} // namespace drt::pov
