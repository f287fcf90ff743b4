// The renderer: scene model -> film, tile-scheduled over all cores with oneTBB.
#pragma once

#include "core/error.h"
#include "image/image.h"
#include "scene/scene.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

namespace drt {

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
    // the standard error of its mean is at most adaptiveError * sqrt(mean^2 +
    // adaptiveDarkFloor^2) in every channel, or it has maxSamplesPerPixel.
    // samplesPerPixel is then unused.
    bool adaptive = false;
    double adaptiveError = 0.02;
    double adaptiveDarkFloor = 0.1; // the 0.01 = 0.1^2 of relMSE's denominator
    int minSamplesPerPixel = 16;
    int maxSamplesPerPixel = 1024;
    // Called now and then from render threads with the fraction done.
    std::function<void(double)> progress;
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
};

// What `scene` rendered with `options` uses.
SceneEffects sceneEffects(const Scene& scene, const RenderOptions& options);
// "AA, DOF, motion, area lights, gloss, translucency, adaptive" (the ones used), or "none".
std::string describeEffects(const SceneEffects& effects);

struct RenderStats {
    double buildSeconds = 0;  // Embree scene build
    double renderSeconds = 0; // tracing
    uint64_t cameraRays = 0;
    uint64_t shadowRays = 0;
    uint64_t secondaryRays = 0; // reflection + refraction
    uint64_t nonFiniteSamples = 0; // NaN/Inf samples caught (and dropped) before the film
    uint64_t pixelSamples = 0;     // camera samples taken, over all pixels
    int minPixelSamples = 0;       // fewest / most samples any pixel took
    int maxPixelSamples = 0;
    SceneEffects effects;
    uint64_t totalRays() const { return cameraRays + shadowRays + secondaryRays; }
};

struct RenderResult {
    Image color;    // linear RGB, the per-pixel mean
    Image variance; // per-pixel variance of the mean, RGB
    Image sampleCount; // samples taken per pixel, one channel
    RenderStats stats;
};

// The memory a render's image buffers take (colour, variance, sample counts,
// adaptive state, the copy an image file is written from), computed without
// overflow; and "" or why `options` are refused before anything is allocated
// (core/limits.h: image_memory_mb, threads).
uint64_t renderImageBytes(const RenderOptions& options);
std::string renderLimitProblem(const RenderOptions& options);

// Throws RenderError on failure.
RenderResult render(const Scene& scene, const RenderOptions& options);

} // namespace drt
