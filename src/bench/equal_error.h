// Comparing two renderers at equal error. Each renderer is measured at several
// settings (sample counts, or any knobs it has); every setting is a point
// (seconds, relMSE), each the median over repetitions. A renderer's best curve
// is the Pareto front of its points: the least time that reaches each error.
// The time a renderer needs for a target relMSE is read off that front by
// linear interpolation in log-log space between the two front points around
// the target, the way an unbiased estimator's error ~ c / time behaves.
#pragma once

#include <string>
#include <vector>

namespace drt::bench {

// One setting of one renderer, over its repetitions.
struct SettingPoint {
    std::string setting; // e.g. "spp 16" or "blur_samples 37, +A0.3"
    double seconds = 0;  // median
    double relMse = 0;   // median
};

// The median (seconds, relMSE) of a setting's repetitions, taken separately:
// the typical time and the typical error of that setting.
SettingPoint medianPoint(const std::string& setting, const std::vector<double>& seconds,
                         const std::vector<double>& relMse);

// The best curve: the points no other point beats in both time and error,
// by increasing time (so by decreasing relMSE).
std::vector<SettingPoint> bestCurve(const std::vector<SettingPoint>& points);

struct TimeToError {
    enum class Kind {
        Interpolated, // between two front points
        AtMost,       // the cheapest point is already below the target: at most its time
        NotReached,   // no point gets down to the target
    };
    Kind kind = Kind::NotReached;
    double seconds = 0;       // meaningful unless NotReached
    std::string below, above; // the settings the value lies between (equal for AtMost)
};

// The time to reach relMSE `target` on the best curve of `points`.
TimeToError timeToReach(const std::vector<SettingPoint>& points, double target);

// Speed-up of `fast` over `slow` at equal error: slow.seconds / fast.seconds,
// and whether that is exact, a lower bound (">=": fast is AtMost, slow is
// exact) or unknown. Formatted as e.g. "3.41", ">= 2.10" or "-".
struct SpeedRatio {
    enum class Kind { Exact, AtLeast, AtMost, Unknown };
    Kind kind = Kind::Unknown;
    double ratio = 0;
};
SpeedRatio speedRatio(const TimeToError& slow, const TimeToError& fast);
std::string formatRatio(const SpeedRatio& ratio);
std::string formatTime(const TimeToError& time); // "1.84 s", "<= 0.52 s", "not reached"

} // namespace drt::bench
