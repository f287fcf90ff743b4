// POV-Ray prism splines -> closed polylines (scene/extrusion.h contours).
//
// Spline semantics (POV-Ray 3.7 prism.cpp, Compute_Prism):
//   linear:    segments p[i] -> p[i+1]; a sub-polygon closes at the point that
//              equals its first point, and the next one starts after it.
//   quadratic: segment i runs from p[i+1] to p[i+2], shaped by p[i]:
//              (p0/2 - p1 + p2/2) t^2 + (p2 - p0)/2 t + p1; a sub-polygon
//              closes when its end equals its first on-curve point p[start+1]
//              and the next one starts three points later.
//   cubic:     Catmull-Rom segment from p[i+1] to p[i+2] with p[i], p[i+3];
//              closes like quadratic, the next starts four points later.
//   bezier:    each four points form one cubic Bezier segment.
// Curved segments are cut into n equal parameter steps with
// n = ceil(sqrt(max|P''| / (8 tol))): a chord then strays at most
// h^2/8 max|P''| <= tol from its curve, with tol = kPrismTolerance times the
// largest extent of the points.
#pragma once

#include "scene/extrusion.h"

#include <vector>

namespace drt {

inline constexpr double kPrismTolerance = 1e-5;

// Throws std::invalid_argument with a message for too few points.
std::vector<std::vector<Vec2>> prismContours(PrismSource::Spline spline, const std::vector<Vec2>& points);

// The fewest points each spline kind needs.
int minimumPrismPoints(PrismSource::Spline spline);

} // namespace drt
