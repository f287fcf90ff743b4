// Convergence-rate tests of the samplers on closed-form pixel integrals
// (docs/accuracy.md; padding: docs/effects.md):
//   - anti-aliasing: the area of a pixel covered by a straight edge (dims 0-1);
//   - motion blur: an edge sweeping across the pixel during the shutter, whose
//     time-averaged coverage couples pixel and time (dims 0, 1, 2);
//   - defocus: an edge seen through a disc lens, coupling pixel and lens
//     (dims 0, 1, 3, 4), the lens point mapped by the concentric disc map.
// For each sampler and N in {16, ..., 4096} the RMSE over kRandomisations
// different pixels and edges is measured and the log-log slope fitted.
//
// Expected rates. Independent: N^-0.5 always. A still edge is a half-plane in
// 2D: stratified and Sobol reach N^-0.75. The coupled integrands are
// half-spaces (or smooth-boundaried sets) in d = 3 and 4 dimensions, and no
// point set can beat N^-(1/2 + 1/(2d)) on average over half-spaces (Beck 1987,
// Alexander 1990; scrambled nets attain it): N^-0.667 for the moving edge and
// N^-0.625 for the defocused one. So the bands there are <= -0.64 and <= -0.60
// (measured about -0.67 and -0.63 over several seeds, +-0.005), not the 2D
// -0.68; the point of the test is the gap to padding, whose 2D pairs are
// stratified but uncorrelated across pairs and fall back to about N^-0.51: at
// N = 4096 Sobol's RMSE must be at least 1.8x lower (measured 2.1x-3.0x).
#include "core/hash.h"
#include "sampling/sampler.h"
#include "sampling/warp.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <vector>

namespace drt {
namespace {

constexpr int kRandomisations = 1000;
const std::vector<int> kSampleCounts{16, 64, 256, 1024, 4096};

// Area of {p in [0, 1]^2 : n . p < c}: clip the unit square by the half-plane
// (Sutherland-Hodgman, one plane) and take the shoelace area.
double coveredArea(Vec2 n, double c) {
    const std::array<Vec2, 4> square{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
    std::vector<Vec2> poly;
    for (size_t i = 0; i < 4; ++i) {
        const Vec2 a = square[i], b = square[(i + 1) % 4];
        const double da = n.x * a.x + n.y * a.y - c, db = n.x * b.x + n.y * b.y - c;
        if (da < 0) poly.push_back(a);
        if ((da < 0) != (db < 0)) {
            const double s = da / (da - db);
            poly.push_back({a.x + s * (b.x - a.x), a.y + s * (b.y - a.y)});
        }
    }
    double twiceArea = 0;
    for (size_t i = 0; i < poly.size(); ++i) {
        const Vec2 a = poly[i], b = poly[(i + 1) % poly.size()];
        twiceArea += a.x * b.y - a.y * b.x;
    }
    return 0.5 * std::fabs(twiceArea);
}

// Integral of f over [a, b] by 5-point Gauss-Legendre on `intervals` pieces.
double integrate1D(const std::function<double(double)>& f, double a, double b, int intervals = 2000) {
    static constexpr std::array<double, 5> x{-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                                             0.9061798459386640};
    static constexpr std::array<double, 5> w{0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                             0.4786286704993665, 0.2369268850561891};
    const double h = (b - a) / intervals;
    double sum = 0;
    for (int i = 0; i < intervals; ++i)
        for (size_t k = 0; k < 5; ++k) sum += w[k] * f(a + (i + 0.5) * h + 0.5 * h * x[k]);
    return sum * 0.5 * h;
}

// One pixel integrand with its exact value.
struct Integrand {
    std::function<double(Sampler&)> sample; // one estimate from the current pixel sample
    double exact;
};

// A random edge through the pixel: normal at a random angle, passing through a
// random point of the pixel's central region.
struct Edge {
    Vec2 n;
    double c;
};
Edge randomEdge(int r) {
    const uint64_t h = hashValues({0xed9eULL, uint64_t(r)});
    const double angle = 2 * kPi * unitFromHash(h);
    const Vec2 q{0.2 + 0.6 * unitFromHash(mix64(h + 1)), 0.2 + 0.6 * unitFromHash(mix64(h + 2))};
    const Vec2 n{std::cos(angle), std::sin(angle)};
    return {n, n.x * q.x + n.y * q.y};
}

constexpr double kSweep = 0.8; // edge travel over the shutter, pixels along its normal
constexpr double kBlur = 0.6;  // radius of the defocus disc, pixels

Integrand stillEdge(int r) {
    const Edge e = randomEdge(r);
    return {[e](Sampler& s) {
                const Vec2 p = s.get2D(kDimPixel);
                return e.n.x * p.x + e.n.y * p.y < e.c ? 1.0 : 0.0;
            },
            coveredArea(e.n, e.c)};
}

// The edge offset moves linearly, c(t) = c + sweep (t - 1/2): value = int_0^1 area(c(t)) dt.
Integrand movingEdge(int r) {
    const Edge e = randomEdge(r);
    return {[e](Sampler& s) {
                const Vec2 p = s.get2D(kDimPixel);
                const double t = s.get1D(kDimTime);
                return e.n.x * p.x + e.n.y * p.y < e.c + kSweep * (t - 0.5) ? 1.0 : 0.0;
            },
            integrate1D([e](double t) { return coveredArea(e.n, e.c + kSweep * (t - 0.5)); }, 0.0, 1.0)};
}

// The pixel point is displaced by blur * (a uniform disc point): value =
// int area(c - blur s) rho(s) ds with rho(s) = 2 sqrt(1 - s^2) / pi, the density
// of n . q for q uniform on the unit disc; s = sin(theta) removes the root.
Integrand defocusedEdge(int r) {
    const Edge e = randomEdge(r);
    return {[e](Sampler& s) {
                const Vec2 p = s.get2D(kDimPixel);
                const Vec2 q = squareToConcentricDisc(s.get2D(kDimLens));
                const double x = p.x + kBlur * q.x, y = p.y + kBlur * q.y;
                return e.n.x * x + e.n.y * y < e.c ? 1.0 : 0.0;
            },
            integrate1D(
                [e](double theta) {
                    const double cs = std::cos(theta);
                    return coveredArea(e.n, e.c - kBlur * std::sin(theta)) * 2.0 * cs * cs / kPi;
                },
                -kPi / 2, kPi / 2)};
}

struct Fit {
    std::vector<double> rmse;
    double slope;
};

Fit measure(const std::string& samplerName, const std::function<Integrand(int)>& makeIntegrand) {
    std::vector<Integrand> integrands;
    for (int r = 0; r < kRandomisations; ++r) integrands.push_back(makeIntegrand(r));
    Fit fit;
    for (int n : kSampleCounts) {
        auto sampler = makeSampler(samplerName, n, 0x5eed);
        double sumSquares = 0;
        for (int r = 0; r < kRandomisations; ++r) {
            double sum = 0;
            for (int i = 0; i < n; ++i) {
                sampler->startPixelSample(r % 100, r / 100, i);
                sum += integrands[size_t(r)].sample(*sampler);
            }
            const double error = sum / n - integrands[size_t(r)].exact;
            sumSquares += error * error;
        }
        fit.rmse.push_back(std::sqrt(sumSquares / kRandomisations));
    }
    // Least-squares slope of log RMSE against log N.
    double mx = 0, my = 0;
    const double k = static_cast<double>(kSampleCounts.size());
    for (size_t i = 0; i < kSampleCounts.size(); ++i) {
        mx += std::log(kSampleCounts[i]) / k;
        my += std::log(fit.rmse[i]) / k;
    }
    double sxy = 0, sxx = 0;
    for (size_t i = 0; i < kSampleCounts.size(); ++i) {
        const double dx = std::log(kSampleCounts[i]) - mx;
        sxy += dx * (std::log(fit.rmse[i]) - my);
        sxx += dx * dx;
    }
    fit.slope = sxy / sxx;
    return fit;
}

Fit report(const char* integrand, const std::string& sampler, const std::function<Integrand(int)>& make) {
    const Fit f = measure(sampler, make);
    std::printf("[slope] %-15s %-12s slope %+.3f  rmse:", integrand, sampler.c_str(), f.slope);
    for (double e : f.rmse) std::printf(" %.2e", e);
    std::printf("\n");
    return f;
}

TEST(ExactValues, CoveredAreaAndTheIntegralsAgreeWithLimits) {
    EXPECT_NEAR(coveredArea({1, 0}, 0.3), 0.3, 1e-15);
    EXPECT_NEAR(coveredArea({std::sqrt(0.5), std::sqrt(0.5)}, std::sqrt(0.5)), 0.5, 1e-15);
    EXPECT_NEAR(coveredArea({1, 1}, 0.5), 0.125, 1e-15); // a corner triangle
    // Independent Monte Carlo (1e6 samples) agrees with the moving and
    // defocused exact values within 5 sigma.
    for (auto make : {movingEdge, defocusedEdge}) {
        const Integrand f = make(7);
        auto sampler = makeSampler("independent", 1, 3);
        const int n = 1000000;
        double sum = 0;
        for (int i = 0; i < n; ++i) {
            sampler->startPixelSample(0, 0, i);
            sum += f.sample(*sampler);
        }
        const double mean = sum / n;
        EXPECT_NEAR(mean, f.exact, 5 * std::sqrt(f.exact * (1 - f.exact) / n));
    }
}

TEST(Convergence, StillEdge) {
    const double independent = report("still edge", "independent", stillEdge).slope;
    EXPECT_GE(independent, -0.55);
    EXPECT_LE(independent, -0.45);
    EXPECT_LE(report("still edge", "stratified", stillEdge).slope, -0.68);
    EXPECT_LE(report("still edge", "sobol", stillEdge).slope, -0.68);
}

TEST(Convergence, MotionBlurredEdgeCouplesPixelAndTime) {
    const Fit independent = report("moving edge", "independent", movingEdge);
    const Fit stratified = report("moving edge", "stratified", movingEdge);
    const Fit sobol = report("moving edge", "sobol", movingEdge);
    EXPECT_GE(independent.slope, -0.55);
    EXPECT_LE(independent.slope, -0.45);
    EXPECT_LE(sobol.slope, -0.64);
    // Padding loses the joint stratification: Sobol ends well ahead.
    EXPECT_LT(sobol.rmse.back() * 1.8, stratified.rmse.back());
}

TEST(Convergence, DefocusedEdgeCouplesPixelAndLens) {
    const Fit independent = report("defocused edge", "independent", defocusedEdge);
    const Fit stratified = report("defocused edge", "stratified", defocusedEdge);
    const Fit sobol = report("defocused edge", "sobol", defocusedEdge);
    EXPECT_GE(independent.slope, -0.55);
    EXPECT_LE(independent.slope, -0.45);
    EXPECT_LE(sobol.slope, -0.60);
    EXPECT_LT(sobol.rmse.back() * 1.8, stratified.rmse.back());
}

} // namespace
} // namespace drt
