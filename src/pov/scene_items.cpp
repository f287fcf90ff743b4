// Top-level statements: camera, light_source, objects, background, sky_sphere,
// global_settings; and the end-of-scene gamma rule.
#include "pov/parser.h"

#include <cmath>
#include <fmt/format.h>

namespace drt::pov {

using Kind = PovValue::Kind;

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

std::optional<CameraMapping> cameraMapping(const std::string& keyword) {
    if (keyword == "fisheye") return CameraMapping::Fisheye;
    if (keyword == "ultra_wide_angle") return CameraMapping::UltraWideAngle;
    if (keyword == "panoramic") return CameraMapping::Panoramic;
    if (keyword == "cylinder") return CameraMapping::Cylinder1; // the type number follows
    if (keyword == "spherical") return CameraMapping::Spherical;
    return std::nullopt;
}

} // namespace

Object toObject(const PovObject& po) {
    Object o = po.object;
    if (Csg* csg = std::get_if<Csg>(&o.shape)) {
        csg->children.clear();
        for (const PovObject& c : po.children) csg->children.push_back(toObject(c));
    }
    return o;
}

CameraSpec PovParser::camera(const CameraSpec& base, SourceLoc loc) {
    expectSymbol("{", "after 'camera'");
    CameraSpec c = base;
    c.loc = loc;
    if (!c.right) c.right = Vec3(1.33, 0, 0);
    double aperture = c.aperture * 2; // POV-Ray's aperture (the model's is half of it)
    int blurSamples = aperture > 0 ? 1 : 0;
    SourceLoc apertureLoc = loc;
    bool nonPerspective = false;
    // Orthographic: POV-Ray's scaling rule is applied once, when the vectors
    // are first resolved (at a transform or at the end).
    bool hadUp = false, hadRight = false, hadAngle = false, orthoPending = true;
    auto resolve = [&] {
        const bool scale = c.orthographic && orthoPending && ((!hadUp && !hadRight) || hadAngle);
        resolveCameraVectors(c, scale);
        if (c.orthographic) orthoPending = false;
    };
    for (;;) {
        const Tok t = peek();
        if (t.is("}")) {
            next();
            break;
        }
        if (t.isWord("motion")) { // drt's motion blur: moves the resolved camera (render/camera_path.h)
            next();
            resolve();
            c.motion.push_back(MotionStage{motionBlock(), Transform()});
            continue;
        }
        if (std::optional<Transform> tr = transformItem(); tr && !c.motion.empty()) {
            c.motion.back().after = c.motion.back().after.then(*tr);
            continue;
        } else if (tr) {
            resolve();
            c.location = tr->point(c.location);
            c.direction = tr->vector(c.direction);
            c.right = tr->vector(*c.right);
            c.up = tr->vector(c.up);
            if (c.focalPoint) c.focalPoint = tr->point(*c.focalPoint);
            continue;
        }
        next();
        if (t.kind != TokKind::Word) failExpected(t, "a camera item or '}'");
        const std::string& w = t.text;
        const Cell id = useIndexed(t);
        if (id && id->kind == Kind::Camera) {
            c = *id->camera;
            aperture = c.aperture * 2;
            if (c.orthographic) orthoPending = false; // resolved when it was declared
            continue;
        }
        if (w == "perspective" || w == "orthographic") {
            c.orthographic = w == "orthographic";
            c.mapping = CameraMapping::Planar;
            continue;
        }
        if (const std::optional<CameraMapping> m = cameraMapping(w)) {
            c.orthographic = false;
            c.mapping = *m;
            if (w == "cylinder") {
                const SourceLoc at = peek().loc;
                const double type = floatExpr(); // POV-Ray truncates
                if (!(std::trunc(type) >= 1 && std::trunc(type) <= 4))
                    fail(at, "invalid cylinder camera type: valid are types 1 to 4");
                const int n = int(type);
                c.mapping = static_cast<CameraMapping>(static_cast<int>(CameraMapping::Cylinder1) + n - 1);
            }
        } else if (w == "omnimax" || w == "mesh_camera") {
            warnOnce("camera-" + w, t.loc, "'" + w + "' camera is not supported; a perspective camera is used");
            nonPerspective = true;
            if (w == "mesh_camera") expectSymbol("{", ""), skipBlock();
        } else if (w == "location") c.location = vectorExpr();
        else if (w == "look_at") c.lookAt = vectorExpr();
        else if (w == "direction") c.direction = vectorExpr();
        else if (w == "right") c.right = vectorExpr(), hadRight = true;
        else if (w == "up") c.up = vectorExpr(), hadUp = true;
        else if (w == "sky") c.sky = vectorExpr();
        else if (w == "angle") {
            const SourceLoc at = peek().loc;
            hadAngle = true;
            // The orthographic camera's angle is optional (POV-Ray: 0, which
            // only triggers the scaling rule).
            if (c.orthographic && !startsFloat(peekOperator())) continue;
            const double a = floatExpr();
            if (c.mapping != CameraMapping::Planar) {
                if (a < 0) fail(at, "negative camera angle");
                c.angle = a;
                c.verticalAngle.reset();
                if (c.mapping == CameraMapping::Spherical && acceptSymbol(",")) {
                    const SourceLoc vat = peek().loc;
                    if (startsFloat(peekOperator())) c.verticalAngle = floatExpr();
                    if (c.verticalAngle && *c.verticalAngle < 0) fail(vat, "negative vertical camera angle");
                }
                continue;
            }
            if (acceptSymbol(",")) {
                floatExpr();
                warnOnce("angle-vertical", at, "the vertical camera angle is ignored (it follows from up/right)");
            }
            if (a > 0 && a < 180) c.angle = a;
            else if (c.orthographic && a == 0) c.angle.reset();
            else if (!nonPerspective) fail(at, "camera angle must be in (0, 180) degrees for a perspective camera");
        } else if (w == "aperture") {
            apertureLoc = t.loc;
            aperture = floatExpr();
        } else if (w == "blur_samples") {
            blurSamples = countExpr("blur_samples", -1e9, 1e9);
            if (acceptSymbol(",")) blurSamples = std::max(blurSamples, countExpr("blur_samples", -1e9, 1e9));
        } else if (w == "focal_point") c.focalPoint = vectorExpr();
        else if (w == "confidence" || w == "variance") {
            floatExpr();
            warnOnce("focal-adaptive", t.loc,
                     "focal blur 'confidence'/'variance' (POV-Ray's adaptive stop) are not used: drt takes "
                     "blur_samples samples per pixel");
        } else if (w == "normal") {
            normalBlock(t.loc);
        } else if (w == "bokeh") {
            warnOnce("bokeh", t.loc, "'bokeh' is not supported; the lens is a uniform disc");
            expectSymbol("{", "");
            skipBlock();
        } else {
            failExpected(t, "a camera item or '}'");
        }
    }
    // POV-Ray blurs only when aperture != 0 and blur_samples > 0; its lens radius
    // is aperture/4, so the model's lens diameter is aperture/2.
    if (aperture != 0 && blurSamples <= 0) {
        warnOnce("aperture-no-samples", apertureLoc, "'aperture' without 'blur_samples': no focal blur (as POV-Ray)");
        aperture = 0;
    }
    c.aperture = std::fabs(aperture) / 2;
    if (c.mapping != CameraMapping::Planar) {
        if (c.aperture > 0)
            warnOnce("mapping-aperture", apertureLoc, "focal blur is supported with the perspective camera only; ignored");
        c.aperture = 0;
    }
    if (c.orthographic) {
        if (c.aperture > 0)
            warnOnce("ortho-aperture", apertureLoc, "focal blur with an orthographic camera is not supported; ignored");
        c.aperture = 0;
        if (orthoPending) resolve();
    }
    if (c.aperture > 0) {
        const int spp = std::max(blurSamples, scene_.render.samplesPerPixel.value_or(0));
        scene_.render.samplesPerPixel = spp;
    }
    return c;
}

Light PovParser::lightSource(SourceLoc loc, std::optional<PovObject>* looksLike) {
    expectSymbol("{", "after 'light_source'");
    Light l;
    l.loc = loc;
    l.mediaAttenuation = false; // POV-Ray's default
    AreaLight early; // area-light modifiers given before area_light
    MotionChain lightMotion; // drt's motion blocks and the transforms after them
    const Tok first = peek();
    const Cell id = first.kind == TokKind::Word ? use(first.text) : nullptr;
    if (id && id->kind == Kind::Object && id->object->lights.size() == 1 &&
        (id->object->lightOnly || looksLike)) {
        // A declared light; one with looks_like is its shape carrying the light.
        next();
        l = id->object->lights.front();
        if (!id->object->lightOnly) {
            *looksLike = *id->object;
            (*looksLike)->lights.clear();
        }
    } else {
        l.position = vectorExpr();
        acceptSymbol(",");
        static const std::set<std::string> items = {
            "spotlight", "area_light", "shadowless", "translate", "rotate", "scale", "matrix", "transform",
            "fade_distance", "fade_power", "point_at", "radius", "falloff", "tightness", "looks_like",
            "parallel", "cylinder", "media_interaction", "media_attenuation", "projected_through", "photons",
            "area_illumination", "jitter", "adaptive", "circular", "orient"};
        const Tok c = peek();
        if (!c.is("}") && !(c.kind == TokKind::Word && items.count(c.text)))
            l.color = toColorFT(colorExpr()).rgb;
    }
    for (;;) {
        const Tok t = peek();
        if (t.is("}")) {
            next();
            break;
        }
        if (t.isWord("motion")) { // drt's motion blur: moves the light (render/light_path.h)
            next();
            lightMotion.push_back(MotionStage{motionBlock(), Transform()});
            continue;
        }
        if (std::optional<Transform> tr = transformItem(); tr && !lightMotion.empty()) {
            lightMotion.back().after = lightMotion.back().after.then(*tr);
            continue;
        } else if (tr) {
            if (looksLike && *looksLike) applyTransform(**looksLike, *tr);
            l.position = tr->point(l.position);
            l.pointAt = tr->point(l.pointAt);
            if (l.area) {
                l.area->axis1 = tr->vector(l.area->axis1);
                l.area->axis2 = tr->vector(l.area->axis2);
            }
            continue;
        }
        next();
        if (t.kind != TokKind::Word) failExpected(t, "a light_source item or '}'");
        const std::string& w = t.text;
        if (w == "color" || w == "colour" || w.rfind("rgb", 0) == 0 || w.rfind("srgb", 0) == 0) {
            pushBack(t);
            l.color = toColorFT(colorExpr()).rgb;
        } else if (w == "spotlight") l.spotlight = true;
        else if (w == "point_at") l.pointAt = vectorExpr();
        else if (w == "radius") l.radius = floatExpr();
        else if (w == "falloff") l.falloff = floatExpr();
        else if (w == "tightness") l.tightness = floatExpr();
        else if (w == "shadowless") l.shadowless = true;
        else if (w == "fade_distance") l.fadeDistance = floatExpr();
        else if (w == "fade_power") l.fadePower = floatExpr();
        else if (w == "looks_like" && looksLike) {
            // POV-Ray: the object is moved to the light's position, moves with
            // the light's later transforms and casts no shadow.
            if (*looksLike) fail(t.loc, "only one looks_like is allowed per light_source");
            PovObject shape = object(Tok{TokKind::Word, "object", 0, t.loc}); // reads `{ object modifiers }`
            applyTransform(shape, Transform::translate(l.position));
            shape.object.noShadow = true;
            *looksLike = std::move(shape);
        } else if (w == "area_light") {
            AreaLight a = early; // modifiers may come first (POV-Ray keeps them as flags)
            a.axis1 = vectorExpr();
            acceptSymbol(",");
            a.axis2 = vectorExpr();
            acceptSymbol(",");
            const SourceLoc at = peek().loc;
            const Limits& limits = diags_.limits();
            a.size1 = countExpr("area_light size", 1, double(limits.areaLightSamples));
            acceptSymbol(",");
            a.size2 = countExpr("area_light size", 1, double(limits.areaLightSamples));
            const double samples = double(a.size1) * double(a.size2);
            if (samples > double(limits.areaLightSamples))
                fail(at, limitExceeded(limits, &Limits::areaLightSamples,
                                       fmt::format("the area_light's sample count {} x {} =", a.size1, a.size2),
                                       samples));
            // POV-Ray's semantics: edge-to-edge grid, shadow-only averaging unless area_illumination.
            // The grid's points are shared out over the pixel's samples (Cook's association,
            // render/lighting.h), which converges to POV-Ray's sum over the grid.
            a.sampling = AreaSampling::Grid;
            l.area = a;
        } else if (w == "adaptive" || w == "jitter" || w == "circular" || w == "orient") {
            AreaLight& target = l.area ? *l.area : early;
            if (w == "adaptive") target.adaptive = countExpr("area_light adaptive", -1e9, 1e9);
            else if (w == "jitter") target.jitter = true;
            else if (w == "circular") target.circular = true;
            else target.orient = true;
        } else if (w == "area_illumination") {
            const Tok n = peekOperator();
            l.areaIllumination = (n.kind == TokKind::Number || n.isWord("on") || n.isWord("off") ||
                                  n.isWord("true") || n.isWord("false"))
                                     ? boolExpr()
                                     : true;
        } else if (w == "looks_like" || w == "projected_through" || w == "photons") {
            warnOnce("light-" + w, t.loc, "light_source '" + w + "' is not supported and is ignored");
            expectSymbol("{", "");
            skipBlock();
        } else if (w == "parallel" || w == "cylinder") {
            warnOnce("light-" + w, t.loc, "'" + w + "' lights are not supported; treated as a point light");
        } else if (w == "media_interaction" || w == "media_attenuation") {
            const Tok n = peekOperator();
            const bool on = n.kind == TokKind::Number || n.isWord("on") || n.isWord("off") ? floatExpr() != 0 : true;
            (w == "media_interaction" ? l.mediaInteraction : l.mediaAttenuation) = on;
        } else {
            failExpected(t, "a light_source item or '}'");
        }
    }
    if (!lightMotion.empty()) l.motion = std::make_shared<LightMotion>(LightMotion{{}, std::move(lightMotion)});
    return l;
}

void PovParser::globalSettings() {
    expectSymbol("{", "after 'global_settings'");
    for (;;) {
        const Tok t = next();
        if (t.is("}")) return;
        if (t.kind != TokKind::Word) failExpected(t, "a global setting or '}'");
        const std::string& w = t.text;
        if (w == "assumed_gamma") {
            const SourceLoc at = peek().loc;
            assumedGamma_ = floatExpr();
            if (!(*assumedGamma_ > 0)) fail(at, "'assumed_gamma' must be positive");
        } else if (w == "max_trace_level") {
            const SourceLoc at = peek().loc;
            // Any finite level is accepted (POV-Ray caps it too); above drt's
            // limit the limit is used, with a warning.
            const double value = floatExpr();
            if (!std::isfinite(value)) fail(at, "max_trace_level must be a finite number");
            const double level = std::max(1.0, std::trunc(value));
            const int64_t limit = diags_.limits().traceLevel;
            if (level > double(limit))
                warn(at, fmt::format("max_trace_level {:.0f} is above drt's {}; {} is used ({})", level, limit, limit,
                                     limitHint(diags_.limits(), &Limits::traceLevel)));
            scene_.global.maxTraceLevel = int(std::min(level, double(limit)));
        } else if (w == "ambient_light") {
            scene_.global.ambientLight = toColorFT(colorExpr()).rgb;
        } else if (w == "adc_bailout") {
            scene_.global.adcBailout = floatExpr();
        } else if (w == "radiosity" || w == "photons" || w == "subsurface") {
            warnOnce("global-" + w, t.loc, "global_settings '" + w + "' is not supported and is ignored");
            expectSymbol("{", "");
            skipBlock();
        } else if (w == "charset") {
            next();
        } else if (w == "number_of_waves" || w == "noise_generator" || w == "max_intersections" ||
                   w == "hf_gray_16" || w == "mm_per_unit") {
            const Tok n = peekOperator();
            if (n.kind == TokKind::Number || n.kind == TokKind::Word) floatExpr();
        } else if (w == "irid_wavelength") {
            colorExpr();
            warnOnce("global-irid", t.loc, "'irid_wavelength' is not supported and is ignored");
        } else {
            failExpected(t, "a global setting or '}'");
        }
    }
}

void PovParser::addToScene(PovObject o) {
    scene_.lights.insert(scene_.lights.end(), o.lights.begin(), o.lights.end());
    if (o.lightOnly) return;
    o.lights.clear();
    scene_.objects.push_back(toObject(o));
    const Limits& limits = diags_.limits();
    const int64_t before = objectsBuilt_;
    objectsBuilt_ += weightOf(scene_.objects.back(), limits.objects).total();
    if (objectsBuilt_ > limits.objects)
        fail(scene_.objects.back().loc, limitExceeded(limits, &Limits::objects,
                                                      "the scene's objects and patterns number", double(objectsBuilt_)));
    if (objectsBuilt_ / 4096 != before / 4096) checkMemoryAt(scene_.objects.back().loc);
}

void PovParser::statement(const Tok& t) {
    if (t.is(";")) return;
    if (t.kind != TokKind::Word) failExpected(t, "an object, camera, light_source or directive");
    const std::string& w = t.text;
    if (isObjectWord(t) || w == "light_source") {
        addToScene(object(t));
    } else if (w == "camera") {
        if (cameraSeen_) warnOnce("camera-twice", t.loc, "more than one camera: the last one is used (as POV-Ray)");
        scene_.camera = camera(scene_.camera, t.loc);
        cameraSeen_ = true;
    } else if (w == "background") {
        expectSymbol("{", "after 'background'");
        scene_.background = toColorFT(colorExpr()).rgb;
        expectSymbol("}", "after the background colour");
    } else if (w == "sky_sphere") {
        scene_.sky = skySphere();
    } else if (w == "global_settings") {
        globalSettings();
    } else if (w == "fog") {
        fog(t);
    } else if (w == "default") {
        defaultBlock();
    } else if (w == "media") {
        scene_.media.push_back(media(Media{}));
    } else if (w == "rainbow" || w == "photons" || w == "radiosity") {
        warnOnce(w, t.loc, "'" + w + "' is not supported and is ignored");
        expectSymbol("{", ("after '" + w + "'").c_str());
        skipBlock();
    } else if (const Cell c = lookup(w)) {
        fail(t.loc, std::string("a ") + kindName(c->kind) + " identifier cannot stand alone here" +
                        (c->kind == Kind::Object ? " (write object { " + w + " })" : ""));
    } else {
        std::string message = "unknown keyword '" + w + "'";
        static const std::vector<std::string> known = {"sphere", "box", "plane", "cylinder", "cone", "disc",
                                                       "torus", "union", "difference", "intersection", "merge",
                                                       "object", "camera", "light_source", "background",
                                                       "sky_sphere", "global_settings", "mesh", "mesh2", "fog"};
        if (const std::string near = nearestWord(w, known); !near.empty()) message += " (did you mean '" + near + "'?)";
        fail(t.loc, message);
    }
}

// sky-sphere = "sky_sphere" "{" [ identifier ] { pigment | emission colour | transform } "}"
// The sky_sphere's transforms turn the directions its pigments see.
std::vector<Pigment> PovParser::skySphere() {
    expectSymbol("{", "after 'sky_sphere'");
    std::vector<Pigment> layers;
    for (;;) {
        const Tok s = next();
        if (s.is("}")) break;
        if (s.isWord("pigment")) {
            layers.push_back(pigment(Pigment{}));
        } else if (s.isWord("emission")) {
            colorExpr();
            warnOnce("sky-emission", s.loc, "sky_sphere 'emission' is not supported and is ignored");
        } else if (s.isWord("translate") || s.isWord("rotate") || s.isWord("scale") || s.isWord("matrix") ||
                   s.isWord("transform")) {
            pushBack(s);
            if (const std::optional<Transform> tr = transformItem())
                for (Pigment& p : layers) transformPigmentSpaces(p, *tr);
        } else if (const Cell c = s.kind == TokKind::Word ? lookup(s.text) : nullptr;
                   c && c->kind == Kind::SkySphere) {
            layers.insert(layers.end(), c->sky->begin(), c->sky->end());
        } else {
            failExpected(s, "'pigment', a transform or '}' in sky_sphere");
        }
    }
    return layers;
}

// POV-Ray 3.7 (Parse_Camera, look_at): when sky is parallel to the view
// direction, it warns and keeps the supplied right vector instead of
// sky x direction; up becomes direction x right. The model's camera would
// refuse such a sky, so the look_at is resolved here into explicit vectors.
void PovParser::resolveParallelSky(CameraSpec& cam) {
    if (!cam.lookAt || !cam.right) return;
    const Vec3 toTarget = *cam.lookAt - cam.location;
    if (!(length(toTarget) > 0) || !(length(cam.sky) > 0)) return; // the renderer reports these
    const Vec3 d = normalize(toTarget);
    if (length(cross(cam.sky, d)) > 1e-12 * length(cam.sky)) return;
    const Vec3 rightUnit = normalize(*cam.right);
    const Vec3 up = cross(d, rightUnit);
    if (!(length(up) > 1e-12)) return; // right along the view too: left to the renderer's error
    note(cam.loc, "camera: sky is parallel to the look_at direction; the right vector is kept (as POV-Ray)");
    cam.direction = d * length(cam.direction);
    cam.up = normalize(up) * length(cam.up);
    cam.lookAt.reset();
}

// fog = "fog" "{" { fog_type n | distance d | colour | fog_offset h | fog_alt a | up v
//                   | turbulence ... | transform } "}"   (POV-Ray defaults: type 1)
void PovParser::fog(const Tok& keyword) {
    expectSymbol("{", "after 'fog'");
    Fog f;
    for (;;) {
        const Tok s = next();
        if (s.is("}")) break;
        if (s.isWord("fog_type")) {
            const double type = floatExpr();
            if (type == 2) f.type = Fog::Type::Ground;
            else if (type != 1) warnOnce("fog_type", s.loc, "fog_type must be 1 or 2; constant fog is used");
        } else if (s.isWord("distance")) {
            f.distance = floatExpr();
        } else if (s.isWord("fog_offset")) {
            f.offset = floatExpr();
        } else if (s.isWord("fog_alt")) {
            f.altitude = floatExpr();
        } else if (s.isWord("up")) {
            f.up = vectorExpr();
        } else if (s.isWord("turbulence")) {
            if (!f.turbulence) f.turbulence = Turbulence{};
            f.turbulence->amount = vectorExpr();
            if (warned_.insert("note-fog-turbulence").second)
                note(s.loc, "fog turbulence is approximated: drt's noise has POV-Ray's shapes but not its exact values");
        } else if (s.isWord("turb_depth")) {
            f.turbDepth = floatExpr();
        } else if (s.isWord("omega") || s.isWord("lambda") || s.isWord("octaves")) {
            if (!f.turbulence) f.turbulence = Turbulence{};
            const SourceLoc at = peek().loc;
            const double v = floatExpr();
            if (s.isWord("omega")) f.turbulence->omega = v;
            else if (s.isWord("lambda")) f.turbulence->lambda = v;
            else f.turbulence->octaves = std::clamp(countValue(v, at, "octaves", -1e9, 1e9), 1, 10);
        } else if (s.isWord("color") || s.isWord("colour") || s.isWord("rgb") || s.isWord("rgbf") ||
                   s.isWord("rgbt") || s.isWord("rgbft") || s.isWord("srgb") || s.isWord("srgbf") ||
                   s.isWord("srgbt") || s.isWord("srgbft") || s.isWord("red") || s.isWord("green") ||
                   s.isWord("blue") || s.isWord("filter") || s.isWord("transmit") || s.is("<")) {
            pushBack(s);
            f.color = toColorFT(colorExpr());
        } else if (s.isWord("translate") || s.isWord("rotate") || s.isWord("scale") || s.isWord("matrix") ||
                   s.isWord("transform")) {
            pushBack(s);
            if (const std::optional<Transform> tr = transformItem()) f.up = tr->vector(f.up);
        } else if (s.kind == TokKind::Word && lookup(s.text)) {
            pushBack(s); // a colour identifier
            f.color = toColorFT(colorExpr());
        } else {
            failExpected(s, "a fog item or '}'");
        }
    }
    if (!(f.distance > 0)) fail(keyword.loc, "fog 'distance' must be positive");
    if (f.type == Fog::Type::Ground && !(f.altitude > 0)) fail(keyword.loc, "fog 'fog_alt' must be positive");
    scene_.fogs.push_back(f);
}

// POV-Ray's gamma rule (docs/pov.md): assumed_gamma 1.0, or
// #version 3.7+ without assumed_gamma, means linear colours. Otherwise the
// scene's colours are encoded with gamma g (2.2 when only an older #version
// says so) and POV-Ray shades them as they are, decoding only the result; the
// model's assumed_gamma does exactly that (render/film.h decodeWorkingGamma).
void PovParser::finishScene() {
    scene_.global.assumedGamma = workingGamma();
    if (!scene_.camera.right) scene_.camera.right = Vec3(1.33, 0, 0);
    resolveParallelSky(scene_.camera);
    scene_.render.width = options_.imageWidth;
    scene_.render.height = options_.imageHeight;
}

} // namespace drt::pov
