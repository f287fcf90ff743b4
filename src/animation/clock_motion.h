// Private to src/animation: merging evaluations of a scene at several clock
// values into one moving scene (clock_motion.cpp), and what the adaptive
// choice of clock values (evaluate_frame.cpp) measures with.
#pragma once

#include "animation/animation.h"

#include <map>
#include <optional>
#include <tuple>
#include <vector>

namespace drt {

struct Evaluation {
    double time = 0; // scene time in the frame
    Scene scene;
};

// An object's or light's identity: where it was made (file, line, column)
// and its order among those made there.
using Identity = std::tuple<int, int, int, int>;
std::vector<Identity> identities(const std::vector<SourceLoc>& locs);
std::map<Identity, size_t> indexByIdentity(const std::vector<Identity>& ids);
template <class T>
std::vector<Identity> identitiesOf(const std::vector<T>& items) {
    std::vector<SourceLoc> locs;
    for (const T& item : items) locs.push_back(item.loc);
    return identities(locs);
}
inline std::vector<Identity> objectIdentities(const Scene& s) { return identitiesOf(s.objects); }
inline std::vector<Identity> lightIdentities(const Scene& s) { return identitiesOf(s.lights); }

// Where `object` (evaluated at `time`) is, as a map from `base`'s object
// space; nothing when their shapes differ by more than a known affine map.
std::optional<Transform> placementIn(const Object& base, const Object& object, double time);
// A point inside the object (its bounds' centre) and its size, in object space.
void objectExtent(const Object& object, Vec3& centre, double& size);
// A light's pose (after its own motion) at `time`.
LightKey lightPose(const Light& light, double time);
bool sameCamera(const CameraSpec& a, const CameraSpec& b);

// Evaluations sorted by time, the first at the shutter's opening (the base).
Scene mergeEvaluations(const std::vector<Evaluation>& evaluations, FrameReport& report);

} // namespace drt
