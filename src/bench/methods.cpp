#include "bench/methods.h"

#include "sampling/filter.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace drt::bench {

namespace {

bool hasAreaLight(const Scene& scene) {
    return std::any_of(scene.lights.begin(), scene.lights.end(), [](const Light& l) { return l.area.has_value(); });
}

std::string needsAreaLight(const Scene& scene) {
    return hasAreaLight(scene) ? "" : "the scene has no area light";
}

std::string always(const Scene&) { return ""; }

BenchMethod samplerMethod(const std::string& sampler, const std::string& description) {
    return {sampler, description, always,
            [sampler](Scene&, RenderOptions& options, int) { options.sampler = sampler; }, false};
}

BenchMethod filterMethod(const std::string& filter) {
    // The scene's own filter under sobol is the sobol method: not run twice.
    const auto whyNot = [filter](const Scene& scene) -> std::string {
        return scene.render.filter.value_or(defaultFilterName()) == filter
                   ? "the scene already uses the " + filter + " filter (the sobol method renders it)"
                   : "";
    };
    return {"filter-" + filter, "sobol sampler, " + filter + " reconstruction filter", whyNot,
            [filter](Scene& scene, RenderOptions& options, int) {
                scene.render.filter = filter;
                options.sampler = "sobol";
            },
            true};
}

BenchMethod lightMethod(const std::string& name, AreaSampling sampling, const std::string& description) {
    return {name, description, needsAreaLight,
            [sampling](Scene& scene, RenderOptions& options, int) {
                for (Light& light : scene.lights)
                    if (light.area) light.area->sampling = sampling;
                options.sampler = "sobol";
            },
            false};
}

int nextPowerOfTwo(int n) { return int(std::bit_ceil(unsigned(std::max(1, n)))); }

} // namespace

void applyAdaptiveBudget(RenderOptions& options, int spp) {
    options.adaptive = true;
    options.adaptiveError = 1.0 / std::sqrt(double(std::max(1, spp)));
    options.minSamplesPerPixel = nextPowerOfTwo(std::max(4, spp / 4));
    options.maxSamplesPerPixel = std::max(options.minSamplesPerPixel, nextPowerOfTwo(4 * spp));
}

const std::vector<BenchMethod>& benchMethods() {
    static const std::vector<BenchMethod> methods = {
        samplerMethod("independent", "independent uniform samples (the N^-1/2 baseline)"),
        samplerMethod("stratified", "jittered strata per dimension pair, padded"),
        samplerMethod("sobol", "Owen-scrambled Sobol, pixel x time x lens jointly stratified"),
        filterMethod("box"),
        filterMethod("tent"),
        filterMethod("gaussian"),
        lightMethod("light-grid", AreaSampling::PovGrid, "sobol sampler, area lights on POV-Ray's edge-to-edge grid"),
        lightMethod("light-stratified", AreaSampling::Stratified,
                    "sobol sampler, area lights stratified over their area (Cook)"),
        lightMethod("light-solid-angle", AreaSampling::SolidAngle,
                    "sobol sampler, area lights uniform in solid angle (Urena et al. 2013)"),
        {"light-split-4", "sobol sampler, 4 points on each area light per camera sample (light_samples 4)",
         needsAreaLight,
         [](Scene&, RenderOptions& options, int) {
             options.sampler = "sobol";
             options.lightSamples = 4;
         },
         false},
        {"adaptive", "sobol sampler, adaptive sampling (error 1/sqrt(N), N/4..4N samples)", always,
         [](Scene&, RenderOptions& options, int spp) {
             options.sampler = "sobol";
             applyAdaptiveBudget(options, spp);
         },
         false},
    };
    return methods;
}

const BenchMethod* findBenchMethod(const std::string& name) {
    for (const BenchMethod& method : benchMethods())
        if (method.name == name) return &method;
    return nullptr;
}

std::vector<std::string> benchMethodNames() {
    std::vector<std::string> names;
    for (const BenchMethod& method : benchMethods()) names.push_back(method.name);
    return names;
}

} // namespace drt::bench
