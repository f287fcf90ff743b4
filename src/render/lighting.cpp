#include "render/lighting.h"
#include "render/light_path.h"

#include "sampling/warp.h"
#include "render/media.h"
#include "render/pigment.h"
#include "render/shading.h"
#include "render/texture_shading.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace drt {

Color shadowTransmittance(const Accelerator& accel, const Hit& from, const Vec3& target, double time,
                          RayCounts& counts, const Scene* mediaScene) {
    Ray ray;
    ray.origin = Accelerator::offsetOrigin(from, target - from.point);
    ray.direction = target - ray.origin; // the light sits at t = 1
    ray.tMin = 0;
    ray.tMax = 1;
    ray.time = time;
    ++counts.shadow;
    // Media between ray.origin and the end of the segment (hit == nullptr: the light).
    thread_local MediaList media;
    const auto throughMedia = [&](const Hit* hit, double t) {
        media.clear();
        if (mediaScene) segmentMedia(*mediaScene, nullptr, hit, ray.direction, media);
        if (media.empty()) return Color(1);
        const double speed = length(ray.direction);
        return mediaTransmittance(media, ray.origin, ray.direction / speed, t * speed);
    };
    if (!accel.occluded(ray)) return mediaScene && !mediaScene->media.empty() ? throughMedia(nullptr, 1) : Color(1);

    // Something is in the way: walk through it, filtering by each surface.
    Color transmittance(1);
    for (int crossed = 0; crossed < kMaxShadowBlockers; ++crossed) {
        Hit blocker;
        ++counts.shadow;
        if (!accel.intersect(ray, blocker)) return mediaScene ? transmittance * throughMedia(nullptr, 1) : transmittance;
        if (mediaScene) transmittance *= throughMedia(&blocker, blocker.t);
        if (!blocker.object->noShadow) {
            transmittance *= textureFilter(blocker.object->texture, blocker.restPoint);
            if (isBlack(transmittance) || !(maxComponent(transmittance) > 0)) return Color(0);
        }
        if (isBlack(transmittance) || !(maxComponent(transmittance) > 0)) return Color(0);
        ray.origin = Accelerator::offsetOrigin(blocker, ray.direction);
        ray.direction = target - ray.origin;
        if (!(dot(ray.direction, target - from.point) > 0)) return transmittance; // passed the light
    }
    return Color(0);
}

int lightDimension(int depth, int lightIndex) {
    if (lightIndex <= 0) return bounceDimension(depth, kOffsetLight);
    // Two dimensions per (light, depth) pair; wraps (harmlessly) past 2^30.
    const int64_t slot = int64_t(lightIndex - 1) * kMaxLightDepth + std::clamp(depth, 0, kMaxLightDepth - 1);
    return kFirstExtraLightDimension + static_cast<int>((2 * slot) % (int64_t(1) << 30));
}

int crandDimension(int depth, int lightIndex) {
    const int64_t slot = int64_t(std::max(lightIndex, 0)) * kMaxLightDepth + std::clamp(depth, 0, kMaxLightDepth - 1);
    return kFirstExtraLightDimension + (1 << 30) + static_cast<int>(slot % (int64_t(1) << 29));
}

namespace {

// U for crand (lighting.h crandDimension); 0 without crand, so no sample is drawn.
double crandNoise(const ShadingPoint& sp, int lightIndex, Sampler& sampler) {
    if (!(sp.finish->crand > 0)) return 0;
    return sampler.get1D(crandDimension(sp.depth, lightIndex));
}

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

// Diffuse and highlights from a point light at `lightPosition` whose colour is
// scaled by `scale` (and by 1/r^2 when `inverseSquare`), shadowed unless shadowless.
Color shadePointLight(const Accelerator& accel, const ShadingPoint& sp, const Light& light,
                      const Vec3& lightPosition, double scale, bool inverseSquare, double crandU, RayCounts& counts,
                      const Scene* mediaScene) {
    const Vec3 toLight = lightPosition - sp.hit.point;
    const double distance = length(toLight);
    if (!(distance > 0)) return Color(0);
    const Vec3 l = toLight / distance;
    if (!(dot(sp.normal, l) > 0)) return Color(0);
    if (inverseSquare) scale /= distance * distance;
    Color intensity = lightIntensityAt(light, lightPosition, sp.hit.point) * scale;
    if (isBlack(intensity) || !std::isfinite(maxComponent(intensity))) return Color(0);
    if (!light.shadowless) {
        intensity *= shadowTransmittance(accel, sp.hit, lightPosition, sp.time, counts, mediaScene);
        if (isBlack(intensity)) return Color(0);
    }
    return lightTerm(*sp.finish, sp.pigment, sp.normal, sp.incoming, l, intensity, crandU);
}

// One sample point of an area light and the weight of its point light
// (lighting.h: 1/N, or the solid-angle and inverse-square factors).
struct AreaSample {
    Vec3 position;
    double weight = 0;
};

// The N sample points of an area light seen from `point`.
class AreaSampler {
public:
    AreaSampler(const Light& light, const Vec3& point, int depth, int lightIndex)
        : light_(light), area_(*light.area), point_(point),
          frame_(areaFrame(area_, light.position, point)), n1_(std::max(1, area_.size1)),
          n2_(std::max(1, area_.size2)), count_(n1_ * n2_), dimension_(lightDimension(depth, lightIndex)) {
        const Vec3 normal = cross(frame_.axis1, frame_.axis2);
        areaMeasure_ = length(normal);
        if (area_.circular) areaMeasure_ *= kPi / 4;
        if (areaMeasure_ > 0 && std::isfinite(areaMeasure_)) normal_ = normal / length(normal);
        sampling_ = area_.sampling;
        if (sampling_ == AreaSampling::SolidAngle) {
            const double l1 = length(frame_.axis1), l2 = length(frame_.axis2);
            const bool perpendicular = std::fabs(dot(frame_.axis1, frame_.axis2)) <= 1e-9 * l1 * l2;
            if (area_.circular || !perpendicular) {
                sampling_ = AreaSampling::Stratified;
            } else {
                rectangle_.emplace(point, light.position - 0.5 * (frame_.axis1 + frame_.axis2), frame_.axis1,
                                   frame_.axis2);
                if (!rectangle_->valid() || !std::isfinite(rectangle_->solidAngle())) sampling_ = AreaSampling::Stratified;
            }
        }
    }

    int count() const { return count_; }

    AreaSample sample(Sampler& sampler, int k) const {
        const bool inverseSquare = light_.inverseSquare;
        AreaSample s;
        if (sampling_ == AreaSampling::PovGrid) {
            const int i = k % n1_, j = k / n1_;
            // Edge to edge: i / (n1 - 1); a single row sits on the centre line.
            double u = n1_ > 1 ? double(i) / (n1_ - 1) : 0.5;
            double v = n2_ > 1 ? double(j) / (n2_ - 1) : 0.5;
            if (area_.jitter) {
                const Vec2 jitter = sampler.get2DStratified(dimension_, k, count_);
                if (n1_ > 1) u += (jitter.x - 0.5) / (n1_ - 1);
                if (n2_ > 1) v += (jitter.y - 0.5) / (n2_ - 1);
            }
            s.position = light_.position + areaOffset(area_, frame_, u, v);
        } else if (sampling_ == AreaSampling::Stratified) {
            const Vec2 u = sampler.get2DStratified(dimension_, k, count_);
            s.position = light_.position + areaOffset(area_, frame_, u.x, u.y);
        } else {
            s.position = rectangle_->sample(sampler.get2DStratified(dimension_, k, count_));
            const double omega = rectangle_->solidAngle();
            if (inverseSquare) {
                // L Omega / N with L = C / A (the colour C is applied later).
                s.weight = omega / (count_ * areaMeasure_);
            } else {
                // Omega r^2 / (N A |cos theta_e|): area density over solid-angle density.
                const Vec3 d = point_ - s.position;
                const double r2 = dot(d, d);
                const double cosEmitter = std::fabs(dot(normal_, d)) / std::sqrt(r2);
                s.weight = cosEmitter > 0 ? omega * r2 / (count_ * areaMeasure_ * cosEmitter) : 0.0;
            }
            return s;
        }
        s.weight = 1.0 / count_;
        if (inverseSquare) {
            // C |cos theta_e| / (N r^2): the area-sampled estimate of int L cos dOmega.
            const Vec3 d = point_ - s.position;
            const double r2 = dot(d, d);
            s.weight = r2 > 0 ? s.weight * emitterCosine(s.position) / r2 : 0.0;
        }
        return s;
    }

private:
    double emitterCosine(const Vec3& position) const {
        if (!(areaMeasure_ > 0)) return 1; // a segment or a point: N point lights
        const Vec3 d = point_ - position;
        const double len = length(d);
        return len > 0 ? std::fabs(dot(normal_, d)) / len : 0.0;
    }

    const Light& light_;
    const AreaLight& area_;
    Vec3 point_;
    AreaFrame frame_;
    int n1_, n2_, count_, dimension_;
    double areaMeasure_ = 0;
    Vec3 normal_{0, 0, 0};
    AreaSampling sampling_;
    std::optional<SphericalRectangle> rectangle_;
};

// areaIllumination off: a point light at the centre times the mean visibility.
Color shadeAreaLightShadowOnly(const Accelerator& accel, const ShadingPoint& sp, const Light& light,
                               int lightIndex, Sampler& sampler, RayCounts& counts, const Scene* mediaScene) {
    const Vec3 toCenter = light.position - sp.hit.point;
    const double distance = length(toCenter);
    if (!(distance > 0)) return Color(0);
    const Vec3 l = toCenter / distance;
    if (!(dot(sp.normal, l) > 0)) return Color(0);
    Color intensity = lightIntensityAt(light, light.position, sp.hit.point);
    if (light.inverseSquare) intensity = intensity / (distance * distance);
    if (isBlack(intensity)) return Color(0);
    Color visibility(1);
    if (!light.shadowless) {
        const AreaSampler points(light, sp.hit.point, sp.depth, lightIndex);
        visibility = Color(0);
        for (int k = 0; k < points.count(); ++k)
            visibility += shadowTransmittance(accel, sp.hit, points.sample(sampler, k).position, sp.time, counts,
                                              mediaScene);
        visibility = visibility / points.count();
        if (isBlack(visibility)) return Color(0);
    }
    return lightTerm(*sp.finish, sp.pigment, sp.normal, sp.incoming, l, intensity * visibility,
                     crandNoise(sp, lightIndex, sampler));
}

// areaIllumination on: each sample point shades as a weighted point light.
Color shadeAreaLightFull(const Accelerator& accel, const ShadingPoint& sp, const Light& light, int lightIndex,
                         Sampler& sampler, RayCounts& counts, const Scene* mediaScene) {
    const AreaSampler points(light, sp.hit.point, sp.depth, lightIndex);
    Color sum(0);
    for (int k = 0; k < points.count(); ++k) {
        const AreaSample s = points.sample(sampler, k);
        if (s.weight > 0)
            sum += shadePointLight(accel, sp, light, s.position, s.weight, false, crandNoise(sp, lightIndex, sampler),
                                   counts, mediaScene);
    }
    return sum;
}

} // namespace

Color directLighting(const Scene& scene, const Accelerator& accel, const ShadingPoint& point, Sampler& sampler,
                     RayCounts& counts) {
    Color sum(0);
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        // A moving light as it is at this point's time (render/light_path.h).
        std::optional<Light> moved;
        if (lightMoves(scene.lights[i])) moved = lightAt(scene.lights[i], point.time);
        const Light& light = moved ? *moved : scene.lights[i];
        if (isBlack(light.color)) continue;
        const int index = static_cast<int>(std::min<size_t>(i, 1u << 20));
        // Shadow rays through media: only for lights that interact with media (POV-Ray).
        const Scene* media = light.mediaAttenuation && light.mediaInteraction ? &scene : nullptr;
        if (!light.area)
            sum += shadePointLight(accel, point, light, light.position, 1.0, light.inverseSquare,
                                   crandNoise(point, index, sampler), counts, media);
        else if (light.areaIllumination)
            sum += shadeAreaLightFull(accel, point, light, index, sampler, counts, media);
        else
            sum += shadeAreaLightShadowOnly(accel, point, light, index, sampler, counts, media);
    }
    return sum;
}

} // namespace drt
