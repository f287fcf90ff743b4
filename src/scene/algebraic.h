// POV-Ray's algebraic surfaces in the scene model: polynomials in x, y, z
// (quadric, cubic, quartic, poly) and the superellipsoid. Inside is where the
// defining function is negative.
#pragma once

#include "core/vec.h"

#include <vector>

namespace drt {

// sum of c * x^i y^j z^k = 0 over every term with i + j + k <= order.
struct Algebraic {
    enum class Form { Quadric, Cubic, Quartic, Poly }; // the keyword it was written with
    Form form = Form::Poly;
    int order = 2; // Poly only: the cubic, quartic and quadric forms have order 3, 4 and 2
    // As written. Quadric: A..J of A x^2 + B y^2 + C z^2 + D xy + E xz + F yz +
    // G x + H y + I z + J. Other forms: one coefficient per term in POV-Ray's
    // order (algebraicTerms below), algebraicTermCount(order) of them.
    std::vector<double> coefficients;
    bool sturm = false; // POV-Ray's root-finder choice; kept for round trips only
    // A polynomial surface may reach infinity (POV-Ray bounds it only by bounded_by).
    bool bounds(Vec3&, Vec3&) const { return false; }
    bool closedSolid() const { return false; }
    bool operator==(const Algebraic& o) const {
        return form == o.form && order == o.order && coefficients == o.coefficients;
    }
};

// superellipsoid { <e, n> }:
// (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) - 1 = 0, inside the cube [-1, 1]^3.
struct Superellipsoid {
    double e = 1; // east-west exponent
    double n = 1; // north-south exponent
    bool bounds(Vec3& lower, Vec3& upper) const {
        lower = Vec3(-1), upper = Vec3(1);
        return true;
    }
    bool closedSolid() const { return true; }
    bool operator==(const Superellipsoid&) const = default;
};

inline constexpr int kMinAlgebraicOrder = 2;
inline constexpr int kMaxAlgebraicOrder = 35; // POV-Ray's limit for poly

// Number of terms of a polynomial of this order in three variables:
// (order + 1)(order + 2)(order + 3) / 6.
inline int algebraicTermCount(int order) { return (order + 1) * (order + 2) * (order + 3) / 6; }

struct Monomial {
    int x = 0, y = 0, z = 0; // exponents
    double coefficient = 0;
};

// The exponents of term `index` in POV-Ray's order: (i, j, k) in decreasing
// lexicographic order over i + j + k <= order, so for order 2
// x^2, xy, xz, x, y^2, yz, y, z^2, z, 1.
void algebraicTermExponents(int order, int index, int& i, int& j, int& k);

// The non-zero terms of the polynomial (any form).
std::vector<Monomial> algebraicTerms(const Algebraic& a);

// The value of the polynomial at (x, y, z), summed term by term.
double evaluateAlgebraic(const std::vector<Monomial>& terms, double x, double y, double z);

// The number of coefficients a form takes: 10, 20, 35, or the term count.
int algebraicCoefficientCount(Algebraic::Form form, int order);

} // namespace drt
