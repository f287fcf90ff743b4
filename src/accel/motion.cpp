#include "accel/motion.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace drt::accel {

namespace {

constexpr int kMaxSteps = RTC_MAX_TIME_STEP_COUNT - 1; // 128
constexpr double kMaxStepDegrees = 90;
constexpr int kRotationScansPerUnitTime = 256;
constexpr double kRelativeTolerance = 1e-4;

// The smallest S <= kMaxSteps with every knot time on a multiple of 1/S, else 1.
int knotAlignedSteps(const MotionChain& chain) {
    std::vector<double> knots;
    for (const MotionStage& stage : chain)
        for (double t : stage.motion.knotTimes())
            if (t > 0 && t < 1) knots.push_back(t);
    for (int s = 1; s <= kMaxSteps; ++s) {
        bool aligned = true;
        for (double t : knots) aligned = aligned && std::fabs(t * s - std::round(t * s)) < 1e-9;
        if (aligned) return s;
    }
    return 1;
}

// Points that stand for the object when measuring how far two paths differ.
std::vector<Vec3> probePoints(const Vec3& lower, const Vec3& upper, double& size) {
    if (!(lower.x <= upper.x && lower.y <= upper.y && lower.z <= upper.z) || !isFinite(lower) || !isFinite(upper)) {
        size = 1;
        return {{-1, -1, -1}, {1, 1, 1}, {-1, 1, 1}, {1, -1, -1}, {0, 0, 0}};
    }
    size = std::max(length(upper - lower), 1e-12);
    std::vector<Vec3> points{0.5 * (lower + upper)};
    for (int c = 0; c < 8; ++c)
        points.push_back({(c & 1) ? upper.x : lower.x, (c & 2) ? upper.y : lower.y, (c & 4) ? upper.z : lower.z});
    return points;
}

} // namespace

InstanceMotion::InstanceMotion(const Transform& before, const MotionChain& chain, const Vec3& lower,
                               const Vec3& upper) {
    const std::optional<Mat4> restInverse = inverse(restPlacement(before, chain).matrix());
    if (!restInverse) throw std::invalid_argument("the object's transform is singular");
    const Transform toRest = *Transform::fromMatrix(*restInverse);
    const auto exact = [&](double t) {
        const Transform a = toRest.then(placementAt(before, chain, t));
        if (!isFinite({a.matrix().m[0][3], a.matrix().m[1][3], a.matrix().m[2][3]}))
            throw std::invalid_argument("the motion is not finite");
        return a;
    };

    // How far the path turns: tracked finely, since two far-apart samples of
    // a full turn look alike.
    double turned = 0;
    AffineParts previous = decomposeAbout(exact(0), {});
    for (int i = 1; i <= kRotationScansPerUnitTime; ++i) {
        const AffineParts next = decomposeAbout(exact(double(i) / kRotationScansPerUnitTime), {});
        turned += rotationBetween(previous, next);
        previous = next;
    }
    const int aligned = knotAlignedSteps(chain);
    const int needed = std::max(1, static_cast<int>(std::ceil(turned / kMaxStepDegrees - 1e-9)));
    if (needed > kMaxSteps)
        throw std::invalid_argument("the motion turns more than " + std::to_string(int(kMaxSteps * kMaxStepDegrees)) +
                                    " degrees over the shutter");
    int steps = aligned * ((needed + aligned - 1) / aligned);
    if (steps > kMaxSteps) steps = needed;

    double size = 1;
    const std::vector<Vec3> probes = probePoints(lower, upper, size);
    const Vec3 fallback = probes.front();
    for (;;) {
        std::vector<Transform> ends, mids;
        for (int k = 0; k <= steps; ++k) ends.push_back(exact(double(k) / steps));
        for (int k = 0; k < steps; ++k) mids.push_back(exact((k + 0.5) / steps));
        std::vector<PivotSample> samples;
        for (int k = 0; k < steps; ++k) samples.push_back({ends[k], mids[k], ends[k + 1], 0.5});
        pivot_ = bestPivot(samples, fallback);
        steps_.clear();
        for (const Transform& a : ends) {
            steps_.push_back(decomposeAbout(a, pivot_));
            if (steps_.size() > 1) alignRotation(steps_[steps_.size() - 2], steps_.back());
        }
        double error = 0;
        for (int k = 0; k < steps; ++k) {
            const Transform approx = at((k + 0.5) / steps);
            for (const Vec3& p : probes) error = std::max(error, length(approx.point(p) - mids[k].point(p)));
        }
        if (error <= kRelativeTolerance * size || steps * 2 > kMaxSteps) break;
        steps *= 2;
    }
}

Transform InstanceMotion::at(double t) const {
    const int segments = timeStepCount() - 1;
    if (segments < 1) return composeParts(steps_.front());
    const double x = std::clamp(t, 0.0, 1.0) * segments;
    const int k = std::min(segments - 1, static_cast<int>(std::floor(x)));
    return composeParts(interpolateParts(steps_[k], steps_[k + 1], x - k));
}

RTCQuaternionDecomposition InstanceMotion::timeStep(int index, const Vec3& frameOrigin) const {
    const AffineParts& p = steps_.at(index);
    // x -> translation + R (U x + shift) on rest-world points; on level points
    // x - f, mapped to world minus f: translation - f + R (U x + shift + U f).
    const auto& u = p.upper;
    const Vec3 uf{u[0] * frameOrigin.x + u[1] * frameOrigin.y + u[2] * frameOrigin.z,
                  u[3] * frameOrigin.y + u[4] * frameOrigin.z, u[5] * frameOrigin.z};
    const Vec3 shift = p.shift + uf, translation = p.translation - frameOrigin;
    RTCQuaternionDecomposition d;
    rtcInitQuaternionDecomposition(&d);
    rtcQuaternionDecompositionSetScale(&d, float(u[0]), float(u[3]), float(u[5]));
    rtcQuaternionDecompositionSetSkew(&d, float(u[1]), float(u[2]), float(u[4]));
    rtcQuaternionDecompositionSetShift(&d, float(shift.x), float(shift.y), float(shift.z));
    rtcQuaternionDecompositionSetQuaternion(&d, float(p.rotation[0]), float(p.rotation[1]), float(p.rotation[2]),
                                            float(p.rotation[3]));
    rtcQuaternionDecompositionSetTranslation(&d, float(translation.x), float(translation.y), float(translation.z));
    return d;
}

bool InstanceMotion::translationOnly() const {
    const AffineParts& first = steps_.front();
    return std::all_of(steps_.begin(), steps_.end(), [&](const AffineParts& p) {
        return p.rotation == first.rotation && p.upper == first.upper && p.shift == first.shift;
    });
}

void InstanceMotion::stepRows(int index, const Vec3& frameOrigin, float rows[12]) const {
    const Transform step = composeParts(steps_.at(size_t(index)));
    const Mat4& m = step.matrix();
    // Level points are rest-world points minus f, mapped to world minus f:
    // x -> M (x + f) - f.
    const double f[3] = {frameOrigin.x, frameOrigin.y, frameOrigin.z};
    for (int r = 0; r < 3; ++r) {
        double t = m.m[r][3] - f[r];
        for (int c = 0; c < 3; ++c) {
            rows[4 * r + c] = float(m.m[r][c]);
            t += m.m[r][c] * f[c];
        }
        rows[4 * r + 3] = float(t);
    }
}

} // namespace drt::accel
