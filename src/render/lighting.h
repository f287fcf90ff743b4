// Direct lighting at a shading point: point lights, spotlights, area lights,
// and shadow rays filtered by transparent blockers.
//
// Area lights (`area_light <axis1>, <axis2>, n1, n2`): a rectangle centred on
// the light's position with edges axis1, axis2 (area A = |axis1 x axis2|), and
// N = n1 n2 sample points per shading point. Where the points go
// (AreaLight::sampling):
//   PovGrid     POV-Ray's edge-to-edge grid, centre + axis1 (i/(n1-1) - 1/2) +
//               axis2 (j/(n2-1) - 1/2); `jitter` moves each point by up to half
//               a grid step. Deterministic without jitter (and so biased).
//   Stratified  Cook: the N points of Sampler::get2DStratified mapped onto the
//               rectangle, one jittered point per cell (a (0,m,2)-net with the
//               sobol sampler: one point in each n1 x n2 cell when both are
//               powers of two). Always jittered, so unbiased.
//   SolidAngle  Urena, Fajardo & King (2013): the same N stratified values
//               mapped through SphericalRectangle, uniform in the solid angle
//               Omega the rectangle subtends. Falls back to Stratified for
//               `circular` lights, non-perpendicular axes and points in the
//               light's plane.
// What the points do (Light::areaIllumination):
//   off  POV-Ray's shadow-only averaging: the light shades as a point light at
//        its centre, times the visibility averaged over the N points.
//   on   full area illumination: each point shades as a point light, weighted
//        so that the sum estimates the light's integral over its area:
//          without inverse_square (POV-Ray's lights, no falloff): the mean over
//            the area of a point light of colour C, i.e. weight 1/N per area
//            sample and Omega r^2 / (N A |cos theta_e|) per solid-angle sample;
//          with inverse_square: a two-sided Lambertian emitter of radiance
//            L = C / A, irradiance E = int L cos theta_r dOmega, so weight
//            A L |cos theta_e| / (N r^2) = C |cos theta_e| / (N r^2) per area
//            sample (Cook's "each sample a point light carrying 1/N of the
//            power", with the emitter cosine) and L Omega / N per solid-angle
//            sample (r^2 and cos theta_e cancel exactly).
//        theta_e is the angle at the emitter between its normal axis1 x axis2
//        and the direction to the shaded point; a degenerate (zero-area) light
//        uses |cos theta_e| = 1, i.e. N point lights of colour C/N.
//   `circular` maps the unit square onto the inscribed ellipse (concentric map,
//   area pi A / 4); `orient` turns the axes to face the shaded point, keeping
//   their lengths; `adaptive` is ignored (the full set of N points is used).
// Sampler dimensions: light i of the scene at trace depth d uses
// lightDimension(d, i): the bounce's kOffsetLight pair for light 0, and
// dimensions past every bounce's for the others, so two area lights never
// share sample points.
#pragma once

#include "accel/accel.h"
#include "core/color.h"
#include "sampling/sampler.h"
#include "scene/scene.h"

#include <cstdint>

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
// also the transmittance of the media along the way (render/media.h).
Color shadowTransmittance(const Accelerator& accel, const Hit& from, const Vec3& target, double time,
                          RayCounts& counts, const Scene* mediaScene = nullptr);

struct ShadingPoint {
    Hit hit;
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

// Sum over the scene's lights of the diffuse and highlight terms at `point`.
Color directLighting(const Scene& scene, const Accelerator& accel, const ShadingPoint& point, Sampler& sampler,
                     RayCounts& counts);

} // namespace drt
