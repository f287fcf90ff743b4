#include "render/media.h"

#include "render/light_path.h"
#include "render/pigment.h"
#include "render/shading.h"

#include <algorithm>
#include <cmath>

namespace drt {

double phaseFunction(int type, double eccentricity, double cosTheta) {
    const double c = std::clamp(cosTheta, -1.0, 1.0);
    const double u = 0.5 * (1 + c); // (1 + cos) / 2, in [0, 1]
    switch (type) {
    case 2: return (1 + 9 * std::pow(u, 8)) / (8 * kPi); // mean of u^8 over the sphere: 1/9
    case 3: return (1 + 50 * std::pow(u, 32)) / (4 * kPi * (1 + 50.0 / 33.0)); // mean of u^32: 1/33
    case 4: return 3 * (1 + c * c) / (16 * kPi);
    case 5: {
        const double g = std::clamp(eccentricity, -0.999999, 0.999999);
        return (1 - g * g) / (4 * kPi * std::pow(1 + g * g - 2 * g * c, 1.5));
    }
    default: return 1 / (4 * kPi);
    }
}

Color mediaDensity(const Media& media, const Vec3& point) {
    Color d(1);
    for (const Pigment& density : media.densities) d *= evaluatePigment(density, point).rgb;
    return d;
}

void segmentMedia(const Scene& scene, const Object* inside, const Hit* hit, const Vec3& direction, MediaList& out) {
    const Object* within = inside;
    if (hit && hit->object && dot(direction, hit->geometricNormal) > 0) { // leaving the object hit
        for (const Media& m : hit->object->interior.media) out.push_back(&m);
        if (!hit->object->hollow) return;
        if (hit->object == inside) within = nullptr; // its media are counted: what is around it is unknown
    } else if (inside) {
        for (const Media& m : inside->interior.media) out.push_back(&m);
        if (!inside->hollow) return;
        within = nullptr;
    }
    if (within) {
        for (const Media& m : within->interior.media) out.push_back(&m);
        if (!within->hollow) return;
    }
    for (const Media& m : scene.media) out.push_back(&m);
}

const Object* mediumAfterCrossing(const Object* before, const Object& object, bool entering) {
    if (entering) return object.interior.media.empty() ? before : &object;
    return before == &object ? nullptr : before;
}

namespace {

bool hasMediaInside(const Object& o) {
    if (!o.interior.media.empty()) return true;
    if (const Csg* csg = std::get_if<Csg>(&o.shape))
        return std::any_of(csg->children.begin(), csg->children.end(), hasMediaInside);
    return false;
}

int strataCount(const MediaList& media) {
    long long n = 1;
    for (const Media* m : media) n = std::max(n, (long long)std::max(1, m->intervals) * std::max(1, m->samples));
    return static_cast<int>(std::min(n, 4096LL)); // a guard against absurd counts
}

Color expNegative(const Color& x) { return {std::exp(-x.r), std::exp(-x.g), std::exp(-x.b)}; }

// (1 - exp(-k h)) / k per channel: the integral of exp(-k t) over [0, h].
double stratumWeight(double k, double h) { return k > 1e-12 ? -std::expm1(-k * h) / k : h; }

struct Coefficients {
    Color extinction{0};
    Color emission{0};
};

// Extinction and emission of all media at a point; the densities go to `densities`.
Coefficients coefficientsAt(const MediaList& media, const Vec3& p, std::vector<Color>* densities) {
    Coefficients c;
    for (const Media* m : media) {
        const Color d = mediaDensity(*m, p);
        c.extinction += d * (m->absorption + m->extinction * m->scattering);
        c.emission += d * m->emission;
        if (densities) densities->push_back(d);
    }
    return c;
}

// Light scattered towards -direction at p: sum over lights and scattering media
// of D s 4 pi p(theta) L_light.
Color inScattered(const MediaList& media, const std::vector<Color>& densities, const Vec3& p, const Vec3& direction,
                  const MediaLighting& lighting, RayCounts& counts) {
    bool scatters = false;
    for (const Media* m : media) scatters = scatters || (m->scatteringType != 0 && !isBlack(m->scattering));
    if (!scatters || !lighting.scene) return Color(0);
    Color sum(0);
    Hit from;
    from.point = p;
    const auto scatterFrom = [&](const Light& light, size_t index) {
        if (!light.mediaInteraction || isBlack(light.color)) return;
        const Vec3 toLight = light.position - p;
        const double distance = length(toLight);
        if (!(distance > 0)) return;
        Color intensity = light.color * (spotlightAttenuation(light, light.position, p) * fadeAttenuation(light, distance));
        if (light.inverseSquare) intensity = intensity / (distance * distance);
        if (isBlack(intensity) || !std::isfinite(maxComponent(intensity))) return;
        if (lighting.accel) { // lightTransmittance knows shadowless lights and projected_through
            const Accelerator* projected = lighting.projected ? lighting.projected->of(index) : nullptr;
            intensity *= lightTransmittance(*lighting.accel, projected, light.shadowless, from, light.position,
                                            lighting.time, counts,
                                            light.mediaAttenuation ? lighting.scene : nullptr); // interaction is on here
            if (isBlack(intensity)) return;
        }
        const double cosTheta = dot(toLight / distance, direction);
        for (size_t i = 0; i < media.size(); ++i) {
            const Media& m = *media[i];
            if (m.scatteringType == 0) continue;
            sum += densities[i] * m.scattering * intensity *
                   (4 * kPi * phaseFunction(m.scatteringType, m.eccentricity, cosTheta));
        }
    };
    for (size_t index = 0; index < lighting.scene->lights.size(); ++index) {
        const Light& light = lighting.scene->lights[index];
        // A moving light as it is at the ray's time (render/light_path.h); a still one as written, with no copy.
        // A parallel light stands where p's ray from it starts (scene.h).
        const bool moves = lightMoves(light);
        if (moves || light.parallel) {
            Light placed = moves ? lightAt(light, lighting.time) : light;
            if (placed.parallel) placed.position = parallelLightPosition(placed, p);
            scatterFrom(placed, index);
        } else {
            scatterFrom(light, index);
        }
    }
    return sum;
}

} // namespace

double mediaMissDistance(const Vec3& lower, const Vec3& upper, const Vec3& origin, const Vec3& direction) {
    double t0 = 0, t1 = 1e30;
    return clipToBox(lower, upper, origin, direction, t0, t1) && t1 > t0 ? t1 : 0;
}

void mediaBounds(const Scene& scene, const Accelerator& accel, Vec3& lower, Vec3& upper) {
    accel.bounds(lower, upper);
    for (const Light& l : scene.lights)
        for (int i = 0; i < 3; ++i) {
            lower[i] = std::min(lower[i], l.position[i]);
            upper[i] = std::max(upper[i], l.position[i]);
        }
    for (int i = 0; i < 3; ++i) { // nothing finite: a box of side 2e4 around the origin
        if (!(lower[i] <= upper[i]) || !std::isfinite(lower[i]) || !std::isfinite(upper[i])) lower[i] = -1e4, upper[i] = 1e4;
    }
}

bool sceneHasMedia(const Scene& scene) {
    return !scene.media.empty() || std::any_of(scene.objects.begin(), scene.objects.end(), hasMediaInside);
}

namespace {

// integrateMedia's densities, kept per thread (accel/thread_scratch.h).
struct MediaScratch {
    std::vector<Color> densities;
};

} // namespace

std::unique_ptr<InstalledScratch> installMediaScratch() { return ThreadScratch<MediaScratch>::install(); }

MediaEffect integrateMedia(const MediaList& media, const Vec3& origin, const Vec3& direction, double length,
                           const MediaLighting& lighting, Sampler& sampler, int dimension, RayCounts& counts) {
    MediaEffect effect;
    if (media.empty() || !(length > 0) || !std::isfinite(length)) return effect;
    const int n = strataCount(media);
    const double h = length / n;
    std::vector<Color>& densities = ThreadScratch<MediaScratch>::get().densities;
    for (int j = 0; j < n; ++j) {
        const double u = sampler.get2DStratified(dimension, j, n).x;
        const Vec3 p = origin + direction * ((j + u) * h);
        densities.clear();
        Coefficients c = coefficientsAt(media, p, &densities); // negative extinction (negative densities) is 0
        const Color source = c.emission + inScattered(media, densities, p, direction, lighting, counts);
        c.extinction = Color(std::max(0.0, c.extinction.r), std::max(0.0, c.extinction.g), std::max(0.0, c.extinction.b));
        const Color w{stratumWeight(c.extinction.r, h), stratumWeight(c.extinction.g, h),
                      stratumWeight(c.extinction.b, h)};
        effect.add += effect.scale * source * w;
        effect.scale *= expNegative(c.extinction * h);
    }
    return effect;
}

Color mediaTransmittance(const MediaList& media, const Vec3& origin, const Vec3& direction, double length) {
    if (media.empty() || !(length > 0)) return Color(1);
    if (!std::isfinite(length)) return Color(0);
    const int n = strataCount(media);
    const double h = length / n;
    Color depth(0);
    for (int j = 0; j < n; ++j) {
        const Color k = coefficientsAt(media, origin + direction * ((j + 0.5) * h), nullptr).extinction;
        depth += Color(std::max(0.0, k.r), std::max(0.0, k.g), std::max(0.0, k.b));
    }
    return expNegative(depth * h);
}

} // namespace drt
