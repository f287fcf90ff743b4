// The renderer: scene model -> film, tile-scheduled over all cores with oneTBB.
#pragma once

#include "image/image.h"
#include "scene/scene.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

namespace drt {

// Anything that goes wrong while building or rendering (e.g. an Embree error).
class RenderError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct RenderOptions {
    int width = 320;
    int height = 240;
    int samplesPerPixel = 1;
    uint64_t seed = 0;
    std::string sampler; // "" -> defaultSamplerName()
    int threads = 0;     // 0: all cores
    int tileSize = 32;
    // Called now and then from render threads with the fraction done.
    std::function<void(double)> progress;
};

// Command-line values that override the scene's RenderSettings when given.
struct RenderOverrides {
    std::optional<int> width, height, samplesPerPixel, threads;
    std::optional<uint64_t> seed;
    std::optional<std::string> sampler;
};

// Scene settings, then overrides, then defaults (320x240, 1 spp, seed 0).
RenderOptions resolveRenderOptions(const Scene& scene, const RenderOverrides& overrides);

struct RenderStats {
    double buildSeconds = 0;  // Embree scene build
    double renderSeconds = 0; // tracing
    uint64_t cameraRays = 0;
    uint64_t shadowRays = 0;
    uint64_t secondaryRays = 0; // reflection + refraction
    uint64_t nonFiniteSamples = 0; // NaN/Inf samples caught (and dropped) before the film
    uint64_t totalRays() const { return cameraRays + shadowRays + secondaryRays; }
};

struct RenderResult {
    Image color;    // linear RGB, the per-pixel mean
    Image variance; // per-pixel variance of the mean, RGB
    RenderStats stats;
};

// Throws RenderError on failure.
RenderResult render(const Scene& scene, const RenderOptions& options);

} // namespace drt
