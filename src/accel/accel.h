// The Embree wrapper: one device, one scene built from the scene model, and
// ray queries. All ray intersection in drt goes through here.
//
// Shapes: spheres, planes, cylinders, cones, discs, tori, the algebraic
// surfaces (polynomials, superellipsoids: algebraic_shapes.h) and extrusions
// (prism, text: extrusion_shape.h) are analytic Embree user geometry
// (intersected in object space in double precision, so any affine transform
// works); boxes, triangles and meshes are Embree triangles.
// Moving objects (Object::motion, scene/motion.h) become instances of their
// own sub-scene, built in their rest pose, with as many transform time steps
// as their path needs (accel/motion.h); static objects carry no time steps.
// Motion stands where it is written in an object's chain of transforms, so
// `translate -c motion { rotate y*360 } translate c` spins about c. A union
// whose members move is split into its members; a whole moving union is one
// instance. Motion inside merge, difference or intersection is not supported
// yet (RenderError).
//
// CSG: union children become separate geometry (Hit::object is the child
// inside Csg::children). Merge, difference and intersection are evaluated
// exactly along the ray (inside/outside classification of every analytic
// leaf, `inverse` honoured); meshes inside them are not supported yet.
//
// clipped_by (Object::clippedBy): a clipped analytic shape or CSG (and a
// clipped box, traced as an analytic shape) keeps only the crossings inside
// every clip; inside a merge, difference or intersection a clipped member's
// clips change its inside state without adding surfaces; a clipped static
// mesh is filtered by Embree's filter functions (moving: RenderError).
// Shadow rays see the same surfaces.
//
// Frame: a scene whose centre is farther from the origin than its size is
// traced in coordinates re-centred on its bounds (Hit::frameOrigin): geometry
// and ray origins are shifted in double before Embree rounds them to float, so
// a scene at 1e5 traces like one at the origin.
//
// Planes and polynomial surfaces get finite bounds of +-1e18 (Embree drops
// bounds beyond ~1.8e18).
#pragma once

#include "accel/thread_scratch.h"
#include "core/ray.h"
#include "core/vec.h"
#include "scene/scene.h"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace drt {

struct Hit {
    double t = 0;
    Vec3 point;            // world space
    Vec3 geometricNormal;  // world space, unit, facing out of the shape (not flipped to the ray)
    Vec3 shadingNormal;    // world space, unit, same side as geometricNormal (interpolated for meshes)
    const Object* object = nullptr;
    uint32_t primitive = 0; // triangle index within a mesh, else 0
    // The surface's uv coordinates (u, v, 0) where it has them (meshes with
    // uv vectors), for uv_mapping.
    bool hasUv = false;
    Vec3 uv;
    // With hasUv: how the surface point moves with u and with v (dP/du, dP/dv),
    // in the space of restPoint, for uv-mapped normals; zero where the
    // triangle's uvs are degenerate.
    Vec3 dpdu, dpdv;
    // A mesh triangle with textures of its own (Mesh::textures): the texture
    // of each corner (null: the object's) and the barycentric weight of each;
    // all null for every other hit.
    std::array<const Texture*, 3> cornerTextures{};
    std::array<double, 3> cornerWeights{};
    // Where offsetOrigin works, set by Accelerator::intersect (the defaults are
    // plain world space): Embree traces float coordinates relative to
    // frameOrigin, and frameUnit (a power of two, at most 1) is the size of the
    // object hit, which scales offsetOrigin's absolute offset near zero.
    Vec3 frameOrigin;
    double frameUnit = 1;
    // Where the surface point is in its object's rest pose (scene/motion.h):
    // textures move with their object, so they are evaluated here. The world
    // point for objects that do not move.
    Vec3 restPoint;
    // The moving object's instance (for restToWorld), or -1.
    int instance = -1;
};

class Accelerator {
public:
    // Throws RenderError (core/error.h) on Embree errors or invalid geometry.
    explicit Accelerator(const Scene& scene);
    // For rays that all have time `onlyTime` (a zero-length shutter): moving
    // objects are placed at that time in double precision (placementAt) and
    // built as static geometry, so the image is the static scene's at that
    // time bit for bit. Rays with another time see the objects at onlyTime.
    Accelerator(const Scene& scene, double onlyTime);
    // The accelerator keeps pointers into the scene (Hit::object, the shapes'
    // user data) for its whole life, so the scene must outlive it: building
    // one from a temporary does not compile.
    explicit Accelerator(Scene&& scene) = delete;
    Accelerator(Scene&& scene, double onlyTime) = delete;
    ~Accelerator();
    Accelerator(const Accelerator&) = delete;
    Accelerator& operator=(const Accelerator&) = delete;

    // Nearest hit with tMin < t < tMax. Thread-safe.
    bool intersect(const Ray& ray, Hit& hit) const;
    // The nearest hits of up to kPacketSize rays at once, traced as one Embree
    // packet (worth it for coherent rays: a pixel's camera rays). found[i] and
    // hits[i] are what intersect(rays[i], hits[i]) gives. Thread-safe.
    static constexpr int kPacketSize = 8;
    void intersectPacket(const Ray* rays, int count, Hit* hits, bool* found) const;
    // Any hit with tMin < t < tMax by an object that casts shadows. Thread-safe.
    bool occluded(const Ray& ray) const;
    // occluded() of up to kPacketSize rays at once, traced as one Embree
    // packet (rtcOccluded8; worth it for coherent rays: a pixel's shadow rays
    // to one light). blocked[i] is what occluded(rays[i]) gives. Thread-safe.
    void occludedPacket(const Ray* rays, int count, bool* blocked) const;
    // occluded() told apart by what the surfaces on the segment do with light
    // (scene/light_through.h): Blocked if one that casts shadows and lets no
    // light through lies on it; else ThroughTransmitters if one that may let
    // light through does (the caller finds them and filters the light); else
    // Clear. One query, where telling them apart with occluded() takes the
    // nearest hits one by one. A scene whose shadow casters all let no light
    // through never answers ThroughTransmitters. Thread-safe.
    enum class Occlusion : uint8_t { Clear, Blocked, ThroughTransmitters };
    Occlusion occludedOpaque(const Ray& ray) const;
    // occludedOpaque() of up to kPacketSize rays at once, as occludedPacket.
    void occludedOpaquePacket(const Ray* rays, int count, Occlusion* out) const;

    // A ray origin just off the surface at `hit`, on the side `direction` points
    // to, robust at every scale (integer-ULP offset along the geometric normal,
    // Waechter and Binder, Ray Tracing Gems ch. 6, in Embree's frame, with the
    // near-zero absolute offset scaled to the object: Hit::frameUnit).
    // Inline (below): every shadow, reflected and refracted ray starts here.
    static Vec3 offsetOrigin(const Hit& hit, const Vec3& direction);
    // The same, one coordinate at a time: what offsetOrigin is on CPUs
    // without SSE2, and the reference its SSE2 form must equal to the bit.
    static Vec3 offsetOriginOneByOne(const Hit& hit, const Vec3& direction);

    // Compact meshes (Mesh::indexed) as built: distinct meshes with a BVH
    // of their own, and the objects placed as instances of them.
    struct MeshStats {
        size_t sharedMeshes = 0;
        size_t placements = 0;
    };
    MeshStats meshStats() const;

    // Installs the calling thread's scratch buffers of ray queries into
    // `into`, for as long as it holds them (accel/thread_scratch.h: without
    // them a thread's first CSG or listed-crossing query registers
    // thread_local destructors, which waits for any dlopen in progress).
    static void installThreadBuffers(InstalledScratchSet& into);

    // Embree takes a ray only if each coordinate of its origin (in the top
    // level's frame) and of its direction lies within +-kLargestCoordinate in
    // float; Debian's Embree asserts, ending the process, on any other. Such a
    // ray is not given to Embree: a shadow ray whose direction alone is too
    // long (a light very far away) is traced with its direction scaled down by
    // a power of two (the same points, exactly); any other meets nothing and
    // is counted here, for the render's warning.
    static constexpr double kLargestCoordinate = 1.8e18;
    uint64_t untraceableRays() const;

    // True if some object has Motion (the scene was built with time steps).
    bool hasMotion() const;
    // The map from a moving object's rest pose to the world at `time`, for a
    // hit on it (Hit::instance >= 0); the identity otherwise.
    Transform restToWorld(const Hit& hit, double time) const;
    // Bounding box of everything finite in the scene (planes excluded).
    void bounds(Vec3& lower, Vec3& upper) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Waechter and Binder, "A Fast and Robust Method for Avoiding Self-Intersection"
// (Ray Tracing Gems, ch. 6): move each float coordinate of the point by
// int(256 n_i) units in the last place, in the direction of n_i, so the offset
// grows with the coordinate's magnitude; coordinates within u/32 of zero, where
// ulps become tiny, move by the absolute amount u n_i / 65536 instead. Their
// u = 1 assumes objects of unit size; u = Hit::frameUnit scales it to the
// object hit (so a 1e-4 object is not pushed 15% of its size away), and the
// coordinates are Embree's (world minus Hit::frameOrigin), whose float
// rounding is what the offset must beat. n is the geometric normal turned to
// the side the new ray leaves on.
//
// With SSE2 the three coordinates are offset at once, in the lanes of one
// register: the same float operations in the same order (no FMA: the build
// targets baseline x86-64), so the same bits as the scalar loop, which stays
// for other CPUs (Accel.OffsetOriginIsTheScalarOnesToTheBit).
namespace accel::detail {

// What both forms of offsetOrigin start from: the point in Embree's frame,
// the normal turned to the side the ray leaves on, and the scales.
struct OriginOffset {
    float nearZero, absoluteScale;
    bool shifted;
    Vec3 point, n;
};

inline OriginOffset originOffset(const Hit& hit, const Vec3& direction) {
    const double unit = hit.frameUnit > 0 && hit.frameUnit <= 1 ? hit.frameUnit : 1.0;
    const bool shifted = hit.frameOrigin.x != 0 || hit.frameOrigin.y != 0 || hit.frameOrigin.z != 0;
    return {float(unit / 32.0), float(unit / 65536.0), shifted,
            shifted ? hit.point - hit.frameOrigin : hit.point,
            dot(hit.geometricNormal, direction) < 0 ? -hit.geometricNormal : hit.geometricNormal};
}

inline constexpr float kUlpScale = 256.0f;

} // namespace accel::detail

inline Vec3 Accelerator::offsetOriginOneByOne(const Hit& hit, const Vec3& direction) {
    const accel::detail::OriginOffset o = accel::detail::originOffset(hit, direction);
    Vec3 out;
    for (int i = 0; i < 3; ++i) {
        const float p = float(o.point[i]);
        const float ni = float(o.n[i]);
        if (std::fabs(p) < o.nearZero) {
            out[i] = p + o.absoluteScale * ni;
            continue;
        }
        // For positive floats a larger bit pattern is a larger value; for
        // negative ones, a larger magnitude. So step toward +n_i accordingly.
        const int32_t ulps = static_cast<int32_t>(accel::detail::kUlpScale * ni);
        const int32_t bits = std::bit_cast<int32_t>(p);
        out[i] = std::bit_cast<float>(bits + (p < 0 ? -ulps : ulps));
    }
    // A float plus the frame origin is exact in double unless the float is
    // below the origin's ulp (then it is rounded to that ulp, ~1e-16 |origin|).
    return o.shifted ? out + hit.frameOrigin : out;
}

inline Vec3 Accelerator::offsetOrigin(const Hit& hit, const Vec3& direction) {
#if defined(__SSE2__)
    const accel::detail::OriginOffset o = accel::detail::originOffset(hit, direction);
    const Vec3& point = o.point;
    const Vec3& n = o.n;
    // Lanes x, y, z, z.
    const __m128 p = _mm_movelh_ps(_mm_cvtpd_ps(_mm_set_pd(point.y, point.x)), _mm_cvtpd_ps(_mm_set1_pd(point.z)));
    const __m128 ni = _mm_movelh_ps(_mm_cvtpd_ps(_mm_set_pd(n.y, n.x)), _mm_cvtpd_ps(_mm_set1_pd(n.z)));
    const __m128 magnitude = _mm_and_ps(p, _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff)));
    const __m128 near = _mm_cmplt_ps(magnitude, _mm_set1_ps(o.nearZero)); // fabs(p) < nearZero
    const __m128 absolute = _mm_add_ps(p, _mm_mul_ps(_mm_set1_ps(o.absoluteScale), ni));
    // As in offsetOriginOneByOne: -ulps (ulps ^ -1) - (-1) where p < 0.
    const __m128i ulps = _mm_cvttps_epi32(_mm_mul_ps(_mm_set1_ps(accel::detail::kUlpScale), ni));
    const __m128i negative = _mm_castps_si128(_mm_cmplt_ps(p, _mm_setzero_ps()));
    const __m128i step = _mm_sub_epi32(_mm_xor_si128(ulps, negative), negative);
    const __m128 stepped = _mm_castsi128_ps(_mm_add_epi32(_mm_castps_si128(p), step));
    const __m128 moved = _mm_or_ps(_mm_and_ps(near, absolute), _mm_andnot_ps(near, stepped));
    alignas(16) double xy[2];
    _mm_store_pd(xy, _mm_cvtps_pd(moved));
    const Vec3 out{xy[0], xy[1], _mm_cvtsd_f64(_mm_cvtps_pd(_mm_movehl_ps(moved, moved)))};
    return o.shifted ? out + hit.frameOrigin : out;
#else
    return offsetOriginOneByOne(hit, direction);
#endif
}

} // namespace drt
