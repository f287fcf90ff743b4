// Whitted's recursion with POV-Ray's classic shading, plus Cook's glossy
// reflection and translucency, written with an explicit stack so that no
// max_trace_level can overflow the call stack.
//
// Trace depth: camera rays have depth 0; a reflected or refracted ray of depth
// d is traced only if d < min(max_trace_level, kTraceLevelLimit); deeper rays
// contribute black (POV-Ray). A ray whose weight (largest channel) falls below
// adc_bailout is dropped. At most kMaxRaysPerSample surface hits are shaded per
// camera sample (a guard against 2^depth trees of lossless glass); the rest is dropped.
//
// Glossy reflection / translucency: Finish::reflectionBlur / refractionBlur
// s in (0, 1] replace the ideal direction by one sample of the lobe
// cos^n around it, n = 2/s^2 - 2 (importance-sampled, so the weight is the
// reflectivity / transmittance itself); a sample on the wrong side of the
// surface has weight 0. Each traced ray spawns at most one reflected and one
// refracted ray, as in Whitted's tree: blur adds no branching. s == 0 draws no
// sample and is the ideal direction bit for bit.
// Sampler dimensions: reflection lobe bounceDimension(d, kOffsetLobe), refraction
// lobe bounceDimension(d, kOffsetRefractionLobe) (sampler.h's spare pair).
#pragma once

#include "accel/accel.h"
#include "core/color.h"
#include "render/lighting.h"
#include "sampling/sampler.h"
#include "scene/scene.h"

#include <vector>

namespace drt {

inline constexpr int kTraceLevelLimit = 256;
inline constexpr int kMaxRaysPerSample = 4096;
inline constexpr int kOffsetRefractionLobe = 6; // 2D, the spare dimensions of each bounce

class Integrator {
public:
    // `lightSamples`: RenderOptions::lightSamples.
    Integrator(const Scene& scene, const Accelerator& accel, int lightSamples = 1);

    // Radiance along a camera ray whose intersection is already found
    // (cameraFound, cameraHit: what Accelerator::intersect gives for it; the
    // renderer traces camera rays in packets). The sampler must already be at
    // the pixel sample (startPixelSample). Thread-safe: the only mutable state
    // is the sampler and `counts`, which each thread owns.
    // cameraShadows: what traceCameraShadows worked out ahead for the packet
    // of rays and hits that cameraRay and cameraHit are in (the hit's facing,
    // its shadow rays), or null.
    Color trace(const Ray& cameraRay, const Hit& cameraHit, bool cameraFound, Sampler& sampler,
                RayCounts& counts, const CameraShadows* cameraShadows = nullptr) const;

    // DirectLighting::traceCameraShadows for a camera packet's hits: their
    // facings and the shadow rays that go in packets.
    void traceCameraShadows(const Ray* rays, const Hit* hits, const bool* found, int count,
                            CameraShadows& out) const {
        lighting_.traceCameraShadows(rays, hits, found, count, out);
    }

    int maxTraceLevel() const { return maxTraceLevel_; }

    // The calling thread's scratch buffers of tracing and shading (the
    // integrator's, the lights', media's, textures' and the accelerator's),
    // installed for as long as the result is held. A render thread holds them
    // from before its first tile: accel/thread_scratch.h says why.
    static InstalledScratchSet installThreadBuffers();

private:
    // Where a ray stands in its sample's tree of rays.
    struct RayPlace {
        int depth = 0;
        const Object* medium = nullptr; // the media-holding object the ray is inside (render/media.h)
        int diffuseDepth = 0;           // radiosity bounces on the way (scene.h Radiosity)
    };
    struct PendingRay {
        // The ray spawned at `hit` along `direction` (from the surface:
        // Accelerator::offsetOrigin), at `time`.
        PendingRay(const Hit& hit, const Vec3& direction, double time, const Color& weight, const RayPlace& place);
        Ray ray;
        Color weight;
        RayPlace place;
        // A layer's reflection about the top layer's normal: shadeLayers
        // drops it where the transmitted ray is totally reflected (POV-Ray).
        bool mirrorsTop = false;
    };
    // The surface point a ray hit, before any texture layer's bump normal.
    struct SurfaceHit {
        const Ray& ray;
        const RayPlace& place;
        const Hit& hit;
        Vec3 incoming; // unit
        bool entering = true;
        Vec3 normal;       // facing the incoming ray
        double eta = 1;    // n_incident / n_transmitted
        PointLightSamples* lights = nullptr; // the point's light samples, shared by its layers
        const CameraShadows* cameraShadows = nullptr; // the camera packet's work ahead (lighting.h)
    };
    // seenWeight: the ray's weight after the fog and media in front of the hit.
    void shade(const Ray& ray, const RayPlace& place, const Color& seenWeight, const Hit& hit, Sampler& sampler,
               RayCounts& counts, Color& result, std::vector<PendingRay>& stack,
               const CameraShadows* cameraShadows) const;
    void shadeMatte(const SurfaceHit& surface, const Texture& layer, const Color& weight, Sampler& sampler,
                    RayCounts& counts, Color& result) const;
    void shadeTexture(const SurfaceHit& surface, const Texture& texture, const Color& weight, Sampler& sampler,
                      RayCounts& counts, Color& result, std::vector<PendingRay>& stack) const;
    void shadePatterned(const SurfaceHit& surface, const Texture& texture, const Color& weight, Sampler& sampler,
                        RayCounts& counts, Color& result, std::vector<PendingRay>& stack) const;
    void shadeLayers(const SurfaceHit& surface, const Texture* const* layers, size_t count, const Color& weight,
                     Sampler& sampler, RayCounts& counts, Color& result, std::vector<PendingRay>& stack) const;
    Vec3 bumpNormal(const Normal& bumps, const Hit& hit, double time, const Vec3& normal) const;

    // The per-thread buffers of trace and shade (integrator.cpp).
    struct Scratch;
    static Scratch& scratch();

    const Scene& scene_;
    const Accelerator& accel_;
    DirectLighting lighting_;
    int maxTraceLevel_;
    double adcBailout_;
    bool hasMedia_; // render/media.h; misses see atmospheric media inside this box:
    Vec3 mediaLower_{0, 0, 0}, mediaUpper_{0, 0, 0};
};

} // namespace drt
