// Summary statistics for `drt bench`: medians and quantiles over seeds, the
// log-log convergence slope, the Pareto front of (time, error), and log-log
// interpolation along a method's curve for the equal-time and equal-quality
// tables.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace drt::bench {

// Quantile q in [0, 1] with linear interpolation between order statistics
// (Hyndman and Fan's type 7, the default of R and NumPy). NaN if empty.
double quantile(std::vector<double> values, double q);
inline double median(std::vector<double> values) { return quantile(std::move(values), 0.5); }

// Least-squares fit of log10 y = intercept + slope * log10 x over the points
// where both are positive and finite. For relMSE against samples per pixel the
// slope is twice the RMSE rate: -1 for independent samples, -2 for jittered
// samples of a smooth integrand, -1.5 at edges.
struct SlopeFit {
    double slope = 0;
    double intercept = 0;
    double r2 = 0; // coefficient of determination in log space
    int points = 0; // points used; slope is meaningful only with 2 or more
};
SlopeFit fitLogLogSlope(const std::vector<double>& x, const std::vector<double>& y);

// A configuration's cost (seconds) and error, both to be minimised.
struct CostError {
    double cost = 0;
    double error = 0;
};
// Indices of the points no other point dominates (another is at least as good
// in both and better in one), sorted by increasing cost (hence decreasing
// error). Points with a non-finite or non-positive coordinate are ignored.
std::vector<size_t> paretoFront(const std::vector<CostError>& points);

// A curve sampled at increasing x (e.g. median time against error for one
// method): y at `x` by linear interpolation in log-log space; nothing outside
// the sampled range (no extrapolation) or if a value there is not positive.
struct CurvePoint {
    double x = 0;
    double y = 0;
};
std::optional<double> interpolateLogLog(std::vector<CurvePoint> curve, double x);

} // namespace drt::bench
