// Scene-level blocks: camera, light_source, background, global_settings, render.
#include "lang/parser.h"

#include "sampling/filter.h"
#include "sampling/sampler.h"

#include <algorithm>
#include <cmath>

namespace drt {

void Parser::requireNonZero(const Vec3& v, const SourceLoc& loc, const char* what) {
    if (v.x == 0 && v.y == 0 && v.z == 0) error(loc, std::string(what) + " must not be a zero-length vector");
}

// transform = "translate" vector | "rotate" vector | "scale" vector
//           | "matrix" "<" float { "," float } ">"   (12 numbers)
std::optional<Transform> Parser::transformItem() {
    if (!check(TokenKind::Identifier)) return std::nullopt;
    const Token word = current_;
    if (word.text == "translate") {
        advance();
        return Transform::translate(vectorExpr());
    }
    if (word.text == "rotate") {
        advance();
        return Transform::rotate(vectorExpr());
    }
    if (word.text == "scale") {
        advance();
        const SourceLoc loc = current_.loc;
        const Vec3 s = vectorExpr();
        if (s.x == 0 || s.y == 0 || s.z == 0) {
            error(loc, "scale has a zero component (the object would collapse)");
            return Transform{};
        }
        return Transform::scale(s);
    }
    if (word.text == "matrix") {
        advance();
        expect(TokenKind::LeftAngle, "'<' after 'matrix'");
        std::array<double, 12> m{};
        int count = 0;
        do {
            const SourceLoc loc = current_.loc;
            const double v = floatExpr("a matrix entry");
            if (count == 12) fail(loc, "'matrix' takes exactly 12 numbers");
            m[count++] = v;
        } while (match(TokenKind::Comma));
        expect(TokenKind::RightAngle, "',' or '>' in the matrix");
        if (count != 12) fail(word.loc, "'matrix' takes exactly 12 numbers, got " + std::to_string(count));
        std::optional<Transform> t = Transform::fromPovMatrix(m);
        if (!t) {
            error(word.loc, "singular matrix (it has no inverse)");
            return Transform{};
        }
        return t;
    }
    return std::nullopt;
}

// camera = "camera" "{" { camera-item } "}"
void Parser::camera() {
    static const std::vector<std::string> known{
        "perspective", "orthographic", "fisheye", "ultra_wide_angle", "panoramic", "cylinder", "spherical", "location",    "look_at",        "up",           "sky",          "right", "direction",
        "angle",       "aperture",    "focal_point",    "focal_distance", "shutter_open", "shutter_close",
        "translate",   "rotate",      "scale",          "matrix",         "motion"};
    const Token keyword = current_;
    advance();
    expect(TokenKind::LeftBrace, "'{' after 'camera'");
    CameraSpec cam;
    cam.loc = keyword.loc;
    SourceLoc lookAtLoc, focalPointLoc, shutterLoc, apertureLoc, angleLoc, verticalLoc;
    while (!match(TokenKind::RightBrace)) {
        // The camera's placement: transforms and motions move the whole
        // camera once its vectors are set up (render/camera_path.h).
        if (std::optional<Transform> t = transformItem()) {
            appendTransform(cam.transform, cam.motion, *t);
            continue;
        }
        if (checkWord("motion")) {
            cam.motion.push_back(MotionStage{motionBlock(), Transform()});
            continue;
        }
        if (!check(TokenKind::Identifier)) failExpected("a camera keyword or '}'");
        const Token word = current_;
        const std::string& w = word.text;
        advance();
        const SourceLoc loc = current_.loc;
        if (w == "perspective") cam.orthographic = false, cam.mapping = CameraMapping::Planar;
        else if (w == "orthographic") cam.orthographic = true, cam.mapping = CameraMapping::Planar;
        else if (w == "fisheye") cam.orthographic = false, cam.mapping = CameraMapping::Fisheye;
        else if (w == "ultra_wide_angle") cam.orthographic = false, cam.mapping = CameraMapping::UltraWideAngle;
        else if (w == "panoramic") cam.orthographic = false, cam.mapping = CameraMapping::Panoramic;
        else if (w == "spherical") cam.orthographic = false, cam.mapping = CameraMapping::Spherical;
        else if (w == "cylinder") {
            static constexpr CameraMapping cylinders[] = {CameraMapping::Cylinder1, CameraMapping::Cylinder2,
                                                          CameraMapping::Cylinder3, CameraMapping::Cylinder4};
            const double n = floatExpr();
            if (!(n == 1 || n == 2 || n == 3 || n == 4)) fail(loc, "'cylinder' camera type must be 1, 2, 3 or 4");
            cam.orthographic = false;
            cam.mapping = cylinders[static_cast<int>(n) - 1];
        }
        else if (w == "location") cam.location = vectorExpr();
        else if (w == "look_at") lookAtLoc = loc, cam.lookAt = vectorExpr();
        else if (w == "up") requireNonZero(cam.up = vectorExpr(), loc, "'up'");
        else if (w == "sky") requireNonZero(cam.sky = vectorExpr(), loc, "'sky'");
        else if (w == "right") requireNonZero(*(cam.right = vectorExpr()), loc, "'right'");
        else if (w == "direction") requireNonZero(cam.direction = vectorExpr(), loc, "'direction'");
        else if (w == "angle") {
            angleLoc = loc;
            cam.angle = floatExpr();
            cam.verticalAngle.reset();
            if (match(TokenKind::Comma)) verticalLoc = current_.loc, cam.verticalAngle = floatExpr();
        } else if (w == "aperture") {
            apertureLoc = loc;
            cam.aperture = floatExpr();
            if (cam.aperture < 0) error(loc, "'aperture' must not be negative");
        } else if (w == "focal_point") focalPointLoc = loc, cam.focalPoint = vectorExpr();
        else if (w == "focal_distance") {
            cam.focalDistance = floatExpr();
            if (*cam.focalDistance <= 0) error(loc, "'focal_distance' must be positive");
        } else if (w == "shutter_open") shutterLoc = loc, cam.shutterOpen = floatExpr();
        else if (w == "shutter_close") shutterLoc = loc, cam.shutterClose = floatExpr();
        else failUnknown(word, known);
    }
    if (cam.lookAt && *cam.lookAt == cam.location) error(lookAtLoc, "'look_at' is the same point as 'location'");
    if (cam.focalPoint && *cam.focalPoint == cam.location)
        error(focalPointLoc, "'focal_point' is the same point as 'location'");
    // The angle's range depends on the camera type, which may follow it.
    const bool planar = cam.mapping == CameraMapping::Planar;
    if (cam.angle && planar && !(*cam.angle > 0 && *cam.angle < 180))
        error(angleLoc, "'angle' must be between 0 and 180 degrees");
    if (cam.angle && !planar && !(*cam.angle > 0)) error(angleLoc, "'angle' must be positive");
    if (cam.verticalAngle && cam.mapping != CameraMapping::Spherical)
        error(verticalLoc, "a vertical angle is only for the spherical camera");
    if (cam.verticalAngle && !(*cam.verticalAngle > 0)) error(verticalLoc, "the vertical angle must be positive");
    if (!planar && cam.aperture > 0) error(apertureLoc, "only a perspective camera has a lens: 'aperture' must be 0");
    if (cam.orthographic && cam.aperture > 0)
        error(apertureLoc, "an orthographic camera has no lens: 'aperture' must be 0");
    if (cam.shutterClose < cam.shutterOpen) error(shutterLoc, "'shutter_close' is before 'shutter_open'");
    scene_.camera = cam;
}

// light_source = "light_source" "{" vector [","] [colour] { light-item } "}"
void Parser::lightSource() {
    static const std::vector<std::string> known{
        "color",   "colour", "rgb",         "spotlight", "point_at", "radius",   "falloff",
        "tightness", "fade_distance", "fade_power", "shadowless", "area_light", "jitter", "adaptive",
        "circular", "orient", "area_illumination", "area_sampling", "inverse_square", "media_interaction",
        "media_attenuation", "translate", "rotate", "scale", "matrix", "motion"};
    const Token keyword = current_;
    advance();
    expect(TokenKind::LeftBrace, "'{' after 'light_source'");
    Light light;
    light.loc = keyword.loc;
    light.position = vectorExpr("the light position <x, y, z>");
    match(TokenKind::Comma);
    // drt's default area light is Cook's: full illumination from stratified points.
    light.areaIllumination = true;
    AreaLight area;
    area.sampling = AreaSampling::Stratified;
    bool hasArea = false;
    SourceLoc pointAtLoc;
    MotionChain motion; // the light's motions and the transforms after them (render/light_path.h)
    while (!match(TokenKind::RightBrace)) {
        if (checkWord("motion")) {
            motion.push_back(MotionStage{motionBlock(), Transform()});
            continue;
        }
        if (std::optional<Transform> t = transformItem(); t && !motion.empty()) {
            motion.back().after = motion.back().after.then(*t);
            continue;
        } else if (t) {
            light.position = t->point(light.position);
            light.pointAt = t->point(light.pointAt);
            area.axis1 = t->vector(area.axis1);
            area.axis2 = t->vector(area.axis2);
            continue;
        }
        const bool colorStart = checkWord("color") || checkWord("colour") || atColorWord() ||
                                check(TokenKind::LeftAngle) ||
                                (check(TokenKind::Identifier) && lookup(current_.text) &&
                                 (std::holds_alternative<VectorValue>(*lookup(current_.text)) ||
                                  std::holds_alternative<double>(*lookup(current_.text))));
        if (colorStart) {
            light.color = rgbExpr();
            continue;
        }
        if (!check(TokenKind::Identifier)) failExpected("a light_source keyword or '}'");
        const Token word = current_;
        const std::string& w = word.text;
        advance();
        const SourceLoc loc = current_.loc;
        if (w == "spotlight") light.spotlight = true;
        else if (w == "point_at") pointAtLoc = loc, light.pointAt = vectorExpr();
        else if (w == "radius" || w == "falloff") {
            const double a = floatExpr();
            // Used through its cosine, as POV-Ray does, so cones wider than 90 degrees work (lights/laser.pov).
            if (a < 0) error(loc, "'" + w + "' must not be negative");
            (w == "radius" ? light.radius : light.falloff) = a;
        } else if (w == "tightness") {
            light.tightness = floatExpr();
            if (light.tightness < 0) error(loc, "'tightness' must not be negative");
        } else if (w == "fade_distance") {
            light.fadeDistance = floatExpr();
            if (light.fadeDistance < 0) error(loc, "'fade_distance' must not be negative");
        } else if (w == "fade_power") {
            light.fadePower = floatExpr();
            if (light.fadePower < 0) error(loc, "'fade_power' must not be negative");
        } else if (w == "shadowless") light.shadowless = true;
        else if (w == "area_light") {
            hasArea = true;
            area.axis1 = vectorExpr();
            requireNonZero(area.axis1, loc, "area_light axis");
            expect(TokenKind::Comma, "',' after the first area_light axis");
            const SourceLoc axis2Loc = current_.loc;
            area.axis2 = vectorExpr();
            requireNonZero(area.axis2, axis2Loc, "area_light axis");
            expect(TokenKind::Comma, "',' after the second area_light axis");
            const SourceLoc n1Loc = current_.loc;
            area.size1 = intExpr("the area_light size");
            expect(TokenKind::Comma, "',' after the first area_light size");
            const SourceLoc n2Loc = current_.loc;
            area.size2 = intExpr("the area_light size");
            if (area.size1 < 1) error(n1Loc, "area_light sizes must be at least 1");
            if (area.size2 < 1) error(n2Loc, "area_light sizes must be at least 1");
            const double samples = double(area.size1) * double(area.size2);
            if (samples > double(diags_.limits().areaLightSamples))
                error(n1Loc, limitExceeded(diags_.limits(), &Limits::areaLightSamples,
                                           "the area_light's sample count " + std::to_string(area.size1) + " x " +
                                               std::to_string(area.size2) + " =",
                                           samples));
        } else if (w == "jitter") area.jitter = booleanOr(true);
        else if (w == "adaptive") {
            area.adaptive = intExpr("'adaptive'");
            if (area.adaptive < 0) error(loc, "'adaptive' must not be negative");
        } else if (w == "circular") area.circular = booleanOr(true);
        else if (w == "orient") area.orient = booleanOr(true);
        else if (w == "area_illumination") light.areaIllumination = booleanOr(true);
        else if (w == "inverse_square") light.inverseSquare = booleanOr(true);
        else if (w == "media_interaction") light.mediaInteraction = booleanOr(true);
        else if (w == "media_attenuation") light.mediaAttenuation = booleanOr(true);
        else if (w == "area_sampling") {
            const Token name = current_;
            if (name.kind == TokenKind::Identifier && name.text == "stratified") area.sampling = AreaSampling::Stratified;
            else if (name.kind == TokenKind::Identifier && name.text == "solid_angle") area.sampling = AreaSampling::SolidAngle;
            else if (name.kind == TokenKind::Identifier && name.text == "pov_grid") area.sampling = AreaSampling::PovGrid;
            else if (name.kind == TokenKind::Identifier && name.text == "grid") area.sampling = AreaSampling::Grid;
            else failExpected("'stratified', 'solid_angle', 'grid' or 'pov_grid' after 'area_sampling'");
            advance();
        }
        else failUnknown(word, known);
    }
    if (light.spotlight && light.pointAt == light.position)
        error(pointAtLoc.valid() ? pointAtLoc : keyword.loc, "'point_at' is the same point as the light position");
    if (hasArea) light.area = area;
    if (!motion.empty()) light.motion = std::make_shared<LightMotion>(LightMotion{{}, std::move(motion)});
    scene_.lights.push_back(light);
}

// background = "background" "{" colour "}"
void Parser::background() {
    advance();
    expect(TokenKind::LeftBrace, "'{' after 'background'");
    scene_.background = rgbExpr();
    expect(TokenKind::RightBrace, "'}' after the background colour");
}

// sky-sphere = "sky_sphere" "{" { pigment } "}"
void Parser::skySphere() {
    const Token keyword = current_;
    advance();
    expect(TokenKind::LeftBrace, "'{' after 'sky_sphere'");
    std::vector<Pigment> layers;
    while (!match(TokenKind::RightBrace)) {
        if (!checkWord("pigment")) failExpected("'pigment' or '}' in sky_sphere");
        layers.push_back(pigment());
    }
    if (layers.empty()) error(keyword.loc, "sky_sphere needs at least one pigment");
    scene_.sky = std::move(layers);
}

// fog = "fog" "{" { "distance" float | colour | "fog_type" int | "fog_offset" float
//                 | "fog_alt" float | "up" vector } "}"
void Parser::fog() {
    static const std::vector<std::string> known{"distance", "color",      "fog_type", "fog_offset", "fog_alt", "up",
                                                "turbulence", "turb_depth", "octaves", "omega", "lambda"};
    const Token keyword = current_;
    advance();
    expect(TokenKind::LeftBrace, "'{' after 'fog'");
    Fog f;
    bool hasDistance = false;
    while (!match(TokenKind::RightBrace)) {
        if (!check(TokenKind::Identifier)) failExpected("a fog keyword or '}'");
        if (checkWord("color") || atColorWord()) {
            f.color = colorExpr();
            continue;
        }
        const Token word = current_;
        const std::string& w = word.text;
        advance();
        const SourceLoc loc = current_.loc;
        if (w == "distance") {
            f.distance = floatExpr("the fog distance");
            hasDistance = true;
            if (!(f.distance > 0)) error(loc, "fog 'distance' must be positive");
        } else if (w == "fog_type") {
            const int type = intExpr("the fog type");
            if (type != 1 && type != 2) error(loc, "'fog_type' must be 1 (constant) or 2 (ground)");
            f.type = type == 2 ? Fog::Type::Ground : Fog::Type::Constant;
        } else if (w == "fog_offset") {
            f.offset = floatExpr("the fog offset");
        } else if (w == "fog_alt") {
            f.altitude = floatExpr("the fog altitude");
            if (!(f.altitude > 0)) error(loc, "'fog_alt' must be positive");
        } else if (w == "up") {
            f.up = vectorExpr();
            requireNonZero(f.up, loc, "the fog 'up'");
        } else if (w == "turbulence") {
            if (!f.turbulence) f.turbulence = Turbulence{};
            f.turbulence->amount = vectorExpr();
        } else if (w == "turb_depth") {
            f.turbDepth = floatExpr("the turbulence depth");
        } else if (w == "octaves" || w == "omega" || w == "lambda") {
            if (!f.turbulence) f.turbulence = Turbulence{};
            if (w == "octaves") {
                f.turbulence->octaves = intExpr("the octave count");
                if (f.turbulence->octaves < 1 || f.turbulence->octaves > 10)
                    error(loc, "'octaves' must be between 1 and 10");
            } else {
                (w == "omega" ? f.turbulence->omega : f.turbulence->lambda) = floatExpr();
            }
        } else {
            failUnknown(word, known);
        }
    }
    if (!hasDistance) error(keyword.loc, "fog needs a 'distance'");
    scene_.fogs.push_back(f);
}

// global-settings = "global_settings" "{" { global-item } "}"
void Parser::globalSettings() {
    static const std::vector<std::string> known{"max_trace_level", "ambient_light", "assumed_gamma", "adc_bailout"};
    advance();
    expect(TokenKind::LeftBrace, "'{' after 'global_settings'");
    while (!match(TokenKind::RightBrace)) {
        if (!check(TokenKind::Identifier)) failExpected("a global_settings keyword or '}'");
        const Token word = current_;
        advance();
        const SourceLoc loc = current_.loc;
        if (word.text == "max_trace_level") {
            scene_.global.maxTraceLevel = intExpr("'max_trace_level'");
            if (scene_.global.maxTraceLevel < 1)
                error(loc, "'max_trace_level' must be at least 1");
            else if (scene_.global.maxTraceLevel > diags_.limits().traceLevel)
                error(loc, limitExceeded(diags_.limits(), &Limits::traceLevel, "'max_trace_level'",
                                         scene_.global.maxTraceLevel));
        } else if (word.text == "ambient_light") {
            scene_.global.ambientLight = rgbExpr();
        } else if (word.text == "assumed_gamma") {
            scene_.global.assumedGamma = floatExpr();
            if (scene_.global.assumedGamma <= 0) error(loc, "'assumed_gamma' must be positive");
        } else if (word.text == "adc_bailout") {
            scene_.global.adcBailout = floatExpr();
            if (scene_.global.adcBailout < 0) error(loc, "'adc_bailout' must not be negative");
        } else {
            failUnknown(word, known);
        }
    }
}

// render = "render" "{" { render-item } "}"   (drt: image size and sampling)
void Parser::renderBlock() {
    static const std::vector<std::string> known{"width", "height", "samples", "seed", "sampler", "filter", "adaptive"};
    advance();
    expect(TokenKind::LeftBrace, "'{' after 'render'");
    RenderSettings& r = scene_.render;
    while (!match(TokenKind::RightBrace)) {
        if (!check(TokenKind::Identifier)) failExpected("a render keyword or '}'");
        const Token word = current_;
        advance();
        const SourceLoc loc = current_.loc;
        const std::string& w = word.text;
        if (w == "width" || w == "height" || w == "samples") {
            const int n = intExpr(("'" + w + "'").c_str());
            if (n < 1) error(loc, "'" + w + "' must be at least 1");
            (w == "width" ? r.width : w == "height" ? r.height : r.samplesPerPixel) = n;
        } else if (w == "seed") {
            const double s = floatExpr();
            if (s < 0 || s != std::floor(s) || s > 1.8e19) error(loc, "'seed' must be a whole number >= 0");
            else r.seed = static_cast<uint64_t>(s);
        } else if (w == "adaptive") {
            adaptiveBlock(word.loc);
        } else if (w == "sampler" || w == "filter") {
            const bool sampler = w == "sampler";
            const Token name = expect(TokenKind::String, sampler ? "a sampler name in quotes" : "a filter name in quotes");
            const auto& names = sampler ? samplerNames() : filterNames();
            if (std::find(names.begin(), names.end(), name.text) == names.end()) {
                std::string message = "unknown " + w + " '" + name.text + "'";
                const std::string near = nearestWord(name.text, names);
                if (!near.empty()) message += "; did you mean '" + near + "'?";
                error(name.loc, message);
            }
            (sampler ? r.sampler : r.filter) = name.text;
        } else {
            failUnknown(word, known);
        }
    }
}

// adaptive = "adaptive" [ "{" { adaptive-item } "}" ]   (render/render.h: RenderOptions)
void Parser::adaptiveBlock(const SourceLoc& keyword) {
    static const std::vector<std::string> known{"error", "min_samples", "max_samples"};
    RenderSettings& r = scene_.render;
    r.adaptive = true;
    if (!match(TokenKind::LeftBrace)) return;
    while (!match(TokenKind::RightBrace)) {
        if (!check(TokenKind::Identifier)) failExpected("an adaptive keyword or '}'");
        const Token word = current_;
        advance();
        const SourceLoc loc = current_.loc;
        if (word.text == "error") {
            const double e = floatExpr();
            if (!(e > 0)) error(loc, "'error' must be positive");
            else r.adaptiveError = e;
        } else if (word.text == "min_samples" || word.text == "max_samples") {
            const int n = intExpr(("'" + word.text + "'").c_str());
            if (n < 1 || n > (1 << 24)) error(loc, "'" + word.text + "' must be between 1 and 16777216");
            else (word.text == "min_samples" ? r.minSamplesPerPixel : r.maxSamplesPerPixel) = n;
        } else {
            failUnknown(word, known);
        }
    }
    if (r.minSamplesPerPixel && r.maxSamplesPerPixel && *r.maxSamplesPerPixel < *r.minSamplesPerPixel)
        error(keyword, "adaptive 'max_samples' (" + std::to_string(*r.maxSamplesPerPixel) +
                           ") must not be below 'min_samples' (" + std::to_string(*r.minSamplesPerPixel) + ")");
}

} // namespace drt
