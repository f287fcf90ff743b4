// The methods `drt bench` compares: named bundles of (scene tweaks, option
// tweaks) applied to a copy of the scene and its render options. Every switch
// the renderer has is one family:
//
//   name               what changes                                     needs
//   independent        sampler independent (N^-1/2 baseline)            -
//   stratified         sampler stratified (jittered, padded)            -
//   sobol              sampler sobol (Owen-scrambled)                   -
//   filter-box         sobol, box reconstruction filter                 -
//   filter-tent        sobol, tent filter                               -
//   filter-gaussian    sobol, Gaussian filter                           -
//   light-grid         sobol, area lights on POV-Ray's grid             an area light
//   light-stratified   sobol, area lights stratified over the area      an area light
//   light-solid-angle  sobol, area lights uniform in solid angle        an area light
//   adaptive           sobol, adaptive sampling at the same budget      -
//
// A filter changes the image itself (it is part of the pixel's definition), so
// filter methods are measured against a reference rendered with their own
// filter; every other method estimates the scene as written and shares its
// reference, so a biased method (e.g. an unjittered light grid) shows as an
// error floor and a bias flag. Glossy samples per hit are not a renderer
// switch yet (one lobe sample per camera sample), so there is no method for them.
#pragma once

#include "render/render.h"
#include "scene/scene.h"

#include <functional>
#include <string>
#include <vector>

namespace drt::bench {

struct BenchMethod {
    std::string name;
    std::string description;
    // "" if the method applies to `scene`, else why not (shown in the summary).
    std::function<std::string(const Scene&)> whyNotApplicable;
    // Applied to copies of the scene and options before a render at budget
    // `spp` samples per pixel (options.samplesPerPixel is already spp).
    std::function<void(Scene&, RenderOptions&, int spp)> apply;
    // True if the method changes the expected image (its reference is then
    // rendered with the method's scene tweaks).
    bool changesExpectedImage = false;
};

// Every method, in the order of the table above.
const std::vector<BenchMethod>& benchMethods();
// Nullptr if no method has that name.
const BenchMethod* findBenchMethod(const std::string& name);
std::vector<std::string> benchMethodNames();

// The adaptive method at budget N samples per pixel: error target 1/sqrt(N)
// (so a pixel's contribution to relMSE is at most about 1/N, what a pixel of
// unit relative variance gets from N fixed samples), at least max(4, N/4) and
// at most 4N samples, rounded to powers of two.
void applyAdaptiveBudget(RenderOptions& options, int spp);

} // namespace drt::bench
