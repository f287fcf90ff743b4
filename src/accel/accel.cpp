// Ray queries: Embree finds the nearest primitive in float; the hit is then
// rebuilt in double (analytic shapes re-solved, triangles intersected again)
// so that the point lies on the surface to double precision, which is what
// offsetOrigin needs to avoid self-intersection.
#include "accel/accel_impl.h"
#include "core/error.h"

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <new>
#include <type_traits>

namespace drt {

using namespace accel;

Accelerator::Accelerator(const Scene& scene) : impl_(std::make_unique<Impl>()) { buildScene(scene, *impl_); }

Accelerator::Accelerator(const Scene& scene, double onlyTime) : impl_(std::make_unique<Impl>()) {
    // Embree clamps ray times to [0, 1]; so does fillRay.
    impl_->onlyTime = std::fmin(1.0, std::fmax(0.0, onlyTime));
    buildScene(scene, *impl_);
}

Accelerator::~Accelerator() = default;

namespace {

// The float after / before a finite float, without a library call: for
// positive floats a larger bit pattern is a larger value, for negative ones a
// smaller; zero steps to the smallest subnormal.
float floatUp(float f) {
    if (f == 0) return std::numeric_limits<float>::denorm_min();
    const int32_t bits = std::bit_cast<int32_t>(f);
    return std::bit_cast<float>(f > 0 ? bits + 1 : bits - 1);
}
float floatDown(float f) { return -floatUp(-f); }

// Float interval limits that never widen [tMin, tMax].
float floatAtLeast(double v) {
    if (v >= double(FLT_MAX)) return INFINITY;
    const float f = float(v);
    return double(f) < v ? floatUp(f) : f;
}
float floatAtMost(double v) {
    if (v >= double(FLT_MAX)) return INFINITY;
    const float f = float(v);
    return double(f) > v ? floatDown(f) : f;
}

// max(v, 0) and min(max(v, 0), 1) with NaN going to 0 as std::fmax sends it,
// by comparisons (std::fmax is a library call here, twice per ray).
inline float atLeastZero(float v) { return v > 0 ? v : 0.0f; }
inline double clampToUnit(double v) { return v > 0 ? (v < 1 ? v : 1.0) : 0.0; }

// The origin is moved into the top level's frame in double, then rounded.
void fillRay(const Ray& ray, const AcceleratorState& state, RTCRay& r, unsigned mask) {
    const Vec3 origin = state.shifted ? ray.origin - state.frameOrigin : ray.origin;
    r.org_x = float(origin.x);
    r.org_y = float(origin.y);
    r.org_z = float(origin.z);
    r.tnear = atLeastZero(floatAtLeast(ray.tMin));
    r.dir_x = float(ray.direction.x);
    r.dir_y = float(ray.direction.y);
    r.dir_z = float(ray.direction.z);
    r.time = float(clampToUnit(ray.time));
    r.tfar = floatAtMost(ray.tMax);
    r.mask = mask;
    r.id = 0;
    r.flags = 0;
}

// Every coordinate within Embree's range (false for NaN).
inline bool withinEmbree(const Vec3& v) {
    constexpr double kLargest = Accelerator::kLargestCoordinate;
    return (std::fabs(v.x) <= kLargest) & (std::fabs(v.y) <= kLargest) & (std::fabs(v.z) <= kLargest);
}
// withinEmbree of the origins and directions of many rays, all at once: with
// SSE2 two coordinates a step (|x| <= kLargestCoordinate, false for NaN, as
// withinEmbree compares them).
class EmbreeRange {
public:
    void add(const Vec3& origin, const Vec3& direction) {
#if defined(__SSE2__)
        const __m128d largest = _mm_set1_pd(Accelerator::kLargestCoordinate);
        const __m128d magnitude = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffff));
        const __m128d xy = _mm_cmple_pd(_mm_and_pd(_mm_set_pd(origin.y, origin.x), magnitude), largest);
        const __m128d zx = _mm_cmple_pd(_mm_and_pd(_mm_set_pd(direction.x, origin.z), magnitude), largest);
        const __m128d yz = _mm_cmple_pd(_mm_and_pd(_mm_set_pd(direction.z, direction.y), magnitude), largest);
        within_ = _mm_and_pd(within_, _mm_and_pd(xy, _mm_and_pd(zx, yz)));
#else
        within_ &= withinEmbree(origin) & withinEmbree(direction);
#endif
    }
    bool all() const {
#if defined(__SSE2__)
        return _mm_movemask_pd(within_) == 3;
#else
        return within_;
#endif
    }

private:
#if defined(__SSE2__)
    __m128d within_ = _mm_castsi128_pd(_mm_set1_epi32(-1));
#else
    bool within_ = true;
#endif
};

// A packet's rays in Embree's layout (RTCRay8, or the ray of an RTCRayHit8),
// each lane what fillRay makes of its ray. The lanes past `count` repeat ray 0
// (Embree ignores them). A packet's rays mostly share their interval and time
// (a pixel's camera rays, the shadow rays to one light): when every lane's
// have the bits of ray 0's, they are converted once and stored in every lane.
// Returns whether Embree can take every ray (traceable): if not, the packet
// is not to be traced.
template <class Packet>
bool fillPacket(const Ray* rays, int count, const AcceleratorState& state, unsigned mask, Packet& packet) {
    constexpr int kN = Accelerator::kPacketSize;
    const Ray& first = rays[0];
    const uint64_t tMinBits = std::bit_cast<uint64_t>(first.tMin), tMaxBits = std::bit_cast<uint64_t>(first.tMax),
                   timeBits = std::bit_cast<uint64_t>(first.time);
    const bool shifted = state.shifted;
    const Vec3 frameOrigin = state.frameOrigin;
    EmbreeRange inRange;
    bool shared = true;
    for (int i = 0; i < kN; ++i) {
        const Ray& ray = rays[i < count ? i : 0];
        const Vec3 origin = shifted ? ray.origin - frameOrigin : ray.origin;
        inRange.add(origin, ray.direction);
        shared &= (std::bit_cast<uint64_t>(ray.tMin) == tMinBits) & (std::bit_cast<uint64_t>(ray.tMax) == tMaxBits) &
                  (std::bit_cast<uint64_t>(ray.time) == timeBits);
        packet.org_x[i] = float(origin.x);
        packet.org_y[i] = float(origin.y);
        packet.org_z[i] = float(origin.z);
        packet.dir_x[i] = float(ray.direction.x);
        packet.dir_y[i] = float(ray.direction.y);
        packet.dir_z[i] = float(ray.direction.z);
    }
    if (shared) [[likely]] {
        const float tnear = atLeastZero(floatAtLeast(first.tMin)), tfar = floatAtMost(first.tMax),
                    time = float(clampToUnit(first.time));
        for (int i = 0; i < kN; ++i) {
            packet.tnear[i] = tnear;
            packet.tfar[i] = tfar;
            packet.time[i] = time;
        }
    } else {
        for (int i = 0; i < kN; ++i) {
            const Ray& ray = rays[i < count ? i : 0];
            packet.tnear[i] = atLeastZero(floatAtLeast(ray.tMin));
            packet.tfar[i] = floatAtMost(ray.tMax);
            packet.time[i] = float(clampToUnit(ray.time));
        }
    }
    for (int i = 0; i < kN; ++i) {
        packet.mask[i] = mask;
        packet.id[i] = static_cast<unsigned>(i);
        packet.flags[i] = 0;
    }
    return inRange.all();
}

// Whether the ray's segment [tMin, tMax] may meet the box (in double; the box
// is grown to cover rounding, AcceleratorState::swept).
inline bool segmentMeetsBox(const Ray& ray, const Vec3& lower, const Vec3& upper) {
    if (ray.tMax < INFINITY) { // a shadow ray's segment has a box of its own: apart from the box, no divisions
        const Vec3 a = ray.origin + ray.tMin * ray.direction, b = ray.origin + ray.tMax * ray.direction;
        for (int axis = 0; axis < 3; ++axis) {
            const bool ordered = a[axis] <= b[axis];
            const double low = ordered ? a[axis] : b[axis], high = ordered ? b[axis] : a[axis];
            if (low > upper[axis] || high < lower[axis]) return false;
        }
    }
    double t0 = ray.tMin, t1 = ray.tMax;
    return clipToBox(lower, upper, ray.origin, ray.direction, t0, t1);
}

// The ray's geometry mask in a scene with a swept box: every bit, less
// kSweptBit where its segment misses the box (for intersect), or kShadowMask
// and kSweptBit where it may meet the box of a shadow-casting object (for occluded).
inline unsigned rayMask(const Ray& ray, const AcceleratorState& state, bool shadow) {
    const AcceleratorState::SweptBox& box = *state.swept;
    const bool meets = (!shadow || box.castsShadow) && segmentMeetsBox(ray, box.lower, box.upper);
    if (shadow) return meets ? kShadowMask | kSweptBit : kShadowMask;
    return meets ? 0xFFFFFFFFu : ~kSweptBit;
}

// Whether Embree can take the ray (Accelerator::kLargestCoordinate).
inline bool traceable(const Ray& ray, const AcceleratorState& state) {
    return withinEmbree(state.shifted ? ray.origin - state.frameOrigin : ray.origin) && withinEmbree(ray.direction);
}
// The ray with its direction divided and its interval multiplied by a power of
// two until the direction is within range: the same points, exactly (a ray whose
// origin is out of range, or that is not finite, stays untraceable).
Ray shortened(const Ray& ray) {
    Ray r = ray;
    const double longest = std::fmax(std::fabs(r.direction.x), std::fmax(std::fabs(r.direction.y), std::fabs(r.direction.z)));
    if (!std::isfinite(longest)) return r;
    int exponent = 0;
    std::frexp(longest / Accelerator::kLargestCoordinate, &exponent);
    if (exponent <= 0) return r;
    r.direction = Vec3(std::ldexp(r.direction.x, -exponent), std::ldexp(r.direction.y, -exponent),
                       std::ldexp(r.direction.z, -exponent));
    r.tMin = std::ldexp(r.tMin, exponent);
    r.tMax = std::ldexp(r.tMax, exponent);
    return r;
}
Vec3 unitOr(const Vec3& v, const Vec3& fallback) {
    const double len = length(v);
    return len > 0 && std::isfinite(len) ? v / len : fallback;
}

// Embree picks a SIMD kernel for the CPU it runs on (SSE, AVX2, AVX-512), and
// its float barycentrics may differ in the last bits between kernels. So the
// hit is solved again in double from the triangle's vertices (Moeller and
// Trumbore 1997: o + t d = (1-u-v) p0 + u p1 + v p2 by Cramer's rule), which
// makes the point and normals the same on every CPU once Embree has chosen
// the triangle. The barycentrics are clamped to the triangle, as the hit lies
// on it up to float error. A ray (nearly) parallel to the plane keeps
// Embree's values: det is then too small to divide by.
void resolveTriangleHit(const Vec3& o, const Vec3& d, const Vec3& p0, const Vec3& p1, const Vec3& p2,
                        double& t, double& u, double& v) {
    const Vec3 e1 = p1 - p0, e2 = p2 - p0;
    const Vec3 pv = cross(d, e2);
    const double det = dot(e1, pv);
    // det = d . (e2 x e1): the sine of the ray's angle to the plane times |d||e1||e2|.
    if (!(std::fabs(det) > 1e-12 * length(d) * length(e1) * length(e2))) return;
    const Vec3 tv = o - p0;
    const Vec3 qv = cross(tv, e1);
    const double uu = dot(tv, pv) / det, vv = dot(d, qv) / det, tt = dot(e2, qv) / det;
    if (!std::isfinite(uu) || !std::isfinite(vv) || !std::isfinite(tt)) return;
    // Embree's t is good to float precision; a far larger disagreement means
    // the double solve lost its digits, and Embree's answer is the better one.
    // By comparisons, as x86-64's std::fmax answers (a library call here, three
    // a hit): fmax(1, |t|) is 1 for NaN; uu and vv are finite, and fmax(0, x)
    // is x for x = -0 (the second operand of equals).
    const double scale = std::fabs(t) > 1.0 ? std::fabs(t) : 1.0;
    if (std::fabs(tt - t) > 1e-3 * scale) return;
    u = uu >= 0.0 ? uu : 0.0;
    v = vv >= 0.0 ? vv : 0.0;
    if (u + v > 1) {
        const double sum = u + v;
        u /= sum;
        v /= sum;
    }
    t = tt;
}

// The uv coordinates and corner textures of a compact mesh's triangle at the
// corners' barycentric weights.
void meshSurface(const IndexedMesh& m, const Mesh& shape, uint32_t prim, const std::array<double, 3>& weights,
                 Hit& hit) {
    if (!m.uvs.empty()) {
        const auto c = m.uvTriangle(prim);
        double u = 0, v = 0;
        for (int k = 0; k < 3; ++k) {
            u += weights[k] * m.uvs[c[k]].u;
            v += weights[k] * m.uvs[c[k]].v;
        }
        hit.hasUv = true;
        hit.uv = {u, v, 0};
    }
    if (m.faceTextures.empty()) return;
    for (int k = 0; k < 3; ++k) {
        const uint32_t t = m.faceTextures[3 * size_t(prim) + k];
        hit.cornerTextures[k] = t < shape.textures.size() ? &shape.textures[t] : nullptr;
        hit.cornerWeights[k] = weights[k];
    }
}

// dP/du and dP/dv of a compact mesh's triangle whose corners, as traced, are
// p0, p1, p2 (a copy may have swapped the IndexedMesh's corners 1 and 2).
// Zero when its uvs span no area.
void uvTangents(const IndexedMesh& m, uint32_t prim, bool swapped, const Vec3& p0, const Vec3& p1, const Vec3& p2,
                Hit& hit) {
    auto c = m.uvTriangle(prim);
    if (swapped) std::swap(c[1], c[2]);
    const double du1 = double(m.uvs[c[1]].u) - m.uvs[c[0]].u, dv1 = double(m.uvs[c[1]].v) - m.uvs[c[0]].v;
    const double du2 = double(m.uvs[c[2]].u) - m.uvs[c[0]].u, dv2 = double(m.uvs[c[2]].v) - m.uvs[c[0]].v;
    const double det = du1 * dv2 - du2 * dv1;
    const Vec3 e1 = p1 - p0, e2 = p2 - p0;
    if (!(std::fabs(det) > 1e-20) || !std::isfinite(1 / det)) {
        hit.dpdu = hit.dpdv = Vec3{};
        return;
    }
    hit.dpdu = (dv2 * e1 - dv1 * e2) / det;
    hit.dpdv = (du1 * e2 - du2 * e1) / det;
}

// The hit record of the hit Embree found for the query's ray (rayhit: its
// ray and hit as Embree left them, geomID valid): any hit (generalHit), or an
// analytic shape's at the top level, solved in double by the callback (the
// most common; topAnalyticHit, the same arithmetic without the cases it
// cannot be).
} // namespace

namespace accel {

[[gnu::noinline]] void generalHit(const AcceleratorState& state, RayQuery& query, const RTCRayHit& rayhit, Hit& hit) {
    hit.hasUv = false;
    hit.uv = {};
    hit.cornerTextures = {};

    // Find the level the hit geometry lives in and the ray in that level's space.
    const Level* level = &state.top;
    const unsigned instID = rayhit.hit.instID[0];
    const Transform* motion = nullptr; // level space -> world, if the top level's is not world
    const Instance* instance = nullptr;
    hit.instance = -1;
    if (instID != RTC_INVALID_GEOMETRY_ID) {
        const size_t index = state.top.geometries[instID].index;
        instance = &state.instances[index];
        level = instance->level.get();
        Vec3 unusedO, unusedD;
        query.levelRay(instID, rayhit.ray.time, unusedO, unusedD); // the callback's transform, or solved now
        motion = &*query.instanceToWorld;
        // A compact mesh's placement is still: only moving objects have a rest pose (restToWorld).
        if (!instance->placed) hit.instance = static_cast<int>(index);
    }
    const bool shiftedTop = !motion && state.shifted;
    const Vec3& o = motion ? query.instanceOrigin : query.origin;
    const Vec3& d = motion ? query.instanceDirection : query.direction;
    // The normal of last resort, computed only when needed.
    const auto unitOrTowardOrigin = [&d](const Vec3& v) {
        const double len = length(v);
        return len > 0 && std::isfinite(len) ? v / len : unitOr(-d, {0, 1, 0});
    };

    const GeometryRef& ref = level->geometries[rayhit.hit.geomID];
    const double embreeT = rayhit.ray.tfar;
    Vec3 point, geometric, shading;
    double frameUnit = 0; // Hit::frameUnit of the object hit; 0 if unbounded (the scene's)
    if (ref.kind == GeometryKind::Analytic) {
        const Primitive& p = level->primitives[rayhit.hit.primID];
        SurfaceCrossing c;
        if (query.hasCrossing && query.primID == rayhit.hit.primID && query.instID == instID) {
            // Solved in double by the callback.
            c = query.objectSpace ? levelCrossing(p, query.objectCrossing) : query.crossing;
        } else if (!closestCrossingTo(p, o, d, embreeT, c)) {
            c.t = embreeT;
            c.normal = {rayhit.hit.Ng_x, rayhit.hit.Ng_y, rayhit.hit.Ng_z};
            c.object = p.object;
        }
        hit.t = c.t;
        point = o + c.t * d;
        geometric = shading = unitOrTowardOrigin(c.normal);
        hit.object = c.object;
        hit.primitive = 0;
        frameUnit = p.frameUnit;
    } else {
        const MeshRecord& mesh = level->meshes[ref.index];
        const uint32_t prim = rayhit.hit.primID;
        const bool prototype = mesh.vertices.empty(); // a compact mesh's shared level: object space
        Vec3 p0, p1, p2;
        if (prototype) {
            const auto tri = mesh.indexed->triangle(prim);
            p0 = mesh.indexed->positions[tri[0]].toVec3();
            p1 = mesh.indexed->positions[tri[1]].toVec3();
            p2 = mesh.indexed->positions[tri[2]].toVec3();
        } else {
            const auto& tri = mesh.triangles[prim];
            p0 = mesh.vertices[tri[0]], p1 = mesh.vertices[tri[1]], p2 = mesh.vertices[tri[2]];
        }
        double u = rayhit.hit.u, v = rayhit.hit.v;
        hit.t = embreeT;
        resolveTriangleHit(o, d, p0, p1, p2, hit.t, u, v);
        const double w = 1 - u - v;
        point = w * p0 + u * p1 + v * p2;
        // A degenerate triangle has no winding normal: face the ray instead of NaN.
        geometric = unitOrTowardOrigin(cross(p1 - p0, p2 - p0));
        shading = geometric;
        if (prototype && !mesh.indexed->normals.empty()) {
            const auto ni = mesh.indexed->normalTriangle(prim);
            const auto& n = mesh.indexed->normals;
            shading = unitOr(w * n[ni[0]].toVec3() + u * n[ni[1]].toVec3() + v * n[ni[2]].toVec3(), geometric);
            if (dot(shading, geometric) < 0) shading = -shading;
        } else if (!mesh.normals.empty()) {
            const auto& ni = mesh.normalIndices[prim];
            shading = unitOr(w * mesh.normals[ni[0]] + u * mesh.normals[ni[1]] + v * mesh.normals[ni[2]], geometric);
            if (dot(shading, geometric) < 0) shading = -shading;
        }
        const bool inverse = instance && instance->placed ? mesh.inverse != instance->inverse : mesh.inverse;
        if (inverse) {
            geometric = -geometric;
            shading = -shading;
        }
        hit.object = mesh.object ? mesh.object : instance->object;
        hit.primitive = prim;
        if (mesh.indexed) {
            // Weights of the IndexedMesh's own corners (a copy may have swapped 1 and 2).
            const std::array<double, 3> weights = mesh.swapped ? std::array<double, 3>{w, v, u}
                                                                : std::array<double, 3>{w, u, v};
            meshSurface(*mesh.indexed, std::get<Mesh>(hit.object->shape), prim, weights, hit);
            if (hit.hasUv) uvTangents(*mesh.indexed, prim, mesh.swapped, p0, p1, p2, hit);
        }
        frameUnit = instance && instance->placed ? instance->frameUnit
                    : mesh.extent > 0            ? frameUnitFor(mesh.extent)
                                                 : 0;
    }
    if (motion) {
        hit.point = motion->point(point);
        if (instance->placed) hit.restPoint = hit.point;
        else hit.restPoint = state.shifted ? point + state.frameOrigin : point;
        if (hit.hasUv && instance->placed) { // tangents, like restPoint, in the world
            hit.dpdu = motion->vector(hit.dpdu);
            hit.dpdv = motion->vector(hit.dpdv);
        }
        hit.geometricNormal = unitOrTowardOrigin(motion->normal(geometric));
        hit.shadingNormal = unitOr(motion->normal(shading), hit.geometricNormal);
    } else {
        hit.point = shiftedTop ? point + state.frameOrigin : point;
        hit.restPoint = hit.point;
        hit.geometricNormal = geometric;
        hit.shadingNormal = shading;
    }
    hit.frameOrigin = state.shifted ? state.frameOrigin : Vec3{};
    hit.frameUnit = frameUnit > 0 ? frameUnit : state.sceneUnit;
}

} // namespace accel

namespace {

// The rest of a short way's record of a hit at the top level (no instance,
// no uvs): `point` in the level's (perhaps shifted) frame, `normal` unit.
[[gnu::always_inline]] inline void topLevelRecord(const AcceleratorState& state, const Vec3& point,
                                                  const Vec3& normal, const Object* object, uint32_t primitive,
                                                  double frameUnit, Hit& hit) {
    hit.geometricNormal = hit.shadingNormal = normal;
    hit.object = object;
    hit.primitive = primitive;
    hit.hasUv = false;
    hit.uv = {};
    hit.cornerTextures = {};
    hit.instance = -1;
    hit.point = state.shifted ? point + state.frameOrigin : point;
    hit.restPoint = hit.point;
    hit.frameOrigin = state.shifted ? state.frameOrigin : Vec3{};
    hit.frameUnit = frameUnit > 0 ? frameUnit : state.sceneUnit;
}

// generalHit's result for a top-level analytic hit whose crossing the
// callback left in the query.
inline void topAnalyticHit(const AcceleratorState& state, const RayQuery& query, const Primitive& p, Hit& hit) {
    const SurfaceCrossing c = query.objectSpace ? levelCrossing(p, query.objectCrossing) : query.crossing;
    const Vec3& d = query.direction;
    hit.t = c.t;
    const double len = length(c.normal);
    topLevelRecord(state, query.origin + c.t * d,
                   len > 0 && std::isfinite(len) ? c.normal / len : unitOr(-d, {0, 1, 0}), c.object, 0, p.frameUnit,
                   hit);
}

// The primitive of Embree's hit (instID, primID, geomID) if topAnalyticHit
// makes its record: an analytic one at the top level whose crossing the
// callback left in the query. Else null.
inline const Primitive* shortWayPrimitive(const AcceleratorState& state, const RayQuery& query, unsigned instID,
                                          unsigned primID, unsigned geomID) {
    if (instID == RTC_INVALID_GEOMETRY_ID && query.hasCrossing && query.instID == RTC_INVALID_GEOMETRY_ID &&
        query.primID == primID && state.top.geometries[geomID].kind == GeometryKind::Analytic)
        return &state.top.primitives[primID];
    return nullptr;
}

// generalHit's result for triangle `prim` of a plain mesh at the top level
// (topTriangleMesh), Embree's hit at distance tfar and barycentrics (u, v).
inline void topTriangleHit(const AcceleratorState& state, const RayQuery& query, const MeshRecord& mesh,
                           uint32_t prim, double tfar, double u, double v, Hit& hit) {
    const auto& tri = mesh.triangles[prim];
    const Vec3 &p0 = mesh.vertices[tri[0]], &p1 = mesh.vertices[tri[1]], &p2 = mesh.vertices[tri[2]];
    const Vec3& d = query.direction;
    hit.t = tfar;
    resolveTriangleHit(query.origin, d, p0, p1, p2, hit.t, u, v);
    const double w = 1 - u - v;
    const Vec3 point = w * p0 + u * p1 + v * p2;
    const Vec3 winding = cross(p1 - p0, p2 - p0);
    const double len = length(winding);
    // A degenerate triangle has no winding normal: face the ray instead of NaN.
    const Vec3 geometric = len > 0 && std::isfinite(len) ? winding / len : unitOr(-d, {0, 1, 0});
    topLevelRecord(state, point, mesh.inverse ? -geometric : geometric, mesh.object, prim,
                   mesh.extent > 0 ? frameUnitFor(mesh.extent) : 0, hit);
}

// The mesh of Embree's hit if topTriangleHit makes its record: a triangle mesh
// at the top level with its own level-space copy and neither normals, uvs nor
// corner textures (a box, a plain mesh). Else null.
inline const MeshRecord* topTriangleMesh(const AcceleratorState& state, unsigned instID, unsigned geomID) {
    if (instID != RTC_INVALID_GEOMETRY_ID) return nullptr;
    const GeometryRef& ref = state.top.geometries[geomID];
    if (ref.kind != GeometryKind::Mesh) return nullptr;
    const MeshRecord& mesh = state.top.meshes[ref.index];
    return !mesh.vertices.empty() && mesh.normals.empty() && !mesh.indexed && mesh.object ? &mesh : nullptr;
}

// accel::hitFromEmbree, inline in the queries.
inline void hitRecord(const AcceleratorState& state, RayQuery& query, const RTCRayHit& rayhit, Hit& hit) {
    if (const Primitive* p = shortWayPrimitive(state, query, rayhit.hit.instID[0], rayhit.hit.primID, rayhit.hit.geomID)) {
        topAnalyticHit(state, query, *p, hit);
        return;
    }
    if (const MeshRecord* mesh = topTriangleMesh(state, rayhit.hit.instID[0], rayhit.hit.geomID)) {
        topTriangleHit(state, query, *mesh, rayhit.hit.primID, rayhit.ray.tfar, rayhit.hit.u, rayhit.hit.v, hit);
        return;
    }
    generalHit(state, query, rayhit, hit);
}

} // namespace

void accel::hitFromEmbree(const AcceleratorState& state, RayQuery& query, const RTCRayHit& rayhit, Hit& hit) {
    hitRecord(state, query, rayhit, hit);
}

bool Accelerator::intersect(const Ray& ray, Hit& hit) const {
    if (!traceable(ray, *impl_)) [[unlikely]] {
        ++impl_->untraceable;
        return false;
    }
    RayQuery query(*impl_, ray.origin, ray.direction);
    RTCRayHit rayhit;
    fillRay(ray, *impl_, rayhit.ray, impl_->swept ? rayMask(ray, *impl_, false) : 0xFFFFFFFFu);
    rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(impl_->top.scene, &query.context, &rayhit);
    impl_->device.throwIfFailed("tracing a ray");
    if (rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    hitRecord(*impl_, query, rayhit, hit);
    return true;
}

void Accelerator::intersectPacket(const Ray* rays, int count, Hit* hits, bool* found) const {
    static_assert(kPacketSize == 8, "rtcIntersect8 traces the packet");
    if (count <= 1) { // nothing to share
        if (count == 1) found[0] = intersect(rays[0], hits[0]);
        return;
    }
    count = std::min(count, kPacketSize);
    alignas(32) RTCRayHit8 packet;
    if (!fillPacket(rays, count, *impl_, 0xFFFFFFFFu, packet.ray)) [[unlikely]] { // some ray beyond Embree's range
        for (int i = 0; i < count; ++i) found[i] = intersect(rays[i], hits[i]);
        return;
    }
    if (impl_->swept)
        for (int i = 0; i < count; ++i) packet.ray.mask[i] = rayMask(rays[i], *impl_, false);
    // Each ray keeps its own query (its double-precision ray and crossing); the
    // callbacks find it by the ray's id through the first query's context.
    // Built in place for the rays there are (a zeroed array of 8 costs more).
    static_assert(std::is_trivially_destructible_v<RayQuery>, "the queries are never destroyed");
    alignas(RayQuery) unsigned char storage[kPacketSize][sizeof(RayQuery)];
    RayQuery* lanes[kPacketSize];
    for (int i = 0; i < count; ++i) lanes[i] = new (storage[i]) RayQuery(*impl_, rays[i].origin, rays[i].direction);
    lanes[0]->lanes = lanes;
    lanes[0]->context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    alignas(32) int valid[kPacketSize];
    for (int i = 0; i < kPacketSize; ++i) {
        valid[i] = i < count ? -1 : 0;
        packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
        packet.hit.primID[i] = RTC_INVALID_GEOMETRY_ID;
        packet.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect8(valid, impl_->top.scene, &lanes[0]->context, &packet);
    impl_->device.throwIfFailed("tracing a ray packet");
    for (int i = 0; i < count; ++i) {
        found[i] = packet.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID;
        if (!found[i]) continue;
        // hitRecord, reading the lane in place where it takes the short way.
        if (const Primitive* p = shortWayPrimitive(*impl_, *lanes[i], packet.hit.instID[0][i], packet.hit.primID[i],
                                                   packet.hit.geomID[i])) {
            topAnalyticHit(*impl_, *lanes[i], *p, hits[i]);
            continue;
        }
        if (const MeshRecord* mesh = topTriangleMesh(*impl_, packet.hit.instID[0][i], packet.hit.geomID[i])) {
            topTriangleHit(*impl_, *lanes[i], *mesh, packet.hit.primID[i], packet.ray.tfar[i], packet.hit.u[i],
                           packet.hit.v[i], hits[i]);
            continue;
        }
        // Lane i as the single-ray record generalHit reads.
        RTCRayHit rayhit;
        rayhit.ray.time = packet.ray.time[i];
        rayhit.ray.tfar = packet.ray.tfar[i];
        rayhit.hit.Ng_x = packet.hit.Ng_x[i];
        rayhit.hit.Ng_y = packet.hit.Ng_y[i];
        rayhit.hit.Ng_z = packet.hit.Ng_z[i];
        rayhit.hit.u = packet.hit.u[i];
        rayhit.hit.v = packet.hit.v[i];
        rayhit.hit.primID = packet.hit.primID[i];
        rayhit.hit.geomID = packet.hit.geomID[i];
        rayhit.hit.instID[0] = packet.hit.instID[0][i];
        generalHit(*impl_, *lanes[i], rayhit, hits[i]);
    }
}

// Shadow rays in a scene with moving objects carry their double-precision
// query too: an analytic shape inside a moving object is then solved on the
// ray moved into its level in double (RayQuery::levelRay), the same surface
// the camera ray's hit was solved on. Embree's own float transform of the ray
// lands up to ~1e-5 away from that surface, more than the origin offset
// (offsetOrigin), and a sphere turning about a far pivot shadowed half of
// itself. Other scenes' shadow rays take Embree's ray as they are.
namespace {

// occluded(), and with `crossed` (one flag) occludedOpaque()'s query
// (QueryContext::crossedTransmitter).
bool occludedQuery(const AcceleratorState& state, const Ray& ray, uint8_t* crossed) {
    if (!traceable(ray, state)) [[unlikely]] {
        const Ray shorter = shortened(ray);
        if (traceable(shorter, state)) return occludedQuery(state, shorter, crossed);
        ++state.untraceable;
        return false;
    }
    RTCRay r;
    const unsigned mask = state.swept ? rayMask(ray, state, true) : kShadowMask;
    fillRay(ray, state, r, mask);
    // A compact mesh's still instance holds only triangles, and a ray without
    // the one moving object's bit never reaches its level: neither needs the query.
    if (state.anyMotion && (!state.swept || (mask & kSweptBit))) {
        RayQuery query(state, ray.origin, ray.direction);
        query.crossedTransmitter = crossed;
        rtcOccluded1(state.top.scene, &query.context, &r);
    } else {
        QueryContext context;
        rtcInitIntersectContext(&context.context);
        context.crossedTransmitter = crossed;
        rtcOccluded1(state.top.scene, &context.context, &r);
    }
    state.device.throwIfFailed("tracing a shadow ray");
    return r.tfar < 0;
}

// occludedPacket, and with `crossed` (kPacketSize flags, by lane) the query of occludedOpaquePacket.
void occludedPacketQuery(const AcceleratorState& state, const Ray* rays, int count, bool* blocked, uint8_t* crossed) {
    static_assert(Accelerator::kPacketSize == 8, "rtcOccluded8 traces the packet");
    if (count <= 1) { // nothing to share
        if (count == 1) blocked[0] = occludedQuery(state, rays[0], crossed);
        return;
    }
    count = std::min(count, Accelerator::kPacketSize);
    alignas(32) RTCRay8 packet;
    if (!fillPacket(rays, count, state, kShadowMask, packet)) [[unlikely]] { // some ray beyond Embree's range
        for (int i = 0; i < count; ++i) blocked[i] = occludedQuery(state, rays[i], crossed ? crossed + i : nullptr);
        return;
    }
    bool reachesMotion = state.anyMotion && !state.swept;
    if (state.swept)
        for (int i = 0; i < count; ++i) {
            packet.mask[i] = rayMask(rays[i], state, true);
            reachesMotion |= (packet.mask[i] & kSweptBit) != 0;
        }
    // With moving objects each ray keeps its double-precision query, found by
    // its id through the first query's context (occluded; intersectPacket).
    static_assert(std::is_trivially_destructible_v<RayQuery>, "the queries are never destroyed");
    alignas(RayQuery) unsigned char storage[Accelerator::kPacketSize][sizeof(RayQuery)];
    RayQuery* lanes[Accelerator::kPacketSize];
    QueryContext plain;
    RTCIntersectContext* context = &plain.context;
    if (reachesMotion) { // a compact mesh's still instance holds only triangles (occluded)
        for (int i = 0; i < count; ++i) lanes[i] = new (storage[i]) RayQuery(state, rays[i].origin, rays[i].direction);
        lanes[0]->lanes = lanes;
        lanes[0]->crossedTransmitter = crossed;
        context = &lanes[0]->context;
    } else {
        rtcInitIntersectContext(&plain.context);
        plain.crossedTransmitter = crossed;
    }
    alignas(32) int valid[Accelerator::kPacketSize];
    for (int i = 0; i < Accelerator::kPacketSize; ++i) valid[i] = i < count ? -1 : 0;
    rtcOccluded8(valid, state.top.scene, context, &packet);
    state.device.throwIfFailed("tracing a shadow ray packet");
    for (int i = 0; i < count; ++i) blocked[i] = packet.tfar[i] < 0;
}

Accelerator::Occlusion occlusionOf(bool blocked, uint8_t crossed) {
    if (blocked) return Accelerator::Occlusion::Blocked;
    return crossed ? Accelerator::Occlusion::ThroughTransmitters : Accelerator::Occlusion::Clear;
}

} // namespace

bool Accelerator::occluded(const Ray& ray) const { return occludedQuery(*impl_, ray, nullptr); }

void Accelerator::occludedPacket(const Ray* rays, int count, bool* blocked) const {
    occludedPacketQuery(*impl_, rays, count, blocked, nullptr);
}

Accelerator::Occlusion Accelerator::occludedOpaque(const Ray& ray) const {
    uint8_t crossed = 0;
    const bool blocked = occludedQuery(*impl_, ray, impl_->transmitters ? &crossed : nullptr);
    return occlusionOf(blocked, crossed);
}

void Accelerator::occludedOpaquePacket(const Ray* rays, int count, Occlusion* out) const {
    count = std::clamp(count, 0, kPacketSize);
    bool blocked[kPacketSize];
    uint8_t crossed[kPacketSize] = {};
    occludedPacketQuery(*impl_, rays, count, blocked, impl_->transmitters ? crossed : nullptr);
    for (int i = 0; i < count; ++i) out[i] = occlusionOf(blocked[i], crossed[i]);
}

void Accelerator::installThreadBuffers(InstalledScratchSet& into) {
    for (auto install : {installShapeScratch, installAlgebraicScratch, installBlobScratch, installJuliaScratch,
                         installCrossingScratch})
        into.push_back(install());
}

bool Accelerator::hasMotion() const { return impl_->anyMotion; }

uint64_t Accelerator::untraceableRays() const { return impl_->untraceable.load(); }

Accelerator::MeshStats Accelerator::meshStats() const {
    MeshStats stats;
    stats.sharedMeshes = impl_->prototypes.size();
    for (const Instance& instance : impl_->instances)
        if (instance.placed) ++stats.placements;
    return stats;
}

Transform Accelerator::restToWorld(const Hit& hit, double time) const {
    if (hit.instance < 0 || size_t(hit.instance) >= impl_->instances.size()) return Transform();
    const Instance& instance = impl_->instances[size_t(hit.instance)];
    if (!instance.motion) return Transform();
    return instance.motion->at(std::fmin(1.0, std::fmax(0.0, time)));
}

void Accelerator::bounds(Vec3& lower, Vec3& upper) const {
    if (impl_->bounded) {
        lower = impl_->lower;
        upper = impl_->upper;
    } else {
        lower = upper = Vec3{};
    }
}

} // namespace drt
