// Participating media (scene.h Media): single scattering as POV-Ray's.
//
// Along a ray segment of length L from o in unit direction d, with the media
// coefficients at x = o + t d (density D(x), the product of the densities'
// colours; sums over all media of the segment):
//   extinction  k(x) = D (a + extinction * s)
//   source      S(x) = D e + D s * sum_lights 4 pi p(theta) L_light(x)
// the segment lets through T(L) = exp(-int_0^L k) of what lies behind it and
// adds int_0^L T(t) S(t) dt. p is the scattering type's phase function,
// normalised so that int_sphere p dOmega = 1 (4 pi p = 1 for isotropic media:
// POV-Ray's convention that the scattering colour is the light scattered per
// unit length). theta is the angle between the direction to the light and d
// (theta = 0: looking into the light, where forward scattering is strongest).
// L_light includes the light's spotlight and fade factors and its shadow test,
// dimmed by media on the way when Light::mediaAttenuation; area lights scatter
// as point lights at their centre. Lights with media_interaction off do not scatter.
//
// Estimator: the segment is cut into N equal strata (N = max over the media
// of intervals x samples, at least 1); stratum j is sampled at one jittered
// position (j + u_j) / N, u_j from the sampler (dimension mediaDimension(depth),
// the j-th of N stratified values), and treated as homogeneous with the
// coefficients found there: it lets through exp(-k h) and adds
// T_j S (1 - exp(-k h)) / k (S h where k = 0), h = L / N. So homogeneous media
// are exact for any N, and the estimate is unbiased in the limit of many
// pixel samples. Shadow rays take the extinction at stratum midpoints
// (deterministic; exact for homogeneous media).
#pragma once

#include "accel/accel.h"
#include "core/color.h"
#include "render/lighting.h"
#include "sampling/sampler.h"
#include "scene/scene.h"

#include <algorithm>
#include <vector>

namespace drt {

// Media dimensions lie past every extra light's (lighting.h): one per trace depth.
inline constexpr int kFirstMediaDimension = kFirstExtraLightDimension + (1 << 30) + 2;
inline int mediaDimension(int depth) { return kFirstMediaDimension + std::clamp(depth, 0, kMaxLightDepth - 1) * 2; }

// Rays that hit nothing see atmospheric media up to where they leave the box
// around the scene's finite objects and its lights: the distance from `origin`
// along the unit `direction` to that exit (0 if the ray never enters the box).
double mediaMissDistance(const Vec3& lower, const Vec3& upper, const Vec3& origin, const Vec3& direction);

// The phase function p(cos theta) of a POV-Ray scattering type (1-5; others
// isotropic), normalised over the sphere:
//   1 isotropic         1 / (4 pi)
//   2 Mie haze          (1 + 9 ((1 + c) / 2)^8) / (8 pi)
//   3 Mie murky         (1 + 50 ((1 + c) / 2)^32) / (4 pi (1 + 50/33))
//   4 Rayleigh          3 (1 + c^2) / (16 pi)
//   5 Henyey-Greenstein (1 - g^2) / (4 pi (1 + g^2 - 2 g c)^1.5)
// (POV-Ray 3.7 scales types 2-4 by constants that make their mean over the
// sphere 1.153, 1.247 and 1.066 instead of 1.)
double phaseFunction(int type, double eccentricity, double cosTheta);

// The density of a medium at a world point: the product of its densities'
// colours (1 without any).
Color mediaDensity(const Media& media, const Vec3& point);

// The media of one ray segment.
using MediaList = std::vector<const Media*>;

// Installs the calling thread's buffer of integrateMedia (accel/thread_scratch.h).
std::unique_ptr<InstalledScratch> installMediaScratch();

// The media along the part of a ray that ends at `hit` travelling along
// `direction` (hit == nullptr: a ray that hits nothing), for a ray known to be
// inside the media-holding object `inside` (nullptr: none known). The segment
// is inside the object the ray leaves at `hit`, else inside `inside`. It sees
// that object's interior media; a hollow one also lets in the media around it
// (`inside`'s when the ray leaves another object, else the scene's
// atmospheric media), a non-hollow one nothing else. Appends to `out`.
void segmentMedia(const Scene& scene, const Object* inside, const Hit* hit, const Vec3& direction, MediaList& out);

// The media-holding object a transmitted ray is inside after crossing the
// surface of `object` (entering it or leaving it), when it was inside `before`.
// One level is kept: leaving a media object returns to none.
const Object* mediumAfterCrossing(const Object* before, const Object& object, bool entering);

// The box for mediaMissDistance: the accelerator's bounds and the lights.
void mediaBounds(const Scene& scene, const Accelerator& accel, Vec3& lower, Vec3& upper);

// True if some object's interior or the scene holds media.
bool sceneHasMedia(const Scene& scene);

struct MediaEffect {
    Color add{0};
    Color scale{1};
};

// What the renderer needs to light a medium.
struct MediaLighting {
    const Scene* scene = nullptr;
    const Accelerator* accel = nullptr;
    double time = 0;
    const ProjectedThrough* projected = nullptr; // the lights' projected_through objects (render/lighting.h)
};

// The single-scattering estimate over the segment from `origin` along the unit
// `direction` for `length`: seen through it, a colour c becomes add + scale c.
MediaEffect integrateMedia(const MediaList& media, const Vec3& origin, const Vec3& direction, double length,
                           const MediaLighting& lighting, Sampler& sampler, int dimension, RayCounts& counts);

// exp(-int extinction) over the segment, by the midpoint rule with N strata.
Color mediaTransmittance(const MediaList& media, const Vec3& origin, const Vec3& direction, double length);

} // namespace drt
