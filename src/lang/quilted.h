// POV-Ray's `quilted` pattern, written as a function of x, y, z (scene/function.h)
// so that pigments, textures and normals take it as they take `function { }`.
// Measured against POV-Ray 3.7's renders (to 1e-5 of the colour-map value):
// with v = p - floor(p) - 1/2 on each axis and t = |v|,
//   quilted(p) = 2 / (3 sqrt 3) (|v.x| + |v.y| + |v.z|) B(t),
//   B(t) = 3 t (1 - t)^2 control0 + 3 t^2 (1 - t) control1 + t^3,
// the cubic from 0 to 1 whose inner control points are control0 and control1
// (both 1 by default).
#pragma once

#include "scene/function.h"

#include <memory>

namespace drt::lang {

std::shared_ptr<const Function> quiltedFunction(double control0, double control1);
// Whether f is a quilted pattern's function, and then its controls.
bool quiltedControls(const Function& f, double& control0, double& control1);

} // namespace drt::lang
