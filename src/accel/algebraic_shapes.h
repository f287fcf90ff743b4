// Ray crossings of POV-Ray's algebraic surfaces in object space, in double
// precision: polynomials in x, y, z (quadric, cubic, quartic, poly) and the
// superellipsoid. Same contract as shapes.h: every crossing of the line
// o + t d, sorted by t, with the outward (not normalised) gradient as normal.
#pragma once

#include "accel/shapes.h"
#include "scene/algebraic.h"

#include <vector>

namespace drt::accel {

// A polynomial ready for tracing: its non-zero terms and its order.
struct PolynomialSurface {
    int order = 0; // highest total degree of a non-zero term
    std::vector<Monomial> terms; // sorted by decreasing x, then y, then z exponent
    // The runs of `terms` with one (x, y) exponent pair, whose z powers
    // expandAlongLine sums before multiplying by the pair's x and y powers.
    // The steps that expandAlongLine takes are chosen for their sizes here, once:
    // series of small degree are summed by loops unrolled at compile time.
    using SeriesProduct = void (*)(const double* a, int na, const double* b, int nb, double* out);
    using SeriesTerm = void (*)(double coefficient, const double* zPowers, int z, double* sum);
    struct TermGroup {
        int x = 0, y = 0;
        int zDegree = 0; // the highest z exponent in the run
        int first = 0, end = 0;
        SeriesProduct xyProduct = nullptr;  // x power times y power: out = a b
        SeriesProduct accumulate = nullptr; // that times the z sum: out += a b
    };
    std::vector<TermGroup> groups;
    std::vector<SeriesTerm> termSteps; // by term: its z sum's share, the first of a run's setting the sum
    int degreeX = 0, degreeY = 0, degreeZ = 0; // the highest exponent of each variable
    // Set for ellipsoids (a quadric whose quadratic part is positive
    // definite): the box around the solid; other polynomials are unbounded.
    bool bounded = false;
    Vec3 lower, upper;
};

// Polynomials are unbounded: crossings are searched on the part of the line
// within this distance of the object-space origin.
inline constexpr double kAlgebraicReach = 1e6;

// Throws std::invalid_argument for a wrong coefficient count, non-finite
// coefficients or a polynomial with no non-constant term.
PolynomialSurface preparePolynomial(const Algebraic& algebraic);

// The coefficients of P(s) = f(p + s u) in powers of s, expanded exactly term
// by term: out[k] multiplies s^k, k = 0..order.
void expandAlongLine(const PolynomialSurface& surface, const Vec3& p, const Vec3& u, double* out);

Vec3 polynomialGradient(const PolynomialSurface& surface, const Vec3& p);

int intersectPolynomial(const PolynomialSurface& surface, const Vec3& o, const Vec3& d, Crossing* out, int capacity);
bool insidePolynomial(const PolynomialSurface& surface, const Vec3& p);

// The superellipsoid's implicit function, evaluated in a form that stays finite
// for tiny exponents: with m = max(|x|, |y|) and r = min / m,
// (|x|^a + |y|^a)^(b/a) = m^b (1 + r^a)^(b/a), a = 2/e, b = 2/n.
double superellipsoidFunction(double e, double n, const Vec3& p);
Vec3 superellipsoidGradient(double e, double n, const Vec3& p);

int intersectSuperellipsoid(double e, double n, const Vec3& o, const Vec3& d, Crossing* out, int capacity);

} // namespace drt::accel
