#include "accel/algebraic_shapes.h"

#include "accel/polynomial.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace drt::accel {

// ---------------------------------------------------------------- polynomials

namespace {

// f = x^T M x + b.x + c with M positive definite is an ellipsoid (or empty):
// with centre m = -M^-1 b / 2 and k = -f(m) = -(b.m / 2 + c), the surface is
// (x - m)^T M (x - m) = k, which spans m_i +- sqrt(k (M^-1)_ii) along axis i.
void ellipsoidBounds(PolynomialSurface& s) {
    double M[3][3] = {}, b[3] = {}, c = 0;
    for (const Monomial& t : s.terms) {
        const int e[3] = {t.x, t.y, t.z};
        int first = -1, second = -1;
        for (int axis = 0; axis < 3; ++axis)
            for (int k = 0; k < e[axis]; ++k) (first < 0 ? first : second) = axis;
        if (first < 0) c += t.coefficient;
        else if (second < 0) b[first] += t.coefficient;
        else if (first == second) M[first][first] += t.coefficient;
        else M[first][second] = M[second][first] = M[first][second] + 0.5 * t.coefficient;
    }
    const double minor2 = M[0][0] * M[1][1] - M[0][1] * M[1][0];
    double inverse[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
            inverse[i][j] = M[i1][j1] * M[i2][j2] - M[i1][j2] * M[i2][j1]; // cofactor, transposed
        }
    const double det = M[0][0] * inverse[0][0] + M[0][1] * inverse[1][0] + M[0][2] * inverse[2][0];
    if (!(M[0][0] > 0 && minor2 > 0 && det > 0)) return;
    for (auto& row : inverse)
        for (double& v : row) v /= det;
    Vec3 centre;
    for (int i = 0; i < 3; ++i) centre[i] = -0.5 * (inverse[i][0] * b[0] + inverse[i][1] * b[1] + inverse[i][2] * b[2]);
    const double k = -(0.5 * (b[0] * centre.x + b[1] * centre.y + b[2] * centre.z) + c);
    if (!std::isfinite(k) || !isFinite(centre)) return;
    Vec3 extent;
    for (int i = 0; i < 3; ++i) extent[i] = std::sqrt(std::max(0.0, k * inverse[i][i]));
    // A margin for the rounding of the computation above.
    extent = extent * (1 + 1e-9) + Vec3(1e-12 * (maxComponent(abs(centre)) + maxComponent(extent)));
    s.bounded = true;
    s.lower = centre - extent;
    s.upper = centre + extent;
}

} // namespace

PolynomialSurface preparePolynomial(const Algebraic& a) {
    const int order = a.form == Algebraic::Form::Cubic     ? 3
                      : a.form == Algebraic::Form::Quartic ? 4
                      : a.form == Algebraic::Form::Quadric ? 2
                                                           : a.order;
    if (order < kMinAlgebraicOrder || order > kMaxAlgebraicOrder)
        throw std::invalid_argument("poly order must be between 2 and 35, not " + std::to_string(order));
    Algebraic normalised = a;
    normalised.order = order;
    const int expected = algebraicCoefficientCount(a.form, order);
    if (int(a.coefficients.size()) != expected)
        throw std::invalid_argument("algebraic surface needs " + std::to_string(expected) + " coefficients, not " +
                                    std::to_string(a.coefficients.size()));
    for (double c : a.coefficients)
        if (!std::isfinite(c)) throw std::invalid_argument("algebraic surface coefficients must be finite");
    PolynomialSurface s;
    s.terms = algebraicTerms(normalised);
    // Grouped by (x, y) exponents so that expandAlongLine sums each group's z
    // polynomial once.
    std::sort(s.terms.begin(), s.terms.end(), [](const Monomial& l, const Monomial& r) {
        return l.x != r.x ? l.x > r.x : l.y != r.y ? l.y > r.y : l.z > r.z;
    });
    for (const Monomial& m : s.terms) s.order = std::max(s.order, m.x + m.y + m.z);
    if (s.order == 0) throw std::invalid_argument("algebraic surface has no non-constant term");
    if (s.order == 2) ellipsoidBounds(s);
    return s;
}

namespace {

// (p + s u)^i for i = 0..order as coefficient rows: row i, column k holds the
// coefficient of s^k, C(i, k) p^(i-k) u^k, built by repeated multiplication.
void linearPowers(double p, double u, int order, double* rows) {
    const int width = order + 1;
    std::fill(rows, rows + width * width, 0.0);
    rows[0] = 1;
    for (int i = 1; i <= order; ++i) {
        const double* prev = rows + (i - 1) * width;
        double* row = rows + i * width;
        for (int k = 0; k <= i; ++k) row[k] = (k < i ? prev[k] * p : 0) + (k > 0 ? prev[k - 1] * u : 0);
    }
}

// out[0..na+nb] += scale * a[0..na] * b[0..nb]
void multiplyAdd(const double* a, int na, const double* b, int nb, double scale, double* out) {
    for (int i = 0; i <= na; ++i) {
        if (a[i] == 0) continue;
        const double ai = scale * a[i];
        for (int j = 0; j <= nb; ++j) out[i + j] += ai * b[j];
    }
}

double integerPower(double v, int e) {
    double r = 1;
    for (int i = 0; i < e; ++i) r *= v;
    return r;
}

// expandAlongLine's rows past kStackOrder, kept per thread (accel/thread_scratch.h).
struct AlgebraicScratch {
    std::vector<double> heap;
};

} // namespace

std::unique_ptr<InstalledScratch> installAlgebraicScratch() { return ThreadScratch<AlgebraicScratch>::install(); }

void expandAlongLine(const PolynomialSurface& surface, const Vec3& p, const Vec3& u, double* out) {
    const int order = surface.order, width = order + 1;
    const size_t size = size_t(width * width * 3 + width * 2);
    constexpr int kStackOrder = 8;
    double stack[(kStackOrder + 1) * (kStackOrder + 1) * 3 + (kStackOrder + 1) * 2];
    std::vector<double>& heap = ThreadScratch<AlgebraicScratch>::get().heap;
    if (order > kStackOrder && heap.size() < size) heap.resize(size);
    double* xs = order > kStackOrder ? heap.data() : stack;
    double* ys = xs + width * width;
    double* zs = ys + width * width;
    double* group = zs + width * width; // sum of c z-powers of one (x, y) group
    double* xy = group + width;         // x power times y power
    linearPowers(p.x, u.x, order, xs);
    linearPowers(p.y, u.y, order, ys);
    linearPowers(p.z, u.z, order, zs);
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
        multiplyAdd(xs + i * width, i, ys + j * width, j, 1.0, xy);
        multiplyAdd(xy, i + j, group, zDegree, 1.0, out);
        start = end;
    }
}

Vec3 polynomialGradient(const PolynomialSurface& surface, const Vec3& p) {
    Vec3 g;
    for (const Monomial& m : surface.terms) {
        const double px = integerPower(p.x, m.x), py = integerPower(p.y, m.y), pz = integerPower(p.z, m.z);
        if (m.x > 0) g.x += m.coefficient * m.x * integerPower(p.x, m.x - 1) * py * pz;
        if (m.y > 0) g.y += m.coefficient * m.y * px * integerPower(p.y, m.y - 1) * pz;
        if (m.z > 0) g.z += m.coefficient * m.z * px * py * integerPower(p.z, m.z - 1);
    }
    return g;
}

bool insidePolynomial(const PolynomialSurface& surface, const Vec3& p) {
    return evaluateAlgebraic(surface.terms, p.x, p.y, p.z) < 0;
}

// The line is re-origined at its point p nearest the object origin with a
// unit direction u, so the polynomial in s is expanded where the surface
// usually is and the search interval is symmetric, [-h, h] with h the half
// chord of the reach sphere. Roots are isolated on monotonic pieces (see
// polynomialRootsInInterval): robust for grazing rays, and double roots,
// which do not change inside/outside, are not crossings.
int intersectPolynomial(const PolynomialSurface& surface, const Vec3& o, const Vec3& d, Crossing* out,
                        int capacity) {
    const double scale = length(d);
    if (!(scale > 0) || !std::isfinite(scale) || !isFinite(o)) return 0;
    const Vec3 u = d / scale;
    const double s0 = -dot(o, u);
    const Vec3 p = o + s0 * u;
    const double reach2 = kAlgebraicReach * kAlgebraicReach - dot(p, p);
    if (!(reach2 > 0)) return 0;
    const double half = std::sqrt(reach2);
    double coefficients[kMaxPolynomialDegree + 1];
    expandAlongLine(surface, p, u, coefficients);
    // Fujiwara's bound: every root has |s| <= 2 max_k |c_(n-k) / c_n|^(1/k)
    // (the constant term's ratio halved). Searching only there keeps the
    // root isolation's intervals short (the polynomial cannot change sign
    // outside, so no crossing is lost).
    int degree = surface.order;
    while (degree > 0 && coefficients[degree] == 0) --degree;
    if (degree == 0) return 0;
    double bound = 0;
    for (int k = 1; k <= degree; ++k) {
        const double ratio = std::fabs(coefficients[degree - k] / coefficients[degree]) * (k == degree ? 0.5 : 1.0);
        const double root = k == 1 ? ratio : k == 2 ? std::sqrt(ratio) : k == 3 ? std::cbrt(ratio)
                            : k == 4 ? std::sqrt(std::sqrt(ratio)) : std::pow(ratio, 1.0 / k);
        bound = std::max(bound, root);
    }
    bound = 2 * bound * (1 + 1e-12) + 1e-6; // a margin: roots at exactly +-bound or 0 stay inside
    const double lo = std::max(-half, -bound), hi = std::min(half, bound);
    double roots[kMaxPolynomialDegree + 1];
    const int n = polynomialRootsInInterval(coefficients, degree, lo, hi, roots);
    int count = 0;
    for (int i = 0; i < n && count < capacity; ++i) {
        const Vec3 at = p + roots[i] * u;
        out[count++] = {(s0 + roots[i]) / scale, polynomialGradient(surface, at)};
    }
    return count;
}

// ---------------------------------------------------------------- superellipsoid

double superellipsoidFunction(double e, double n, const Vec3& q) {
    const double a = 2 / e, b = 2 / n;
    const double ax = std::fabs(q.x), ay = std::fabs(q.y), az = std::fabs(q.z);
    const double m = std::max(ax, ay);
    double g = 0;
    if (m > 0) g = std::pow(m, b) * std::pow(1 + std::pow(std::min(ax, ay) / m, a), e / n);
    return g + std::pow(az, b) - 1;
}

// The gradient divided by b = 2/n: with S = m^a (1 + r^a),
// d/dx = S^(b/a - 1) |x|^(a-1) sgn x = m^(b-1) (1 + r^a)^(b/a - 1) (|x|/m)^(a-1) sgn x,
// d/dz = |z|^(b-1) sgn z. Components are 0 where their coordinate is (the
// surface's cusps when an exponent exceeds 2).
Vec3 superellipsoidGradient(double e, double n, const Vec3& q) {
    const double a = 2 / e, b = 2 / n;
    const double ax = std::fabs(q.x), ay = std::fabs(q.y), az = std::fabs(q.z);
    const double m = std::max(ax, ay);
    Vec3 g;
    if (m > 0) {
        const double common = std::pow(m, b - 1) * std::pow(1 + std::pow(std::min(ax, ay) / m, a), e / n - 1);
        if (ax > 0) g.x = std::copysign(common * std::pow(ax / m, a - 1), q.x);
        if (ay > 0) g.y = std::copysign(common * std::pow(ay / m, a - 1), q.y);
    }
    if (az > 0) g.z = std::copysign(std::pow(az, b - 1), q.z);
    return g;
}

namespace {

// Illinois regula falsi on [lo, hi] with f(lo), f(hi) of opposite signs,
// bisecting whenever the bracket fails to halve in two steps.
template <class F>
double bracketedRoot(const F& f, double lo, double hi, double fLo, double fHi) {
    int side = 0;
    double previousWidth = hi - lo;
    for (int iteration = 0; iteration < 200; ++iteration) {
        const double width = hi - lo;
        if (width <= 4e-16 * std::max(1.0, std::max(std::fabs(lo), std::fabs(hi)))) break;
        double t = (iteration % 2 == 1 && width > 0.5 * previousWidth) ? 0.5 * (lo + hi)
                                                                        : (lo * fHi - hi * fLo) / (fHi - fLo);
        if (iteration % 2 == 1) previousWidth = width;
        if (!(t > lo && t < hi)) t = 0.5 * (lo + hi);
        const double ft = f(t);
        if (ft == 0) return t;
        if ((ft < 0) == (fLo < 0)) {
            lo = t;
            fLo = ft;
            if (side == -1) fHi *= 0.5;
            side = -1;
        } else {
            hi = t;
            fHi = ft;
            if (side == 1) fLo *= 0.5;
            side = 1;
        }
    }
    return 0.5 * (lo + hi);
}

} // namespace

// The line is clipped to the cube [-1.001, 1.001]^3 (f > 0 on its faces) and
// re-origined at the entry. The chord is split where x, y or z is zero or
// |x| = |y| (where the formula's pieces meet and the surface has its cusps),
// each piece is sampled at kSamples sub-intervals, and every sign change is
// refined by bracketing. Two crossings closer than a sub-interval (a graze)
// can be missed, as in POV-Ray's own sampling.
int intersectSuperellipsoid(double e, double n, const Vec3& oIn, const Vec3& d, Crossing* out, int capacity) {
    constexpr double kBox = 1.001;
    constexpr int kSamples = 6;
    const double scale = length(d);
    if (!(scale > 0) || !std::isfinite(scale) || !isFinite(oIn)) return 0;
    const Vec3 u = d / scale;
    double enter = -INFINITY, exit = INFINITY;
    for (int axis = 0; axis < 3; ++axis) {
        if (u[axis] == 0) {
            if (std::fabs(oIn[axis]) >= kBox) return 0;
            continue;
        }
        double t0 = (-kBox - oIn[axis]) / u[axis], t1 = (kBox - oIn[axis]) / u[axis];
        if (t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0);
        exit = std::min(exit, t1);
    }
    if (!(enter < exit)) return 0;
    const Vec3 o = oIn + enter * u;
    const double span = exit - enter;
    double cuts[8];
    int cutCount = 0;
    cuts[cutCount++] = 0;
    auto cutAt = [&](double value, double slope) { // value + s slope = 0
        if (slope == 0) return;
        const double s = -value / slope;
        if (s > 0 && s < span) cuts[cutCount++] = s;
    };
    cutAt(o.x, u.x);
    cutAt(o.y, u.y);
    cutAt(o.z, u.z);
    cutAt(o.x - o.y, u.x - u.y);
    cutAt(o.x + o.y, u.x + u.y);
    cuts[cutCount++] = span;
    for (int i = 1; i < cutCount; ++i) // insertion sort of at most 7 values
        for (int j = i; j > 0 && cuts[j - 1] > cuts[j]; --j) std::swap(cuts[j - 1], cuts[j]);
    auto f = [&](double s) { return superellipsoidFunction(e, n, o + s * u); };
    int count = 0;
    double previous = 0, fPrevious = f(0);
    for (int piece = 0; piece + 1 < cutCount; ++piece) {
        const double a = cuts[piece], b = cuts[piece + 1];
        if (!(b > a)) continue;
        for (int k = 1; k <= kSamples; ++k) {
            const double s = k == kSamples ? b : a + (b - a) * k / kSamples;
            const double fs = f(s);
            if ((fs < 0) != (fPrevious < 0) && count < capacity) {
                const double root = bracketedRoot(f, previous, s, fPrevious, fs);
                out[count++] = {(enter + root) / scale, superellipsoidGradient(e, n, o + root * u)};
            }
            previous = s;
            fPrevious = fs;
        }
    }
    return count;
}

} // namespace drt::accel
