// Scene model -> .drt text. Each block is written so that the .drt parser
// (src/lang/parser*.cpp) rebuilds the same model; where the parser derives a
// value (a pigment's pattern -> world map from the transforms around it), the
// writer composes the candidate text the way the parser will and keeps it only
// if the result is identical (writer_detail.h).
#include "lang/writer.h"

#include "lang/keywords.h"
#include "lang/shape_syntax.h"
#include "lang/writer_detail.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

namespace drt {

using writer::decompose;
using writer::formatSteps;
using writer::number;
using writer::Step;
using writer::vector;
using namespace writer; // texture text (writer_texture.cpp)

namespace {

class SceneWriter {
  public:
    explicit SceneWriter(const WriterOptions& options) : options_(options) {}

    std::string write(const Scene& scene);
    std::vector<std::string> problems() const { return {problems_.begin(), problems_.end()}; }

  private:
    void line(int indent, const std::string& text) {
        out_ += std::string(size_t(indent) * 2, ' ') + text + "\n";
    }
    void sourceComment(int indent, const SourceLoc& loc);
    void settings(const Scene& scene);
    void camera(const CameraSpec& c);
    void light(const Light& l);
    void topLevelObject(const Object& o);
    void lightGroup(const Scene& scene, int group); // its lights, objects and inner groups
    void flattenUnion(const Object& o, const Transform& parentBefore, const MotionChain& parentChain, bool inverse,
                      bool noShadow, bool hollow, const std::vector<Object>& clips);
    void clips(const std::vector<Object>& clippedBy, int indent);
    void writeClips(const Object& o, const Transform& toWritten, int indent);
    void object(const Object& o, int indent);
    std::string shapeHead(const Object& o, int indent);
    void texture(const Texture& t, const std::string& pigment, const std::string& normal, int indent);
    static std::string motionText(const Motion& m);
    // A camera's or light's motions, each with the transforms after it.
    void motionLines(const MotionChain& chain, int indent);
    std::string placementText(const Object& o);

    WriterOptions options_;
    std::string out_;
    std::set<std::string> problems_;
};

std::string SceneWriter::write(const Scene& scene) {
    if (options_.sourceName.empty())
        line(0, "// Written by drt's .drt writer (src/lang/writer.cpp).");
    else
        line(0, "// Converted from " + options_.sourceName + " by drt convert.");
    line(0, "// The .drt language: docs/language.md.");
    out_ += "\n";
    settings(scene);
    camera(scene.camera);
    for (const Light& l : scene.lights)
        if (l.group == 0)
            light(l);
    for (const Object& o : scene.objects)
        if (o.lightGroup == 0)
            topLevelObject(o);
    for (size_t g = 1; g < scene.lightGroupParents.size(); ++g)
        if (scene.lightGroupParents[g] == 0)
            lightGroup(scene, int(g));
    return out_;
}

// The lights and objects of a light_group, written as one (lights and objects
// inside it keep the places they were given: world space).
void SceneWriter::lightGroup(const Scene& scene, int group) {
    const bool used = std::any_of(scene.objects.begin(), scene.objects.end(),
                                  [&](const Object& o) { return o.lightGroup == group; }) ||
                      std::any_of(scene.lights.begin(), scene.lights.end(),
                                  [&](const Light& l) { return l.group == group; });
    if (!used)
        return;
    out_ += "\n";
    line(0, "light_group {");
    bool globalLights = false;
    for (const Light& l : scene.lights)
        if (l.group == group)
            light(l);
    for (const Object& o : scene.objects)
        if (o.lightGroup == group) {
            globalLights = globalLights || o.globalLights;
            topLevelObject(o);
        }
    for (size_t g = 1; g < scene.lightGroupParents.size(); ++g)
        if (scene.lightGroupParents[g] == group)
            lightGroup(scene, int(g));
    if (globalLights)
        line(1, "global_lights on");
    line(0, "}");
}

void SceneWriter::sourceComment(int indent, const SourceLoc& loc) {
    if (!options_.sourceFiles || !loc.valid() || loc.file >= options_.sourceFiles->count())
        return;
    const std::string name = std::filesystem::path(options_.sourceFiles->path(loc.file)).filename().string();
    line(indent, "// " + name + ":" + std::to_string(loc.line));
}

void SceneWriter::settings(const Scene& scene) {
    const RenderSettings& r = scene.render;
    std::string items;
    if (r.width)
        items += " width " + std::to_string(*r.width);
    if (r.height)
        items += " height " + std::to_string(*r.height);
    if (r.samplesPerPixel)
        items += " samples " + std::to_string(*r.samplesPerPixel);
    if (r.lightSamples)
        items += " light_samples " + std::to_string(*r.lightSamples);
    if (r.seed) {
        items += " seed " + std::to_string(*r.seed);
        if (*r.seed > (uint64_t(1) << 53))
            problems_.insert("a seed above 2^53 (the .drt parser reads it as a double)");
    }
    if (r.sampler)
        items += " sampler \"" + *r.sampler + "\"";
    if (r.filter)
        items += " filter \"" + *r.filter + "\"";
    if (r.adaptive.value_or(false)) {
        std::string adaptive;
        if (r.adaptiveError)
            adaptive += " error " + number(*r.adaptiveError);
        if (r.minSamplesPerPixel)
            adaptive += " min_samples " + std::to_string(*r.minSamplesPerPixel);
        if (r.maxSamplesPerPixel)
            adaptive += " max_samples " + std::to_string(*r.maxSamplesPerPixel);
        items += adaptive.empty() ? " adaptive" : " adaptive {" + adaptive + " }";
    } else if (r.adaptiveError || r.minSamplesPerPixel || r.maxSamplesPerPixel) {
        problems_.insert("adaptive sampling limits without adaptive sampling");
    }
    if (!items.empty())
        line(0, "render {" + items + " }");

    const GlobalSettings& g = scene.global;
    const GlobalSettings d;
    items.clear();
    if (g.maxTraceLevel != d.maxTraceLevel)
        items += " max_trace_level " + std::to_string(g.maxTraceLevel);
    if (!(g.ambientLight == d.ambientLight))
        items += " ambient_light " + colorText(g.ambientLight);
    if (g.assumedGamma != d.assumedGamma)
        items += " assumed_gamma " + number(g.assumedGamma);
    if (g.adcBailout != d.adcBailout)
        items += " adc_bailout " + number(g.adcBailout);
    if (g.radiosity)
        items += " radiosity { recursion_limit " + std::to_string(g.radiosity->recursionLimit) + " brightness " +
                 number(g.radiosity->brightness) + " }";
    if (!items.empty())
        line(0, "global_settings {" + items + " }");
    if (!isBlack(scene.background))
        line(0, "background { color " + colorText(scene.background) + " }");
    if (!scene.sky.empty()) {
        line(0, "sky_sphere {");
        for (const Pigment& p : scene.sky) {
            bool exact = true;
            line(1, "pigment {" + pigmentBody(p, {}, exact, problems_) + " }");
        }
        line(0, "}");
    }
    for (const Fog& f : scene.fogs) {
        std::string items = " distance " + number(f.distance) + " color " + colorText(f.color);
        if (f.type == Fog::Type::Ground)
            items += " fog_type 2 fog_offset " + number(f.offset) + " fog_alt " + number(f.altitude) + " up " +
                     vector(f.up);
        if (f.turbulence)
            items += " turbulence " + vector(f.turbulence->amount) + " octaves " +
                     std::to_string(f.turbulence->octaves) + " omega " + number(f.turbulence->omega) + " lambda " +
                     number(f.turbulence->lambda) + " turb_depth " + number(f.turbDepth);
        line(0, "fog {" + items + " }");
    }
    for (const Media& m : scene.media)
        line(0, "media {" + mediaBody(m, problems_) + " }");
    out_ += "\n";
}

void SceneWriter::camera(const CameraSpec& c) {
    const CameraSpec d;
    line(0, "camera {");
    if (c.orthographic || c.mapping != CameraMapping::Planar)
        line(1, lang::cameraKeyword(c));
    line(1, "location " + vector(c.location));
    if (!(c.direction == d.direction))
        line(1, "direction " + vector(c.direction));
    if (!(c.up == d.up))
        line(1, "up " + vector(c.up));
    if (c.right)
        line(1, "right " + vector(*c.right));
    if (!(c.sky == d.sky))
        line(1, "sky " + vector(c.sky));
    if (c.lookAt)
        line(1, "look_at " + vector(*c.lookAt));
    if (c.angle)
        line(1, "angle " + number(*c.angle) + (c.verticalAngle ? ", " + number(*c.verticalAngle) : ""));
    if (c.aperture != d.aperture)
        line(1, "aperture " + number(c.aperture));
    if (c.focalPoint)
        line(1, "focal_point " + vector(*c.focalPoint));
    if (c.focalDistance)
        line(1, "focal_distance " + number(*c.focalDistance));
    if (c.shutterOpen != d.shutterOpen)
        line(1, "shutter_open " + number(c.shutterOpen));
    if (c.shutterClose != d.shutterClose)
        line(1, "shutter_close " + number(c.shutterClose));
    motionLines(c.motion, 1);
    line(0, "}");
    out_ += "\n";
}

void SceneWriter::light(const Light& l) {
    const Light d;
    sourceComment(0, l.loc);
    line(0, "light_source {");
    line(1, vector(l.position) + ", color " + colorText(l.color));
    if (l.spotlight)
        line(1, "spotlight");
    if (l.parallel)
        line(1, "parallel");
    if (!(l.pointAt == d.pointAt))
        line(1, "point_at " + vector(l.pointAt));
    std::string items;
    // The cone angles act through their cosines, so a negative angle (which a
    // POV-Ray scene may give and the .drt dialect refuses) is its magnitude.
    if (l.radius != d.radius)
        items += " radius " + number(std::fabs(l.radius));
    if (l.falloff != d.falloff)
        items += " falloff " + number(std::fabs(l.falloff));
    // The others have no such equivalent: written as given, they make a .drt
    // file that reads with an error, so the conversion says so.
    const auto nonNegative = [&](double v, const char* word) {
        if (v < 0)
            problems_.insert("a light's negative '" + std::string(word) + "' (the .drt dialect refuses it)");
        return " " + std::string(word) + " " + number(v);
    };
    if (l.tightness != d.tightness)
        items += nonNegative(l.tightness, "tightness");
    if (l.fadeDistance != d.fadeDistance)
        items += nonNegative(l.fadeDistance, "fade_distance");
    if (l.fadePower != d.fadePower)
        items += nonNegative(l.fadePower, "fade_power");
    if (!items.empty())
        line(1, items.substr(1));
    if (l.shadowless)
        line(1, "shadowless");
    if (!l.mediaInteraction)
        line(1, "media_interaction off");
    if (!l.mediaAttenuation)
        line(1, "media_attenuation off");
    if (l.area) {
        const AreaLight& a = *l.area;
        std::string area = "area_light " + vector(a.axis1) + ", " + vector(a.axis2) + ", " +
                           std::to_string(a.size1) + ", " + std::to_string(a.size2);
        if (a.jitter)
            area += " jitter";
        if (a.adaptive >= 0)
            area += " adaptive " + std::to_string(a.adaptive);
        if (a.circular)
            area += " circular";
        if (a.orient)
            area += " orient";
        line(1, area);
    }
    // The .drt defaults differ from the model's (POV-Ray's): area_illumination
    // on and stratified sampling; say so whenever the model differs.
    if (l.area && !l.areaIllumination)
        line(1, "area_illumination off"); // a no-op without an area
    if (l.area && l.area->sampling != AreaSampling::Stratified)
        line(1, std::string("area_sampling ") + lang::areaSamplingWord(l.area->sampling));
    if (l.inverseSquare)
        line(1, "inverse_square");
    if (l.projectedThrough) { // its objects are in world space, as the light is written
        line(1, "projected_through {");
        if (l.projectedThrough->objects.size() == 1) {
            object(l.projectedThrough->objects.front(), 2);
        } else {
            line(2, "union {");
            for (const Object& o : l.projectedThrough->objects)
                object(o, 3);
            line(2, "}");
        }
        line(1, "}");
    }
    if (l.motion)
        motionLines(l.motion->chain, 1);
    line(0, "}");
}

void SceneWriter::motionLines(const MotionChain& chain, int indent) {
    for (const MotionStage& stage : chain) {
        line(indent, motionText(stage.motion));
        if (const std::vector<Step> after = decompose(stage.after); !after.empty())
            line(indent, formatSteps(after).substr(1));
    }
}

void SceneWriter::topLevelObject(const Object& o) {
    if (const Csg* csg = std::get_if<Csg>(&o.shape); csg && csg->op == Csg::Op::Union) {
        flattenUnion(o, Transform{}, MotionChain{}, false, false, false, {});
        return;
    }
    out_ += "\n";
    object(o, 0);
}

// The .drt parser stores a union as its members, each with the union's
// transforms and motions after its own; the renderer treats both forms alike.
void SceneWriter::flattenUnion(const Object& o, const Transform& parentBefore, const MotionChain& parentChain,
                               bool inverse, bool noShadow, bool hollow, const std::vector<Object>& parentClips) {
    Object leaf = o;
    appendPlacement(leaf.transform, leaf.motion, parentBefore, parentChain);
    // Clips live in the object's parent space: take them to the rest pose's world.
    const Transform clipToRest = restPlacement(Transform{}, o.motion).then(restPlacement(parentBefore, parentChain));
    leaf.clippedBy = parentClips;
    for (const Object& clip : o.clippedBy) {
        leaf.clippedBy.push_back(clip);
        leaf.clippedBy.back().transform = clip.transform.then(clipToRest);
    }
    leaf.inverse = o.inverse != inverse;
    leaf.noShadow = o.noShadow || noShadow;
    leaf.hollow = o.hollow || hollow;
    if (const Csg* csg = std::get_if<Csg>(&o.shape); csg && csg->op == Csg::Op::Union) {
        for (const Object& child : csg->children)
            flattenUnion(child, leaf.transform, leaf.motion, leaf.inverse, leaf.noShadow, leaf.hollow,
                         leaf.clippedBy);
        return;
    }
    out_ += "\n";
    object(leaf, 0);
}

// Writes one object. Non-union CSG is written with its transforms baked into
// its members (the pigments are already in world space).
void SceneWriter::object(const Object& o, int indent) {
    if (indent == 0)
        sourceComment(indent, o.loc);
    const std::string head = shapeHead(o, indent);
    if (head.empty())
        return;
    line(indent, head);
    // A moving object's textures and clips are in its rest pose: the
    // transforms written after its motions take them there again.
    const Transform afterMotions = restPlacement(Transform{}, o.motion);
    const Transform undoAfterMotions = afterMotions.inverted();
    if (const Csg* csg = std::get_if<Csg>(&o.shape)) {
        for (const Object& child : csg->children) {
            Object baked = child;
            baked.transform = child.transform.then(o.transform);
            for (Object& clip : baked.clippedBy) clip.transform = clip.transform.then(o.transform);
            if (!o.motion.empty()) {
                transformObjectTextures(baked, undoAfterMotions);
                transformInteriorSpaces(baked.interior, undoAfterMotions);
            }
            object(baked, indent + 1);
        }
        writeClips(o, undoAfterMotions, indent + 1);
        if (o.inverse)
            line(indent + 1, "inverse");
        if (o.noShadow)
            line(indent + 1, "no_shadow");
        if (o.hollow)
            line(indent + 1, "hollow");
        motionLines(o.motion, indent + 1);
        line(indent, "}");
        return;
    }
    // Texture placement is decided on the rest pose; the placement itself is
    // written as the transforms, motions and transforms after them.
    const std::vector<Step> steps = decompose(restPlacement(o.transform, o.motion));
    const std::string placement = placementText(o);
    // A texture moves with the transforms written after it. Before the
    // transforms, a pattern placed with the object needs no transform of its
    // own; after them, it needs its whole pattern -> world map. Take the form
    // that rebuilds the model exactly, the one without `matrix` if both do.
    const Texture& t = o.texture;
    if (!t.plain()) { // layers or a pattern: the same choice, over all blocks
        bool exactBefore = true, exactAfter = true;
        const std::vector<std::string> before = textureBlocks(t, steps, exactBefore, problems_);
        const std::vector<std::string> after = steps.empty() ? before : textureBlocks(t, {}, exactAfter, problems_);
        const bool readableBefore = std::none_of(before.begin(), before.end(), [](const std::string& b) {
            return b.find(" matrix") != std::string::npos;
        });
        const bool textureBefore = steps.empty() || (exactBefore && (readableBefore || !exactAfter)) ||
                                   (!exactBefore && !exactAfter);
        if (textureBefore)
            for (const std::string& block : before)
                line(indent + 1, block);
        if (!placement.empty())
            line(indent + 1, placement);
        if (!textureBefore)
            for (const std::string& block : after)
                line(indent + 1, block);
    } else {
        const bool untextured = isDefaultPigment(t.pigment) && isDefaultFinish(t.finish) && !t.normal &&
                                writer::sameTransform(t.pigment.toWorld, writer::compose(steps));
        bool exactBefore = true, exactAfter = true;
        const std::string before = untextured ? "" : pigmentBody(t.pigment, steps, exactBefore, problems_);
        const std::string after =
            untextured || steps.empty() ? before : pigmentBody(t.pigment, {}, exactAfter, problems_);
        const std::string normalBefore = t.normal ? normalBody(*t.normal, steps, exactBefore) : "";
        const std::string normalAfter = t.normal ? normalBody(*t.normal, {}, exactAfter) : "";
        const bool readableBefore =
            before.find(" matrix") == std::string::npos && normalBefore.find(" matrix") == std::string::npos;
        const bool textureBefore = untextured || steps.empty() ||
                                   (exactBefore && (readableBefore || !exactAfter)) ||
                                   (!exactBefore && !exactAfter);
        if (textureBefore && !untextured)
            texture(t, before, normalBefore, indent + 1);
        if (!placement.empty())
            line(indent + 1, placement);
        if (!textureBefore)
            texture(t, after, normalAfter, indent + 1);
    }
    if (!isDefaultInterior(o.interior))
        line(indent + 1, "interior {" + interiorBody(o.interior, problems_) + " }");
    std::string flags;
    if (o.noShadow)
        flags += " no_shadow";
    if (o.hollow)
        flags += " hollow";
    if (o.inverse)
        flags += " inverse";
    if (!flags.empty())
        line(indent + 1, flags.substr(1));
    if (o.motion.empty())
        clips(o.clippedBy, indent + 1);
    line(indent, "}");
}

// The object's transforms, motions and the transforms after them. A moving
// object's clips are written before its first motion (clipped_by may not
// follow one), in the space there.
std::string SceneWriter::placementText(const Object& o) {
    std::string text = formatSteps(decompose(o.transform));
    if (o.motion.empty())
        return text.empty() ? text : text.substr(1);
    if (!o.clippedBy.empty()) {
        const std::string saved = out_;
        out_.clear();
        writeClips(o, restPlacement(Transform{}, o.motion).inverted(), 0);
        std::string block = out_;
        out_ = saved;
        while (!block.empty() && block.back() == '\n')
            block.pop_back();
        for (char& c : block)
            if (c == '\n')
                c = ' ';
        text += " " + block;
    }
    for (const MotionStage& stage : o.motion)
        text += " " + motionText(stage.motion) + formatSteps(decompose(stage.after));
    return text.substr(1);
}

// Clips stored in the rest pose's world, written where `toWritten` maps them.
void SceneWriter::writeClips(const Object& o, const Transform& toWritten, int indent) {
    if (o.motion.empty()) {
        clips(o.clippedBy, indent);
        return;
    }
    std::vector<Object> moved = o.clippedBy;
    for (Object& clip : moved) clip.transform = clip.transform.then(toWritten);
    clips(moved, indent);
}

// After the object's transforms, so that none of them moves the clips again.
void SceneWriter::clips(const std::vector<Object>& clippedBy, int indent) {
    if (clippedBy.empty())
        return;
    line(indent, "clipped_by {");
    for (const Object& clip : clippedBy) {
        // A clip's texture is never seen: write none.
        Object shape = clip;
        shape.texture = Texture{};
        transformTextureSpaces(shape.texture.edit(), clip.transform);
        object(shape, indent + 1);
    }
    line(indent, "}");
}

// One key at time 1 from the identity at 0 is written without `at`.
std::string SceneWriter::motionText(const Motion& m) {
    const auto items = [](const MotionKey& k) {
        std::string text;
        if (!(k.translate == Vec3(0)))
            text += " translate " + vector(k.translate);
        if (!(k.rotate == Vec3(0)))
            text += " rotate " + vector(k.rotate);
        if (!(k.scale == Vec3(1)))
            text += " scale " + vector(k.scale);
        return text;
    };
    std::string text = m.spline ? "motion { spline" : "motion {";
    const bool oneStep = m.keys.size() == 2 && m.keys[0] == MotionKey{0} && m.keys[1].time == 1;
    if (oneStep)
        return text + items(m.keys[1]) + " }";
    for (size_t i = 0; i < m.keys.size(); ++i) {
        if (i == 0 && m.keys[0] == MotionKey{0})
            continue; // the parser adds it again
        text += " at " + number(m.keys[i].time) + items(m.keys[i]);
    }
    return text + " }";
}

// The opening of an object's block, through its fixed arguments (each
// shape's entry in shapes_*.cpp).
std::string SceneWriter::shapeHead(const Object& o, int indent) {
    lang::ShapeText text{indent, problems_, &o};
    return lang::shapeHead(o.shape, text);
}

void SceneWriter::texture(const Texture& t, const std::string& pigmentText, const std::string& normalText,
                          int indent) {
    const std::string pigment = "pigment {" + pigmentText + " }";
    if (isDefaultFinish(t.finish) && !t.normal) {
        line(indent, "texture { " + pigment + " }");
        return;
    }
    line(indent, "texture {");
    line(indent + 1, pigment);
    if (t.normal)
        line(indent + 1, "normal {" + normalText + " }");
    if (!isDefaultFinish(t.finish))
        line(indent + 1, "finish {" + finishBody(t.finish) + " }");
    line(indent, "}");
}

} // namespace

namespace writer {

// The parser normalises plane, disc and smooth-triangle normals. A unit
// vector rarely normalises to itself to the last bit, so look for the short
// direction the author most likely wrote (<0, 1, 1> for a 45-degree disc).
Vec3 unnormalised(const Vec3& n) {
    const double largest = maxComponent(abs(n));
    if (!(largest > 0))
        return n;
    const Vec3 scaled = n / largest;
    auto rounded = [&](double perUnit) {
        auto r = [&](double v) { return std::round(v * perUnit) / perUnit; };
        return Vec3(r(scaled.x), r(scaled.y), r(scaled.z));
    };
    for (const Vec3& c : {n, rounded(1e10), rounded(1e6), scaled})
        if (length(c) > 0 && c / length(c) == n)
            return c;
    return n;
}

} // namespace writer

std::string writeDrtScene(const Scene& scene, const WriterOptions& options) {
    SceneWriter writer(options);
    return writer.write(scene);
}

std::vector<std::string> drtInexpressible(const Scene& scene) {
    SceneWriter writer(WriterOptions{});
    writer.write(scene);
    return writer.problems();
}

} // namespace drt
