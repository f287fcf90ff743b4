#include "accel/algebraic_shapes.h"

#include "accel/polynomial.h"

#include <algorithm>
#include <array>
#include <utility>
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

namespace {
void prepareExpansion(PolynomialSurface& s); // below
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
    for (const Monomial& m : s.terms) {
        s.order = std::max(s.order, m.x + m.y + m.z);
        s.degreeX = std::max(s.degreeX, m.x);
        s.degreeY = std::max(s.degreeY, m.y);
        s.degreeZ = std::max(s.degreeZ, m.z);
        const int index = int(&m - s.terms.data());
        if (s.groups.empty() || s.groups.back().x != m.x || s.groups.back().y != m.y)
            s.groups.push_back({m.x, m.y, 0, index, index});
        s.groups.back().zDegree = std::max(s.groups.back().zDegree, m.z);
        s.groups.back().end = index + 1;
    }
    if (s.order == 0) throw std::invalid_argument("algebraic surface has no non-constant term");
    prepareExpansion(s);
    if (s.order == 2) ellipsoidBounds(s);
    return s;
}

namespace {

// Row i of a triangular table of rows 0, 1, 2, ... of lengths 1, 2, 3, ...
constexpr size_t triangleRow(int i) { return size_t(i) * size_t(i + 1) / 2; }

// Series up to this degree are handled by loops of fixed length, unrolled.
constexpr int kUnrolled = 4;

// (p + s u)^i for i = 0..degree as triangular rows: row i, column k holds the
// coefficient of s^k, C(i, k) p^(i-k) u^k, built by repeated multiplication.
// The first and last columns add a zero to their one product (as rows of full
// width did, whose other columns were zero): -0 becomes +0 there.
template <int kDegree>
void linearPowers(double p, double u, int degreeIn, double* rows) {
    const int degree = kDegree < 0 ? degreeIn : kDegree;
    rows[0] = 1;
    for (int i = 1; i <= degree; ++i) {
        const double* prev = rows + triangleRow(i - 1);
        double* row = rows + triangleRow(i);
        row[0] = prev[0] * p + 0.0;
        for (int k = 1; k < i; ++k) row[k] = prev[k] * p + prev[k - 1] * u;
        row[i] = 0.0 + prev[i - 1] * u;
    }
}

void linearPowersOfDegree(double p, double u, int degree, double* rows) {
    switch (degree) {
    case 1: linearPowers<1>(p, u, degree, rows); break;
    case 2: linearPowers<2>(p, u, degree, rows); break;
    case 3: linearPowers<3>(p, u, degree, rows); break;
    case 4: linearPowers<4>(p, u, degree, rows); break;
    default: linearPowers<-1>(p, u, degree, rows); break;
    }
}

// out[0..na+nb] += a[0..na] * b[0..nb], skipping a's zeros (kNa, kNb >= 0: of
// that fixed degree).
template <int kNa, int kNb>
void multiplyAdd(const double* a, int naIn, const double* b, int nbIn, double* out) {
    const int na = kNa < 0 ? naIn : kNa, nb = kNb < 0 ? nbIn : kNb;
    for (int i = 0; i <= na; ++i) {
        if (a[i] == 0) continue;
        const double ai = a[i];
        for (int j = 0; j <= nb; ++j) out[i + j] += ai * b[j];
    }
}

// out[0..na+nb] = a[0..na] * b[0..nb]: zeros, then multiplyAdd.
template <int kNa, int kNb>
void product(const double* a, int naIn, const double* b, int nbIn, double* out) {
    const int size = (kNa < 0 ? naIn : kNa) + (kNb < 0 ? nbIn : kNb) + 1;
    for (int k = 0; k < size; ++k) out[k] = 0.0;
    multiplyAdd<kNa, kNb>(a, naIn, b, nbIn, out);
}

// sum[0..z] += c zPowers[0..z]; the first term of a run sets the sum to 0 + c
// zPowers (its z is the run's highest), as adding to a sum of zeros did.
template <int kZ, bool kFirst>
void addTerm(double c, const double* zPowers, int zIn, double* sum) {
    const int z = kZ < 0 ? zIn : kZ;
    for (int k = 0; k <= z; ++k) sum[k] = (kFirst ? 0.0 : sum[k]) + c * zPowers[k];
}

template <template <int, int> class Step, size_t... I>
constexpr std::array<PolynomialSurface::SeriesProduct, sizeof...(I)> seriesTable(std::index_sequence<I...>) {
    return {&Step<int(I) / (kUnrolled + 1), int(I) % (kUnrolled + 1)>::run...};
}
template <int kNa, int kNb>
struct ProductStep {
    static void run(const double* a, int na, const double* b, int nb, double* out) {
        product<kNa, kNb>(a, na, b, nb, out);
    }
};
template <int kNa, int kNb>
struct MultiplyAddStep {
    static void run(const double* a, int na, const double* b, int nb, double* out) {
        multiplyAdd<kNa, kNb>(a, na, b, nb, out);
    }
};
constexpr auto kProducts = seriesTable<ProductStep>(std::make_index_sequence<(kUnrolled + 1) * (kUnrolled + 1)>());
constexpr auto kMultiplyAdds =
    seriesTable<MultiplyAddStep>(std::make_index_sequence<(kUnrolled + 1) * (kUnrolled + 1)>());

template <bool kFirst, size_t... I>
constexpr std::array<PolynomialSurface::SeriesTerm, sizeof...(I)> termTable(std::index_sequence<I...>) {
    return {&addTerm<int(I), kFirst>...};
}
constexpr auto kFirstTerms = termTable<true>(std::make_index_sequence<kUnrolled + 1>());
constexpr auto kLaterTerms = termTable<false>(std::make_index_sequence<kUnrolled + 1>());

bool unrolled(int na, int nb) { return na <= kUnrolled && nb <= kUnrolled; }

// expandAlongLine's rows past kStackOrder, kept per thread (accel/thread_scratch.h).
struct AlgebraicScratch {
    std::vector<double> heap;
};

// Chooses expandAlongLine's steps for the groups' and terms' degrees.
void prepareExpansion(PolynomialSurface& s) {
    for (PolynomialSurface::TermGroup& g : s.groups) {
        const size_t at = size_t(g.x * (kUnrolled + 1) + g.y);
        g.xyProduct = unrolled(g.x, g.y) ? kProducts[at] : &product<-1, -1>;
        const size_t sumAt = size_t((g.x + g.y) * (kUnrolled + 1) + g.zDegree);
        g.accumulate = unrolled(g.x + g.y, g.zDegree) ? kMultiplyAdds[sumAt] : &multiplyAdd<-1, -1>;
        for (int t = g.first; t < g.end; ++t) {
            const int z = s.terms[size_t(t)].z;
            const bool first = t == g.first;
            s.termSteps.push_back(z <= kUnrolled ? (first ? kFirstTerms : kLaterTerms)[size_t(z)]
                                                 : first ? &addTerm<-1, true> : &addTerm<-1, false>);
        }
    }
}

} // namespace

std::unique_ptr<InstalledScratch> installAlgebraicScratch() { return ThreadScratch<AlgebraicScratch>::install(); }

// Each coefficient is the sum of the same products in the same order as the
// expansion first written (full-width power rows, zeroed and recomputed per
// group): only the products of the zeros that rows of full width held are no
// longer formed.
void expandAlongLine(const PolynomialSurface& surface, const Vec3& p, const Vec3& u, double* out) {
    const int order = surface.order, width = order + 1;
    const size_t xSize = triangleRow(surface.degreeX + 1), ySize = triangleRow(surface.degreeY + 1);
    const size_t size = xSize + ySize + triangleRow(surface.degreeZ + 1) + size_t(width) * 2;
    constexpr int kStackOrder = 8;
    double stack[3 * triangleRow(kStackOrder + 1) + (kStackOrder + 1) * 2];
    double* xs = stack;
    if (order > kStackOrder) {
        std::vector<double>& heap = ThreadScratch<AlgebraicScratch>::get().heap;
        if (heap.size() < size) heap.resize(size);
        xs = heap.data();
    }
    double* ys = xs + xSize;
    double* zs = ys + ySize;
    double* group = zs + triangleRow(surface.degreeZ + 1); // sum of c z-powers of one (x, y) group
    double* xy = group + width;                            // x power times y power
    linearPowersOfDegree(p.x, u.x, surface.degreeX, xs);
    linearPowersOfDegree(p.y, u.y, surface.degreeY, ys);
    linearPowersOfDegree(p.z, u.z, surface.degreeZ, zs);
    for (int k = 0; k < width; ++k) out[k] = 0.0;
    const Monomial* terms = surface.terms.data();
    const PolynomialSurface::SeriesTerm* steps = surface.termSteps.data();
    for (const PolynomialSurface::TermGroup& g : surface.groups) {
        for (int t = g.first; t < g.end; ++t)
            steps[t](terms[t].coefficient, zs + triangleRow(terms[t].z), terms[t].z, group);
        g.xyProduct(xs + triangleRow(g.x), g.x, ys + triangleRow(g.y), g.y, xy);
        g.accumulate(xy, g.x + g.y, group, g.zDegree, out);
    }
}

// The powers p^0..p^degree, each the product 1 p p ... p from the left.
static void integerPowers(double p, int degree, double* powers) {
    powers[0] = 1;
    for (int e = 1; e <= degree; ++e) powers[e] = powers[e - 1] * p;
}

Vec3 polynomialGradient(const PolynomialSurface& surface, const Vec3& p) {
    double px[kMaxAlgebraicOrder + 1], py[kMaxAlgebraicOrder + 1], pz[kMaxAlgebraicOrder + 1];
    integerPowers(p.x, surface.degreeX, px);
    integerPowers(p.y, surface.degreeY, py);
    integerPowers(p.z, surface.degreeZ, pz);
    Vec3 g;
    for (const Monomial& m : surface.terms) {
        if (m.x > 0) g.x += m.coefficient * m.x * px[m.x - 1] * py[m.y] * pz[m.z];
        if (m.y > 0) g.y += m.coefficient * m.y * px[m.x] * py[m.y - 1] * pz[m.z];
        if (m.z > 0) g.z += m.coefficient * m.z * px[m.x] * py[m.y] * pz[m.z - 1];
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
