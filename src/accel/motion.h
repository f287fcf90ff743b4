// Motion over the shutter (scene.h Motion) as drt interprets it, in double
// precision, plus its Embree instance form.
//
// Pivot: the motion scale and rotation pivot on the world origin, like every
// POV-Ray transform; the motion is simply appended after Object::transform:
//   world(t) = translate(t T) * rotate(t theta about a) * scale(lerp(1, S, t)) * transform.
// The rotation `rotate <x, y, z>` (degrees, x then y then z) is turned into one
// axis a and angle theta in [0, 360) from its quaternion, and interpolated at
// constant angular speed about that axis (slerp from the identity). A
// single-axis rotation below 360 degrees therefore turns the long way if asked
// to (rotate 270*y turns by 270 degrees, not -90).
#pragma once

#include "core/transform.h"
#include "scene/scene.h"

#include <embree3/rtcore.h>

#include <vector>

namespace drt::accel {

class MotionPath {
public:
    // Throws std::invalid_argument for non-positive or non-finite scale.
    explicit MotionPath(const Motion& motion);

    // The motion part of the transform at time t in [0, 1] (applied after the
    // object's own transform).
    Transform at(double t) const;

    // Embree instance time steps: enough that each step turns less than 180
    // degrees, because Embree slerps along the shorter arc between steps.
    int timeStepCount() const;
    // With a frame origin f (accel.h "Frame"), the step maps level space
    // (world at time 0 minus f) to the top level (world minus f):
    //   x -> R Sc (x + f) + t T - f.
    RTCQuaternionDecomposition timeStep(int index, const Vec3& frameOrigin = {}) const;

private:
    Vec3 scale_{1, 1, 1};
    Vec3 axis_{0, 1, 0};
    double angleDegrees_ = 0;
    Vec3 translate_;
};

} // namespace drt::accel
