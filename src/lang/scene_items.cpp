// Top-level statements: objects, camera, light_source, background, sky_sphere,
// fog, media, global_settings, drt's render block and #default; and the
// end-of-scene rules (POV-Ray's gamma, the image size).
#include "lang/evaluator.h"
#include "lang/shape_syntax.h"
#include "sampling/filter.h"
#include "sampling/sampler.h"

#include <cmath>
#include <fmt/format.h>

namespace drt::lang {

using Kind = Value::Kind;

void Evaluator::statement(const Token& t) {
    if (t.is(";")) return; // stray ';' as after an object declaration
    if (t.kind != TokenKind::Word) failExpected(t, "a statement (an object, camera, light_source, ...)");
    const std::string& w = t.text;
    if (isObjectWord(t) || (w == "light_source" && !lookup(w))) {
        addToScene(object(t));
    } else if (const Cell c = lookup(w)) {
        fail(t.loc, "'" + w + "' is " + kindName(*c) + ", not a statement" +
                        (c->kind == Kind::Object ? "; write object { " + w + " }" : ""));
    } else if (w == "camera") {
        if (cameraSeen_ && !isDrt())
            warnOnce("camera-twice", t.loc, "more than one camera: the last one is used (as POV-Ray)");
        scene_.camera = camera(scene_.camera, t.loc);
        cameraSeen_ = true;
    } else if (w == "background") {
        background();
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
    } else if (w == "render") {
        renderBlock();
    } else if (w == "rainbow" || w == "photons" || w == "radiosity") {
        unsupported(w, t.loc, "'" + w + "' is not supported and is ignored");
        expectSymbol("{", "after '", w, "'");
        skipBlock();
    } else {
        std::vector<std::string> known{"object"};
        for (const auto& [word, reader] : shapeReaders()) known.push_back(word);
        failUnknown(t, Block::Statement, known);
    }
}

void Evaluator::background() {
    const Token keyword = lastToken();
    expectSymbol("{", "after 'background'");
    BlockScope scope(*this, "background", keyword.loc);
    scene_.background = rgbExpr();
    const Token close = next();
    if (!close.is("}")) failInBlock(close, "'}' after the background colour");
}

// sky_sphere { [identifier] { pigment | emission colour | transform } }: the
// sky_sphere's transforms turn the directions its pigments see.
std::vector<Pigment> Evaluator::skySphere() {
    const Token keyword = lastToken();
    expectSymbol("{", "after 'sky_sphere'");
    BlockScope scope(*this, "sky_sphere", keyword.loc);
    std::vector<Pigment> layers;
    for (;;) {
        if (std::optional<Transform> tr = transformItem()) {
            for (Pigment& p : layers) transformPigmentSpaces(p, *tr);
            continue;
        }
        const Token s = next();
        if (s.is("}")) break;
        if (s.isWord("pigment")) {
            layers.push_back(pigment(Pigment{}));
        } else if (s.isWord("emission")) {
            colorExpr();
            unsupported("sky-emission", s.loc, "sky_sphere 'emission' is not supported and is ignored");
        } else if (const Cell c = s.kind == TokenKind::Word ? lookup(s.text) : nullptr; c && c->kind == Kind::SkySphere) {
            use(s.text);
            layers.insert(layers.end(), c->sky->begin(), c->sky->end());
        } else {
            failInBlock(s, "'pigment', a transform or '}' in sky_sphere");
        }
    }
    if (layers.empty()) refuse(keyword.loc, "sky_sphere needs at least one pigment");
    return layers;
}

// fog { fog_type n | distance d | colour | fog_offset h | fog_alt a | up v
//       | turbulence ... | turb_depth d | transform }   (POV-Ray defaults: type 1)
void Evaluator::fog(const Token& keyword) {
    expectSymbol("{", "after 'fog'");
    BlockScope scope(*this, "fog", keyword.loc);
    Fog f;
    bool hasDistance = false;
    for (;;) {
        const Token s = peek();
        if (s.is("}")) {
            next();
            break;
        }
        if (std::optional<Transform> tr = transformItem()) {
            f.up = tr->vector(f.up);
            continue;
        }
        if (startsColor(s) && !s.is("(") && !s.is("-")) {
            f.color = toColorFT(colorExpr());
            continue;
        }
        next();
        if (s.kind != TokenKind::Word) failInBlock(s, "a fog keyword or '}'");
        const std::string& w = s.text;
        const SourceLoc at = peek().loc;
        if (w == "fog_type") {
            const int type = intExpr("the fog type");
            if (type != 1 && type != 2) {
                if (syntax().strictValues) error(at, "'fog_type' must be 1 (constant) or 2 (ground)" + got(type));
                else warnOnce("fog_type", s.loc, "fog_type must be 1 or 2; constant fog is used");
            }
            f.type = type == 2 ? Fog::Type::Ground : Fog::Type::Constant;
        } else if (w == "distance") {
            f.distance = floatExpr("the fog distance");
            hasDistance = true;
            if (!(f.distance > 0)) refuse(at, "fog 'distance' must be positive" + got(f.distance), true);
        } else if (w == "fog_offset") {
            f.offset = floatExpr("the fog offset");
        } else if (w == "fog_alt") {
            f.altitude = floatExpr("the fog altitude");
            if (!(f.altitude > 0)) refuse(at, "'fog_alt' must be positive" + got(f.altitude));
        } else if (w == "up") {
            f.up = vectorExpr();
            requireNonZero(f.up, at, "the fog 'up'");
        } else if (w == "turbulence") {
            if (!f.turbulence) f.turbulence = Turbulence{};
            f.turbulence->amount = vectorExpr();
            noiseNote("fog turbulence", s.loc);
        } else if (w == "turb_depth") {
            f.turbDepth = floatExpr("the turbulence depth");
        } else if (w == "octaves" || w == "omega" || w == "lambda") {
            if (!f.turbulence) f.turbulence = Turbulence{};
            if (w == "octaves") {
                const int n = countExpr("octaves", -1e9, 1e9);
                if (n < 1 || n > 10) refuse(at, "'octaves' must be between 1 and 10" + got(n));
                f.turbulence->octaves = std::clamp(n, 1, 10);
            } else {
                (w == "omega" ? f.turbulence->omega : f.turbulence->lambda) = floatExpr();
            }
        } else {
            failUnknown(s, Block::Fog);
        }
    }
    if (!hasDistance && syntax().strictValues) error(keyword.loc, "fog needs a 'distance'");
    if (!(f.distance > 0)) fail(keyword.loc, "fog 'distance' must be positive");
    if (f.type == Fog::Type::Ground && !(f.altitude > 0)) fail(keyword.loc, "fog 'fog_alt' must be positive");
    scene_.fogs.push_back(f);
}

void Evaluator::globalSettings() {
    const Token keyword = lastToken();
    expectSymbol("{", "after 'global_settings'");
    BlockScope scope(*this, "global_settings", keyword.loc);
    for (;;) {
        const Token t = next();
        if (t.is("}")) {
            // POV-Ray 3.7 drops `ambient` under radiosity (only emission glows); 3.6 and before keep it.
            if (scene_.global.radiosity && version_ >= 3.7) scene_.global.ambientLight = Color(0);
            return;
        }
        if (t.kind != TokenKind::Word) failInBlock(t, "a global_settings keyword or '}'");
        const std::string& w = t.text;
        const SourceLoc at = peek().loc;
        if (w == "assumed_gamma") {
            const double g = floatExpr();
            if (!(g > 0)) fail(at, "'assumed_gamma' must be positive" + got(g));
            assumedGamma_ = g;
            scene_.global.assumedGamma = g;
        } else if (w == "max_trace_level") {
            const int64_t limit = diags_.limits().traceLevel;
            if (syntax().strictValues) {
                const int n = intExpr("'max_trace_level'");
                if (n < 1) error(at, "'max_trace_level' must be at least 1" + got(n));
                else if (n > limit)
                    error(at, limitExceeded(diags_.limits(), &Limits::traceLevel, "'max_trace_level'", n));
                scene_.global.maxTraceLevel = int(std::clamp<int64_t>(n, 1, limit));
            } else {
                // POV-Ray takes any finite level (and caps it too); above drt's
                // limit the limit is used, with a warning.
                const double value = floatExpr("'max_trace_level'");
                if (!std::isfinite(value)) fail(at, "max_trace_level must be a finite number" + got(value));
                const double level = std::max(1.0, std::trunc(value));
                if (level > double(limit))
                    warn(at, fmt::format("max_trace_level {:.0f} is above drt's {}; {} is used ({})", level, limit,
                                         limit, limitHint(diags_.limits(), &Limits::traceLevel)));
                scene_.global.maxTraceLevel = int(std::min(level, double(limit)));
            }
        } else if (w == "ambient_light") {
            scene_.global.ambientLight = rgbExpr();
        } else if (w == "adc_bailout") {
            scene_.global.adcBailout = floatExpr();
            if (scene_.global.adcBailout < 0) refuse(at, "'adc_bailout' must not be negative" + got(scene_.global.adcBailout));
        } else if (w == "radiosity") {
            // scene.h Radiosity: recursion_limit and brightness shape drt's estimate; the
            // settings of POV-Ray's sample cache have no part in it and are read and dropped.
            expectSymbol("{", "after 'radiosity'");
            BlockScope radiosityScope(*this, "radiosity", t.loc);
            Radiosity r;
            for (;;) {
                const Token k = next();
                if (k.is("}")) break;
                if (k.kind != TokenKind::Word) failInBlock(k, "a radiosity keyword or '}'");
                const std::string& item = k.text;
                const SourceLoc valueAt = peek().loc;
                if (item == "recursion_limit") {
                    const double n = floatExpr("'recursion_limit'");
                    if (!(n >= 1 && n <= 100)) fail(valueAt, "'recursion_limit' must be 1 to 100" + got(n));
                    r.recursionLimit = int(n);
                } else if (item == "brightness") {
                    r.brightness = floatExpr("'brightness'");
                    if (!(r.brightness >= 0 && std::isfinite(r.brightness)))
                        fail(valueAt, "'brightness' must be finite and not negative" + got(r.brightness));
                } else if (item == "count" || item == "nearest_count") {
                    floatExpr();
                    if (acceptSymbol(",")) floatExpr();
                } else if (item == "gray_threshold") {
                    if (floatExpr() != 0)
                        noteOnce("radiosity-gray", k.loc,
                                 "radiosity 'gray_threshold' is ignored: the gathered light keeps its colour");
                } else if (item == "error_bound" || item == "low_error_factor" || item == "minimum_reuse" ||
                           item == "maximum_reuse" || item == "pretrace_start" || item == "pretrace_end" ||
                           item == "adc_bailout" || item == "max_sample") {
                    floatExpr();
                } else if (item == "always_sample" || item == "normal" || item == "media" || item == "subsurface") {
                    optionalBool(true);
                } else if (item == "save_file" || item == "load_file") {
                    stringExpr();
                } else {
                    failExpected(k, "a radiosity keyword (recursion_limit, brightness, count, error_bound, "
                                    "gray_threshold, nearest_count, pretrace_start, pretrace_end, ...) or '}'");
                }
            }
            scene_.global.radiosity = r;
        } else if (w == "photons" || w == "subsurface") {
            unsupported("global-" + w, t.loc, "global_settings '" + w + "' is not supported and is ignored");
            expectSymbol("{", "after '", w, "'");
            skipBlock();
        } else if (w == "charset") {
            next();
        } else if (w == "number_of_waves" || w == "noise_generator" || w == "max_intersections" ||
                   w == "hf_gray_16" || w == "mm_per_unit") {
            const Token n = peekOperator();
            if (n.kind == TokenKind::Number || n.kind == TokenKind::Word) floatExpr();
        } else if (w == "irid_wavelength") {
            colorExpr();
            unsupported("global-irid", t.loc, "'irid_wavelength' is not supported and is ignored");
        } else {
            failUnknown(t, Block::GlobalSettings);
        }
    }
}

// render { width w height h samples n seed s sampler "name" filter "name" adaptive [{ ... }] }
// (drt: image size and sampling; the command line overrides them)
void Evaluator::renderBlock() {
    const Token keyword = lastToken();
    expectSymbol("{", "after 'render'");
    BlockScope scope(*this, "render", keyword.loc);
    RenderSettings& r = scene_.render;
    for (;;) {
        const Token word = next();
        if (word.is("}")) return;
        if (word.kind != TokenKind::Word) failInBlock(word, "a render keyword or '}'");
        const std::string& w = word.text;
        const SourceLoc at = peek().loc;
        if (w == "width" || w == "height" || w == "samples") {
            const int n = intExpr(("'" + w + "'").c_str());
            if (n < 1) error(at, "'" + w + "' must be at least 1" + got(n));
            else (w == "width" ? r.width : w == "height" ? r.height : r.samplesPerPixel) = n;
        } else if (w == "light_samples") {
            const int n = intExpr("'light_samples'");
            if (n < 1 || n > kMaxLightSamples)
                error(at, "'light_samples' must be between 1 and " + std::to_string(kMaxLightSamples) + got(n));
            else r.lightSamples = n;
        } else if (w == "seed") {
            const double s = floatExpr();
            if (s < 0 || s != std::floor(s) || s > 1.8e19) error(at, "'seed' must be a whole number >= 0" + got(s));
            else r.seed = static_cast<uint64_t>(s);
        } else if (w == "adaptive") {
            adaptiveBlock(word.loc);
        } else if (w == "sampler" || w == "filter") {
            const bool sampler = w == "sampler";
            const Token name = next();
            if (name.kind != TokenKind::String)
                failExpected(name, sampler ? "a sampler name in quotes" : "a filter name in quotes");
            const auto& names = sampler ? samplerNames() : filterNames();
            if (std::find(names.begin(), names.end(), name.text) == names.end()) {
                std::string message = "unknown " + w + " '" + name.text + "'";
                const std::string near = nearestWord(name.text, names);
                if (!near.empty()) message += "; did you mean '" + near + "'?";
                std::string valid;
                for (const std::string& n : names) valid += (valid.empty() ? "" : ", ") + n;
                error(name.loc, message + " (the " + w + "s are " + valid + ")");
            }
            (sampler ? r.sampler : r.filter) = name.text;
        } else {
            failUnknown(word, Block::Render);
        }
    }
}

// adaptive [ { error E min_samples a max_samples b } ]   (render/render.h: RenderOptions)
void Evaluator::adaptiveBlock(SourceLoc keyword) {
    RenderSettings& r = scene_.render;
    r.adaptive = true;
    if (!acceptSymbol("{")) return;
    BlockScope scope(*this, "adaptive", keyword);
    for (;;) {
        const Token word = next();
        if (word.is("}")) break;
        if (word.kind != TokenKind::Word) failInBlock(word, "an adaptive keyword or '}'");
        const SourceLoc at = peek().loc;
        if (word.text == "error") {
            const double e = floatExpr();
            if (!(e > 0)) error(at, "'error' must be positive" + got(e));
            else r.adaptiveError = e;
        } else if (word.text == "min_samples" || word.text == "max_samples") {
            const int n = intExpr(("'" + word.text + "'").c_str());
            if (n < 1 || n > (1 << 24)) error(at, "'" + word.text + "' must be between 1 and 16777216" + got(n));
            else (word.text == "min_samples" ? r.minSamplesPerPixel : r.maxSamplesPerPixel) = n;
        } else {
            failUnknown(word, Block::Adaptive);
        }
    }
    if (r.minSamplesPerPixel && r.maxSamplesPerPixel && *r.maxSamplesPerPixel < *r.minSamplesPerPixel)
        error(keyword, "adaptive 'max_samples' (" + std::to_string(*r.maxSamplesPerPixel) +
                           ") must not be below 'min_samples' (" + std::to_string(*r.minSamplesPerPixel) + ")");
}

// #default { texture {..} | pigment {..} | finish {..} | normal {..} }: the
// texture of objects placed after it that have none of their own. POV-Ray
// also accepts the old form without '#'.
void Evaluator::defaultBlock() {
    expectSymbol("{", "after #default");
    defaultSet_ = true;
    for (;;) {
        const Token item = next();
        if (item.is("}")) break;
        if (item.isWord("texture")) defaultTexture_ = texture(defaultTexture_);
        else if (item.isWord("pigment")) defaultTexture_.pigment = pigment(defaultTexture_.pigment);
        else if (item.isWord("finish")) defaultTexture_.finish = finish(defaultTexture_.finish);
        else if (item.isWord("normal")) {
            if (std::optional<Normal> n = normalBlock(item.loc, defaultTexture_.normal)) defaultTexture_.normal = n;
        } else {
            failExpected(item, "'texture', 'pigment', 'finish', 'normal' or '}' in #default");
        }
    }
}

namespace {

// POV-Ray 3.7 (Parse_Camera, look_at): when sky is parallel to the view
// direction, it warns and keeps the supplied right vector instead of
// sky x direction; up becomes direction x right. The model's camera would
// refuse such a sky, so the look_at is resolved here into explicit vectors.
bool resolveParallelSky(CameraSpec& cam) {
    if (!cam.lookAt || !cam.right) return false;
    const Vec3 toTarget = *cam.lookAt - cam.location;
    if (!(length(toTarget) > 0) || !(length(cam.sky) > 0)) return false; // the renderer reports these
    const Vec3 d = normalize(toTarget);
    if (length(cross(cam.sky, d)) > 1e-12 * length(cam.sky)) return false;
    const Vec3 rightUnit = normalize(*cam.right);
    const Vec3 up = cross(d, rightUnit);
    if (!(length(up) > 1e-12)) return false; // right along the view too: left to the renderer's error
    cam.direction = d * length(cam.direction);
    cam.up = normalize(up) * length(cam.up);
    cam.lookAt.reset();
    return true;
}

} // namespace

// POV-Ray's gamma rule: assumed_gamma 1.0, or #version 3.7+ without
// assumed_gamma, means linear colours. Otherwise the scene's colours are
// encoded with gamma g (2.2 when only an older #version says so) and POV-Ray
// shades them as they are, decoding only the result; the model's
// assumed_gamma does exactly that (render/film.h decodeWorkingGamma).
void Evaluator::finishScene() {
    if (scene().versionGammaRules) scene_.global.assumedGamma = workingGamma();
    if (scene().povCameraRules) {
        if (!scene_.camera.right) scene_.camera.right = Vec3(1.33, 0, 0);
        if (resolveParallelSky(scene_.camera))
            note(scene_.camera.loc, "camera: sky is parallel to the look_at direction; the right vector is kept (as POV-Ray)");
        scene_.render.width = options_.imageWidth;
        scene_.render.height = options_.imageHeight;
    }
}

} // namespace drt::lang
