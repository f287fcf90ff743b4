#include "bench/stats.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace drt::bench {

double quantile(std::vector<double> values, double q) {
    if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::sort(values.begin(), values.end());
    // Type 7: h = (n - 1) q, between the floor(h)-th and ceil(h)-th order statistics.
    const double h = (double(values.size()) - 1) * std::clamp(q, 0.0, 1.0);
    const size_t below = size_t(std::floor(h));
    const size_t above = std::min(below + 1, values.size() - 1);
    return values[below] + (h - double(below)) * (values[above] - values[below]);
}

SlopeFit fitLogLogSlope(const std::vector<double>& x, const std::vector<double>& y) {
    std::vector<double> lx, ly;
    for (size_t i = 0; i < std::min(x.size(), y.size()); ++i) {
        if (x[i] > 0 && y[i] > 0 && std::isfinite(x[i]) && std::isfinite(y[i])) {
            lx.push_back(std::log10(x[i]));
            ly.push_back(std::log10(y[i]));
        }
    }
    SlopeFit fit;
    fit.points = int(lx.size());
    if (lx.empty()) return fit;
    const double n = double(lx.size());
    double mx = 0, my = 0;
    for (size_t i = 0; i < lx.size(); ++i) mx += lx[i] / n, my += ly[i] / n;
    double sxx = 0, sxy = 0, syy = 0;
    for (size_t i = 0; i < lx.size(); ++i) {
        sxx += (lx[i] - mx) * (lx[i] - mx);
        sxy += (lx[i] - mx) * (ly[i] - my);
        syy += (ly[i] - my) * (ly[i] - my);
    }
    // slope = Sxy / Sxx; R^2 = Sxy^2 / (Sxx Syy).
    fit.slope = sxx > 0 ? sxy / sxx : 0;
    fit.intercept = my - fit.slope * mx;
    fit.r2 = sxx > 0 && syy > 0 ? sxy * sxy / (sxx * syy) : 1;
    return fit;
}

std::vector<size_t> paretoFront(const std::vector<CostError>& points) {
    std::vector<size_t> order;
    for (size_t i = 0; i < points.size(); ++i) {
        const CostError& p = points[i];
        if (std::isfinite(p.cost) && std::isfinite(p.error) && p.cost > 0 && p.error > 0) order.push_back(i);
    }
    // Sweep by increasing cost (ties: smaller error first); a point is on the
    // front if its error is below every cheaper point's error.
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return points[a].cost != points[b].cost ? points[a].cost < points[b].cost : points[a].error < points[b].error;
    });
    std::vector<size_t> front;
    double bestError = std::numeric_limits<double>::infinity();
    for (size_t i : order) {
        if (points[i].error < bestError) {
            front.push_back(i);
            bestError = points[i].error;
        }
    }
    return front;
}

std::optional<double> interpolateLogLog(std::vector<CurvePoint> curve, double x) {
    std::erase_if(curve, [](const CurvePoint& p) { return !(p.x > 0 && p.y > 0) || !std::isfinite(p.x + p.y); });
    if (curve.empty() || !(x > 0)) return std::nullopt;
    std::sort(curve.begin(), curve.end(), [](const CurvePoint& a, const CurvePoint& b) { return a.x < b.x; });
    if (x < curve.front().x || x > curve.back().x) return std::nullopt;
    for (size_t i = 0; i + 1 < curve.size(); ++i) {
        const CurvePoint& a = curve[i];
        const CurvePoint& b = curve[i + 1];
        if (x >= a.x && x <= b.x) {
            if (b.x == a.x) return std::min(a.y, b.y);
            const double t = (std::log(x) - std::log(a.x)) / (std::log(b.x) - std::log(a.x));
            return std::exp(std::log(a.y) + t * (std::log(b.y) - std::log(a.y)));
        }
    }
    return curve.back().y; // x equals the only point
}

} // namespace drt::bench
