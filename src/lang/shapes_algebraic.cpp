// The algebraic shapes (POV-Ray's syntax):
//   quadric { <A, B, C>, <D, E, F>, <G, H, I>, J }
//   cubic { <20 coefficients> }   quartic { <35 coefficients> }
//   poly { order, <(order+1)(order+2)(order+3)/6 coefficients> }
//   superellipsoid { <e, n> }
// `sturm` is an object modifier (objects.cpp). Coefficients are written back
// so that each reads back exactly.
#include "lang/evaluator.h"
#include "lang/shape_syntax.h"
#include "lang/writer_detail.h"

#include <cmath>
#include <fmt/format.h>

namespace drt::lang {

using writer::number;
using writer::vector;

namespace {

const char* formName(Algebraic::Form form) {
    switch (form) {
    case Algebraic::Form::Quadric: return "quadric";
    case Algebraic::Form::Cubic: return "cubic";
    case Algebraic::Form::Quartic: return "quartic";
    case Algebraic::Form::Poly: return "poly";
    }
    return "poly";
}

// "<" float { "," float } ">": a coefficient list, whose length is checked
// (the list is then padded or cut).
std::vector<double> coefficientList(Evaluator& e, const std::string& what, size_t expected) {
    const Token open = e.expectSymbol("<", "to open the " + what);
    Evaluator::DepthGuard guard(e, open.loc);
    const bool saved = e.inVector_;
    e.inVector_ = true;
    std::vector<double> values;
    for (;;) {
        values.push_back(e.floatExpr("a coefficient"));
        if (e.acceptSymbol(",")) {
            if (!e.syntax().requireCommas && e.peek().is(">")) break;
            continue;
        }
        if (e.peek().is(">")) break;
        if (e.syntax().requireCommas) e.failExpected(e.peek(), "',' or '>' in the " + what);
    }
    e.expectSymbol(">", "to close the " + what);
    e.inVector_ = saved;
    if (values.size() != expected) {
        e.error(open.loc, fmt::format("{} needs {} numbers, found {}", what, expected, values.size()));
        values.resize(expected, 0.0);
    }
    return values;
}

} // namespace

template <>
const std::vector<std::string>& ShapeSyntax<Algebraic>::keywords() {
    static const std::vector<std::string> w{"quadric", "cubic", "quartic", "poly"};
    return w;
}

template <>
void ShapeSyntax<Algebraic>::read(Evaluator& e, const Token& keyword, ObjectValue& o) {
    const std::string& w = keyword.text;
    Algebraic a;
    if (w == "quadric") {
        a.form = Algebraic::Form::Quadric;
        a.order = 2;
        for (int i = 0; i < 3; ++i) {
            const Vec3 v = e.vectorExpr("a vector of three quadric coefficients");
            a.coefficients.insert(a.coefficients.end(), {v.x, v.y, v.z});
            e.comma("quadric's vector");
        }
        a.coefficients.push_back(e.floatExpr("the quadric's constant J"));
    } else {
        a.form = w == "cubic" ? Algebraic::Form::Cubic : w == "quartic" ? Algebraic::Form::Quartic : Algebraic::Form::Poly;
        a.order = w == "cubic" ? 3 : 4;
        if (a.form == Algebraic::Form::Poly) {
            const SourceLoc loc = e.peek().loc;
            // `poly { 4 <...> }` (no comma, as in objects/primitiv.pov): a number
            // before '<' is the order, not the left side of a comparison.
            e.countBeforeVector_ = true;
            double order = 0;
            try {
                order = e.floatExpr("the poly order");
            } catch (...) {
                e.countBeforeVector_ = false;
                throw;
            }
            e.countBeforeVector_ = false;
            if (order != std::floor(order)) {
                e.error(loc, "the poly order must be a whole number" + e.got(order));
                order = 2;
            }
            if (order < kMinAlgebraicOrder || order > kMaxAlgebraicOrder) {
                e.error(loc, fmt::format("poly order must be a whole number from 2 to 35, not {}", order));
                order = 2;
            }
            a.order = int(order);
            e.comma("poly order");
        }
        a.coefficients = coefficientList(e, std::string(formName(a.form)) + " coefficient list",
                                         size_t(algebraicCoefficientCount(a.form, a.order)));
    }
    bool constantOnly = true;
    for (const Monomial& m : algebraicTerms(a))
        if (m.x + m.y + m.z > 0) constantOnly = false;
    if (constantOnly) e.error(keyword.loc, w + " has no term in x, y or z: it defines no surface");
    o.object.shape = std::move(a);
}

template <>
std::string ShapeSyntax<Algebraic>::head(const Algebraic& a, ShapeText&) {
    std::vector<double> c = a.coefficients;
    if (a.form == Algebraic::Form::Quadric) {
        c.resize(10, 0.0); // a quadric has 10 coefficients
        return "quadric { " + vector({c[0], c[1], c[2]}) + ", " + vector({c[3], c[4], c[5]}) + ", " +
               vector({c[6], c[7], c[8]}) + ", " + number(c[9]);
    }
    std::string text;
    switch (a.form) {
    case Algebraic::Form::Cubic: text = "cubic { <"; break;
    case Algebraic::Form::Quartic: text = "quartic { <"; break;
    default: text = "poly { " + std::to_string(a.order) + ", <"; break;
    }
    for (size_t i = 0; i < c.size(); ++i) text += (i ? ", " : "") + number(c[i]);
    return text + ">" + (a.sturm ? " sturm" : "");
}

template <>
const std::vector<std::string>& ShapeSyntax<Superellipsoid>::keywords() {
    static const std::vector<std::string> w{"superellipsoid"};
    return w;
}

template <>
void ShapeSyntax<Superellipsoid>::read(Evaluator& e, const Token&, ObjectValue& o) {
    const SourceLoc loc = e.peek().loc;
    Superellipsoid s;
    if (e.peek().is("<")) {
        const std::vector<double> exponents = coefficientList(e, "superellipsoid exponents <e, n>", 2);
        s.e = exponents[0];
        s.n = exponents[1];
    } else {
        s.e = s.n = e.floatExpr("the superellipsoid exponents <e, n>");
    }
    if (!(s.e > 0) || !(s.n > 0)) {
        e.error(loc, "superellipsoid exponents must be positive");
        s.e = s.n = 1;
    }
    o.object.shape = s;
}

template <>
std::string ShapeSyntax<Superellipsoid>::head(const Superellipsoid& s, ShapeText&) {
    return "superellipsoid { <" + number(s.e) + ", " + number(s.n) + ">";
}

} // namespace drt::lang
