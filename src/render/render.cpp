// resolveRenderOptions and render: the tile scheduler. Tiles are independent
// tasks of a tbb::parallel_for inside a task_arena of the requested size; each
// pixel's samples are taken in sample-index order by one task, with every
// random number a function of (seed, pixel, sample index, dimension), so the
// image is bit-identical for any thread count and tile size.
#include "render/render.h"

#include "accel/accel.h"
#include "render/camera.h"
#include "render/film.h"
#include "render/integrator.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <mutex>

namespace drt {

RenderOptions resolveRenderOptions(const Scene& scene, const RenderOverrides& overrides) {
    RenderOptions options;
    const RenderSettings& settings = scene.render;
    options.width = overrides.width.value_or(settings.width.value_or(options.width));
    options.height = overrides.height.value_or(settings.height.value_or(options.height));
    options.samplesPerPixel = overrides.samplesPerPixel.value_or(settings.samplesPerPixel.value_or(options.samplesPerPixel));
    options.seed = overrides.seed.value_or(settings.seed.value_or(options.seed));
    options.sampler = overrides.sampler.value_or(settings.sampler.value_or(options.sampler));
    options.threads = overrides.threads.value_or(options.threads);
    return options;
}

namespace {

constexpr int kMaxImageSide = 1 << 16;

void validate(const RenderOptions& options) {
    if (options.width < 1 || options.height < 1 || options.width > kMaxImageSide || options.height > kMaxImageSide)
        throw RenderError("image size must be between 1 and " + std::to_string(kMaxImageSide) + " pixels a side");
    if (options.samplesPerPixel < 1) throw RenderError("samples per pixel must be at least 1");
    if (options.threads < 0) throw RenderError("threads must be 0 (all cores) or more");
    if (options.tileSize < 1) throw RenderError("tile size must be at least 1");
}

std::unique_ptr<Sampler> createSampler(const RenderOptions& options) {
    try {
        return makeSampler(options.sampler.empty() ? defaultSamplerName() : options.sampler, options.samplesPerPixel,
                           options.seed);
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

} // namespace

RenderResult render(const Scene& scene, const RenderOptions& options) {
    validate(options);
    const ResolvedCamera camera = resolveCamera(scene.camera, options.width, options.height);
    const std::unique_ptr<Sampler> prototype = createSampler(options);
    const Filter filter = sceneFilter(scene);

    RenderResult result;
    const auto buildStart = std::chrono::steady_clock::now();
    const Accelerator accel(scene);
    result.stats.buildSeconds = secondsSince(buildStart);

    const Integrator integrator(scene, accel);
    result.color = Image(options.width, options.height, 3);
    result.variance = Image(options.width, options.height, 3);

    const int tilesX = (options.width + options.tileSize - 1) / options.tileSize;
    const int tilesY = (options.height + options.tileSize - 1) / options.tileSize;
    const int tileCount = tilesX * tilesY;
    const auto tileAt = [&](int index) {
        const int tx = index % tilesX, ty = index / tilesX;
        return Tile{tx * options.tileSize, ty * options.tileSize, std::min(options.width, (tx + 1) * options.tileSize),
                    std::min(options.height, (ty + 1) * options.tileSize)};
    };

    std::atomic<uint64_t> cameraRays{0}, shadowRays{0}, secondaryRays{0}, nonFinite{0};
    std::atomic<int> tilesDone{0};
    std::mutex progressMutex;

    const auto renderTile = [&](int index) {
        const Tile tile = tileAt(index);
        const std::unique_ptr<Sampler> sampler = prototype->clone();
        RayCounts counts;
        uint64_t dropped = 0;
        for (int y = tile.y0; y < tile.y1; ++y) {
            for (int x = tile.x0; x < tile.x1; ++x) {
                PixelAccumulator pixel;
                for (int s = 0; s < options.samplesPerPixel; ++s) {
                    sampler->startPixelSample(x, y, s);
                    const Vec2 position = pixelSamplePosition(*sampler, filter, x, y);
                    const double time =
                        camera.hasShutter() ? camera.timeAt(sampler->get1D(kDimTime)) : camera.shutterOpen;
                    const Vec2 lens = camera.hasLens() ? sampler->get2D(kDimLens) : Vec2{0.5, 0.5};
                    const Ray ray = camera.generateRay(position.x, position.y, lens, time);
                    pixel.add(integrator.trace(ray, *sampler, counts));
                }
                dropped += pixel.nonFinite();
                storePixel(pixel, x, y, result.color, result.variance);
            }
        }
        cameraRays += counts.camera;
        shadowRays += counts.shadow;
        secondaryRays += counts.secondary;
        nonFinite += dropped;
        const int done = ++tilesDone;
        if (options.progress) {
            std::lock_guard<std::mutex> lock(progressMutex);
            options.progress(static_cast<double>(done) / tileCount);
        }
    };

    const auto renderStart = std::chrono::steady_clock::now();
    tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, tileCount, 1), [&](const tbb::blocked_range<int>& range) {
            for (int index = range.begin(); index != range.end(); ++index) renderTile(index);
        });
    });
    result.stats.renderSeconds = secondsSince(renderStart);
    result.stats.cameraRays = cameraRays;
    result.stats.shadowRays = shadowRays;
    result.stats.secondaryRays = secondaryRays;
    result.stats.nonFiniteSamples = nonFinite;
    return result;
}

} // namespace drt
