#include "lang/keywords.h"

#include "scene/pattern_wave.h"

#include <algorithm>
#include <map>
#include <set>

namespace drt::lang {

namespace {

using Words = std::vector<std::string>;

const Words kTransforms{"translate", "rotate", "scale", "matrix", "transform"};

// frequency, phase and the wave types (scene/pattern_wave.h).
Words waveWords() {
    Words w{"frequency", "phase"};
    for (const auto& [keyword, kind] : kWaveKeywords) w.emplace_back(keyword);
    return w;
}

Words with(Words words, const Words& more) {
    words.insert(words.end(), more.begin(), more.end());
    return words;
}

const std::map<Block, Words>& table() {
    static const std::map<Block, Words> t = [] {
        std::map<Block, Words> m;
        m[Block::Statement] = {"camera", "light_source", "background", "sky_sphere", "fog", "media",
                               "global_settings", "render", "default"};
        m[Block::Object] = with({"texture", "pigment", "finish", "normal", "interior", "material", "no_shadow",
                                 "hollow", "inverse", "motion", "open", "clipped_by", "bounded_by", "sturm",
                                 "hierarchy", "double_illuminate", "no_image", "no_reflection", "no_radiosity",
                                 "photons", "radiosity", "interior_texture", "uv_mapping", "cutaway_textures",
                                 "split_union", "inside_vector"},
                                kTransforms);
        m[Block::Camera] = with({"perspective", "orthographic", "fisheye", "ultra_wide_angle", "panoramic",
                                 "cylinder", "spherical", "omnimax", "mesh_camera", "location", "look_at", "up",
                                 "sky", "right", "direction", "angle", "aperture", "focal_point", "focal_distance",
                                 "blur_samples", "confidence", "variance", "bokeh", "shutter_open",
                                 "shutter_close", "motion"},
                                kTransforms);
        m[Block::LightSource] = with({"color", "colour", "rgb", "spotlight", "point_at", "radius", "falloff",
                                      "tightness", "fade_distance", "fade_power", "shadowless", "area_light",
                                      "jitter", "adaptive", "circular", "orient", "area_illumination",
                                      "area_sampling", "inverse_square", "media_interaction", "media_attenuation",
                                      "looks_like", "parallel", "projected_through", "photons", "motion"},
                                     kTransforms);
        Words texture{"pigment", "finish", "normal", "texture_map", "tiles", "checker", "hexagon",
                      "brick",   "gradient", "average", "function", "uv_mapping"};
        for (const PlacePatternWord& w : placePatternWords()) texture.push_back(w.word);
        m[Block::Texture] = with(texture, kTransforms);
        Words pigment{"color", "colour", "rgb", "rgbf", "rgbt", "rgbft", "srgb", "checker", "hexagon", "brick",
                      "brick_size", "mortar", "gradient", "color_map", "colour_map",
                      "pigment_map", "average", "image_map", "turbulence", "octaves", "omega", "lambda", "warp",
                      "quick_color", "uv_mapping", "function", "mandel", "julia", "magnet",
                      "image_pattern"};
        for (const std::string& w : noisePatternNames()) pigment.push_back(w);
        for (const PlacePatternWord& w : placePatternWords()) pigment.push_back(w.word);
        pigment = with(pigment, waveWords());
        m[Block::Pigment] = with(pigment, kTransforms);
        Words normal{"turbulence", "octaves", "omega", "lambda", "accuracy", "bump_size", "function",
                     "mandel", "julia", "magnet"};
        for (const std::string& w : noisePatternNames()) normal.push_back(w);
        normal = with(normal, waveWords());
        m[Block::Normal] = with(normal, kTransforms);
        m[Block::TexturePattern] = with({"texture_map", "brick_size", "mortar", "turbulence", "octaves", "omega",
                                         "lambda"},
                                        kTransforms);
        m[Block::Finish] = {"ambient", "diffuse", "brilliance", "phong", "phong_size", "specular", "roughness",
                            "metallic", "emission", "reflection", "conserve_energy", "reflection_blur",
                            "refraction_blur", "crand", "irid", "subsurface", "reflection_exponent"};
        m[Block::Reflection] = {"fresnel", "falloff", "metallic", "exponent"};
        m[Block::Interior] = {"ior", "fade_distance", "fade_power", "fade_color", "fade_colour", "media",
                              "caustics", "dispersion", "dispersion_samples"};
        m[Block::Media] = with({"absorption", "emission", "scattering", "density", "intervals", "samples",
                                "method", "confidence", "variance", "ratio", "jitter", "aa_threshold", "aa_level"},
                               kTransforms);
        m[Block::Scattering] = {"eccentricity", "extinction"};
        m[Block::GlobalSettings] = {"max_trace_level", "ambient_light", "assumed_gamma", "adc_bailout",
                                    "radiosity", "photons", "subsurface", "charset", "number_of_waves",
                                    "noise_generator", "max_intersections", "hf_gray_16", "mm_per_unit",
                                    "irid_wavelength"};
        m[Block::Render] = {"width", "height", "samples", "light_samples", "seed", "sampler", "filter", "adaptive"};
        m[Block::Adaptive] = {"error", "min_samples", "max_samples"};
        m[Block::Fog] = with({"distance", "color", "colour", "fog_type", "fog_offset", "fog_alt", "up",
                              "turbulence", "turb_depth", "octaves", "omega", "lambda"},
                             kTransforms);
        m[Block::Motion] = {"at", "translate", "rotate", "scale", "spline"};
        m[Block::ImageMap] = {"map_type", "once", "interpolate", "filter", "transmit", "gamma", "premultiplied",
                              "use_color", "use_index", "use_alpha"};
        m[Block::SkySphere] = with({"pigment", "emission"}, kTransforms);
        m[Block::Transform] = with({"inverse"}, kTransforms);
        return m;
    }();
    return t;
}

} // namespace

const char* blockName(Block block) {
    switch (block) {
    case Block::Statement: return "a statement";
    case Block::Object: return "object";
    case Block::Camera: return "camera";
    case Block::LightSource: return "light_source";
    case Block::Texture: return "texture";
    case Block::Pigment: return "pigment";
    case Block::Normal: return "normal";
    case Block::Finish: return "finish";
    case Block::Reflection: return "reflection";
    case Block::Interior: return "interior";
    case Block::Media: return "media";
    case Block::Scattering: return "scattering";
    case Block::GlobalSettings: return "global_settings";
    case Block::Render: return "render";
    case Block::Adaptive: return "adaptive";
    case Block::Fog: return "fog";
    case Block::Motion: return "motion";
    case Block::ImageMap: return "image_map";
    case Block::SkySphere: return "sky_sphere";
    case Block::TexturePattern: return "texture";
    case Block::Transform: return "transform";
    }
    return "block";
}

const std::vector<std::string>& blockKeywords(Block block) { return table().at(block); }

std::vector<Block> homesOf(const std::string& word, Block in) {
    // Words of many blocks say nothing about where they belong.
    static const std::set<std::string> shared = [] {
        std::set<std::string> s(kTransforms.begin(), kTransforms.end());
        for (const char* w : {"color", "colour", "rgb", "turbulence", "octaves", "omega", "lambda", "emission",
                              "metallic", "samples", "adaptive", "jitter", "filter", "media", "photons",
                              "radiosity", "pigment", "normal", "finish", "texture", "inverse", "cylinder",
                              "spherical", "average", "checker", "hexagon", "brick", "gradient", "radial",
                              "onion", "fade_distance", "fade_power", "confidence", "variance", "up"})
            s.insert(w);
        return s;
    }();
    std::vector<Block> homes;
    if (shared.count(word)) return homes;
    for (const auto& [block, words] : table()) {
        if (block == in || block == Block::Statement || block == Block::Transform ||
            block == Block::TexturePattern)
            continue;
        if (std::find(words.begin(), words.end(), word) != words.end()) homes.push_back(block);
    }
    return homes;
}

const std::vector<NoisePatternWord>& noisePatternWords() {
    static const std::vector<NoisePatternWord> words{
        {"bozo", PatternKind::Bozo},         {"granite", PatternKind::Granite},   {"marble", PatternKind::Marble},
        {"wood", PatternKind::Wood},         {"agate", PatternKind::Agate},       {"leopard", PatternKind::Leopard},
        {"crackle", PatternKind::Crackle},   {"wrinkles", PatternKind::Wrinkles}, {"dents", PatternKind::Dents},
        {"bumps", PatternKind::Bumps},       {"ripples", PatternKind::Ripples},   {"waves", PatternKind::Waves},
        {"spotted", PatternKind::Bozo}, // POV-Ray's spotted is bozo without the colour map's default
    };
    return words;
}

namespace {

std::optional<PatternKind> kindNamed(const std::vector<PatternWord>& words, const std::string& word) {
    for (const PatternWord& w : words)
        if (word == w.word) return w.kind;
    return std::nullopt;
}

const char* wordOfKind(const std::vector<PatternWord>& words, PatternKind kind) {
    for (const PatternWord& w : words)
        if (w.kind == kind) return w.word;
    return nullptr;
}

} // namespace

std::optional<PatternKind> noisePatternNamed(const std::string& word) { return kindNamed(noisePatternWords(), word); }

const char* noisePatternWord(PatternKind kind) { return wordOfKind(noisePatternWords(), kind); }

std::vector<std::string> noisePatternNames() {
    std::vector<std::string> names;
    for (const NoisePatternWord& w : noisePatternWords())
        if (noisePatternWord(w.kind) == w.word) names.push_back(w.word);
    return names;
}

const std::vector<PlacePatternWord>& placePatternWords() {
    static const std::vector<PlacePatternWord> words{
        {"radial", PatternKind::Radial}, {"onion", PatternKind::Onion},           {"spherical", PatternKind::Spherical},
        {"planar", PatternKind::Planar}, {"cylindrical", PatternKind::Cylindrical}, {"boxed", PatternKind::Boxed},
    };
    return words;
}

std::optional<PatternKind> placePatternNamed(const std::string& word) { return kindNamed(placePatternWords(), word); }

const char* placePatternWord(PatternKind kind) { return wordOfKind(placePatternWords(), kind); }

bool isApproximatedPattern(const std::string& word) {
    static const std::set<std::string> words = {
        "spiral1", "spiral2", "cells", "cubic",
        "tiling", "pavement", "facets", "object", "aoi", "slope",
        "fractal", "wave", "noise"};
    return words.count(word) > 0;
}

const std::vector<CsgWord>& csgWords() {
    static const std::vector<CsgWord> words{{"union", Csg::Op::Union},
                                            {"merge", Csg::Op::Merge},
                                            {"difference", Csg::Op::Difference},
                                            {"intersection", Csg::Op::Intersection}};
    return words;
}

std::optional<Csg::Op> csgOpNamed(const std::string& word) {
    for (const CsgWord& w : csgWords())
        if (word == w.word) return w.op;
    return std::nullopt;
}

const char* csgWord(Csg::Op op) {
    for (const CsgWord& w : csgWords())
        if (w.op == op) return w.word;
    return "union";
}

const std::vector<CameraWord>& cameraWords() {
    static const std::vector<CameraWord> words{
        {"perspective", CameraMapping::Planar, false},     {"orthographic", CameraMapping::Planar, true},
        {"fisheye", CameraMapping::Fisheye, false},        {"ultra_wide_angle", CameraMapping::UltraWideAngle, false},
        {"panoramic", CameraMapping::Panoramic, false},    {"cylinder", CameraMapping::Cylinder1, false},
        {"spherical", CameraMapping::Spherical, false},    {"omnimax", CameraMapping::Omnimax, false},
    };
    return words;
}

std::optional<CameraWord> cameraWordNamed(const std::string& word) {
    for (const CameraWord& w : cameraWords())
        if (word == w.word) return w;
    return std::nullopt;
}

std::string cameraKeyword(const CameraSpec& camera) {
    switch (camera.mapping) {
    case CameraMapping::Cylinder1: return "cylinder 1";
    case CameraMapping::Cylinder2: return "cylinder 2";
    case CameraMapping::Cylinder3: return "cylinder 3";
    case CameraMapping::Cylinder4: return "cylinder 4";
    case CameraMapping::Planar: return camera.orthographic ? "orthographic" : "perspective";
    default: break;
    }
    for (const CameraWord& w : cameraWords())
        if (w.mapping == camera.mapping) return w.word;
    return "perspective";
}

const std::vector<AreaSamplingWord>& areaSamplingWords() {
    static const std::vector<AreaSamplingWord> words{{"stratified", AreaSampling::Stratified},
                                                     {"solid_angle", AreaSampling::SolidAngle},
                                                     {"grid", AreaSampling::Grid},
                                                     {"pov_grid", AreaSampling::PovGrid}};
    return words;
}

const char* areaSamplingWord(AreaSampling sampling) {
    for (const AreaSamplingWord& w : areaSamplingWords())
        if (w.sampling == sampling) return w.word;
    return "stratified";
}

} // namespace drt::lang
