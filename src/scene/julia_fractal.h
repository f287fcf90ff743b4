// POV-Ray's julia_fractal in the scene model: the 3-D slice of a 4-D Julia
// set. A point p = (x, y, z) of object space is the 4-D number
// (x, y, z, w) with w = (sliceDistance - n.xyz . p) / n.w, n the unit slice
// normal: the point of the hyperplane n . q = sliceDistance above p (default: w = 0).
// It belongs to the set when the orbit q_0 = that number, q_{i+1} = f(q_i) + c
// keeps |q_i|^2 <= the exit value for max_iteration steps. The algebra is
// POV-Ray's quaternions (f: sqr or cube) or its hypercomplex numbers
// (commutative; f: sqr, cube, reciprocal or a complex function applied to
// the two complex halves of the number's duplex form: exp, ln, sin, asin,
// cos, acos, tan, atan, sinh, asinh, cosh, acosh, tanh, atanh, pwr).
//
// The exit value and the bounding sphere about the origin are POV-Ray 3.7's:
// quaternions R = min(1 + |c| + 1e-7, 2), exit value R^2 + 1e-7; hypercomplex
// R = 4, exit value 16. precision p sets the march's smallest step 1/p
// (accel/julia_fractal_shape.h).
#pragma once

#include "core/vec.h"

#include <array>
#include <cmath>

namespace drt {

struct JuliaFractal {
    enum class Algebra { Quaternion, Hypercomplex };
    // The iterated map; the functions after Reciprocal are hypercomplex only.
    enum class Function { Sqr, Cube, Reciprocal, Exp, Ln, Sin, Asin, Cos, Acos, Tan, Atan, Sinh, Asinh, Cosh,
                          Acosh, Tanh, Atanh, Pwr };
    std::array<double, 4> parameter{1, 0, 0, 0}; // c; POV-Ray's default
    Algebra algebra = Algebra::Quaternion;
    Function function = Function::Sqr;
    std::array<double, 2> exponent{0, 0}; // pwr's complex exponent
    int maxIteration = 20;
    double precision = 20; // the march's smallest step is 1 / precision (POV-Ray: at least 1)
    std::array<double, 4> slice{0, 0, 0, 1}; // normal of the slice hyperplane (any length), slice[3] != 0
    double sliceDistance = 0;

    // Radius of the bounding sphere about the origin.
    double radius() const {
        if (algebra == Algebra::Hypercomplex) return 4;
        const double c = std::sqrt(parameter[0] * parameter[0] + parameter[1] * parameter[1] +
                                   parameter[2] * parameter[2] + parameter[3] * parameter[3]);
        return std::fmin(1 + c + 1e-7, 2.0);
    }
    double exitValue() const { return algebra == Algebra::Hypercomplex ? 16 : radius() * radius() + 1e-7; }

    bool bounds(Vec3& lower, Vec3& upper) const {
        lower = Vec3(-radius()), upper = Vec3(radius());
        return true;
    }
    bool closedSolid() const { return true; }
    bool operator==(const JuliaFractal&) const = default;
};

} // namespace drt
