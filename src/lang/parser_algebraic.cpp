// The algebraic shapes of the .drt language (POV-Ray's syntax):
//   quadric { <A, B, C>, <D, E, F>, <G, H, I>, J }
//   cubic { <20 coefficients> [sturm] }
//   quartic { <35 coefficients> [sturm] }
//   poly { order, <(order+1)(order+2)(order+3)/6 coefficients> [sturm] }
//   superellipsoid { <e, n> }
#include "lang/parser.h"

#include <cmath>

namespace drt {

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

} // namespace

bool Parser::isAlgebraicWord(const std::string& word) {
    return word == "quadric" || word == "cubic" || word == "quartic" || word == "poly" || word == "superellipsoid";
}

// coefficients = "<" expression { "," expression } ">"; an error names the
// count expected when another count is given (the list is then padded or cut).
std::vector<double> Parser::coefficientList(const std::string& what, int expected) {
    const Token open = expect(TokenKind::LeftAngle, ("'<' to open the " + what).c_str());
    DepthGuard guard(*this, open.loc);
    std::vector<double> values;
    do {
        values.push_back(floatExpr("a coefficient"));
    } while (match(TokenKind::Comma));
    expect(TokenKind::RightAngle, ("',' or '>' in the " + what).c_str());
    if (int(values.size()) != expected) {
        error(open.loc, what + " needs " + std::to_string(expected) + " numbers, found " +
                            std::to_string(values.size()));
        values.resize(size_t(expected), 0.0);
    }
    return values;
}

void Parser::algebraicBody(const Token& keyword, ParsedObject& po) {
    const std::string& w = keyword.text;
    if (w == "superellipsoid") {
        const SourceLoc loc = current_.loc;
        const std::vector<double> exponents = coefficientList("superellipsoid exponents <e, n>", 2);
        Superellipsoid s;
        s.e = exponents[0];
        s.n = exponents[1];
        if (!(s.e > 0) || !(s.n > 0)) {
            error(loc, "superellipsoid exponents must be positive");
            s.e = s.n = 1;
        }
        po.object.shape = s;
        return;
    }
    Algebraic a;
    if (w == "quadric") {
        a.form = Algebraic::Form::Quadric;
        a.order = 2;
        for (int i = 0; i < 3; ++i) {
            const Vec3 v = vectorExpr("a vector of three quadric coefficients");
            a.coefficients.insert(a.coefficients.end(), {v.x, v.y, v.z});
            expect(TokenKind::Comma, "',' after the quadric's vector");
        }
        a.coefficients.push_back(floatExpr("the quadric's constant J"));
    } else {
        a.form = w == "cubic" ? Algebraic::Form::Cubic : w == "quartic" ? Algebraic::Form::Quartic : Algebraic::Form::Poly;
        a.order = w == "cubic" ? 3 : 4;
        if (a.form == Algebraic::Form::Poly) {
            const SourceLoc loc = current_.loc;
            a.order = intExpr("the poly order");
            if (a.order < kMinAlgebraicOrder || a.order > kMaxAlgebraicOrder) {
                error(loc, "poly order must be between 2 and 35, not " + std::to_string(a.order));
                a.order = 2;
            }
            expect(TokenKind::Comma, "',' after the poly order");
        }
        a.coefficients = coefficientList(std::string(formName(a.form)) + " coefficient list",
                                         algebraicCoefficientCount(a.form, a.order));
        a.sturm = matchWord("sturm");
    }
    bool constantOnly = true;
    for (const Monomial& m : algebraicTerms(a))
        if (m.x + m.y + m.z > 0) constantOnly = false;
    if (constantOnly) error(keyword.loc, w + " has no term in x, y or z: it defines no surface");
    po.object.shape = std::move(a);
}

} // namespace drt
