// The renderer: scene model -> film, tile-scheduled over all cores with oneTBB.
#pragma once

#include "core/error.h"
#include "image/image.h"
#include "scene/scene.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

namespace drt {

// The pixels [x0, x1) x [y0, y1) of an image.
struct PixelWindow {
    int x0 = 0, x1 = 0, y0 = 0, y1 = 0;
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
    bool operator==(const PixelWindow&) const = default;
};

struct RenderOptions {
    int width = 320;
    int height = 240;
    int samplesPerPixel = 1;
    uint64_t seed = 0;
    std::string sampler; // "" -> defaultSamplerName()
    int threads = 0;     // 0: all cores
    int tileSize = 32;
    // Adaptive sampling (render.cpp, "Adaptive sampling"): each pixel takes
    // samples in rounds that double its count, from minSamplesPerPixel, until
    // the mean estimated relative error of its 5x5 neighbourhood (relative to
    // sqrt(mean^2 + adaptiveDarkFloor^2)) is at most adaptiveError^2 n / 16 at
    // its n samples (tile_state.h kAdaptiveReferenceSamples), or it has
    // maxSamplesPerPixel. samplesPerPixel is then unused.
    bool adaptive = false;
    double adaptiveError = 0.02;
    double adaptiveDarkFloor = 0.1; // the 0.01 = 0.1^2 of relMSE's denominator
    int minSamplesPerPixel = 16;
    int maxSamplesPerPixel = 1024;
    // Shadow rays each area light sends from a shading point at one camera
    // sample (render/lighting.h): 1 is Cook's association. K > 1 splits the
    // sample: its K points are the pixel's stratified light sequence at
    // K i .. K i + K - 1, so a pixel's N samples stratify N K points as N K
    // camera samples would, for the cost of N camera paths and N K shadow rays.
    // POV-Ray's pov_grid sampling ignores it (every grid point at every hit).
    int lightSamples = 1;
    // Only these pixels of the width x height image (a crop window for farm
    // renders): each is bit-identical to the same pixel of a full render, and
    // the result's images are the window's size. None: the whole image.
    std::optional<PixelWindow> crop;
    // Called now and then from render threads with the fraction done.
    std::function<void(double)> progress;
    // Set (e.g. by a signal handler) to stop: no new tile starts, the tiles in
    // progress finish. render() then throws RenderInterrupted; the tile API
    // (render/tile_state.h) leaves the finished tiles in its RenderState.
    const std::atomic<bool>* cancel = nullptr;
};

// The settings given, else the defaults (320x240, 1 spp, seed 0, all cores).
// A caller that lets a user override the scene's settings overlays them first
// (scene/scene.h overlaySettings).
RenderOptions resolveRenderOptions(const RenderSettings& settings);

// The effects a render used (render/summary: "what the scene used"). Each is
// true only if its code path ran: a pinhole camera draws no lens samples, a
// zero shutter or a scene without motion draws no time samples, etc.
struct SceneEffects {
    bool antialiasing = false; // more than one sample per pixel
    bool depthOfField = false; // a thin lens with aperture > 0
    bool motionBlur = false;   // an object with motion and an open shutter
    bool areaLights = false;   // a (lit) area light
    bool gloss = false;        // reflection_blur on a reflective finish
    bool translucency = false; // refraction_blur on a transmitting finish
    bool adaptive = false;     // adaptive sampling
    bool radiosity = false;    // radiosity { } gathering from a diffuse finish
};

// What `scene` rendered with `options` uses.
SceneEffects sceneEffects(const Scene& scene, const RenderOptions& options);
// "AA, DOF, motion, area lights, gloss, translucency, adaptive, radiosity" (the ones used), or "none".
std::string describeEffects(const SceneEffects& effects);

struct RenderStats {
    double buildSeconds = 0;  // Embree scene build
    double renderSeconds = 0; // tracing
    // CPU time of the render's threads while they traced, summed: the tracing
    // alone, without what other threads of the process (the image module's
    // load) took from the same cores.
    double traceCpuSeconds = 0;
    uint64_t cameraRays = 0;
    uint64_t shadowRays = 0;
    uint64_t secondaryRays = 0; // reflection + refraction
    uint64_t nonFiniteSamples = 0; // NaN/Inf samples caught (and dropped) before the film
    // Rays with a coordinate beyond Accelerator::kLargestCoordinate, taken to
    // meet nothing (a camera or objects very far from the origin).
    uint64_t untraceableRays = 0;
    uint64_t pixelSamples = 0;     // camera samples taken, over all pixels
    int minPixelSamples = 0;       // fewest / most samples any pixel took
    int maxPixelSamples = 0;
    SceneEffects effects;
    uint64_t totalRays() const { return cameraRays + shadowRays + secondaryRays; }
};

struct RenderResult {
    PixelWindow window; // the pixels the images hold (the crop, or the whole image)
    Image color;    // linear RGB, the per-pixel mean
    Image variance; // per-pixel variance of the mean, RGB
    Image sampleCount; // samples taken per pixel, one channel
    RenderStats stats;
};

// What render() throws when RenderOptions::cancel stopped it.
class RenderInterrupted : public RenderError {
public:
    RenderInterrupted() : RenderError("the render was interrupted") {}
};

// The memory a render's image buffers take (colour, variance, sample counts,
// adaptive state, the copy an image file is written from), computed without
// overflow; and "" or why `options` are refused before anything is allocated
// (core/limits.h: image_memory_mb, threads).
uint64_t renderImageBytes(const RenderOptions& options);
std::string renderLimitProblem(const RenderOptions& options);

// Throws RenderError on failure. render/tile_state.h splits it into steps for
// other schedulers (other processes, resumed renders).
RenderResult render(const Scene& scene, const RenderOptions& options);

} // namespace drt
