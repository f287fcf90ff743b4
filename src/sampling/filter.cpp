#include "sampling/filter.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace drt {

const std::vector<std::string>& filterNames() {
    static const std::vector<std::string> names{"box", "tent", "gaussian"};
    return names;
}

std::string defaultFilterName() { return "box"; }

Filter makeFilter(const std::string& name) {
    if (name == "box") return {FilterType::Box, 0.5, 0.5};
    if (name == "tent") return {FilterType::Tent, 1.0, 0.5};
    if (name == "gaussian") return {FilterType::Gaussian, 1.5, 0.5};
    throw std::invalid_argument("unknown filter '" + name + "' (expected box, tent or gaussian)");
}

std::string filterName(const Filter& filter) {
    switch (filter.type) {
    case FilterType::Tent: return "tent";
    case FilterType::Gaussian: return "gaussian";
    case FilterType::Box: break;
    }
    return "box";
}

namespace {

// Tent density (1 - |x|/r) / r on [-r, r]: invert each half's CDF,
// x = -r + r sqrt(2u) for u < 1/2 and x = r - r sqrt(2 - 2u) above.
double sampleTent(double u, double r) {
    if (u < 0.5) return -r + r * std::sqrt(2.0 * u);
    return r - r * std::sqrt(2.0 - 2.0 * u);
}

// Inverse of erf on (-1, 1): a start from the logistic-like approximation
// erf(x) ~ tanh(sqrt(pi) * log(2) * x) (within a few per cent), then Newton steps on
// erf(x) - y, whose derivative is 2/sqrt(pi) exp(-x^2); converges to double
// precision for |y| < 1 - 1e-15, which is all a truncated Gaussian needs.
double inverseErf(double y) {
    y = std::clamp(y, -1.0 + 1e-15, 1.0 - 1e-15);
    double x = std::atanh(y) / (std::sqrt(kPi) * std::log(2.0));
    for (int i = 0; i < 40; ++i) {
        const double step = (std::erf(x) - y) / (2.0 / std::sqrt(kPi) * std::exp(-x * x));
        x -= step;
        if (std::fabs(step) < 1e-15 * std::max(1.0, std::fabs(x))) break;
    }
    return x;
}

// Gaussian of deviation sigma truncated to [-r, r]: CDF
// (erf(x / (sigma sqrt 2)) - erf(-a)) / (2 erf(a)), a = r / (sigma sqrt 2).
double sampleTruncatedGaussian(double u, double sigma, double r) {
    const double a = std::erf(r / (sigma * std::sqrt(2.0)));
    const double x = sigma * std::sqrt(2.0) * inverseErf(a * (2.0 * u - 1.0));
    return std::clamp(x, -r, r);
}

double pdf1D(const Filter& f, double x) {
    if (std::fabs(x) > f.radius) return 0.0;
    switch (f.type) {
    case FilterType::Tent: return (1.0 - std::fabs(x) / f.radius) / f.radius;
    case FilterType::Gaussian: {
        const double norm = std::erf(f.radius / (f.sigma * std::sqrt(2.0))) * f.sigma * std::sqrt(2.0 * kPi);
        return std::exp(-x * x / (2.0 * f.sigma * f.sigma)) / norm;
    }
    case FilterType::Box: break;
    }
    return 1.0 / (2.0 * f.radius);
}

double sample1D(const Filter& f, double u) {
    switch (f.type) {
    case FilterType::Tent: return sampleTent(u, f.radius);
    case FilterType::Gaussian: return sampleTruncatedGaussian(u, f.sigma, f.radius);
    case FilterType::Box: break;
    }
    return (2.0 * u - 1.0) * f.radius;
}

} // namespace

Vec2 sampleFilterShaped(const Filter& filter, Vec2 u) { return {sample1D(filter, u.x), sample1D(filter, u.y)}; }

double filterPdf(const Filter& filter, Vec2 offset) { return pdf1D(filter, offset.x) * pdf1D(filter, offset.y); }

} // namespace drt
