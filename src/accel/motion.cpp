#include "accel/motion.h"

#include <cmath>
#include <stdexcept>

namespace drt::accel {

namespace {

struct Quaternion {
    double w = 1, x = 0, y = 0, z = 0;
};

Quaternion multiply(const Quaternion& a, const Quaternion& b) {
    return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

// The rotation by `degrees` about a unit axis: (cos(theta/2), sin(theta/2) axis).
// Transform::rotateAxis builds the matching matrix (Rodrigues' formula).
Quaternion axisAngle(const Vec3& axis, double degrees) {
    const double half = degrees * kPi / 360.0;
    const double s = std::sin(half);
    return {std::cos(half), axis.x * s, axis.y * s, axis.z * s};
}

double lerp(double a, double b, double t) { return a + (b - a) * t; }

} // namespace

MotionPath::MotionPath(const Motion& motion) : scale_(motion.scale), translate_(motion.translate) {
    for (int i = 0; i < 3; ++i)
        if (!(std::isfinite(motion.scale[i]) && motion.scale[i] > 0))
            throw std::invalid_argument("motion scale must be positive and finite");
    if (!isFinite(motion.translate) || !isFinite(motion.rotate))
        throw std::invalid_argument("motion translate and rotate must be finite");
    // POV-Ray rotate: about x, then y, then z, so q = qz * qy * qx.
    const Quaternion q = multiply(axisAngle({0, 0, 1}, motion.rotate.z),
                                  multiply(axisAngle({0, 1, 0}, motion.rotate.y), axisAngle({1, 0, 0}, motion.rotate.x)));
    const double sinHalf = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
    if (sinHalf > 1e-15) {
        axis_ = Vec3{q.x, q.y, q.z} / sinHalf;
        angleDegrees_ = 2 * std::atan2(sinHalf, q.w) * 180.0 / kPi; // in [0, 360]
    }
}

Transform MotionPath::at(double t) const {
    const Vec3 s{lerp(1, scale_.x, t), lerp(1, scale_.y, t), lerp(1, scale_.z, t)};
    return Transform::scale(s).then(Transform::rotateAxis(axis_, t * angleDegrees_)).then(Transform::translate(t * translate_));
}

int MotionPath::timeStepCount() const {
    // Steps of at most 120 degrees keep every pair well inside Embree's shorter-arc slerp.
    return 1 + std::max(1, static_cast<int>(std::ceil(angleDegrees_ / 120.0)));
}

RTCQuaternionDecomposition MotionPath::timeStep(int index, const Vec3& frameOrigin) const {
    const double t = static_cast<double>(index) / (timeStepCount() - 1);
    RTCQuaternionDecomposition d;
    rtcInitQuaternionDecomposition(&d);
    // Embree's decomposition is translation * rotation * (scale, skew, shift).
    const Vec3 scale{lerp(1, scale_.x, t), lerp(1, scale_.y, t), lerp(1, scale_.z, t)};
    rtcQuaternionDecompositionSetScale(&d, float(scale.x), float(scale.y), float(scale.z));
    const Quaternion q = axisAngle(axis_, t * angleDegrees_);
    rtcQuaternionDecompositionSetQuaternion(&d, float(q.w), float(q.x), float(q.y), float(q.z));
    Vec3 translation = t * translate_;
    if (angleDegrees_ == 0) {
        // x -> Sc x + (Sc f + t T - f): the constant is linear in t, so Embree's
        // interpolation between steps is exact, and it is small (computed in
        // double) even when f is large.
        translation = translation + scale * frameOrigin - frameOrigin;
    } else {
        // R Sc f is not linear in t: pivot through Embree's shift instead
        // (rounded to float, as far from the origin as the object is).
        const Vec3 shift = scale * frameOrigin;
        rtcQuaternionDecompositionSetShift(&d, float(shift.x), float(shift.y), float(shift.z));
        translation = translation - frameOrigin;
    }
    rtcQuaternionDecompositionSetTranslation(&d, float(translation.x), float(translation.y), float(translation.z));
    return d;
}

} // namespace drt::accel
