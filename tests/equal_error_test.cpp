// The measuring logic of the performance instruments: time to a target error
// on a best curve, speed ratios, reference agreement (bias between two
// references), references averaged from parts, and the process runner.
#include "bench/agreement.h"
#include "bench/equal_error.h"
#include "bench/process.h"
#include "bench/reference.h"

#include <gtest/gtest.h>

#include <cmath>
#include <csignal>
#include <random>

using namespace drt;
using namespace drt::bench;

namespace {

// An image of `value` plus independent Gaussian noise of standard deviation `sigma`.
Image noisyImage(int width, int height, double value, double sigma, uint32_t seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0, sigma);
    Image image(width, height, 3);
    for (float& v : image.pixels)
        v = float(value + noise(rng));
    return image;
}

} // namespace

TEST(EqualError, TimeToReachInterpolatesLogLogOnTheBestCurve) {
    // error = 1e-3 / seconds: an unbiased estimator's curve. A dominated
    // setting (slower and worse) must not change the answer.
    const std::vector<SettingPoint> points = {
        {"1 s", 1, 1e-3}, {"dominated", 5, 5e-3}, {"10 s", 10, 1e-4}, {"100 s", 100, 1e-5}};
    const TimeToError t = timeToReach(points, 3e-4);
    ASSERT_EQ(t.kind, TimeToError::Kind::Interpolated);
    EXPECT_NEAR(t.seconds, 1e-3 / 3e-4, 1e-9);
    EXPECT_EQ(t.above, "1 s");
    EXPECT_EQ(t.below, "10 s");
    // On a point exactly.
    EXPECT_NEAR(timeToReach(points, 1e-4).seconds, 10, 1e-9);
    // A steeper segment: between (10 s, 1e-4) and (100 s, 1e-5) the slope is
    // -1 too; between unequal slopes the interpolation is still a straight
    // line in log-log space.
    const std::vector<SettingPoint> kinked = {{"a", 1, 1e-2}, {"b", 4, 1e-4}};
    // log t = log 1 + (log e - log 1e-2) / (log 1e-4 - log 1e-2) * log 4, at e = 1e-3: t = 2.
    EXPECT_NEAR(timeToReach(kinked, 1e-3).seconds, 2, 1e-9);
}

TEST(EqualError, TargetsOutsideTheCurveAreBoundsOrUnreached) {
    const std::vector<SettingPoint> points = {{"fast", 2, 1e-4}, {"slow", 8, 2e-5}};
    const TimeToError easy = timeToReach(points, 1e-3);
    EXPECT_EQ(easy.kind, TimeToError::Kind::AtMost);
    EXPECT_EQ(easy.seconds, 2);
    EXPECT_EQ(formatTime(easy), "<= 2.00 s");
    const TimeToError hard = timeToReach(points, 1e-5);
    EXPECT_EQ(hard.kind, TimeToError::Kind::NotReached);
    EXPECT_EQ(formatTime(hard), "not reached");
    EXPECT_EQ(timeToReach({}, 1e-4).kind, TimeToError::Kind::NotReached);
    // Failed runs (NaN error, zero time) are ignored rather than trusted.
    EXPECT_EQ(timeToReach({{"broken", 0, 1e-6}, {"nan", 1, NAN}}, 1e-4).kind, TimeToError::Kind::NotReached);
}

TEST(EqualError, SpeedRatiosCarryTheirBounds) {
    const TimeToError slow{TimeToError::Kind::Interpolated, 8, "", ""};
    const TimeToError fast{TimeToError::Kind::Interpolated, 2, "", ""};
    const TimeToError fastBound{TimeToError::Kind::AtMost, 2, "", ""};
    const TimeToError missing{TimeToError::Kind::NotReached, 0, "", ""};
    EXPECT_EQ(formatRatio(speedRatio(slow, fast)), "4.00");
    EXPECT_EQ(formatRatio(speedRatio(slow, fastBound)), ">= 4.00");
    EXPECT_EQ(formatRatio(speedRatio(fastBound, slow)), "<= 0.25");
    EXPECT_EQ(formatRatio(speedRatio(fastBound, fastBound)), "-");
    EXPECT_EQ(formatRatio(speedRatio(slow, missing)), "-");
}

TEST(EqualError, MedianPointTakesEachMedianApart) {
    const SettingPoint p = medianPoint("x", {3, 1, 2, 100}, {1e-3, 5e-4, 2e-3, 1e-4});
    EXPECT_EQ(p.setting, "x");
    EXPECT_DOUBLE_EQ(p.seconds, 2.5);
    EXPECT_DOUBLE_EQ(p.relMse, 7.5e-4);
    const std::vector<SettingPoint> front = bestCurve({{"a", 1, 1e-3}, {"b", 2, 2e-3}, {"c", 3, 1e-4}});
    ASSERT_EQ(front.size(), 2u);
    EXPECT_EQ(front[0].setting, "a");
    EXPECT_EQ(front[1].setting, "c");
}

TEST(ReferenceAgreement, IndependentNoiseAgrees) {
    const Image a = noisyImage(96, 64, 0.5, 0.01, 1);
    const Image b = noisyImage(96, 64, 0.5, 0.01, 2);
    const ReferenceAgreement r = compareReferences(a, b);
    EXPECT_TRUE(r.agree()) << formatAgreement(r, "a", "b");
    EXPECT_EQ(r.tiles, 6 * 4);
    EXPECT_EQ(r.materialTiles, 0);
    // relMSE of two independent noises: 2 sigma^2 / (0.25 + 0.01).
    EXPECT_NEAR(r.relMse, 2 * 1e-4 / 0.26, 0.1 * 2 * 1e-4 / 0.26);
    EXPECT_LT(std::fabs(r.relativeMeanDifference), 0.001);
}

TEST(ReferenceAgreement, ALocalBiasIsFoundInItsTile) {
    const Image b = noisyImage(96, 64, 0.5, 0.01, 2);
    Image a = noisyImage(96, 64, 0.5, 0.01, 1);
    // +4% in the tile at (32, 16): 16 x 16 pixels.
    for (int y = 16; y < 32; ++y)
        for (int x = 32; x < 48; ++x)
            for (int c = 0; c < 3; ++c)
                a.at(x, y, c) += 0.02f;
    const ReferenceAgreement r = compareReferences(a, b);
    EXPECT_FALSE(r.agree());
    EXPECT_EQ(r.materialTiles, 1);
    EXPECT_EQ(r.worstTile.x0, 32);
    EXPECT_EQ(r.worstTile.y0, 16);
    EXPECT_NEAR(r.worstTile.relativeMean, 0.02 / std::sqrt(0.25 + 0.01), 0.005);
    EXPECT_NE(formatAgreement(r, "a", "b").find("DISAGREE"), std::string::npos);
}

TEST(ReferenceAgreement, AGlobalBiasAndASmallSignificantOneAreTold) {
    const Image b = noisyImage(64, 64, 0.5, 0.01, 2);
    Image a = noisyImage(64, 64, 0.5, 0.01, 1);
    for (float& v : a.pixels)
        v *= 1.03f;
    const ReferenceAgreement global = compareReferences(a, b);
    EXPECT_FALSE(global.agree());
    EXPECT_NEAR(global.relativeMeanDifference, 0.015 / std::sqrt(0.26), 0.002);
    EXPECT_EQ(global.materialTiles, global.tiles);

    // 0.2%: every tile notices it (the noise is small), but it is below the
    // 1% tolerance, so the references agree.
    Image close = noisyImage(64, 64, 0.5, 0.001, 1);
    const Image closeReference = noisyImage(64, 64, 0.5, 0.001, 2);
    for (float& v : close.pixels)
        v *= 1.002f;
    const ReferenceAgreement small = compareReferences(close, closeReference);
    EXPECT_GT(small.significantTiles, small.tiles / 2);
    EXPECT_EQ(small.materialTiles, 0);
    EXPECT_TRUE(small.agree());

    EXPECT_FALSE(compareReferences(noisyImage(8, 8, 1, 0, 1), noisyImage(8, 9, 1, 0, 1)).agree());
}

TEST(AveragedReference, MeanAndVarianceOfTheMeanFromTheSpread) {
    std::vector<Image> parts;
    for (float v : {1.0f, 2.0f, 3.0f, 4.0f}) {
        Image part(2, 1, 3);
        for (float& p : part.pixels)
            p = v;
        part.at(1, 0, 2) = NAN; // a non-finite value never reaches the reference
        parts.push_back(part);
    }
    const AveragedImage averaged = averageImages(parts);
    EXPECT_FLOAT_EQ(averaged.mean.at(0, 0, 0), 2.5f);
    // sum (m_k - m)^2 = 2.25 + 0.25 + 0.25 + 2.25 = 5, / (K (K - 1)) = 5 / 12.
    EXPECT_FLOAT_EQ(averaged.varianceOfMean.at(0, 0, 1), 5.0f / 12.0f);
    EXPECT_EQ(averaged.mean.at(1, 0, 2), 0.0f);
    EXPECT_EQ(averaged.varianceOfMean.at(1, 0, 2), 0.0f);
    // Var / (r^2 + 0.01) averaged over the 6 values (one of them 0 / 0.01).
    const double expected = (5 * (5.0 / 12) / (6.25 + 0.01)) / 6;
    EXPECT_NEAR(referenceNoise(averaged.mean, averaged.varianceOfMean), expected, 1e-6);
    EXPECT_EQ(averageImages({parts[0]}).varianceOfMean.at(0, 0, 0), 0.0f);
}

TEST(ProcessRun, CapturesOutputStatusFolderAndEnvironment) {
    const ProcessRun run =
        runProcess({"sh", "-c", "echo out; echo err >&2; pwd; echo $DRT_TEST_VALUE; exit 3"}, "/tmp",
                   {"DRT_TEST_VALUE=forty-two"});
    ASSERT_TRUE(run.started);
    EXPECT_EQ(run.exitCode, 3);
    EXPECT_FALSE(run.succeeded());
    EXPECT_NE(run.output.find("out\n"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("err\n"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("/tmp\n"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("forty-two"), std::string::npos) << run.output;
    EXPECT_GT(run.peakRssMiB, 0);
    EXPECT_GE(run.wallSeconds, 0);

    const ProcessRun killed = runProcess({"sh", "-c", "kill -9 $$"});
    EXPECT_TRUE(killed.started);
    EXPECT_EQ(killed.signal, 9);
    EXPECT_EQ(killed.exitCode, -1);

    const ProcessRun slow = runProcess({"sleep", "30"}, "", {}, 0.2);
    EXPECT_TRUE(slow.timedOut);
    EXPECT_EQ(slow.signal, SIGKILL);
    EXPECT_LT(slow.wallSeconds, 20); // killed, not waited for
    EXPECT_FALSE(runProcess({"true"}, "", {}, 30).timedOut);

    const ProcessRun missing = runProcess({"/nonexistent/program"});
    EXPECT_FALSE(missing.started);
    EXPECT_FALSE(missing.succeeded());
    EXPECT_FALSE(runProcess({}).started);
    EXPECT_NE(currentExecutable(), "");
}
