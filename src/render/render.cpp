// resolveRenderOptions and render: the tile scheduler. Tiles are independent
// tasks of a tbb::parallel_for inside a task_arena of the requested size; each
// pixel's samples are taken in sample-index order by one task, with every
// random number a function of (seed, pixel, sample index, dimension), so the
// image is bit-identical for any thread count and tile size.
//
// Adaptive sampling (RenderOptions::adaptive). A pixel takes samples in rounds
// with indices 0..n-1 in order; the first round ends at n = min_spp, each later
// one at the next power of two (capped at max_spp), because the Sobol sampler's
// samples are stratified per power-of-two prefix (an aligned block of a
// (0,m,2)-net); other round ends would leave a partial, unevenly spread block.
// After each round a pixel passes the stopping rule if, in every channel c,
//     sqrt(var_c / n) <= E * sqrt(mean_c^2 + f^2),
// var_c the unbiased sample variance, E the adaptive error and f the dark
// floor: E^2 bounds the pixel's expected contribution var/(r^2 + f^2) to
// relMSE (docs/accuracy.md; f = 0.1 matches its 0.01). It stops once it and
// its 8 neighbours pass (a stopped pixel takes no more samples).
// Why the neighbours: a pixel whose first min_spp samples all miss a sliver of
// an edge sees zero variance and would stop with the sliver lost; that bias
// dominated the error (examples/minimal.drt, min_spp 16: a relMSE floor of
// 2.9e-6, all from such pixels), and an edge almost always shows in a
// neighbour. Rounds are image-wide passes with a barrier between them, and each
// decision reads only samples taken by the end of the round, so the image is
// still bit-identical for any thread count and tile size.
// Remaining bias: features smaller than about 1/min_spp of a pixel, isolated
// from any feature a neighbour sees, can be missed. Owen-scrambled Sobol's nets
// make that rarer than independent samples do;
// tests/statistical/adaptive_test.cpp bounds the effect on an image against a
// fixed-sample reference. The stratified sampler's strata are permuted over
// max_spp, so its prefixes are unbiased but not stratified.
#include "render/render.h"
#include "assets/assets.h"

#include "accel/accel.h"
#include "render/camera.h"
#include "render/film.h"
#include "render/integrator.h"
#include "render/texture_shading.h"

#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#define DRT_HAVE_MXCSR 1
#endif
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <variant>
#include <chrono>
#include <mutex>

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
    return options;
}

namespace {

constexpr int kMaxImageSide = 1 << 16;
constexpr int kMaxAdaptiveSamples = 1 << 24;

void validate(const RenderOptions& options) {
    if (options.width < 1 || options.height < 1 || options.width > kMaxImageSide || options.height > kMaxImageSide)
        throw RenderError("image size must be between 1 and " + std::to_string(kMaxImageSide) + " pixels a side");
    if (options.samplesPerPixel < 1) throw RenderError("samples per pixel must be at least 1");
    if (options.threads < 0) throw RenderError("threads must be 0 (all cores) or more");
    if (options.tileSize < 1) throw RenderError("tile size must be at least 1");
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

struct Tile {
    int x0, y0, x1, y1;
};

// Where the round that has taken n samples ends: see "Adaptive sampling" above.
int nextRoundEnd(int n, const RenderOptions& options) {
    if (n == 0) return options.minSamplesPerPixel;
    int end = 1;
    while (end <= n && end < options.maxSamplesPerPixel) end *= 2;
    return std::min(end, options.maxSamplesPerPixel);
}

bool converged(const PixelAccumulator& pixel, const RenderOptions& options) {
    if (pixel.count() < 2) return false;
    const Color mean = pixel.mean(), varianceOfMean = pixel.varianceOfMean();
    const double e2 = options.adaptiveError * options.adaptiveError;
    const double floor2 = options.adaptiveDarkFloor * options.adaptiveDarkFloor;
    for (int c = 0; c < 3; ++c)
        if (!(varianceOfMean[c] <= e2 * (mean[c] * mean[c] + floor2))) return false;
    return true;
}

bool anyFinish(const std::vector<Object>& objects, const auto& predicate) {
    for (const Object& object : objects) {
        if (anyFinish(object.texture, predicate)) return true;
        if (const auto* csg = std::get_if<Csg>(&object.shape); csg && anyFinish(csg->children, predicate)) return true;
    }
    return false;
}

bool anyMotion(const std::vector<Object>& objects) {
    for (const Object& object : objects) {
        if (object.motion) return true;
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
    e.motionBlur = scene.camera.shutterOpen != scene.camera.shutterClose && anyMotion(scene.objects);
    for (const Light& light : scene.lights)
        e.areaLights = e.areaLights || (light.area && !isBlack(light.color));
    e.gloss = anyFinish(scene.objects, [](const Finish& f) {
        return f.reflectionBlur > 0 && (!isBlack(f.reflectionMax) || !isBlack(f.reflectionMin));
    });
    e.translucency = anyFinish(scene.objects, [](const Finish& f) { return f.refractionBlur > 0; });
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

RenderResult render(const Scene& scene, const RenderOptions& options) {
    validate(options);
    if (!assetsResolved(scene))
        throw RenderError("the scene names image or mesh files that were not read (call resolveAssets after parsing)");
    const ResolvedCamera camera = resolveCamera(scene.camera, options.width, options.height);
    const std::unique_ptr<Sampler> prototype = createSampler(options);
    const Filter filter = sceneFilter(scene);

    RenderResult result;
    const auto buildStart = std::chrono::steady_clock::now();
    // A zero-length shutter gives every ray the same time: the accelerator
    // then places moving objects at that time in double precision, so the
    // image is the static scene's at that time bit for bit.
    const auto accelerator = camera.hasShutter() ? std::make_unique<Accelerator>(scene)
                                                 : std::make_unique<Accelerator>(scene, camera.shutterOpen);
    const Accelerator& accel = *accelerator;
    result.stats.buildSeconds = secondsSince(buildStart);

    const Integrator integrator(scene, accel);
    result.color = Image(options.width, options.height, 3);
    result.variance = Image(options.width, options.height, 3);
    result.sampleCount = Image(options.width, options.height, 1);

    const int tilesX = (options.width + options.tileSize - 1) / options.tileSize;
    const int tilesY = (options.height + options.tileSize - 1) / options.tileSize;
    const int tileCount = tilesX * tilesY;
    const auto tileAt = [&](int index) {
        const int tx = index % tilesX, ty = index / tilesX;
        return Tile{tx * options.tileSize, ty * options.tileSize, std::min(options.width, (tx + 1) * options.tileSize),
                    std::min(options.height, (ty + 1) * options.tileSize)};
    };

    std::atomic<uint64_t> cameraRays{0}, shadowRays{0}, secondaryRays{0}, nonFinite{0}, samplesTaken{0};
    std::atomic<int> fewestSamples{std::numeric_limits<int>::max()}, mostSamples{0};
    std::atomic<int> tilesDone{0};
    std::mutex progressMutex;
    int progressRounds = 1; // adaptive: the most rounds a pixel can take
    if (options.adaptive)
        for (int n = nextRoundEnd(0, options); n < options.maxSamplesPerPixel; n = nextRoundEnd(n, options))
            ++progressRounds;

    // Samples first..last-1 of pixel (x, y), in index order.
    const auto takeSamples = [&](Sampler& sampler, PixelAccumulator& pixel, int x, int y, int first, int last,
                                 RayCounts& counts) {
        for (int s = first; s < last; ++s) {
            sampler.startPixelSample(x, y, s);
            const Vec2 position = pixelSamplePosition(sampler, filter, x, y);
            // Only the effects in use draw samples (a pinhole takes no lens sample).
            const double time = camera.hasShutter() ? camera.timeAt(sampler.get1D(kDimTime)) : camera.shutterOpen;
            const Vec2 lens = camera.hasLens() ? sampler.get2D(kDimLens) : Vec2{0.5, 0.5};
            if (!camera.covers(position.x, position.y)) {
                pixel.add(Color(0)); // no ray there (POV-Ray: black)
                continue;
            }
            const Ray ray = camera.generateRay(position.x, position.y, lens, time);
            pixel.add(integrator.trace(ray, sampler, counts));
        }
    };

    // Adaptive sampling keeps every pixel's running sums between rounds; a
    // fixed sample count needs none (one round, the pixel finished in place).
    struct PixelState {
        PixelAccumulator samples;
        int taken = 0;
        bool active = true;      // samples in the coming round
        bool unconverged = true; // failed the stopping rule at the last round end
    };
    std::vector<PixelState> states(options.adaptive ? size_t(options.width) * size_t(options.height) : 0);
    const auto finishPixel = [&](const PixelAccumulator& pixel, int x, int y, int n, uint64_t& dropped,
                                 uint64_t& taken, int& fewest, int& most) {
        dropped += pixel.nonFinite();
        taken += uint64_t(n);
        fewest = std::min(fewest, n);
        most = std::max(most, n);
        storePixel(pixel, x, y, result.color, result.variance);
        result.sampleCount.at(x, y, 0) = static_cast<float>(n);
    };

    // One round over one tile: fixed sampling takes all its samples; adaptive
    // sampling takes the active pixels' samples up to `roundEnd` (0: finish
    // every pixel, storing it).
    const auto renderTile = [&](int index, int roundEnd) {
        const Tile tile = tileAt(index);
        const std::unique_ptr<Sampler> sampler = prototype->clone();
        RayCounts counts;
        uint64_t dropped = 0, taken = 0;
        int fewest = std::numeric_limits<int>::max(), most = 0;
        for (int y = tile.y0; y < tile.y1; ++y) {
            for (int x = tile.x0; x < tile.x1; ++x) {
                if (!options.adaptive) {
                    PixelAccumulator pixel;
                    takeSamples(*sampler, pixel, x, y, 0, options.samplesPerPixel, counts);
                    finishPixel(pixel, x, y, options.samplesPerPixel, dropped, taken, fewest, most);
                    continue;
                }
                PixelState& state = states[size_t(y) * size_t(options.width) + size_t(x)];
                if (roundEnd == 0) {
                    finishPixel(state.samples, x, y, state.taken, dropped, taken, fewest, most);
                } else if (state.active) {
                    takeSamples(*sampler, state.samples, x, y, state.taken, roundEnd, counts);
                    state.taken = roundEnd;
                    state.unconverged = !converged(state.samples, options);
                }
            }
        }
        cameraRays += counts.camera;
        shadowRays += counts.shadow;
        secondaryRays += counts.secondary;
        nonFinite += dropped;
        samplesTaken += taken;
        for (int seen = fewestSamples.load(); fewest < seen && !fewestSamples.compare_exchange_weak(seen, fewest);) {}
        for (int seen = mostSamples.load(); most > seen && !mostSamples.compare_exchange_weak(seen, most);) {}
        if (roundEnd != 0 || !options.adaptive) {
            const int done = ++tilesDone;
            if (options.progress) {
                std::lock_guard<std::mutex> lock(progressMutex);
                // Adaptive rounds: the fraction of the round, then of the rounds at most to come.
                options.progress(std::min(1.0, static_cast<double>(done) / tileCount / progressRounds));
            }
        }
    };

    // Which pixels sample in the next round (see "Adaptive sampling" above):
    // those still active that failed the rule or have such a neighbour.
    const auto nextActive = [&](int roundEnd) {
        bool any = false;
        std::vector<uint8_t> next(states.size(), 0);
        for (int y = 0; y < options.height; ++y)
            for (int x = 0; x < options.width; ++x) {
                const PixelState& state = states[size_t(y) * size_t(options.width) + size_t(x)];
                if (!state.active || roundEnd >= options.maxSamplesPerPixel) continue;
                bool again = false;
                for (int dy = -1; dy <= 1 && !again; ++dy)
                    for (int dx = -1; dx <= 1 && !again; ++dx) {
                        const int nx = x + dx, ny = y + dy;
                        if (nx < 0 || ny < 0 || nx >= options.width || ny >= options.height) continue;
                        const PixelState& neighbour = states[size_t(ny) * size_t(options.width) + size_t(nx)];
                        again = neighbour.active && neighbour.unconverged;
                    }
                next[size_t(y) * size_t(options.width) + size_t(x)] = again;
                any = any || again;
            }
        for (size_t i = 0; i < states.size(); ++i) states[i].active = next[i] != 0;
        return any;
    };

    const auto renderStart = std::chrono::steady_clock::now();
    tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
    const auto runRound = [&](int roundEnd) {
        arena.execute([&] {
            tbb::parallel_for(tbb::blocked_range<int>(0, tileCount, 1), [&](const tbb::blocked_range<int>& range) {
                const IeeeDenormals ieee;
                for (int index = range.begin(); index != range.end(); ++index) renderTile(index, roundEnd);
            });
        });
    };
    if (!options.adaptive) {
        runRound(options.samplesPerPixel);
    } else {
        int taken = 0;
        while (true) {
            const int end = nextRoundEnd(taken, options);
            runRound(end);
            taken = end;
            if (!nextActive(end)) break;
        }
        runRound(0);
    }
    decodeWorkingGamma(result.color, result.variance, scene.global.assumedGamma);
    result.stats.renderSeconds = secondsSince(renderStart);
    result.stats.cameraRays = cameraRays;
    result.stats.shadowRays = shadowRays;
    result.stats.secondaryRays = secondaryRays;
    result.stats.nonFiniteSamples = nonFinite;
    result.stats.pixelSamples = samplesTaken;
    result.stats.minPixelSamples = fewestSamples;
    result.stats.maxPixelSamples = mostSamples;
    result.stats.effects = sceneEffects(scene, options);
    result.stats.effects.motionBlur = result.stats.effects.motionBlur && accel.hasMotion() && camera.hasShutter();
    result.stats.effects.depthOfField = camera.hasLens();
    return result;
}

} // namespace drt
