// Time in the scene model: transforms over the shutter (`motion { ... }`) and
// their place in an object's chain of transforms.
//
// Scene time t runs over one frame: 0 is the frame's own clock, 1 the next
// frame's (for a still image the span motion blocks are written for); the
// camera's shutter opens and closes at times in [0, 1].
//
// A motion path is a transform-valued function of t, given by keys. Each key
// holds a scale, a rotation (degrees about x, then y, then z, as `rotate`) and a
// translation, applied in that order. Between keys every component is
// interpolated on its own, linearly (or along a cubic Hermite spline through
// the keys with `spline`): a rotation's angles, not its matrix, so `rotate
// y*720` turns twice and `rotate <0, 360, 0> * t` is what POV-Ray's `rotate
// y*360*clock` gives an animation. Before the first key and after the last the
// path holds still.
//
// Placement over time: an object's transforms up to its first motion form
// Object::transform; each motion is a MotionStage with the static transforms
// written after it, so at time t
//   world(t) = transform, then motion[0](t), then after[0], then motion[1](t), ...
// and `translate -c motion { rotate y*360 } translate c` spins about c. The
// rest pose is the same chain with every motion the identity: textures,
// interiors and clips are placed in it and move with their object.
//
// Sampled paths come from re-evaluating an animated scene at several clock
// values over the shutter: transforms at increasing times, interpolated as an
// affine motion about a pivot (AffineParts below).
#pragma once

#include "core/transform.h"
#include "core/vec.h"

#include <array>
#include <vector>

namespace drt {

struct MotionKey {
    double time = 1;
    Vec3 translate{0, 0, 0};
    Vec3 rotate{0, 0, 0}; // degrees, as `rotate`
    Vec3 scale{1, 1, 1};
    bool operator==(const MotionKey&) const = default;
};

struct Motion {
    // Keyed path: times strictly increasing (the .drt parser puts an identity
    // key at time 0 unless one is given there).
    std::vector<MotionKey> keys;
    bool spline = false;
    // Sampled path (when samples is not empty): transforms at strictly
    // increasing times, interpolated about `pivot`.
    std::vector<double> sampleTimes;
    std::vector<Transform> samples;
    Vec3 pivot;

    // The transform at time t.
    Transform at(double t) const;
    bool sampled() const { return !samples.empty(); }
    // The times where the path changes direction (keys or samples).
    std::vector<double> knotTimes() const;
};

// A one-key motion as `motion { translate .. rotate .. scale .. }` writes it:
// the identity at time 0, these at time 1.
Motion motionTo(const Vec3& translate, const Vec3& rotate = {0, 0, 0}, const Vec3& scale = {1, 1, 1});

// A sampled motion through `samples` at `times`, its pivot chosen by bestPivot
// (`fallbackPivot` where the samples do not decide it).
Motion sampledMotion(std::vector<double> times, std::vector<Transform> samples, const Vec3& fallbackPivot);

struct MotionStage {
    Motion motion;
    Transform after; // static transforms written after the motion
};
using MotionChain = std::vector<MotionStage>;

// `before`, then the chain at time t.
Transform placementAt(const Transform& before, const MotionChain& chain, double t);
// `before`, then the chain with every motion the identity.
Transform restPlacement(const Transform& before, const MotionChain& chain);

// Appends a static transform to a placement (to the last stage's `after`, or
// to `before` when there is no motion).
void appendTransform(Transform& before, MotionChain& chain, const Transform& t);
// Appends another placement (`outerBefore` then `outerChain`) after this one.
void appendPlacement(Transform& before, MotionChain& chain, const Transform& outerBefore,
                     const MotionChain& outerChain);

// ------------------------------------------------------------ affine motion
// An affine map as Embree's quaternion decomposition writes it, taken about a
// pivot p: x -> translation + R (U x + shift), with R a rotation (unit
// quaternion w, x, y, z), U upper triangular (scale and skew) and shift = -U p,
// so translation is where p goes. Interpolating two of them (translation, U
// and shift linearly, R by slerp along the shorter arc) moves p on a straight
// line and turns about it: a rotation about a fixed axis through p, plus a
// linear translation and scale, is interpolated exactly.
struct AffineParts {
    Vec3 translation;
    std::array<double, 4> rotation{1, 0, 0, 0};
    std::array<double, 6> upper{1, 0, 0, 1, 0, 1}; // U00 U01 U02 U11 U12 U22
    Vec3 shift;
};
AffineParts decomposeAbout(const Transform& a, const Vec3& pivot);
Transform composeParts(const AffineParts& parts);
// s in [0, 1]; b's quaternion is taken on a's side (the shorter arc).
AffineParts interpolateParts(const AffineParts& a, const AffineParts& b, double s);
// The angle in degrees between the rotations of a and b (shorter arc).
double rotationBetween(const AffineParts& a, const AffineParts& b);
// Flips b's quaternion sign to a's side, so Embree's shorter-arc slerp and
// interpolateParts agree.
void alignRotation(const AffineParts& a, AffineParts& b);

// The pivot p whose path is closest to straight between the samples: the
// least-squares solution of sum |middle p - ((1 - w) first p + w last p)|^2
// over the samples (middle the transform a fraction w of the way from first to
// last), nudged toward `fallback` along the directions this leaves free (a
// rotation's axis; everything when nothing turns).
struct PivotSample {
    Transform first, middle, last;
    double weight = 0.5;
};
Vec3 bestPivot(const std::vector<PivotSample>& samples, const Vec3& fallback);

} // namespace drt
