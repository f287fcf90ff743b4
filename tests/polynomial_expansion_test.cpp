// The algebraic surfaces' arithmetic along a ray (accel/algebraic_shapes.h,
// accel/polynomial.h) against the code as first written: expandAlongLine with
// rows of full width and a group's sums recomputed from zero, polynomialGradient
// with a power computed per factor, and the root isolation with loops of
// run-time length. Steps chosen per surface and loops of fixed length must give
// every value to the bit.
#include "accel/algebraic_shapes.h"
#include "accel/polynomial.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <random>
#include <vector>

namespace drt::accel {
namespace {

// ---------------------------------------------------------------- as first written

void firstLinearPowers(double p, double u, int order, double* rows) {
    const int width = order + 1;
    std::fill(rows, rows + width * width, 0.0);
    rows[0] = 1;
    for (int i = 1; i <= order; ++i) {
        const double* prev = rows + (i - 1) * width;
        double* row = rows + i * width;
        for (int k = 0; k <= i; ++k) row[k] = (k < i ? prev[k] * p : 0) + (k > 0 ? prev[k - 1] * u : 0);
    }
}

void firstMultiplyAdd(const double* a, int na, const double* b, int nb, double scale, double* out) {
    for (int i = 0; i <= na; ++i) {
        if (a[i] == 0) continue;
        const double ai = scale * a[i];
        for (int j = 0; j <= nb; ++j) out[i + j] += ai * b[j];
    }
}

void firstExpandAlongLine(const PolynomialSurface& surface, const Vec3& p, const Vec3& u, double* out) {
    const int order = surface.order, width = order + 1;
    std::vector<double> rows(size_t(width * width * 3 + width * 2));
    double* xs = rows.data();
    double* ys = xs + width * width;
    double* zs = ys + width * width;
    double* group = zs + width * width;
    double* xy = group + width;
    firstLinearPowers(p.x, u.x, order, xs);
    firstLinearPowers(p.y, u.y, order, ys);
    firstLinearPowers(p.z, u.z, order, zs);
    std::fill(out, out + width, 0.0);
    const auto& terms = surface.terms;
    for (size_t start = 0; start < terms.size();) {
        const int i = terms[start].x, j = terms[start].y;
        std::fill(group, group + width, 0.0);
        int zDegree = 0;
        size_t end = start;
        for (; end < terms.size() && terms[end].x == i && terms[end].y == j; ++end) {
            const Monomial& m = terms[end];
            zDegree = std::max(zDegree, m.z);
            for (int k = 0; k <= m.z; ++k) group[k] += m.coefficient * zs[m.z * width + k];
        }
        std::fill(xy, xy + width, 0.0);
        firstMultiplyAdd(xs + i * width, i, ys + j * width, j, 1.0, xy);
        firstMultiplyAdd(xy, i + j, group, zDegree, 1.0, out);
        start = end;
    }
}

double integerPower(double v, int e) {
    double r = 1;
    for (int i = 0; i < e; ++i) r *= v;
    return r;
}

Vec3 firstGradient(const PolynomialSurface& surface, const Vec3& p) {
    Vec3 g;
    for (const Monomial& m : surface.terms) {
        const double px = integerPower(p.x, m.x), py = integerPower(p.y, m.y), pz = integerPower(p.z, m.z);
        if (m.x > 0) g.x += m.coefficient * m.x * integerPower(p.x, m.x - 1) * py * pz;
        if (m.y > 0) g.y += m.coefficient * m.y * px * integerPower(p.y, m.y - 1) * pz;
        if (m.z > 0) g.z += m.coefficient * m.z * px * py * integerPower(p.z, m.z - 1);
    }
    return g;
}

double firstEvaluate(const double* c, int degree, double t) {
    double v = c[degree];
    for (int i = degree - 1; i >= 0; --i) v = v * t + c[i];
    return v;
}

// Newton steps safeguarded by bisection, each step's evaluation at the top of
// the loop (after the last step, one evaluation more than needed).
double firstRefine(const double* c, const double* derivative, int degree, double lo, double hi, double fLo) {
    if (fLo > 0) std::swap(lo, hi);
    double t = 0.5 * (lo + hi), step = std::fabs(hi - lo), stepBefore = step;
    for (int iteration = 0;; ++iteration) {
        const double f = firstEvaluate(c, degree, t), slope = firstEvaluate(derivative, degree - 1, t);
        if (iteration > 0) (f < 0 ? lo : hi) = t;
        if (iteration == 200 || f == 0) return t;
        const bool outside = ((t - hi) * slope - f) * ((t - lo) * slope - f) > 0;
        const bool bisect = outside || std::fabs(2 * f) > std::fabs(stepBefore * slope);
        stepBefore = step;
        step = bisect ? 0.5 * (hi - lo) : f / slope;
        t = bisect ? lo + step : t - step;
        if (std::fabs(step) <= 1e-15 * std::fmax(1.0, std::fabs(t))) return t;
    }
}

// Degrees 1 and 2 (closed forms) are as they were: the library's own.
int firstRoots(const double* c, int degree, double lo, double hi, double* roots) {
    while (degree > 0 && c[degree] == 0) --degree;
    if (degree <= 2) return polynomialRootsInInterval(c, degree, lo, hi, roots);
    if (degree > kMaxPolynomialDegree) return 0;
    // The critical points (roots of the derivative) split [lo, hi] into
    // monotonic pieces; a piece whose ends' signs differ holds one root.
    std::vector<double> slopeCoefficients, edges(size_t(degree) + 1);
    for (int i = 1; i <= degree; ++i) slopeCoefficients.push_back(i * c[i]);
    edges[0] = lo;
    const int pieces = 1 + firstRoots(slopeCoefficients.data(), degree - 1, lo, hi, edges.data() + 1);
    edges[size_t(pieces)] = hi;
    std::vector<double> values;
    for (int k = 0; k <= pieces; ++k) values.push_back(firstEvaluate(c, degree, edges[size_t(k)]));
    int count = 0;
    for (int k = 0; k < pieces; ++k)
        if ((values[size_t(k)] < 0) != (values[size_t(k) + 1] < 0))
            roots[count++] =
                firstRefine(c, slopeCoefficients.data(), degree, edges[size_t(k)], edges[size_t(k) + 1], values[size_t(k)]);
    return count;
}

// ---------------------------------------------------------------- cases

bool sameBits(double a, double b) { return std::bit_cast<uint64_t>(a) == std::bit_cast<uint64_t>(b); }

// A value for a point or a direction: mostly random, sometimes a signed zero
// (a line along an axis, a point on a plane of symmetry), a small integer or a
// large value.
double coordinate(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1, 1);
    switch (rng() % 10) {
    case 0: return 0.0;
    case 1: return -0.0;
    case 2: return double(int(rng() % 5) - 2);
    case 3: return u(rng) * 1e6;
    default: return u(rng) * 3;
    }
}

// A polynomial of the given order: every coefficient random, many of them zero,
// magnitudes over several decades; some with one term only or only even powers.
Algebraic randomPolynomial(std::mt19937_64& rng, int order) {
    std::uniform_real_distribution<double> u(-1, 1);
    Algebraic a;
    a.order = order;
    const double density = (rng() % 4 + 1) / 4.0;
    const bool even = rng() % 5 == 0;
    const int count = algebraicTermCount(order);
    for (int t = 0; t < count; ++t) {
        int i, j, k;
        algebraicTermExponents(order, t, i, j, k);
        const bool kept = (rng() % 1000) < density * 1000 && (!even || (i % 2 == 0 && j % 2 == 0 && k % 2 == 0));
        a.coefficients.push_back(kept ? u(rng) * std::pow(10.0, double(int(rng() % 7) - 3)) : 0.0);
    }
    if (rng() % 6 == 0) { // one term only
        const int keep = int(rng() % uint64_t(count));
        for (int t = 0; t < count; ++t)
            if (t != keep) a.coefficients[size_t(t)] = 0;
    }
    a.coefficients[0] = a.coefficients[0] == 0 ? 1 : a.coefficients[0]; // x^order: the order is reached
    return a;
}

TEST(PolynomialExpansion, CoefficientsGradientsAndRootsAreThoseAsFirstWrittenToTheBit) {
    std::mt19937_64 rng(41);
    std::uniform_real_distribution<double> u(-1, 1);
    // POV-Ray's torus.pov: a quartic with major radius sqrt(40), minor radius sqrt(12).
    Algebraic torus;
    torus.form = Algebraic::Form::Quartic;
    torus.coefficients = {1, 0, 0, 0, 2, 0, 0, 2, 0, -104, 0, 0, 0, 0, 0, 0, 0, 0,
                          0, 0, 1, 0, 0, 2, 0, 56,   0, 0, 0, 0, 1, 0, -104, 0, 784};
    int lines = 0, roots = 0, nonZero = 0;
    for (int shape = 0; shape < 600; ++shape) {
        const int order = shape % 5 == 4 ? 5 + int(rng() % 8) : 2 + shape % 4; // up to 12: past the stack rows
        const Algebraic a = shape == 0 ? torus : randomPolynomial(rng, order);
        const PolynomialSurface surface = preparePolynomial(a);
        for (int line = 0; line < 40; ++line, ++lines) {
            const Vec3 p(coordinate(rng), coordinate(rng), coordinate(rng));
            Vec3 dir(coordinate(rng), coordinate(rng), coordinate(rng));
            if (line % 4 == 0) dir = Vec3(u(rng), u(rng), u(rng));
            double got[kMaxPolynomialDegree + 1], expected[kMaxPolynomialDegree + 1];
            expandAlongLine(surface, p, dir, got);
            firstExpandAlongLine(surface, p, dir, expected);
            for (int k = 0; k <= surface.order; ++k) {
                ASSERT_TRUE(sameBits(got[k], expected[k]))
                    << "shape " << shape << " line " << line << " s^" << k << ": " << got[k] << " " << expected[k];
                nonZero += got[k] != 0;
            }
            const Vec3 g = polynomialGradient(surface, p), gExpected = firstGradient(surface, p);
            ASSERT_TRUE(sameBits(g.x, gExpected.x) && sameBits(g.y, gExpected.y) && sameBits(g.z, gExpected.z))
                << "shape " << shape << " line " << line;
            // The roots of the expansion, over a window around the line's point
            // and over a long one (more pieces, more bisection).
            const double half = line % 2 == 0 ? 4 : 1e6;
            double r[kMaxPolynomialDegree + 1], rExpected[kMaxPolynomialDegree + 1];
            const int n = polynomialRootsInInterval(got, surface.order, -half, half, r);
            ASSERT_EQ(n, firstRoots(expected, surface.order, -half, half, rExpected));
            for (int i = 0; i < n; ++i) ASSERT_TRUE(sameBits(r[i], rExpected[i]));
            roots += n;
        }
    }
    // Random polynomials of every degree up to the largest, not from a surface.
    for (int trial = 0; trial < 20000; ++trial) {
        const int degree = 1 + int(rng() % uint64_t(trial % 2 == 0 ? 4 : kMaxPolynomialDegree));
        double c[kMaxPolynomialDegree + 1];
        for (int k = 0; k <= degree; ++k) c[k] = rng() % 4 == 0 ? 0.0 : u(rng) * std::pow(10.0, double(int(rng() % 5) - 2));
        double lo = u(rng) * 10, hi = u(rng) * 10;
        if (lo > hi) std::swap(lo, hi);
        double r[kMaxPolynomialDegree + 1], rExpected[kMaxPolynomialDegree + 1];
        const int n = polynomialRootsInInterval(c, degree, lo, hi, r);
        ASSERT_EQ(n, firstRoots(c, degree, lo, hi, rExpected)) << "trial " << trial;
        for (int i = 0; i < n; ++i) ASSERT_TRUE(sameBits(r[i], rExpected[i])) << "trial " << trial;
        roots += n;
    }
    EXPECT_EQ(lines, 24000);
    EXPECT_GT(roots, 20000);
    EXPECT_GT(nonZero, 50000);
}

} // namespace
} // namespace drt::accel
