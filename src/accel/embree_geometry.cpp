// The Embree side of the build: the device with its error callback, the user
// geometry callbacks for analytic primitives, and triangle geometry.
#include "accel/accel_impl.h"
#include "core/error.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#if defined(__x86_64__)
#include <immintrin.h>
#endif
#include <string>
#include <type_traits>

namespace drt::accel {

// ---------------------------------------------------------------- device

EmbreeDevice::EmbreeDevice() {
    device_ = rtcNewDevice(nullptr);
    if (!device_)
        throw RenderError("Embree error: cannot create a device (error code " +
                          std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))) + ")");
    rtcSetDeviceErrorFunction(device_, &EmbreeDevice::onError, this);
}

EmbreeDevice::~EmbreeDevice() { rtcReleaseDevice(device_); }

static const char* errorName(RTCError code) {
    switch (code) {
    case RTC_ERROR_NONE: return "none";
    case RTC_ERROR_UNKNOWN: return "unknown";
    case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
    case RTC_ERROR_CANCELLED: return "cancelled";
    }
    return "unrecognised";
}

void EmbreeDevice::onError(void* self, RTCError code, const char* message) {
    auto* device = static_cast<EmbreeDevice*>(self);
    std::lock_guard lock(device->mutex_);
    if (device->failed_.load()) return; // keep the first error: later ones tend to be consequences
    device->message_ = std::string(errorName(code)) + ": " + (message ? message : "(no message)");
    device->failed_.store(true);
}

void EmbreeDevice::throwIfFailed(const char* what) const {
    if (!failed()) return;
    std::lock_guard lock(mutex_);
    throw RenderError("Embree error (" + message_ + ") while " + what);
}

Level::~Level() { release(); }

void Level::release() {
    if (scene) rtcReleaseScene(scene);
    scene = nullptr;
    primitives.clear();
    meshes.clear();
    geometries.clear();
}

// ---------------------------------------------------------------- user geometry
// Embree hands the callbacks the ray in the space of the scene the geometry is
// in: for a moving object's sub-scene, the ray already transformed by the
// inverse instance transform at the ray's time. The intersect callback solves
// with the double-precision ray of its RayQuery instead (the same ray, unrounded).
// Camera rays are traced in packets (rtcIntersect8), so a callback may get N
// rays at once: each valid one is solved on its own, and its query is found by
// the ray's id (RayQuery::lane), whatever N Embree chose.

// Bounds must stay conservative after rounding to float.
static float roundDown(double v) {
    const float f = float(v);
    return double(f) > v ? std::nextafter(f, -INFINITY) : f;
}
static float roundUp(double v) {
    const float f = float(v);
    return double(f) < v ? std::nextafter(f, INFINITY) : f;
}

static void boundsCallback(const RTCBoundsFunctionArguments* args) {
    const auto* level = static_cast<const Level*>(args->geometryUserPtr);
    const Primitive& p = level->primitives[args->primID];
    RTCBounds* b = args->bounds_o;
    b->lower_x = roundDown(p.lower.x);
    b->lower_y = roundDown(p.lower.y);
    b->lower_z = roundDown(p.lower.z);
    b->upper_x = roundUp(p.upper.x);
    b->upper_y = roundUp(p.upper.y);
    b->upper_z = roundUp(p.upper.z);
}

uint64_t nextAcceleratorGeneration() {
    static std::atomic<uint64_t> next{1};
    return next.fetch_add(1, std::memory_order_relaxed);
}

// A moving object's level -> world transform at `time`, kept per thread. The
// rays of one camera sample (camera, shadow, reflected, refracted) share its
// time, so each moving object's transform is interpolated once per sample
// rather than once per ray; the result is the same to the bit. The slot is a
// hash of the object and the time: a packet's camera rays carry 8 sample
// times, and each sample's later rays must still find its own.
static const Transform& cachedToWorld(const AcceleratorState& state, unsigned index, double time) {
    struct Entry {
        uint64_t generation = 0; // no accelerator has generation 0
        unsigned index = 0;
        double time = 0;
        Transform toWorld;
    };
    constexpr int kSlotBits = 5;
    // Trivially destructible: no destructor to register (Accelerator::prepareThread).
    static_assert(std::is_trivially_destructible_v<Entry>);
    thread_local std::array<Entry, size_t(1) << kSlotBits> cache;
    const uint64_t key = (uint64_t(index) * 0x9e3779b97f4a7c15ULL) ^ (std::bit_cast<uint64_t>(time) * 0xff51afd7ed558ccdULL);
    Entry& e = cache[size_t(key >> (64 - kSlotBits))];
    if (e.generation != state.generation || e.index != index || e.time != time) {
        e.toWorld = state.instances[index].toWorld(time);
        e.generation = state.generation;
        e.index = index;
        e.time = time;
    }
    return e.toWorld;
}

void RayQuery::instanceRay(unsigned instID, double time, Vec3& o, Vec3& d) {
    if (instance != instID) {
        instance = instID;
        instanceToWorld.emplace(cachedToWorld(*state, state->top.geometries[instID].index, time));
        instanceOrigin = instanceToWorld->inversePoint(worldOrigin);
        instanceDirection = instanceToWorld->inverseVector(direction);
    }
    o = instanceOrigin;
    d = instanceDirection;
}

// One ray (lane i of the callback's N) against the primitive, in the level's
// space (o, d): if it crosses it within the ray's interval, the crossing goes
// into the ray's query and Embree's hit record. Inline, and N a constant for
// the packets' N = 8 (intersectCallback): Embree's lanes are then at fixed
// offsets.
[[gnu::always_inline]] inline void intersectLane(const RTCIntersectFunctionNArguments* args, unsigned N,
                                                 const Primitive& p, unsigned i, RayQuery& query, unsigned instID,
                                                 const Vec3& o, const Vec3& d) {
    RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, N);
    const float tnear = RTCRayN_tnear(ray, N, i);
    float& tfar = RTCRayN_tfar(ray, N, i);
    Vec3 normal; // level or object space: only for Embree's record, the hit is rebuilt from the query
    if (p.plain) {
        Crossing& c = query.objectCrossing; // written only if found
        if (!firstPlainCrossing(p, o, d, tnear, tfar, c)) return;
        tfar = float(c.t);
        normal = c.normal;
    } else {
        SurfaceCrossing c;
        if (!nearestCrossing(p, o, d, tnear, tfar, c)) return;
        query.crossing = c;
        tfar = float(c.t);
        normal = c.normal;
    }
    query.hasCrossing = true;
    query.objectSpace = p.plain;
    query.primID = args->primID;
    query.instID = instID;
    RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, N);
    RTCHitN_Ng_x(hit, N, i) = float(normal.x);
    RTCHitN_Ng_y(hit, N, i) = float(normal.y);
    RTCHitN_Ng_z(hit, N, i) = float(normal.z);
    RTCHitN_u(hit, N, i) = RTCHitN_v(hit, N, i) = 0;
    RTCHitN_primID(hit, N, i) = args->primID;
    RTCHitN_geomID(hit, N, i) = args->geomID;
    RTCHitN_instID(hit, N, i, 0) = instID;
}

// The valid lanes of the callback's N (kN, or args->N if kN is 0). At the top
// level a ray's query holds it as is; in a moving object's level it is moved
// there (RayQuery::levelRay).
template <unsigned kN>
void intersectLanes(const RTCIntersectFunctionNArguments* args, const Primitive& p) {
    const unsigned N = kN ? kN : args->N;
    RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, N);
    RayQuery& first = RayQuery::of(args->context);
    const unsigned instID = args->context->instID[0];
    for (unsigned i = 0; i < N; ++i) {
        if (!args->valid[i]) continue;
        RayQuery& query = first.lane(RTCRayN_id(ray, N, i));
        if (instID == RTC_INVALID_GEOMETRY_ID) {
            intersectLane(args, N, p, i, query, instID, query.origin, query.direction);
        } else {
            Vec3 o, d;
            query.levelRay(instID, RTCRayN_time(ray, N, i), o, d);
            intersectLane(args, N, p, i, query, instID, o, d);
        }
    }
}

// intersectLanes for N rays (a packet of 8, or one) at the top level and a
// plain primitive without a transform whose first crossing `solve` finds (a
// sphere or a plane: what most rays meet): the same crossings, with the
// shape's values held in `solve` and the per-lane tests of intersectLanes made
// once.
template <unsigned N, class Solve>
[[gnu::always_inline]] inline void intersectTopLanes(const RTCIntersectFunctionNArguments* args, Solve solve) {
    RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, N);
    RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, N);
    RayQuery& first = RayQuery::of(args->context);
    RayQuery* const* const lanes = first.lanes;
    const unsigned primID = args->primID, geomID = args->geomID;
    const int* const valid = args->valid;
    for (unsigned i = 0; i < N; ++i) {
        if (!valid[i]) continue;
        RayQuery& query = lanes ? *lanes[RTCRayN_id(ray, N, i)] : first;
        float& tfar = RTCRayN_tfar(ray, N, i);
        Crossing c;
        if (!solve(query.origin, query.direction, RTCRayN_tnear(ray, N, i), tfar, c)) continue;
        query.objectCrossing = c;
        tfar = float(c.t);
        query.hasCrossing = true;
        query.objectSpace = true;
        query.primID = primID;
        query.instID = RTC_INVALID_GEOMETRY_ID;
        RTCHitN_Ng_x(hit, N, i) = float(c.normal.x);
        RTCHitN_Ng_y(hit, N, i) = float(c.normal.y);
        RTCHitN_Ng_z(hit, N, i) = float(c.normal.z);
        RTCHitN_u(hit, N, i) = RTCHitN_v(hit, N, i) = 0;
        RTCHitN_primID(hit, N, i) = primID;
        RTCHitN_geomID(hit, N, i) = geomID;
        RTCHitN_instID(hit, N, i, 0) = RTC_INVALID_GEOMETRY_ID;
    }
}

// The short way's solvers: a sphere's and a plane's first crossing, from
// their values held in the solver.
struct SphereSolver {
    Vec3 center;
    double radius;
    bool operator()(const Vec3& o, const Vec3& d, double tMin, double tMax, Crossing& c) const {
        return firstSphereCrossing(center, radius, o, d, tMin, tMax, c);
    }
};
struct PlaneSolver {
    Vec3 normal;
    double distance;
    bool operator()(const Vec3& o, const Vec3& d, double tMin, double tMax, Crossing& c) const {
        return firstPlaneCrossing(normal, distance, o, d, tMin, tMax, c);
    }
};

// The short way of the callbacks: a plain primitive without a transform
// whose first crossing has a solver of its own (a sphere or a plane) calls
// run(solver) and returns true; any other returns false.
template <class Run>
[[gnu::always_inline]] inline bool withShortWay(const Primitive& p, Run run) {
    if (!p.plain || !p.identity) return false;
    if (p.shape.kind == ShapeKind::Sphere) run(SphereSolver{p.shape.center, p.shape.radius});
    else if (p.shape.kind == ShapeKind::Plane) run(PlaneSolver{p.shape.normal, p.shape.distance});
    else return false;
    return true;
}

// A callback's lanes: a packet of 8 or a single ray (shadow and secondary
// rays) at the top level takes the short way where the primitive has one
// (top(n, solve)); the rest the general way (lanes(n)); n an
// integral_constant: 8, 1, or 0 for Embree's N.
template <class Args, class Top, class Lanes>
[[gnu::always_inline]] inline void runLanes(const Args* args, const Primitive& p, Top top, Lanes lanes) {
    const auto run = [&](auto n) {
        if (args->context->instID[0] == RTC_INVALID_GEOMETRY_ID &&
            withShortWay(p, [&](auto solve) { top(n, solve); }))
            return;
        lanes(n);
    };
    if (args->N == 8) return run(std::integral_constant<unsigned, 8>{});
    if (args->N == 1) return run(std::integral_constant<unsigned, 1>{});
    lanes(std::integral_constant<unsigned, 0>{});
}

static void intersectCallback(const RTCIntersectFunctionNArguments* args) {
    const auto* level = static_cast<const Level*>(args->geometryUserPtr);
    const Primitive& p = level->primitives[args->primID];
    runLanes(args, p, [args](auto n, auto solve) { intersectTopLanes<decltype(n)::value>(args, solve); },
             [args, &p](auto n) { intersectLanes<decltype(n)::value>(args, p); });
}

// Inside a moving object the ray comes from its query, moved into this level
// in double (Accelerator::occluded); at the top level it is Embree's. N as in
// intersectLanes.
template <unsigned kN>
void occludedLanes(const RTCOccludedFunctionNArguments* args, const Primitive& p) {
    const unsigned N = kN ? kN : args->N;
    RTCRayN* ray = args->ray;
    const unsigned instID = args->context->instID[0];
    for (unsigned i = 0; i < N; ++i) {
        if (!args->valid[i]) continue;
        Vec3 o, d;
        if (instID != RTC_INVALID_GEOMETRY_ID) {
            RayQuery::of(args->context).lane(RTCRayN_id(ray, N, i)).levelRay(instID, RTCRayN_time(ray, N, i), o, d);
        } else {
            o = {RTCRayN_org_x(ray, N, i), RTCRayN_org_y(ray, N, i), RTCRayN_org_z(ray, N, i)};
            d = {RTCRayN_dir_x(ray, N, i), RTCRayN_dir_y(ray, N, i), RTCRayN_dir_z(ray, N, i)};
        }
        const float tnear = RTCRayN_tnear(ray, N, i);
        float& tfar = RTCRayN_tfar(ray, N, i);
        if (p.plain) { // any crossing blocks: no normal needed
            Crossing c;
            if (firstPlainCrossing(p, o, d, tnear, tfar, c)) tfar = -INFINITY;
            continue;
        }
        SurfaceCrossing c;
        if (nearestCrossing(p, o, d, tnear, tfar, c) && !c.object->noShadow) tfar = -INFINITY;
    }
}

#if defined(__SSE2__)
// occludedTopLanes of a packet of 8 against a sphere or a plane, two lanes an
// instruction: the solver's arithmetic, operation for operation (separate
// multiplies and adds, no FMA, IEEE division and square root), so each lane's
// answer is the one it gets alone. A lane is blocked where a root t has
// tnear < t < tfar and is finite; a negative discriminant's square root is
// NaN, whose roots fail those tests as the solver's early return does.
struct PacketLanes {
    const float *ox, *oy, *oz, *dx, *dy, *dz, *tnear;
    float* tfar;
    explicit PacketLanes(RTCRayN* ray)
        : ox(&RTCRayN_org_x(ray, 8, 0)), oy(&RTCRayN_org_y(ray, 8, 0)), oz(&RTCRayN_org_z(ray, 8, 0)),
          dx(&RTCRayN_dir_x(ray, 8, 0)), dy(&RTCRayN_dir_y(ray, 8, 0)), dz(&RTCRayN_dir_z(ray, 8, 0)),
          tnear(&RTCRayN_tnear(ray, 8, 0)), tfar(&RTCRayN_tfar(ray, 8, 0)) {}
    // Lanes i and i + 1 of a float array, widened to double.
    static __m128d pair(const float* v, int i) {
        return _mm_cvtps_pd(_mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(v + i))));
    }
    // Where the valid lanes i, i + 1 have a root in their interval: tfar = -inf.
    void block(const int* valid, int i, __m128d t0, __m128d t1) {
        const __m128d infinity = _mm_set1_pd(INFINITY);
        const __m128d magnitude = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffff));
        const __m128d near = pair(tnear, i), far = pair(tfar, i);
        const auto within = [&](__m128d t) {
            return _mm_and_pd(_mm_cmplt_pd(_mm_and_pd(t, magnitude), infinity),
                              _mm_and_pd(_mm_cmpgt_pd(t, near), _mm_cmplt_pd(t, far)));
        };
        const int hit = _mm_movemask_pd(_mm_or_pd(within(t0), within(t1)));
        if ((hit & 1) && valid[i]) tfar[i] = -INFINITY;
        if ((hit & 2) && valid[i + 1]) tfar[i + 1] = -INFINITY;
    }
};

// sphereRoots' t0 and t1 for lanes i, i + 1.
inline void occludeSphereLanes8(const RTCOccludedFunctionNArguments* args, const Vec3& center, double radius) {
    PacketLanes lanes(args->ray);
    const __m128d cx = _mm_set1_pd(center.x), cy = _mm_set1_pd(center.y), cz = _mm_set1_pd(center.z);
    const __m128d r2 = _mm_set1_pd(radius * radius);
    const __m128d sign = _mm_castsi128_pd(_mm_set1_epi64x(int64_t(0x8000000000000000ULL)));
    for (int i = 0; i < 8; i += 2) {
        if (!args->valid[i] && !args->valid[i + 1]) continue;
        const __m128d dx = PacketLanes::pair(lanes.dx, i), dy = PacketLanes::pair(lanes.dy, i),
                      dz = PacketLanes::pair(lanes.dz, i);
        const __m128d fx = _mm_sub_pd(PacketLanes::pair(lanes.ox, i), cx),
                      fy = _mm_sub_pd(PacketLanes::pair(lanes.oy, i), cy),
                      fz = _mm_sub_pd(PacketLanes::pair(lanes.oz, i), cz);
        const auto dot = [](__m128d ax, __m128d ay, __m128d az, __m128d bx, __m128d by, __m128d bz) {
            return _mm_add_pd(_mm_add_pd(_mm_mul_pd(ax, bx), _mm_mul_pd(ay, by)), _mm_mul_pd(az, bz));
        };
        const __m128d a = dot(dx, dy, dz, dx, dy, dz);
        const __m128d b = dot(fx, fy, fz, dx, dy, dz);
        const __m128d s = _mm_div_pd(b, a);
        const __m128d lx = _mm_sub_pd(fx, _mm_mul_pd(s, dx)), ly = _mm_sub_pd(fy, _mm_mul_pd(s, dy)),
                      lz = _mm_sub_pd(fz, _mm_mul_pd(s, dz));
        const __m128d discriminant = _mm_mul_pd(a, _mm_sub_pd(r2, dot(lx, ly, lz, lx, ly, lz)));
        const __m128d root = _mm_sqrt_pd(discriminant); // NaN where negative: no root
        // q = -b - copysign(root, b)
        const __m128d q = _mm_sub_pd(_mm_xor_pd(b, sign), _mm_or_pd(_mm_andnot_pd(sign, root), _mm_and_pd(sign, b)));
        const __m128d c = _mm_sub_pd(dot(fx, fy, fz, fx, fy, fz), r2);
        const __m128d t0 = _mm_div_pd(q, a);
        const __m128d nonzero = _mm_cmpneq_pd(q, _mm_setzero_pd()); // true for NaN, as q != 0 is
        const __m128d t1 = _mm_or_pd(_mm_and_pd(nonzero, _mm_div_pd(c, q)), _mm_andnot_pd(nonzero, t0));
        lanes.block(args->valid, i, t0, t1);
    }
}

// firstPlaneCrossing's t for lanes i, i + 1 (dn = 0 gives an infinite or NaN t).
inline void occludePlaneLanes8(const RTCOccludedFunctionNArguments* args, const Vec3& normal, double distance) {
    PacketLanes lanes(args->ray);
    const __m128d nx = _mm_set1_pd(normal.x), ny = _mm_set1_pd(normal.y), nz = _mm_set1_pd(normal.z);
    for (int i = 0; i < 8; i += 2) {
        if (!args->valid[i] && !args->valid[i + 1]) continue;
        const auto along = [&](const float* x, const float* y, const float* z) {
            const __m128d xx = _mm_mul_pd(nx, PacketLanes::pair(x, i)), yy = _mm_mul_pd(ny, PacketLanes::pair(y, i));
            return _mm_add_pd(_mm_add_pd(xx, yy), _mm_mul_pd(nz, PacketLanes::pair(z, i)));
        };
        const __m128d dn = along(lanes.dx, lanes.dy, lanes.dz);
        const __m128d t = _mm_div_pd(_mm_sub_pd(_mm_set1_pd(distance), along(lanes.ox, lanes.oy, lanes.oz)), dn);
        lanes.block(args->valid, i, t, t);
    }
}

#if defined(__x86_64__)
// The same two kernels four lanes an instruction where the processor has AVX
// (its double operations are IEEE's, as SSE2's, and no FMA is enabled): each
// lane's answer is the same.
#define DRT_AVX __attribute__((target("avx"), always_inline)) inline
bool avxLanes = __builtin_cpu_supports("avx");

// Lanes i to i + 3 of a float array, widened to double.
DRT_AVX __m256d quadOf(const float* v, int i) { return _mm256_cvtps_pd(_mm_loadu_ps(v + i)); }

DRT_AVX __m256d withinQuad(__m256d t, __m256d near, __m256d far) {
    const __m256d infinity = _mm256_set1_pd(INFINITY);
    const __m256d magnitude = _mm256_castsi256_pd(_mm256_set1_epi64x(0x7fffffffffffffff));
    return _mm256_and_pd(_mm256_cmp_pd(_mm256_and_pd(t, magnitude), infinity, _CMP_LT_OS),
                         _mm256_and_pd(_mm256_cmp_pd(t, near, _CMP_GT_OS), _mm256_cmp_pd(t, far, _CMP_LT_OS)));
}

// PacketLanes::block for lanes i to i + 3.
DRT_AVX void blockQuad(PacketLanes& lanes, const int* valid, int i, __m256d t0, __m256d t1) {
    const __m256d near = quadOf(lanes.tnear, i), far = quadOf(lanes.tfar, i);
    const int hit = _mm256_movemask_pd(_mm256_or_pd(withinQuad(t0, near, far), withinQuad(t1, near, far)));
    for (int k = 0; k < 4; ++k)
        if ((hit >> k & 1) && valid[i + k]) lanes.tfar[i + k] = -INFINITY;
}

DRT_AVX __m256d dotQuad(__m256d ax, __m256d ay, __m256d az, __m256d bx, __m256d by, __m256d bz) {
    return _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(ax, bx), _mm256_mul_pd(ay, by)), _mm256_mul_pd(az, bz));
}

DRT_AVX bool anyValidOfFour(const int* valid, int i) { return valid[i] || valid[i + 1] || valid[i + 2] || valid[i + 3]; }

__attribute__((target("avx"))) void occludeSphereLanes8Avx(const RTCOccludedFunctionNArguments* args,
                                                           const Vec3& center, double radius) {
    PacketLanes lanes(args->ray);
    const __m256d cx = _mm256_set1_pd(center.x), cy = _mm256_set1_pd(center.y), cz = _mm256_set1_pd(center.z);
    const __m256d r2 = _mm256_set1_pd(radius * radius);
    const __m256d sign = _mm256_castsi256_pd(_mm256_set1_epi64x(int64_t(0x8000000000000000ULL)));
    for (int i = 0; i < 8; i += 4) {
        if (!anyValidOfFour(args->valid, i)) continue;
        const __m256d dx = quadOf(lanes.dx, i), dy = quadOf(lanes.dy, i), dz = quadOf(lanes.dz, i);
        const __m256d fx = _mm256_sub_pd(quadOf(lanes.ox, i), cx), fy = _mm256_sub_pd(quadOf(lanes.oy, i), cy),
                      fz = _mm256_sub_pd(quadOf(lanes.oz, i), cz);
        const __m256d a = dotQuad(dx, dy, dz, dx, dy, dz);
        const __m256d b = dotQuad(fx, fy, fz, dx, dy, dz);
        const __m256d s = _mm256_div_pd(b, a);
        const __m256d lx = _mm256_sub_pd(fx, _mm256_mul_pd(s, dx)), ly = _mm256_sub_pd(fy, _mm256_mul_pd(s, dy)),
                      lz = _mm256_sub_pd(fz, _mm256_mul_pd(s, dz));
        const __m256d discriminant = _mm256_mul_pd(a, _mm256_sub_pd(r2, dotQuad(lx, ly, lz, lx, ly, lz)));
        const __m256d root = _mm256_sqrt_pd(discriminant); // NaN where negative: no root
        // q = -b - copysign(root, b)
        const __m256d q = _mm256_sub_pd(_mm256_xor_pd(b, sign),
                                        _mm256_or_pd(_mm256_andnot_pd(sign, root), _mm256_and_pd(sign, b)));
        const __m256d c = _mm256_sub_pd(dotQuad(fx, fy, fz, fx, fy, fz), r2);
        const __m256d t0 = _mm256_div_pd(q, a);
        const __m256d nonzero = _mm256_cmp_pd(q, _mm256_setzero_pd(), _CMP_NEQ_UQ); // true for NaN, as q != 0 is
        const __m256d t1 =
            _mm256_or_pd(_mm256_and_pd(nonzero, _mm256_div_pd(c, q)), _mm256_andnot_pd(nonzero, t0));
        blockQuad(lanes, args->valid, i, t0, t1);
    }
}

__attribute__((target("avx"))) void occludePlaneLanes8Avx(const RTCOccludedFunctionNArguments* args,
                                                          const Vec3& normal, double distance) {
    PacketLanes lanes(args->ray);
    const __m256d nx = _mm256_set1_pd(normal.x), ny = _mm256_set1_pd(normal.y), nz = _mm256_set1_pd(normal.z);
    for (int i = 0; i < 8; i += 4) {
        if (!anyValidOfFour(args->valid, i)) continue;
        const __m256d dn = dotQuad(nx, ny, nz, quadOf(lanes.dx, i), quadOf(lanes.dy, i), quadOf(lanes.dz, i));
        const __m256d on = dotQuad(nx, ny, nz, quadOf(lanes.ox, i), quadOf(lanes.oy, i), quadOf(lanes.oz, i));
        const __m256d t = _mm256_div_pd(_mm256_sub_pd(_mm256_set1_pd(distance), on), dn);
        blockQuad(lanes, args->valid, i, t, t);
    }
}
#undef DRT_AVX
#endif
#endif

// occludedLanes for N rays at the top level and a plain primitive without a
// transform (intersectTopLanes).
template <unsigned N, class Solve>
[[gnu::always_inline]] inline void occludedTopLanes(const RTCOccludedFunctionNArguments* args, Solve solve) {
#if defined(__SSE2__)
#if defined(__x86_64__)
    if constexpr (N == 8 && std::is_same_v<Solve, SphereSolver>)
        if (avxLanes) return occludeSphereLanes8Avx(args, solve.center, solve.radius);
    if constexpr (N == 8 && std::is_same_v<Solve, PlaneSolver>)
        if (avxLanes) return occludePlaneLanes8Avx(args, solve.normal, solve.distance);
#endif
    if constexpr (N == 8 && std::is_same_v<Solve, SphereSolver>)
        return occludeSphereLanes8(args, solve.center, solve.radius);
    if constexpr (N == 8 && std::is_same_v<Solve, PlaneSolver>)
        return occludePlaneLanes8(args, solve.normal, solve.distance);
#endif
    RTCRayN* ray = args->ray;
    const int* const valid = args->valid;
    for (unsigned i = 0; i < N; ++i) {
        if (!valid[i]) continue;
        const Vec3 o{RTCRayN_org_x(ray, N, i), RTCRayN_org_y(ray, N, i), RTCRayN_org_z(ray, N, i)};
        const Vec3 d{RTCRayN_dir_x(ray, N, i), RTCRayN_dir_y(ray, N, i), RTCRayN_dir_z(ray, N, i)};
        float& tfar = RTCRayN_tfar(ray, N, i);
        Crossing c;
        if (solve(o, d, RTCRayN_tnear(ray, N, i), tfar, c)) tfar = -INFINITY;
    }
}

static void occludedCallback(const RTCOccludedFunctionNArguments* args) {
    const auto* level = static_cast<const Level*>(args->geometryUserPtr);
    const Primitive& p = level->primitives[args->primID];
    if (p.noShadow) return;
    const auto occlude = [&] {
        runLanes(args, p, [args](auto n, auto solve) { occludedTopLanes<decltype(n)::value>(args, solve); },
                 [args, &p](auto n) { occludedLanes<decltype(n)::value>(args, p); });
    };
    uint8_t* const crossed = p.mayTransmit ? QueryContext::of(args->context).crossedTransmitter : nullptr;
    if (!crossed) return occlude();
    // An opaque query and a surface that may let light through: where the
    // lanes would be blocked they go on, recorded as crossing it.
    constexpr unsigned kMaxLanes = 16; // Embree's widest packet
    const unsigned n = std::min(args->N, kMaxLanes);
    float before[kMaxLanes];
    for (unsigned i = 0; i < n; ++i) before[i] = RTCRayN_tfar(args->ray, args->N, i);
    occlude();
    for (unsigned i = 0; i < n; ++i) {
        float& tfar = RTCRayN_tfar(args->ray, args->N, i);
        if (!args->valid[i] || tfar == before[i]) continue;
        tfar = before[i];
        crossed[RTCRayN_id(args->ray, args->N, i)] = 1;
    }
}

void attachPrimitives(RTCDevice device, Level& level) {
    if (level.primitives.empty()) return;
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    if (!geometry) return; // the device error is rethrown by the caller
    rtcSetGeometryUserPrimitiveCount(geometry, static_cast<unsigned>(level.primitives.size()));
    rtcSetGeometryUserData(geometry, &level);
    rtcSetGeometryBoundsFunction(geometry, boundsCallback, nullptr);
    rtcSetGeometryIntersectFunction(geometry, intersectCallback);
    rtcSetGeometryOccludedFunction(geometry, occludedCallback);
    rtcCommitGeometry(geometry);
    const unsigned id = rtcAttachGeometry(level.scene, geometry);
    rtcReleaseGeometry(geometry);
    if (level.geometries.size() <= id) level.geometries.resize(id + 1);
    level.geometries[id] = {GeometryKind::Analytic, 0};
}

// ---------------------------------------------------------------- triangles

// A clipped mesh: a hit counts only where it lies inside every clip. Only
// static meshes are clipped, so the ray is in the level's space.
static void clipFilter(const RTCFilterFunctionNArguments* args) {
    const auto* level = static_cast<const Level*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (!args->valid[i]) continue;
        const unsigned geomID = RTCHitN_geomID(args->hit, args->N, i);
        const MeshRecord& mesh = level->meshes[level->geometries[geomID].index];
        RTCRayN* ray = args->ray;
        const Vec3 o{RTCRayN_org_x(ray, args->N, i), RTCRayN_org_y(ray, args->N, i), RTCRayN_org_z(ray, args->N, i)};
        const Vec3 d{RTCRayN_dir_x(ray, args->N, i), RTCRayN_dir_y(ray, args->N, i), RTCRayN_dir_z(ray, args->N, i)};
        const Vec3 point = o + double(RTCRayN_tfar(ray, args->N, i)) * d; // tfar holds the candidate hit
        for (const CsgNode& clip : mesh.clips)
            if (!insideNode(clip, point)) {
                args->valid[i] = 0;
                break;
            }
    }
}

void recordTransmitters(const RTCFilterFunctionNArguments* args) {
    uint8_t* const crossed = QueryContext::of(args->context).crossedTransmitter;
    if (!crossed) return;
    for (unsigned i = 0; i < args->N; ++i) {
        if (!args->valid[i]) continue;
        args->valid[i] = 0;
        crossed[RTCRayN_id(args->ray, args->N, i)] = 1;
    }
}

// The occlusion filter of a mesh that may let light through: its clips first,
// then an opaque query records what is left instead of being blocked by it.
static void occludedMeshFilter(const RTCFilterFunctionNArguments* args) {
    const auto* level = static_cast<const Level*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (!args->valid[i]) continue;
        const unsigned geomID = RTCHitN_geomID(args->hit, args->N, i);
        if (!level->meshes[level->geometries[geomID].index].clips.empty()) clipFilter(args); // every lane's
        break;
    }
    recordTransmitters(args);
}

void attachMesh(RTCDevice device, Level& level, MeshRecord mesh, bool noShadow) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!geometry) return;
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                                 RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                                 mesh.vertices.size()));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0,
                                                                   RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                                                   mesh.triangles.size()));
    if (!vertices || !indices) {
        rtcReleaseGeometry(geometry);
        return;
    }
    for (size_t i = 0; i < mesh.vertices.size(); ++i)
        for (int k = 0; k < 3; ++k) vertices[3 * i + k] = float(mesh.vertices[i][k]);
    for (size_t i = 0; i < mesh.triangles.size(); ++i)
        for (int k = 0; k < 3; ++k) indices[3 * i + k] = static_cast<unsigned>(mesh.triangles[i][k]);
    rtcSetGeometryMask(geometry, noShadow ? kCameraMask : (kCameraMask | kShadowMask));
    if (!mesh.clips.empty() || mesh.mayTransmit) rtcSetGeometryUserData(geometry, &level);
    if (!mesh.clips.empty()) rtcSetGeometryIntersectFilterFunction(geometry, clipFilter);
    if (mesh.mayTransmit) rtcSetGeometryOccludedFilterFunction(geometry, occludedMeshFilter);
    else if (!mesh.clips.empty()) rtcSetGeometryOccludedFilterFunction(geometry, clipFilter);
    rtcCommitGeometry(geometry);
    const unsigned id = rtcAttachGeometry(level.scene, geometry);
    rtcReleaseGeometry(geometry);
    if (level.geometries.size() <= id) level.geometries.resize(id + 1);
    level.geometries[id] = {GeometryKind::Mesh, level.meshes.size()};
    level.meshes.push_back(std::move(mesh));
}

} // namespace drt::accel

namespace drt::accel {

// Embree reads vertex buffers 16 bytes at a time, so the last float3 must be
// followed by 4 readable bytes: the positions' capacity must exceed their size
// (padIndexedMesh). A mesh without that slack is copied.
void attachIndexedMesh(RTCDevice device, Level& level, std::shared_ptr<const IndexedMesh> mesh,
                       RTCFilterFunctionN occludedFilter, void* user) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!geometry) return;
    const std::vector<Float3>& positions = mesh->positions;
    if (positions.capacity() > positions.size()) {
        rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, positions.data(), 0,
                                   sizeof(Float3), positions.size());
    } else {
        auto* copy = static_cast<Float3*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                                  RTC_FORMAT_FLOAT3, sizeof(Float3),
                                                                  positions.size()));
        if (copy) std::copy(positions.begin(), positions.end(), copy);
    }
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh->indices.data(), 0,
                               3 * sizeof(uint32_t), mesh->triangleCount());
    if (occludedFilter) {
        rtcSetGeometryUserData(geometry, user);
        rtcSetGeometryOccludedFilterFunction(geometry, occludedFilter);
    }
    rtcCommitGeometry(geometry);
    const unsigned id = rtcAttachGeometry(level.scene, geometry);
    rtcReleaseGeometry(geometry);
    MeshRecord record;
    record.indexed = std::move(mesh);
    Vec3 lo, hi;
    if (indexedMeshBounds(*record.indexed, lo, hi)) record.extent = maxComponent(hi - lo);
    if (level.geometries.size() <= id) level.geometries.resize(id + 1);
    level.geometries[id] = {GeometryKind::Mesh, level.meshes.size()};
    level.meshes.push_back(std::move(record));
}

} // namespace drt::accel
