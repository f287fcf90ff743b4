// A reusable chi-square goodness-of-fit harness for sampling routines.
//
// Recipe: draw 1e6 samples, histogram them over ~100 x 100
// bins of a 2D parametrisation of the domain, compute each bin's expected count
// by numerically integrating the routine's own density over the bin, pool bins
// expecting fewer than 5 samples, and compare with the chi-square distribution
// at alpha = 0.01, Sidak-corrected for the number of tests run.
#pragma once

#include "core/hash.h"
#include "core/vec.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace drt::test {

// Regularised upper incomplete gamma Q(a, x) = Gamma(a, x) / Gamma(a): the
// series for P below x < a + 1, Lentz's continued fraction for Q above
// (Abramowitz & Stegun 6.5.29 and 6.5.31).
inline double upperIncompleteGamma(double a, double x) {
    if (x <= 0) return 1.0;
    const double logPrefix = -x + a * std::log(x) - std::lgamma(a);
    if (x < a + 1.0) {
        double term = 1.0 / a, sum = term;
        for (int n = 1; n < 100000; ++n) {
            term *= x / (a + n);
            sum += term;
            if (term < sum * 1e-16) break;
        }
        return std::max(0.0, 1.0 - sum * std::exp(logPrefix));
    }
    const double tiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 100000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::fabs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::fabs(c) < tiny) c = tiny;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::fabs(delta - 1.0) < 1e-16) break;
    }
    return std::exp(logPrefix) * h;
}

// P(X >= statistic) for X chi-square distributed with `dof` degrees of freedom.
inline double chiSquarePValue(double statistic, int dof) { return upperIncompleteGamma(0.5 * dof, 0.5 * statistic); }

// Per-test significance level so that `tests` independent tests at this level
// have a family-wise false-alarm rate of alpha: 1 - (1 - alpha)^(1/tests).
inline double sidakAlpha(double alpha, int tests) { return 1.0 - std::pow(1.0 - alpha, 1.0 / tests); }

struct ChiSquareResult {
    double statistic = 0;
    int dof = 0;
    double pValue = 0;
    long impossibleSamples = 0; // samples in bins of zero expected count
};

// Pearson's statistic sum (O - E)^2 / E over the bins; bins expecting fewer
// than `minExpected` samples are pooled into one bin (which is merged into the
// smallest remaining bin if it still expects too few).
inline ChiSquareResult chiSquare(const std::vector<double>& observed, const std::vector<double>& expected,
                                 double minExpected = 5.0) {
    ChiSquareResult r;
    std::vector<std::pair<double, double>> bins; // (expected, observed)
    double pooledE = 0, pooledO = 0;
    for (size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] <= 0 && observed[i] > 0) r.impossibleSamples += static_cast<long>(observed[i]);
        if (expected[i] < minExpected) {
            pooledE += expected[i];
            pooledO += observed[i];
        } else {
            bins.push_back({expected[i], observed[i]});
        }
    }
    if (pooledE >= minExpected || bins.empty()) {
        bins.push_back({pooledE, pooledO});
    } else if (pooledE > 0 || pooledO > 0) {
        auto smallest = std::min_element(bins.begin(), bins.end());
        smallest->first += pooledE;
        smallest->second += pooledO;
    }
    for (const auto& [e, o] : bins)
        if (e > 0) r.statistic += (o - e) * (o - e) / e;
    r.dof = static_cast<int>(bins.size()) - 1;
    r.pValue = r.dof > 0 ? chiSquarePValue(r.statistic, r.dof) : 1.0;
    if (r.impossibleSamples > 0) r.pValue = 0;
    return r;
}

// A rectangle of parameter space cut into nx x ny bins.
struct Grid2D {
    double x0, x1, y0, y1;
    int nx = 100, ny = 100;
    int bins() const { return nx * ny; }
    // -1 when outside.
    int binOf(Vec2 p) const {
        if (!(p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1)) return -1;
        const int i = std::min(nx - 1, static_cast<int>((p.x - x0) / (x1 - x0) * nx));
        const int j = std::min(ny - 1, static_cast<int>((p.y - y0) / (y1 - y0) * ny));
        return j * nx + i;
    }
};

// Integral of f over [x0, x1] x [y0, y1] by a 5 x 5-point Gauss-Legendre rule
// on each of sub x sub cells (exact for polynomials of degree 9 per cell).
inline double integrate2D(const std::function<double(double, double)>& f, double x0, double x1, double y0, double y1,
                          int sub = 2) {
    static constexpr std::array<double, 5> nodes{-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                                                 0.9061798459386640};
    static constexpr std::array<double, 5> weights{0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                                   0.4786286704993665, 0.2369268850561891};
    const double hx = (x1 - x0) / sub, hy = (y1 - y0) / sub;
    double sum = 0;
    for (int a = 0; a < sub; ++a)
        for (int b = 0; b < sub; ++b) {
            const double cx = x0 + (a + 0.5) * hx, cy = y0 + (b + 0.5) * hy;
            for (size_t i = 0; i < 5; ++i)
                for (size_t j = 0; j < 5; ++j)
                    sum += weights[i] * weights[j] * f(cx + 0.5 * hx * nodes[i], cy + 0.5 * hy * nodes[j]);
        }
    return sum * 0.25 * hx * hy;
}

// One chi-square case: a sampling routine seen through a 2D parametrisation.
struct ChiSquareCase {
    std::string name;
    Grid2D grid;
    // The parameters of the sample drawn from u (nullopt: an invalid sample,
    // e.g. a non-finite value, which fails the test).
    std::function<std::optional<Vec2>(Vec2 u)> sample;
    // The routine's density with respect to d(param x) d(param y).
    std::function<double(double, double)> density;
    // Parameter region outside the grid that still has probability (samples
    // landing off the grid are counted in one extra bin expecting its integral).
    std::optional<Grid2D> outside;
};

struct ChiSquareReport {
    ChiSquareResult result;
    double totalProbability = 0; // integral of the density over grid + outside: 1 if pdf is normalised
    long invalidSamples = 0;
};

inline ChiSquareReport runChiSquare(const ChiSquareCase& c, uint64_t seed, long sampleCount = 1000000) {
    ChiSquareReport report;
    const int bins = c.grid.bins();
    std::vector<double> observed(static_cast<size_t>(bins) + 1, 0.0), expected(observed.size(), 0.0);
    for (long i = 0; i < sampleCount; ++i) {
        const uint64_t h = hashValues({seed, static_cast<uint64_t>(i)});
        const Vec2 u{unitFromHash(h), unitFromHash(mix64(h + 0x9e3779b97f4a7c15ULL))};
        const std::optional<Vec2> p = c.sample(u);
        if (!p || !std::isfinite(p->x) || !std::isfinite(p->y)) {
            ++report.invalidSamples;
            continue;
        }
        const int b = c.grid.binOf(*p);
        observed[static_cast<size_t>(b < 0 ? bins : b)] += 1;
    }
    const Grid2D& g = c.grid;
    const double dx = (g.x1 - g.x0) / g.nx, dy = (g.y1 - g.y0) / g.ny;
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) {
            const double p = integrate2D(c.density, g.x0 + i * dx, g.x0 + (i + 1) * dx, g.y0 + j * dy, g.y0 + (j + 1) * dy);
            expected[static_cast<size_t>(j * g.nx + i)] = p * sampleCount;
            report.totalProbability += p;
        }
    if (c.outside) {
        const Grid2D& o = *c.outside;
        const double ox = (o.x1 - o.x0) / o.nx, oy = (o.y1 - o.y0) / o.ny;
        double p = 0;
        for (int j = 0; j < o.ny; ++j)
            for (int i = 0; i < o.nx; ++i)
                p += integrate2D(c.density, o.x0 + i * ox, o.x0 + (i + 1) * ox, o.y0 + j * oy, o.y0 + (j + 1) * oy);
        expected[static_cast<size_t>(bins)] = p * sampleCount;
        report.totalProbability += p;
    }
    report.result = chiSquare(observed, expected);
    return report;
}

} // namespace drt::test
