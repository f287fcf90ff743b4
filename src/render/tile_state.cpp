// RenderState (tiles, rounds, the adaptive neighbour rule, packing) and the
// local tile scheduler. See render/tile_state.h.
#include "render/tile_state.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <type_traits>

namespace drt {

namespace {

constexpr int kMaxImageSide = 1 << 16;
constexpr int kMaxAdaptiveSamples = 1 << 24;
// A pixel whose own variance error is this many times the target samples
// again whatever its neighbourhood says (an isolated noisy pixel: a thin
// feature, a glint); its own estimate is too noisy to be trusted below that.
constexpr double kAdaptiveOwnFactor = 16;

void validate(const RenderOptions& options) {
    if (std::string problem = renderLimitProblem(options); !problem.empty()) throw RenderError(problem);
    if (options.width < 1 || options.height < 1 || options.width > kMaxImageSide || options.height > kMaxImageSide)
        throw RenderError("image size must be between 1 and " + std::to_string(kMaxImageSide) + " pixels a side");
    if (options.samplesPerPixel < 1) throw RenderError("samples per pixel must be at least 1");
    if (options.threads < 0) throw RenderError("threads must be 0 (all cores) or more");
    if (options.tileSize < 1) throw RenderError("tile size must be at least 1");
    if (options.crop) {
        const PixelWindow& c = *options.crop;
        if (c.empty() || c.x0 < 0 || c.y0 < 0 || c.x1 > options.width || c.y1 > options.height)
            throw RenderError("the crop window x " + std::to_string(c.x0) + ".." + std::to_string(c.x1) + ", y " +
                              std::to_string(c.y0) + ".." + std::to_string(c.y1) + " is not a non-empty part of the " +
                              std::to_string(options.width) + "x" + std::to_string(options.height) + " image");
    }
    if (!options.adaptive) return;
    if (options.minSamplesPerPixel < 1) throw RenderError("adaptive minimum samples per pixel must be at least 1");
    if (options.maxSamplesPerPixel > kMaxAdaptiveSamples)
        throw RenderError("adaptive maximum samples per pixel must be at most " + std::to_string(kMaxAdaptiveSamples));
    if (options.maxSamplesPerPixel < options.minSamplesPerPixel)
        throw RenderError("adaptive maximum samples per pixel (" + std::to_string(options.maxSamplesPerPixel) +
                          ") is below the minimum (" + std::to_string(options.minSamplesPerPixel) + ")");
    if (!(options.adaptiveError > 0) || !std::isfinite(options.adaptiveError))
        throw RenderError("adaptive error must be a positive number");
    if (!(options.adaptiveDarkFloor >= 0) || !std::isfinite(options.adaptiveDarkFloor))
        throw RenderError("adaptive dark floor must be 0 or more");
}

// Where the adaptive round that has taken n samples ends: the first round at
// min_spp, each later one at the next power of two, capped at max_spp (the
// Sobol sampler's power-of-two prefixes are stratified: render.cpp).
int nextRoundEnd(int n, const RenderOptions& options) {
    // The first round takes at least two samples: a pixel with one cannot
    // estimate its error, so a round ending there would only decide that every
    // pixel samples again (and split each pixel's first two camera rays into
    // two packets).
    if (n == 0) return std::min(std::max(options.minSamplesPerPixel, 2), options.maxSamplesPerPixel);
    int end = 1;
    while (end <= n && end < options.maxSamplesPerPixel) end *= 2;
    return std::min(end, options.maxSamplesPerPixel);
}

static_assert(std::is_trivially_copyable_v<AdaptivePixel>, "adaptive pixel states are copied as bytes");

void appendBytes(std::vector<std::byte>& out, const void* data, size_t size) {
    const auto* bytes = static_cast<const std::byte*>(data);
    out.insert(out.end(), bytes, bytes + size);
}

template <class T> void appendValue(std::vector<std::byte>& out, const T& value) {
    appendBytes(out, &value, sizeof value);
}

// Reads bytes in order, throwing RenderError past the end.
class ByteReader {
public:
    ByteReader(const std::byte* data, size_t size) : data_(data), size_(size) {}
    void read(void* to, size_t size) {
        if (size > size_ - offset_) throw RenderError("truncated render state");
        std::memcpy(to, data_ + offset_, size);
        offset_ += size;
    }
    template <class T> T value() {
        T v;
        read(&v, sizeof v);
        return v;
    }
    bool atEnd() const { return offset_ == size_; }

private:
    const std::byte* data_;
    size_t size_;
    size_t offset_ = 0;
};

constexpr int kFixedChannels = 7; // mean RGB, variance RGB, count

} // namespace

TileCounts& TileCounts::operator+=(const TileCounts& o) {
    cameraRays += o.cameraRays;
    shadowRays += o.shadowRays;
    secondaryRays += o.secondaryRays;
    nonFiniteSamples += o.nonFiniteSamples;
    return *this;
}

RenderState::RenderState(const RenderOptions& options) : options_(options) {
    validate(options);
    options_.progress = nullptr;
    options_.cancel = nullptr;
    output_ = options.crop.value_or(PixelWindow{0, options.width, 0, options.height});
    window_ = output_;
    if (options.adaptive) {
        for (int n = nextRoundEnd(0, options);; n = nextRoundEnd(n, options)) {
            roundEnds_.push_back(n);
            if (n >= options.maxSamplesPerPixel) break;
        }
        // tile_state.h, "Crop windows": a pixel depends on those within r (rounds - 1).
        const int margin = kAdaptiveRadius * (roundCount() - 1);
        window_ = {std::max(0, output_.x0 - margin), std::min(options.width, output_.x1 + margin),
                   std::max(0, output_.y0 - margin), std::min(options.height, output_.y1 + margin)};
        pixels_.resize(size_t(window_.width()) * size_t(window_.height()));
    } else {
        roundEnds_.push_back(options.samplesPerPixel);
        color_ = Image(window_.width(), window_.height(), 3);
        variance_ = Image(window_.width(), window_.height(), 3);
        sampleCount_ = Image(window_.width(), window_.height(), 1);
    }
    tilesX_ = (window_.width() + options.tileSize - 1) / options.tileSize;
    tilesY_ = (window_.height() + options.tileSize - 1) / options.tileSize;
    tileDone_.assign(size_t(tileCount()), 0);
    if (options.adaptive) { // every pixel samples in the first round
        tileWork_.resize(size_t(tileCount()));
        for (int index = 0; index < tileCount(); ++index) {
            const PixelWindow t = tile(index);
            tileWork_[size_t(index)] = t.width() * t.height();
        }
    }
    startRound();
}

PixelWindow RenderState::tile(int index) const {
    const int tx = index % tilesX_, ty = index / tilesX_, size = options_.tileSize;
    return {window_.x0 + tx * size, std::min(window_.x1, window_.x0 + (tx + 1) * size), window_.y0 + ty * size,
            std::min(window_.y1, window_.y0 + (ty + 1) * size)};
}

double RenderState::fractionDone() const {
    if (finished_) return 1.0;
    return (double(round_) + double(tilesDone_) / tileCount()) / roundCount();
}

// Adaptive rounds skip the tiles without an active pixel: done from the start.
void RenderState::startRound() {
    std::fill(tileDone_.begin(), tileDone_.end(), 0);
    tilesDone_ = 0;
    tilesSkipped_ = 0;
    if (!adaptive()) return; // tileWork_: set by the constructor, restore and decideNextRound
    for (int index = 0; index < tileCount(); ++index)
        if (tileWork_[size_t(index)] == 0) {
            tileDone_[size_t(index)] = 1;
            ++tilesDone_;
        }
}

void RenderState::countTileWork() {
    tileWork_.assign(size_t(tileCount()), 0);
    for (int index = 0; index < tileCount(); ++index) {
        const PixelWindow t = tile(index);
        int& work = tileWork_[size_t(index)];
        for (int y = t.y0; y < t.y1; ++y)
            for (int x = t.x0; x < t.x1; ++x) work += adaptivePixel(x, y).active ? 1 : 0;
    }
}

void RenderState::store(const TileResult& result) {
    const PixelWindow t = tile(result.task.tile);
    for (int y = t.y0; y < t.y1; ++y)
        for (int x = t.x0; x < t.x1; ++x) {
            const int tx = x - t.x0, ty = y - t.y0;
            if (adaptive()) {
                adaptivePixel(x, y) = result.adaptive[size_t(ty) * size_t(t.width()) + size_t(tx)];
                continue;
            }
            const int wx = x - window_.x0, wy = y - window_.y0;
            for (int c = 0; c < 3; ++c) {
                color_.at(wx, wy, c) = result.color.at(tx, ty, c);
                variance_.at(wx, wy, c) = result.variance.at(tx, ty, c);
            }
            sampleCount_.at(wx, wy, 0) = float(options_.samplesPerPixel);
        }
}

void RenderState::completeTile(int index, const TileCounts& counts) {
    if (finished_ || index < 0 || index >= tileCount() || tileDone_[size_t(index)]) return;
    tileDone_[size_t(index)] = 1;
    counts_ += counts;
    if (++tilesDone_ < tileCount()) return;
    if (adaptive() && decideNextRound()) {
        ++round_;
        startRound();
    } else {
        finished_ = true;
    }
}

// The neighbourhood rule (render.cpp, "Adaptive sampling"): a pixel samples
// again if it is still active and either the mean error of the pixels within
// kAdaptiveRadius of it (in the window; every pixel, stopped or not, at its
// latest estimate) is above its target or its own variance error is far above
// it; none does after the last round. The target grows with the samples the
// pixel has taken (kAdaptiveReferenceSamples). Sums are taken in a fixed order over a
// window clipped to the rendered window, so a pixel far enough inside it
// (tile_state.h, "Crop windows") decides as in a full render.
bool RenderState::decideNextRound() {
    const int w = window_.width(), h = window_.height();
    tileWork_.assign(size_t(tileCount()), 0);
    if (roundEnd(round_) >= options_.maxSamplesPerPixel) { // the last round: no pixel samples again
        for (AdaptivePixel& pixel : pixels_) pixel.active = false;
        decideCopies_ = false;
        return false;
    }
    const double target = options_.adaptiveError * options_.adaptiveError;
    bool any = false;
    // The errors and the active flags side by side: the sums below read 25
    // errors a pixel, and a pixel's whole state is about a hundred bytes. No
    // decision changes an error, and a pixel's decision reads no other
    // pixel's flag, so each is written as it is made, to the pixel and its
    // copy. The copies are kept between rounds (a fresh buffer of this size
    // is new memory for the system to map and zero every round), and since
    // the last decision only the pixels it left active have sampled, so only
    // their errors are copied again; the first decision, and the first after
    // a restore, copies every pixel.
    std::vector<double>& errors = decideErrors_;
    std::vector<uint8_t>& active = decideActive_;
    if (!decideCopies_) {
        errors.resize(pixels_.size());
        active.resize(pixels_.size());
        for (size_t i = 0; i < pixels_.size(); ++i) {
            errors[i] = pixels_[i].error;
            active[i] = pixels_[i].active;
        }
        decideCopies_ = true;
    } else {
        for (size_t i = 0; i < pixels_.size(); ++i)
            if (active[i]) errors[i] = pixels_[i].error;
    }
    const int size = options_.tileSize;
    constexpr int r = kAdaptiveRadius;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * size_t(w) + size_t(x);
            if (!active[i]) continue;
            AdaptivePixel& pixel = pixels_[i];
            const double allowed = target * double(pixel.taken) / kAdaptiveReferenceSamples;
            // Written so that NaN or infinity means "sample again". The
            // pixel's own error first: where it already says so, the
            // neighbourhood's sum is not needed.
            bool again = !(pixel.varianceError <= kAdaptiveOwnFactor * allowed);
            if (!again) {
                double sum = 0;
                int count = 0;
                for (int ny = std::max(0, y - r); ny <= std::min(h - 1, y + r); ++ny)
                    for (int nx = std::max(0, x - r); nx <= std::min(w - 1, x + r); ++nx) {
                        sum += errors[size_t(ny) * size_t(w) + size_t(nx)];
                        ++count;
                    }
                again = !(sum <= allowed * count);
            }
            pixel.active = again;
            active[i] = again;
            any = any || again;
            if (again) ++tileWork_[size_t(y / size) * size_t(tilesX_) + size_t(x / size)];
        }
    return any;
}

void RenderState::packTile(int index, std::vector<std::byte>& out) const {
    const PixelWindow t = tile(index);
    for (int y = t.y0; y < t.y1; ++y)
        for (int x = t.x0; x < t.x1; ++x) {
            if (adaptive()) {
                appendValue(out, adaptivePixel(x, y));
                continue;
            }
            const int wx = x - window_.x0, wy = y - window_.y0;
            for (int c = 0; c < 3; ++c) appendValue(out, color_.at(wx, wy, c));
            for (int c = 0; c < 3; ++c) appendValue(out, variance_.at(wx, wy, c));
            appendValue(out, sampleCount_.at(wx, wy, 0));
        }
}

void RenderState::unpackTile(int index, const std::byte* data, size_t size) {
    if (index < 0 || index >= tileCount()) throw RenderError("tile " + std::to_string(index) + " out of range");
    const PixelWindow t = tile(index);
    const size_t pixelBytes = adaptive() ? sizeof(AdaptivePixel) : kFixedChannels * sizeof(float);
    if (size != size_t(t.width()) * size_t(t.height()) * pixelBytes)
        throw RenderError("tile " + std::to_string(index) + ": " + std::to_string(size) + " bytes do not fit it");
    ByteReader in(data, size);
    for (int y = t.y0; y < t.y1; ++y)
        for (int x = t.x0; x < t.x1; ++x) {
            if (adaptive()) {
                adaptivePixel(x, y) = in.value<AdaptivePixel>();
                continue;
            }
            const int wx = x - window_.x0, wy = y - window_.y0;
            for (int c = 0; c < 3; ++c) color_.at(wx, wy, c) = in.value<float>();
            for (int c = 0; c < 3; ++c) variance_.at(wx, wy, c) = in.value<float>();
            sampleCount_.at(wx, wy, 0) = in.value<float>();
        }
}

// Layout: the window and tiling (checked on restore), the round, the tile
// flags, the counts, then every pixel (fixed: the three images; adaptive: the
// pixel states).
void RenderState::save(std::vector<std::byte>& out) const {
    for (int v : {window_.x0, window_.x1, window_.y0, window_.y1, tilesX_, tilesY_, roundCount(), round_})
        appendValue(out, int32_t(v));
    appendValue(out, uint8_t(finished_));
    appendBytes(out, tileDone_.data(), tileDone_.size());
    appendValue(out, counts_);
    if (adaptive()) {
        appendBytes(out, pixels_.data(), pixels_.size() * sizeof(AdaptivePixel));
        return;
    }
    for (const Image* image : {&color_, &variance_, &sampleCount_})
        appendBytes(out, image->pixels.data(), image->pixels.size() * sizeof(float));
}

void RenderState::restore(const std::byte* data, size_t size) {
    ByteReader in(data, size);
    for (int expected : {window_.x0, window_.x1, window_.y0, window_.y1, tilesX_, tilesY_, roundCount()})
        if (in.value<int32_t>() != expected) throw RenderError("the saved render has another window or tiling");
    const int round = in.value<int32_t>();
    if (round < 0 || round >= roundCount()) throw RenderError("the saved render's round is out of range");
    round_ = round;
    finished_ = in.value<uint8_t>() != 0;
    in.read(tileDone_.data(), tileDone_.size());
    tilesDone_ = int(std::count_if(tileDone_.begin(), tileDone_.end(), [](uint8_t d) { return d != 0; }));
    counts_ = in.value<TileCounts>();
    if (adaptive()) {
        in.read(pixels_.data(), pixels_.size() * sizeof(AdaptivePixel));
        decideCopies_ = false; // every pixel may have changed
        countTileWork();
    } else {
        for (Image* image : {&color_, &variance_, &sampleCount_})
            in.read(image->pixels.data(), image->pixels.size() * sizeof(float));
    }
    if (!in.atEnd()) throw RenderError("the saved render has trailing bytes");
}

LocalTileScheduler::LocalTileScheduler(RenderState& state, const std::atomic<bool>* cancel,
                                       std::function<void(double)> progress)
    : state_(state), cancel_(cancel), progress_(std::move(progress)) {}

std::optional<TileTask> LocalTileScheduler::take() {
    if (state_.finished() || cancelled()) return std::nullopt;
    if (pendingRound_ != state_.round()) {
        pendingRound_ = state_.round();
        pending_.clear();
        for (int index = state_.tileCount() - 1; index >= 0; --index)
            if (!state_.tileDone(index)) pending_.push_back(index);
        // Handed out from the back: the busiest tiles first, in index order
        // among equals (a tile's pixels come out the same in any order).
        std::stable_sort(pending_.begin(), pending_.end(),
                         [this](int a, int b) { return state_.tileWork(a) < state_.tileWork(b); });
    }
    if (pending_.empty()) return std::nullopt;
    const int tile = pending_.back();
    pending_.pop_back();
    ++inFlight_;
    return TileTask{tile, pendingRound_};
}

std::optional<TileTask> LocalTileScheduler::next() {
    std::unique_lock lock(mutex_);
    while (true) {
        if (std::optional<TileTask> task = take()) return task;
        if (state_.finished() || cancelled()) return std::nullopt;
        // The round's last tiles are in flight: wait for the next round (and
        // look at the cancel flag now and then: a signal handler cannot notify).
        changed_.wait_for(lock, std::chrono::milliseconds(50));
    }
}

std::optional<TileTask> LocalTileScheduler::tryNext() {
    std::lock_guard lock(mutex_);
    return take();
}

void LocalTileScheduler::complete(const TileTask& task, const TileCounts& counts) {
    --inFlight_;
    if (task.round == state_.round()) state_.completeTile(task.tile, counts);
    if (progress_) progress_(state_.fractionDone());
}

void LocalTileScheduler::done(TileResult&& result) {
    {
        std::lock_guard lock(mutex_);
        if (result.task.round == state_.round() && !state_.tileDone(result.task.tile)) state_.store(result);
        complete(result.task, result.counts);
    }
    changed_.notify_all();
}

void LocalTileScheduler::donePacked(const TileTask& task, const TileCounts& counts, const std::byte* data,
                                    size_t size) {
    {
        std::lock_guard lock(mutex_);
        if (task.round == state_.round() && !state_.tileDone(task.tile)) state_.unpackTile(task.tile, data, size);
        complete(task, counts);
    }
    changed_.notify_all();
}

int LocalTileScheduler::inFlight() {
    std::lock_guard lock(mutex_);
    return inFlight_;
}

bool LocalTileScheduler::over() {
    std::lock_guard lock(mutex_);
    return state_.finished() || (cancelled() && inFlight_ == 0);
}

void LocalTileScheduler::wake() {
    { std::lock_guard lock(mutex_); }
    changed_.notify_all();
}

Image partialImage(const Scene& scene, const RenderState& state) {
    const PixelWindow out = state.output(), window = state.window();
    Image color(out.width(), out.height(), 3), variance(out.width(), out.height(), 3);
    Image covered(out.width(), out.height(), 1);
    if (state.adaptive()) {
        for (int y = out.y0; y < out.y1; ++y)
            for (int x = out.x0; x < out.x1; ++x) {
                const AdaptivePixel& pixel = state.adaptivePixel(x, y);
                if (pixel.taken == 0) continue;
                storePixel(pixel.samples, x - out.x0, y - out.y0, color, variance);
                covered.at(x - out.x0, y - out.y0, 0) = 1;
            }
    } else {
        for (int index = 0; index < state.tileCount(); ++index) {
            if (!state.tileDone(index) && !state.finished()) continue;
            const PixelWindow t = state.tile(index);
            for (int y = t.y0; y < t.y1; ++y)
                for (int x = t.x0; x < t.x1; ++x) {
                    for (int c = 0; c < 3; ++c)
                        color.at(x - out.x0, y - out.y0, c) = state.color().at(x - window.x0, y - window.y0, c);
                    covered.at(x - out.x0, y - out.y0, 0) = 1;
                }
        }
    }
    decodeWorkingGamma(color, variance, scene.global.assumedGamma);
    Image rgba(out.width(), out.height(), 4);
    for (int y = 0; y < out.height(); ++y)
        for (int x = 0; x < out.width(); ++x) {
            const float alpha = covered.at(x, y, 0);
            for (int c = 0; c < 3; ++c) rgba.at(x, y, c) = alpha > 0 ? color.at(x, y, c) : 0.0f;
            rgba.at(x, y, 3) = alpha;
        }
    return rgba;
}

} // namespace drt
