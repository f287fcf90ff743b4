// Private to src/accel: the Accelerator's state, shared by the builder
// (accel_build.cpp) and the queries (accel.cpp).
#pragma once

#include "accel/accel.h"
#include "accel/built_scene.h"

namespace drt {

namespace accel {
struct AcceleratorState {
    EmbreeDevice device;
    Level top;
    std::vector<Instance> instances; // moving objects, by GeometryRef::index
    bool bounded = false;
    Vec3 lower, upper; // world bounds of everything finite
};

// Fills state from the scene and commits every Embree scene. Throws RenderError.
void buildScene(const Scene& scene, AcceleratorState& state);
} // namespace accel

struct Accelerator::Impl : accel::AcceleratorState {};

} // namespace drt
