// Adaptive sampling (render/render.cpp, "Adaptive sampling"): the stopping
// rule, its round ends, determinism, options from the scene and the command
// line, and the samples-per-pixel image. The bias test against a fixed-sample
// reference is in statistical/adaptive_test.cpp.
#include "render/render.h"
#include "render/tile_state.h"

#include "lang/load.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <cmath>
#include <limits>
#include <random>
#include <set>

namespace drt {
namespace {

// A red sphere on a grey floor before a flat sky: large smooth regions and edges.
const char* kSphereScene = R"(
camera { location <0, 1.5, -5> look_at <0, 0.8, 0> angle 50 }
light_source { <-4, 6, -5>, color rgb 1 }
background { color rgb <0.55, 0.7, 0.9> }
sphere { <0, 1, 0>, 1 pigment { color rgb <0.8, 0.1, 0.1> } finish { phong 0.6 } }
plane { y, 0 pigment { checker color rgb 0.2, color rgb 0.8 } }
)";

Scene parse(const std::string& text) {
    Diagnostics diagnostics;
    std::optional<Scene> scene = loadSceneText(text, "adaptive.drt", diagnostics);
    EXPECT_TRUE(scene) << diagnostics.formatAll();
    return scene ? *scene : Scene{};
}

RenderOptions adaptiveOptions(int w, int h, int minSpp, int maxSpp, double error) {
    RenderOptions o;
    o.width = w;
    o.height = h;
    o.threads = 1;
    o.adaptive = true;
    o.minSamplesPerPixel = minSpp;
    o.maxSamplesPerPixel = maxSpp;
    o.adaptiveError = error;
    return o;
}

TEST(Adaptive, FlatImageStopsEveryPixelAtTheMinimum) {
    Scene scene; // nothing but the background: every sample is the same colour
    scene.background = {0.3, 0.5, 0.7};
    const RenderResult r = render(scene, adaptiveOptions(8, 6, 8, 256, 0.01));
    for (float n : r.sampleCount.pixels) EXPECT_EQ(n, 8.0f);
    EXPECT_EQ(r.stats.pixelSamples, 8u * 6u * 8u);
    EXPECT_EQ(r.stats.minPixelSamples, 8);
    EXPECT_EQ(r.stats.maxPixelSamples, 8);
    EXPECT_TRUE(r.stats.effects.adaptive);
}

TEST(Adaptive, RoundsEndAtTheMinimumThenPowersOfTwoThenTheMaximum) {
    const Scene scene = parse(kSphereScene);
    // A target no pixel can meet with noise: every noisy pixel runs to the maximum
    // through the round ends 10, 16, 32, 64, 100.
    const RenderResult r = render(scene, adaptiveOptions(24, 18, 10, 100, 1e-9));
    const std::set<float> allowed{10, 16, 32, 64, 100};
    std::set<float> seen(r.sampleCount.pixels.begin(), r.sampleCount.pixels.end());
    for (float n : seen) EXPECT_TRUE(allowed.count(n)) << n;
    EXPECT_TRUE(seen.count(100)) << "edge pixels must reach the maximum";
    EXPECT_TRUE(seen.count(10)) << "flat sky pixels must stop at the minimum";
    EXPECT_EQ(r.stats.maxPixelSamples, 100);
    EXPECT_EQ(r.stats.minPixelSamples, 10);
    uint64_t total = 0;
    for (float n : r.sampleCount.pixels) total += uint64_t(n);
    EXPECT_EQ(total, r.stats.pixelSamples);
    EXPECT_EQ(r.stats.cameraRays, r.stats.pixelSamples); // no secondary rays in this scene
}

TEST(Adaptive, LooserTargetsTakeFewerSamples) {
    const Scene scene = parse(kSphereScene);
    const RenderResult tight = render(scene, adaptiveOptions(24, 18, 4, 512, 0.005));
    const RenderResult loose = render(scene, adaptiveOptions(24, 18, 4, 512, 0.1));
    EXPECT_LT(loose.stats.pixelSamples, tight.stats.pixelSamples);
    // And the guard on a pixel's own variance holds wherever a pixel stopped
    // before the maximum: var / n <= 16 T(n) (mean^2 + 0.01) in every channel,
    // T(n) = E^2 n / 16 the target at its n samples.
    for (int y = 0; y < 18; ++y)
        for (int x = 0; x < 24; ++x) {
            const double n = loose.sampleCount.at(x, y, 0);
            if (n >= 512) continue;
            const double target = 0.1 * 0.1 * n / kAdaptiveReferenceSamples;
            for (int c = 0; c < 3; ++c) {
                const double mean = loose.color.at(x, y, c), var = loose.variance.at(x, y, c);
                EXPECT_LE(var, 16 * target * (mean * mean + 0.01) * (1 + 1e-5)) << x << "," << y;
            }
        }
}

// The stopping rule itself (render/tile_state.cpp, decideNextRound), on pixel
// states set by hand: one 15x15 tile, error target E = 0.1, rounds 4, 8, ...;
// the pixels have taken kAdaptiveReferenceSamples, where the target is E^2.
class AdaptiveRule : public ::testing::Test {
protected:
    static constexpr double kTarget = 0.1 * 0.1;
    AdaptiveRule() : state_(options()) {}
    static RenderOptions options() {
        RenderOptions o = adaptiveOptions(15, 15, 4, 64, 0.1);
        o.tileSize = 15;
        return o;
    }
    void setAll(double error, double varianceError, int taken = kAdaptiveReferenceSamples) {
        for (int y = 0; y < 15; ++y)
            for (int x = 0; x < 15; ++x) {
                AdaptivePixel& p = state_.adaptivePixel(x, y);
                p.taken = taken;
                p.error = error;
                p.varianceError = varianceError;
            }
    }
    AdaptivePixel& at(int x, int y) { return state_.adaptivePixel(x, y); }
    // Ends the round; the pixels that sample in the next, as a set.
    std::set<std::pair<int, int>> endRound() {
        state_.completeTile(0, TileCounts{});
        std::set<std::pair<int, int>> active;
        for (int y = 0; y < 15; ++y)
            for (int x = 0; x < 15; ++x)
                if (state_.adaptivePixel(x, y).active) active.insert({x, y});
        return active;
    }
    RenderState state_;
};

TEST_F(AdaptiveRule, APixelWhoseOwnSamplesAgreeSamplesAgainInANoisyNeighbourhood) {
    setAll(4 * kTarget, 0);
    at(7, 7).error = 0; // its halves agree by chance: a mean of 24/25 of 4 E^2 is still above E^2
    EXPECT_TRUE(endRound().count({7, 7}));
    EXPECT_EQ(state_.round(), 1);
}

TEST_F(AdaptiveRule, EveryPixelStopsWhenItsNeighbourhoodMeetsTheTarget) {
    setAll(0.5 * kTarget, 0);
    at(7, 7).error = 10 * kTarget; // one noisy pixel among quiet ones: the 5x5 mean is 0.88 E^2
    EXPECT_TRUE(endRound().empty());
    EXPECT_TRUE(state_.finished());
}

TEST_F(AdaptiveRule, APixelFarAboveTheTargetOnItsOwnSamplesAgain) {
    setAll(0, 0);
    at(3, 4).varianceError = 17 * kTarget;
    EXPECT_EQ(endRound(), (std::set<std::pair<int, int>>{{3, 4}}));
}

// The target is E^2 n / 16 at n samples: a pixel's next round costs n samples
// and takes about half its error off, so a pixel with more samples stops at a
// proportionally larger error.
TEST_F(AdaptiveRule, TheTargetGrowsInProportionToTheSamplesTaken) {
    setAll(1.5 * kTarget, 0, 32); // at 32 samples the target is 2 E^2
    EXPECT_TRUE(endRound().empty());
}

TEST_F(AdaptiveRule, APixelWithFewerSamplesThanTheReferenceMeetsASmallerTarget) {
    setAll(0.3 * kTarget, 0, 4); // at 4 samples the target is E^2 / 4
    EXPECT_EQ(endRound().size(), 15u * 15u);
}

TEST_F(AdaptiveRule, TheTargetIsThePixelsOwnAtItsOwnSampleCount) {
    setAll(0.75 * kTarget, 0, 8); // E^2 / 2 at 8 samples: every pixel samples again
    for (int y = 5; y <= 9; ++y)
        for (int x = 5; x <= 9; ++x) at(x, y).taken = 16; // E^2 here: these stop
    const std::set<std::pair<int, int>> active = endRound();
    for (int y = 0; y < 15; ++y)
        for (int x = 0; x < 15; ++x)
            EXPECT_EQ(active.count({x, y}) == 1, !(x >= 5 && x <= 9 && y >= 5 && y <= 9)) << x << "," << y;
}

TEST_F(AdaptiveRule, TheOwnVarianceGuardScalesWithTheTarget) {
    setAll(0, 20 * kTarget, 32); // 16 T(32) = 32 E^2: under the guard
    at(3, 4).varianceError = 33 * kTarget;
    EXPECT_EQ(endRound(), (std::set<std::pair<int, int>>{{3, 4}}));
}

TEST_F(AdaptiveRule, AnUnknownOrNonFiniteErrorKeepsItsNeighbourhoodSampling) {
    setAll(0, 0);
    at(2, 2).error = std::numeric_limits<double>::infinity(); // halves not known
    at(12, 12).error = std::numeric_limits<double>::quiet_NaN();
    const std::set<std::pair<int, int>> active = endRound();
    for (int y = 0; y < 15; ++y)
        for (int x = 0; x < 15; ++x) {
            const bool near = (std::abs(x - 2) <= 2 && std::abs(y - 2) <= 2) ||
                              (std::abs(x - 12) <= 2 && std::abs(y - 12) <= 2);
            EXPECT_EQ(active.count({x, y}) == 1, near) << x << "," << y;
        }
}

TEST_F(AdaptiveRule, AStoppedPixelNeverSamplesAgainButStillCountsInItsNeighbours) {
    setAll(0, 0);
    at(7, 7).active = false;
    at(7, 7).error = 100 * kTarget; // stopped earlier (say at the last round's decision)
    const std::set<std::pair<int, int>> active = endRound();
    EXPECT_FALSE(active.count({7, 7}));
    EXPECT_TRUE(active.count({6, 7}));
    EXPECT_TRUE(active.count({9, 9}));
    EXPECT_FALSE(active.count({10, 7}));
}

// Round after round the rule copies again only the errors of the pixels it
// left active (the others have not sampled): each decision must be the one a
// fresh state, copying every pixel, makes from the same pixels.
TEST(AdaptiveRuleRounds, EachRoundDecidesAsAFreshStateWouldFromTheSamePixels) {
    RenderOptions o = adaptiveOptions(40, 30, 4, 1 << 20, 0.1);
    o.tileSize = 8;
    RenderState rounds(o);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int decided = 0;
    for (int round = 0; round < 8 && !rounds.finished(); ++round) {
        // The round's samples: new errors for the pixels that take part, above
        // their target (E^2 n / 16) on the left and below it on the right, the
        // noisy part narrowing round by round.
        const int taken = 4 << round;
        const int noisyBelow = 40 - 6 * (round + 1);
        for (int y = 0; y < 30; ++y)
            for (int x = 0; x < 40; ++x) {
                AdaptivePixel& p = rounds.adaptivePixel(x, y);
                if (!p.active) continue;
                p.taken = taken;
                p.error = 0.01 * taken / 16 * (x < noisyBelow ? 3.0 : 0.8) * unit(rng);
                p.varianceError = 0.01 * taken / 16 * (unit(rng) < 0.02 ? 20.0 : 0.5) * unit(rng);
            }
        RenderState fresh(o);
        for (int y = 0; y < 30; ++y)
            for (int x = 0; x < 40; ++x) fresh.adaptivePixel(x, y) = rounds.adaptivePixel(x, y);
        for (int t = 0; t < rounds.tileCount(); ++t) {
            rounds.completeTile(t, TileCounts{});
            fresh.completeTile(t, TileCounts{});
        }
        ASSERT_EQ(rounds.finished(), fresh.finished()) << "round " << round;
        int active = 0;
        for (int y = 0; y < 30; ++y)
            for (int x = 0; x < 40; ++x) {
                ASSERT_EQ(rounds.adaptivePixel(x, y).active, fresh.adaptivePixel(x, y).active)
                    << "round " << round << " pixel " << x << "," << y;
                active += rounds.adaptivePixel(x, y).active ? 1 : 0;
            }
        if (active > 0 && active < 40 * 30) ++decided; // a round that stopped some pixels and not others
    }
    EXPECT_GE(decided, 3); // the rounds exercised the rule
}

TEST(Adaptive, ImageIsBitIdenticalForAnyThreadCountAndTileSize) {
    const Scene scene = parse(kSphereScene);
    RenderOptions one = adaptiveOptions(40, 30, 4, 128, 0.02);
    RenderOptions many = one;
    many.threads = 3;
    many.tileSize = 7;
    const RenderResult a = render(scene, one), b = render(scene, many);
    EXPECT_EQ(a.color.pixels, b.color.pixels);
    EXPECT_EQ(a.variance.pixels, b.variance.pixels);
    EXPECT_EQ(a.sampleCount.pixels, b.sampleCount.pixels);
    EXPECT_EQ(a.stats.totalRays(), b.stats.totalRays());
}

TEST(Adaptive, FixedSamplingRecordsItsCountEverywhere) {
    Scene scene;
    RenderOptions o;
    o.width = 5;
    o.height = 4;
    o.samplesPerPixel = 3;
    const RenderResult r = render(scene, o);
    for (float n : r.sampleCount.pixels) EXPECT_EQ(n, 3.0f);
    EXPECT_EQ(r.stats.pixelSamples, 60u);
    EXPECT_FALSE(r.stats.effects.adaptive);
    EXPECT_TRUE(r.stats.effects.antialiasing);
}

TEST(Adaptive, InvalidOptionsAreRenderErrors) {
    const Scene scene;
    EXPECT_THROW(render(scene, adaptiveOptions(4, 4, 32, 16, 0.02)), RenderError); // max < min
    EXPECT_THROW(render(scene, adaptiveOptions(4, 4, 0, 16, 0.02)), RenderError);
    EXPECT_THROW(render(scene, adaptiveOptions(4, 4, 4, 16, 0)), RenderError);
    EXPECT_THROW(render(scene, adaptiveOptions(4, 4, 4, 16, -1)), RenderError);
    EXPECT_THROW(render(scene, adaptiveOptions(4, 4, 4, (1 << 24) + 1, 0.02)), RenderError);
}

TEST(Adaptive, SceneBlockSetsTheOptionsAndTheCommandLineOverridesThem) {
    const Scene scene = parse("render { samples 4 adaptive { error 0.05 min_samples 8 max_samples 64 } }");
    RenderOptions o = resolveRenderOptions(scene.render);
    EXPECT_TRUE(o.adaptive);
    EXPECT_EQ(o.adaptiveError, 0.05);
    EXPECT_EQ(o.minSamplesPerPixel, 8);
    EXPECT_EQ(o.maxSamplesPerPixel, 64);
    RenderSettings overrides;
    overrides.adaptive = false;
    overrides.maxSamplesPerPixel = 32;
    o = resolveRenderOptions(overlaySettings(scene.render, overrides));
    EXPECT_FALSE(o.adaptive);
    EXPECT_EQ(o.maxSamplesPerPixel, 32);

    const Scene bare = parse("render { adaptive }");
    o = resolveRenderOptions(bare.render);
    EXPECT_TRUE(o.adaptive);
    EXPECT_EQ(o.minSamplesPerPixel, RenderOptions{}.minSamplesPerPixel);
    EXPECT_FALSE(resolveRenderOptions(RenderSettings{}).adaptive);
}

TEST(Adaptive, BadSceneValuesAreErrorsWithALocation) {
    const auto errors = [](const std::string& text) {
        Diagnostics diagnostics;
        EXPECT_FALSE(loadSceneText(text, "bad.drt", diagnostics));
        return diagnostics.formatAll();
    };
    EXPECT_NE(errors("render {\n  adaptive { min_samples 64 max_samples 8 }\n}").find("bad.drt:2:3"),
              std::string::npos);
    EXPECT_NE(errors("render { adaptive { error 0 } }").find("'error' must be positive"), std::string::npos);
    EXPECT_NE(errors("render { adaptive { max_samples 0 } }").find("'max_samples'"), std::string::npos);
    EXPECT_NE(errors("render { adaptive { eror 0.1 } }").find("error"), std::string::npos);
}

TEST(Adaptive, CommandLineWritesTheSamplesPerPixelImageAndReportsIt) {
    const std::string dir = test::tempDir();
    const std::string scene = test::writeFile(dir + "/s.drt", std::string(kSphereScene));
    const test::CommandResult r =
        test::runDrt("render '" + scene + "' -o '" + dir + "/out.exr' --width 24 --height 18 --adaptive "
                     "--adaptive-error 0.05 --min-spp 4 --max-spp 64 --spp-image '" + dir + "/spp.exr'");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("adaptive"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("effects: AA, adaptive"), std::string::npos) << r.err;
    Image counts;
    ASSERT_EQ(readImage(dir + "/spp.exr", counts), "");
    ASSERT_EQ(counts.width, 24);
    const auto [lo, hi] = std::minmax_element(counts.pixels.begin(), counts.pixels.end());
    EXPECT_EQ(*lo, 4.0f);
    EXPECT_LE(*hi, 64.0f);
    EXPECT_GT(*hi, 4.0f);

    const test::CommandResult bad = test::runDrt("render '" + scene + "' -o '" + dir +
                                                 "/x.exr' --adaptive --min-spp 64 --max-spp 8");
    EXPECT_EQ(bad.exitCode, 1) << bad.err;
    EXPECT_NE(bad.err.find("below the minimum"), std::string::npos) << bad.err;
}

TEST(LightSamples, SceneSettingCommandLineAndBadValues) {
    // render { light_samples K } sets RenderOptions::lightSamples; the
    // command line overrides it; out-of-range values are located errors.
    const Scene scene = parse("render { samples 4 light_samples 3 }");
    EXPECT_EQ(resolveRenderOptions(scene.render).lightSamples, 3);
    EXPECT_EQ(resolveRenderOptions(RenderSettings{}).lightSamples, 1);
    RenderSettings overrides;
    overrides.lightSamples = 6;
    EXPECT_EQ(resolveRenderOptions(overlaySettings(scene.render, overrides)).lightSamples, 6);

    const auto errors = [](const std::string& text) {
        Diagnostics diagnostics;
        EXPECT_FALSE(loadSceneText(text, "bad.drt", diagnostics));
        return diagnostics.formatAll();
    };
    const std::string zero = errors("render {\n  light_samples 0\n}");
    EXPECT_NE(zero.find("bad.drt:2:17"), std::string::npos) << zero;
    EXPECT_NE(zero.find("'light_samples' must be between 1 and 1024"), std::string::npos) << zero;
    EXPECT_NE(zero.find("^"), std::string::npos) << zero;
    EXPECT_NE(errors("render { light_samples 1025 }").find("'light_samples' must be between 1 and 1024"),
              std::string::npos);
    EXPECT_NE(errors("render { light_samples 2.5 }").find("light_samples"), std::string::npos);
    EXPECT_NE(errors("render { light_sample 2 }").find("light_samples"), std::string::npos); // suggested

    // From the command line: K shadow rays per camera sample (the --stats
    // file counts them), and a K out of range is refused with no output file.
    const std::string dir = test::tempDir();
    // Every pixel sees the floor, and the whole light is above it: each hit
    // sends exactly K rays.
    const std::string text = "camera { location <0, 5, 0> look_at <0, 0, 0.01> angle 40 }\n"
                             "light_source { <1, 6, 0>, color rgb 1 area_light <1, 0, 0>, <0, 0, 1>, 3, 3 }\n"
                             "plane { y, 0 pigment { color rgb 0.8 } }\n";
    const std::string file = test::writeFile(dir + "/s.drt", text);
    std::string counts[2];
    for (const int k : {1, 4}) {
        const std::string stats = dir + "/stats" + std::to_string(k) + ".json";
        const test::CommandResult r =
            test::runDrt("render '" + file + "' -o '" + dir + "/out.exr' --width 8 --height 6 --spp 2 -q --stats '" +
                         stats + "' --light-samples " + std::to_string(k));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        std::ifstream in(stats);
        const std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        EXPECT_NE(json.find("\"shadow_rays\""), std::string::npos) << json;
        counts[k == 1 ? 0 : 1] = json;
    }
    const auto shadowRays = [](const std::string& json) {
        const size_t at = json.find("\"shadow_rays\"");
        return std::stoull(json.substr(json.find(':', at) + 1));
    };
    EXPECT_EQ(shadowRays(counts[0]), 8u * 6 * 2);
    EXPECT_EQ(shadowRays(counts[1]), 4u * 8 * 6 * 2);
    for (const char* bad : {"0", "1025", "x"}) {
        const test::CommandResult r = test::runDrt("render '" + file + "' -o '" + dir + "/bad.exr' --light-samples " +
                                                   std::string(bad));
        EXPECT_NE(r.exitCode, 0) << bad;
        EXPECT_NE(r.err.find("--light-samples"), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir + "/bad.exr"));
    }
}

} // namespace
} // namespace drt
