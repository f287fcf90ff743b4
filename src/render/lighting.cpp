#include "render/lighting.h"

#include "sampling/warp.h"
#include "render/pigment.h"
#include "render/shading.h"

#include <cmath>

namespace drt {

Color shadowTransmittance(const Accelerator& accel, const Hit& from, const Vec3& target, double time,
                          RayCounts& counts) {
    Ray ray;
    ray.origin = Accelerator::offsetOrigin(from, target - from.point);
    ray.direction = target - ray.origin; // the light sits at t = 1
    ray.tMin = 0;
    ray.tMax = 1;
    ray.time = time;
    ++counts.shadow;
    if (!accel.occluded(ray)) return Color(1);

    // Something is in the way: walk through it, filtering by each surface.
    Color transmittance(1);
    for (int crossed = 0; crossed < kMaxShadowBlockers; ++crossed) {
        Hit blocker;
        ++counts.shadow;
        if (!accel.intersect(ray, blocker)) return transmittance;
        if (!blocker.object->noShadow) {
            const ColorFT p = evaluatePigment(blocker.object->texture.pigment, blocker.point);
            transmittance *= p.rgb * p.filter + Color(p.transmit);
            if (isBlack(transmittance) || !(maxComponent(transmittance) > 0)) return Color(0);
        }
        ray.origin = Accelerator::offsetOrigin(blocker, ray.direction);
        ray.direction = target - ray.origin;
        if (!(dot(ray.direction, target - from.point) > 0)) return transmittance; // passed the light
    }
    return Color(0);
}

namespace {

struct AreaFrame {
    Vec3 axis1, axis2;
};

AreaFrame areaFrame(const AreaLight& area, const Vec3& center, const Vec3& point) {
    if (!area.orient) return {area.axis1, area.axis2};
    const Vec3 toPoint = point - center;
    const double len = length(toPoint);
    if (!(len > 0)) return {area.axis1, area.axis2};
    Vec3 t, b;
    orthonormalBasis(toPoint / len, t, b);
    return {t * length(area.axis1), b * length(area.axis2)};
}

// (u, v) in [0,1]^2 to an offset from the light's centre.
Vec3 areaOffset(const AreaLight& area, const AreaFrame& frame, double u, double v) {
    if (area.circular) {
        const Vec2 d = squareToConcentricDisc({u, v}); // in the unit disc
        return frame.axis1 * (0.5 * d.x) + frame.axis2 * (0.5 * d.y);
    }
    return frame.axis1 * (u - 0.5) + frame.axis2 * (v - 0.5);
}

Color lightIntensityAt(const Light& light, const Vec3& lightPosition, const Vec3& point) {
    return light.color * (spotlightAttenuation(light, lightPosition, point) *
                          fadeAttenuation(light, length(lightPosition - point)));
}

Color shadePointLight(const Accelerator& accel, const ShadingPoint& sp, const Light& light,
                      const Vec3& lightPosition, const Color& scale, RayCounts& counts) {
    const Vec3 toLight = lightPosition - sp.hit.point;
    const double distance = length(toLight);
    if (!(distance > 0)) return Color(0);
    const Vec3 l = toLight / distance;
    if (!(dot(sp.normal, l) > 0)) return Color(0);
    Color intensity = lightIntensityAt(light, lightPosition, sp.hit.point) * scale;
    if (isBlack(intensity)) return Color(0);
    if (!light.shadowless) {
        intensity *= shadowTransmittance(accel, sp.hit, lightPosition, sp.time, counts);
        if (isBlack(intensity)) return Color(0);
    }
    return lightTerm(*sp.finish, sp.pigment, sp.normal, sp.incoming, l, intensity);
}

Color shadeAreaLightPov(const Accelerator& accel, const ShadingPoint& sp, const Light& light,
                        Sampler& sampler, RayCounts& counts) {
    const AreaLight& area = *light.area;
    const Vec3 toCenter = light.position - sp.hit.point;
    const double distance = length(toCenter);
    if (!(distance > 0)) return Color(0);
    const Vec3 l = toCenter / distance;
    if (!(dot(sp.normal, l) > 0)) return Color(0);
    const Color intensity = lightIntensityAt(light, light.position, sp.hit.point);
    if (isBlack(intensity)) return Color(0);
    Color visibility(1);
    if (!light.shadowless) {
        const int n1 = std::max(1, area.size1), n2 = std::max(1, area.size2);
        const int count = n1 * n2;
        const AreaFrame frame = areaFrame(area, light.position, sp.hit.point);
        const int dimension = bounceDimension(sp.depth, kOffsetLight);
        visibility = Color(0);
        for (int k = 0; k < count; ++k) {
            const int i = k % n1, j = k / n1;
            // Edge to edge: i / (n1 - 1); a single row sits on the centre line.
            double u = n1 > 1 ? double(i) / (n1 - 1) : 0.5;
            double v = n2 > 1 ? double(j) / (n2 - 1) : 0.5;
            if (area.jitter) {
                const Vec2 jitter = sampler.get2DStratified(dimension, k, count);
                if (n1 > 1) u += (jitter.x - 0.5) / (n1 - 1);
                if (n2 > 1) v += (jitter.y - 0.5) / (n2 - 1);
            }
            const Vec3 position = light.position + areaOffset(area, frame, u, v);
            visibility += shadowTransmittance(accel, sp.hit, position, sp.time, counts);
        }
        visibility = visibility / count;
        if (isBlack(visibility)) return Color(0);
    }
    return lightTerm(*sp.finish, sp.pigment, sp.normal, sp.incoming, l, intensity * visibility);
}

Color shadeAreaLightCook(const Accelerator& accel, const ShadingPoint& sp, const Light& light,
                         Sampler& sampler, RayCounts& counts) {
    const AreaLight& area = *light.area;
    const int n1 = std::max(1, area.size1), n2 = std::max(1, area.size2);
    const int count = n1 * n2;
    const AreaFrame frame = areaFrame(area, light.position, sp.hit.point);
    const int dimension = bounceDimension(sp.depth, kOffsetLight);
    const Color share(1.0 / count);
    Color sum(0);
    for (int k = 0; k < count; ++k) {
        const int i = k % n1, j = k / n1;
        const Vec2 jitter = sampler.get2DStratified(dimension, k, count);
        const double u = (i + jitter.x) / n1, v = (j + jitter.y) / n2;
        const Vec3 position = light.position + areaOffset(area, frame, u, v);
        sum += shadePointLight(accel, sp, light, position, share, counts);
    }
    return sum;
}

} // namespace

Color directLighting(const Scene& scene, const Accelerator& accel, const ShadingPoint& point, Sampler& sampler,
                     RayCounts& counts) {
    Color sum(0);
    for (const Light& light : scene.lights) {
        if (isBlack(light.color)) continue;
        if (!light.area)
            sum += shadePointLight(accel, point, light, light.position, Color(1), counts);
        else if (light.areaIllumination)
            sum += shadeAreaLightCook(accel, point, light, sampler, counts);
        else
            sum += shadeAreaLightPov(accel, point, light, sampler, counts);
    }
    return sum;
}

} // namespace drt
