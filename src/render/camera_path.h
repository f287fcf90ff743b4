// The camera over the shutter: each camera ray is made by the camera as it is
// at the ray's own time.
//
// Two things move a camera (scene.h CameraSpec, Scene::cameraKeys):
//   - keys: the camera as written at several times (an animated scene
//     evaluated at several clock values over the shutter). Between keys every
//     number (location, look_at, the vectors, angle, aperture, focal point and
//     distance) is interpolated linearly, then the camera is resolved
//     (render/camera.h); switches (orthographic, mapping) are the earlier key's.
//   - its placement: the resolved camera's location (a point) and direction,
//     right and up (vectors) are moved by CameraSpec::transform and then by
//     its motion chain at that time (scene/motion.h), so `motion { rotate
//     y*30 }` pans at a constant rate about the world origin and `translate -c
//     motion { rotate y*30 } translate c` about c.
// A zero-length shutter resolves the camera once, at that time: the same
// arithmetic as a still camera placed there, so the image is bit-identical.
#pragma once

#include "render/camera.h"
#include "scene/scene.h"

namespace drt {

class CameraPath {
public:
    // Throws RenderError if the camera cannot be resolved at some time over
    // the shutter (checked at 33 times across it).
    CameraPath(const Scene& scene, int width, int height);

    // True if rays at different times see different cameras.
    bool moving() const { return moving_; }
    // The camera at the shutter's opening (at every time, unless moving()).
    const ResolvedCamera& still() const { return still_; }
    // The camera at `time` (resolved anew when moving).
    ResolvedCamera at(double time) const;
    // A lens at some time over the shutter (lens samples are drawn then).
    bool hasLens() const { return hasLens_; }

private:
    const CameraSpec& base_;
    const std::vector<CameraKey>& keys_;
    int width_, height_;
    bool moving_ = false;
    bool hasLens_ = false;
    ResolvedCamera still_;
};

// The camera as written at `time`: the keys interpolated (or the spec itself
// without keys), before its placement is applied.
CameraSpec cameraSpecAt(const CameraSpec& base, const std::vector<CameraKey>& keys, double time);
// Moves a resolved camera by an affine placement (location as a point, the
// vectors as vectors; the focal plane keeps its place along the view).
void placeCamera(ResolvedCamera& camera, const Transform& placement);

} // namespace drt
