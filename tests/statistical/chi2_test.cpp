// Chi-square tests of every sampling routine in src/sampling (warps and pixel
// filters): each draws 1e6 samples and compares their histogram over ~100 x 100
// bins with the routine's own density, integrated per bin. The same integrals
// check that each density is normalised (integrates to 1 over its domain).
#include "sampling/filter.h"
#include "sampling/warp.h"
#include "statistical/chi2_harness.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace drt::test {
namespace {

constexpr double kTwoPi = 2.0 * kPi;

// A frame about `axis` built independently of the renderer's orthonormalBasis
// (Gram-Schmidt against a fixed helper), so a bug there cannot cancel out.
struct TestFrame {
    Vec3 t, b, n;
    explicit TestFrame(const Vec3& axis) : n(normalize(axis)) {
        const Vec3 helper = std::fabs(n.x) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
        t = normalize(helper - n * dot(helper, n));
        b = cross(n, t);
    }
    // (cos theta, phi in [0, 2 pi)) of a direction.
    Vec2 toParams(const Vec3& w) const {
        double phi = std::atan2(dot(w, b), dot(w, t));
        if (phi < 0) phi += kTwoPi;
        return {dot(w, n), phi};
    }
    Vec3 fromParams(double cosTheta, double phi) const {
        const double s = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
        return t * (s * std::cos(phi)) + b * (s * std::sin(phi)) + n * cosTheta;
    }
};

std::optional<Vec2> unitLengthOnly(const Vec3& w, const Vec2& params) {
    if (std::fabs(length(w) - 1.0) > 1e-9) return std::nullopt;
    return params;
}

// A direction sampler binned over (cos theta, phi) about `axis`, cos theta in
// [cosLow, 1]; dω = d cos(theta) d phi, so the density in these parameters is
// the solid-angle pdf itself.
ChiSquareCase directionCase(std::string name, Vec3 axis, double cosLow, std::function<Vec3(Vec2)> sample,
                            std::function<double(const Vec3&)> pdf) {
    const TestFrame frame(axis);
    ChiSquareCase c;
    c.name = std::move(name);
    c.grid = {cosLow, 1.0, 0.0, kTwoPi};
    c.sample = [frame, sample](Vec2 u) { const Vec3 w = sample(u); return unitLengthOnly(w, frame.toParams(w)); };
    c.density = [frame, pdf](double ct, double phi) { return pdf(frame.fromParams(ct, phi)); };
    if (cosLow > -1.0) c.outside = Grid2D{-1.0, cosLow, 0.0, kTwoPi, 200, 8};
    return c;
}

// A disc sampler binned over polar (r, phi): density r / pi.
ChiSquareCase discCase(std::string name, std::function<Vec2(Vec2)> sample) {
    ChiSquareCase c;
    c.name = std::move(name);
    c.grid = {0.0, 1.0, 0.0, kTwoPi};
    c.sample = [sample](Vec2 u) -> std::optional<Vec2> {
        const Vec2 d = sample(u);
        double phi = std::atan2(d.y, d.x);
        if (phi < 0) phi += kTwoPi;
        return Vec2{std::sqrt(d.x * d.x + d.y * d.y), phi};
    };
    c.density = [](double r, double) { return r * uniformDiscPdf(); };
    return c;
}

// The Phong lobe: cos theta binned over [c_low, 1] with c_low^(n+1) = 1e-5, the
// probability of falling below it, so even n = 1000 spreads over many bins.
ChiSquareCase phongCase(double n, Vec3 axis) {
    axis = normalize(axis);
    const double cosLow = n > 0 ? std::pow(1e-5, 1.0 / (n + 1.0)) : -1.0;
    char name[96];
    std::snprintf(name, sizeof name, "phong n=%g axis=(%.2f,%.2f,%.2f)", n, axis.x, axis.y, axis.z);
    return directionCase(
        name, axis, cosLow, [axis, n](Vec2 u) { return sampleLobeAround(axis, n, u); },
        [axis, n](const Vec3& w) { return lobeAroundPdf(axis, n, w); });
}

// Solid-angle sampling of a rectangle, binned over the rectangle's own (s, t)
// in [0, 1]^2: the density is pdf_omega * |cos theta_light| / r^2 * area.
ChiSquareCase sphericalRectangleCase(std::string name, Vec3 origin, Vec3 corner, Vec3 e1, Vec3 e2) {
    const SphericalRectangle rect(origin, corner, e1, e2);
    EXPECT_TRUE(rect.valid()) << name;
    const Vec3 normal = normalize(cross(e1, e2));
    const double area = length(cross(e1, e2));
    ChiSquareCase c;
    c.name = std::move(name);
    c.grid = {0.0, 1.0, 0.0, 1.0};
    c.sample = [=](Vec2 u) -> std::optional<Vec2> {
        const Vec3 p = rect.sample(u);
        const Vec3 d = p - corner;
        if (std::fabs(dot(d, normal)) > 1e-9 * (1.0 + length(d))) return std::nullopt; // off the plane
        return Vec2{dot(d, e1) / dot(e1, e1), dot(d, e2) / dot(e2, e2)};
    };
    c.density = [=](double s, double t) {
        return areaToSolidAnglePdf(1.0, origin, corner + e1 * s + e2 * t, normal) > 0
                   ? rect.pdf() * area / areaToSolidAnglePdf(1.0, origin, corner + e1 * s + e2 * t, normal)
                   : 0.0;
    };
    return c;
}

ChiSquareCase filterCase(const std::string& filterName) {
    const Filter f = makeFilter(filterName);
    ChiSquareCase c;
    c.name = "filter " + filterName;
    c.grid = {-f.radius, f.radius, -f.radius, f.radius};
    c.sample = [f](Vec2 u) -> std::optional<Vec2> { return sampleFilter(f, u); };
    c.density = [f](double x, double y) { return filterPdf(f, {x, y}); };
    return c;
}

std::vector<ChiSquareCase> allCases() {
    std::vector<ChiSquareCase> cases;
    cases.push_back(discCase("concentric disc", squareToConcentricDisc));
    cases.push_back(discCase("polar disc", squareToUniformDiscPolar));
    cases.push_back(directionCase("uniform sphere", {0, 0, 1}, -1.0, squareToUniformSphere,
                                  [](const Vec3&) { return uniformSpherePdf(); }));
    cases.push_back(directionCase("uniform hemisphere", {0, 0, 1}, -1.0, squareToUniformHemisphere,
                                  [](const Vec3& w) { return w.z >= 0 ? uniformHemispherePdf() : 0.0; }));
    cases.push_back(directionCase("cosine hemisphere", {0, 0, 1}, -1.0, squareToCosineHemisphere,
                                  [](const Vec3& w) { return cosineHemispherePdf(w.z); }));
    {
        const Vec3 axis = normalize(Vec3{-1, 2, 0.5});
        cases.push_back(directionCase(
            "cosine about an axis", axis, -1.0, [axis](Vec2 u) { return sampleCosineAround(axis, u); },
            [axis](const Vec3& w) { return cosineHemispherePdf(dot(axis, w)); }));
    }
    cases.push_back(phongCase(1, {0, 0, 1}));
    cases.push_back(phongCase(10, {1, 2, -3}));
    cases.push_back(phongCase(10, {1e-3, 0, -1})); // near the frame's singular axis
    cases.push_back(phongCase(100, {0, 0, -1}));
    cases.push_back(phongCase(1000, {-0.3, 0.9, 0.1}));
    cases.push_back(phongCase(1000, {0, 1, 0}));
    // Parallelogram: skewed edges, binned over its (s, t); uniform density 1 there.
    {
        const Vec3 corner{1, 2, 3}, e1{2, 0.5, 0}, e2{0.7, 0, 1.5};
        ChiSquareCase c;
        c.name = "parallelogram";
        c.grid = {0, 1, 0, 1};
        c.sample = [=](Vec2 u) -> std::optional<Vec2> {
            const Vec3 d = sampleParallelogram(corner, e1, e2, u) - corner;
            // Solve d = s e1 + t e2 by the normal equations (Cramer's rule).
            const double a = dot(e1, e1), b = dot(e1, e2), cc = dot(e2, e2), p = dot(d, e1), q = dot(d, e2);
            const double det = a * cc - b * b;
            return Vec2{(p * cc - q * b) / det, (q * a - p * b) / det};
        };
        c.density = [=](double, double) { return parallelogramPdf(e1, e2) * length(cross(e1, e2)); };
        cases.push_back(c);
    }
    cases.push_back(sphericalRectangleCase("rectangle overhead", {0, 0, 0}, {-0.5, -0.5, 1}, {1, 0, 0}, {0, 1, 0}));
    cases.push_back(sphericalRectangleCase("rectangle offset, point below", {0.3, -2, 4}, {1, 1, 1}, {3, 0, 0},
                                           {0, 0.5, 0}));
    cases.push_back(sphericalRectangleCase("rectangle tilted, large", {0.1, 0.2, 0.3}, {-2, -1, 0.5},
                                           normalize(Vec3{1, 1, 0}) * 4.0, normalize(Vec3{-1, 1, 1}) * 3.0));
    cases.push_back(sphericalRectangleCase("rectangle grazing", {0, 0, 0}, {0.5, -1, 0.02}, {2, 0, 0}, {0, 2, 0}));
    cases.push_back(sphericalRectangleCase("rectangle far and small", {0, 0, 0}, {30, 40, 50}, {0.5, 0, 0},
                                           {0, 0.2, 0}));
    for (const auto& name : filterNames()) cases.push_back(filterCase(name));
    return cases;
}

class ChiSquare : public ::testing::TestWithParam<int> {};

TEST_P(ChiSquare, SamplesFollowTheirDensity) {
    const auto cases = allCases();
    const ChiSquareCase& c = cases[static_cast<size_t>(GetParam())];
    const double alpha = sidakAlpha(0.01, static_cast<int>(cases.size()));
    const ChiSquareReport r = runChiSquare(c, 0xC41 + static_cast<uint64_t>(GetParam()));
    std::printf("[chi2] %-42s chi2=%9.1f dof=%5d p=%.4f  total pdf=%.7f\n", c.name.c_str(), r.result.statistic,
                r.result.dof, r.result.pValue, r.totalProbability);
    RecordProperty("p_value", std::to_string(r.result.pValue));
    EXPECT_EQ(r.invalidSamples, 0) << c.name;
    EXPECT_EQ(r.result.impossibleSamples, 0) << c.name << ": samples where the density is zero";
    EXPECT_NEAR(r.totalProbability, 1.0, 1e-5) << c.name << ": the density does not integrate to 1";
    EXPECT_GT(r.result.pValue, alpha) << c.name << " (Sidak-corrected alpha " << alpha << ")";
}

INSTANTIATE_TEST_SUITE_P(AllWarps, ChiSquare, ::testing::Range(0, static_cast<int>(allCases().size())),
                         [](const testing::TestParamInfo<int>& info) {
                             return test::testNameOf(allCases()[size_t(info.param)].name) + "_" +
                                    std::to_string(info.param);
                         });

// The harness itself must reject a wrong density: sampling u^2 on [0, 1]
// against a uniform density, and a cosine hemisphere against a uniform one.
TEST(ChiSquareHarness, RejectsWrongDensities) {
    ChiSquareCase skewed;
    skewed.name = "skewed";
    skewed.grid = {0, 1, 0, 1};
    skewed.sample = [](Vec2 u) -> std::optional<Vec2> { return Vec2{u.x * (0.8 + 0.2 * u.x), u.y}; };
    skewed.density = [](double, double) { return 1.0; };
    EXPECT_LT(runChiSquare(skewed, 1).result.pValue, 1e-6);

    const ChiSquareCase wrongPdf = directionCase("cosine vs uniform", {0, 0, 1}, -1.0, squareToCosineHemisphere,
                                                 [](const Vec3& w) { return w.z >= 0 ? uniformHemispherePdf() : 0.0; });
    EXPECT_LT(runChiSquare(wrongPdf, 2).result.pValue, 1e-6);
}

TEST(ChiSquareHarness, PValuesOfKnownQuantiles) {
    // Chi-square quantiles from standard tables.
    EXPECT_NEAR(chiSquarePValue(3.841, 1), 0.05, 1e-4);
    EXPECT_NEAR(chiSquarePValue(23.209, 10), 0.01, 1e-4);
    EXPECT_NEAR(chiSquarePValue(124.342, 100), 0.05, 1e-4);
    EXPECT_NEAR(chiSquarePValue(100.0, 100), 0.4812, 1e-3);
}

} // namespace
} // namespace drt::test
