// A conservative test of whether a whole line o + t d (every t) misses a box,
// for skipping parts of a shape that a line cannot meet (CSG leaves, blob
// components). Callers grow the box by a margin far above their solvers'
// rounding, so that a skipped part is one the solver would have found no
// crossing with; the test's own rounding is of order 1e-16 |o|.
#pragma once

#include "core/vec.h"

#include <algorithm>
#include <cmath>

namespace drt::accel {

struct CullLine {
    Vec3 o, inverseD;  // the direction's reciprocals, 0 on an axis the line runs across
    bool across[3];    // d is 0 on this axis: the line keeps o's coordinate
    double originNorm; // max |o_i|
    bool usable;       // o and the reciprocals are finite; else nothing may be skipped
};

inline CullLine cullLine(const Vec3& o, const Vec3& d) {
    CullLine line{o, Vec3(0.0), {}, maxComponent(abs(o)), isFinite(o) && isFinite(d)};
    for (int axis = 0; axis < 3; ++axis) {
        line.across[axis] = d[axis] == 0;
        if (!line.across[axis]) line.inverseD[axis] = 1 / d[axis];
    }
    line.usable = line.usable && isFinite(line.inverseD) && std::isfinite(line.originNorm);
    return line;
}

// Whether the line misses [lower - margin, upper + margin] (a usable line only).
inline bool lineMissesBox(const CullLine& line, const Vec3& lower, const Vec3& upper, double margin) {
    double tNear = -HUGE_VAL, tFar = HUGE_VAL;
    for (int axis = 0; axis < 3; ++axis) {
        const double lo = lower[axis] - margin - line.o[axis], hi = upper[axis] + margin - line.o[axis];
        if (line.across[axis]) {
            if (lo > 0 || hi < 0) return true;
            continue;
        }
        const double t0 = lo * line.inverseD[axis], t1 = hi * line.inverseD[axis];
        tNear = std::max(tNear, std::min(t0, t1));
        tFar = std::min(tFar, std::max(t0, t1));
    }
    return tNear > tFar;
}

} // namespace drt::accel
