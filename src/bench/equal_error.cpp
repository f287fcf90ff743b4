#include "bench/equal_error.h"

#include "bench/stats.h"

#include <cmath>
#include <fmt/format.h>

namespace drt::bench {

SettingPoint medianPoint(const std::string& setting, const std::vector<double>& seconds,
                         const std::vector<double>& relMse) {
    return SettingPoint{setting, median(seconds), median(relMse)};
}

std::vector<SettingPoint> bestCurve(const std::vector<SettingPoint>& points) {
    std::vector<CostError> costs;
    for (const SettingPoint& p : points)
        costs.push_back({p.seconds, p.relMse});
    std::vector<SettingPoint> front;
    for (size_t i : paretoFront(costs))
        front.push_back(points[i]);
    return front;
}

TimeToError timeToReach(const std::vector<SettingPoint>& points, double target) {
    const std::vector<SettingPoint> front = bestCurve(points);
    TimeToError result;
    if (front.empty() || !(target > 0))
        return result;
    // The front runs from the cheapest (largest error) to the most accurate.
    if (front.front().relMse <= target) {
        result.kind = TimeToError::Kind::AtMost;
        result.seconds = front.front().seconds;
        result.below = result.above = front.front().setting;
        return result;
    }
    for (size_t i = 0; i + 1 < front.size(); ++i) {
        const SettingPoint& a = front[i];     // error above the target
        const SettingPoint& b = front[i + 1]; // the next, more accurate point
        if (b.relMse > target)
            continue;
        std::vector<CurvePoint> segment = {{a.relMse, a.seconds}, {b.relMse, b.seconds}};
        if (std::optional<double> t = interpolateLogLog(segment, target)) {
            result.kind = TimeToError::Kind::Interpolated;
            result.seconds = *t;
            result.above = a.setting;
            result.below = b.setting;
        }
        return result;
    }
    return result; // even the most accurate point stays above the target
}

SpeedRatio speedRatio(const TimeToError& slow, const TimeToError& fast) {
    using K = TimeToError::Kind;
    SpeedRatio r;
    if (slow.kind == K::NotReached || fast.kind == K::NotReached || !(slow.seconds > 0) ||
        !(fast.seconds > 0))
        return r;
    r.ratio = slow.seconds / fast.seconds;
    if (slow.kind == K::Interpolated && fast.kind == K::Interpolated)
        r.kind = SpeedRatio::Kind::Exact;
    else if (slow.kind == K::Interpolated && fast.kind == K::AtMost)
        r.kind = SpeedRatio::Kind::AtLeast; // fast needs at most its time: the ratio is at least this
    else if (slow.kind == K::AtMost && fast.kind == K::Interpolated)
        r.kind = SpeedRatio::Kind::AtMost;
    return r; // both AtMost: unknown
}

std::string formatRatio(const SpeedRatio& ratio) {
    switch (ratio.kind) {
    case SpeedRatio::Kind::Exact:
        return fmt::format("{:.2f}", ratio.ratio);
    case SpeedRatio::Kind::AtLeast:
        return fmt::format(">= {:.2f}", ratio.ratio);
    case SpeedRatio::Kind::AtMost:
        return fmt::format("<= {:.2f}", ratio.ratio);
    case SpeedRatio::Kind::Unknown:
        break;
    }
    return "-";
}

std::string formatTime(const TimeToError& time) {
    switch (time.kind) {
    case TimeToError::Kind::Interpolated:
        return fmt::format("{:.2f} s", time.seconds);
    case TimeToError::Kind::AtMost:
        return fmt::format("<= {:.2f} s", time.seconds);
    case TimeToError::Kind::NotReached:
        break;
    }
    return "not reached";
}

} // namespace drt::bench
