// camera { }: the camera types, the vectors, the lens and the shutter. In the
// POV-Ray dialect the vectors are resolved as POV-Ray's parser resolves them
// (angle, look_at and transforms in order; right defaults to <1.33, 0, 0>),
// `aperture` is POV-Ray's (twice the model's lens diameter) and needs
// `blur_samples`. In the .drt dialect the camera is kept as written and the
// renderer resolves it for the image size (render/camera.h).
#include "lang/evaluator.h"

#include <cmath>
#include <fmt/format.h>

namespace drt::lang {

using Kind = Value::Kind;

namespace {

// The camera vectors after POV-Ray's angle and look_at rules (the same as
// render/camera.cpp's resolveCamera), so that a transform can act on them.
// `orthoScale`: POV-Ray's orthographic rule (parse.cpp Parse_Camera): with
// angle, or with neither up nor right given, right and up are scaled by
// |look_at - location| / |direction| (look_at defaults to <0, 0, 1>), which
// gives the view the perspective camera has at the look_at point.
void resolveCameraVectors(CameraSpec& c, bool orthoScale = false) {
    const double lookAtDistance = length(c.lookAt.value_or(Vec3(0, 0, 1)) - c.location);
    Vec3 right = c.right.value_or(Vec3(1.33, 0, 0));
    Vec3 dir = c.direction, up = c.up;
    // The non-planar cameras keep angle for their mapping; it leaves direction alone.
    const bool planar = c.mapping == CameraMapping::Planar;
    if (planar && c.angle && *c.angle > 0 && *c.angle < 180 && length(dir) > 0)
        dir = normalize(dir) * (0.5 * length(right) / std::tan(*c.angle * kPi / 360.0));
    if (c.lookAt) {
        const Vec3 to = *c.lookAt - c.location;
        const Vec3 r = cross(c.sky, to);
        if (length(to) > 0 && length(r) > 0) {
            const double handedness = dot(cross(up, dir), right);
            const Vec3 d = normalize(to);
            const Vec3 ru = normalize(cross(c.sky, d));
            dir = d * length(dir);
            right = ru * (handedness > 0 ? length(right) : -length(right));
            up = cross(d, ru) * length(up);
        } else if (length(to) > 0 && length(right) > 0) {
            // Looking along the sky (a camera straight above look_at): POV-Ray keeps
            // right as it is and turns up to be square to it and to the new direction.
            const Vec3 d = normalize(to);
            dir = d * length(dir);
            up = normalize(cross(d, right)) * length(up);
        }
    }
    if (orthoScale) {
        const double k = lookAtDistance / length(dir);
        if (lookAtDistance > 1e-10 && std::isfinite(k)) {
            right = right * k;
            up = up * k;
        }
    }
    c.direction = dir;
    c.right = right;
    c.up = up;
    if (planar) c.angle.reset();
    c.lookAt.reset();
}

} // namespace

CameraSpec Evaluator::camera(const CameraSpec& base, SourceLoc loc) {
    const bool pov = scene().povCameraRules;
    expectSymbol("{", "after 'camera'");
    BlockScope scope(*this, "camera", loc);
    CameraSpec c = scene().modifyBlocks ? base : CameraSpec{};
    c.loc = loc;
    if (pov && !c.right) c.right = Vec3(1.33, 0, 0);
    double aperture = pov ? c.aperture * 2 : c.aperture; // POV-Ray's aperture is twice the model's diameter
    int blurSamples = aperture > 0 ? 1 : 0;
    SourceLoc apertureLoc = loc, lookAtLoc, focalPointLoc, shutterLoc, angleLoc, verticalLoc;
    bool nonPerspective = false;
    // Orthographic (POV-Ray): the scaling rule is applied once, when the
    // vectors are first resolved (at a transform or at the end).
    bool hadUp = false, hadRight = false, hadAngle = false, orthoPending = true;
    auto resolve = [&] {
        const bool scale = c.orthographic && orthoPending && ((!hadUp && !hadRight) || hadAngle);
        resolveCameraVectors(c, scale);
        if (c.orthographic) orthoPending = false;
    };
    bool first = true;
    for (;;) {
        const Token t = peek();
        if (t.is("}")) {
            next();
            break;
        }
        // After a motion, a transform goes after it: the motion chain moves
        // the resolved camera at each ray's time (render/camera_path.h).
        if (t.isWord("motion")) {
            next();
            if (pov) resolve();
            c.motion.push_back(MotionStage{motionBlock(), Transform()});
            first = false;
            continue;
        }
        if (std::optional<Transform> tr = transformItem(); tr && !c.motion.empty()) {
            c.motion.back().after = c.motion.back().after.then(*tr);
            continue;
        } else if (tr) {
            if (pov) {
                resolve();
            } else if (!c.right && !c.lookAt && !(tr->vector(Vec3(1, 0, 0)) == Vec3(1, 0, 0))) {
                // The renderer derives right along x from the image size: a turned camera needs it given.
                error(t.loc, "a camera turned by a transform needs 'right' or 'look_at' before the transform");
            }
            c.location = tr->point(c.location);
            c.direction = tr->vector(c.direction);
            c.up = tr->vector(c.up);
            if (c.right) c.right = tr->vector(*c.right);
            if (!pov) {
                c.sky = tr->vector(c.sky);
                if (c.lookAt) c.lookAt = tr->point(*c.lookAt);
            }
            if (c.focalPoint) c.focalPoint = tr->point(*c.focalPoint);
            first = false;
            continue;
        }
        next();
        if (t.kind != TokenKind::Word) failInBlock(t, "a camera keyword or '}'");
        const std::string& w = t.text;
        const SourceLoc at = peek().loc;
        if (const Cell id = useIndexed(t); id && id->kind == Kind::Camera && first) {
            c = *id->camera;
            aperture = pov ? c.aperture * 2 : c.aperture;
            if (c.orthographic) orthoPending = false; // resolved when it was declared
            first = false;
            continue;
        } else if (id) {
            fail(t.loc, "'" + w + "' is " + kindName(*id) + ", not a camera");
        }
        first = false;
        if (const std::optional<CameraWord> type = cameraWordNamed(w)) {
            c.orthographic = type->orthographic;
            c.mapping = type->mapping;
            if (w == "cylinder") {
                const double n = floatExpr("the cylinder camera type");
                if (!(n >= 1 && n < 5) || (n != std::floor(n) && !pov))
                    fail(at, (pov ? "invalid cylinder camera type: valid are types 1 to 4"
                                  : "'cylinder' camera type must be 1, 2, 3 or 4") +
                                 got(n));
                // POV-Ray truncates the type number.
                c.mapping = static_cast<CameraMapping>(static_cast<int>(CameraMapping::Cylinder1) + int(n) - 1);
            }
        } else if (w == "mesh_camera") {
            unsupported("camera-" + w, t.loc, "'" + w + "' camera is not supported; a perspective camera is used");
            nonPerspective = true;
            expectSymbol("{", "after 'mesh_camera'"), skipBlock();
        } else if (w == "location") {
            c.location = vectorExpr();
        } else if (w == "look_at") {
            lookAtLoc = at;
            c.lookAt = vectorExpr();
        } else if (w == "direction") {
            c.direction = vectorExpr();
            requireNonZero(c.direction, at, "'direction'");
        } else if (w == "right") {
            c.right = vectorExpr();
            hadRight = true;
            requireNonZero(*c.right, at, "'right'");
        } else if (w == "up") {
            c.up = vectorExpr();
            hadUp = true;
            requireNonZero(c.up, at, "'up'");
        } else if (w == "sky") {
            c.sky = vectorExpr();
            requireNonZero(c.sky, at, "'sky'");
        } else if (w == "angle") {
            angleLoc = at;
            hadAngle = true;
            // The orthographic camera's angle is optional (POV-Ray: 0, which
            // only triggers the scaling rule).
            if (pov && c.orthographic && !startsFloat(peekOperator())) continue;
            const double a = floatExpr("the angle");
            c.verticalAngle.reset();
            if (!pov) {
                c.angle = a;
                if (acceptSymbol(",")) verticalLoc = peek().loc, c.verticalAngle = floatExpr("the vertical angle");
                continue;
            }
            if (c.mapping != CameraMapping::Planar) {
                if (a < 0) fail(at, "'angle' must be positive" + got(a));
                c.angle = a;
                if (c.mapping == CameraMapping::Spherical && acceptSymbol(",")) {
                    const SourceLoc vat = peek().loc;
                    if (startsFloat(peekOperator())) c.verticalAngle = floatExpr();
                    if (c.verticalAngle && *c.verticalAngle < 0) fail(vat, "the vertical angle must be positive");
                }
                continue;
            }
            if (acceptSymbol(",")) {
                floatExpr();
                warnOnce("angle-vertical", at, "the vertical camera angle is ignored (it follows from up/right)");
            }
            if (a > 0 && a < 180) c.angle = a;
            else if (c.orthographic && a == 0) c.angle.reset();
            else if (!nonPerspective) fail(at, "'angle' must be between 0 and 180 degrees" + got(a));
        } else if (w == "aperture") {
            apertureLoc = at;
            aperture = floatExpr("the aperture");
            if (!pov && aperture < 0) error(at, "'aperture' must not be negative" + got(aperture));
        } else if (w == "blur_samples") {
            blurSamples = intExpr("the number of blur samples");
            if (acceptSymbol(",")) blurSamples = std::max(blurSamples, intExpr("the number of blur samples"));
        } else if (w == "focal_point") {
            focalPointLoc = at;
            c.focalPoint = vectorExpr();
        } else if (w == "focal_distance") {
            c.focalDistance = floatExpr("the focal distance");
            if (!(*c.focalDistance > 0)) error(at, "'focal_distance' must be positive" + got(*c.focalDistance));
        } else if (w == "shutter_open" || w == "shutter_close") {
            shutterLoc = at;
            (w == "shutter_open" ? c.shutterOpen : c.shutterClose) = floatExpr("the shutter time");
        } else if (w == "confidence" || w == "variance") {
            floatExpr();
            warnOnce("focal-adaptive", t.loc,
                     "focal blur 'confidence'/'variance' (POV-Ray's adaptive stop) are not used: drt takes "
                     "blur_samples samples per pixel");
        } else if (w == "normal") {
            unsupported("camera-normal", t.loc, "a camera 'normal' is not supported and is ignored");
            normalBlock(t.loc, std::nullopt);
        } else if (w == "bokeh") {
            unsupported("bokeh", t.loc, "'bokeh' is not supported; the lens is a uniform disc");
            expectSymbol("{", "after 'bokeh'");
            skipBlock();
        } else {
            failUnknown(t, Block::Camera, declaredNames({Kind::Camera}));
        }
    }
    const bool planar = c.mapping == CameraMapping::Planar;
    if (pov && c.lookAt && !(*c.lookAt == c.location) &&
        length(cross(c.sky, *c.lookAt - c.location)) <= 1e-12 * length(c.sky) * length(*c.lookAt - c.location))
        resolve(); // look_at along the sky: POV-Ray's rule above, which the renderer's look_at refuses
    if (pov) {
        // POV-Ray blurs only when aperture != 0 and blur_samples > 0; its lens radius
        // is aperture/4, so the model's lens diameter is aperture/2.
        if (aperture != 0 && blurSamples <= 0) {
            warnOnce("aperture-no-samples", apertureLoc,
                     "'aperture' without 'blur_samples': no focal blur (as POV-Ray)");
            aperture = 0;
        }
        c.aperture = std::fabs(aperture) / 2;
        if (!planar) {
            if (c.aperture > 0)
                warnOnce("mapping-aperture", apertureLoc,
                         "focal blur is supported with the perspective camera only; ignored");
            c.aperture = 0;
        }
        if (c.orthographic) {
            if (c.aperture > 0)
                warnOnce("ortho-aperture", apertureLoc,
                         "focal blur with an orthographic camera is not supported; ignored");
            c.aperture = 0;
            if (orthoPending) resolve();
        }
    } else {
        c.aperture = aperture;
        if (c.lookAt && *c.lookAt == c.location) error(lookAtLoc, "'look_at' is the same point as 'location'");
        if (c.focalPoint && *c.focalPoint == c.location)
            error(focalPointLoc, "'focal_point' is the same point as 'location'");
        // The angle's range depends on the camera type, which may follow it.
        if (c.angle && planar && !(*c.angle > 0 && *c.angle < 180))
            error(angleLoc, "'angle' must be between 0 and 180 degrees" + got(*c.angle));
        if (c.angle && !planar && !(*c.angle > 0)) error(angleLoc, "'angle' must be positive" + got(*c.angle));
        if (c.verticalAngle && c.mapping != CameraMapping::Spherical)
            error(verticalLoc, "a vertical angle is only for the spherical camera");
        if (c.verticalAngle && !(*c.verticalAngle > 0))
            error(verticalLoc, "the vertical angle must be positive" + got(*c.verticalAngle));
        if (!planar && c.aperture > 0)
            error(apertureLoc, "only a perspective camera has a lens: 'aperture' must be 0");
        if (c.orthographic && c.aperture > 0)
            error(apertureLoc, "an orthographic camera has no lens: 'aperture' must be 0");
    }
    if (c.shutterClose < c.shutterOpen) error(shutterLoc, "'shutter_close' is before 'shutter_open'");
    if (c.aperture > 0 && blurSamples > 0 && pov) {
        const int spp = std::max(blurSamples, scene_.render.samplesPerPixel.value_or(0));
        scene_.render.samplesPerPixel = spp;
    } else if (!pov && blurSamples > 1) {
        scene_.render.samplesPerPixel = std::max(blurSamples, scene_.render.samplesPerPixel.value_or(0));
    }
    return c;
}

} // namespace drt::lang
