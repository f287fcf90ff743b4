// The .drt writer (src/lang/writer.h): every example scene survives
// load -> write -> load with an identical scene model and a bit-identical
// image; every field the language can express is written; what it cannot
// express is reported.
#include "lang/load.h"
#include "lang/writer.h"
#include "lang/writer_function.h"
#include "lang/writer_detail.h"
#include "render/render.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

namespace drt {
namespace {

namespace fs = std::filesystem;

// ------------------------------------------------------------ deep comparison
// The first field that differs between two scene models, as a path
// ("objects[2].texture.pigment.toWorld"), or "" if they are identical.
// Source locations are not compared (the files differ by design).

struct Differ {
    std::string where;
    bool differs(const std::string& path) {
        if (where.empty())
            where = path;
        return false;
    }
    template <class T> bool eq(const T& a, const T& b, const std::string& path) {
        return a == b || differs(path);
    }
    bool transform(const Transform& a, const Transform& b, const std::string& path) {
        // The renderer uses the inverse too: compare both.
        return (a.matrix() == b.matrix() && a.inverseMatrix() == b.inverseMatrix()) || differs(path);
    }
    // Functions: the same parameters and the same text (their pattern operands are copies).
    bool function(const std::shared_ptr<const Function>& a, const std::shared_ptr<const Function>& b,
                  const std::string& p) {
        if (!a || !b) return eq(bool(a), bool(b), p);
        std::set<std::string> problems;
        return eq(a->params, b->params, p + ".params") && eq(a->colour, b->colour, p + ".colour") &&
               eq(writer::functionText(*a, problems), writer::functionText(*b, problems), p + ".text");
    }
    bool pigment(const Pigment& a, const Pigment& b, const std::string& p) {
        bool ok = eq(a.pattern, b.pattern, p + ".pattern") && eq(a.color, b.color, p + ".color") &&
                  function(a.function, b.function, p + ".function") &&
                  eq(a.gradientAxis, b.gradientAxis, p + ".gradientAxis") &&
                  eq(a.brickSize, b.brickSize, p + ".brickSize") && eq(a.mortar, b.mortar, p + ".mortar") &&
                  eq(a.wave.kind, b.wave.kind, p + ".wave.kind") &&
                  eq(a.wave.frequency, b.wave.frequency, p + ".wave.frequency") &&
                  eq(a.wave.phase, b.wave.phase, p + ".wave.phase") &&
                  eq(a.wave.exponent, b.wave.exponent, p + ".wave.exponent") &&
                  // A solid colour's transform is unused (and not written).
                  (a.pattern == PatternKind::Solid || transform(a.toWorld, b.toWorld, p + ".toWorld")) &&
                  eq(a.colorMap.size(), b.colorMap.size(), p + ".colorMap.size") &&
                  eq(a.children.size(), b.children.size(), p + ".children.size");
        for (size_t i = 0; ok && i < a.colorMap.size(); ++i)
            ok = eq(a.colorMap[i].value, b.colorMap[i].value, p + ".colorMap.value") &&
                 eq(a.colorMap[i].color, b.colorMap[i].color, p + ".colorMap.color");
        for (size_t i = 0; ok && i < a.children.size(); ++i)
            ok = pigment(a.children[i], b.children[i], p + ".children[" + std::to_string(i) + "]");
        return ok;
    }
    bool media(const std::vector<Media>& a, const std::vector<Media>& b, const std::string& p) {
        bool ok = eq(a.size(), b.size(), p + ".size");
        for (size_t i = 0; ok && i < a.size(); ++i) {
            const Media &s = a[i], &t = b[i];
            const std::string q = p + "[" + std::to_string(i) + "]";
            ok = eq(s.absorption, t.absorption, q + ".absorption") && eq(s.emission, t.emission, q + ".emission") &&
                 eq(s.scatteringType, t.scatteringType, q + ".scatteringType") &&
                 eq(s.scattering, t.scattering, q + ".scattering") &&
                 eq(s.eccentricity, t.eccentricity, q + ".eccentricity") &&
                 eq(s.extinction, t.extinction, q + ".extinction") && eq(s.intervals, t.intervals, q + ".intervals") &&
                 eq(s.samples, t.samples, q + ".samples") &&
                 eq(s.densities.size(), t.densities.size(), q + ".densities.size");
            for (size_t j = 0; ok && j < s.densities.size(); ++j)
                ok = pigment(s.densities[j], t.densities[j], q + ".densities[" + std::to_string(j) + "]");
        }
        return ok;
    }
    bool finish(const Finish& a, const Finish& b, const std::string& p) {
        return eq(a.ambient, b.ambient, p + ".ambient") && eq(a.emission, b.emission, p + ".emission") &&
               eq(a.diffuse, b.diffuse, p + ".diffuse") &&
               eq(a.brilliance, b.brilliance, p + ".brilliance") && eq(a.phong, b.phong, p + ".phong") &&
               eq(a.phongSize, b.phongSize, p + ".phongSize") &&
               eq(a.specular, b.specular, p + ".specular") &&
               eq(a.roughness, b.roughness, p + ".roughness") &&
               eq(a.metallic, b.metallic, p + ".metallic") &&
               eq(a.reflectionMin, b.reflectionMin, p + ".reflectionMin") &&
               eq(a.reflectionMax, b.reflectionMax, p + ".reflectionMax") &&
               eq(a.reflectionFresnel, b.reflectionFresnel, p + ".reflectionFresnel") &&
               eq(a.reflectionFalloff, b.reflectionFalloff, p + ".reflectionFalloff") &&
               eq(a.reflectionMetallic, b.reflectionMetallic, p + ".reflectionMetallic") &&
               eq(a.conserveEnergy, b.conserveEnergy, p + ".conserveEnergy") &&
               eq(a.reflectionBlur, b.reflectionBlur, p + ".reflectionBlur") &&
               eq(a.refractionBlur, b.refractionBlur, p + ".refractionBlur") && eq(a.crand, b.crand, p + ".crand");
    }
    bool shape(const Shape& a, const Shape& b, const std::string& p) {
        if (!eq(a.index(), b.index(), p + ".kind"))
            return false;
        if (auto* s = std::get_if<Sphere>(&a)) {
            auto& t = std::get<Sphere>(b);
            return eq(s->center, t.center, p + ".center") && eq(s->radius, t.radius, p + ".radius");
        }
        if (auto* s = std::get_if<Plane>(&a)) {
            auto& t = std::get<Plane>(b);
            return eq(s->normal, t.normal, p + ".normal") && eq(s->distance, t.distance, p + ".distance");
        }
        if (auto* s = std::get_if<Box>(&a)) {
            auto& t = std::get<Box>(b);
            return eq(s->corner1, t.corner1, p + ".corner1") && eq(s->corner2, t.corner2, p + ".corner2");
        }
        if (auto* s = std::get_if<Cylinder>(&a)) {
            auto& t = std::get<Cylinder>(b);
            return eq(s->base, t.base, p + ".base") && eq(s->cap, t.cap, p + ".cap") &&
                   eq(s->radius, t.radius, p + ".radius") && eq(s->open, t.open, p + ".open");
        }
        if (auto* s = std::get_if<Cone>(&a)) {
            auto& t = std::get<Cone>(b);
            return eq(s->base, t.base, p + ".base") && eq(s->baseRadius, t.baseRadius, p + ".baseRadius") &&
                   eq(s->cap, t.cap, p + ".cap") && eq(s->capRadius, t.capRadius, p + ".capRadius") &&
                   eq(s->open, t.open, p + ".open");
        }
        if (auto* s = std::get_if<Disc>(&a)) {
            auto& t = std::get<Disc>(b);
            return eq(s->center, t.center, p + ".center") && eq(s->normal, t.normal, p + ".normal") &&
                   eq(s->radius, t.radius, p + ".radius") &&
                   eq(s->holeRadius, t.holeRadius, p + ".holeRadius");
        }
        if (auto* s = std::get_if<Torus>(&a)) {
            auto& t = std::get<Torus>(b);
            return eq(s->majorRadius, t.majorRadius, p + ".major") &&
                   eq(s->minorRadius, t.minorRadius, p + ".minor");
        }
        if (auto* s = std::get_if<Algebraic>(&a)) {
            auto& t = std::get<Algebraic>(b);
            return eq(s->form, t.form, p + ".form") && eq(s->order, t.order, p + ".order") &&
                   eq(s->coefficients, t.coefficients, p + ".coefficients") && eq(s->sturm, t.sturm, p + ".sturm");
        }
        if (auto* s = std::get_if<Superellipsoid>(&a)) {
            auto& t = std::get<Superellipsoid>(b);
            return eq(s->e, t.e, p + ".e") && eq(s->n, t.n, p + ".n");
        }
        if (auto* s = std::get_if<Mesh>(&a)) {
            auto& t = std::get<Mesh>(b);
            return eq(s->vertices, t.vertices, p + ".vertices") &&
                   eq(s->triangles, t.triangles, p + ".triangles") &&
                   eq(s->normals, t.normals, p + ".normals") &&
                   eq(s->normalIndices, t.normalIndices, p + ".normalIndices");
        }
        if (auto* s = std::get_if<Extrusion>(&a))
            return extrusion(*s, std::get<Extrusion>(b), p);
        if (auto* s = std::get_if<Revolution>(&a)) {
            auto& t = std::get<Revolution>(b);
            bool ok = eq(s->kind, t.kind, p + ".kind") && eq(s->spline, t.spline, p + ".spline") &&
                      eq(s->open, t.open, p + ".open") && eq(s->sturm, t.sturm, p + ".sturm") &&
                      eq(s->points.size(), t.points.size(), p + ".points.size");
            for (size_t i = 0; ok && i < s->points.size(); ++i)
                ok = eq(s->points[i].x, t.points[i].x, p + ".points.x") &&
                     eq(s->points[i].y, t.points[i].y, p + ".points.y");
            return ok;
        }
        if (auto* s = std::get_if<Blob>(&a)) {
            auto& t = std::get<Blob>(b);
            bool ok = eq(s->threshold, t.threshold, p + ".threshold") && eq(s->sturm, t.sturm, p + ".sturm") &&
                      eq(s->hierarchy, t.hierarchy, p + ".hierarchy") &&
                      eq(s->components.size(), t.components.size(), p + ".components.size");
            for (size_t i = 0; ok && i < s->components.size(); ++i) {
                const BlobComponent &x = s->components[i], &y = t.components[i];
                ok = eq(x.kind, y.kind, p + ".kind") && eq(x.center, y.center, p + ".center") &&
                     eq(x.end, y.end, p + ".end") && eq(x.radius, y.radius, p + ".radius") &&
                     eq(x.strength, y.strength, p + ".strength") &&
                     eq(x.transform.matrix() == y.transform.matrix() &&
                            x.transform.inverseMatrix() == y.transform.inverseMatrix(),
                        true, p + ".transform");
            }
            return ok;
        }
        if (auto* s = std::get_if<Isosurface>(&a)) {
            auto& t = std::get<Isosurface>(b);
            Isosurface x = *s, y = t;
            x.function = y.function = nullptr;
            return function(s->function, t.function, p + ".function") && eq(x == y, true, p + ".isosurface");
        }
        auto& s = std::get<Csg>(a);
        auto& t = std::get<Csg>(b);
        bool ok = eq(s.op, t.op, p + ".op") && eq(s.children.size(), t.children.size(), p + ".children.size");
        for (size_t i = 0; ok && i < s.children.size(); ++i)
            ok = object(s.children[i], t.children[i], p + ".children[" + std::to_string(i) + "]");
        return ok;
    }
    bool extrusion(const Extrusion& s, const Extrusion& t, const std::string& p) {
        bool ok = eq(s.plane, t.plane, p + ".plane") && eq(s.fill, t.fill, p + ".fill") &&
                  eq(s.height1, t.height1, p + ".height1") && eq(s.height2, t.height2, p + ".height2") &&
                  eq(s.conic, t.conic, p + ".conic") && eq(s.open, t.open, p + ".open") &&
                  eq(s.contours.size(), t.contours.size(), p + ".contours.size") &&
                  eq(s.prism.has_value(), t.prism.has_value(), p + ".prism") &&
                  eq(s.text.has_value(), t.text.has_value(), p + ".text");
        for (size_t i = 0; ok && i < s.contours.size(); ++i) {
            ok = eq(s.contours[i].size(), t.contours[i].size(), p + ".contours.size");
            for (size_t k = 0; ok && k < s.contours[i].size(); ++k)
                ok = eq(s.contours[i][k].x, t.contours[i][k].x, p + ".contours.x") &&
                     eq(s.contours[i][k].y, t.contours[i][k].y, p + ".contours.y");
        }
        if (ok && s.text)
            ok = eq(s.text->fontPath, t.text->fontPath, p + ".text.fontPath") &&
                 eq(s.text->string, t.text->string, p + ".text.string") &&
                 eq(s.text->offset, t.text->offset, p + ".text.offset");
        if (ok && s.prism)
            ok = eq(s.prism->spline, t.prism->spline, p + ".prism.spline") &&
                 eq(s.prism->points.size(), t.prism->points.size(), p + ".prism.points");
        return ok;
    }
    bool motion(const MotionChain& a, const MotionChain& b, const std::string& p) {
        if (!eq(a.size(), b.size(), p + ".size"))
            return false;
        for (size_t i = 0; i < a.size(); ++i) {
            const Motion &m = a[i].motion, &n = b[i].motion;
            const std::string q = p + "[" + std::to_string(i) + "]";
            if (!eq(m.keys.size(), n.keys.size(), q + ".keys") || !eq(m.spline, n.spline, q + ".spline") ||
                !transform(a[i].after, b[i].after, q + ".after"))
                return false;
            for (size_t k = 0; k < m.keys.size(); ++k)
                if (!eq(m.keys[k].time, n.keys[k].time, q + ".time") ||
                    !eq(m.keys[k].translate, n.keys[k].translate, q + ".translate") ||
                    !eq(m.keys[k].rotate, n.keys[k].rotate, q + ".rotate") ||
                    !eq(m.keys[k].scale, n.keys[k].scale, q + ".scale"))
                    return false;
        }
        return true;
    }
    bool object(const Object& a, const Object& b, const std::string& p) {
        return shape(a.shape, b.shape, p + ".shape") &&
               transform(a.transform, b.transform, p + ".transform") &&
               motion(a.motion, b.motion, p + ".motion") &&
               pigment(a.texture->pigment, b.texture->pigment, p + ".pigment") &&
               finish(a.texture->finish, b.texture->finish, p + ".finish") &&
               eq(a.interior.ior, b.interior.ior, p + ".ior") &&
               eq(a.interior.fadeDistance, b.interior.fadeDistance, p + ".fadeDistance") &&
               eq(a.interior.fadePower, b.interior.fadePower, p + ".fadePower") &&
               eq(a.interior.fadeColor, b.interior.fadeColor, p + ".fadeColor") &&
               media(a.interior.media, b.interior.media, p + ".media") &&
               eq(a.noShadow, b.noShadow, p + ".noShadow") && eq(a.hollow, b.hollow, p + ".hollow") &&
               eq(a.inverse, b.inverse, p + ".inverse") && clips(a.clippedBy, b.clippedBy, p + ".clippedBy");
    }
    bool clips(const std::vector<Object>& a, const std::vector<Object>& b, const std::string& p) {
        bool ok = eq(a.size(), b.size(), p + ".size");
        for (size_t i = 0; ok && i < a.size(); ++i) {
            const std::string q = p + "[" + std::to_string(i) + "]";
            ok = shape(a[i].shape, b[i].shape, q + ".shape") && transform(a[i].transform, b[i].transform, q) &&
                 eq(a[i].inverse, b[i].inverse, q + ".inverse") && clips(a[i].clippedBy, b[i].clippedBy, q);
        }
        return ok;
    }
    bool light(const Light& a, const Light& b, const std::string& p) {
        bool ok = eq(a.position, b.position, p + ".position") && eq(a.color, b.color, p + ".color") &&
                  eq(a.shadowless, b.shadowless, p + ".shadowless") &&
                  eq(a.spotlight, b.spotlight, p + ".spotlight") &&
                  eq(a.pointAt, b.pointAt, p + ".pointAt") && eq(a.radius, b.radius, p + ".radius") &&
                  eq(a.falloff, b.falloff, p + ".falloff") &&
                  eq(a.tightness, b.tightness, p + ".tightness") &&
                  eq(a.fadeDistance, b.fadeDistance, p + ".fadeDistance") &&
                  eq(a.fadePower, b.fadePower, p + ".fadePower") &&
                  // area_illumination means nothing without an area (and is then not written).
                  (!a.area || eq(a.areaIllumination, b.areaIllumination, p + ".areaIllumination")) &&
                  eq(a.inverseSquare, b.inverseSquare, p + ".inverseSquare") &&
                  eq(a.mediaInteraction, b.mediaInteraction, p + ".mediaInteraction") &&
                  eq(a.mediaAttenuation, b.mediaAttenuation, p + ".mediaAttenuation") &&
                  eq(a.area.has_value(), b.area.has_value(), p + ".area");
        if (ok && a.area) {
            const AreaLight &s = *a.area, &t = *b.area;
            ok = eq(s.axis1, t.axis1, p + ".axis1") && eq(s.axis2, t.axis2, p + ".axis2") &&
                 eq(s.size1, t.size1, p + ".size1") && eq(s.size2, t.size2, p + ".size2") &&
                 eq(s.jitter, t.jitter, p + ".jitter") && eq(s.adaptive, t.adaptive, p + ".adaptive") &&
                 eq(s.circular, t.circular, p + ".circular") && eq(s.orient, t.orient, p + ".orient") &&
                 eq(s.sampling, t.sampling, p + ".sampling");
        }
        return ok;
    }
    bool camera(const CameraSpec& a, const CameraSpec& b) {
        return eq(a.location, b.location, "camera.location") &&
               eq(a.direction, b.direction, "camera.direction") && eq(a.up, b.up, "camera.up") &&
               eq(a.right, b.right, "camera.right") && eq(a.sky, b.sky, "camera.sky") &&
               eq(a.lookAt, b.lookAt, "camera.lookAt") && eq(a.angle, b.angle, "camera.angle") &&
               eq(a.aperture, b.aperture, "camera.aperture") &&
               eq(a.focalPoint, b.focalPoint, "camera.focalPoint") &&
               eq(a.focalDistance, b.focalDistance, "camera.focalDistance") &&
               eq(a.shutterOpen, b.shutterOpen, "camera.shutterOpen") &&
               eq(a.shutterClose, b.shutterClose, "camera.shutterClose");
    }
    bool scene(const Scene& a, const Scene& b) {
        bool ok = camera(a.camera, b.camera) && eq(a.background, b.background, "background") &&
                  eq(a.global.maxTraceLevel, b.global.maxTraceLevel, "global.maxTraceLevel") &&
                  eq(a.global.ambientLight, b.global.ambientLight, "global.ambientLight") &&
                  eq(a.global.assumedGamma, b.global.assumedGamma, "global.assumedGamma") &&
                  eq(a.global.adcBailout, b.global.adcBailout, "global.adcBailout") &&
                  eq(a.render.width, b.render.width, "render.width") &&
                  eq(a.render.height, b.render.height, "render.height") &&
                  eq(a.render.samplesPerPixel, b.render.samplesPerPixel, "render.samples") &&
                  eq(a.render.lightSamples, b.render.lightSamples, "render.lightSamples") &&
                  eq(a.render.seed, b.render.seed, "render.seed") &&
                  eq(a.render.sampler, b.render.sampler, "render.sampler") &&
                  eq(a.render.filter, b.render.filter, "render.filter") &&
                  eq(a.render.adaptive, b.render.adaptive, "render.adaptive") &&
                  eq(a.render.adaptiveError, b.render.adaptiveError, "render.adaptiveError") &&
                  eq(a.render.minSamplesPerPixel, b.render.minSamplesPerPixel, "render.minSamples") &&
                  eq(a.render.maxSamplesPerPixel, b.render.maxSamplesPerPixel, "render.maxSamples") &&
                  media(a.media, b.media, "media") &&
                  eq(a.lights.size(), b.lights.size(), "lights.size") &&
                  eq(a.objects.size(), b.objects.size(), "objects.size");
        for (size_t i = 0; ok && i < a.lights.size(); ++i)
            ok = light(a.lights[i], b.lights[i], "lights[" + std::to_string(i) + "]");
        for (size_t i = 0; ok && i < a.objects.size(); ++i)
            ok = object(a.objects[i], b.objects[i], "objects[" + std::to_string(i) + "]");
        return ok;
    }
};

std::string firstDifference(const Scene& a, const Scene& b) {
    Differ d;
    d.scene(a, b);
    return d.where;
}

// ------------------------------------------------------------ helpers

std::optional<Scene> loadText(const std::string& text, const std::string& dir = ".") {
    Diagnostics diags;
    std::optional<Scene> scene = loadSceneText(text, "written.drt", diags, dir);
    EXPECT_FALSE(diags.hasErrors()) << diags.formatAll() << "\n--- text:\n" << text;
    return diags.hasErrors() ? std::nullopt : scene;
}

// Writes `scene`, loads the text back, and checks the model is identical.
std::optional<Scene> roundTrip(const Scene& scene, std::string* written = nullptr) {
    const std::string text = writeDrtScene(scene, {"test"});
    if (written)
        *written = text;
    std::optional<Scene> again = loadText(text);
    if (!again)
        return std::nullopt;
    const std::string difference = firstDifference(scene, *again);
    EXPECT_EQ(difference, "") << "--- written:\n" << text;
    return again;
}

Image renderSmall(const Scene& scene) {
    RenderOptions options = resolveRenderOptions(scene.render);
    options.width = 64;
    options.height = 48;
    options.samplesPerPixel = std::min(options.samplesPerPixel, 4);
    return render(test::withAssets(scene), options).color;
}

// ------------------------------------------------------------ examples

TEST(Writer, EveryExampleRoundTripsToTheSameModelAndTheSameImage) {
    int examples = 0;
    for (const auto& entry : fs::directory_iterator(test::sourcePath("examples"))) {
        if (entry.path().extension() != ".drt")
            continue;
        SCOPED_TRACE(entry.path().filename().string());
        ++examples;
        Diagnostics diags;
        const std::optional<Scene> original = loadSceneFile(entry.path().string(), diags);
        ASSERT_TRUE(original) << diags.formatAll();
        std::string text;
        const std::optional<Scene> again = roundTrip(*original, &text);
        ASSERT_TRUE(again);
        EXPECT_TRUE(drtInexpressible(*original).empty());
        const Image a = renderSmall(*original), b = renderSmall(*again);
        ASSERT_EQ(a.pixels.size(), b.pixels.size());
        size_t differing = 0;
        for (size_t i = 0; i < a.pixels.size(); ++i)
            differing += a.pixels[i] != b.pixels[i];
        EXPECT_EQ(differing, 0u) << "float channel values differ after the round trip";
        // Writing is a fixed point: the reloaded scene writes the same text.
        EXPECT_EQ(writeDrtScene(*again, {"test"}), text);
    }
    EXPECT_GE(examples, 3);
}

TEST(Writer, RotationsBeyondNinetyDegreesAreWrittenAsRotationsThatRebuildTheModel) {
    // asin gives the Euler angle about y within +-90 degrees, so `rotate y*160`
    // first decomposes as <180, 20, 180> and `rotate y*200` as <0, -160, 0>:
    // the same rotation, not the same bits. The writer tries the other Euler
    // solution and the [0, 360) form too, and checks each by composing it.
    for (const char* rotation : {"y * 160", "y * 200", "x * 120", "z * -135", "<10, 160, 30>"}) {
        SCOPED_TRACE(rotation);
        const std::optional<Scene> scene = loadText(std::string("sphere { 0, 1 scale 0.1 rotate ") + rotation +
                                                    " translate <-0.9, 0, -1.1> }");
        ASSERT_TRUE(scene);
        std::string written;
        ASSERT_TRUE(roundTrip(*scene, &written));
        EXPECT_EQ(written.find("matrix"), std::string::npos) << written;
    }
}

// ------------------------------------------------------------ every field

TEST(Writer, EveryLanguageFieldRoundTrips) {
    const std::optional<Scene> scene = loadText(R"(
render { width 40 height 30 samples 3 light_samples 5 seed 7 sampler "independent" filter "box" adaptive { error 0.05 min_samples 2 max_samples 9 } }
global_settings { max_trace_level 12 ambient_light rgb <0.5, 0.6, 0.7> assumed_gamma 2.2 adc_bailout 0.01 }
background { color rgb <0.1, 0.2, 0.3> }
camera { location <1, 2, -5> direction <0, 0, 2> up <0, 1.1, 0> right <1.4, 0, 0> sky <0, 1, 0.1>
         look_at <0, 1, 0> angle 47 aperture 0.3 focal_point <0, 1, 0.5> focal_distance 4
         shutter_open 0.1 shutter_close 0.9 }
light_source { <0, 10, 0>, color rgb <1, 0.9, 0.8> translate x rotate 10 * y inverse_square }
light_source { <-5, 8, -5>, rgb 2 spotlight point_at <0, 0, 1> radius 12 falloff 20 tightness 5
               fade_distance 3 fade_power 2 shadowless area_illumination off }
light_source { <5, 8, -5>, rgb 0.5 area_light <2, 0, 0>, <0, 0, 3>, 4, 5 jitter adaptive 2 circular orient
               area_sampling pov_grid scale 2 }
light_source { <5, 8, 5>, rgb 0.5 area_light x, z, 2, 3 area_sampling solid_angle }
sphere { <0, 1, 0>, 1.5 pigment { rgbft <0.1, 0.2, 0.3, 0.4, 0.5> } scale <1, 2, 3> rotate <10, 20, 30> translate 1 }
plane { <0, 2, 0>, 1 pigment { checker rgb 1, pigment { gradient <1, 1, 0> color_map { [0 rgb 0] [0.3 rgbf <1, 0, 0, 0.5>] [1 rgbt <0, 0, 1, 0.2>] } scale 0.3 } rotate 5 * y } }
box { <-1, 0, -1>, <1, 0.5, 1> translate x * 3 pigment { hexagon rgb 1, rgb 0.5, rgb 0 scale 0.2 } }
box { 0, 1 pigment { brick rgb 0.8, rgb <0.6, 0.2, 0.1> brick_size <0.5, 0.2, 0.3> mortar 0.02 } rotate <0, 0, 17> }
cylinder { <0, 0, 0>, <0, 2, 0>, 0.5 open translate -x * 3 pigment { radial color_map { [0 rgb 1] [1 rgb 0] } } }
cone { <0, 0, 0>, 1, <0, 2, 0>, 0.2 open pigment { onion } translate z * 3 }
sphere { <2, 0, 2>, 0.5 pigment { planar color_map { [0 rgb 0] [1 rgb <1, 0.5, 0>] } scale 0.5 } }
sphere { <2, 0, -2>, 0.5 pigment { cylindrical } }
sphere { <-2, 0, 2>, 0.5 texture { boxed texture_map { [0 pigment { rgb 1 }] [1 pigment { rgb 0 }] } } }
disc { <0, 0.01, 0>, <0, 1, 1>, 2, 1 }
torus { 1, 0.25 translate y * 3 no_shadow hollow inverse }
quadric { <1, 2, 3>, <0.5, -0.25, 0.125>, <0.1, 0.2, 0.3>, -1 translate <4, 1, 0> }
cubic { <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, -0.5> sturm scale 0.5 translate <-4, 1, 0> }
quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, -104, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 56, 0, 0, 0, 0, 1, 0, -104, 0, 784> scale 0.1 }
poly { 2, <1, 0, 0, 0, 0, 0, 0, 1, 0, -0.01> }
superellipsoid { <0.3, 2.5> translate <2, 1, 2> }
triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
smooth_triangle { <0, 0, 0>, <0, 0, -1>, <1, 0, 0>, <0, 0.2, -1>, <0, 1, 0>, <0.1, 0, -1> }
mesh { triangle { <0, 0, 0>, <1, 0, 0>, <1, 1, 0> } smooth_triangle { <0, 0, 0>, <0, 0, -1>, <1, 1, 0>, <0, 1, -1>, <0, 1, 0>, <1, 0, -1> } translate z * 5 }
sphere { 0, 1 texture { pigment { rgb 1 } finish { ambient rgb <0.1, 0.2, 0.3> emission 0.2 diffuse 0.5 brilliance 2
   phong 0.6 phong_size 60 specular 0.2 roughness 0.02 metallic 0.7
   reflection { 0.05, rgb <0.6, 0.5, 0.4> fresnel on falloff 2 metallic 0.5 } conserve_energy
   reflection_blur 0.1 refraction_blur 0.3 crand 0.05 } }
   interior { ior 1.5 fade_distance 2 fade_power 1 fade_color rgb <0, 0.3, 0.4> } }
sphere { 0, 0.5 pigment { rgb <1, 0, 0> } finish { reflection 0.3 } translate <-1, 1, 0> motion { translate <2, 0, 0> rotate <0, 30, 0> scale 1.5 } }
union { sphere { <-1, 0, 0>, 0.3 } sphere { <1, 0, 0>, 0.3 pigment { rgb <0, 0, 1> } } pigment { checker scale 0.1 }
        rotate 30 * x translate y * 2.5 no_shadow }
sphere { 0, 1 scale 2 clipped_by { box { -1, <1, 0.5, 1> } plane { x, 0.3 inverse } } translate <4, 1, 0> }
union { sphere { 0, 1 clipped_by { plane { y, 0 } } } box { -1, 1 translate 3 * x } clipped_by { sphere { x, 1.5 } } rotate 20 * z }
difference { box { -1, 1 translate -4 * x } sphere { 0, 1.2 clipped_by { box { 0, 2 } } translate <-4, 1, 0> } clipped_by { plane { -z, 0.5 } } }
#declare Sq = function(t) { t * t }
#declare Pat = function { pattern { gradient x scale 2 } }
#declare Col = function { pigment { checker rgb <1, 0, 0>, rgb <0, 0, 1> } }
sphere { 0, 1 pigment { function { Sq(x) * 0.5 + abs(-y) + select(z, 1, 0.5) + (x < 0 ? f_sphere(x, y, z, 0.5) : -2) } color_map { [0 rgb 0] [1 rgb 1] } } translate <0, 5, 0> }
box { -1, 1 texture { function { Pat(x, y, z) + Col(x, y, z).blue * 0.25 + f_noise3d(x, y, z) * 0.1 } texture_map { [0 pigment { rgb 1 }] [1 pigment { rgb 0 }] } } translate <3, 5, 0> }
sphere { 0, 1 pigment { rgb 0.5 } normal { function { sin(x * 10) * pow(y, 2) } 0.4 } translate <-3, 5, 0> }
isosurface { function { f_torus(x, y, z, 0.8, 0.2) + 0.05 * sin(x * 9) } contained_by { box { <-1, -0.4, -1>, <1, 0.4, 1> } } threshold 0.01 accuracy 0.002 max_gradient 1.6 translate <0, 5, 3> }
isosurface { function(a, b, c) { a * a + b * b + c * c - 0.5 } contained_by { sphere { 0, 1 } } open all_intersections evaluate 1, 2, 0.9 translate <3, 5, 3> }
)");
    ASSERT_TRUE(scene);
    std::string text;
    const std::optional<Scene> again = roundTrip(*scene, &text);
    ASSERT_TRUE(again);
    EXPECT_TRUE(drtInexpressible(*scene).empty());
    EXPECT_EQ(writeDrtScene(*again, {"test"}), text);
    const Image a = renderSmall(*scene), b = renderSmall(*again);
    EXPECT_TRUE(a.pixels == b.pixels);
}

TEST(Writer, PatternWavesRoundTripToTheSameModelAndTheSameImage) {
    const std::optional<Scene> scene = loadText(R"(
camera { location <0, 1, -5> look_at <0, 0.5, 0> }
light_source { <5, 8, -5>, rgb 1 }
plane { y, 0 pigment { gradient x color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] } frequency 2 phase 0.25 triangle_wave } }
sphere { <-1.2, 1, 0>, 1 pigment { marble poly_wave 2.5 frequency 3 } normal { bumps 0.6 sine_wave scale 0.2 } }
sphere { <1.2, 1, 0>, 1 pigment { onion scallop_wave scale 0.3 } }
box { <-3, 0, 1>, <3, 2, 1.5> texture { gradient y texture_map { [0 pigment { rgb 1 }] [1 pigment { rgb <0, 1, 0> }] } cubic_wave frequency -1.5 } }
cylinder { <0, 0, -2>, <0, 2, -2>, 0.3 pigment { bozo ramp_wave phase 0.5 } }
)");
    ASSERT_TRUE(scene);
    std::string text;
    const std::optional<Scene> again = roundTrip(*scene, &text);
    ASSERT_TRUE(again);
    EXPECT_NE(text.find("triangle_wave"), std::string::npos) << text;
    EXPECT_NE(text.find("poly_wave 2.5"), std::string::npos) << text;
    EXPECT_NE(text.find("cubic_wave"), std::string::npos) << text;
    EXPECT_NE(text.find("sine_wave"), std::string::npos) << text;
    EXPECT_EQ(again->objects.at(1).texture->normal->wave.kind, WaveKind::Sine);
    EXPECT_EQ(again->objects.at(3).texture->pigment.wave.frequency, -1.5);
    EXPECT_EQ(writeDrtScene(*again, {"test"}), text);
    const Image a = renderSmall(*scene), b = renderSmall(*again);
    EXPECT_TRUE(a.pixels == b.pixels);
}

TEST(Writer, MediaRoundTripToTheSameModelAndTheSameImage) {
    const std::optional<Scene> scene = loadText(R"(
camera { location <0, 0, -6> look_at 0 }
media { scattering { 4, rgb <0.01, 0.02, 0.03> extinction 0.5 } intervals 2 samples 3 method 3 jitter 0.1 }
light_source { <2, 4, -3>, rgb 1 spotlight point_at 0 radius 10 falloff 20 media_interaction off }
light_source { <-2, 4, -3>, rgb 0.5 media_attenuation off }
sphere { 0, 1 pigment { rgbt 1 } hollow scale 1.5 rotate 20 * y
  interior { ior 1.2 media { emission rgb <0.2, 0.1, 0> absorption 0.3
                             scattering { 5, 0.2 eccentricity -0.4 }
                             density { spherical color_map { [0 rgb 0] [1 rgb 1] } scale 0.5 }
                             density { gradient y translate 0.1 } }
             media { absorption rgb <0.1, 0, 0> } } translate x }
box { -1, 1 translate <0, -2, 2> }
)");
    ASSERT_TRUE(scene);
    ASSERT_EQ(scene->objects[0].interior.media.size(), 2u);
    ASSERT_EQ(scene->objects[0].interior.media[0].densities.size(), 2u);
    std::string text;
    const std::optional<Scene> again = roundTrip(*scene, &text);
    ASSERT_TRUE(again);
    EXPECT_TRUE(drtInexpressible(*scene).empty());
    EXPECT_EQ(writeDrtScene(*again, {"test"}), text);
    const Image a = renderSmall(*scene), b = renderSmall(*again);
    EXPECT_TRUE(a.pixels == b.pixels);
}

// ------------------------------------------------------------ transforms

TEST(Writer, TransformsAreWrittenReadablyWhenExact) {
    const std::optional<Scene> scene =
        loadText("sphere { 0, 1 scale 2 translate <1, 2, 3> }\n"
                 "sphere { 0, 1 rotate <0, 30, 0> translate x }\n"
                 "sphere { 0, 1 translate 2 * x rotate <0, 30, 0> scale <1.3, 1, 1> }\n");
    ASSERT_TRUE(scene);
    std::string text;
    ASSERT_TRUE(roundTrip(*scene, &text));
    EXPECT_NE(text.find("scale 2 translate <1, 2, 3>"), std::string::npos) << text;
    EXPECT_NE(text.find("rotate <0, 30, 0> translate <1, 0, 0>"), std::string::npos) << text;
    EXPECT_NE(text.find("translate <2, 0, 0> rotate <0, 30, 0> scale <1.3, 1, 1>"), std::string::npos)
        << text;
    EXPECT_EQ(text.find("matrix"), std::string::npos) << text;
}

TEST(Writer, AnyAffineTransformRoundTripsItsMatrix) {
    // Shears have no translate/rotate/scale form: they come out as `matrix`.
    std::array<double, 12> shear{1, 0.5, 0, 0, 1, 0, 0.25, 0, 1, 3, -2, 1e-7};
    Scene scene;
    Object o;
    o.transform = *Transform::fromPovMatrix(shear);
    o.texture.edit().pigment.toWorld = o.transform; // as the parser leaves an untextured object
    scene.objects.push_back(o);
    std::string text;
    const std::optional<Scene> again = roundTrip(scene, &text);
    ASSERT_TRUE(again);
    EXPECT_NE(text.find("matrix <1, 0.5, 0, 0, 1, 0, 0.25, 0, 1, 3, -2, 1e-07>"), std::string::npos) << text;
}

TEST(Writer, DecomposeReproducesRandomTransformChains) {
    // Chains of random rotations, scales (some mirroring) and translations:
    // whatever the writer picks must give back the same matrix.
    uint64_t state = 12345;
    auto uniform = [&](double lo, double hi) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return lo + (hi - lo) * double(state >> 11) / double(1ull << 53);
    };
    for (int trial = 0; trial < 200; ++trial) {
        Transform t;
        const int steps = 1 + trial % 4;
        for (int k = 0; k < steps; ++k) {
            const int kind = int(uniform(0, 3));
            const Vec3 v(uniform(-90, 90), uniform(-90, 90), uniform(-90, 90));
            if (kind == 0)
                t = t.then(Transform::translate(v));
            else if (kind == 1)
                t = t.then(Transform::rotate(v));
            else
                t = t.then(Transform::scale(Vec3(uniform(0.2, 3), uniform(-3, -0.2), uniform(0.2, 3))));
        }
        const std::vector<writer::Step> written = writer::decompose(t);
        EXPECT_EQ(writer::compose(written).matrix(), t.matrix()) << "trial " << trial;
    }
}

TEST(Writer, NumbersReadBackExactly) {
    for (double v : {0.1, 1.0 / 3.0, -2.5e-300, 1e300, 123456789.123, -0.0, 5e-324}) {
        const std::string text = writer::number(v);
        EXPECT_EQ(std::strtod(text.c_str(), nullptr), v) << text;
    }
    EXPECT_EQ(writer::number(30), "30");
    EXPECT_EQ(writer::number(0.25), "0.25");
}

// ------------------------------------------------------------ limits of .drt

TEST(Writer, SolidCsgRoundTripsThroughDrt) {
    // merge, difference and intersection are .drt keywords: a difference is
    // written as one and reads back with the same members, in world space.
    Scene scene;
    Object difference;
    Csg csg;
    csg.op = Csg::Op::Difference;
    csg.children.resize(2);
    csg.children[1].shape = Sphere{Vec3(0.5, 0, 0), 0.7};
    difference.shape = csg;
    difference.transform = Transform::translate(Vec3(0, 1, 0));
    scene.objects.push_back(difference);
    EXPECT_TRUE(drtInexpressible(scene).empty());
    const std::string text = writeDrtScene(scene);
    EXPECT_NE(text.find("difference {"), std::string::npos) << text;
    const std::optional<Scene> again = loadText(text);
    ASSERT_TRUE(again) << text;
    ASSERT_EQ(again->objects.size(), 1u);
    const Csg* back = std::get_if<Csg>(&again->objects[0].shape);
    ASSERT_NE(back, nullptr);
    EXPECT_EQ(back->op, Csg::Op::Difference);
    ASSERT_EQ(back->children.size(), 2u);
    const Transform sphereToWorld = back->children[1].transform.then(again->objects[0].transform);
    EXPECT_EQ(sphereToWorld.point(Vec3(0, 0, 0)), Vec3(0, 1, 0));
}

TEST(Writer, PrismAndTextRoundTripToTheSameOutlinesAndImage) {
    const char* source = R"(
camera { location <1, 1, -4> look_at <1, 0.3, 0> }
light_source { <-5, 10, -10> color rgb 1 }
text { font "timrom.ttf" string "Wo\"rd" thickness 0.25 offset <0.05, -0.02, 0> pigment { color rgb 1 } }
prism { conic_sweep bezier_spline 0.5, 1, 8, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 1>, <-1, 1>, <-1, 0>, <0, 0>
  open translate <2, -1, 0> }
prism { quadratic_spline -0.5, 0.25, 6, <0, 1>, <1, 0>, <0, -1>, <-1, 0>, <0, 1>, <1, 0> rotate <-90, 0, 0> }
)";
    const std::optional<Scene> scene = loadText(source);
    ASSERT_TRUE(scene);
    std::string text;
    const std::optional<Scene> again = roundTrip(*scene, &text);
    ASSERT_TRUE(again);
    EXPECT_NE(text.find("text { font \"timrom.ttf\" string \"Wo\\\"rd\" thickness 0.25"), std::string::npos) << text;
    EXPECT_NE(text.find("prism { conic_sweep bezier_spline 0.5, 1, 8,"), std::string::npos) << text;
    const Image a = renderSmall(*scene), b = renderSmall(*again);
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    EXPECT_TRUE(a.pixels == b.pixels);
}

TEST(Writer, UnionsAreFlattenedIntoTheirMembers) {
    // A union in the model (as the POV-Ray front end may build it) is written as
    // its members with the union's transform, inversion and flags applied.
    Scene scene;
    Object group;
    Csg csg;
    csg.children.resize(2);
    csg.children[0].shape = Sphere{Vec3(1, 0, 0), 0.5};
    csg.children[1].shape = Box{};
    csg.children[1].inverse = true;
    group.shape = csg;
    group.transform = Transform::translate(Vec3(0, 2, 0));
    group.noShadow = true;
    scene.objects.push_back(group);
    const std::optional<Scene> again = loadText(writeDrtScene(scene));
    ASSERT_TRUE(again);
    ASSERT_EQ(again->objects.size(), 2u);
    for (const Object& o : again->objects) {
        EXPECT_EQ(o.transform, Transform::translate(Vec3(0, 2, 0)));
        EXPECT_TRUE(o.noShadow);
    }
    EXPECT_FALSE(again->objects[0].inverse);
    EXPECT_TRUE(again->objects[1].inverse);
    EXPECT_TRUE(drtInexpressible(scene).empty());
}

TEST(Writer, NamesTheSourceOfEachObject) {
    Diagnostics diags;
    const std::optional<Scene> scene = loadSceneText("\n\nsphere { 0, 1 }\n", "original.drt", diags);
    ASSERT_TRUE(scene);
    WriterOptions options;
    options.sourceName = "original.drt";
    options.sourceFiles = &diags.files();
    const std::string text = writeDrtScene(*scene, options);
    EXPECT_NE(text.find("// Converted from original.drt"), std::string::npos) << text;
    EXPECT_NE(text.find("// original.drt:3\nsphere {"), std::string::npos) << text;
}

} // namespace
} // namespace drt
