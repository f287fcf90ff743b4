// One frame's scene (animation.h evaluateFrame): evaluated at the frame's
// clock and, when the scene reads the clock and the shutter is open, at more
// clock values over the shutter until the path through them predicts the
// scene halfway between them.
#include "animation/clock_motion.h"
#include "render/camera_path.h"
#include "render/light_path.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace drt {

namespace {

constexpr int kMaxSegments = 32;            // at most 33 evaluations over the shutter
constexpr double kRelativeTolerance = 1e-3; // of an object's size; of the view distance for cameras and lights

void overrideShutter(Scene& scene, const FrameOptions& options) {
    if (!options.shutter) return;
    scene.camera.shutterOpen = 0;
    scene.camera.shutterClose = *options.shutter;
}

// How far the merged scene's paths are, at each midpoint evaluation's time,
// from where that evaluation puts things: the largest ratio to the tolerance.
double misprediction(const Scene& merged, const std::vector<Evaluation>& midpoints) {
    double worst = 0;
    const std::vector<Identity> objectIds = objectIdentities(merged), lightIds = lightIdentities(merged);
    const double view = std::max(1e-9, length(merged.camera.lookAt.value_or(merged.camera.location + merged.camera.direction) -
                                              merged.camera.location));
    for (const Evaluation& mid : midpoints) {
        const std::map<Identity, size_t> objects = indexByIdentity(objectIdentities(mid.scene));
        for (size_t i = 0; i < merged.objects.size(); ++i) {
            const auto found = objects.find(objectIds[i]);
            if (found == objects.end()) continue;
            const Object& o = merged.objects[i];
            const std::optional<Transform> actual = placementIn(o, mid.scene.objects[found->second], mid.time);
            if (!actual) continue;
            const Transform predicted = placementAt(o.transform, o.motion, mid.time);
            Vec3 centre;
            double size = 1;
            objectExtent(o, centre, size);
            for (int c = 0; c < 9; ++c) {
                const Vec3 p = c == 8 ? centre : centre + 0.5 * size * Vec3{c & 1 ? 1.0 : -1.0, c & 2 ? 1.0 : -1.0, c & 4 ? 1.0 : -1.0};
                worst = std::max(worst, length(predicted.point(p) - actual->point(p)) / (kRelativeTolerance * size));
            }
        }
        const std::map<Identity, size_t> lights = indexByIdentity(lightIdentities(mid.scene));
        for (size_t i = 0; i < merged.lights.size(); ++i) {
            const auto found = lights.find(lightIds[i]);
            if (found == lights.end()) continue;
            const LightKey a = lightPose(merged.lights[i], mid.time), b = lightPose(mid.scene.lights[found->second], mid.time);
            const double d = std::max({length(a.position - b.position), length(a.pointAt - b.pointAt),
                                       length(a.axis1 - b.axis1), length(a.axis2 - b.axis2)});
            worst = std::max(worst, d / (kRelativeTolerance * view));
        }
        if (!merged.cameraKeys.empty()) {
            const CameraSpec a = cameraSpecAt(merged.camera, merged.cameraKeys, mid.time), &b = mid.scene.camera;
            double d = length(a.location - b.location);
            if (a.lookAt && b.lookAt) d = std::max(d, length(*a.lookAt - *b.lookAt));
            d = std::max(d, view * length(normalize(a.direction) - normalize(b.direction)));
            if (a.angle && b.angle) d = std::max(d, view * std::fabs(*a.angle - *b.angle) * kPi / 180);
            d = std::max({d, std::fabs(a.aperture - b.aperture), length(a.up - b.up) * view, length(a.sky - b.sky) * view});
            worst = std::max(worst, d / (kRelativeTolerance * view));
        }
    }
    return worst;
}

} // namespace

std::optional<Scene> evaluateFrame(const SceneEvaluator& evaluate, const FrameClock& frame,
                                   const FrameOptions& options, Diagnostics& diagnostics, FrameReport* report) {
    FrameReport local;
    FrameReport& out = report ? *report : local;
    out = FrameReport{};
    std::optional<Scene> base = evaluate(frame, diagnostics);
    if (!base || diagnostics.hasErrors()) return base;
    overrideShutter(*base, options);
    const double open = base->camera.shutterOpen, close = base->camera.shutterClose;
    if (!base->readsClock || frame.clockDelta == 0) return base;

    // Scene time t of the frame is clock + t clock_delta.
    const auto evaluateAt = [&](double time) -> std::optional<Evaluation> {
        if (time == 0) return Evaluation{0, *base};
        FrameClock at = frame;
        at.clock = frame.clock + time * frame.clockDelta;
        Diagnostics quiet; // the base evaluation's warnings are the ones shown
        std::optional<Scene> scene = evaluate(at, quiet);
        ++out.evaluations;
        if (!scene || quiet.hasErrors()) {
            diagnostics.error({}, fmt::format("the scene fails when evaluated at clock {} (scene time {} of the "
                                              "frame, within its shutter):\n{}",
                                              at.clock, time, quiet.formatAll()));
            return std::nullopt;
        }
        overrideShutter(*scene, options);
        return Evaluation{time, std::move(*scene)};
    };
    if (!(close > open)) { // a zero-length shutter: the scene as it is then
        std::optional<Evaluation> e = evaluateAt(open);
        if (!e) return std::nullopt;
        return std::move(e->scene);
    }
    std::vector<Evaluation> samples;
    for (double time : {open, close}) {
        std::optional<Evaluation> e = evaluateAt(time);
        if (!e) return std::nullopt;
        samples.push_back(std::move(*e));
    }
    for (int segments = 1;; segments *= 2) {
        FrameReport merging;
        const Scene merged = mergeEvaluations(samples, merging);
        std::vector<Evaluation> midpoints;
        for (int k = 0; k < segments; ++k) {
            std::optional<Evaluation> e = evaluateAt(open + (close - open) * (k + 0.5) / segments);
            if (!e) return std::nullopt;
            midpoints.push_back(std::move(*e));
        }
        const double worst = misprediction(merged, midpoints);
        // Every evaluation made is used: the midpoints join the samples.
        for (Evaluation& e : midpoints) samples.push_back(std::move(e));
        std::sort(samples.begin(), samples.end(), [](const Evaluation& a, const Evaluation& b) { return a.time < b.time; });
        if (worst <= 1 || segments * 2 >= kMaxSegments) break;
    }
    const int evaluations = out.evaluations;
    Scene merged = mergeEvaluations(samples, out);
    out.evaluations = evaluations;
    return merged;
}

} // namespace drt
