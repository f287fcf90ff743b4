#include "render/integrator.h"

#include "render/atmosphere.h"
#include "render/directions.h"
#include "render/media.h"
#include "render/noise.h"
#include "render/pigment.h"
#include "render/shading.h"
#include "render/texture_shading.h"
#include "sampling/warp.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace drt {

static_assert(kTraceLevelLimit < kMaxLightDepth, "extra lights' sampler dimensions must lie past every bounce's");

Integrator::Integrator(const Scene& scene, const Accelerator& accel, int lightSamples)
    : scene_(scene), accel_(accel), lighting_(scene, accel, true, lightSamples),
      maxTraceLevel_(std::clamp(scene.global.maxTraceLevel, 1, kTraceLevelLimit)),
      adcBailout_(std::isfinite(scene.global.adcBailout) ? std::max(0.0, scene.global.adcBailout) : 0.0),
      hasMedia_(sceneHasMedia(scene)) {
    if (hasMedia_) mediaBounds(scene, accel, mediaLower_, mediaUpper_);
}

struct Integrator::Scratch {
    std::vector<PendingRay> stack;
    MediaList media;
    PointLightSamples lights;
};

Integrator::Scratch& Integrator::scratch() { return ThreadScratch<Scratch>::get(); }

InstalledScratchSet Integrator::installThreadBuffers() {
    InstalledScratchSet installed;
    for (auto install : {ThreadScratch<Scratch>::install, installLightingScratch, installMediaScratch,
                         installTextureScratch})
        installed.push_back(install());
    Accelerator::installThreadBuffers(installed);
    return installed;
}

Color Integrator::trace(const Ray& cameraRay, const Hit& cameraHit, bool cameraFound, Sampler& sampler,
                        RayCounts& counts, const CameraShadows* cameraShadows) const {
    std::vector<PendingRay>& stack = scratch().stack;
    stack.clear();
    Color result(0);
    int shaded = 0;
    // What a ray sees, given its hit (if found): false once the sample has
    // shaded all it may. Inlined in both places it is called (the camera ray,
    // the stack's rays): a call would pass all it captures through memory.
    const auto see = [&](const Ray& ray, const RayPlace& place, const Color& weight, bool found, const Hit& hit,
                         const CameraShadows* shadows) __attribute__((always_inline)) {
        if (place.depth == 0)
            ++counts.camera;
        else
            ++counts.secondary;
        Color seen = weight; // what reaches the eye of what the ray sees
        if (!scene_.fogs.empty()) { // the fog in front of what the ray sees
            const double speed = length(ray.direction);
            const FogEffect fog = fogEffect(scene_.fogs, ray.origin, ray.direction / speed,
                                            found ? hit.t * speed : kFogMissDistance);
            result += weight * fog.add;
            seen = weight * fog.scale;
        }
        if (hasMedia_) { // the media in front of what the ray sees
            MediaList& media = scratch().media;
            media.clear();
            segmentMedia(scene_, place.medium, found ? &hit : nullptr, ray.direction, media);
            const double speed = length(ray.direction);
            const Vec3 unit = ray.direction / speed;
            const double distance =
                found ? hit.t * speed : mediaMissDistance(mediaLower_, mediaUpper_, ray.origin, unit);
            const MediaEffect effect = integrateMedia(media, ray.origin, unit, distance,
                                                      {&scene_, &accel_, ray.time, &lighting_.projectedThrough()},
                                                      sampler, mediaDimension(place.depth), counts);
            result += seen * effect.add;
            seen *= effect.scale;
        }
        if (!found) {
            const Color sky =
                scene_.sky.empty() ? scene_.background : skyColor(scene_, normalize(ray.direction));
            result += seen * sky;
            return true;
        }
        if (++shaded > kMaxRaysPerSample) return false;
        shade(ray, place, seen, hit, sampler, counts, result, stack, shadows);
        return true;
    };
    // The camera ray, whose hit the caller found, is read where the caller
    // has it. A copy into a PendingRay would be read back at once by loads
    // that straddle the copy's stores, which the store buffer cannot forward:
    // each such load waits for the stores to reach the cache.
    if (see(cameraRay, RayPlace{}, Color(1), cameraFound, cameraHit, cameraShadows)) {
        while (!stack.empty()) {
            // The copy (shading pushes onto the stack) is made before the
            // intersection, which reads the ray where it lies: by the time
            // the copy is read, its stores have reached the cache.
            const PendingRay pending = stack.back();
            // `traced` is one record per thread, not one per ray: a Hit is
            // about 230 bytes of initialised members, and
            // Accelerator::intersect writes every field a found hit is read by.
            static_assert(std::is_trivially_destructible_v<Hit>,
                          "no destructor to register (accel/thread_scratch.h)");
            thread_local Hit traced;
            const bool found = accel_.intersect(stack.back().ray, traced);
            stack.pop_back();
            if (!see(pending.ray, pending.place, pending.weight, found, traced, nullptr)) break;
        }
    }
    stack.clear();
    return result;
}

namespace {

// Perturbs an ideal direction into the lobe of the given blur, or returns it
// unchanged for blur 0 (drawing no sample).
Vec3 lobeDirection(const Vec3& ideal, double blur, Sampler& sampler, int dimension) {
    if (!(blur > 0)) return ideal;
    return sampleLobeAround(ideal, lobeExponent(blur), sampler.get2D(dimension));
}

// Radiosity's 2D sampler dimension at trace depth d: past the media's.
int radiosityDimension(int depth) {
    return kFirstMediaDimension + 2 * kMaxLightDepth + 2 * std::clamp(depth, 0, kMaxLightDepth - 1);
}

// A layer whose whole shading is its ambient and light terms: a solid
// pigment that lets nothing through (filter and transmit 0), no bump pattern
// and no reflection (a constant black one, not metallic).
bool matteLayer(const Texture& layer) {
    const ColorFT& colour = layer.pigment.color;
    const Finish& finish = layer.finish;
    return layer.pigment.pattern == PatternKind::Solid && !layer.normal && colour.filter == 0 &&
           colour.transmit == 0 && finish.reflectionMin == finish.reflectionMax && isBlack(finish.reflectionMin) &&
           !(finish.reflectionMetallic > 0);
}

// The shading point of a layer at a surface hit, with the layer's normal
// (bumped or not), its pigment's colour there and its finish.
ShadingPoint shadingPointOf(const Hit& hit, double time, int depth, const CameraShadows* cameraShadows,
                            const Vec3& normal, const Vec3& incoming, const ColorFT& pigment, const Finish& finish) {
    ShadingPoint sp;
    sp.hit = &hit;
    sp.cameraShadows = cameraShadows;
    sp.normal = normal;
    sp.incoming = incoming;
    sp.pigment = pigment;
    sp.finish = &finish;
    sp.time = time;
    sp.depth = depth;
    return sp;
}

} // namespace

// Written where the ray lies on the stack (emplace_back): a PendingRay built
// aside and then copied in is read back by the copy at once, in widths its
// stores do not match, which the store buffer cannot forward (the copy waits).
Integrator::PendingRay::PendingRay(const Hit& hit, const Vec3& direction, double time, const Color& weight,
                                   const RayPlace& place)
    : weight(weight), place(place) {
    ray.origin = Accelerator::offsetOrigin(hit, direction);
    ray.direction = direction;
    ray.tMin = 0;
    ray.time = time;
}

// A bump pattern moves with its object: on a moving object it tilts the
// normal in the object's rest pose, which is then turned to the world at the
// ray's time (normals map by the inverse transpose).
// A uv-mapped one reads the surface's uv and tangent frame (in the rest pose
// too); on a surface without uvs it has nothing to vary over and leaves the
// normal as it is.
Vec3 Integrator::bumpNormal(const Normal& bumps, const Hit& hit, double time, const Vec3& normal) const {
    if (bumps.uvMapping && !hit.hasUv) return normal;
    const auto perturb = [&](const Vec3& point, const Vec3& n) {
        return bumps.uvMapping ? perturbNormalUv(bumps, hit.uv, hit.dpdu, hit.dpdv, n) : perturbNormal(bumps, point, n);
    };
    if (hit.instance < 0) return perturb(hit.point, normal);
    const Transform toWorld = accel_.restToWorld(hit, time);
    const Vec3 restNormal = normalize(toWorld.inverted().normal(normal));
    return normalize(toWorld.normal(perturb(hit.restPoint, restNormal)));
}

void Integrator::shade(const Ray& ray, const RayPlace& place, const Color& seenWeight, const Hit& hit,
                       Sampler& sampler, RayCounts& counts, Color& result, std::vector<PendingRay>& stack,
                       const CameraShadows* cameraShadows) const {
    const Object& object = *hit.object;
    PointLightSamples& lights = scratch().lights;
    lights.clear();
    // A camera hit's facing, if its shadow rays were traced ahead, was worked out for them.
    const int ahead = cameraShadows ? cameraShadows->indexOf(hit) : -1;
    const Facing facing = ahead >= 0 ? cameraShadows->facings_[ahead] : facingOf(ray.direction, hit);
    SurfaceHit surface{ray, place, hit, facing.incoming, facing.entering, facing.normal, 1.0, &lights, cameraShadows};

    Color weight = seenWeight;
    if (!surface.entering) // the ray crossed the object's interior
        weight *= interiorAttenuation(object.interior, hit.t * length(ray.direction));
    const auto& corners = hit.cornerTextures;
    const bool plain =
        corners[0] == nullptr && corners[1] == nullptr && corners[2] == nullptr && object.texture->plain();
    if (plain && !scene_.global.radiosity && matteLayer(*object.texture)) { // (shadeMatte reads no eta)
        shadeMatte(surface, *object.texture, weight, sampler, counts, result);
        return;
    }
    const double ior = object.interior.ior > 0 && std::isfinite(object.interior.ior) ? object.interior.ior : 1.0;
    surface.eta = surface.entering ? 1.0 / ior : ior; // n_incident / n_transmitted
    if (plain) {
        // The object's own texture, one plain layer: what forEachSurfaceTexture
        // and shadeTexture come to (with a share of 1: weight * 1 == weight).
        const Texture* single = &*object.texture;
        shadeLayers(surface, &single, 1, weight, sampler, counts, result, stack);
        return;
    }
    forEachSurfaceTexture(hit, [&](const Texture& texture, double share) {
        shadeTexture(surface, texture, weight * share, sampler, counts, result, stack);
    });
}

// shadeLayers for one matte layer (matteLayer) in a scene without
// radiosity: the same shading point, its ambient and light terms added with
// the same weight (weight * filter with the filter still 1 is weight, x * 1
// being x), and nothing else: every ray shadeLayers might spawn has a weight
// that is a product with zero (the reflection, the filter rgb * 0 + 0), which
// worthTracing refuses whatever the other factor (a NaN or a +-0 component
// is never > 0).
void Integrator::shadeMatte(const SurfaceHit& surface, const Texture& layer, const Color& weight, Sampler& sampler,
                            RayCounts& counts, Color& result) const {
    // layer.pigment.color: evaluatePigment of a solid pigment.
    const ColorFT& pigment = layer.pigment.color;
    // DirectLighting::shade of no lights is Color(0): no shading point to make.
    Color lit(0);
    if (!scene_.lights.empty())
        lit = lighting_.shade(shadingPointOf(surface.hit, surface.ray.time, surface.place.depth, surface.cameraShadows,
                                             surface.normal, surface.incoming, pigment, layer.finish),
                              *surface.lights, sampler, counts);
    result += weight * (ambientTerm(layer.finish, pigment, scene_.global.ambientLight) + lit);
}

void Integrator::shadeTexture(const SurfaceHit& surface, const Texture& texture, const Color& weight, Sampler& sampler,
                              RayCounts& counts, Color& result, std::vector<PendingRay>& stack) const {
    if (texture.layersAbove.empty()) {
        if (!texture.map.empty()) {
            shadePatterned(surface, texture, weight, sampler, counts, result, stack);
            return;
        }
        const Texture* single = &texture;
        shadeLayers(surface, &single, 1, weight, sampler, counts, result, stack);
        return;
    }
    const TextureLayers layers(texture);
    shadeLayers(surface, layers.data(), layers.size(), weight, sampler, counts, result, stack);
}

// Each entry the pattern picks shades fully with its blend weight (the
// patterned texture's own layersAbove are not its business).
void Integrator::shadePatterned(const SurfaceHit& surface, const Texture& texture, const Color& weight,
                                Sampler& sampler, RayCounts& counts, Color& result,
                                std::vector<PendingRay>& stack) const {
    const Vec3* uv = surface.hit.hasUv ? &surface.hit.uv : nullptr;
    forEachPickedEntry(texture, surface.hit.restPoint, uv, [&](const Texture& entry, double w) {
        shadeTexture(surface, entry, weight * w, sampler, counts, result, stack);
    });
}

// texture_shading.h gives the layer model; one plain layer is Whitted's shading.
void Integrator::shadeLayers(const SurfaceHit& surface, const Texture* const* layers, size_t count,
                             const Color& weight, Sampler& sampler, RayCounts& counts, Color& result,
                             std::vector<PendingRay>& stack) const {
    const Ray& ray = surface.ray;
    const RayPlace& place = surface.place;
    const Hit& hit = surface.hit;
    const Vec3& incoming = surface.incoming;
    const int childDepth = place.depth + 1;
    const bool traceChildren = childDepth < maxTraceLevel_; // deeper rays are black (POV-Ray)
    const auto worthTracing = [&](const Color& w) { return maxComponent(w) > 0 && maxComponent(w) >= adcBailout_; };

    Color filter(1); // what the layers so far let through
    Vec3 topNormal = surface.normal;
    const size_t firstPushed = stack.size(); // this hit's rays are stack[firstPushed..)
    bool anyMirrorsTop = false;
    for (size_t i = 0; i < count; ++i) {
        const Texture& layer = *layers[i];
        if (!layer.map.empty()) { // a patterned layer shades itself and all below it, seen through `filter`
            shadePatterned(surface, layer, weight * filter, sampler, counts, result, stack);
            return;
        }
        const Finish& finish = layer.finish;
        Vec3 normal = surface.normal;
        if (layer.normal) { // bump pattern; kept only while it still faces the viewer
            const Vec3 bumped = bumpNormal(*layer.normal, hit, ray.time, normal);
            if (dot(bumped, incoming) < 0) normal = bumped;
        }
        if (i == 0) topNormal = normal;

        // Textures move with their object (restPoint); uv_mapping reads the surface's uv.
        const ShadingPoint sp =
            shadingPointOf(hit, ray.time, place.depth, surface.cameraShadows, normal, incoming,
                           evaluatePigment(layer.pigment, hit.restPoint, hit.hasUv ? &hit.uv : nullptr), finish);

        const Color local = ambientTerm(finish, sp.pigment, scene_.global.ambientLight) +
                            lighting_.shade(sp, *surface.lights, sampler, counts);
        result += weight * filter * local;
        // Radiosity (scene.h): one cosine-distributed ray about the unbumped normal carries the layer's diffuse share.
        if (const std::optional<Radiosity>& radiosity = scene_.global.radiosity;
            radiosity && place.diffuseDepth < radiosity->recursionLimit && childDepth < kTraceLevelLimit &&
            finish.diffuse > 0) {
            const Color gathered = weight * filter * sp.pigment.rgb *
                                   (finish.diffuse * radiosity->brightness * sp.pigment.opacity());
            if (worthTracing(gathered))
                stack.emplace_back(hit,
                                   sampleCosineAround(surface.normal, sampler.get2D(radiosityDimension(place.depth))),
                                   ray.time, gathered, RayPlace{childDepth, place.medium, place.diffuseDepth + 1});
        }

        const double cosIncident = std::clamp(-dot(incoming, normal), 0.0, 1.0);
        // A reflection that does not vary (min == max, no metallic tint) is its
        // value: reflectivity returns min and the tint is 1, and x * 1 == x.
        const bool constantReflection =
            finish.reflectionMin == finish.reflectionMax && !(finish.reflectionMetallic > 0);
        const Color reflected = !traceChildren        ? Color(0)
                                : constantReflection ? finish.reflectionMin
                                                     : reflectivity(finish, cosIncident, surface.eta) *
                                                           metallicTint(finish.reflectionMetallic, sp.pigment,
                                                                        cosIncident);
        const Color reflectedWeight = weight * reflected;
        if (traceChildren && worthTracing(reflectedWeight)) {
            const Vec3 direction = lobeDirection(reflect(incoming, normal), finish.reflectionBlur, sampler,
                                                 bounceDimension(place.depth, kOffsetLobe));
            if (dot(direction, normal) > 0) { // below the surface: weight 0
                stack.emplace_back(hit, direction, ray.time, reflectedWeight,
                                   RayPlace{childDepth, place.medium, place.diffuseDepth});
                // POV-Ray compares the layer's normal with the top one's to within 1e-10.
                const Vec3 off = normal - topNormal;
                stack.back().mirrorsTop =
                    std::fabs(off.x) <= 1e-10 && std::fabs(off.y) <= 1e-10 && std::fabs(off.z) <= 1e-10;
                anyMirrorsTop |= stack.back().mirrorsTop;
            }
        }

        filter *= sp.pigment.rgb * sp.pigment.filter + Color(sp.pigment.transmit);
        if (finish.conserveEnergy) // what is reflected is not transmitted as well
            filter *= Color(std::max(0.0, 1 - reflected.r), std::max(0.0, 1 - reflected.g),
                            std::max(0.0, 1 - reflected.b));
        if (i + 1 < count && std::min(1.0, std::fabs(greyValue(filter))) < adcBailout_) return;
    }
    if (!traceChildren) return;

    // The transmitted ray: everything the layers let through, bent at the top layer.
    const Finish& top = layers[0]->finish;
    const Color transmittedWeight = weight * filter;
    if (worthTracing(transmittedWeight)) {
        Vec3 ideal;
        bool internalReflection = false;
        if (surface.eta == 1.0)
            ideal = incoming; // no bending: exactly straight on
        else if (!refract(incoming, topNormal, surface.eta, ideal)) {
            // Total internal reflection (POV-Ray's rule): the transmitted
            // light, unfiltered, follows the mirror ray, and the layers'
            // reflections about the same normal are not traced as well (they
            // would count the mirror ray twice).
            ideal = reflect(incoming, topNormal);
            internalReflection = true;
            if (anyMirrorsTop)
                stack.erase(std::remove_if(stack.begin() + std::ptrdiff_t(firstPushed), stack.end(),
                                           [](const PendingRay& r) { return r.mirrorsTop; }),
                            stack.end());
        }
        const Vec3 direction = lobeDirection(ideal, top.refractionBlur, sampler,
                                             bounceDimension(place.depth, kOffsetRefractionLobe));
        const double side = dot(direction, topNormal);
        if (internalReflection ? side > 0 : side < 0)
            stack.emplace_back(hit, direction, ray.time, internalReflection ? weight : transmittedWeight,
                               RayPlace{childDepth,
                                        internalReflection
                                            ? place.medium
                                            : mediumAfterCrossing(place.medium, *hit.object, surface.entering),
                                        place.diffuseDepth});
    }
}

} // namespace drt
