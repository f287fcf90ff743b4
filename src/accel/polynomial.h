// Real roots of small polynomials, for the analytic shapes' ray equations.
#pragma once

namespace drt::accel {

// Roots of a t^2 + b t + c = 0 in ascending order, using the cancellation-free
// form q = -(b + sign(b) sqrt(b^2 - 4ac)) / 2, t = q / a and c / q (Numerical
// Recipes 5.6). Returns the number of real roots (0 or 2; a double root counts
// twice). a == 0 falls back to the linear equation.
int solveQuadratic(double a, double b, double c, double roots[2]);

inline constexpr int kMaxPolynomialDegree = 35; // POV-Ray's largest poly order

// Real roots of sum_i coefficients[i] t^i (degree <= kMaxPolynomialDegree)
// inside [lo, hi], in ascending order; `roots` must hold degree + 1 values. Each root is isolated
// between consecutive roots of the derivative (found recursively), where the
// polynomial is monotonic, then refined by Newton steps safeguarded with
// bisection. Roots of even multiplicity (tangent grazes) without a sign change
// are not reported. Every root is found where the evaluated sign changes, so
// the count always agrees with the signs at lo and hi (odd count: they
// differ), which keeps CSG inside/outside parity right even where rounding
// blurs near-double roots.
int polynomialRootsInInterval(const double* coefficients, int degree, double lo, double hi, double* roots);

} // namespace drt::accel
