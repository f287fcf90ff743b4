// A moving object's placement over the shutter (scene/motion.h) as Embree's
// multi-step instance motion, and the same interpolation in double precision.
//
// The instance maps the object's rest pose (its level space) to the world at
// time t: A(t) = placementAt(t) * restPlacement^-1. Embree takes A at S + 1
// equally spaced times, each as a quaternion decomposition about one pivot p
// (scene/motion.h AffineParts), and between steps moves p on a straight line,
// slerps the rotation and blends scale and skew linearly. drt chooses:
//   - p, the point whose path is straightest (bestPivot over the steps and
//     their midpoints): the centre of a spin, of an orbit or of a rolling
//     wheel, so that their arcs are followed exactly, not cut by chords;
//   - S, the smallest step count that puts every key time on a step (when one
//     of at most 128 does), turns at most 90 degrees per step (so Embree's
//     shorter-arc slerp turns the right way; the rotation is tracked at 256
//     times per unit time first), and keeps the interpolated path within 1e-4 of
//     the object's size of the true one at every step's midpoint, doubling S
//     up to 128 (Embree's limit) until it does.
// at(t) repeats Embree's interpolation in double, so a hit Embree reports is
// re-solved on the same moving surface.
#pragma once

#include "core/transform.h"
#include "scene/motion.h"

#include <embree3/rtcore.h>

#include <vector>

namespace drt::accel {

class InstanceMotion {
public:
    // `before` and `chain` place the object in the world over time; lower and
    // upper bound its rest pose (world space; unbounded: pass lower > upper).
    InstanceMotion(const Transform& before, const MotionChain& chain, const Vec3& lower, const Vec3& upper);

    // Rest pose (world) -> world at time t in [0, 1], as Embree interpolates it.
    Transform at(double t) const;

    int timeStepCount() const { return static_cast<int>(steps_.size()); }
    // With a frame origin f (accel.h "Frame"), the step maps level space (rest
    // world minus f) to the top level (world minus f).
    RTCQuaternionDecomposition timeStep(int index, const Vec3& frameOrigin = {}) const;
    // Whether every step has the same rotation, scale, skew and shift, so
    // that only the translation moves: interpolating the steps' matrices
    // linearly is then the same motion.
    bool translationOnly() const;
    // Step `index` as a 3x4 row-major matrix from level space to the top level.
    void stepRows(int index, const Vec3& frameOrigin, float rows[12]) const;
    const Vec3& pivot() const { return pivot_; }

private:
    std::vector<AffineParts> steps_;
    Vec3 pivot_;
};

} // namespace drt::accel
