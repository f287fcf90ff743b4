// Raw Embree: the ceiling drt's ray rate is measured against. The scene of
// rays_scene.h, built the way drt builds it (spheres and the plane as one
// user geometry with float intersection callbacks, the mesh as an Embree
// triangle geometry), traced with nothing else around it: no sampler, no
// shading beyond the facing test that decides a shadow ray, no film.
#pragma once

#include "rays_scene.h"

#include <cstdint>
#include <memory>
#include <string>

namespace drt::perf {

enum class RayMix { CameraOnly, CameraAndShadow };
// Single rays (rtcIntersect1/rtcOccluded1) or coherent packets of 8 (4x2
// pixels) or 16 (4x4 pixels) rays at the same sample index.
enum class RayWidth { Single = 1, Packet8 = 8, Packet16 = 16 };

struct RawRate {
    uint64_t cameraRays = 0, shadowRays = 0, hits = 0;
    double seconds = 0;    // tracing only (the BVH is built before the clock starts)
    double cpuSeconds = 0; // the tracing threads' CPU time, summed over them
    double mraysPerSecond() const {
        return seconds > 0 ? double(cameraRays + shadowRays) / seconds / 1e6 : 0;
    }
};

class RawEmbreeScene {
  public:
    explicit RawEmbreeScene(const RaysScene& scene); // throws std::runtime_error on an Embree error
    ~RawEmbreeScene();
    RawEmbreeScene(const RawEmbreeScene&) = delete;
    RawEmbreeScene& operator=(const RawEmbreeScene&) = delete;

    // Traces width x height pixels x spp jittered camera rays (and, with
    // CameraAndShadow, one shadow ray to the light from every hit facing it)
    // on `threads` threads.
    RawRate trace(RayMix mix, RayWidth width, int imageWidth, int imageHeight, int spp, int threads) const;
    double buildSeconds() const { return buildSeconds_; }

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    double buildSeconds_ = 0;
};

const char* rayWidthName(RayWidth width); // "single", "packet 8", "packet 16"

} // namespace drt::perf
