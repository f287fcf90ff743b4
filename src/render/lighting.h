// Direct lighting at a shading point: point lights, spotlights, area lights,
// and shadow rays filtered by transparent blockers.
//
// Area lights (`area_light <axis1>, <axis2>, n1, n2`): a rectangle centred on
// the light's position with edges axis1, axis2 (area A = |axis1 x axis2|).
// Cook's association: a shading point sends one shadow ray to the light per
// camera sample (K = 1), its position taken from the light's own 2-D sampler
// dimension, so that the pixel's spp samples stratify the light jointly with
// pixel, lens and time; n1 x n2 sets how the light is stratified, not how many
// rays a hit sends. The render's `light_samples K` splits a camera sample
// (RenderOptions::lightSamples): its K points are the light sequence's points
// K i .. K i + K - 1 of the pixel's sample i, so the pixel's N samples still
// stratify N K points as one sequence does, for N camera paths; a pixel whose
// noise is that of its soft shadows then needs K times fewer camera samples.
// pov_grid alone ignores K. Where the points go
// (AreaLight::sampling):
//   Stratified  the pixel's light samples are one scrambled (0,2)-sequence
//               over the rectangle (Sampler::get2D). Unbiased.
//   SolidAngle  Urena, Fajardo & King (2013): the same values mapped through
//               SphericalRectangle, uniform in the solid angle Omega the
//               rectangle subtends. Falls back to Stratified for `circular`
//               lights, non-perpendicular axes and points in the light's plane.
//   Grid        POV-Ray's point set: the edge-to-edge grid centre +
//               axis1 (i/(n1-1) - 1/2) + axis2 (j/(n2-1) - 1/2), each point moved
//               by up to half a grid step with `jitter`, and weighted as
//               POV-Ray weighs them: it averages the grid quadrant by quadrant
//               down to single cells, each cell the mean of its four corners,
//               so a row's two end points weigh half an inner one (the
//               trapezoid rule in each axis). The sample's 2-D light value w
//               picks the point nearest w (n1 - 1, n2 - 1), which chooses each
//               point with its weight, and with jitter where w lies around it
//               places the point within its step, so the pixel's samples
//               stratify the grid as the (0,2)-sequence stratifies the square
//               (exactly for n - 1 a power of two and enough samples) and the
//               pixel converges to POV-Ray's weighted sum over the grid. The
//               POV-Ray front end's default.
//   PovGrid     POV-Ray's own method: every one of the n1 n2 grid points, with
//               those weights, at every shading point and camera sample
//               (K = n1 n2), for comparisons with POV-Ray at equal settings.
// What the points do (Light::areaIllumination):
//   off  POV-Ray's shadow-only averaging: the light shades as a point light at
//        its centre, times the visibility averaged over the K points (PovGrid:
//        weighted as above).
//   on   full area illumination: each point shades as a point light, weighted
//        so that the sum estimates the light's integral over its area:
//          without inverse_square (POV-Ray's lights, no falloff): the mean over
//            the area of a point light of colour C, i.e. weight 1/K per area
//            sample and Omega r^2 / (K A |cos theta_e|) per solid-angle sample;
//          with inverse_square: a two-sided Lambertian emitter of radiance
//            L = C / A, irradiance E = int L cos theta_r dOmega, so weight
//            A L |cos theta_e| / (K r^2) = C |cos theta_e| / (K r^2) per area
//            sample (Cook's "each sample a point light carrying 1/K of the
//            power", with the emitter cosine) and L Omega / K per solid-angle
//            sample (r^2 and cos theta_e cancel exactly).
//        theta_e is the angle at the emitter between its normal axis1 x axis2
//        and the direction to the shaded point; a degenerate (zero-area) light
//        uses |cos theta_e| = 1, i.e. K point lights of colour C/K.
//        Highlights (phong, specular) of such a light, when its points have
//        a density over its area (stratified or solid_angle, not a grid):
//        multiple importance sampling (Veach's power heuristic). Besides
//        the light's K points, one direction is drawn from the finish's
//        highlight lobe (shading.h) in highlightDimension; where it meets
//        the light it is one more estimate with its own shadow ray. A point
//        is weighted (K p_light)^2 / ((K p_light)^2 + p_lobe^2) and the lobe's
//        direction p_lobe^2 / ((K p_light)^2 + p_lobe^2), densities per
//        steradian, so together they estimate the same integral as the
//        light's points alone, and a narrow highlight that the points seldom
//        find is found by its lobe. The diffuse term takes the points alone.
//   `circular` maps the unit square onto the inscribed ellipse (concentric map,
//   area pi A / 4); `orient` turns the axes to face the shaded point, keeping
//   their lengths; `adaptive` is ignored.
// Sampler dimensions: light i of the scene at trace depth d uses
// lightDimension(d, i): the bounce's kOffsetLight pair for light 0, and
// dimensions past every bounce's for the others, so two area lights never
// share sample points.
//
// Shadow rays: in a scene where no shadow-casting surface can let light
// through (no filter or transmit in any of their pigments), a shadow ray is
// one occlusion query; otherwise a blocked ray walks through its blockers,
// filtering by each.
#pragma once

#include "accel/accel.h"
#include "core/color.h"
#include "render/shading.h"
#include "sampling/sampler.h"
#include "scene/scene.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace drt {

struct RayCounts {
    uint64_t camera = 0;
    uint64_t shadow = 0;
    uint64_t secondary = 0;
};

// At most this many transparent blockers are filtered through per shadow ray;
// a longer chain counts as fully blocked.
inline constexpr int kMaxShadowBlockers = 64;

// The light reaching `target` from `from` (a surface hit): 1 if nothing casts a
// shadow in between, else the product of P*filter + transmit over every
// shadow-casting surface crossed (0 at the first opaque one). With `mediaScene`,
// also the transmittance of the media along the way (render/media.h). One
// occlusion query (Accelerator::occludedOpaque) answers a clear segment and
// one blocked by a surface that lets no light through; only the surfaces of a
// segment that crosses nothing else are found one by one.
Color shadowTransmittance(const Accelerator& accel, const Hit& from, const Vec3& target, double time,
                          RayCounts& counts, const Scene* mediaScene = nullptr);

// Installs the calling thread's buffer of shadowTransmittance (accel/thread_scratch.h).
std::unique_ptr<InstalledScratch> installLightingScratch();

// The accelerators of the scene's projected_through objects
// (Light::projectedThrough), by light; built once per render.
class ProjectedThrough {
public:
    explicit ProjectedThrough(const Scene& scene);
    ~ProjectedThrough();
    // The light's projected_through objects, or null for an ordinary light.
    const Accelerator* of(size_t light) const { return light < byLight_.size() ? byLight_[light].get() : nullptr; }
    bool any() const { return !byLight_.empty(); }

private:
    std::vector<std::unique_ptr<Accelerator>> byLight_; // empty if no light has any
};

// shadowTransmittance for a light at `target` that shines through the objects
// of `projected` (POV-Ray's projected_through): black if the segment from
// `from` to the light does not cross them; else what shadowTransmittance gives
// up to the first crossing (nothing beyond it casts a shadow, the placed copy
// of the object among them). Null `projected`: shadowTransmittance. A
// `shadowless` light casts no shadow: 1, or through `projected` 1 where the
// segment crosses it and 0 elsewhere (POV-Ray's rule).
Color lightTransmittance(const Accelerator& accel, const Accelerator* projected, bool shadowless, const Hit& from,
                         const Vec3& target, double time, RayCounts& counts, const Scene* mediaScene = nullptr);

// How a surface hit faces the ray that found it, as the shading takes it:
// the ray's unit direction, whether the ray enters the object (meets the
// outside of the geometric normal), and the shading normal turned to the
// ray's side, or the geometric normal so turned where the shading normal
// would then face away from the ray.
struct Facing {
    Vec3 incoming; // unit
    Vec3 normal;   // unit, facing the incoming ray
    bool entering = true;
};

inline Facing facingOf(const Vec3& direction, const Hit& hit) {
    Facing f;
    f.incoming = normalize(direction);
    f.entering = dot(f.incoming, hit.geometricNormal) < 0;
    f.normal = f.entering ? hit.shadingNormal : -hit.shadingNormal;
    if (dot(f.normal, f.incoming) >= 0) f.normal = f.entering ? hit.geometricNormal : -hit.geometricNormal;
    return f;
}

// The shadow rays of a camera packet's hits, traced ahead of their shading
// as packets (one per light: DirectLighting::traceCameraShadows). Only for
// what one occlusion query answers exactly (a point light that neither moves
// nor is a spotlight, area light or shadowless, no media along its rays); the
// shading then takes the answer instead of tracing the same ray alone, and
// counts the ray when it does. A ray that crosses only shadow casters that
// may let light through (Accelerator::occludedOpaque) gets no answer: the
// shading traces it alone and filters the light through them.
// A shadow ray the shading does not ask for is traced and not counted.
// The hits' facings, which decide the rays, are kept for the shading too.
struct CameraShadows {
    // Written by traceCameraShadows, read by DirectLighting::shade and Integrator::shade.
    const Hit* hits_ = nullptr; // the packet's hits
    int count_ = 0;             // 0 if no light's shadow rays go in packets
    Facing facings_[Accelerator::kPacketSize]; // by hit, set for the found ones
    // By light * Accelerator::kPacketSize + hit: 0 not traced, 1 visible, 2 blocked.
    std::vector<uint8_t> answers_;

    // Nothing was worked out ahead (no light's shadow rays go in packets).
    bool empty() const { return count_ == 0; }
    // The index of `hit` in the packet, or -1 if it is not one of the packet's
    // hits (compared as addresses: a shading point's hit need not be one).
    int indexOf(const Hit& hit) const {
        const auto at = reinterpret_cast<uintptr_t>(&hit), first = reinterpret_cast<uintptr_t>(hits_);
        if (at < first || at >= first + sizeof(Hit) * size_t(count_)) return -1;
        return static_cast<int>((at - first) / sizeof(Hit));
    }
};

struct ShadingPoint {
    const Hit* hit = nullptr; // the surface point, not copied
    // A camera hit's shadow answers traced ahead (or null).
    const CameraShadows* cameraShadows = nullptr;
    Vec3 normal;   // unit, facing the incoming ray
    Vec3 incoming; // unit ray direction
    ColorFT pigment;
    const Finish* finish = nullptr;
    double time = 0;
    int depth = 0;
};

// Lights after the first take their dimensions from here on: past every
// bounce's dimensions up to depth 1024 (the integrator's limit is lower; it
// static_asserts so).
inline constexpr int kMaxLightDepth = 1024;
inline constexpr int kFirstExtraLightDimension = bounceDimension(kMaxLightDepth, 0);

// The 2D sampler dimension of light `lightIndex` at trace depth `depth`.
int lightDimension(int depth, int lightIndex);
// The 1D sampler dimension of crand's noise for light `lightIndex` at depth
// `depth`: past every lightDimension (which span 2^30 from kFirstExtraLightDimension).
int crandDimension(int depth, int lightIndex);
// The 2D sampler dimension of the direction drawn from a highlight's lobe
// toward area light `lightIndex` at depth `depth` (DirectLighting::shade):
// past every other dimension (crand's, the media's and radiosity's included).
int highlightDimension(int depth, int lightIndex);

// The light samples of one surface point and their shadows, shared by every
// layer and pattern entry of its texture: all of them shade the same point at
// the same camera sample, so they draw the same light samples (the same
// sampler dimensions) and would trace the same shadow rays.
class PointLightSamples {
public:
    // Forget the samples: the next shading point is another one.
    void clear() { ++generation_, samples_.clear(); }

private:
    friend class DirectLighting;
    struct Sample {
        Vec3 position;
        double weight = 0;
        bool tested = false; // visibility is known
        Color visibility;
    };
    struct Range {
        uint64_t generation = 0; // the samples are drawn for this point if it equals generation_
        int begin = 0;           // the light's first sample in samples_
        int count = 0;
        Sample single;           // a light without area: its one sample, kept here rather than in samples_
    };
    uint64_t generation_ = 1;
    std::vector<Range> lights_; // by light
    std::vector<Sample> samples_;
    Light moved_; // a moving light as it is at the shaded point's time (render/light_path.h)
    SpotCones movedCones_; // its cones, if a spotlight
    // The highlight of the last finish that met an area light, and how far it reaches (lighting.cpp).
    struct Reach {
        double phong = -1, phongSize = 0, specular = -1, roughness = 0;
        double cosReach = 1;
    };
    Reach reach_;
};

// The scene's lights as one render sees them: what is known before tracing
// (whether shadows can be filtered) and the direct lighting at a shading point.
class DirectLighting {
public:
    // shortWays: shade plain point lights (plainPoint_) the short way and
    // trace an area light's points' shadow rays together (traceAhead), the
    // same bits as the general way (false: every light the general way, each
    // ray alone, for tests).
    // lightSamples: K of RenderOptions::lightSamples (at least 1).
    DirectLighting(const Scene& scene, const Accelerator& accel, bool shortWays = true, int lightSamples = 1);

    // Sum over the scene's lights of the diffuse and highlight terms at
    // `point`. `samples` holds the point's light samples: cleared for each new
    // surface point, kept while its layers are shaded.
    Color shade(const ShadingPoint& point, PointLightSamples& samples, Sampler& sampler, RayCounts& counts) const;

    // Traces, light by light as one packet, the shadow rays the shading of
    // camera hits hits[0..count) will ask for (where found[k]), into `out`:
    // the rays shadowTransmittance would trace from hits[k] at rays[k].time
    // toward each light that CameraShadows allows and the surface, as the
    // integrator turns its normal to the viewer, faces. Nothing for a scene
    // without such lights.
    void traceCameraShadows(const Ray* rays, const Hit* hits, const bool* found, int count,
                            CameraShadows& out) const;

    const ProjectedThrough& projectedThrough() const { return projected_; }

private:
    // The visibility of light i (as it is at sp: `light`) from sp at sample s,
    // found once per sample: traced ahead, or traced now.
    const Color& visibility(const ShadingPoint& sp, size_t i, const Light& light, PointLightSamples::Sample& s,
                            RayCounts& counts) const;
    // The visibility of those of samples[0..count) of light i from sp for
    // which wanted(k) holds, each of which the caller will ask for, traced
    // ahead kPacketSize rays at a time as one Embree packet where one
    // occlusion query answers them (no media, no projected_through): the same
    // rays, the same answers as visibility() would find one by one. Those the
    // query cannot settle (past a surface that may let light through) are
    // left to visibility(). Defined in lighting.cpp.
    template <class Wanted>
    void traceAhead(const ShadingPoint& sp, size_t i, const Light& light, PointLightSamples::Sample* samples,
                    int count, RayCounts& counts, Wanted&& wanted) const;

    const Scene& scene_;
    const Accelerator& accel_;
    bool hasMedia_; // media or fog anywhere: shadow rays of lights that interact with them look for them
    bool anyLightMoves_; // some light moves over the shutter (render/light_path.h)
    int lightSamples_;   // K: points per area light per shading point and camera sample
    bool traceAhead_;    // shortWays: traceAhead traces together
    ProjectedThrough projected_;
    std::vector<SpotCones> cones_; // by light, as written (a moving light's are taken at each point)
    std::vector<int> packetLights_; // the lights whose camera shadow rays go in packets (CameraShadows)
    // By light: a still point light, neither a spotlight nor an area or
    // parallel light, not fading and not black, which shade takes a short way.
    std::vector<uint8_t> plainPoint_;
};

// The shadow ray shadowTransmittance traces first from `from` to `target`.
Ray shadowRay(const Hit& from, const Vec3& target, double time);
// The same from an origin already offset (Accelerator::offsetOrigin, which
// depends on the target only by the side of the surface it lies on).
Ray shadowRayFrom(const Vec3& origin, const Vec3& target, double time);

} // namespace drt
