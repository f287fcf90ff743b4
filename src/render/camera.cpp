#include "render/camera.h"

#include "sampling/warp.h"
#include "render/render.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace drt {

namespace {

constexpr double kMaxLensRadius = 1e15;

void requireUsable(const Vec3& v, const char* what) {
    if (!isFinite(v) || dot(v, v) == 0.0) throw RenderError(std::string("camera: ") + what + " must be a finite non-zero vector");
}

} // namespace

ResolvedCamera resolveCamera(const CameraSpec& spec, int width, int height) {
    if (width < 1 || height < 1) throw RenderError("camera: image size must be at least 1x1");
    if (!isFinite(spec.location)) throw RenderError("camera: location must be finite");

    ResolvedCamera cam;
    cam.width = width;
    cam.height = height;
    cam.location = spec.location;
    cam.direction = spec.direction;
    cam.up = spec.up;
    cam.right = spec.right.value_or(Vec3(static_cast<double>(width) / height, 0, 0));
    requireUsable(cam.direction, "direction");
    requireUsable(cam.up, "up");
    requireUsable(cam.right, "right");

    // Orthographic: the distance the angle's view width is measured at.
    const double orthoDistance = spec.lookAt ? length(*spec.lookAt - spec.location) : length(spec.direction);
    const bool planar = spec.mapping == CameraMapping::Planar;
    if (!planar && spec.orthographic) throw RenderError("camera: an orthographic camera cannot also be a non-planar one");
    if (spec.angle && planar) {
        const double angle = *spec.angle;
        if (!(angle > 0 && angle < 180)) throw RenderError("camera: angle must be in (0, 180) degrees");
        // POV-Ray: |direction| = 0.5 |right| / tan(angle / 2).
        cam.direction = normalize(cam.direction) * (0.5 * length(cam.right) / std::tan(angle * kPi / 360.0));
    }

    if (spec.lookAt) {
        // POV-Ray's look_at: direction points at the target, right = sky x direction,
        // up = direction x right; every vector keeps its length, and right keeps the
        // handedness the vectors had before.
        requireUsable(spec.sky, "sky");
        const Vec3 toTarget = *spec.lookAt - spec.location;
        if (!isFinite(toTarget) || dot(toTarget, toTarget) == 0.0)
            throw RenderError("camera: look_at must differ from location");
        const double handedness = dot(cross(cam.up, cam.direction), cam.right);
        const Vec3 d = normalize(toTarget);
        const Vec3 r = cross(spec.sky, d);
        if (length(r) <= 1e-12 * length(spec.sky)) throw RenderError("camera: sky is parallel to the look_at direction");
        const Vec3 rightUnit = normalize(r);
        const Vec3 upUnit = cross(d, rightUnit);
        cam.direction = d * length(cam.direction);
        cam.right = rightUnit * (handedness > 0 ? length(cam.right) : -length(cam.right));
        cam.up = upUnit * length(cam.up);
    }

    if (spec.orthographic) {
        cam.orthographic = true;
        if (spec.aperture != 0) throw RenderError("camera: an orthographic camera has no lens (aperture must be 0)");
        if (spec.angle) {
            // |direction| is now |right| / (2 tan(angle / 2)); scaling right by
            // d / |direction| makes the width 2 d tan(angle / 2) (POV-Ray's rule).
            const double k = orthoDistance / length(cam.direction);
            if (!(k > 0) || !std::isfinite(k)) throw RenderError("camera: look_at must differ from location");
            cam.right = cam.right * k;
            cam.up = cam.up * k;
        }
    }

    if (!planar) {
        cam.mapping = spec.mapping;
        if (spec.aperture != 0) throw RenderError("camera: only perspective cameras have a lens (aperture must be 0)");
        const bool spherical = spec.mapping == CameraMapping::Spherical;
        const double angle = spec.angle.value_or(spherical ? 360.0 : 90.0);
        const double vertical = spec.verticalAngle.value_or(spherical ? angle / 2 : 0.0);
        if (!(angle > 0) || !std::isfinite(angle) || !(vertical >= 0) || !std::isfinite(vertical))
            throw RenderError("camera: angle must be positive and finite");
        cam.mappingAngle = angle * kPi / 180;
        cam.verticalAngle = vertical * kPi / 180;
    }

    if (planar && length(cross(cam.up, cam.direction)) <= 1e-12 * length(cam.up) * length(cam.direction))
        throw RenderError(spec.lookAt ? "camera: up is parallel to the look_at direction"
                                      : "camera: up is parallel to the direction");
    cam.viewAxis = normalize(cam.direction);
    cam.lensU = normalize(cam.right);
    cam.lensV = normalize(cam.up);

    if (!(spec.aperture >= 0) || !std::isfinite(spec.aperture)) throw RenderError("camera: aperture must be >= 0");
    // Embree traces in float: a lens point (the ray origin) beyond ~1e15 would
    // overflow its squared-length arithmetic. No real lens is that wide.
    cam.lensRadius = std::min(spec.aperture / 2, kMaxLensRadius);
    if (spec.focalDistance) {
        if (!(*spec.focalDistance > 0) || !std::isfinite(*spec.focalDistance))
            throw RenderError("camera: focal distance must be positive");
        cam.focalDistance = *spec.focalDistance;
    } else if (spec.focalPoint) {
        // POV-Ray 3.7 uses the Euclidean distance to the focal point as the depth
        // of the focal plane (an off-axis focal point is itself slightly out of focus).
        cam.focalDistance = length(*spec.focalPoint - spec.location);
        if (!(cam.focalDistance > 0) || !std::isfinite(cam.focalDistance))
            throw RenderError("camera: focal_point must differ from location");
    } else {
        cam.focalDistance = length(cam.direction);
    }

    if (!std::isfinite(spec.shutterOpen) || !std::isfinite(spec.shutterClose))
        throw RenderError("camera: shutter times must be finite");
    cam.shutterOpen = spec.shutterOpen;
    cam.shutterClose = spec.shutterClose;
    return cam;
}

Ray ResolvedCamera::generateRay(double px, double py, Vec2 lens, double time) const {
    const double x0 = px / width - 0.5;
    const double y0 = 0.5 - py / height;
    Ray ray;
    // Motion spans time 0..1; outside it objects hold their end positions.
    ray.time = std::clamp(time, 0.0, 1.0);
    if (mapping != CameraMapping::Planar) {
        const Ray mapped = mappedRay(px, py);
        ray.origin = mapped.origin;
        ray.direction = mapped.direction;
        return ray;
    }
    if (orthographic) {
        ray.origin = location + x0 * right + y0 * up;
        ray.direction = direction;
        return ray;
    }
    ray.origin = location;
    ray.direction = direction + x0 * right + y0 * up;
    if (lensRadius > 0) {
        // Thin lens: every ray through the lens point meets the pinhole ray where it
        // crosses the focal plane, at depth focalDistance along the view axis.
        const double along = dot(ray.direction, viewAxis);
        if (along > 0) {
            const Vec3 focus = location + ray.direction * (focalDistance / along);
            const Vec2 disc = squareToConcentricDisc(lens);
            ray.origin = location + lensRadius * (disc.x * lensU + disc.y * lensV);
            ray.direction = focus - ray.origin;
        }
    }
    return ray;
}

} // namespace drt
