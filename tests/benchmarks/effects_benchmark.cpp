// "A scene pays only for the effects it uses": a plain Whitted scene
// (examples/whitted.drt: point lights, mirror and glass, pinhole camera, no
// motion, no blur) rendered by the full renderer, against a bare Whitted
// tracer below that has no distribution code at all: no sampler, no lens or
// time dimensions, no area-light or lobe branches, one ray through each pixel
// centre. Both trace the same ray tree per pixel (the counters show the rays),
// so equal time per ray means the effects code costs nothing when unused.
//
// Run: drt_benchmarks [--benchmark_repetitions=5]. Not part of ctest.
#include "accel/accel.h"
#include "lang/load.h"
#include "render/camera.h"
#include "render/directions.h"
#include "render/lighting.h"
#include "render/pigment.h"
#include "render/render.h"
#include "render/shading.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace drt {
namespace {

constexpr int kWidth = 160, kHeight = 120;

const Scene& whittedScene() {
    static const Scene scene = [] {
        Diagnostics diagnostics;
        std::optional<Scene> s = loadSceneFile(DRT_SOURCE_DIR "/examples/whitted.drt", diagnostics);
        if (!s) throw std::runtime_error(diagnostics.formatAll());
        return *s;
    }();
    return scene;
}

// Whitted's recursion with the classic POV-Ray shading, as render/integrator.cpp
// does it for a scene without blur, area lights, lens or shutter.
class BareWhitted {
public:
    BareWhitted(const Scene& scene, const Accelerator& accel) : scene_(scene), accel_(accel) {}

    Color trace(const Ray& ray, const Color& weight, int depth, RayCounts& counts) const {
        depth == 0 ? ++counts.camera : ++counts.secondary;
        Hit hit;
        if (!accel_.intersect(ray, hit)) return weight * scene_.background;
        const Object& object = *hit.object;
        const Finish& finish = object.texture->finish;
        const Vec3 incoming = normalize(ray.direction);
        const bool entering = dot(incoming, hit.geometricNormal) < 0;
        Vec3 normal = entering ? hit.shadingNormal : -hit.shadingNormal;
        if (dot(normal, incoming) >= 0) normal = entering ? hit.geometricNormal : -hit.geometricNormal;
        Color w = weight;
        if (!entering) w *= interiorAttenuation(object.interior, hit.t * length(ray.direction));
        const ColorFT pigment = evaluatePigment(object.texture->pigment, hit.point);
        Color result = w * ambientTerm(finish, pigment, scene_.global.ambientLight);
        for (const Light& light : scene_.lights) {
            const Vec3 toLight = light.position - hit.point;
            const Vec3 l = normalize(toLight);
            if (!(dot(normal, l) > 0)) continue;
            const Color visible = light.color * shadowTransmittance(accel_, hit, light.position, 0, counts);
            result += w * lightTerm(finish, pigment, normal, incoming, l, visible);
        }
        if (depth + 1 >= scene_.global.maxTraceLevel) return result;
        const double ior = object.interior.ior > 0 ? object.interior.ior : 1.0;
        const double eta = entering ? 1.0 / ior : ior;
        const double cosIncident = std::clamp(-dot(incoming, normal), 0.0, 1.0);
        const Color reflected =
            reflectivity(finish, cosIncident, eta) * metallicTint(finish.reflectionMetallic, pigment, cosIncident);
        Color transmitted = pigment.rgb * pigment.filter + Color(pigment.transmit);
        if (finish.conserveEnergy)
            transmitted *= Color(std::max(0.0, 1 - reflected.r), std::max(0.0, 1 - reflected.g),
                                 std::max(0.0, 1 - reflected.b));
        const auto worth = [&](const Color& c) { return maxComponent(c) > 0 && maxComponent(c) >= scene_.global.adcBailout; };
        const Vec3 mirror = reflect(incoming, normal);
        if (worth(w * reflected)) result += trace(spawn(hit, mirror), w * reflected, depth + 1, counts);
        if (worth(w * transmitted)) {
            Vec3 direction = incoming;
            if (eta != 1.0 && !refract(incoming, normal, eta, direction)) direction = mirror;
            result += trace(spawn(hit, direction), w * transmitted, depth + 1, counts);
        }
        return result;
    }

private:
    static Ray spawn(const Hit& hit, const Vec3& direction) {
        Ray r;
        r.origin = Accelerator::offsetOrigin(hit, direction);
        r.direction = direction;
        return r;
    }
    const Scene& scene_;
    const Accelerator& accel_;
};

void reportRays(benchmark::State& state, uint64_t rays) {
    state.counters["rays"] = double(rays);
    state.counters["Mrays/s"] =
        benchmark::Counter(double(rays) * double(state.iterations()) / 1e6, benchmark::Counter::kIsRate);
}

void BM_WhittedFullRenderer(benchmark::State& state) {
    const Scene& scene = whittedScene();
    RenderOptions options;
    options.width = kWidth;
    options.height = kHeight;
    options.samplesPerPixel = 1;
    options.threads = 1;
    uint64_t rays = 0;
    for (auto _ : state) {
        const RenderResult r = render(scene, options);
        rays = r.stats.totalRays();
        benchmark::DoNotOptimize(r.color.pixels.data());
    }
    reportRays(state, rays);
}

void BM_WhittedBareTracer(benchmark::State& state) {
    const Scene& scene = whittedScene();
    uint64_t rays = 0;
    for (auto _ : state) {
        const Accelerator accel(scene); // built per iteration, as render() does
        const ResolvedCamera camera = resolveCamera(scene.camera, kWidth, kHeight);
        const BareWhitted tracer(scene, accel);
        RayCounts counts;
        Color sum(0);
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x)
                sum += tracer.trace(camera.generateRay(x + 0.5, y + 0.5, {0.5, 0.5}, 0), Color(1), 0, counts);
        rays = counts.camera + counts.shadow + counts.secondary;
        benchmark::DoNotOptimize(sum);
    }
    reportRays(state, rays);
}

BENCHMARK(BM_WhittedFullRenderer)->Unit(benchmark::kMillisecond)->UseRealTime(); // render() traces on TBB workers
BENCHMARK(BM_WhittedBareTracer)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace
} // namespace drt

BENCHMARK_MAIN();
