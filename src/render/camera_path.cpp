#include "render/camera_path.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>

namespace drt {

namespace {

double mix(double a, double b, double s) { return (1 - s) * a + s * b; }
Vec3 mix(const Vec3& a, const Vec3& b, double s) { return (1 - s) * a + s * b; }

template <class T>
std::optional<T> mixOptional(const std::optional<T>& a, const std::optional<T>& b, double s) {
    if (a && b) return mix(*a, *b, s);
    return s < 1 ? a : b;
}

bool hasPlacement(const CameraSpec& spec) { return !spec.transform.isIdentity() || !spec.motion.empty(); }

} // namespace

CameraSpec cameraSpecAt(const CameraSpec& base, const std::vector<CameraKey>& keys, double time) {
    if (keys.empty()) return base;
    if (keys.size() == 1 || time <= keys.front().time) return keys.front().camera;
    if (time >= keys.back().time) return keys.back().camera;
    size_t i = 0;
    while (i + 2 < keys.size() && keys[i + 1].time <= time) ++i;
    const CameraSpec &a = keys[i].camera, &b = keys[i + 1].camera;
    const double s = (time - keys[i].time) / (keys[i + 1].time - keys[i].time);
    CameraSpec c = a;
    c.location = mix(a.location, b.location, s);
    c.direction = mix(a.direction, b.direction, s);
    c.up = mix(a.up, b.up, s);
    c.right = mixOptional(a.right, b.right, s);
    c.sky = mix(a.sky, b.sky, s);
    c.lookAt = mixOptional(a.lookAt, b.lookAt, s);
    c.angle = mixOptional(a.angle, b.angle, s);
    c.verticalAngle = mixOptional(a.verticalAngle, b.verticalAngle, s);
    c.aperture = mix(a.aperture, b.aperture, s);
    c.focalPoint = mixOptional(a.focalPoint, b.focalPoint, s);
    c.focalDistance = mixOptional(a.focalDistance, b.focalDistance, s);
    return c;
}

void placeCamera(ResolvedCamera& camera, const Transform& placement) {
    const Vec3 axis = placement.vector(camera.viewAxis);
    camera.location = placement.point(camera.location);
    camera.direction = placement.vector(camera.direction);
    camera.right = placement.vector(camera.right);
    camera.up = placement.vector(camera.up);
    camera.focalDistance *= length(axis);
    camera.viewAxis = normalize(camera.direction);
    camera.lensU = normalize(camera.right);
    camera.lensV = normalize(camera.up);
}

CameraPath::CameraPath(const Scene& scene, int width, int height)
    : base_(scene.camera), keys_(scene.cameraKeys), width_(width), height_(height) {
    const double open = scene.camera.shutterOpen, close = scene.camera.shutterClose;
    bool changes = !scene.camera.motion.empty() || scene.cameraKeys.size() > 1;
    still_ = at(open); // validates the camera at the shutter's opening
    hasLens_ = still_.hasLens();
    moving_ = changes && open != close;
    if (!moving_) return;
    for (int k = 1; k <= 32; ++k) hasLens_ = at(open + (close - open) * k / 32.0).hasLens() || hasLens_;
}

ResolvedCamera CameraPath::at(double time) const {
    const double t = std::clamp(time, 0.0, 1.0); // motion spans time 0..1, as for objects
    const CameraSpec spec = cameraSpecAt(base_, keys_, t);
    ResolvedCamera camera = resolveCamera(spec, width_, height_);
    if (hasPlacement(spec)) placeCamera(camera, placementAt(spec.transform, spec.motion, t));
    camera.shutterOpen = base_.shutterOpen;
    camera.shutterClose = base_.shutterClose;
    return camera;
}

} // namespace drt
