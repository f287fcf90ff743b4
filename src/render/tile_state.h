// A render in steps: the pixels of a render in progress (RenderState), the
// schedulers that hand its tiles to render threads (TileScheduler), and
// renderTiles / finishRender, which render() is made of. Other processes
// (distributed/), checkpoints and resumed renders use the same steps, and
// since every pixel is a function of (seed, pixel, sample index), whoever
// renders a tile, the image is the same bit for bit.
//
// Rounds. A fixed sample count is one round over every tile. Adaptive
// sampling (render.cpp) takes rounds with image-wide decisions between them:
// after a round, the pixels that sample in the next one are those still
// active whose neighbourhood (the pixels within kAdaptiveRadius) has not yet
// met the error target. So a tile's pixel states go from round to round, and
// the decision needs every tile of the round: a round is complete only when
// all its tiles are. A checkpoint
// saves the round and which of its tiles are done; a tile is the unit that
// moves between processes.
//
// Crop windows. A crop's pixels are bit-identical to a full render's. Fixed
// sampling renders exactly the crop. Under adaptive sampling a pixel's sample
// count depends, through the neighbourhood rule, on the pixels within
// kAdaptiveRadius * (rounds - 1) of it, so the rendered window is the crop
// grown by that many pixels (within the image) and the result keeps only the
// crop.
#pragma once

#include "render/film.h"
#include "render/render.h"

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace drt {

// Adaptive sampling's neighbourhood: a pixel stops when the mean estimated
// error of the (2r + 1)^2 pixels around it (within the image) meets the target.
inline constexpr int kAdaptiveRadius = 2;
// The target a pixel meets is the adaptive error's square at this many samples
// (the default min_samples), and n / kAdaptiveReferenceSamples times that at n
// samples: a pixel keeps sampling while another round would take as much error
// off per sample as it does at the reference (render.cpp, "Adaptive sampling").
inline constexpr int kAdaptiveReferenceSamples = 16;

// Adaptive sampling's state of one pixel between rounds.
struct AdaptivePixel {
    PixelAccumulator samples;
    int taken = 0;
    bool active = true; // samples in the coming round
    // The pixel's estimated contribution to relMSE at the last round end, from
    // the two halves of its samples (render.cpp, "Adaptive sampling"); +inf
    // when the halves are not known (the round did not start at or before
    // its middle).
    double error = std::numeric_limits<double>::infinity();
    // Its own error by the sample variance, var / n / (mean^2 + floor^2),
    // the largest of the channels: a guard against isolated noisy pixels.
    double varianceError = std::numeric_limits<double>::infinity();
};

// What one tile task adds to the render's statistics.
struct TileCounts {
    uint64_t cameraRays = 0, shadowRays = 0, secondaryRays = 0;
    uint64_t nonFiniteSamples = 0; // fixed sampling (an adaptive pixel keeps its own count)
    TileCounts& operator+=(const TileCounts& o);
};

// One unit of work: a tile in a round.
struct TileTask {
    int tile = -1;
    int round = 0;
};

// A rendered task, before it enters the state: render threads never write the
// state, so it is always consistent under its scheduler's lock (a checkpoint
// can be taken while tiles render).
struct TileResult {
    TileTask task;
    TileCounts counts;
    Image color, variance;              // fixed sampling: the tile's finished pixels
    std::vector<AdaptivePixel> adaptive; // adaptive sampling: the tile's pixel states, row by row
};

class RenderState {
public:
    // The tiles of `options` (its crop, tile size, sampling); throws RenderError
    // on invalid options.
    explicit RenderState(const RenderOptions& options);

    const RenderOptions& options() const { return options_; }
    bool adaptive() const { return options_.adaptive; }
    const PixelWindow& output() const { return output_; } // the pixels of the result: the crop or the image
    const PixelWindow& window() const { return window_; } // the pixels rendered: output, grown under adaptive sampling
    int tileCount() const { return tilesX_ * tilesY_; }
    PixelWindow tile(int index) const;

    int roundCount() const { return int(roundEnds_.size()); } // the most rounds there can be
    int roundEnd(int round) const { return roundEnds_[size_t(round)]; } // samples per pixel after round `round`
    int round() const { return round_; }
    bool finished() const { return finished_; }
    bool tileDone(int index) const { return tileDone_[size_t(index)] != 0; }
    // Adaptive: the pixels of a tile that sample in this round (0 for every
    // tile under fixed sampling). The scheduler hands out the busiest tiles first,
    // so that no thread is left with a long one while the others wait for the
    // round to end.
    int tileWork(int index) const { return tileWork_.empty() ? 0 : tileWork_[size_t(index)]; }
    int tilesDoneThisRound() const { return tilesDone_; }
    // Tiles done over all rounds, as a fraction of the most there can be.
    double fractionDone() const;
    // Writes a tile's pixels into the state.
    void store(const TileResult& result);
    // Marks a tile of the current round done and, after the round's last one,
    // decides the next round (or that the render is finished). Not thread-safe:
    // schedulers call store and completeTile under their lock.
    void completeTile(int index, const TileCounts& counts);
    const TileCounts& counts() const { return counts_; }

    // Pixels, for the renderer: fixed sampling stores each pixel's mean,
    // variance and count; adaptive sampling keeps each pixel's running state.
    // Between two decisions of the adaptive rule only the pixels the first
    // left active change (the rule copies only theirs again; restore copies
    // every pixel).
    AdaptivePixel& adaptivePixel(int x, int y) { return pixels_[indexOf(x, y)]; }
    const AdaptivePixel& adaptivePixel(int x, int y) const { return pixels_[indexOf(x, y)]; }
    Image& color() { return color_; } // the window's size; (x - window.x0, y - window.y0)
    Image& variance() { return variance_; }
    Image& sampleCount() { return sampleCount_; }
    const Image& color() const { return color_; }
    const Image& variance() const { return variance_; }
    const Image& sampleCount() const { return sampleCount_; }

    // A tile's pixels as bytes (between processes of one build): fixed
    // sampling the finished mean, variance and count, adaptive sampling the
    // pixel states. unpackTile throws RenderError on a malformed packet.
    void packTile(int index, std::vector<std::byte>& out) const;
    void unpackTile(int index, const std::byte* data, size_t size);

    // Everything but the options, as bytes (checkpoints); restore throws
    // RenderError if the bytes do not fit these options.
    void save(std::vector<std::byte>& out) const;
    void restore(const std::byte* data, size_t size);

private:
    size_t indexOf(int x, int y) const {
        return size_t(y - window_.y0) * size_t(window_.width()) + size_t(x - window_.x0);
    }
    void startRound();
    void countTileWork(); // tileWork_ from the pixels' flags
    bool decideNextRound(); // adaptive: the neighbourhood rule; false when no pixel samples again

    RenderOptions options_;
    PixelWindow output_, window_;
    int tilesX_ = 0, tilesY_ = 0;
    std::vector<int> roundEnds_;
    int round_ = 0;
    bool finished_ = false;
    std::vector<uint8_t> tileDone_;
    int tilesDone_ = 0;
    int tilesSkipped_ = 0; // adaptive: tiles of this round without an active pixel (done at its start)
    std::vector<int> tileWork_; // adaptive: active pixels per tile (decideNextRound counts them)
    std::vector<double> decideErrors_;  // decideNextRound's copies of the pixels' errors and flags
    std::vector<uint8_t> decideActive_;
    bool decideCopies_ = false; // the copies hold every pixel as the last decision left it
    TileCounts counts_;
    std::vector<AdaptivePixel> pixels_;
    Image color_, variance_, sampleCount_;
};

// Hands tile tasks to a process's render threads.
class TileScheduler {
public:
    virtual ~TileScheduler() = default;
    // The next task for this process, or none when it has no more (the render
    // is finished or stopping). Called from render threads; may block.
    virtual std::optional<TileTask> next() = 0;
    // A task is rendered.
    virtual void done(TileResult&& result) = 0;
};

// Another scheduler's tasks, with one render thread held back while `busy()`
// says that other work of the process needs a core: the first thread to ask
// for a task while it is busy calls `wait()` (which returns when that work is
// done) before taking tasks again; the others go on. Only one thread is ever
// held, once. A render whose threads fill every core uses it while the image
// module loads (cli/render_run.cpp), so that the load, which the end of a
// short render waits for, has a core of its own.
class LendingScheduler final : public TileScheduler {
public:
    LendingScheduler(TileScheduler& inner, std::function<bool()> busy, std::function<void()> wait)
        : inner_(inner), busy_(std::move(busy)), wait_(std::move(wait)) {}
    std::optional<TileTask> next() override {
        if (!lent_.load(std::memory_order_relaxed) && busy_() && !lent_.exchange(true)) wait_();
        return inner_.next();
    }
    void done(TileResult&& result) override { inner_.done(std::move(result)); }
    bool lent() const { return lent_.load(); } // a thread was held (or is)

private:
    TileScheduler& inner_;
    std::function<bool()> busy_;
    std::function<void()> wait_;
    std::atomic<bool> lent_{false};
};

// Every tile of a state, round by round, to this process's threads: the
// scheduler of render(), and the pool a distributed render's first process
// shares with the others (tryNext / done for the tasks they take).
class LocalTileScheduler : public TileScheduler {
public:
    // Hands out nothing more once `*cancel` is set; reports fractionDone to `progress`.
    LocalTileScheduler(RenderState& state, const std::atomic<bool>* cancel = nullptr,
                       std::function<void(double)> progress = {});
    std::optional<TileTask> next() override;
    void done(TileResult&& result) override;
    // A task another process rendered: its tile packed by RenderState::packTile.
    void donePacked(const TileTask& task, const TileCounts& counts, const std::byte* data, size_t size);
    // Calls `f(state)` under the lock (a consistent state between tiles).
    template <class F> void withState(F&& f) {
        std::lock_guard lock(mutex_);
        f(static_cast<const RenderState&>(state_));
    }
    // A task if one is free now, without waiting for the round to end.
    std::optional<TileTask> tryNext();
    // Tasks handed out and not yet done.
    int inFlight();
    // The state is finished, or cancelled with no task in flight.
    bool over();
    // Wakes threads waiting in next() (after *cancel is set from elsewhere).
    void wake();

private:
    bool cancelled() const { return cancel_ && cancel_->load(); }
    std::optional<TileTask> take();                              // under the lock
    void complete(const TileTask& task, const TileCounts& counts); // under the lock

    RenderState& state_;
    const std::atomic<bool>* cancel_;
    std::function<void(double)> progress_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::vector<int> pending_; // this round's tiles not yet handed out
    int pendingRound_ = -1;
    int inFlight_ = 0;
};

// What renderTiles measured, for finishRender.
struct TileRenderInfo {
    double buildSeconds = 0;
    double renderSeconds = 0;
    double traceCpuSeconds = 0; // the render threads' CPU time, summed (RenderStats)
    uint64_t untraceableRays = 0; // rays beyond Embree's range (Accelerator::untraceableRays)
    bool motionBlur = false;   // the accelerator has motion and the camera a shutter
    bool depthOfField = false; // the camera has a lens
};

// Renders the tasks `scheduler` hands out into `state` on options.threads
// threads, until it has no more. Throws RenderError.
TileRenderInfo renderTiles(const Scene& scene, const RenderOptions& options, RenderState& state,
                           TileScheduler& scheduler);

// The images and statistics of a finished state (its output window). Throws
// RenderError if the state is not finished.
RenderResult finishRender(const Scene& scene, const RenderState& state, const TileRenderInfo& info);

// The image so far: finished pixels (fixed sampling: the finished tiles;
// adaptive: every pixel with samples, at its current mean) in RGB and alpha 1,
// the others black with alpha 0. Linear, the output window's size.
Image partialImage(const Scene& scene, const RenderState& state);

} // namespace drt
