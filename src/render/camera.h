// The POV-Ray perspective camera with Cook's thin lens and shutter, and the
// orthographic camera.
//
// Parameters (scene.h CameraSpec) and their meaning here:
//   location, direction, up, right  POV-Ray's camera vectors (left-handed: x right, y up, z in).
//                                   right unset -> x * width/height (drt; POV-Ray's own default is 1.33).
//   sky, look_at                    look_at re-aims direction/right/up about sky, keeping their lengths;
//                                   the handedness is kept from the sign of (up x direction) . right.
//   angle                           horizontal field of view: |direction| = 0.5 |right| / tan(angle/2).
//   aperture                        lens *diameter* in scene units (0: pinhole, draws no lens sample).
//   focal_distance / focal_point    the focal plane, perpendicular to the view axis at focal_distance, else at
//                                   |focal_point - location| (Euclidean, as POV-Ray 3.7), else at |direction|.
//   orthographic                    parallel rays along direction, from location + x0 right + y0 up (the view is
//                                   |right| x |up|); with angle, right and up scale so the width is
//                                   2 d tan(angle/2), d = |look_at - location| (|direction| without look_at).
//                                   No lens: aperture must be 0.
//   mapping (non-planar cameras, render/camera_mappings.cpp; x0, y0 as below, a = angle in radians;
//   d, r, u the unit direction, right, up, |r|, |u| their lengths):
//     fisheye          X = 2 x0 |r|, Y = 2 y0 |u|, rho = hypot(X, Y) <= 1 (else no ray), phi = atan2(Y, X),
//                      theta = rho a / 2: D = sin theta (cos phi r + sin phi u) + cos theta d.
//     ultra_wide_angle D = sin(x0 a) r + sin(y0 a |u|/|r|) u + cos(x0 a) cos(y0 a |u|/|r|) d.
//     panoramic        p = (1 - px/width) pi, q = 2 y0 pi/2: D = cos p right + tan q up + sin p direction
//                      (the vectors with their lengths; tan q capped at +-2e10 at the poles).
//     cylinder 1       D = sin(x0 a) r + y0 |u| u + cos(x0 a) d (the axis is up).
//     cylinder 2       D = x0 |r| r + sin(y0 a) u + cos(y0 a) d (the axis is right).
//     cylinder 3       origin location + y0 |u| u, D = sin(x0 a) r + cos(x0 a) d.
//     cylinder 4       origin location + x0 |r| r, D = sin(y0 a) u + cos(y0 a) d.
//     spherical        h, v the horizontal, vertical angles: direction turned by y0 v towards up, then by
//                      x0 h about up towards right (longitude/latitude).
//     omnimax          X = 2 x0, Y = 2 y0, squeezed to the dome with the aspect A = |r|/|u|: for
//                      A > 1.283458, X *= A/1.283458 and Y = (Y - 1)/1.283458 + 1; for 1 < A <= 1.283458,
//                      Y = (Y - 1)/A + 1; else Y /= A. rho = hypot(X, Y) <= 1 (else no ray), phi the polar
//                      angle of (X, Y), theta = 1.411269 rho - 0.09439 rho^3 + 0.25674 rho^5 (the angle is not
//                      used): D = sin theta (cos phi r + sin phi u) + cos theta d, and no ray where D points
//                      more than 45 degrees below the axis (sin phi sin theta < -cos theta).
//                      No lens: aperture must be 0.
//   shutter_open / shutter_close    ray time = lerp(open, close, u), clamped to Motion's [0, 1] (objects hold
//                                   their end poses outside it); equal values draw no time sample.
#pragma once

#include "accel/accel.h"
#include "core/vec.h"
#include "scene/scene.h"

namespace drt {

struct ResolvedCamera {
    Vec3 location;
    Vec3 direction; // centre of the image, unnormalised
    Vec3 right;     // spans the image width
    Vec3 up;        // spans the image height
    int width = 1;
    int height = 1;
    // Thin lens: radius = aperture / 2; the lens disc spans lensU, lensV (unit).
    double lensRadius = 0;
    double focalDistance = 1; // along the unit view axis
    Vec3 viewAxis{0, 0, 1};   // unit direction
    Vec3 lensU{1, 0, 0}, lensV{0, 1, 0};
    double shutterOpen = 0;
    double shutterClose = 0;
    // Parallel rays along direction from location + x0 right + y0 up.
    bool orthographic = false;
    // Non-planar cameras (see above); angles in radians.
    CameraMapping mapping = CameraMapping::Planar;
    double mappingAngle = kPi / 2;
    double verticalAngle = kPi;

    bool hasLens() const { return lensRadius > 0; }
    bool hasShutter() const { return shutterOpen != shutterClose; }
    // Ray time for a sample u in [0, 1).
    double timeAt(double u) const { return shutterOpen + (shutterClose - shutterOpen) * u; }

    // The primary ray through image position (px, py) (pixel (x, y) covers
    // [x, x+1) x [y, y+1), y down), through lens sample `lens` in [0,1)^2 (ignored
    // without a lens) at `time`: D = direction + x0 right + y0 up with
    // x0 = px/width - 0.5, y0 = 0.5 - py/height.
    Ray generateRay(double px, double py, Vec2 lens, double time) const;
    // False where the camera traces no ray (outside a fisheye's or omnimax's circle): the
    // pixel there is black, as in POV-Ray.
    bool covers(double px, double py) const;

private:
    Ray mappedRay(double px, double py) const;
};

// Throws RenderError on input that would produce NaN (zero vectors, sky
// parallel to the view direction, non-positive image size, bad angle).
ResolvedCamera resolveCamera(const CameraSpec& spec, int width, int height);

} // namespace drt
