#include "accel/polynomial.h"

#include <algorithm>
#include <cmath>

namespace drt::accel {

int solveQuadratic(double a, double b, double c, double roots[2]) {
    if (a == 0) {
        if (b == 0) return 0;
        roots[0] = roots[1] = -c / b;
        return 2;
    }
    const double discriminant = b * b - 4 * a * c;
    if (discriminant < 0) return 0;
    const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
    double t0 = q / a;
    double t1 = q != 0 ? c / q : t0; // q == 0 only when b == 0 and c == 0: double root at 0
    if (t0 > t1) std::swap(t0, t1);
    roots[0] = t0;
    roots[1] = t1;
    return 2;
}

namespace {

// The loops below take their degree from the template when it is not negative:
// cubics and quartics (every quartic's derivative is a cubic) get loops of fixed
// length, unrolled; the operations are the same.
template <int kDegree>
double evaluate(const double* c, int degreeIn, double t) {
    const int degree = kDegree < 0 ? degreeIn : kDegree;
    double v = c[degree];
    for (int i = degree - 1; i >= 0; --i) v = v * t + c[i];
    return v;
}

// The root of a polynomial that is monotonic on [lo, hi] with f(lo), f(hi) of
// opposite signs: Newton steps safeguarded as in Numerical Recipes' rtsafe
// (9.4): a bisection instead whenever the Newton step would leave the bracket
// or would not at least halve the step before last, so the bracket shrinks
// geometrically even far from the root, where Newton on a degree-n
// polynomial gains only a factor 1 - 1/n per step.
template <int kDegree>
double refineBracketedRoot(const double* c, const double* derivative, int degree, double lo, double hi, double fLo) {
    if (fLo > 0) std::swap(lo, hi); // from here f(lo) < 0 < f(hi), lo may exceed hi
    double t = 0.5 * (lo + hi);
    double step = std::fabs(hi - lo), stepBefore = step;
    double f = evaluate<kDegree>(c, degree, t), slope = evaluate<kDegree - 1>(derivative, degree - 1, t);
    for (int iteration = 0; iteration < 200; ++iteration) {
        if (f == 0) return t;
        const bool leaves = ((t - hi) * slope - f) * ((t - lo) * slope - f) > 0;
        const bool slow = std::fabs(2 * f) > std::fabs(stepBefore * slope);
        stepBefore = step;
        if (leaves || slow) {
            step = 0.5 * (hi - lo);
            t = lo + step;
        } else {
            step = f / slope;
            t -= step;
        }
        if (std::fabs(step) <= 1e-15 * std::max(1.0, std::fabs(t))) return t; // as fmax: 1 where |t| is NaN
        f = evaluate<kDegree>(c, degree, t);
        slope = evaluate<kDegree - 1>(derivative, degree - 1, t);
        if (f < 0) lo = t;
        else hi = t;
    }
    return t;
}

// polynomialRootsInInterval from degree 3 on: c[degree] != 0.
template <int kDegree>
int rootsByCriticalPoints(const double* c, int degreeIn, double lo, double hi, double* roots) {
    const int degree = kDegree < 0 ? degreeIn : kDegree;
    double derivative[kDegree < 0 ? kMaxPolynomialDegree : kDegree];
    if constexpr (kDegree < 0) std::fill(derivative, derivative + kMaxPolynomialDegree, 0.0); // for -Wmaybe-uninitialized
    for (int i = 1; i <= degree; ++i) derivative[i - 1] = i * c[i];
    // Critical points split [lo, hi] into monotonic pieces.
    double edges[kMaxPolynomialDegree + 2];
    edges[0] = lo;
    const int criticalCount = polynomialRootsInInterval(derivative, degree - 1, lo, hi, edges + 1);
    edges[criticalCount + 1] = hi;
    // Signs only (zero counts as positive): a root is reported where the sign
    // changes, never for an exact zero at a critical point that the surface
    // only touches.
    int count = 0;
    double fLo = evaluate<kDegree>(c, degree, edges[0]);
    for (int piece = 0; piece <= criticalCount; ++piece) {
        const double a = edges[piece], b = edges[piece + 1];
        const double fHi = evaluate<kDegree>(c, degree, b);
        if ((fLo < 0) != (fHi < 0)) roots[count++] = refineBracketedRoot<kDegree>(c, derivative, degree, a, b, fLo);
        fLo = fHi;
    }
    return count;
}

} // namespace

int polynomialRootsInInterval(const double* c, int degree, double lo, double hi, double* roots) {
    while (degree > 0 && c[degree] == 0) --degree;
    if (degree <= 0) return 0;
    if (degree == 1) {
        const double t = -c[0] / c[1];
        if (t >= lo && t <= hi) {
            roots[0] = t;
            return 1;
        }
        return 0;
    }
    if (degree == 2) {
        // Closed form (cancellation-free, as solveQuadratic). A double or
        // complex pair does not change sign: no root, as below.
        const double a = c[2], b = c[1], c0 = c[0];
        const double discriminant = b * b - 4 * a * c0;
        if (!(discriminant > 0)) return 0;
        const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
        double t0 = q / a, t1 = c0 / q;
        if (t0 > t1) std::swap(t0, t1);
        int count = 0;
        if (t0 >= lo && t0 <= hi) roots[count++] = t0;
        if (t1 >= lo && t1 <= hi) roots[count++] = t1;
        return count;
    }
    if (degree > kMaxPolynomialDegree) return 0;
    switch (degree) {
    case 3: return rootsByCriticalPoints<3>(c, degree, lo, hi, roots);
    case 4: return rootsByCriticalPoints<4>(c, degree, lo, hi, roots);
    default: return rootsByCriticalPoints<-1>(c, degree, lo, hi, roots);
    }
}

} // namespace drt::accel
