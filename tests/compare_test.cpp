// Tests of drt's image comparison on synthetic images with known answers
// (docs/golden-tests.md): exact metrics on hand-made images, idiff-style thresholds, and the
// statistical mode's power and false-alarm rate.
#include "cli/commands.h"
#include "compare/compare.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <sstream>

namespace drt {
namespace {

Image constantImage(int w, int h, float value) {
    Image image(w, h, 3);
    for (float& v : image.pixels)
        v = value;
    return image;
}

// reference + (1 + relativeBias) scaling inside [x0, x0+bw) x [y0, y0+bh),
// plus zero-mean Gaussian noise of standard deviation sigma everywhere.
Image noisyCopy(const Image& reference, double sigma, uint64_t seed, double relativeBias = 0, int x0 = 0,
                int y0 = 0, int bw = 1 << 20, int bh = 1 << 20) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> normal(0.0, sigma);
    Image out = reference;
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const bool biased = x >= x0 && x < x0 + bw && y >= y0 && y < y0 + bh;
                out.at(x, y, c) =
                    float(reference.at(x, y, c) * (biased ? 1 + relativeBias : 1) + normal(rng));
            }
    return out;
}

TEST(CompareMetrics, ExactValuesOnATwoPixelImage) {
    Image reference(2, 1, 3), candidate(2, 1, 3);
    for (int c = 0; c < 3; ++c)
        reference.at(0, 0, c) = candidate.at(0, 0, c) = 0.5f;
    reference.at(1, 0, 0) = 0.5f;
    candidate.at(1, 0, 0) = 1.0f; // one error of +0.5 among 6 values
    CompareOptions options;
    options.failThreshold = 0.1;
    const CompareResult r = compareImages(candidate, reference, options);
    EXPECT_NEAR(r.rmse, std::sqrt(0.25 / 6), 1e-12);
    EXPECT_NEAR(r.relMse, 0.25 / (0.25 + 0.01) / 6, 1e-12);
    EXPECT_NEAR(r.robustRelMse, r.relMse, 1e-12); // fewer than 1000 pixels: nothing dropped
    EXPECT_NEAR(r.meanSignedError, 0.5 / 6, 1e-12);
    EXPECT_NEAR(r.meanAbsoluteError, 0.5 / 6, 1e-12);
    EXPECT_DOUBLE_EQ(r.maxError, 0.5);
    EXPECT_EQ(r.maxErrorX, 1);
    EXPECT_EQ(r.maxErrorY, 0);
    EXPECT_EQ(r.maxErrorChannel, 0);
    // Tonemapped: sRGB(1) - sRGB(0.5) = 1 - 0.7353569 (IEC 61966-2-1 curve).
    const double toneError = 1 - 0.7353569;
    EXPECT_NEAR(r.psnr, 10 * std::log10(6 / (toneError * toneError)), 1e-4);
    EXPECT_EQ(r.nonFinitePixels, 0);
    EXPECT_EQ(r.failingPixels, 1);
    EXPECT_EQ(r.status, CompareStatus::Fail);
}

TEST(CompareMetrics, SignedErrorSeesBiasThatCancelsNowhere) {
    Image reference = constantImage(4, 4, 0.25f);
    Image lower = constantImage(4, 4, 0.15f);
    const CompareResult r = compareImages(lower, reference);
    EXPECT_NEAR(r.meanSignedError, -0.1, 1e-6);
    EXPECT_NEAR(r.meanAbsoluteError, 0.1, 1e-6);
}

TEST(CompareMetrics, IdenticalImagesPassWithInfinitePsnr) {
    const Image image = noisyCopy(constantImage(5, 3, 0.3f), 0.1, 7);
    const CompareResult r = compareImages(image, image);
    EXPECT_EQ(r.status, CompareStatus::Pass);
    EXPECT_EQ(r.rmse, 0);
    EXPECT_EQ(r.failingPixels, 0);
    EXPECT_TRUE(std::isinf(r.psnr));
}

TEST(CompareMetrics, RobustRelMseDropsTheWorstTenthOfAPercent) {
    const Image reference = constantImage(50, 40, 0.5f); // 2000 pixels: the 2 worst are dropped
    Image candidate = reference;
    candidate.at(3, 4, 0) = 100.0f;
    candidate.at(10, 20, 1) = 50.0f;
    CompareResult r = compareImages(candidate, reference);
    EXPECT_GT(r.relMse, 1.0);
    EXPECT_EQ(r.robustRelMse, 0.0);
    candidate.at(30, 30, 2) = 0.6f; // a third, smaller error is kept
    r = compareImages(candidate, reference);
    EXPECT_NEAR(r.robustRelMse, 0.01 / 0.26 / 3 / 1998, 1e-9);
}

TEST(CompareThresholds, FailPercentAndWarnFollowIdiff) {
    const Image reference = constantImage(10, 10, 0.5f);
    Image candidate = reference;
    for (int x = 0; x < 3; ++x)
        candidate.at(x, 0, 1) = 0.6f; // 3% of pixels off by 0.1
    CompareOptions options;
    options.failThreshold = 0.05;
    options.warnThreshold = 0.05;
    options.failPercent = 2.5;
    EXPECT_EQ(compareImages(candidate, reference, options).status, CompareStatus::Fail);
    options.failPercent = 3; // "more than 3%" fails, exactly 3% does not
    options.warnPercent = 1;
    CompareResult r = compareImages(candidate, reference, options);
    EXPECT_EQ(r.status, CompareStatus::Warn); // warned although nothing failed (unlike idiff)
    EXPECT_EQ(r.failingPixels, 3);
    options.warnPercent = 5;
    EXPECT_EQ(compareImages(candidate, reference, options).status, CompareStatus::Pass);
    options.failThreshold = 0.2; // errors under the threshold do not count
    options.failPercent = 0;
    EXPECT_EQ(compareImages(candidate, reference, options).failingPixels, 0);
}

TEST(CompareThresholds, OneNanFailsWhateverTheThresholds) {
    const Image reference = constantImage(8, 8, 0.5f);
    Image candidate = reference;
    candidate.at(2, 5, 1) = std::numeric_limits<float>::quiet_NaN();
    CompareOptions lax;
    lax.failThreshold = lax.warnThreshold = 1e30;
    lax.failPercent = lax.warnPercent = 100;
    CompareResult r = compareImages(candidate, reference, lax);
    EXPECT_EQ(r.nonFinitePixels, 1);
    EXPECT_EQ(r.status, CompareStatus::Fail);
    EXPECT_TRUE(std::isfinite(r.rmse)); // the metrics skip the bad pixel
    Image infinite = reference;
    infinite.at(0, 0, 0) = std::numeric_limits<float>::infinity();
    EXPECT_EQ(compareImages(reference, infinite, lax).status, CompareStatus::Fail);
    // Also in statistical mode.
    const Image variance = constantImage(8, 8, 1.0f);
    EXPECT_EQ(compareImages(candidate, reference, lax, {&variance, nullptr}).status, CompareStatus::Fail);
}

TEST(CompareThresholds, SizeMismatch) {
    const CompareResult r = compareImages(constantImage(4, 4, 0), constantImage(4, 5, 0));
    EXPECT_EQ(r.status, CompareStatus::SizeMismatch);
    EXPECT_EQ(static_cast<int>(r.status), 3);
    const Image variance = constantImage(3, 4, 1);
    EXPECT_EQ(compareImages(constantImage(4, 4, 0), constantImage(4, 4, 0), {}, {&variance, nullptr}).status,
              CompareStatus::SizeMismatch);
}

TEST(CompareStatistics, NormalQuantilesAndSidak) {
    EXPECT_NEAR(twoSidedNormalQuantile(0.05), 1.959964, 1e-5);
    EXPECT_NEAR(twoSidedNormalQuantile(0.01), 2.575829, 1e-5);
    EXPECT_NEAR(sidakAlpha(0.05, 2), 1 - std::sqrt(0.95), 1e-12);
    EXPECT_DOUBLE_EQ(sidakAlpha(0.01, 1), 0.01);
    // Tiny per-test alphas keep their precision.
    EXPECT_NEAR(sidakAlpha(0.01, 1000000) / (-std::log(0.99) / 1e6), 1.0, 1e-7);
}

// Statistical tests over 200 fixed seeds. Under the null hypothesis each run
// raises a false alarm with probability <= alpha = 0.01, so about 2 in 200;
// P(more than 8) < 1e-4 for Binomial(200, 0.01).
TEST(CompareStatistics, ZeroMeanNoiseWithMatchingVariancePasses) {
    const double sigma = 0.05;
    const Image reference = constantImage(32, 32, 0.5f);
    const Image variance = constantImage(32, 32, float(sigma * sigma));
    int failures = 0;
    for (uint64_t seed = 0; seed < 200; ++seed) {
        const CompareResult r =
            compareImages(noisyCopy(reference, sigma, seed), reference, {}, {&variance, nullptr});
        EXPECT_TRUE(r.statistical);
        EXPECT_EQ(r.tileTests, 16 * 3);
        failures += r.status != CompareStatus::Pass;
    }
    EXPECT_LE(failures, 8);
    // The same noise fails idiff-style thresholds: they measure noise, not bias.
    CompareOptions thresholds;
    thresholds.failThreshold = 0.1;
    EXPECT_EQ(compareImages(noisyCopy(reference, sigma, 1), reference, thresholds).status,
              CompareStatus::Fail);
}

// The candidate's variance works the same way as the reference's.
TEST(CompareStatistics, CandidateVarianceAlsoDecides) {
    const double sigma = 0.05;
    const Image reference = constantImage(32, 32, 0.5f);
    const Image variance = constantImage(32, 32, float(sigma * sigma));
    int failures = 0;
    for (uint64_t seed = 0; seed < 200; ++seed)
        failures +=
            compareImages(noisyCopy(reference, sigma, seed), reference, {}, {nullptr, &variance}).status !=
            CompareStatus::Pass;
    EXPECT_LE(failures, 8);
}

// A 1% bias on 64x64 pixels of value 0.5 with noise sigma 0.05: the global
// mean error 0.005 has standard deviation 0.05 / 64, z = 6.4 per channel,
// far above the threshold (about 2.9), so every seed must fail.
TEST(CompareStatistics, OnePercentGlobalBiasFails) {
    const double sigma = 0.05;
    const Image reference = constantImage(64, 64, 0.5f);
    const Image variance = constantImage(64, 64, float(sigma * sigma));
    for (uint64_t seed = 0; seed < 20; ++seed) {
        const CompareResult r =
            compareImages(noisyCopy(reference, sigma, seed, 0.01), reference, {}, {&variance, nullptr});
        EXPECT_EQ(r.status, CompareStatus::Fail) << "seed " << seed;
        for (double z : r.globalZ)
            EXPECT_GT(z, r.globalZThreshold);
        // A per-pixel threshold at 6 sigma does not see it.
        CompareOptions thresholds;
        thresholds.failThreshold = thresholds.warnThreshold = 0.3;
        EXPECT_EQ(compareImages(noisyCopy(reference, sigma, seed, 0.01), reference, thresholds).status,
                  CompareStatus::Pass);
    }
}

// A 5% bias in the 8x8 tile at (16, 24) with noise sigma 0.02: the tile's mean
// error 0.025 has standard deviation 0.02 / 8, z = 10, above the tile threshold
// (about 3.9 for 192 tests); the global z is only 1.25, so the tile test decides.
TEST(CompareStatistics, FivePercentBiasInOneTileFails) {
    const double sigma = 0.02;
    const Image reference = constantImage(64, 64, 0.5f);
    const Image variance = constantImage(64, 64, float(sigma * sigma));
    for (uint64_t seed = 0; seed < 20; ++seed) {
        const CompareResult r = compareImages(noisyCopy(reference, sigma, seed, 0.05, 16, 24, 8, 8),
                                              reference, {}, {&variance, nullptr});
        EXPECT_EQ(r.status, CompareStatus::Fail) << "seed " << seed;
        EXPECT_GE(r.failingTiles, 1);
        EXPECT_EQ(r.worstTile.x0, 16);
        EXPECT_EQ(r.worstTile.y0, 24);
        EXPECT_NEAR(r.worstTile.meanError, 0.025, 0.01);
    }
}

TEST(CompareStatistics, NoiselessIdenticalRegionsAreNotBiased) {
    const Image reference = constantImage(16, 16, 0.5f);
    const Image zeroVariance = constantImage(16, 16, 0.0f);
    EXPECT_EQ(compareImages(reference, reference, {}, {&zeroVariance, nullptr}).status, CompareStatus::Pass);
    Image candidate = reference;
    candidate.at(9, 9, 2) = 0.51f; // a difference where no noise is expected is a real one
    EXPECT_EQ(compareImages(candidate, reference, {}, {&zeroVariance, nullptr}).status, CompareStatus::Fail);
}

TEST(CompareReports, HeatmapMarksErrorsAndNonFinitePixels) {
    const Image reference = constantImage(3, 1, 0.5f);
    Image candidate = reference;
    candidate.at(1, 0, 0) = 0.7f;
    candidate.at(2, 0, 1) = std::numeric_limits<float>::quiet_NaN();
    const Image heat = errorHeatmap(candidate, reference);
    for (int c = 0; c < 3; ++c)
        EXPECT_EQ(heat.at(0, 0, c), 0.0f);                                   // no error: black
    EXPECT_GT(heat.at(1, 0, 0) + heat.at(1, 0, 1) + heat.at(1, 0, 2), 2.0f); // the largest error: near white
    EXPECT_EQ(heat.at(2, 0, 1), 1.0f);                                       // NaN: green
    EXPECT_EQ(heat.at(2, 0, 0), 0.0f);
}

TEST(CompareReports, ZMapIsSigned) {
    const Image reference = constantImage(3, 1, 0.5f);
    const Image variance = constantImage(3, 1, 0.01f);
    Image candidate = reference;
    candidate.at(0, 0, 0) = 0.9f; // z > 0: red
    candidate.at(2, 0, 0) = 0.1f; // z < 0: blue
    const Image z = zScoreMap(candidate, reference, {&variance, nullptr});
    EXPECT_GT(z.at(0, 0, 0), z.at(0, 0, 2));
    EXPECT_LT(z.at(2, 0, 0), z.at(2, 0, 2));
    EXPECT_EQ(z.at(1, 0, 0), z.at(1, 0, 2)); // z = 0: white
}

TEST(CompareReports, JsonHasTheFiguresAndNoInfinity) {
    const Image image = constantImage(2, 2, 0.5f);
    const std::string json = formatCompareJson(compareImages(image, image), "a.exr", "b \"q\".exr");
    EXPECT_NE(json.find("\"status\": \"PASS\""), std::string::npos) << json;
    EXPECT_NE(json.find("\"psnr\": null"), std::string::npos) << json;
    EXPECT_NE(json.find("\"reference\": \"b \\\"q\\\".exr\""), std::string::npos) << json;
    EXPECT_EQ(json.find("inf"), std::string::npos) << json;
    EXPECT_EQ(json.front(), '{');
}

// runCompare in-process: files through OpenImageIO, idiff's exit statuses.
TEST(CompareCommand, ExitStatusesFromFiles) {
    const std::string dir = test::tempDir();
    const Image reference = constantImage(8, 8, 0.5f);
    Image different = reference;
    different.at(1, 1, 1) = 0.9f;
    ASSERT_EQ(writeImage(dir + "/ref.exr", reference), "");
    ASSERT_EQ(writeImage(dir + "/same.exr", reference), "");
    ASSERT_EQ(writeImage(dir + "/different.exr", different), "");
    ASSERT_EQ(writeImage(dir + "/small.exr", constantImage(4, 8, 0.5f)), "");
    auto run = [&](const std::string& a, const std::string& b) {
        cli::CompareCommand command;
        command.candidate = dir + "/" + a;
        command.reference = dir + "/" + b;
        std::ostringstream out, err;
        return cli::runCompare(command, out, err);
    };
    EXPECT_EQ(run("same.exr", "ref.exr"), 0);
    EXPECT_EQ(run("different.exr", "ref.exr"), 2);
    EXPECT_EQ(run("small.exr", "ref.exr"), 3);
    EXPECT_EQ(run("missing.exr", "ref.exr"), 4);
    EXPECT_EQ(run("same.exr", "missing.exr"), 4);
}

} // namespace
} // namespace drt
