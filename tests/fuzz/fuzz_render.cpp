// libFuzzer harness: .drt scene text -> scene model -> an 8 x 6 image at 2
// samples per pixel on one thread (accelerator build, every shape's
// intersection, textures, lights, media). A scene error or a RenderError is a
// clean outcome; a crash, a sanitizer report or a NaN in a pixel is a finding.
#include "fuzz_support.h"
#include "assets/assets.h"
#include "lang/load.h"
#include "render/render.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace {

// Scenes may legitimately ask for hours of work (a 256 x 256 area light,
// 4096 x 4096 media samples per ray): the limits let them, and the fuzzer is
// after wrong behaviour, not long renders. Such counts are cut to a few here.
void cutWork(std::vector<drt::Media>& media) {
    for (drt::Media& m : media) {
        m.intervals = std::min(m.intervals, 4);
        m.samples = std::min(m.samples, 4);
    }
}

void cutWork(drt::Object& object) {
    cutWork(object.interior.media);
    if (drt::Csg* csg = std::get_if<drt::Csg>(&object.shape))
        for (drt::Object& child : csg->children) cutWork(child);
}

void cutWork(drt::Scene& scene) {
    for (drt::Light& light : scene.lights)
        if (light.area) {
            light.area->size1 = std::min(light.area->size1, 4);
            light.area->size2 = std::min(light.area->size2, 4);
        }
    cutWork(scene.media);
    for (drt::Object& object : scene.objects) cutWork(object);
    scene.global.maxTraceLevel = std::min(scene.global.maxTraceLevel, 6);
}

} // namespace

int drt::fuzz::fuzzRender(const uint8_t* data, size_t size) {
    drt::Diagnostics diagnostics = drt::fuzz::fuzzDiagnostics();
    std::optional<drt::Scene> scene =
        drt::loadSceneText(drt::fuzz::text(data, size), "fuzz.drt", diagnostics, drt::fuzz::includeDir());
    if (!scene || diagnostics.hasErrors() || !drt::resolveAssets(*scene, diagnostics)) return 0;
    if (scene->objects.size() > 2000) return 0; // a big scene is the front end's test, not the renderer's
    cutWork(*scene);
    drt::RenderOptions options = drt::resolveRenderOptions(scene->render);
    options.width = 8;
    options.height = 6;
    options.samplesPerPixel = 2;
    options.adaptive = false;
    options.threads = 1;
    try {
        drt::RenderResult result = drt::render(*scene, options);
        for (float v : result.color.pixels)
            if (std::isnan(v)) std::abort(); // NaN samples must be caught before the film
    } catch (const drt::RenderError&) {
    }
    return 0;
}

DRT_FUZZ_ENTRY_POINT(fuzzRender)
