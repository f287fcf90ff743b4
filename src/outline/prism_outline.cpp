#include "outline/prism_outline.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace drt {

namespace {

// POV-Ray compares prism points with this tolerance when closing sub-polygons.
constexpr double kSamePoint = 1e-10;

bool samePoint(Vec2 a, Vec2 b) { return std::fabs(a.x - b.x) < kSamePoint && std::fabs(a.y - b.y) < kSamePoint; }

// P(t) = A t^3 + B t^2 + C t + D on [0, 1].
struct Cubic {
    Vec2 A, B, C, D;
    Vec2 at(double t) const {
        return {((A.x * t + B.x) * t + C.x) * t + D.x, ((A.y * t + B.y) * t + C.y) * t + D.y};
    }
    // P'' = 6 A t + 2 B is linear in t: its largest length is at an end.
    double maxSecondDerivative() const {
        return std::max(std::hypot(2 * B.x, 2 * B.y), std::hypot(6 * A.x + 2 * B.x, 6 * A.y + 2 * B.y));
    }
};

Vec2 lin(double a, Vec2 p, double b, Vec2 q, double c = 0, Vec2 r = {}, double d = 0, Vec2 s = {}) {
    return {a * p.x + b * q.x + c * r.x + d * s.x, a * p.y + b * q.y + c * r.y + d * s.y};
}

// Appends the curve's points for t in [0, 1) (the end is the next segment's start).
void flatten(const Cubic& curve, double tolerance, std::vector<Vec2>& out) {
    const double m = curve.maxSecondDerivative();
    const int n = std::clamp(int(std::ceil(std::sqrt(m / (8 * tolerance)))), 1, 4096);
    for (int k = 0; k < n; ++k) out.push_back(curve.at(double(k) / n));
}

void closeContour(std::vector<Vec2>& contour, std::vector<std::vector<Vec2>>& contours) {
    if (contour.size() >= 2 && samePoint(contour.front(), contour.back())) contour.pop_back();
    if (contour.size() >= 3) contours.push_back(std::move(contour));
    contour.clear();
}

[[noreturn]] void tooFew() {
    throw std::invalid_argument("too few points in prism: a sub-polygon is not closed or control points are missing");
}

} // namespace

int minimumPrismPoints(PrismSource::Spline spline) {
    switch (spline) {
    case PrismSource::Spline::Linear: return 3;
    case PrismSource::Spline::Quadratic: return 5;
    case PrismSource::Spline::Cubic: return 6;
    case PrismSource::Spline::Bezier: return 4;
    }
    return 3;
}

std::vector<std::vector<Vec2>> prismContours(PrismSource::Spline spline, const std::vector<Vec2>& p) {
    const int count = static_cast<int>(p.size());
    if (count < minimumPrismPoints(spline)) tooFew();
    Vec2 lo = p[0], hi = p[0];
    for (const Vec2& q : p) {
        if (!std::isfinite(q.x) || !std::isfinite(q.y)) throw std::invalid_argument("prism point is not finite");
        lo = {std::min(lo.x, q.x), std::min(lo.y, q.y)};
        hi = {std::max(hi.x, q.x), std::max(hi.y, q.y)};
    }
    const double tolerance = kPrismTolerance * std::max({hi.x - lo.x, hi.y - lo.y, 1e-300});
    std::vector<std::vector<Vec2>> contours;
    std::vector<Vec2> contour;
    using S = PrismSource::Spline;
    if (spline == S::Linear) {
        Vec2 first = p[0];
        contour.push_back(p[0]);
        for (int i = 0; i + 1 < count; ++i) {
            if (samePoint(p[i + 1], first)) {
                closeContour(contour, contours);
                ++i;
                if (i + 1 < count) {
                    first = p[i + 1];
                    contour.push_back(first);
                }
            } else {
                contour.push_back(p[i + 1]);
            }
        }
        closeContour(contour, contours); // an unclosed last sub-polygon closes itself
        return contours;
    }
    if (spline == S::Bezier) {
        if (count % 4 > 1) tooFew();
        for (int i = 0; i + 3 < count; i += 4) {
            const Cubic c{lin(1, p[i + 3], -3, p[i + 2], 3, p[i + 1], -1, p[i]), lin(3, p[i + 2], -6, p[i + 1], 3, p[i]),
                          lin(3, p[i + 1], -3, p[i]), p[i]};
            // A segment that does not start where the last one ended: keep that end.
            if (!contour.empty() && !samePoint(p[i], p[i - 1])) contour.push_back(p[i - 1]);
            flatten(c, tolerance, contour);
            if (samePoint(p[i + 3], contour.front())) closeContour(contour, contours);
        }
        if (!contour.empty()) contour.push_back(p[count - 1 - count % 4]);
        closeContour(contour, contours);
        return contours;
    }
    const bool cubic = spline == S::Cubic;
    Vec2 first = p[1];
    for (int i = 0; i < count - 1; ++i) {
        if (i + (cubic ? 3 : 2) >= count) tooFew();
        Cubic c;
        if (cubic) {
            c = {lin(-0.5, p[i], 1.5, p[i + 1], -1.5, p[i + 2], 0.5, p[i + 3]),
                 lin(1, p[i], -2.5, p[i + 1], 2, p[i + 2], -0.5, p[i + 3]), lin(-0.5, p[i], 0.5, p[i + 2]), p[i + 1]};
        } else {
            c = {{0, 0}, lin(0.5, p[i], -1, p[i + 1], 0.5, p[i + 2]), lin(-0.5, p[i], 0.5, p[i + 2]), p[i + 1]};
        }
        flatten(c, tolerance, contour);
        if (samePoint(p[i + 2], first)) {
            closeContour(contour, contours);
            i += cubic ? 3 : 2;
            if (i + 2 < count) first = p[i + 2];
        }
    }
    closeContour(contour, contours);
    return contours;
}

} // namespace drt
