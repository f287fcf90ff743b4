// Ray queries: Embree finds the nearest primitive in float; the hit is then
// rebuilt in double (analytic shapes re-solved, triangles intersected again)
// so that the point lies on the surface to double precision, which is what
// offsetOrigin needs to avoid self-intersection.
#include "accel/accel_impl.h"
#include "render/render.h"

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>

namespace drt {

using namespace accel;

Accelerator::Accelerator(const Scene& scene) : impl_(std::make_unique<Impl>()) { buildScene(scene, *impl_); }

Accelerator::~Accelerator() = default;

namespace {

// Float interval limits that never widen [tMin, tMax].
float floatAtLeast(double v) {
    if (v >= double(FLT_MAX)) return INFINITY;
    const float f = float(v);
    return double(f) < v ? std::nextafter(f, INFINITY) : f;
}
float floatAtMost(double v) {
    if (v >= double(FLT_MAX)) return INFINITY;
    const float f = float(v);
    return double(f) > v ? std::nextafter(f, -INFINITY) : f;
}

void fillRay(const Ray& ray, RTCRay& r, unsigned mask) {
    r.org_x = float(ray.origin.x);
    r.org_y = float(ray.origin.y);
    r.org_z = float(ray.origin.z);
    r.tnear = std::fmax(0.0f, floatAtLeast(ray.tMin));
    r.dir_x = float(ray.direction.x);
    r.dir_y = float(ray.direction.y);
    r.dir_z = float(ray.direction.z);
    r.time = float(std::fmin(1.0, std::fmax(0.0, ray.time)));
    r.tfar = floatAtMost(ray.tMax);
    r.mask = mask;
    r.id = 0;
    r.flags = 0;
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
    if (std::fabs(tt - t) > 1e-3 * std::fmax(1.0, std::fabs(t))) return;
    u = std::fmax(0.0, uu);
    v = std::fmax(0.0, vv);
    if (u + v > 1) {
        const double sum = u + v;
        u /= sum;
        v /= sum;
    }
    t = tt;
}

} // namespace

bool Accelerator::intersect(const Ray& ray, Hit& hit) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rayhit;
    fillRay(ray, rayhit.ray, 0xFFFFFFFFu);
    rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(impl_->top.scene, &context, &rayhit);
    impl_->device.throwIfFailed("tracing a ray");
    if (rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;

    // Find the level the hit geometry lives in and the ray in that level's space.
    const Level* level = &impl_->top;
    std::optional<Transform> motion;
    if (rayhit.hit.instID[0] != RTC_INVALID_GEOMETRY_ID) {
        const Instance& instance = impl_->instances[impl_->top.geometries[rayhit.hit.instID[0]].index];
        level = instance.level.get();
        motion = instance.motion.at(rayhit.ray.time);
    }
    const Vec3 o = motion ? motion->inversePoint(ray.origin) : ray.origin;
    const Vec3 d = motion ? motion->inverseVector(ray.direction) : ray.direction;
    const Vec3 towardOrigin = unitOr(-d, {0, 1, 0}); // normal of last resort

    const GeometryRef& ref = level->geometries[rayhit.hit.geomID];
    const double embreeT = rayhit.ray.tfar;
    Vec3 point, geometric, shading;
    if (ref.kind == GeometryKind::Analytic) {
        const Primitive& p = level->primitives[rayhit.hit.primID];
        SurfaceCrossing c;
        if (!closestCrossingTo(p, o, d, embreeT, c)) {
            c.t = embreeT;
            c.normal = {rayhit.hit.Ng_x, rayhit.hit.Ng_y, rayhit.hit.Ng_z};
            c.object = p.object;
        }
        hit.t = c.t;
        point = o + c.t * d;
        geometric = shading = unitOr(c.normal, towardOrigin);
        hit.object = c.object;
        hit.primitive = 0;
    } else {
        const MeshRecord& mesh = level->meshes[ref.index];
        const auto& tri = mesh.triangles[rayhit.hit.primID];
        const Vec3 &p0 = mesh.vertices[tri[0]], &p1 = mesh.vertices[tri[1]], &p2 = mesh.vertices[tri[2]];
        double u = rayhit.hit.u, v = rayhit.hit.v;
        hit.t = embreeT;
        resolveTriangleHit(o, d, p0, p1, p2, hit.t, u, v);
        const double w = 1 - u - v;
        point = w * p0 + u * p1 + v * p2;
        // A degenerate triangle has no winding normal: face the ray instead of NaN.
        geometric = unitOr(cross(p1 - p0, p2 - p0), towardOrigin);
        shading = geometric;
        if (!mesh.normals.empty()) {
            const auto& ni = mesh.normalIndices[rayhit.hit.primID];
            shading = unitOr(w * mesh.normals[ni[0]] + u * mesh.normals[ni[1]] + v * mesh.normals[ni[2]], geometric);
            if (dot(shading, geometric) < 0) shading = -shading;
        }
        if (mesh.inverse) {
            geometric = -geometric;
            shading = -shading;
        }
        hit.object = mesh.object;
        hit.primitive = rayhit.hit.primID;
    }
    if (motion) {
        hit.point = motion->point(point);
        hit.geometricNormal = unitOr(motion->normal(geometric), towardOrigin);
        hit.shadingNormal = unitOr(motion->normal(shading), hit.geometricNormal);
    } else {
        hit.point = point;
        hit.geometricNormal = geometric;
        hit.shadingNormal = shading;
    }
    return true;
}

bool Accelerator::occluded(const Ray& ray) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay r;
    fillRay(ray, r, kShadowMask);
    rtcOccluded1(impl_->top.scene, &context, &r);
    impl_->device.throwIfFailed("tracing a shadow ray");
    return r.tfar < 0;
}

// Waechter and Binder, "A Fast and Robust Method for Avoiding Self-Intersection"
// (Ray Tracing Gems, ch. 6): move each float coordinate of the point by
// int(256 n_i) units in the last place, in the direction of n_i, so the offset
// grows with the coordinate's magnitude; coordinates within 1/32 of zero, where
// ulps become tiny, move by the absolute amount n_i / 65536 instead. n is the
// geometric normal turned to the side the new ray leaves on.
Vec3 Accelerator::offsetOrigin(const Hit& hit, const Vec3& direction) {
    constexpr float kNearZero = 1.0f / 32.0f;
    constexpr float kAbsoluteScale = 1.0f / 65536.0f;
    constexpr float kUlpScale = 256.0f;
    const Vec3 n = dot(hit.geometricNormal, direction) < 0 ? -hit.geometricNormal : hit.geometricNormal;
    Vec3 out;
    for (int i = 0; i < 3; ++i) {
        const float p = float(hit.point[i]);
        const float ni = float(n[i]);
        if (std::fabs(p) < kNearZero) {
            out[i] = p + kAbsoluteScale * ni;
            continue;
        }
        // For positive floats a larger bit pattern is a larger value; for
        // negative ones, a larger magnitude. So step toward +n_i accordingly.
        const int32_t ulps = static_cast<int32_t>(kUlpScale * ni);
        const int32_t bits = std::bit_cast<int32_t>(p);
        out[i] = std::bit_cast<float>(bits + (p < 0 ? -ulps : ulps));
    }
    return out;
}

bool Accelerator::hasMotion() const { return !impl_->instances.empty(); }

void Accelerator::bounds(Vec3& lower, Vec3& upper) const {
    if (impl_->bounded) {
        lower = impl_->lower;
        upper = impl_->upper;
    } else {
        lower = upper = Vec3{};
    }
}

} // namespace drt
