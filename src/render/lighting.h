// Direct lighting at a shading point: point lights, spotlights, area lights,
// and shadow rays filtered by transparent blockers.
//
// Area lights (`area_light <axis1>, <axis2>, n1, n2`), two modes:
//   areaIllumination == false (default, POV-Ray's): shading is computed for a
//     point light at the centre and multiplied by the visibility averaged over
//     an edge-to-edge n1 x n2 grid, centre + axis1 (i/(n1-1) - 1/2) + axis2
//     (j/(n2-1) - 1/2); `jitter` moves each grid point by up to half a grid step.
//   areaIllumination == true (Cook's full area illumination): the rectangle
//     centre +- axis/2 is cut into n1 x n2 cells; one jittered point per cell
//     shades as a point light with 1/(n1 n2) of the colour (always jittered,
//     so the estimate is unbiased).
//   `circular` maps the square onto the inscribed ellipse (concentric map);
//   `orient` turns the axes to face the shaded point, keeping their lengths.
//   `adaptive` is ignored (the full grid is always used).
// Sample values come from the sampler at bounceDimension(depth, kOffsetLight)
// through get2DStratified, one point per grid cell.
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
// shadow-casting surface crossed (0 at the first opaque one).
Color shadowTransmittance(const Accelerator& accel, const Hit& from, const Vec3& target, double time,
                          RayCounts& counts);

struct ShadingPoint {
    Hit hit;
    Vec3 normal;   // unit, facing the incoming ray
    Vec3 incoming; // unit ray direction
    ColorFT pigment;
    const Finish* finish = nullptr;
    double time = 0;
    int depth = 0;
};

// Sum over the scene's lights of the diffuse and highlight terms at `point`.
Color directLighting(const Scene& scene, const Accelerator& accel, const ShadingPoint& point, Sampler& sampler,
                     RayCounts& counts);

} // namespace drt
