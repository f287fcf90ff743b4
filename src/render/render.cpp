// renderTiles, finishRender and render: the tile renderer. Worker threads of
// a task_arena of the requested size take tile tasks from a scheduler
// (render/tile_state.h); each pixel's samples are taken in sample-index order
// by one task, with every random number a function of (seed, pixel, sample
// index, dimension), so the image is bit-identical for any thread count, tile
// size, tile order and process that renders a tile.
//
// Adaptive sampling (RenderOptions::adaptive). A pixel takes samples in rounds
// with indices 0..n-1 in order; the first round ends at n = min_spp, each later
// one at the next power of two (capped at max_spp), because the Sobol sampler's
// samples are stratified per power-of-two prefix (an aligned block of a
// (0,m,2)-net); other round ends would leave a partial, unevenly spread block.
//
// The error estimate (after Dammertz et al., "A hierarchical automatic stopping
// condition for Monte Carlo global illumination", 2009): at a round end n the
// pixel's mean I of all its samples is compared with the mean A of the first
// n/2, and its estimated contribution to relMSE (docs/accuracy.md) is
//     e = mean over channels c of (I_c - A_c)^2 / (I_c^2 + f^2),
// f the dark floor (0.1 matches relMSE's 0.01). For independent samples
// E[(I - A)^2] = Var(I) exactly; for the stratified Sobol prefixes it is
// somewhat more (the half converges more slowly than the whole), so e errs on
// the safe side, but much less than var/n does: the sample variance ignores
// stratification altogether. When the round started after n/2 (a min_spp that
// is not a power of two) e is unknown (+inf) for that round.
//
// The stopping rule. A pixel that has taken n samples samples again while the
// mean of e over the (2r + 1)^2 pixels within r = kAdaptiveRadius of it
// (render/tile_state.h) is above T(n) = E^2 n / n0, E the adaptive error and
// n0 = kAdaptiveReferenceSamples (16, the default min_samples), or its own
// var/n/(mean^2 + f^2) in some channel is above 16 T(n) (an isolated noisy
// pixel); once it stops it takes no more samples. Why the target grows with n:
// the next round doubles n, costs n samples and takes about e/2 off the
// error, so e/n is what a sample buys there. Stopping where e/n falls to one
// threshold (E^2 / n0) for every pixel spends the samples where they take most
// error off: the samples go as the pixel's standard deviation, not as its
// variance as with one fixed target, which gives a smaller image error for
// the same samples (minimising sum s_i^2 / n_i under sum n_i = N gives n_i
// proportional to s_i). On POV-Ray's focalblur, arealit1 and arealit2 the
// same relMSE took 7-26% fewer samples than with the fixed target
// (docs/performance.md). At n0 samples the target is E^2, as before. Why a neighbourhood and not the pixel alone: in a penumbra a
// pixel's first few samples often agree by chance (each sees the whole light),
// its own estimate is then 0 and it would stop with a large error that is
// also a bias (the pixels that stop early are the ones whose samples agreed).
// The per-pixel rule this replaces (each pixel's var/n against E^2, stopping
// once it and its 8 neighbours passed) flattened near relMSE 2e-5 on
// POV-Ray's arealit2 for that reason (docs/performance.md). Averaged over 25
// pixels the estimate rests on 25 times the samples, so a penumbra shows in it
// even where one pixel's samples missed it, and one pixel's own samples weigh
// 1/25 in its decision, which keeps the correlation between when a pixel stops
// and what its samples said small. A pixel that stops at n samples has an
// estimated error of at most E^2 n / 16; the halves estimate is conservative
// on stratified samples, so images end near or below E^2 (E = 0.01 aims at
// relMSE 1e-4; measured figures in docs/sampling.md).
//
// Rounds are image-wide passes with a barrier between them (RenderState in
// render/tile_state.cpp applies the rule), and each decision reads only
// samples taken by the end of the round, so the image is still bit-identical
// for any thread count and tile size. Remaining bias: a feature smaller than
// about 1/min_spp of a pixel that no pixel within r sees in its first samples
// can be missed; tests/statistical/adaptive_test.cpp bounds the effect on
// images against fixed-sample references. The stratified sampler's strata are
// permuted over max_spp, so its prefixes are unbiased but not stratified.
#include "render/render.h"
#include "assets/assets.h"

#include "accel/accel.h"
#include "core/limits.h"
#include "render/camera.h"
#include "render/camera_path.h"
#include "render/light_path.h"
#include "render/film.h"
#include "render/integrator.h"
#include "render/tile_state.h"
#include "render/texture_shading.h"

#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#define DRT_HAVE_MXCSR 1
#endif
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <memory>
#include <variant>
#include <chrono>
#include <ctime>
#include <mutex>
#include <optional>

namespace drt {

RenderOptions resolveRenderOptions(const RenderSettings& settings) {
    RenderOptions options;
    options.width = settings.width.value_or(options.width);
    options.height = settings.height.value_or(options.height);
    options.samplesPerPixel = settings.samplesPerPixel.value_or(options.samplesPerPixel);
    options.seed = settings.seed.value_or(options.seed);
    options.sampler = settings.sampler.value_or(options.sampler);
    options.threads = settings.threads.value_or(options.threads);
    options.adaptive = settings.adaptive.value_or(options.adaptive);
    options.adaptiveError = settings.adaptiveError.value_or(options.adaptiveError);
    options.minSamplesPerPixel = settings.minSamplesPerPixel.value_or(options.minSamplesPerPixel);
    options.maxSamplesPerPixel = settings.maxSamplesPerPixel.value_or(options.maxSamplesPerPixel);
    options.lightSamples = settings.lightSamples.value_or(options.lightSamples);
    return options;
}

namespace {

int samplerSampleCount(const RenderOptions& options) {
    return options.adaptive ? options.maxSamplesPerPixel : options.samplesPerPixel;
}

std::unique_ptr<Sampler> createSampler(const RenderOptions& options) {
    try {
        return makeSampler(options.sampler.empty() ? defaultSamplerName() : options.sampler,
                           samplerSampleCount(options), options.seed);
    } catch (const std::invalid_argument& e) {
        throw RenderError(e.what());
    }
}

// The scene's filter setting (the command line has none yet); box by default.
Filter sceneFilter(const Scene& scene) {
    try {
        return makeFilter(scene.render.filter.value_or(defaultFilterName()));
    } catch (const std::invalid_argument& e) {
        throw RenderError(e.what());
    }
}

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The CPU time the calling thread has used (0 where the clock is missing).
double threadCpuSeconds() {
    timespec now{};
    if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now) != 0) return 0;
    return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
}

// (I - A)^2 / (I^2 + f^2), the mean over channels (see "Adaptive sampling").
double halvesError(const Color& all, const Color& firstHalf, const RenderOptions& options) {
    const double floor2 = options.adaptiveDarkFloor * options.adaptiveDarkFloor;
    double sum = 0;
    for (int c = 0; c < 3; ++c) {
        const double d = all[c] - firstHalf[c];
        sum += d * d / (all[c] * all[c] + floor2);
    }
    return sum / 3;
}

// var / n / (mean^2 + f^2), the largest over channels; +inf under two samples.
double varianceError(const PixelAccumulator& pixel, const RenderOptions& options) {
    if (pixel.count() < 2) return std::numeric_limits<double>::infinity();
    const Color mean = pixel.mean(), varianceOfMean = pixel.varianceOfMean();
    const double floor2 = options.adaptiveDarkFloor * options.adaptiveDarkFloor;
    double worst = 0;
    for (int c = 0; c < 3; ++c) worst = std::max(worst, double(varianceOfMean[c]) / (mean[c] * mean[c] + floor2));
    return worst;
}

bool anyFinish(const std::vector<Object>& objects, const auto& predicate) {
    for (const Object& object : objects) {
        if (anyFinish(object.texture, predicate)) return true;
        if (const auto* mesh = std::get_if<Mesh>(&object.shape))
            for (const Texture& own : mesh->textures)
                if (anyFinish(own, predicate)) return true;
        if (const auto* csg = std::get_if<Csg>(&object.shape); csg && anyFinish(csg->children, predicate)) return true;
    }
    return false;
}

bool anyMotion(const std::vector<Object>& objects) {
    for (const Object& object : objects) {
        if (!object.motion.empty()) return true;
        if (const auto* csg = std::get_if<Csg>(&object.shape); csg && anyMotion(csg->children)) return true;
    }
    return false;
}

} // namespace

SceneEffects sceneEffects(const Scene& scene, const RenderOptions& options) {
    SceneEffects e;
    e.adaptive = options.adaptive;
    e.antialiasing = options.adaptive ? options.maxSamplesPerPixel > 1 : options.samplesPerPixel > 1;
    e.depthOfField = scene.camera.aperture > 0;
    e.motionBlur = scene.camera.shutterOpen != scene.camera.shutterClose &&
                   (anyMotion(scene.objects) || !scene.camera.motion.empty() || scene.cameraKeys.size() > 1 ||
                    std::any_of(scene.lights.begin(), scene.lights.end(), lightMoves));
    for (const Light& light : scene.lights)
        e.areaLights = e.areaLights || (light.area && !isBlack(light.color));
    e.gloss = anyFinish(scene.objects, [](const Finish& f) {
        return f.reflectionBlur > 0 && (!isBlack(f.reflectionMax) || !isBlack(f.reflectionMin));
    });
    e.translucency = anyFinish(scene.objects, [](const Finish& f) { return f.refractionBlur > 0; });
    e.radiosity = scene.global.radiosity && scene.global.radiosity->brightness > 0 &&
                  anyFinish(scene.objects, [](const Finish& f) { return f.diffuse > 0; });
    return e;
}

std::string describeEffects(const SceneEffects& e) {
    std::string text;
    const auto add = [&](bool used, const char* name) {
        if (!used) return;
        if (!text.empty()) text += ", ";
        text += name;
    };
    add(e.antialiasing, "AA");
    add(e.depthOfField, "DOF");
    add(e.motionBlur, "motion");
    add(e.areaLights, "area lights");
    add(e.gloss, "gloss");
    add(e.translucency, "translucency");
    add(e.adaptive, "adaptive");
    add(e.radiosity, "radiosity");
    return text.empty() ? "none" : text;
}

namespace {

// Denormal handling is per thread (x86 MXCSR flush-to-zero and
// denormals-are-zero bits), and what a worker thread inherits depends on who
// created it, so the same sample could round differently on two threads. Every
// tile runs with IEEE denormals (both bits off) and restores the thread's mode.
class IeeeDenormals {
public:
#ifdef DRT_HAVE_MXCSR
    IeeeDenormals() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ & ~(kFlushToZero | kDenormalsAreZero)); }
    ~IeeeDenormals() { _mm_setcsr(saved_); }

private:
    static constexpr unsigned kFlushToZero = 0x8000, kDenormalsAreZero = 0x0040;
    unsigned saved_;
#endif
};

} // namespace

uint64_t renderImageBytes(const RenderOptions& options) {
    // colour and variance (3 floats each), the sample count (1 float), the
    // file's copy (up to 4 floats), and the adaptive state of every pixel.
    const uint64_t perPixel = 4 * (3 + 3 + 1 + 4) + (options.adaptive ? sizeof(PixelAccumulator) + 8 : 0);
    const uint64_t pixels = saturatingBytes(uint64_t(std::max(options.width, 0)), uint64_t(std::max(options.height, 0)));
    return saturatingBytes(pixels, perPixel);
}

std::string renderLimitProblem(const RenderOptions& options) {
    const Limits& limits = defaultLimits();
    if (options.threads > limits.threads)
        return limitExceeded(limits, &Limits::threads, "the thread count", options.threads);
    const uint64_t megabytes = (renderImageBytes(options) + (1 << 20) - 1) >> 20;
    if (megabytes > uint64_t(limits.imageMemoryMB))
        return fmt::format("a {} x {} image needs {} MB for its buffers, over the limit of {} MB ({})", options.width,
                           options.height, megabytes, limits.imageMemoryMB,
                           limitHint(limits, &Limits::imageMemoryMB));
    return "";
}

TileRenderInfo renderTiles(const Scene& scene, const RenderOptions& options, RenderState& state,
                           TileScheduler& scheduler) {
    if (!assetsResolved(scene))
        throw RenderError("the scene names image or mesh files that were not read (call resolveAssets after parsing)");
    // The camera at each ray's time (render/camera_path.h); `camera` is the still one.
    const CameraPath cameraPath(scene, options.width, options.height);
    const ResolvedCamera& camera = cameraPath.still();
    const std::unique_ptr<Sampler> prototype = createSampler(options);
    const Filter filter = sceneFilter(scene);

    TileRenderInfo info;
    const auto buildStart = std::chrono::steady_clock::now();
    // A zero-length shutter gives every ray the same time: the accelerator
    // then places moving objects at that time in double precision, so the
    // image is the static scene's at that time bit for bit.
    const auto accelerator = camera.hasShutter() ? std::make_unique<Accelerator>(scene)
                                                 : std::make_unique<Accelerator>(scene, camera.shutterOpen);
    const Accelerator& accel = *accelerator;
    info.buildSeconds = secondsSince(buildStart);
    info.motionBlur = camera.hasShutter() && (accel.hasMotion() || cameraPath.moving() ||
                                              std::any_of(scene.lights.begin(), scene.lights.end(), lightMoves));
    info.depthOfField = cameraPath.hasLens();

    const Integrator integrator(scene, accel, options.lightSamples);

    // Samples first..last-1 of pixel (x, y), in index order. A pixel's camera
    // rays are traced in packets of up to Accelerator::kPacketSize (they are
    // coherent: one pixel, one lens); each sample's hit is exactly the one a
    // ray alone finds, and the rest of the sample is traced after, in order.
    // Every sample value is a function of (pixel, index, dimension), so drawing
    // a packet's camera dimensions before the rest changes none of them.
    const bool cameraMoves = cameraPath.moving(), lensSampled = cameraPath.hasLens();
    // A packet's rays and hits, made once per tile (a Hit is about 260 bytes
    // of initialised members: not something to build for every pixel), and
    // its camera dimensions (zeroing their Vec2s for every packet took about
    // a sixth of this loop's own time).
    constexpr int kPacket = Accelerator::kPacketSize;
    struct Packet {
        ResolvedCamera moved; // a moving camera at the sample's time
        Ray rays[kPacket];
        Hit hits[kPacket];
        bool found[kPacket];
        bool covered[kPacket];
        Vec2 pixelDimensions[kPacket], lensDimensions[kPacket];
        double timeDimensions[kPacket];
        CameraShadows shadows; // the hits' shadow rays, traced ahead in packets
    };
    // `snapshot`, if given, takes the pixel as it stands before sample `snapshotAt` (first <= snapshotAt < last):
    // an adaptive pixel's first half, taken on the way so that the halves share the camera's packets.
    const auto takeSamples = [&](Packet& packet, Sampler& sampler, PixelAccumulator& pixel, int x, int y, int first,
                                 int last, RayCounts& counts, int snapshotAt = -1,
                                 PixelAccumulator* snapshot = nullptr) {
        ResolvedCamera& moved = packet.moved;
        Ray* const rays = packet.rays;
        Hit* const hits = packet.hits;
        bool* const found = packet.found;
        bool* const covered = packet.covered;
        Vec2* const pixelDimensions = packet.pixelDimensions;
        Vec2* const lensDimensions = packet.lensDimensions;
        double* const timeDimensions = packet.timeDimensions;
        for (int start = first; start < last; start += kPacket) {
            const int n = std::min(kPacket, last - start);
            int traced = 0;
            // Only the effects in use draw samples (a pinhole takes no lens sample).
            sampler.getCameraDimensions(x, y, start, n, pixelDimensions, camera.hasShutter() ? timeDimensions : nullptr,
                                        lensSampled ? lensDimensions : nullptr);
            for (int j = 0; j < n; ++j) {
                const Vec2 position = pixelSamplePosition(filter, pixelDimensions[j], x, y);
                const double time = camera.hasShutter() ? camera.timeAt(timeDimensions[j]) : camera.shutterOpen;
                const Vec2 lens = lensSampled ? lensDimensions[j] : Vec2{0.5, 0.5};
                if (cameraMoves) moved = cameraPath.at(time);
                const ResolvedCamera& at = cameraMoves ? moved : camera;
                covered[j] = at.covers(position.x, position.y); // else no ray (POV-Ray: black)
                // Made in place: an assignment would copy the 72-byte ray.
                if (covered[j]) ::new (&rays[traced++]) Ray(at.generateRay(position.x, position.y, lens, time));
            }
            accel.intersectPacket(rays, traced, hits, found);
            integrator.traceCameraShadows(rays, hits, found, traced, packet.shadows);
            // Null where nothing went ahead: the shading then looks for nothing there.
            const CameraShadows* const ahead = packet.shadows.empty() ? nullptr : &packet.shadows;
            for (int j = 0, k = 0; j < n; ++j) {
                if (snapshot && start + j == snapshotAt) *snapshot = pixel;
                if (!covered[j]) {
                    pixel.add(Color(0));
                    continue;
                }
                sampler.startPixelSample(x, y, start + j);
                pixel.add(integrator.trace(rays[k], hits[k], found[k], sampler, counts, ahead));
                ++k;
            }
        }
    };

    // One task: fixed sampling takes all of a tile's samples; adaptive sampling
    // takes the round's samples of its active pixels, from their states in
    // `state` (render/tile_state.h keeps them between rounds).
    const auto renderTile = [&](const TileTask& task) {
        const PixelWindow tile = state.tile(task.tile);
        const int roundEnd = state.roundEnd(task.round);
        const std::unique_ptr<Sampler> sampler = prototype->clone();
        TileResult result;
        result.task = task;
        if (options.adaptive) result.adaptive.reserve(size_t(tile.width()) * size_t(tile.height()));
        else result.color = Image(tile.width(), tile.height(), 3), result.variance = result.color;
        RayCounts counts;
        Packet packet; // once per tile
        for (int y = tile.y0; y < tile.y1; ++y) {
            for (int x = tile.x0; x < tile.x1; ++x) {
                if (!options.adaptive) {
                    PixelAccumulator pixel;
                    takeSamples(packet, *sampler, pixel, x, y, 0, options.samplesPerPixel, counts);
                    result.counts.nonFiniteSamples += pixel.nonFinite();
                    storePixel(pixel, x - tile.x0, y - tile.y0, result.color, result.variance);
                    continue;
                }
                AdaptivePixel pixel = state.adaptivePixel(x, y);
                if (pixel.active) {
                    // The first half's mean, on the way (see "Adaptive sampling").
                    const int half = roundEnd / 2;
                    const bool halves = half >= 1 && pixel.taken <= half;
                    PixelAccumulator firstHalf = pixel.samples;
                    takeSamples(packet, *sampler, pixel.samples, x, y, pixel.taken, roundEnd, counts,
                                halves ? half : -1, halves ? &firstHalf : nullptr);
                    pixel.taken = roundEnd;
                    pixel.error = halves && firstHalf.count() > 0 && pixel.samples.count() > firstHalf.count()
                                      ? halvesError(pixel.samples.mean(), firstHalf.mean(), options)
                                      : std::numeric_limits<double>::infinity();
                    pixel.varianceError = varianceError(pixel.samples, options);
                }
                result.adaptive.push_back(pixel);
            }
        }
        result.counts.cameraRays = counts.camera;
        result.counts.shadowRays = counts.shadow;
        result.counts.secondaryRays = counts.secondary;
        return result;
    };

    const auto renderStart = std::chrono::steady_clock::now();
    std::mutex cpuMutex;
    double cpuSeconds = 0;
    tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
    arena.execute([&] {
        // Each worker takes tasks until the scheduler has none: it may hand
        // them out over rounds (with waits between them) and other processes.
        tbb::parallel_for(0, arena.max_concurrency(), [&](int) {
            const IeeeDenormals ieee;
            // Installed before the first tile: the image module starts
            // loading once a tile is done, and a thread that made thread_local
            // buffers during that load would wait for all of it
            // (accel/thread_scratch.h).
            const InstalledScratchSet buffers = Integrator::installThreadBuffers();
            const double cpuStart = threadCpuSeconds();
            while (const std::optional<TileTask> task = scheduler.next())
                scheduler.done(renderTile(*task));
            const double used = threadCpuSeconds() - cpuStart;
            const std::lock_guard<std::mutex> lock(cpuMutex);
            cpuSeconds += used;
        });
    });
    info.renderSeconds = secondsSince(renderStart);
    info.traceCpuSeconds = cpuSeconds;
    info.untraceableRays = accel.untraceableRays();
    return info;
}

RenderResult finishRender(const Scene& scene, const RenderState& state, const TileRenderInfo& info) {
    if (!state.finished()) throw RenderError("the render is not finished");
    const RenderOptions& options = state.options();
    const PixelWindow out = state.output(), window = state.window();
    RenderResult result;
    result.window = out;
    result.color = Image(out.width(), out.height(), 3);
    result.variance = Image(out.width(), out.height(), 3);
    result.sampleCount = Image(out.width(), out.height(), 1);
    uint64_t nonFinite = state.counts().nonFiniteSamples, taken = 0;
    int fewest = std::numeric_limits<int>::max(), most = 0;
    for (int y = out.y0; y < out.y1; ++y)
        for (int x = out.x0; x < out.x1; ++x) {
            const int ox = x - out.x0, oy = y - out.y0;
            int n = options.samplesPerPixel;
            if (options.adaptive) {
                const AdaptivePixel& pixel = state.adaptivePixel(x, y);
                n = pixel.taken;
                nonFinite += pixel.samples.nonFinite();
                storePixel(pixel.samples, ox, oy, result.color, result.variance);
            } else {
                for (int c = 0; c < 3; ++c) {
                    result.color.at(ox, oy, c) = state.color().at(x - window.x0, y - window.y0, c);
                    result.variance.at(ox, oy, c) = state.variance().at(x - window.x0, y - window.y0, c);
                }
            }
            result.sampleCount.at(ox, oy, 0) = static_cast<float>(n);
            taken += uint64_t(n);
            fewest = std::min(fewest, n);
            most = std::max(most, n);
        }
    decodeWorkingGamma(result.color, result.variance, scene.global.assumedGamma);
    RenderStats& stats = result.stats;
    stats.buildSeconds = info.buildSeconds;
    stats.renderSeconds = info.renderSeconds;
    stats.traceCpuSeconds = info.traceCpuSeconds;
    stats.untraceableRays = info.untraceableRays;
    stats.cameraRays = state.counts().cameraRays;
    stats.shadowRays = state.counts().shadowRays;
    stats.secondaryRays = state.counts().secondaryRays;
    stats.nonFiniteSamples = nonFinite;
    stats.pixelSamples = taken;
    stats.minPixelSamples = fewest;
    stats.maxPixelSamples = most;
    stats.effects = sceneEffects(scene, options);
    stats.effects.motionBlur = stats.effects.motionBlur && info.motionBlur;
    stats.effects.depthOfField = info.depthOfField;
    return result;
}

RenderResult render(const Scene& scene, const RenderOptions& options) {
    RenderState state(options);
    LocalTileScheduler scheduler(state, options.cancel, options.progress);
    const TileRenderInfo info = renderTiles(scene, options, state, scheduler);
    if (!state.finished()) throw RenderInterrupted();
    return finishRender(scene, state, info);
}

} // namespace drt
