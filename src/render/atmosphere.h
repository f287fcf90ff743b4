// What lies between surfaces and around the scene: POV-Ray's fog and
// sky_sphere (scene.h Fog, Scene::sky).
#pragma once

#include "scene/scene.h"

namespace drt {

// POV-Ray's Max_Distance: the length given to rays that hit nothing.
inline constexpr double kFogMissDistance = 1e7;

// The effect of fogs on a ray segment of `length` from `origin` along the unit
// `direction`: seen through the fog, a colour c becomes add + scale * c.
struct FogEffect {
    Color add{0};
    Color scale{1};
};

// The fog depth along the segment: `length` for constant fog; for ground fog
// the integral of the density. With F(h) = h for h <= 0 and a atan(h / a) above
// (a = altitude, h the height above the offset), F' is the density, so the
// depth is length (F(h1) - F(h0)) / (h1 - h0).
double fogDepth(const Fog& fog, const Vec3& origin, const Vec3& direction, double length);

FogEffect fogEffect(const std::vector<Fog>& fogs, const Vec3& origin, const Vec3& direction, double length);

// The colour of a ray that misses everything: the sky pigments at the unit
// direction, the last on top, over the background.
Color skyColor(const Scene& scene, const Vec3& unitDirection);

} // namespace drt
