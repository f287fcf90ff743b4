// The tile API (render/tile_state.h) in one process: crop windows equal the
// same pixels of a full render, a render stopped after any number of tiles,
// saved and restored, finishes to the same image bit for bit (fixed and
// adaptive sampling), packets and saved states are checked; crop parsing and
// checkpoint refusals (distributed/).
#include "distributed/checkpoint.h"
#include "distributed/crop_merge.h"
#include "lang/load.h"
#include "render/tile_state.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <future>
#include <thread>

namespace drt {
namespace {

Scene loadExample(const std::string& name) {
    Diagnostics diagnostics;
    std::optional<Scene> scene = loadSceneFile(test::sourcePath("examples/" + name), diagnostics);
    EXPECT_TRUE(scene && !diagnostics.hasErrors()) << diagnostics.formatAll();
    return test::withAssets(std::move(*scene));
}

RenderOptions smallOptions(bool adaptive) {
    RenderOptions o;
    o.width = 40;
    o.height = 30;
    o.samplesPerPixel = 3;
    o.seed = 7;
    o.threads = 2;
    o.tileSize = 8;
    o.adaptive = adaptive;
    o.minSamplesPerPixel = 2;
    o.maxSamplesPerPixel = 32;
    o.adaptiveError = 0.05;
    return o;
}

// Pixel (x, y) of `full` equals pixel (x - x0, y - y0) of `crop`, in every channel.
void expectCropOf(const Image& full, const Image& crop, const PixelWindow& w, const std::string& what) {
    ASSERT_EQ(crop.width, w.width());
    ASSERT_EQ(crop.height, w.height());
    for (int y = w.y0; y < w.y1; ++y)
        for (int x = w.x0; x < w.x1; ++x)
            for (int c = 0; c < full.channels; ++c)
                ASSERT_EQ(full.at(x, y, c), crop.at(x - w.x0, y - w.y0, c))
                    << what << " pixel (" << x << ", " << y << ") channel " << c;
}

TEST(CropWindow, PixelsEqualTheFullRenderForFixedAndAdaptiveSampling) {
    const Scene scene = loadExample("soft_shadows.drt");
    for (bool adaptive : {false, true}) {
        SCOPED_TRACE(adaptive ? "adaptive" : "fixed");
        const RenderOptions options = smallOptions(adaptive);
        const RenderResult full = render(scene, options);
        // Inside, on each edge, a corner, one pixel, one column, and tiles cut anywhere.
        for (const PixelWindow w : {PixelWindow{5, 23, 4, 17}, PixelWindow{0, 40, 0, 30}, PixelWindow{33, 40, 25, 30},
                                    PixelWindow{17, 18, 9, 10}, PixelWindow{0, 1, 0, 30}, PixelWindow{3, 37, 21, 29}}) {
            RenderOptions cropped = options;
            cropped.crop = w;
            cropped.tileSize = 5;
            const RenderResult part = render(scene, cropped);
            EXPECT_EQ(part.window, w);
            const std::string what = formatWindow(w);
            expectCropOf(full.color, part.color, w, what + " colour");
            expectCropOf(full.variance, part.variance, w, what + " variance");
            expectCropOf(full.sampleCount, part.sampleCount, w, what + " samples");
        }
    }
}

TEST(CropWindow, AdaptiveCropsRenderAMarginOfTheNeighbourhoodRadiusPerRoundAfterTheFirst) {
    RenderOptions options = smallOptions(true);
    options.crop = PixelWindow{10, 20, 10, 20};
    const RenderState state(options);
    // min 2, max 32: rounds end at 2, 4, 8, 16, 32 -> 5 rounds, a margin of 4 radii of 2.
    static_assert(kAdaptiveRadius == 2);
    EXPECT_EQ(state.roundCount(), 5);
    EXPECT_EQ(state.window(), (PixelWindow{2, 28, 2, 28}));
    EXPECT_EQ(state.output(), (PixelWindow{10, 20, 10, 20}));
    options.crop = PixelWindow{0, 3, 28, 30}; // clipped by the image
    EXPECT_EQ(RenderState(options).window(), (PixelWindow{0, 11, 20, 30}));
}

// The first round takes at least two samples (one cannot estimate a pixel's
// error), unless max_samples is 1; min_samples 1 and 2 then render the same.
TEST(RenderState, TheFirstAdaptiveRoundTakesAtLeastTwoSamples) {
    RenderOptions options = smallOptions(true);
    options.minSamplesPerPixel = 1;
    const RenderState state(options);
    EXPECT_EQ(state.roundEnd(0), 2);
    EXPECT_EQ(state.roundCount(), 5); // 2, 4, 8, 16, 32
    options.maxSamplesPerPixel = 1;
    const RenderState single(options);
    EXPECT_EQ(single.roundCount(), 1);
    EXPECT_EQ(single.roundEnd(0), 1);
    options.minSamplesPerPixel = 3;
    options.maxSamplesPerPixel = 32;
    EXPECT_EQ(RenderState(options).roundEnd(0), 3);

    const Scene scene = loadExample("soft_shadows.drt");
    RenderOptions one = smallOptions(true), two = smallOptions(true);
    one.minSamplesPerPixel = 1;
    two.minSamplesPerPixel = 2;
    const RenderResult a = render(scene, one), b = render(scene, two);
    EXPECT_TRUE(a.color.pixels == b.color.pixels);
    EXPECT_TRUE(a.sampleCount.pixels == b.sampleCount.pixels);
}

TEST(CropWindow, OutsideTheImageIsARenderError) {
    RenderOptions options = smallOptions(false);
    options.crop = PixelWindow{30, 41, 0, 5};
    EXPECT_THROW(RenderState{options}, RenderError);
    options.crop = PixelWindow{5, 5, 0, 5};
    EXPECT_THROW(RenderState{options}, RenderError);
}

// Hands out at most `limit` tasks of the wrapped scheduler, then none: a
// render stopped after exactly `limit` tiles.
class StopAfter : public TileScheduler {
public:
    StopAfter(TileScheduler& inner, int limit) : inner_(inner), left_(limit) {}
    std::optional<TileTask> next() override {
        if (left_.fetch_sub(1) <= 0) return std::nullopt;
        return inner_.next();
    }
    void done(TileResult&& result) override { inner_.done(std::move(result)); }

private:
    TileScheduler& inner_;
    std::atomic<int> left_;
};

TEST(RenderState, StoppedSavedAndRestoredAtAnyTileFinishesBitIdentical) {
    const Scene scene = loadExample("soft_shadows.drt");
    for (bool adaptive : {false, true}) {
        SCOPED_TRACE(adaptive ? "adaptive" : "fixed");
        const RenderOptions options = smallOptions(adaptive);
        const RenderResult full = render(scene, options);
        const int tiles = RenderState(options).tileCount();
        // Adaptive: stops inside the first round, at its end, and in later rounds.
        for (const int stopAt : {0, 1, tiles / 2, tiles, tiles + 3, 3 * tiles}) {
            SCOPED_TRACE("stopped after " + std::to_string(stopAt) + " tasks");
            RenderState first(options);
            LocalTileScheduler scheduler(first, nullptr);
            StopAfter limited(scheduler, stopAt);
            renderTiles(scene, options, first, limited);
            std::vector<std::byte> saved;
            first.save(saved);

            RenderOptions resumed = options;
            resumed.threads = 1; // another thread count
            RenderState second(resumed);
            second.restore(saved.data(), saved.size());
            EXPECT_EQ(second.round(), first.round());
            EXPECT_EQ(second.tilesDoneThisRound(), first.tilesDoneThisRound());
            LocalTileScheduler rest(second, nullptr);
            const TileRenderInfo info = renderTiles(scene, resumed, second, rest);
            ASSERT_TRUE(second.finished());
            const RenderResult result = finishRender(scene, second, info);
            EXPECT_TRUE(result.color.pixels == full.color.pixels);
            EXPECT_TRUE(result.variance.pixels == full.variance.pixels);
            EXPECT_TRUE(result.sampleCount.pixels == full.sampleCount.pixels);
        }
    }
}

// After a round of adaptive sampling, each tile's work is the number of its
// pixels that sample again, a tile without any is done, and the scheduler
// hands out the rest busiest first (index order among equals); a state
// restored from its bytes counts the same.
TEST(RenderState, AdaptiveRoundsHandOutTheBusiestTilesFirst) {
    const Scene scene = loadExample("soft_shadows.drt");
    const RenderOptions options = smallOptions(true);
    for (int rounds = 1; rounds <= 3; ++rounds) {
        SCOPED_TRACE(std::to_string(rounds) + " rounds rendered");
        RenderState state(options);
        for (int r = 0; r < rounds; ++r) {
            LocalTileScheduler scheduler(state, nullptr);
            StopAfter oneRound(scheduler, state.tileCount() - state.tilesDoneThisRound());
            renderTiles(scene, options, state, oneRound);
        }
        ASSERT_EQ(state.round(), rounds);
        ASSERT_FALSE(state.finished());
        std::vector<std::byte> saved;
        state.save(saved);
        RenderState restored(options);
        restored.restore(saved.data(), saved.size());
        std::vector<int> expected; // the tiles still to render, busiest first
        int zero = 0;
        for (int index = 0; index < state.tileCount(); ++index) {
            const PixelWindow t = state.tile(index);
            int active = 0;
            for (int y = t.y0; y < t.y1; ++y)
                for (int x = t.x0; x < t.x1; ++x) active += state.adaptivePixel(x, y).active ? 1 : 0;
            EXPECT_EQ(state.tileWork(index), active) << "tile " << index;
            EXPECT_EQ(restored.tileWork(index), active) << "tile " << index;
            EXPECT_EQ(state.tileDone(index), active == 0) << "tile " << index;
            if (active > 0) expected.push_back(index);
            else ++zero;
        }
        std::stable_sort(expected.begin(), expected.end(),
                         [&](int a, int b) { return state.tileWork(a) > state.tileWork(b); });
        // The order says something only if the work differs between tiles.
        ASSERT_GT(expected.size(), 2u);
        EXPECT_NE(state.tileWork(expected.front()), state.tileWork(expected.back()));
        for (RenderState* s : {&state, &restored}) {
            LocalTileScheduler scheduler(*s, nullptr);
            std::vector<int> handedOut;
            while (std::optional<TileTask> task = scheduler.tryNext()) handedOut.push_back(task->tile);
            EXPECT_EQ(handedOut, expected);
        }
        if (rounds == 3) {
            EXPECT_GT(zero, 0) << "a later round skips tiles";
        }
    }
}

TEST(RenderState, CancelStopsHandingOutTilesAndRenderThrowsInterrupted) {
    const Scene scene = loadExample("minimal.drt");
    RenderOptions options = smallOptions(false);
    std::atomic<bool> cancel{true};
    options.cancel = &cancel;
    EXPECT_THROW(render(scene, options), RenderInterrupted);
    RenderState state(options);
    LocalTileScheduler scheduler(state, &cancel);
    EXPECT_FALSE(scheduler.next().has_value());
    EXPECT_TRUE(scheduler.over());
    EXPECT_EQ(state.tilesDoneThisRound(), 0);
}

// Hands out `count` tasks, from any thread.
class CountedTasks final : public TileScheduler {
public:
    explicit CountedTasks(int count) : left_(count) {}
    std::optional<TileTask> next() override {
        if (left_.fetch_sub(1) <= 0) return std::nullopt;
        ++handedOut;
        return TileTask{0, 0};
    }
    void done(TileResult&&) override {}
    std::atomic<int> handedOut{0};

private:
    std::atomic<int> left_;
};

// While busy, the first thread to ask waits and the others take every task;
// when not busy, nobody waits.
TEST(LendingScheduler, OneThreadWaitsWhileBusyAndTheOthersTakeEveryTask) {
    constexpr int kTasks = 60, kThreads = 3;
    for (const bool busy : {true, false}) {
        SCOPED_TRACE(busy ? "busy" : "not busy");
        CountedTasks inner(kTasks);
        std::promise<void> release;
        const std::shared_future<void> released = release.get_future().share();
        std::atomic<int> waits{0};
        std::thread::id held; // the thread that waited
        LendingScheduler lending(inner, [busy] { return busy; }, [&] {
            ++waits;
            held = std::this_thread::get_id();
            released.wait();
        });
        std::vector<int> taken(kThreads, 0);
        std::vector<std::thread::id> ids(kThreads);
        std::vector<std::thread> threads;
        for (int i = 0; i < kThreads; ++i)
            threads.emplace_back([&, i] {
                ids[size_t(i)] = std::this_thread::get_id();
                while (lending.next()) {
                    ++taken[size_t(i)];
                    lending.done(TileResult{});
                }
            });
        // The held thread is released only once the others took every task.
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
        while (inner.handedOut < kTasks && std::chrono::steady_clock::now() < deadline)
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        EXPECT_EQ(inner.handedOut.load(), kTasks);
        release.set_value();
        for (std::thread& t : threads) t.join();
        EXPECT_EQ(waits.load(), busy ? 1 : 0);
        EXPECT_EQ(lending.lent(), busy);
        // The held thread took none: it waited before its first task.
        const auto heldAt = std::find(ids.begin(), ids.end(), held);
        ASSERT_EQ(heldAt != ids.end(), busy);
        if (busy) {
            EXPECT_EQ(taken[size_t(heldAt - ids.begin())], 0);
        }
        int sum = 0;
        for (int n : taken) sum += n;
        EXPECT_EQ(sum, kTasks);
    }
}

// A render with a thread held for a while gives the same pixels.
TEST(LendingScheduler, ARenderWithAThreadHeldIsBitIdentical) {
    const Scene scene = loadExample("soft_shadows.drt");
    for (bool adaptive : {false, true}) {
        SCOPED_TRACE(adaptive ? "adaptive" : "fixed");
        const RenderOptions options = smallOptions(adaptive);
        const RenderResult full = render(scene, options);
        RenderState state(options);
        LocalTileScheduler local(state, nullptr);
        std::atomic<int> waits{0};
        LendingScheduler lending(local, [] { return true; }, [&] {
            ++waits;
            // Until the other thread has finished, or a while if the arena runs one thread.
            const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(300);
            while (!local.over() && std::chrono::steady_clock::now() < deadline)
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
        });
        const TileRenderInfo info = renderTiles(scene, options, state, lending);
        ASSERT_TRUE(state.finished());
        EXPECT_EQ(waits.load(), 1);
        const RenderResult result = finishRender(scene, state, info);
        EXPECT_TRUE(result.color.pixels == full.color.pixels);
        EXPECT_TRUE(result.variance.pixels == full.variance.pixels);
        EXPECT_TRUE(result.sampleCount.pixels == full.sampleCount.pixels);
    }
}

TEST(RenderState, PacketsRoundTripAndMalformedOnesAreRefused) {
    const Scene scene = loadExample("minimal.drt");
    for (bool adaptive : {false, true}) {
        const RenderOptions options = smallOptions(adaptive);
        RenderState a(options);
        LocalTileScheduler scheduler(a, nullptr);
        StopAfter one(scheduler, 1);
        renderTiles(scene, options, a, one);
        std::vector<std::byte> packet;
        a.packTile(0, packet);
        RenderState b(options);
        b.unpackTile(0, packet.data(), packet.size());
        std::vector<std::byte> again;
        b.packTile(0, again);
        EXPECT_TRUE(packet == again);
        EXPECT_THROW(b.unpackTile(0, packet.data(), packet.size() - 1), RenderError);
        EXPECT_THROW(b.unpackTile(a.tileCount(), packet.data(), packet.size()), RenderError);
    }
}

TEST(RenderState, RestoreRefusesAnotherTilingOrTruncatedBytes) {
    RenderOptions options = smallOptions(false);
    std::vector<std::byte> saved;
    RenderState(options).save(saved);
    RenderOptions other = options;
    other.tileSize = 16;
    RenderState differentTiles(other);
    EXPECT_THROW(differentTiles.restore(saved.data(), saved.size()), RenderError);
    RenderState same(options);
    EXPECT_THROW(same.restore(saved.data(), saved.size() - 4), RenderError);
    EXPECT_NO_THROW(same.restore(saved.data(), saved.size()));
}

TEST(CropWindow, ParsesPixelsAndFractions) {
    PixelWindow w;
    EXPECT_EQ(parseCropWindow("10,20,0,5", 40, 30, w), "");
    EXPECT_EQ(w, (PixelWindow{10, 20, 0, 5}));
    EXPECT_EQ(parseCropWindow("0.0,0.5,0.25,1.0", 40, 30, w), "");
    EXPECT_EQ(w, (PixelWindow{0, 20, 8, 30})); // 0.25 * 30 = 7.5 rounds to 8
    // Fractions that meet give windows that meet.
    PixelWindow left, right;
    EXPECT_EQ(parseCropWindow("0.0,0.3,0.0,1.0", 333, 10, left), "");
    EXPECT_EQ(parseCropWindow("0.3,1.0,0.0,1.0", 333, 10, right), "");
    EXPECT_EQ(left.x1, right.x0);
    EXPECT_NE(parseCropWindow("1,2,3", 40, 30, w).find("four values"), std::string::npos);
    EXPECT_NE(parseCropWindow("a,2,3,4", 40, 30, w).find("'a' is not a number"), std::string::npos);
    EXPECT_NE(parseCropWindow("0,50,0,5", 40, 30, w).find("not a non-empty part of the 40x30 image"),
              std::string::npos);
    EXPECT_NE(parseCropWindow("5,5,0,5", 40, 30, w).find("not a non-empty part"), std::string::npos);
    EXPECT_NE(parseCropWindow("0.0,1.5,0.0,1.0", 40, 30, w).find("between 0 and 1"), std::string::npos);
    EXPECT_NE(parseCropWindow("1,2.5,0,5", 40, 30, w).find("between 0 and 1"), std::string::npos);
}

TEST(Checkpoint, WrittenAndReadBackOrRefusedWithTheDifference) {
    const std::string dir = test::tempDir();
    const RenderOptions options = smallOptions(false);
    const RenderIdentity identity = renderIdentity(options, "1234");
    const std::string path = dir + "/out.png.drt-checkpoint";
    ASSERT_EQ(writeCheckpoint(path, makeCheckpoint(identity, RenderState(options))), "");
    Checkpoint read;
    ASSERT_EQ(readCheckpoint(path, read), "");
    EXPECT_EQ(read.identity, identity);
    EXPECT_EQ(read.tileSize, 8);
    EXPECT_EQ(checkpointMismatch(read, path, identity, options), "");

    RenderOptions seed = options;
    seed.seed = 8;
    EXPECT_NE(checkpointMismatch(read, path, renderIdentity(seed, "1234"), seed).find("seed=7 there, seed=8 here"),
              std::string::npos);
    RenderOptions split = options;
    split.lightSamples = 4;
    EXPECT_NE(checkpointMismatch(read, path, renderIdentity(split, "1234"), split).find("light_samples=4 here"),
              std::string::npos);
    RenderOptions size = options;
    size.width = 41;
    EXPECT_NE(checkpointMismatch(read, path, renderIdentity(size, "1234"), size).find("size=40x30 there, size=41x30"),
              std::string::npos);
    EXPECT_NE(checkpointMismatch(read, path, renderIdentity(options, "99"), options).find("another scene"),
              std::string::npos);
    RenderIdentity otherVersion = identity;
    otherVersion.version = "0.0.1";
    EXPECT_NE(checkpointMismatch(read, path, otherVersion, options).find("was made by drt"), std::string::npos);
    RenderOptions cropped = options;
    cropped.crop = PixelWindow{0, 10, 0, 10};
    EXPECT_NE(checkpointMismatch(read, path, identity, cropped).find("is of the whole image, this render is of the "
                                                                     "crop 0,10,0,10"),
              std::string::npos);

    test::writeFile(dir + "/not.drt-checkpoint", "hello");
    EXPECT_NE(readCheckpoint(dir + "/not.drt-checkpoint", read).find("is not a drt checkpoint"), std::string::npos);
    const std::string bytes = test::readFile(path);
    test::writeFile(dir + "/short.drt-checkpoint", bytes.substr(0, 30));
    EXPECT_NE(readCheckpoint(dir + "/short.drt-checkpoint", read).find("truncated"), std::string::npos);
    EXPECT_NE(readCheckpoint(dir + "/missing", read).find("no checkpoint"), std::string::npos);
}

} // namespace
} // namespace drt
