// Private to src/accel: the Accelerator's state, shared by the builder
// (accel_build.cpp) and the queries (accel.cpp).
#pragma once

#include "accel/accel.h"
#include "accel/built_scene.h"

#include <cstdint>
#include <atomic>
#include <map>
#include <optional>

namespace drt {

namespace accel {
// A number no other accelerator of this process has had (caches key on it).
uint64_t nextAcceleratorGeneration();

struct AcceleratorState {
    const uint64_t generation = nextAcceleratorGeneration();
    EmbreeDevice device;
    Level top;
    std::vector<Instance> instances; // moving objects and compact-mesh placements, by GeometryRef::index
    bool anyMotion = false;          // some instance moves
    // Some shadow-casting surface may let light through (scene/light_through.h):
    // primitives, meshes and placements say which (mayTransmit).
    bool transmitters = false;
    // A scene's one moving instance, when it has exactly one, with kSweptBit
    // as its mask. Embree tests no bounds above a level of one primitive: the
    // one moving ball of a scene had every ray of the scene moved into its
    // level and tested against it. A ray carries the bit only if it may meet
    // the box the instance sweeps over the shutter (accel.cpp rayMask), so the
    // others skip it at its mask.
    struct SweptBox {
        Vec3 lower, upper; // world space, grown to be conservative (accel_build.cpp)
        bool castsShadow = true;
    };
    std::optional<SweptBox> swept;
    // One level per compact mesh, shared by all its placements.
    struct Prototype {
        std::shared_ptr<Level> level;
        Vec3 lower, upper; // object-space bounds
    };
    std::map<const IndexedMesh*, Prototype> prototypes;
    bool bounded = false;
    Vec3 lower, upper; // world bounds of everything finite
    // Embree's top-level frame: world minus frameOrigin (accel.h "Frame").
    bool shifted = false;
    Vec3 frameOrigin;
    double sceneUnit = 1; // frameUnit for unbounded objects
    std::optional<double> onlyTime; // motion baked at this time (Accelerator(scene, onlyTime))
    // Rays Embree could not take (Accelerator::untraceableRays).
    mutable std::atomic<uint64_t> untraceable{0};
};

inline RayQuery::RayQuery(const AcceleratorState& accelerator, const Vec3& rayOrigin, const Vec3& rayDirection)
    : state(&accelerator), worldOrigin(rayOrigin),
      origin(accelerator.shifted ? rayOrigin - accelerator.frameOrigin : rayOrigin), direction(rayDirection) {
    rtcInitIntersectContext(&context);
}

// Hit::frameUnit for an object of this size: the smallest power of two at
// least `extent`, at most 1 (1 for no or an infinite extent).
double frameUnitFor(double extent);

// Fills state from the scene and commits every Embree scene. Throws RenderError.
void buildScene(const Scene& scene, AcceleratorState& state);

// The hit record of the hit Embree found for the query's ray (rayhit: its ray
// and hit as Embree left them, geomID valid; accel.cpp). generalHit handles
// every case; hitFromEmbree gives the same record, by a short way for an
// analytic shape at the top level whose crossing the callback solved.
void hitFromEmbree(const AcceleratorState& state, RayQuery& query, const RTCRayHit& rayhit, Hit& hit);
void generalHit(const AcceleratorState& state, RayQuery& query, const RTCRayHit& rayhit, Hit& hit);
// Whether the packet kernels for spheres and planes take four lanes an
// instruction (AVX, where the processor has it) rather than two (SSE2): the
// same answers either way; tests set it to compare them.
extern bool avxLanes;
} // namespace accel

struct Accelerator::Impl : accel::AcceleratorState {};

} // namespace drt
