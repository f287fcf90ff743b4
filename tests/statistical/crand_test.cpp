// finish crand (POV-Ray's graininess): under a light straight above, a white
// floor with diffuse d and crand c shows d - U c per pixel sample, U uniform
// in [0, 1): mean d - c/2, variance c^2/12, within [d - c, d]. Deterministic
// per seed for any thread count. Fixed seeds; tolerances stated below.
#include "render/render.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace drt {
namespace {

constexpr double kDiffuse = 0.6;
constexpr double kCrand = 0.2;
constexpr int kSize = 64; // 4096 pixels, one sample each

Scene grainyFloor() {
    Scene s;
    // Straight down at the floor; the light 1e6 above makes cos(theta) = 1
    // within 1e-11 over the 8 x 8 view.
    s.camera.orthographic = true;
    s.camera.location = {0, 1, 0};
    s.camera.direction = {0, -1, 0};
    s.camera.up = {0, 0, 8};
    s.camera.right = Vec3(8, 0, 0);
    Object floor;
    floor.shape = Plane{{0, 1, 0}, 0};
    floor.texture.edit().pigment.color = ColorFT{Color(1)};
    floor.texture.edit().finish.ambient = Color(0);
    floor.texture.edit().finish.diffuse = kDiffuse;
    floor.texture.edit().finish.crand = kCrand;
    s.objects.push_back(floor);
    Light light;
    light.position = {0, 1e6, 0};
    s.lights.push_back(light);
    return s;
}

RenderResult renderFloor(uint64_t seed, int threads) {
    RenderOptions o;
    o.width = o.height = kSize;
    o.samplesPerPixel = 1;
    o.seed = seed;
    o.threads = threads;
    return render(grainyFloor(), o);
}

TEST(Crand, NoiseHasPovRaysMeanAndVariance) {
    for (uint64_t seed : {1u, 2u}) {
        const RenderResult r = renderFloor(seed, 1);
        const int n = kSize * kSize;
        double sum = 0, sumSq = 0, lo = INFINITY, hi = -INFINITY;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const double v = r.color.at(x, y, 0);
                sum += v;
                sumSq += v * v;
                lo = std::min(lo, v);
                hi = std::max(hi, v);
                EXPECT_EQ(v, r.color.at(x, y, 1)); // grey: the same U for every channel
            }
        const double mean = sum / n, variance = sumSq / n - mean * mean;
        // Mean d - c/2 = 0.5; standard error c / sqrt(12 n) = 9.0e-4: within 5 SE.
        EXPECT_NEAR(mean, kDiffuse - kCrand / 2, 4.5e-3) << seed;
        // Variance c^2/12 = 3.33e-3; for a uniform the sample variance has
        // standard error c^2 sqrt((1/80 - 1/144) / n) = 4.7e-5: within 5 SE.
        EXPECT_NEAR(variance, kCrand * kCrand / 12, 2.4e-4) << seed;
        EXPECT_GE(lo, kDiffuse - kCrand - 1e-6);
        EXPECT_LE(hi, kDiffuse + 1e-6);
    }
}

TEST(Crand, SameSeedSameImageForAnyThreadCount) {
    const RenderResult one = renderFloor(7, 1), four = renderFloor(7, 4), other = renderFloor(8, 1);
    EXPECT_TRUE(one.color.pixels == four.color.pixels);
    EXPECT_FALSE(one.color.pixels == other.color.pixels);
}

} // namespace
} // namespace drt
