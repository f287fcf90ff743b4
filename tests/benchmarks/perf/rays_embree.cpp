#include "rays_embree.h"

#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fmt/format.h>
#include <mutex>
#include <stdexcept>

namespace drt::perf {

namespace {

// One analytic primitive of the user geometry, in float like Embree's own.
struct Primitive {
    bool plane = false;
    float cx = 0, cy = 0, cz = 0, radius = 0;   // sphere
    float nx = 0, ny = 1, nz = 0, distance = 0; // plane: n . p = distance, |n| = 1
};

// drt bounds an unbounded primitive by +-1e18; a plane along an axis is a slab.
constexpr float kUnbounded = 1e18f;

void boundsCallback(const RTCBoundsFunctionArguments* args) {
    const Primitive& p = static_cast<const Primitive*>(args->geometryUserPtr)[args->primID];
    RTCBounds* b = args->bounds_o;
    if (!p.plane) {
        b->lower_x = p.cx - p.radius, b->lower_y = p.cy - p.radius, b->lower_z = p.cz - p.radius;
        b->upper_x = p.cx + p.radius, b->upper_y = p.cy + p.radius, b->upper_z = p.cz + p.radius;
        return;
    }
    b->lower_x = b->lower_y = b->lower_z = -kUnbounded;
    b->upper_x = b->upper_y = b->upper_z = kUnbounded;
    if (std::fabs(p.ny) == 1)
        b->lower_y = b->upper_y = p.distance * p.ny;
    if (std::fabs(p.nx) == 1)
        b->lower_x = b->upper_x = p.distance * p.nx;
    if (std::fabs(p.nz) == 1)
        b->lower_z = b->upper_z = p.distance * p.nz;
}

// The nearest t in (tnear, tfar) where the ray meets the primitive, and the
// geometric normal there; false if none.
bool intersect(const Primitive& p, const float o[3], const float d[3], float tnear, float tfar, float& t,
               float n[3]) {
    if (p.plane) {
        const float denominator = p.nx * d[0] + p.ny * d[1] + p.nz * d[2];
        if (denominator == 0)
            return false;
        t = (p.distance - (p.nx * o[0] + p.ny * o[1] + p.nz * o[2])) / denominator;
        if (!(t > tnear && t < tfar))
            return false;
        n[0] = p.nx, n[1] = p.ny, n[2] = p.nz;
        return true;
    }
    // |o + t d - c|^2 = r^2: a t^2 + 2 b t + c = 0.
    const float ox = o[0] - p.cx, oy = o[1] - p.cy, oz = o[2] - p.cz;
    const float a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    const float b = ox * d[0] + oy * d[1] + oz * d[2];
    const float c = ox * ox + oy * oy + oz * oz - p.radius * p.radius;
    const float discriminant = b * b - a * c;
    if (discriminant < 0)
        return false;
    const float root = std::sqrt(discriminant);
    t = (-b - root) / a;
    if (!(t > tnear && t < tfar)) {
        t = (-b + root) / a;
        if (!(t > tnear && t < tfar))
            return false;
    }
    n[0] = ox + t * d[0], n[1] = oy + t * d[1], n[2] = oz + t * d[2];
    return true;
}

// Callbacks for any N: single rays arrive with N = 1, packets with 8 or 16.
void intersectCallback(const RTCIntersectFunctionNArguments* args) {
    const Primitive& p = static_cast<const Primitive*>(args->geometryUserPtr)[args->primID];
    RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
    RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
    const unsigned N = args->N;
    for (unsigned i = 0; i < N; ++i) {
        if (!args->valid[i])
            continue;
        const float o[3] = {RTCRayN_org_x(ray, N, i), RTCRayN_org_y(ray, N, i), RTCRayN_org_z(ray, N, i)};
        const float d[3] = {RTCRayN_dir_x(ray, N, i), RTCRayN_dir_y(ray, N, i), RTCRayN_dir_z(ray, N, i)};
        float t, n[3];
        if (!intersect(p, o, d, RTCRayN_tnear(ray, N, i), RTCRayN_tfar(ray, N, i), t, n))
            continue;
        RTCRayN_tfar(ray, N, i) = t;
        RTCHitN_Ng_x(hit, N, i) = n[0];
        RTCHitN_Ng_y(hit, N, i) = n[1];
        RTCHitN_Ng_z(hit, N, i) = n[2];
        RTCHitN_u(hit, N, i) = 0;
        RTCHitN_v(hit, N, i) = 0;
        RTCHitN_primID(hit, N, i) = args->primID;
        RTCHitN_geomID(hit, N, i) = args->geomID;
        RTCHitN_instID(hit, N, i, 0) = args->context->instID[0];
    }
}

void occludedCallback(const RTCOccludedFunctionNArguments* args) {
    const Primitive& p = static_cast<const Primitive*>(args->geometryUserPtr)[args->primID];
    const unsigned N = args->N;
    for (unsigned i = 0; i < N; ++i) {
        if (!args->valid[i])
            continue;
        const float o[3] = {RTCRayN_org_x(args->ray, N, i), RTCRayN_org_y(args->ray, N, i),
                            RTCRayN_org_z(args->ray, N, i)};
        const float d[3] = {RTCRayN_dir_x(args->ray, N, i), RTCRayN_dir_y(args->ray, N, i),
                            RTCRayN_dir_z(args->ray, N, i)};
        float t, n[3];
        if (intersect(p, o, d, RTCRayN_tnear(args->ray, N, i), RTCRayN_tfar(args->ray, N, i), t, n))
            RTCRayN_tfar(args->ray, N, i) = -INFINITY;
    }
}

// A hash of (pixel, sample) to a jitter in [0, 1)^2: cheap, and the same for
// every ray width.
inline float jitter(uint32_t x, uint32_t y, uint32_t s, uint32_t axis) {
    uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u ^ s * 0xcb1ab31fu ^ axis * 0x165667b1u;
    h ^= h >> 16, h *= 0x7feb352du, h ^= h >> 15, h *= 0x846ca68bu, h ^= h >> 16;
    return float(h >> 8) * (1.0f / 16777216.0f);
}

// The shadow ray of a hit, if the hit faces the light: from just off the
// surface towards the light, ending just before it.
struct ShadowRay {
    float o[3], d[3];
    bool valid = false;
};
inline ShadowRay shadowRayOf(const float o[3], const float d[3], float t, float nx, float ny, float nz,
                             const Vec3& light) {
    ShadowRay s;
    const float p[3] = {o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]};
    if (nx * d[0] + ny * d[1] + nz * d[2] > 0)
        nx = -nx, ny = -ny, nz = -nz; // face the viewer
    const float l[3] = {float(light.x) - p[0], float(light.y) - p[1], float(light.z) - p[2]};
    if (!(nx * l[0] + ny * l[1] + nz * l[2] > 0))
        return s;
    const float scale = 1e-4f / std::sqrt(nx * nx + ny * ny + nz * nz);
    for (int k = 0; k < 3; ++k)
        s.o[k] = p[k] + (k == 0 ? nx : k == 1 ? ny : nz) * scale, s.d[k] = l[k];
    s.valid = true;
    return s;
}

} // namespace

struct RawEmbreeScene::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::vector<Primitive> primitives;
    RaysScene source;
    std::string error;
};

const char* rayWidthName(RayWidth width) {
    switch (width) {
    case RayWidth::Single:
        return "single";
    case RayWidth::Packet8:
        return "packet 8";
    case RayWidth::Packet16:
        return "packet 16";
    }
    return "?";
}

RawEmbreeScene::RawEmbreeScene(const RaysScene& scene) : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.source = scene;
    m.device = rtcNewDevice(nullptr);
    if (!m.device)
        throw std::runtime_error("Embree: cannot create a device");
    // Embree calls this from C code: keep the first error, and throw after the build.
    rtcSetDeviceErrorFunction(
        m.device,
        [](void* user, RTCError code, const char* message) {
            std::string& error = static_cast<Impl*>(user)->error;
            if (error.empty())
                error = fmt::format("Embree error {}: {}", int(code), message ? message : "");
        },
        &m);
    const auto start = std::chrono::steady_clock::now();
    m.scene = rtcNewScene(m.device);
    Primitive plane;
    plane.plane = true;
    m.primitives.push_back(plane);
    for (const RaysSphere& s : scene.spheres) {
        Primitive p;
        p.cx = float(s.center.x), p.cy = float(s.center.y), p.cz = float(s.center.z),
        p.radius = float(s.radius);
        m.primitives.push_back(p);
    }
    RTCGeometry user = rtcNewGeometry(m.device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(user, unsigned(m.primitives.size()));
    rtcSetGeometryUserData(user, m.primitives.data());
    rtcSetGeometryBoundsFunction(user, boundsCallback, nullptr);
    rtcSetGeometryIntersectFunction(user, intersectCallback);
    rtcSetGeometryOccludedFunction(user, occludedCallback);
    rtcCommitGeometry(user);
    rtcAttachGeometry(m.scene, user);
    rtcReleaseGeometry(user);
    if (!scene.triangles.empty()) {
        RTCGeometry mesh = rtcNewGeometry(m.device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
            mesh, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), scene.vertices.size()));
        auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            mesh, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), scene.triangles.size()));
        for (size_t i = 0; i < scene.vertices.size(); ++i)
            for (int k = 0; k < 3; ++k)
                vertices[3 * i + k] = scene.vertices[i][k];
        for (size_t i = 0; i < scene.triangles.size(); ++i)
            for (int k = 0; k < 3; ++k)
                indices[3 * i + k] = scene.triangles[i][k];
        rtcCommitGeometry(mesh);
        rtcAttachGeometry(m.scene, mesh);
        rtcReleaseGeometry(mesh);
    }
    rtcCommitScene(m.scene);
    if (!m.error.empty())
        throw std::runtime_error(m.error);
    buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

RawEmbreeScene::~RawEmbreeScene() {
    if (impl_->scene)
        rtcReleaseScene(impl_->scene);
    if (impl_->device)
        rtcReleaseDevice(impl_->device);
}

namespace {

// The CPU time the calling thread has used.
double threadCpuSeconds() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
}

// Traces one block of `W` pixels (4 wide) at one sample index as a packet.
template <int W, typename RayHitW, typename RayW>
void tracePacket(RTCScene scene, const CameraFrame& camera, const Vec3& light, bool shadows, int x0, int y0,
                 int s, int width, int height, uint64_t& cameraRays, uint64_t& shadowRays, uint64_t& hits,
                 void (*intersectW)(const int*, RTCScene, RTCIntersectContext*, RayHitW*),
                 void (*occludedW)(const int*, RTCScene, RTCIntersectContext*, RayW*)) {
    alignas(64) RayHitW packet;
    alignas(64) int valid[W];
    for (int i = 0; i < W; ++i) {
        const int x = x0 + i % 4, y = y0 + i / 4;
        const Vec3 d = cameraDirection(camera, x + jitter(x, y, s, 0), y + jitter(x, y, s, 1), width, height);
        packet.ray.org_x[i] = float(camera.origin.x), packet.ray.org_y[i] = float(camera.origin.y);
        packet.ray.org_z[i] = float(camera.origin.z);
        packet.ray.dir_x[i] = float(d.x), packet.ray.dir_y[i] = float(d.y), packet.ray.dir_z[i] = float(d.z);
        packet.ray.tnear[i] = 0, packet.ray.tfar[i] = INFINITY, packet.ray.time[i] = 0;
        packet.ray.mask[i] = 0xFFFFFFFFu, packet.ray.id[i] = 0, packet.ray.flags[i] = 0;
        packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
        packet.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
        valid[i] = -1;
    }
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    intersectW(valid, scene, &context, &packet);
    cameraRays += W;
    if (!shadows) {
        for (int i = 0; i < W; ++i)
            hits += packet.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID;
        return;
    }
    alignas(64) RayW shadow;
    alignas(64) int shadowValid[W];
    for (int i = 0; i < W; ++i) {
        shadowValid[i] = 0;
        if (packet.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID)
            continue;
        ++hits;
        const float o[3] = {packet.ray.org_x[i], packet.ray.org_y[i], packet.ray.org_z[i]};
        const float d[3] = {packet.ray.dir_x[i], packet.ray.dir_y[i], packet.ray.dir_z[i]};
        const ShadowRay r = shadowRayOf(o, d, packet.ray.tfar[i], packet.hit.Ng_x[i], packet.hit.Ng_y[i],
                                        packet.hit.Ng_z[i], light);
        if (!r.valid)
            continue;
        shadow.org_x[i] = r.o[0], shadow.org_y[i] = r.o[1], shadow.org_z[i] = r.o[2];
        shadow.dir_x[i] = r.d[0], shadow.dir_y[i] = r.d[1], shadow.dir_z[i] = r.d[2];
        shadow.tnear[i] = 0, shadow.tfar[i] = 1 - 1e-4f, shadow.time[i] = 0;
        shadow.mask[i] = 0xFFFFFFFFu, shadow.id[i] = 0, shadow.flags[i] = 0;
        shadowValid[i] = -1;
        ++shadowRays;
    }
    occludedW(shadowValid, scene, &context, &shadow);
}

} // namespace

RawRate RawEmbreeScene::trace(RayMix mix, RayWidth rayWidth, int width, int height, int spp,
                              int threads) const {
    const CameraFrame camera = cameraFrame(impl_->source, width, height);
    const Vec3 light = impl_->source.light;
    const bool shadows = mix == RayMix::CameraAndShadow;
    const RTCScene scene = impl_->scene;
    constexpr int kTile = 16; // tiles of 16 x 16 pixels, handed to the threads
    const int tilesX = (width + kTile - 1) / kTile, tilesY = (height + kTile - 1) / kTile;
    std::atomic<uint64_t> cameraTotal{0}, shadowTotal{0}, hitTotal{0};

    const auto traceTile = [&](int tile) {
        uint64_t cameraRays = 0, shadowRays = 0, hits = 0;
        const int tx = (tile % tilesX) * kTile, ty = (tile / tilesX) * kTile;
        const int xEnd = std::min(width, tx + kTile), yEnd = std::min(height, ty + kTile);
        if (rayWidth == RayWidth::Single) {
            RTCIntersectContext context;
            rtcInitIntersectContext(&context);
            for (int y = ty; y < yEnd; ++y)
                for (int x = tx; x < xEnd; ++x)
                    for (int s = 0; s < spp; ++s) {
                        const Vec3 d = cameraDirection(camera, x + jitter(x, y, s, 0), y + jitter(x, y, s, 1),
                                                       width, height);
                        RTCRayHit rh;
                        rh.ray.org_x = float(camera.origin.x), rh.ray.org_y = float(camera.origin.y);
                        rh.ray.org_z = float(camera.origin.z);
                        rh.ray.dir_x = float(d.x), rh.ray.dir_y = float(d.y), rh.ray.dir_z = float(d.z);
                        rh.ray.tnear = 0, rh.ray.tfar = INFINITY, rh.ray.time = 0;
                        rh.ray.mask = 0xFFFFFFFFu, rh.ray.id = 0, rh.ray.flags = 0;
                        rh.hit.geomID = rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
                        rtcIntersect1(scene, &context, &rh);
                        ++cameraRays;
                        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
                            continue;
                        ++hits;
                        if (!shadows)
                            continue;
                        const float o[3] = {rh.ray.org_x, rh.ray.org_y, rh.ray.org_z};
                        const float dd[3] = {rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z};
                        const ShadowRay r =
                            shadowRayOf(o, dd, rh.ray.tfar, rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z, light);
                        if (!r.valid)
                            continue;
                        RTCRay shadow;
                        shadow.org_x = r.o[0], shadow.org_y = r.o[1], shadow.org_z = r.o[2];
                        shadow.dir_x = r.d[0], shadow.dir_y = r.d[1], shadow.dir_z = r.d[2];
                        shadow.tnear = 0, shadow.tfar = 1 - 1e-4f, shadow.time = 0;
                        shadow.mask = 0xFFFFFFFFu, shadow.id = 0, shadow.flags = 0;
                        rtcOccluded1(scene, &context, &shadow);
                        ++shadowRays;
                    }
        } else {
            const int rows = rayWidth == RayWidth::Packet8 ? 2 : 4;
            for (int y = ty; y + rows <= yEnd; y += rows)
                for (int x = tx; x + 4 <= xEnd; x += 4)
                    for (int s = 0; s < spp; ++s) {
                        if (rayWidth == RayWidth::Packet8)
                            tracePacket<8, RTCRayHit8, RTCRay8>(scene, camera, light, shadows, x, y, s, width,
                                                                height, cameraRays, shadowRays, hits,
                                                                rtcIntersect8, rtcOccluded8);
                        else
                            tracePacket<16, RTCRayHit16, RTCRay16>(scene, camera, light, shadows, x, y, s,
                                                                   width, height, cameraRays, shadowRays,
                                                                   hits, rtcIntersect16, rtcOccluded16);
                    }
        }
        cameraTotal += cameraRays, shadowTotal += shadowRays, hitTotal += hits;
    };

    tbb::task_arena arena(threads);
    std::mutex cpuMutex;
    double cpuSeconds = 0;
    const auto start = std::chrono::steady_clock::now();
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, tilesX * tilesY),
                          [&](const tbb::blocked_range<int>& range) {
                              const double cpuStart = threadCpuSeconds();
                              for (int tile = range.begin(); tile < range.end(); ++tile)
                                  traceTile(tile);
                              const double used = threadCpuSeconds() - cpuStart;
                              const std::lock_guard<std::mutex> lock(cpuMutex);
                              cpuSeconds += used;
                          });
    });
    RawRate rate;
    rate.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    rate.cpuSeconds = cpuSeconds;
    rate.cameraRays = cameraTotal, rate.shadowRays = shadowTotal, rate.hits = hitTotal;
    return rate;
}

} // namespace drt::perf
