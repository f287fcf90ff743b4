// POV-Ray's algebraic shapes: quadric, cubic, quartic, poly and
// superellipsoid, read into the scene model's Algebraic and Superellipsoid.
// `sturm` is an object modifier (objects.cpp).
#include "pov/parser.h"

#include <fmt/format.h>

#include <cmath>

namespace drt::pov {

using Kind = PovValue::Kind;

// "<" float { [","] float } ">": POV-Ray's coefficient list, of any length.
std::vector<double> PovParser::coefficientList(const std::string& what, int expected) {
    const Tok open = expectSymbol("<", ("to open the " + what).c_str());
    const bool saved = inVector_;
    inVector_ = true;
    std::vector<double> values;
    while (!peek().is(">")) {
        values.push_back(floatExpr());
        acceptSymbol(",");
    }
    expectSymbol(">", ("to close the " + what).c_str());
    inVector_ = saved;
    if (int(values.size()) != expected)
        fail(open.loc, fmt::format("{} needs {} numbers, found {}", what, expected, values.size()));
    return values;
}

bool PovParser::isAlgebraicWord(const std::string& w) {
    return w == "quadric" || w == "cubic" || w == "quartic" || w == "poly" || w == "superellipsoid";
}

// After the shape's "{".
Shape PovParser::algebraicShape(const Tok& keyword) {
    const std::string& w = keyword.text;
    if (w == "superellipsoid") {
        const SourceLoc at = peek().loc;
        const PovValue v = expression();
        Superellipsoid s;
        if (v.kind == Kind::Float) s.e = s.n = v.number;
        else if (v.kind == Kind::Vector || v.kind == Kind::Color) s.e = v.v[0], s.n = v.v[1];
        else fail(at, std::string("superellipsoid needs a vector <e, n>, found a ") + kindName(v.kind));
        if (!(s.e > 0) || !(s.n > 0)) fail(at, "superellipsoid exponents must be positive");
        return s;
    }
    Algebraic a;
    if (w == "quadric") {
        a.form = Algebraic::Form::Quadric;
        a.order = 2;
        for (int i = 0; i < 3; ++i) {
            const Vec3 v = vectorExpr();
            a.coefficients.insert(a.coefficients.end(), {v.x, v.y, v.z});
            acceptSymbol(",");
        }
        a.coefficients.push_back(floatExpr());
        return a;
    }
    a.form = w == "cubic" ? Algebraic::Form::Cubic : w == "quartic" ? Algebraic::Form::Quartic : Algebraic::Form::Poly;
    a.order = w == "cubic" ? 3 : 4;
    if (a.form == Algebraic::Form::Poly) {
        const SourceLoc at = peek().loc;
        // `poly { 4 <...> }` (no comma, as in objects/primitiv.pov): a bare
        // number before '<' is the order, not the left side of a comparison.
        const Tok first = peek();
        double order = 0;
        if (first.kind == TokKind::Number) {
            next();
            if (peekOperator().is("<")) order = first.number;
            else {
                pushBack(first);
                order = floatExpr();
            }
        } else {
            order = floatExpr();
        }
        if (order != std::floor(order) || order < kMinAlgebraicOrder || order > kMaxAlgebraicOrder)
            fail(at, fmt::format("poly order must be a whole number from 2 to 35, not {}", order));
        a.order = int(order);
        acceptSymbol(",");
    }
    a.coefficients = coefficientList(w + " coefficient list", algebraicCoefficientCount(a.form, a.order));
    return a;
}

} // namespace drt::pov
