// A ray as the renderer and the accelerator exchange it: world space, double
// precision, with its time in the shutter.
#pragma once

#include "core/vec.h"

namespace drt {

struct Ray {
    Vec3 origin;
    Vec3 direction; // need not be unit length; t is in units of |direction|
    double tMin = 0;
    double tMax = 1e30;
    double time = 0; // in [0, 1]: the Motion parameter
};

} // namespace drt
