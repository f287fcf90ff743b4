// The highlight lobe that area lights' multiple importance sampling draws
// directions from (render/shading.h): its draws must follow the density it
// reports, or the weights of lighting.cpp would be wrong.
#include "render/shading.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace drt {
namespace {

Finish highlightFinish(double phong, double phongSize, double specular, double roughness) {
    Finish f;
    f.diffuse = 0;
    f.phong = phong;
    f.phongSize = phongSize;
    f.specular = specular;
    f.roughness = roughness;
    return f;
}

// The integral of g over the unit sphere by the midpoint rule in a frame
// whose pole is `axis` (fine near the pole, where the lobes are).
template <class G> double sphereIntegral(const Vec3& axis, G&& g) {
    Vec3 t, b;
    orthonormalBasis(axis, t, b);
    const int nTheta = 3000, nPhi = 360;
    double sum = 0;
    for (int i = 0; i < nTheta; ++i) {
        const double theta = (i + 0.5) * kPi / nTheta;
        const double weight = std::sin(theta) * (kPi / nTheta) * (2 * kPi / nPhi);
        for (int j = 0; j < nPhi; ++j) {
            const double phi = (j + 0.5) * 2 * kPi / nPhi;
            const Vec3 d = axis * std::cos(theta) + t * (std::sin(theta) * std::cos(phi)) +
                           b * (std::sin(theta) * std::sin(phi));
            sum += g(d) * weight;
        }
    }
    return sum;
}

struct LobeCase {
    const char* name;
    Finish finish;
    double incidence; // degrees from the normal
};

TEST(HighlightLobe, DrawsFollowTheDensityItReports) {
    // For each finish and view: E[h(w) / p(w)] over the lobe's draws must be
    // the highlight's integral over the sphere (midpoint rule), within 4
    // standard errors of 200,000 draws plus 2e-3 of the value (the rule's own
    // error). A draw's reported density must match highlightLobePdf. And the
    // density must integrate to the share of draws that give a direction.
    const Vec3 normal{0, 0, 1};
    const LobeCase cases[] = {
        {"phong 40, head-on", highlightFinish(1, 40, 0, 0), 0},
        {"phong 300, 60 degrees", highlightFinish(0.7, 300, 0, 0), 60},
        {"specular 1/100, head-on", highlightFinish(0, 40, 1, 0.01), 0},
        {"specular 1/20, 50 degrees", highlightFinish(0, 40, 0.5, 0.05), 50},
        {"phong 80 + specular 1/300, 30 degrees", highlightFinish(0.4, 80, 0.9, 1.0 / 300), 30},
    };
    std::mt19937_64 rng(20261204);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (const LobeCase& c : cases) {
        const double a = c.incidence * kPi / 180;
        const Vec3 incoming{std::sin(a), 0, -std::cos(a)};
        const ColorFT white{Color(1), 0, 0};
        const Vec3 mirror = reflect(incoming, normal);
        const auto h = [&](const Vec3& l) { return highlightTerm(c.finish, white, normal, incoming, l).r; };
        const double exact = sphereIntegral(mirror, h);
        const double total = sphereIntegral(mirror, [&](const Vec3& l) {
            return highlightLobePdf(c.finish, normal, incoming, l);
        });
        const int n = 200000;
        double sum = 0, sumSquares = 0;
        int given = 0;
        for (int k = 0; k < n; ++k) {
            Vec3 l;
            const double y = [&] {
                if (!sampleHighlightLobe(c.finish, normal, incoming, {uniform(rng), uniform(rng)}, l)) return 0.0;
                ++given;
                EXPECT_NEAR(length(l), 1.0, 1e-12);
                const double p = highlightLobePdf(c.finish, normal, incoming, l);
                EXPECT_GT(p, 0) << c.name;
                return p > 0 ? h(l) / p : 0.0;
            }();
            sum += y;
            sumSquares += y * y;
        }
        const double mean = sum / n, error = std::sqrt(std::max(0.0, sumSquares / n - mean * mean) / n);
        std::printf("  %-40s integral %.6f, estimated %.6f (+- %.1e); density integrates to %.5f, draws given %.5f\n",
                    c.name, exact, mean, error, total, double(given) / n);
        EXPECT_GT(exact, 0) << c.name;
        EXPECT_LT(std::fabs(mean - exact), 4 * error + 2e-3 * exact) << c.name;
        EXPECT_NEAR(total, double(given) / n, 4 * std::sqrt(0.25 / n) + 2e-3) << c.name;
    }
}

TEST(HighlightLobe, OnlyFinishesWithAHighlightHaveOne) {
    EXPECT_FALSE(hasHighlight(highlightFinish(0, 40, 0, 0.05)));
    EXPECT_FALSE(hasHighlight(highlightFinish(0, 40, 1, 0)));
    EXPECT_TRUE(hasHighlight(highlightFinish(0.1, 40, 0, 0)));
    EXPECT_TRUE(hasHighlight(highlightFinish(0, 40, 0.1, 0.05)));
    // Without a lobe there is nothing to draw from.
    Vec3 l;
    EXPECT_FALSE(sampleHighlightLobe(highlightFinish(0, 40, 0, 0.05), {0, 0, 1}, {0, 0, -1}, {0.3, 0.6}, l));
}

} // namespace
} // namespace drt
