#include "render/lighting.h"
#include "render/atmosphere.h"
#include "render/light_path.h"

#include "sampling/warp.h"
#include "render/media.h"
#include "render/pigment.h"
#include "render/shading.h"
#include "render/texture_shading.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

namespace drt {

Ray shadowRay(const Hit& from, const Vec3& target, double time) {
    return shadowRayFrom(Accelerator::offsetOrigin(from, target - from.point), target, time);
}

Ray shadowRayFrom(const Vec3& origin, const Vec3& target, double time) {
    Ray ray;
    ray.origin = origin;
    ray.direction = target - ray.origin; // the light sits at t = 1
    ray.tMin = 0;
    ray.tMax = 1;
    ray.time = time;
    return ray;
}

namespace {

// The media of a shadow ray's segments, kept per thread (accel/thread_scratch.h).
struct ShadowScratch {
    MediaList media;
};

// shadowTransmittance without the fog.
Color surfaceAndMediaTransmittance(const Accelerator& accel, const Hit& from, const Vec3& target, double time,
                                   RayCounts& counts, const Scene* mediaScene) {
    Ray ray = shadowRay(from, target, time);
    ++counts.shadow;
    // Media between ray.origin and the end of the segment (hit == nullptr: the light).
    MediaList& media = ThreadScratch<ShadowScratch>::get().media;
    const auto throughMedia = [&](const Hit* hit, double t) {
        media.clear();
        if (mediaScene) segmentMedia(*mediaScene, nullptr, hit, ray.direction, media);
        if (media.empty()) return Color(1);
        const double speed = length(ray.direction);
        return mediaTransmittance(media, ray.origin, ray.direction / speed, t * speed);
    };
    // One query tells a segment with nothing in the way and one blocked by a
    // surface that lets no light through (black, whatever else or whatever
    // media it crosses) from one that crosses only surfaces that may let light
    // through, which alone are found one by one below.
    const Accelerator::Occlusion occlusion = accel.occludedOpaque(ray);
    if (occlusion == Accelerator::Occlusion::Clear)
        return mediaScene && !mediaScene->media.empty() ? throughMedia(nullptr, 1) : Color(1);
    if (occlusion == Accelerator::Occlusion::Blocked) return Color(0);

    // Something is in the way: walk through it, filtering by each surface.
    Color transmittance(1);
    for (int crossed = 0; crossed < kMaxShadowBlockers; ++crossed) {
        Hit blocker;
        ++counts.shadow;
        if (!accel.intersect(ray, blocker)) return mediaScene ? transmittance * throughMedia(nullptr, 1) : transmittance;
        if (mediaScene) transmittance *= throughMedia(&blocker, blocker.t);
        if (!blocker.object->noShadow) {
            // Leaving an object: the segment before this hit ran inside it (POV-Ray fades shadows too).
            if (dot(ray.direction, blocker.geometricNormal) > 0)
                transmittance *= interiorAttenuation(blocker.object->interior, blocker.t * length(ray.direction));
            Color filter(0);
            forEachSurfaceTexture(blocker, [&](const Texture& texture, double share) {
                filter += textureFilter(texture, blocker.restPoint, blocker.hasUv ? &blocker.uv : nullptr) * share;
            });
            transmittance *= filter;
            if (isBlack(transmittance) || !(maxComponent(transmittance) > 0)) return Color(0);
        }
        if (isBlack(transmittance) || !(maxComponent(transmittance) > 0)) return Color(0);
        ray.origin = Accelerator::offsetOrigin(blocker, ray.direction);
        ray.direction = target - ray.origin;
        if (!(dot(ray.direction, target - from.point) > 0)) return transmittance; // passed the light
    }
    return Color(0);
}

} // namespace

std::unique_ptr<InstalledScratch> installLightingScratch() { return ThreadScratch<ShadowScratch>::install(); }

Color shadowTransmittance(const Accelerator& accel, const Hit& from, const Vec3& target, double time,
                          RayCounts& counts, const Scene* mediaScene) {
    Color transmittance = surfaceAndMediaTransmittance(accel, from, target, time, counts, mediaScene);
    // Fog dims the light on its way as it dims what the camera sees (POV-Ray,
    // with media_attenuation on): the fog's scale over the segment; its own
    // colour is not added to the light.
    if (mediaScene && !mediaScene->fogs.empty() && !isBlack(transmittance)) {
        const Vec3 toLight = target - from.point;
        const double distance = length(toLight);
        if (distance > 0) transmittance *= fogEffect(mediaScene->fogs, from.point, toLight / distance, distance).scale;
    }
    return transmittance;
}

ProjectedThrough::ProjectedThrough(const Scene& scene) {
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        if (!scene.lights[i].projectedThrough) continue;
        if (byLight_.empty()) byLight_.resize(scene.lights.size()); // the first such light
        byLight_[i] = std::make_unique<Accelerator>(*scene.lights[i].projectedThrough);
    }
}

ProjectedThrough::~ProjectedThrough() = default;

Color lightTransmittance(const Accelerator& accel, const Accelerator* projected, bool shadowless, const Hit& from,
                         const Vec3& target, double time, RayCounts& counts, const Scene* mediaScene) {
    if (!projected)
        return shadowless ? Color(1) : shadowTransmittance(accel, from, target, time, counts, mediaScene);
    const Ray ray = shadowRay(from, target, time);
    Hit crossing;
    ++counts.shadow;
    if (!projected->intersect(ray, crossing)) return Color(0); // the light does not shine this way
    if (shadowless) return Color(1);
    // Only what lies before the first crossing casts a shadow. The segment
    // stops short of it, so that a placed copy of the object, whose surface is
    // there, does not shadow the light it shapes.
    const double speed = length(ray.direction);
    const double cut = crossing.t - std::max(1e-4, 1e-5 * crossing.t * speed) / speed;
    if (!(cut > 0)) return Color(1);
    return shadowTransmittance(accel, from, ray.origin + ray.direction * cut, time, counts, mediaScene);
}

int lightDimension(int depth, int lightIndex) {
    if (lightIndex <= 0) return bounceDimension(depth, kOffsetLight);
    // Two dimensions per (light, depth) pair; wraps (harmlessly) past 2^30.
    const int64_t slot = int64_t(lightIndex - 1) * kMaxLightDepth + std::clamp(depth, 0, kMaxLightDepth - 1);
    return kFirstExtraLightDimension + static_cast<int>((2 * slot) % (int64_t(1) << 30));
}

int highlightDimension(int depth, int lightIndex) {
    // Past crandDimension's 2^29 (and so past the media's and radiosity's, which
    // start among them), two per (light, depth) pair; wraps (harmlessly) past 2^28.
    constexpr int first = kFirstExtraLightDimension + (1 << 30) + (1 << 29);
    const int64_t slot = int64_t(std::max(lightIndex, 0)) * kMaxLightDepth + std::clamp(depth, 0, kMaxLightDepth - 1);
    return first + static_cast<int>((2 * slot) % (int64_t(1) << 28));
}

int crandDimension(int depth, int lightIndex) {
    const int64_t slot = int64_t(std::max(lightIndex, 0)) * kMaxLightDepth + std::clamp(depth, 0, kMaxLightDepth - 1);
    return kFirstExtraLightDimension + (1 << 30) + static_cast<int>(slot % (int64_t(1) << 29));
}

namespace {

// The cones of a light that is not a spotlight (never read).
const SpotCones kNoCones{};

// U for crand (lighting.h crandDimension); 0 without crand, so no sample is drawn.
double crandNoise(const ShadingPoint& sp, int lightIndex, Sampler& sampler) {
    if (!(sp.finish->crand > 0)) return 0;
    return sampler.get1D(crandDimension(sp.depth, lightIndex));
}

// Whether a point light at `position` whose colour there is intensityAt()
// times `scale` (and 1/r^2 when `inverseSquare`) lights sp before shadows:
// the surface faces it and the colour is neither black nor infinite. Then `l`
// is the unit way to it and `intensity` its colour at sp. addPointLight's
// test, and so which of a light's points the shading asks the visibility of.
template <class IntensityAt>
[[gnu::always_inline]] inline bool pointLightReaches(const ShadingPoint& sp, const Vec3& position, double scale,
                                                     bool inverseSquare, IntensityAt&& intensityAt, Vec3& l,
                                                     Color& intensity) {
    const Vec3 toLight = position - sp.hit->point;
    const double distance = length(toLight);
    if (!(distance > 0)) return false;
    l = toLight / distance;
    if (!(dot(sp.normal, l) > 0)) return false;
    if (inverseSquare) scale /= distance * distance;
    intensity = intensityAt() * scale;
    return !isBlack(intensity) && std::isfinite(maxComponent(intensity));
}

// Diffuse and highlights at sp from a point light at `position` whose colour
// there is intensityAt() times `scale` (and 1/r^2 when `inverseSquare`), times
// visible() when `shadowed`, added to `sum`; noise() is crand's U.
template <class IntensityAt, class Visible, class Noise>
[[gnu::always_inline]] inline void addPointLight(const ShadingPoint& sp, const Vec3& position, double scale,
                                                 bool inverseSquare, IntensityAt&& intensityAt, bool shadowed,
                                                 Visible&& visible, Noise&& noise, Color& sum,
                                                 double highlightScale = 1) {
    Vec3 l;
    Color intensity;
    if (!pointLightReaches(sp, position, scale, inverseSquare, intensityAt, l, intensity)) return;
    if (shadowed) {
        intensity *= visible();
        if (isBlack(intensity)) return;
    }
    sum += lightTerm(*sp.finish, sp.pigment, sp.normal, sp.incoming, l, intensity, noise(), highlightScale);
}

// Whether the finish's highlight can be more than a thousandth of its peak
// anywhere on the area light as seen from `point`: decided from the light's
// bounding cone and the highlight's, both about their axes. Only the cost of
// multiple importance sampling depends on it (either way the estimate is
// unbiased); where it is false the light's sample point alone takes the
// highlight, and no lobe direction is drawn.
//   Phong's term falls below 1e-3 of its peak beyond the angle c_p from R
//   with cos c_p = 1e-3^(1/phong_size). Blinn's is a function of the angle
//   between H and N, and L and R are V mirrored about H and about N, so the
//   angle from L to R is at most twice that between H and N: beyond 2 c_b
//   from R, cos c_b = 1e-3^(1/e), it is below 1e-3 too.
// The cosine of the widest angle from R at which the finish's highlight is
// above the cut.
double highlightCosReach(const Finish& finish) {
    constexpr double kLog = -6.907755278982137; // ln 1e-3
    double cosReach = 1;
    if (finish.phong > 0) cosReach = std::min(cosReach, finish.phongSize > 0 ? std::exp(kLog / finish.phongSize) : 0.0);
    if (finish.specular > 0 && finish.roughness > 0) {
        const double c = std::exp(kLog * finish.roughness);
        cosReach = std::min(cosReach, 2 * c * c - 1);
    }
    return cosReach;
}

// `cosReach` is highlightCosReach(finish).
bool highlightMayReach(double cosReach, const Vec3& normal, const Vec3& incoming, const Light& light,
                       const Vec3& point) {
    const AreaLight& area = *light.area;
    const Vec3 toCentre = light.position - point;
    const double distance = length(toCentre);
    const double radius = 0.5 * (length(area.axis1) + length(area.axis2)); // at least half the diagonal
    if (!(distance > radius)) return true;
    // The smallest angle from R to a direction within the light's cone:
    // alpha - beta, from their cosines.
    const Vec3 mirror = reflect(incoming, normal);
    const double cosAlpha = std::clamp(dot(mirror, toCentre) / distance, -1.0, 1.0);
    const double sinBeta = radius / distance;
    const double cosBeta = std::sqrt(std::max(0.0, 1 - sinBeta * sinBeta));
    if (cosAlpha >= cosBeta) return true; // R lies within the cone
    const double sinAlpha = std::sqrt(std::max(0.0, 1 - cosAlpha * cosAlpha));
    const double cosGap = cosAlpha * cosBeta + sinAlpha * sinBeta;
    return cosGap >= cosReach;
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
[[gnu::always_inline]] inline Vec3 areaOffset(const AreaLight& area, const AreaFrame& frame, double u, double v) {
    if (area.circular) {
        const Vec2 d = squareToConcentricDisc({u, v}); // in the unit disc
        return frame.axis1 * (0.5 * d.x) + frame.axis2 * (0.5 * d.y);
    }
    return frame.axis1 * (u - 0.5) + frame.axis2 * (v - 0.5);
}

Color lightIntensityAt(const Light& light, const SpotCones& cones, const Vec3& lightPosition, const Vec3& point,
                       bool atCentre) {
    // The distance only for a fading light (fadeAttenuation is 1 otherwise).
    const bool fades = light.fadeDistance > 0 && light.fadePower > 0;
    if (!light.spotlight && !fades) return light.color; // the colour times 1 * 1: the same bits
    return light.color * (spotlightAttenuation(light, cones, lightPosition, point, atCentre) *
                          (fades ? fadeAttenuation(light, length(lightPosition - point)) : 1.0));
}

// One sample point of an area light and the weight of its point light
// (lighting.h: 1/K, or the solid-angle and inverse-square factors).
struct AreaSample {
    Vec3 position;
    double weight = 0;
};

// POV-Ray's weight of point i of a row of n grid points (AreaSampler::sampleFrom,
// "the trapezoid rule"): 1 / (n - 1), half at the two ends; 1 for a single point.
double trapezoidWeight(int n, int i) { return n <= 1 ? 1.0 : (i == 0 || i == n - 1 ? 0.5 : 1.0) / (n - 1); }

// The weight of point k of an n1 x n2 grid, taken row by row (pov_grid's order):
// its row's weight times its column's.
double povGridWeight(int n1, int n2, int k) { return trapezoidWeight(n1, k % n1) * trapezoidWeight(n2, k / n1); }

// The K sample points of an area light seen from `point` at one camera sample.
class AreaSampler {
public:
    // `highlights`: the area and normal are wanted for continuous() and what follows it.
    // `split`: the render's K (RenderOptions::lightSamples).
    AreaSampler(const Light& light, const Vec3& point, int depth, int lightIndex, int split, bool highlights = false)
        : light_(light), area_(*light.area), point_(point),
          frame_(areaFrame(area_, light.position, point)), n1_(std::max(1, area_.size1)),
          n2_(std::max(1, area_.size2)), dimension_(lightDimension(depth, lightIndex)) {
        sampling_ = area_.sampling;
        // POV-Ray's own method takes every grid point at every hit; the others
        // send K rays per camera sample (lighting.h), one unless the render
        // splits its samples. The front ends keep n1 n2 within
        // Limits::areaLightSamples; a scene built in code is clamped rather
        // than overflow.
        if (sampling_ == AreaSampling::PovGrid)
            count_ = static_cast<int>(std::min<int64_t>(int64_t(n1_) * n2_, std::numeric_limits<int>::max()));
        else
            count_ = std::max(1, split);
        share_ = 1.0 / count_;
        // The area and the emitter's normal weigh solid-angle and inverse-square samples only.
        if (sampling_ != AreaSampling::SolidAngle && !light.inverseSquare && !highlights) return;
        const Vec3 normal = cross(frame_.axis1, frame_.axis2);
        areaMeasure_ = length(normal);
        if (area_.circular) areaMeasure_ *= kPi / 4;
        if (areaMeasure_ > 0 && std::isfinite(areaMeasure_)) normal_ = normal / length(normal);
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

    // Whether the sample points have a density over the light's area (K
    // points a camera sample, stratified or uniform in solid angle), which a
    // direction drawn from a highlight's lobe can meet: not a grid of points,
    // nor a light without area.
    bool continuous() const {
        return (sampling_ == AreaSampling::Stratified || sampling_ == AreaSampling::SolidAngle) &&
               areaMeasure_ > 0 && std::isfinite(areaMeasure_) && dot(normal_, normal_) > 0;
    }

    // For a continuous() light, with the sample point `position` on it, seen
    // from the shaded point: the density per steradian with which sample()
    // draws that direction.
    double solidAnglePdf(const Vec3& position) const {
        return sampling_ == AreaSampling::SolidAngle ? 1.0 / rectangle_->solidAngle() : uniformAreaPdf(position);
    }

    // What the light's colour is multiplied by per steradian at `position`:
    // sample()'s weight times solidAnglePdf (lighting.h: 1/A with
    // inverse_square, else r^2 / (A |cos theta_e|), the mean over the area).
    double perSteradian(const Vec3& position) const {
        return light_.inverseSquare ? 1.0 / areaMeasure_ : uniformAreaPdf(position);
    }

    // Where the ray from the shaded point in unit `direction` meets a
    // continuous() light: the rectangle, or the ellipse of a circular one.
    bool meet(const Vec3& direction, Vec3& position) const {
        const double facing = dot(direction, normal_);
        if (facing == 0 || !std::isfinite(facing)) return false;
        const double t = dot(light_.position - point_, normal_) / facing;
        if (!(t > 0) || !std::isfinite(t)) return false;
        position = point_ + direction * t;
        // position - centre = s axis1 + q axis2, solved with the axes' Gram matrix.
        const Vec3 d = position - light_.position;
        const Vec3 &a1 = frame_.axis1, &a2 = frame_.axis2;
        const double g11 = dot(a1, a1), g12 = dot(a1, a2), g22 = dot(a2, a2);
        const double det = g11 * g22 - g12 * g12;
        if (!(det > 0)) return false;
        const double b1 = dot(d, a1), b2 = dot(d, a2);
        const double s = (b1 * g22 - b2 * g12) / det, q = (b2 * g11 - b1 * g12) / det;
        if (area_.circular) return 4 * (s * s + q * q) <= 1;
        return std::fabs(s) <= 0.5 && std::fabs(q) <= 0.5;
    }

    // Whether sample() draws a uniform value: all but an unjittered pov_grid.
    bool drawsUniforms() const { return sampling_ != AreaSampling::PovGrid || area_.jitter; }
    int dimension() const { return dimension_; }

    AreaSample sample(Sampler& sampler, int k) const {
        return sampleFrom(drawsUniforms() ? uniform(sampler, k) : Vec2{0.5, 0.5}, k);
    }

    // The k-th point from its uniform value `w` (uniform(sampler, k); unread
    // where !drawsUniforms()).
    [[gnu::always_inline]] AreaSample sampleFrom(const Vec2& w, int k) const {
        const bool inverseSquare = light_.inverseSquare;
        AreaSample s;
        double gridWeight = 1.0; // PovGrid: the k-th point's trapezoid weight (below), over 1 / K
        if (sampling_ == AreaSampling::PovGrid || sampling_ == AreaSampling::Grid) {
            // POV-Ray averages an area light's grid by halving it into
            // quadrants down to single cells, each cell's value the mean of its
            // four corners: a grid point counts once for each cell it is a
            // corner of, so the edge points weigh half and the corners a
            // quarter of an inner point (the trapezoid rule, in each axis).
            // PovGrid: the k-th point, with that weight. Grid: the point
            // nearest this sample's 2-D light value scaled to 0..n-1, which
            // picks each point with that weight; the value's place around it
            // is its jitter, so the pixel's samples stratify the grid as they
            // do the area.
            int i, j;
            Vec2 jitter = {0.5, 0.5};
            if (sampling_ == AreaSampling::Grid) {
                jitter = {cells1_.nearestPoint(w.x, i), cells2_.nearestPoint(w.y, j)};
            } else {
                i = k % n1_;
                j = k / n1_;
                if (area_.jitter) jitter = w;
                gridWeight = povGridWeight(n1_, n2_, k) * count_;
            }
            // Edge to edge: i / (n1 - 1); a single row sits on the centre line.
            double u = n1_ > 1 ? cells1_.of(double(i)) : 0.5;
            double v = n2_ > 1 ? cells2_.of(double(j)) : 0.5;
            if (area_.jitter) {
                if (n1_ > 1) u += cells1_.of(jitter.x - 0.5);
                if (n2_ > 1) v += cells2_.of(jitter.y - 0.5);
            }
            s.position = light_.position + areaOffset(area_, frame_, u, v);
        } else if (sampling_ == AreaSampling::Stratified) {
            s.position = light_.position + areaOffset(area_, frame_, w.x, w.y);
        } else {
            s.position = rectangle_->sample(w);
            const double omega = rectangle_->solidAngle();
            if (inverseSquare) {
                // L Omega / K with L = C / A (the colour C is applied later).
                s.weight = omega / (count_ * areaMeasure_);
            } else {
                // Omega r^2 / (K A |cos theta_e|): area density over solid-angle density.
                const Vec3 d = point_ - s.position;
                const double r2 = dot(d, d);
                const double cosEmitter = std::fabs(dot(normal_, d)) / std::sqrt(r2);
                s.weight = cosEmitter > 0 ? omega * r2 / (count_ * areaMeasure_ * cosEmitter) : 0.0;
            }
            return s;
        }
        s.weight = share_ * gridWeight;
        if (inverseSquare) {
            // C |cos theta_e| / (K r^2): the area-sampled estimate of int L cos dOmega.
            const Vec3 d = point_ - s.position;
            const double r2 = dot(d, d);
            s.weight = r2 > 0 ? s.weight * emitterCosine(s.position) / r2 : 0.0;
        }
        return s;
    }

private:
    // The k-th of the K uniform values of this camera sample: with K = 1 the
    // pixel's own stratified sequence in the light's dimension; with K > 1
    // its points K i + k (Sampler::get2DStratified).
    Vec2 uniform(Sampler& sampler, int k) const {
        return count_ == 1 ? sampler.get2D(dimension_) : sampler.get2DStratified(dimension_, k, count_);
    }

    // The density per steradian of points uniform over the area, seen from
    // the shaded point: r^2 / (A |cos theta_e|), 0 edge-on.
    double uniformAreaPdf(const Vec3& position) const {
        const Vec3 d = point_ - position;
        const double r2 = dot(d, d);
        const double cosEmitter = std::fabs(dot(normal_, d)) / std::sqrt(r2);
        return cosEmitter > 0 ? r2 / (areaMeasure_ * cosEmitter) : 0.0;
    }

    double emitterCosine(const Vec3& position) const {
        if (!(areaMeasure_ > 0)) return 1; // a segment or a point: K point lights
        const Vec3 d = point_ - position;
        const double len = length(d);
        return len > 0 ? std::fabs(dot(normal_, d)) / len : 0.0;
    }

    // x / (n - 1) for a grid of n > 1 points a row: by the reciprocal where
    // n - 1 is a power of two (POV-Ray's usual 2^k + 1 points), which is the
    // same value exactly, else by the division.
    struct Cells {
        int n = 1, gaps = 1;
        double step = 1;
        bool exact = true;
        explicit Cells(int points)
            : n(std::max(1, points)), gaps(std::max(1, n - 1)), step(1.0 / gaps), exact((gaps & (gaps - 1)) == 0) {}
        double of(double x) const { return exact ? x * step : x / gaps; }
        // The point nearest x * (n - 1), x uniform in [0, 1): each inner point
        // with probability 1 / (n - 1), the two end points with half that (the
        // trapezoid weights); and, returned, where x lies around it as a
        // uniform value in [0, 1) (the end points' half ranges stretched).
        double nearestPoint(double x, int& index) const {
            if (n == 1) {
                index = 0;
                return x;
            }
            const double scaled = x * gaps;
            // scaled + 0.5 is positive: truncation is the floor (without a call to floor).
            index = std::min(static_cast<int>(scaled + 0.5), gaps);
            const double offset = scaled - index; // [-0.5, 0.5), or half of it at an end
            const bool first = index == 0, last = index == gaps;
            const double place = (first || last ? 2 * offset : offset) + (last ? 1.0 : first ? 0.0 : 0.5);
            constexpr double kBelowOne = 0x1.fffffffffffffp-1; // the largest double below 1
            // min(max(place, 0), kBelowOne) by comparisons, NaN going to 0 as
            // std::fmax sends it (std::fmin and std::fmax are library calls
            // here, four a sample); place is never -0.
            return place > 0 ? (place < kBelowOne ? place : kBelowOne) : 0.0;
        }
    };

    const Light& light_;
    const AreaLight& area_;
    Vec3 point_;
    AreaFrame frame_;
    int n1_, n2_, count_ = 1, dimension_;
    Cells cells1_{n1_}, cells2_{n2_};
    double share_ = 1; // 1 / count_
    double areaMeasure_ = 0;
    Vec3 normal_{0, 0, 0};
    AreaSampling sampling_;
    std::optional<SphericalRectangle> rectangle_;
};

} // namespace

DirectLighting::DirectLighting(const Scene& scene, const Accelerator& accel, bool shortWays, int lightSamples)
    : scene_(scene), accel_(accel),
      hasMedia_(sceneHasMedia(scene) || !scene.fogs.empty()),
      anyLightMoves_(std::any_of(scene.lights.begin(), scene.lights.end(), lightMoves)),
      lightSamples_(std::max(1, lightSamples)), traceAhead_(shortWays), projected_(scene) {
    cones_.reserve(scene.lights.size());
    for (const Light& light : scene.lights) {
        cones_.push_back(spotCones(light));
        const bool fades = light.fadeDistance > 0 && light.fadePower > 0;
        plainPoint_.push_back(shortWays && !light.area && !light.spotlight && !light.parallel && !lightMoves(light) &&
                              !fades && !isBlack(light.color));
    }
    // One occlusion query answers these lights' shadow rays (shadowTransmittance
    // with no media; with casters that may let light through, all but those
    // that cross only such casters): they can be traced ahead in packets.
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& light = scene.lights[i];
        const bool media = hasMedia_ && light.mediaAttenuation && light.mediaInteraction;
        if (!light.area && !light.spotlight && !light.parallel && !light.shadowless && !lightMoves(light) && !media &&
            !light.projectedThrough && !isBlack(light.color))
            packetLights_.push_back(static_cast<int>(i));
    }
}

void DirectLighting::traceCameraShadows(const Ray* rays, const Hit* hits, const bool* found, int count,
                                        CameraShadows& out) const {
    constexpr int kPacket = Accelerator::kPacketSize;
    out.hits_ = hits;
    out.count_ = std::clamp(count, 0, kPacket);
    if (packetLights_.empty() || out.count_ == 0) {
        out.count_ = 0;
        return;
    }
    out.answers_.assign(scene_.lights.size() * kPacket, 0);
    // Which way each hit's shadow rays may go: the side its normal faces.
    for (int k = 0; k < out.count_; ++k)
        if (found[k]) out.facings_[k] = facingOf(rays[k].direction, hits[k]);
    // The rays are made in place below, the array left unset: a default Ray is
    // 72 bytes of stores, and an assignment a copy of as many.
    static_assert(std::is_trivially_destructible_v<Ray> && std::is_trivially_copyable_v<Ray>);
    alignas(Ray) unsigned char storage[kPacket][sizeof(Ray)];
    Ray* const shadow = reinterpret_cast<Ray*>(storage);
    for (const int i : packetLights_) {
        const Vec3& position = scene_.lights[size_t(i)].position;
        int lane[kPacket];
        int n = 0;
        for (int k = 0; k < out.count_; ++k) {
            if (!found[k]) continue;
            const Vec3 toLight = position - hits[k].point;
            if (!(dot(out.facings_[k].normal, toLight) > 0)) continue; // facing away: the shading sends no ray
            ::new (storage[n]) Ray(shadowRay(hits[k], position, rays[k].time));
            lane[n++] = k;
        }
        uint8_t* const answers = out.answers_.data() + size_t(i) * kPacket;
        Accelerator::Occlusion occlusion[kPacket];
        accel_.occludedOpaquePacket(shadow, n, occlusion);
        for (int j = 0; j < n; ++j)
            answers[lane[j]] = occlusion[j] == Accelerator::Occlusion::Clear     ? 1
                               : occlusion[j] == Accelerator::Occlusion::Blocked ? 2
                                                                                 : 0; // traced alone
    }
}

namespace {

// The answer traced ahead for the shadow ray of light i from sp's hit, if any
// (CameraShadows: 0 none, 1 visible, 2 blocked).
uint8_t cameraShadow(const ShadingPoint& sp, size_t i) {
    const CameraShadows* pre = sp.cameraShadows;
    if (!pre) return 0;
    const int k = pre->indexOf(*sp.hit);
    return k < 0 ? 0 : pre->answers_[i * Accelerator::kPacketSize + size_t(k)];
}

} // namespace

const Color& DirectLighting::visibility(const ShadingPoint& sp, size_t i, const Light& light,
                                       PointLightSamples::Sample& s, RayCounts& counts) const {
    if (!s.tested) {
        const uint8_t answer = cameraShadow(sp, i);
        if (answer != 0) { // traced ahead: the same ray, the same answer
            ++counts.shadow;
            s.visibility = Color(answer == 1 ? 1.0 : 0.0);
        } else {
            // Shadow rays through media: only for lights that interact with media (POV-Ray).
            const Scene* media = hasMedia_ && light.mediaAttenuation && light.mediaInteraction ? &scene_ : nullptr;
            s.visibility = lightTransmittance(accel_, projected_.of(i), light.shadowless, *sp.hit, s.position, sp.time,
                                              counts, media);
        }
        s.tested = true;
    }
    return s.visibility;
}

template <class Wanted>
void DirectLighting::traceAhead(const ShadingPoint& sp, size_t i, const Light& light,
                                PointLightSamples::Sample* samples, int count, RayCounts& counts,
                                Wanted&& wanted) const {
    if (!traceAhead_ || light.shadowless || projected_.of(i) ||
        (hasMedia_ && light.mediaAttenuation && light.mediaInteraction))
        return; // shadowTransmittance is more than one occlusion query
    constexpr int kPacket = Accelerator::kPacketSize;
    static_assert(std::is_trivially_destructible_v<Ray> && std::is_trivially_copyable_v<Ray>);
    alignas(Ray) unsigned char storage[kPacket][sizeof(Ray)];
    Ray* const rays = reinterpret_cast<Ray*>(storage);
    PointLightSamples::Sample* lane[kPacket];
    // shadowRay's origin depends on the target only by the side of the
    // surface it lies on (Accelerator::offsetOrigin): made once per side.
    const Hit& hit = *sp.hit;
    Vec3 origins[2];
    bool made[2] = {false, false};
    for (int first = 0; first < count; first += kPacket) {
        int n = 0;
        for (int k = first; k < std::min(count, first + kPacket); ++k) {
            if (samples[k].tested || !wanted(k)) continue;
            const Vec3& target = samples[k].position;
            const Vec3 toTarget = target - hit.point;
            const int side = dot(hit.geometricNormal, toTarget) < 0 ? 1 : 0;
            if (!made[side]) {
                origins[side] = Accelerator::offsetOrigin(hit, toTarget);
                made[side] = true;
            }
            ::new (storage[n]) Ray(shadowRayFrom(origins[side], target, sp.time));
            lane[n++] = samples + k;
        }
        if (n < 2) continue; // one ray: visibility() traces it alone
        Accelerator::Occlusion occlusion[kPacket];
        accel_.occludedOpaquePacket(rays, n, occlusion);
        for (int j = 0; j < n; ++j) {
            if (occlusion[j] == Accelerator::Occlusion::ThroughTransmitters) continue;
            ++counts.shadow;
            lane[j]->visibility = Color(occlusion[j] == Accelerator::Occlusion::Clear ? 1.0 : 0.0);
            lane[j]->tested = true;
        }
    }
}

Color DirectLighting::shade(const ShadingPoint& sp, PointLightSamples& cache, Sampler& sampler,
                            RayCounts& counts) const {
    if (cache.lights_.size() != scene_.lights.size()) cache.lights_.assign(scene_.lights.size(), {});
    Color sum(0);
    // Light i's samples as drawn for this point: none yet if it is a new one.
    const auto rangeOf = [&cache](size_t i) -> PointLightSamples::Range& {
        PointLightSamples::Range& range = cache.lights_[i];
        if (range.generation != cache.generation_) { // the first layer at this point: no samples drawn yet
            range.generation = cache.generation_;
            range.count = 0;
            range.single.tested = false;
        }
        return range;
    };
    for (size_t i = 0; i < scene_.lights.size(); ++i) {
        // A moving light as it is at this point's time (render/light_path.h);
        // a still one as written, with no copy.
        const Light* light = &scene_.lights[i];
        if (sp.hit->object && !lightReaches(scene_, *light, *sp.hit->object)) continue; // light_group
        const int index = static_cast<int>(std::min<size_t>(i, 1u << 20));
        if (plainPoint_[i]) {
            // What the general way below comes to for a plain point light: no
            // copy, no cones, lightIntensityAt's colour times 1 * 1 (neither a
            // spotlight nor fading), its one sample at its position.
            PointLightSamples::Range& range = rangeOf(i);
            range.single.position = light->position;
            range.single.weight = 1.0;
            addPointLight(
                sp, light->position, 1.0, light->inverseSquare, [&]() -> const Color& { return light->color; }, true,
                [&]() -> const Color& { return visibility(sp, i, *light, range.single, counts); },
                [&] { return crandNoise(sp, index, sampler); }, sum);
            continue;
        }
        const bool moved = anyLightMoves_ && lightMoves(*light);
        if (moved) light = &(cache.moved_ = lightAt(*light, sp.time));
        if (light->parallel) { // it stands where this point's parallel ray from it starts (scene.h)
            if (!moved) cache.moved_ = *light;
            cache.moved_.position = parallelLightPosition(cache.moved_, sp.hit->point);
            light = &cache.moved_;
        }
        if (isBlack(light->color)) continue;
        const SpotCones& cones = !light->spotlight ? kNoCones
                                 : moved          ? (cache.movedCones_ = spotCones(*light))
                                                  : cones_[i];
        // A spotlight whose cone leaves this point out lights it with black
        // (lightIntensityAt's colour times 0) at its centre: the point light and
        // the light without area illumination skip it before any other test.
        const bool centreDark = light->spotlight && (!light->area || !light->areaIllumination) &&
                                isFinite(light->color) && outsideSpotCone(*light, cones, sp.hit->point);
        if (centreDark) continue;
        PointLightSamples::Range& range = rangeOf(i);
        // The light's samples at this point, drawn the first time a layer needs
        // them: a light whose centre sends nothing here (a spotlight's cone, a
        // point facing away) draws none. Every value is a function of its
        // sampler dimension alone, so when they are drawn changes none.
        // (only area lights draw samples; `made`: the light's AreaSampler at this point, if made already)
        const auto drawSamplesWith = [&](const AreaSampler& points) {
            range.begin = static_cast<int>(cache.samples_.size());
            const int count = points.count();
            constexpr int kRun = 64; // K or n1 n2 points: their values in one run up to this many
            const bool run = count > 1 && count <= kRun && points.drawsUniforms();
            static_assert(std::is_trivially_destructible_v<Vec2>);
            alignas(Vec2) unsigned char storage[kRun * sizeof(Vec2)]; // written by the run, not zeroed first
            Vec2* const w = reinterpret_cast<Vec2*>(storage);
            if (run) sampler.get2DStratifiedRun(points.dimension(), count, w);
            for (int k = 0; k < count; ++k) {
                const AreaSample a = run ? points.sampleFrom(w[k], k) : points.sample(sampler, k);
                cache.samples_.push_back({a.position, a.weight, false, Color(0)});
            }
            range.count = static_cast<int>(cache.samples_.size()) - range.begin;
        };
        const auto drawSamples = [&](const AreaSampler* made) {
            if (range.count > 0) return;
            if (made)
                drawSamplesWith(*made);
            else
                drawSamplesWith(AreaSampler(*light, sp.hit->point, sp.depth, index, lightSamples_));
        };
        const auto visible = [&](PointLightSamples::Sample& s) -> const Color& {
            return visibility(sp, i, *light, s, counts);
        };
        // With area illumination, the K points whose shading will ask for
        // their visibility (addPointLight's test, pointLightReaches), traced
        // together.
        const auto traceLitAhead = [&](PointLightSamples::Sample* samples) {
            if (range.count < 2) return;
            traceAhead(sp, i, *light, samples, range.count, counts, [&](int k) {
                const PointLightSamples::Sample& s = samples[k];
                Vec3 l;
                Color intensity;
                return s.weight > 0 &&
                       pointLightReaches(
                           sp, s.position, s.weight, false,
                           [&] { return lightIntensityAt(*light, cones, s.position, sp.hit->point, false); }, l,
                           intensity);
            });
        };
        // Diffuse and highlights from a point light at `position` whose colour
        // is scaled by `scale` (and by 1/r^2 when `inverseSquare`), times its visibility.
        const auto pointLight = [&](const Vec3& position, bool atCentre, double scale, bool inverseSquare,
                                    PointLightSamples::Sample* shadow) {
            addPointLight(
                sp, position, scale, inverseSquare,
                [&] { return lightIntensityAt(*light, cones, position, sp.hit->point, atCentre); }, shadow != nullptr,
                [&]() -> const Color& { return visible(*shadow); }, [&] { return crandNoise(sp, index, sampler); },
                sum);
        };
        if (!light->area) {
            // Its one sample, the light's position, lives in the range: nothing to draw.
            range.single.position = light->position;
            range.single.weight = 1.0;
            pointLight(light->position, true, 1.0, light->inverseSquare, &range.single);
        } else if (light->areaIllumination) {
            // Each sample point shades as a weighted point light; a highlight
            // is also sampled from its own lobe (highlights below).
            const Finish& finish = *sp.finish;
            bool highlights = hasHighlight(finish);
            if (highlights) {
                // How far the finish's highlight reaches, kept for the next point of the same finish.
                PointLightSamples::Reach& reach = cache.reach_;
                if (reach.phong != finish.phong || reach.phongSize != finish.phongSize ||
                    reach.specular != finish.specular || reach.roughness != finish.roughness)
                    reach = {finish.phong, finish.phongSize, finish.specular, finish.roughness,
                             highlightCosReach(finish)};
                highlights = highlightMayReach(reach.cosReach, sp.normal, sp.incoming, *light, sp.hit->point);
            }
            if (highlights) {
                const AreaSampler made(*light, sp.hit->point, sp.depth, index, lightSamples_, true);
                drawSamples(&made);
                if (made.continuous()) {
                    const AreaSampler* const points = &made;
                    PointLightSamples::Sample* samples = cache.samples_.data() + range.begin;
                    // Multiple importance sampling of the highlights (lighting.h):
                    // the light's K sample points and a direction drawn from the
                    // highlight's lobe each estimate the highlight, weighted by
                    // the power heuristic (K p)^2 / ((K p_light)^2 + p_lobe^2) in
                    // solid angle; the diffuse term takes the light's points alone.
                    const Vec3& p = sp.hit->point;
                    const double split = range.count;
                    traceLitAhead(samples);
                    for (int k = 0; k < range.count; ++k) {
                        if (!(samples[k].weight > 0)) continue;
                        const Vec3 position = samples[k].position;
                        const double lobe = [&] {
                            const Vec3 toLight = position - p;
                            const double distance = length(toLight);
                            return distance > 0
                                       ? highlightLobePdf(finish, sp.normal, sp.incoming, toLight / distance)
                                       : 0.0;
                        }();
                        // The power heuristic own^2 / (own^2 + lobe^2) through their ratio, which
                        // neither overflows nor underflows for a tiny light's huge density.
                        const double own = split * points->solidAnglePdf(position), ratio = lobe / own;
                        const double share = own > 0 && std::isfinite(ratio) ? 1 / (1 + ratio * ratio) : 1.0;
                        addPointLight(
                            sp, position, samples[k].weight, false,
                            [&] { return lightIntensityAt(*light, cones, position, p, false); }, true,
                            [&]() -> const Color& { return visible(samples[k]); },
                            [&] { return crandNoise(sp, index, sampler); }, sum, share);
                    }
                    Vec3 direction, position;
                    if (sampleHighlightLobe(finish, sp.normal, sp.incoming,
                                            sampler.get2D(highlightDimension(sp.depth, index)), direction) &&
                        dot(sp.normal, direction) > 0 && points->meet(direction, position)) {
                        const double lobe = highlightLobePdf(finish, sp.normal, sp.incoming, direction);
                        // perSteradian / lobe times lobe^2 / (own^2 + lobe^2), as above through the ratio.
                        const double own = split * points->solidAnglePdf(position), ratio = own / lobe;
                        const double scale = points->perSteradian(position) / lobe / (1 + ratio * ratio);
                        if (lobe > 0 && std::isfinite(scale) && scale > 0) {
                            Color seen =
                                highlightTerm(finish, sp.pigment, sp.normal, sp.incoming, direction) *
                                lightIntensityAt(*light, cones, position, p, false) * scale;
                            if (!isBlack(seen) && std::isfinite(maxComponent(seen))) {
                                const Scene* media =
                                    hasMedia_ && light->mediaAttenuation && light->mediaInteraction ? &scene_
                                                                                                    : nullptr;
                                seen *=
                                    lightTransmittance(accel_, projected_.of(i), light->shadowless, *sp.hit,
                                                       position, sp.time, counts, media);
                                sum += seen;
                            }
                        }
                    }
                    continue;
                }
            } else {
                drawSamples(nullptr);
            }
            PointLightSamples::Sample* samples = cache.samples_.data() + range.begin;
            traceLitAhead(samples);
            for (int k = 0; k < range.count; ++k)
                if (samples[k].weight > 0)
                    pointLight(samples[k].position, false, samples[k].weight, false, samples + k);
        } else {
            // A point light at the centre times the mean visibility of the samples.
            const Vec3 toCenter = light->position - sp.hit->point;
            const double distance = length(toCenter);
            if (!(distance > 0)) continue;
            const Vec3 l = toCenter / distance;
            if (!(dot(sp.normal, l) > 0)) continue;
            Color intensity = lightIntensityAt(*light, cones, light->position, sp.hit->point, true);
            if (light->inverseSquare) intensity = intensity / (distance * distance);
            if (isBlack(intensity)) continue;
            if (!light->shadowless) {
                drawSamples(nullptr);
                PointLightSamples::Sample* samples = cache.samples_.data() + range.begin;
                // Every sample's visibility is asked for: K or n1 n2 rays from one point, traced together.
                if (range.count > 1) traceAhead(sp, i, *light, samples, range.count, counts, [](int) { return true; });
                Color seen(0);
                if (light->area->sampling == AreaSampling::PovGrid) {
                    // Every grid point, each with POV-Ray's weight (AreaSampler::sampleFrom).
                    const int n1 = std::max(1, light->area->size1), n2 = std::max(1, light->area->size2);
                    for (int k = 0; k < range.count; ++k) seen += visible(samples[k]) * povGridWeight(n1, n2, k);
                    intensity *= seen;
                } else {
                    for (int k = 0; k < range.count; ++k) seen += visible(samples[k]);
                    intensity *= seen / range.count;
                }
                if (isBlack(intensity)) continue;
            }
            sum += lightTerm(*sp.finish, sp.pigment, sp.normal, sp.incoming, l, intensity,
                             crandNoise(sp, index, sampler));
        }
    }
    return sum;
}

} // namespace drt
