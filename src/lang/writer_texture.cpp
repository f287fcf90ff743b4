// Texture text for the .drt writer: colours, pigments (with their pattern
// transforms chosen so the parser rebuilds them exactly), finishes, interiors.
#include "lang/keywords.h"
#include "lang/writer_detail.h"
#include "lang/writer_function.h"

#include <algorithm>
#include <limits>

namespace drt::writer {

std::string colorText(const Color& c) {
    if (c.r == c.g && c.g == c.b)
        return "rgb " + number(c.r);
    return "rgb " + vector(Vec3(c.r, c.g, c.b));
}

std::string colorText(const ColorFT& c) {
    const std::string rgb = number(c.rgb.r) + ", " + number(c.rgb.g) + ", " + number(c.rgb.b);
    if (c.filter == 0 && c.transmit == 0)
        return colorText(c.rgb);
    if (c.transmit == 0)
        return "rgbf <" + rgb + ", " + number(c.filter) + ">";
    if (c.filter == 0)
        return "rgbt <" + rgb + ", " + number(c.transmit) + ">";
    return "rgbft <" + rgb + ", " + number(c.filter) + ", " + number(c.transmit) + ">";
}

// A pigment that is POV-Ray's default (solid black), whatever its transform.
bool isDefaultPigment(const Pigment& p) {
    const Pigment d;
    return p.pattern == PatternKind::Solid && p.color == d.color && p.children.empty() &&
           p.colorMap.empty() && p.pigmentMap.empty() && p.gradientAxis == d.gradientAxis && p.brickSize == d.brickSize &&
           p.mortar == d.mortar;
}

// The .drt keyword of a noise pattern, or nullptr for the other kinds.
static const char* noiseKeyword(PatternKind kind) { return lang::noisePatternWord(kind); }

// " turbulence ... octaves ..." for the non-default items.
static std::string turbulenceText(const Turbulence& t) {
    const Turbulence d;
    std::string text;
    if (!(t.amount == d.amount))
        text += " turbulence " +
                (t.amount.x == t.amount.y && t.amount.y == t.amount.z ? number(t.amount.x) : vector(t.amount));
    if (t.octaves != d.octaves)
        text += " octaves " + std::to_string(t.octaves);
    if (t.omega != d.omega)
        text += " omega " + number(t.omega);
    if (t.lambda != d.lambda)
        text += " lambda " + number(t.lambda);
    return text;
}

// " frequency ... phase ... triangle_wave" for the non-default items.
static std::string waveText(const PatternWave& w) {
    const PatternWave d;
    std::string text;
    if (w.frequency != d.frequency) text += " frequency " + number(w.frequency);
    if (w.phase != d.phase) text += " phase " + number(w.phase);
    if (w.kind != WaveKind::PatternDefault) text += " " + std::string(waveKeyword(w.kind));
    if (w.kind == WaveKind::Poly) text += " " + number(w.exponent);
    return text;
}

// A fractal pattern's keyword and arguments ("julia <0.3, 0.4, 0> 30"), and its modifiers apart
// (in a normal the bump amount comes between them).
static std::string fractalHead(const FractalPattern& f) {
    std::string text;
    switch (f.kind) {
    case FractalKind::Mandel: text = "mandel"; break;
    case FractalKind::Julia: text = "julia"; break;
    case FractalKind::Magnet1Mandel: text = "magnet 1 mandel"; break;
    case FractalKind::Magnet1Julia: text = "magnet 1 julia"; break;
    case FractalKind::Magnet2Mandel: text = "magnet 2 mandel"; break;
    case FractalKind::Magnet2Julia: text = "magnet 2 julia"; break;
    }
    if (isJuliaForm(f.kind)) text += " " + vector(Vec3(f.cx, f.cy, 0)) + ",";
    return text + " " + number(double(f.iterations));
}

static std::string fractalModifiers(const FractalPattern& f) {
    const FractalPattern d;
    std::string text;
    if (f.exponent != d.exponent) text += " exponent " + number(f.exponent);
    if (f.exteriorType != d.exteriorType || f.exteriorFactor != d.exteriorFactor)
        text += " exterior " + number(f.exteriorType) + ", " + number(f.exteriorFactor);
    if (f.interiorType != d.interiorType || f.interiorFactor != d.interiorFactor)
        text += " interior " + number(f.interiorType) + ", " + number(f.interiorFactor);
    return text;
}

std::string normalBody(const Normal& n, const std::vector<Step>& suffix, bool& exact) {
    // A uv-mapped normal lives in uv space, which the object's transforms do not move.
    const std::vector<Step> placedBy = n.uvMapping ? std::vector<Step>{} : suffix;
    const Transform after = writer::compose(placedBy);
    std::vector<Step> own;
    if (!writer::sameTransform(n.toWorld, after)) {
        own = decompose(n.toWorld.then(after.inverted()));
        exact = exact && writer::sameTransform(writer::compose(placedBy, writer::compose(own)), n.toWorld);
    }
    const char* keyword = noiseKeyword(n.pattern);
    std::string pattern = keyword ? keyword : "bumps";
    if (n.pattern == PatternKind::Function && n.function) {
        std::set<std::string> problems; // none for a function of x, y, z without patterns
        pattern = functionHead(*n.function) + "{ " + functionText(*n.function, problems) + " }";
    }
    if (n.pattern == PatternKind::DensityFile && n.densityFile) pattern = densityFileText(*n.densityFile).substr(1) + ",";
    std::string modifiers;
    if (n.pattern == PatternKind::Fractal && n.fractal) {
        pattern = fractalHead(*n.fractal) + ",";
        modifiers = fractalModifiers(*n.fractal);
    }
    if (!n.slopeMap.empty()) {
        modifiers += " slope_map {";
        for (const SlopeMapEntry& e : n.slopeMap)
            modifiers += " [" + number(e.value) + " <" + number(e.height) + ", " + number(e.slope) + ">]";
        modifiers += " }";
    }
    return std::string(n.uvMapping ? " uv_mapping " : " ") + pattern + " " + number(n.amount) + modifiers +
           turbulenceText(n.turbulence) + waveText(n.wave) + formatSteps(own);
}

bool isDefaultFinish(const Finish& f) {
    const Finish d;
    return f.ambient == d.ambient && f.emission == d.emission && f.diffuse == d.diffuse &&
           f.brilliance == d.brilliance && f.phong == d.phong && f.phongSize == d.phongSize &&
           f.specular == d.specular && f.roughness == d.roughness && f.metallic == d.metallic &&
           f.reflectionMin == d.reflectionMin && f.reflectionMax == d.reflectionMax &&
           f.reflectionFresnel == d.reflectionFresnel && f.reflectionFalloff == d.reflectionFalloff &&
           f.reflectionMetallic == d.reflectionMetallic && f.conserveEnergy == d.conserveEnergy &&
           f.reflectionBlur == d.reflectionBlur && f.refractionBlur == d.refractionBlur && f.crand == d.crand;
}

bool isDefaultInterior(const Interior& i) {
    const Interior d;
    return i.ior == d.ior && i.fadeDistance == d.fadeDistance && i.fadePower == d.fadePower &&
           i.fadeColor == d.fadeColor && i.media.empty();
}

// The inside of `pigment { ... }` for `p`, given the transform items the
// enclosing text applies after it (`suffix`). Its own items are chosen so
// that own-then-suffix composes to p.toWorld.
std::string pigmentBody(const Pigment& p, const std::vector<Step>& suffix, bool& exact,
                        std::set<std::string>& problems) {
    // A uv-mapped pattern lives in uv space, which the transforms after it
    // (the object's) do not move: it is written with its own transform only.
    const std::vector<Step> placedBy = p.uvMapping ? std::vector<Step>{} : suffix;
    const Transform after = writer::compose(placedBy);
    std::vector<Step> own;
    // A solid colour has no pattern space: its transform is never used, so it
    // is not written.
    if (p.pattern != PatternKind::Solid && !writer::sameTransform(p.toWorld, after)) {
        own = decompose(p.toWorld.then(after.inverted()));
        exact = exact && writer::sameTransform(writer::compose(placedBy, writer::compose(own)), p.toWorld);
    }
    std::vector<Step> childSuffix = own;
    childSuffix.insert(childSuffix.end(), placedBy.begin(), placedBy.end());

    std::string text = p.uvMapping && p.pattern != PatternKind::Solid ? " uv_mapping" : "";
    auto subPigment = [&](const Pigment& child) {
        const std::string body = pigmentBody(child, childSuffix, exact, problems);
        if (child.pattern == PatternKind::Solid && body.find(" matrix") == std::string::npos &&
            body.find(" translate") == std::string::npos && body.find(" rotate") == std::string::npos &&
            body.find(" scale") == std::string::npos)
            return body.substr(1); // just the colour
        return "pigment {" + body + " }";
    };
    auto list = [&](const char* keyword, size_t count) {
        text += std::string(" ") + keyword;
        if (p.children.size() != count)
            problems.insert(std::string(keyword) + " with a sub-pigment count other than " +
                            std::to_string(count));
        for (size_t i = 0; i < p.children.size() && i < count; ++i)
            text += (i ? ", " : " ") + subPigment(p.children[i]);
    };
    auto colorMap = [&] {
        if (!p.pigmentMap.empty()) {
            text += " pigment_map {";
            for (const Pigment::MapEntry& e : p.pigmentMap)
                text += " [" + number(e.value) + pigmentBody(e.pigment, childSuffix, exact, problems) + "]";
            text += " }";
            return;
        }
        if (!p.children.empty())
            problems.insert("a pigment_map (sub-pigments of a colour-map pattern)");
        std::vector<ColorMapEntry> map = p.colorMap;
        if (map.empty())
            map = {{0.0, {Color(0), 0, 0}}, {1.0, {Color(1), 0, 0}}}; // the renderer's empty-map ramp
        // .drt takes values that do not decrease; POV-Ray takes any order: raise them.
        double previous = -std::numeric_limits<double>::infinity();
        for (ColorMapEntry& e : map) {
            const double v = std::max(previous, e.value);
            if (v != e.value)
                problems.insert("decreasing color_map values (raised to the one before)");
            e.value = previous = v;
        }
        text += " color_map {";
        for (const ColorMapEntry& e : map)
            text += " [" + number(e.value) + " " + colorText(e.color) + "]";
        text += " }";
    };
    switch (p.pattern) {
    case PatternKind::Solid:
        text += " color " + colorText(p.color);
        break;
    case PatternKind::Checker:
        list("checker", 2);
        break;
    case PatternKind::Hexagon:
        list("hexagon", 3);
        break;
    case PatternKind::Brick:
        list("brick", 2);
        break;
    case PatternKind::Gradient:
        text += " gradient " + vector(p.gradientAxis);
        colorMap();
        break;
    case PatternKind::Radial:
    case PatternKind::Onion:
    case PatternKind::Spherical:
    case PatternKind::Planar:
    case PatternKind::Cylindrical:
    case PatternKind::Boxed:
        text += std::string(" ") + lang::placePatternWord(p.pattern);
        colorMap();
        break;
    case PatternKind::Average:
        text += " average";
        if (!p.pigmentMap.empty())
            colorMap();
        break;
    case PatternKind::Function:
        text += " " + functionHead(*p.function) + "{ " + functionText(*p.function, problems) + " }";
        colorMap();
        break;
    case PatternKind::Fractal:
        if (p.fractal) text += " " + fractalHead(*p.fractal) + fractalModifiers(*p.fractal);
        colorMap();
        break;
    case PatternKind::DensityFile:
        if (p.densityFile) text += densityFileText(*p.densityFile);
        else problems.insert("a density_file without its file");
        colorMap();
        break;
    case PatternKind::ImageMap:
        if (p.imageMap) text += imageMapText(*p.imageMap);
        else problems.insert("an image_map without its image");
        break;
    case PatternKind::ImagePattern:
        if (p.imageMap) text += imageMapText(*p.imageMap);
        else problems.insert("an image_pattern without its image");
        colorMap();
        break;
    default:
        text += std::string(" ") + noiseKeyword(p.pattern);
        colorMap();
        break;
    }
    if (p.pattern != PatternKind::Solid)
        text += turbulenceText(p.turbulence) + waveText(p.wave);
    const Pigment d;
    if (!(p.brickSize == d.brickSize))
        text += " brick_size " + vector(p.brickSize);
    if (p.mortar != d.mortar)
        text += " mortar " + number(p.mortar);
    return text + formatSteps(own);
}

// The pattern keyword of a patterned texture (its pigment carries the pattern).
static std::string texturePatternWord(const Pigment& p) {
    switch (p.pattern) {
    case PatternKind::Checker: return "checker";
    case PatternKind::Hexagon: return "hexagon";
    case PatternKind::Brick: return "brick";
    case PatternKind::Gradient: return "gradient " + vector(p.gradientAxis);
    case PatternKind::Average: return "average";
    case PatternKind::Fractal: return p.fractal ? fractalHead(*p.fractal) + fractalModifiers(*p.fractal) : "average";
    case PatternKind::DensityFile: return p.densityFile ? densityFileText(*p.densityFile).substr(1) : "average";
    case PatternKind::Function: {
        std::set<std::string> problems; // the pigment's own are reported where it is written
        return functionHead(*p.function) + "{ " + functionText(*p.function, problems) + " }";
    }
    default: {
        if (const char* place = lang::placePatternWord(p.pattern)) return place;
        const char* word = noiseKeyword(p.pattern);
        return word ? word : "average";
    }
    }
}

std::string textureBody(const Texture& t, const std::vector<Step>& suffix, bool& exact,
                        std::set<std::string>& problems) {
    if (t.map.empty()) { // one plain layer
        std::string text = " pigment {" + pigmentBody(t.pigment, suffix, exact, problems) + " }";
        if (t.normal) {
            text += " normal {" + normalBody(*t.normal, suffix, exact) + " }";
            if (!noiseKeyword(t.normal->pattern) && t.normal->pattern != PatternKind::Function &&
                t.normal->pattern != PatternKind::Fractal)
                problems.insert("a normal pattern other than the noise patterns");
            if (t.normal->accuracy != Normal{}.accuracy) problems.insert("a normal's accuracy");
        }
        if (!isDefaultFinish(t.finish))
            text += " finish {" + finishBody(t.finish) + " }";
        return text;
    }
    // A patterned texture: the pattern's own transform comes last and moves the entries too.
    // A uv-mapped pattern lives in uv space: the transforms after it move only its entries.
    const Pigment& p = t.pigment;
    const std::vector<Step> placedBy = p.uvMapping ? std::vector<Step>{} : suffix;
    const Transform after = writer::compose(placedBy);
    std::vector<Step> own;
    if (!writer::sameTransform(p.toWorld, after)) {
        own = decompose(p.toWorld.then(after.inverted()));
        exact = exact && writer::sameTransform(writer::compose(placedBy, writer::compose(own)), p.toWorld);
    }
    std::vector<Step> childSuffix = own;
    childSuffix.insert(childSuffix.end(), suffix.begin(), suffix.end());
    auto blocks = [&](const Texture& entry) {
        std::string text;
        for (const std::string& block : textureBlocks(entry, childSuffix, exact, problems))
            text += " " + block;
        return text;
    };
    std::string text = p.uvMapping ? " uv_mapping" : "";
    const bool block =
        p.pattern == PatternKind::Checker || p.pattern == PatternKind::Hexagon || p.pattern == PatternKind::Brick;
    const bool layeredEntry = std::any_of(t.map.begin(), t.map.end(),
                                          [](const Texture::MapEntry& e) { return !e.texture.layersAbove.empty(); });
    if (p.pattern == PatternKind::ImageMap && p.imageMap && p.imageMap->material) {
        std::string textures;
        if (layeredEntry) problems.insert("layered textures inside a material_map");
        for (const Texture::MapEntry& e : t.map)
            textures += " texture {" + textureBody(e.texture, childSuffix, exact, problems) + " }";
        text += imageMapText(*p.imageMap, textures);
    } else if (block && p.pattern == PatternKind::Checker && t.map.size() == 2 && layeredEntry) {
        text += " tiles {" + blocks(t.map[1].texture) + " tile2" + blocks(t.map[0].texture) + " }"; // see the parser
    } else if (block) {
        const size_t count = p.pattern == PatternKind::Hexagon ? 3 : 2;
        if (t.map.size() != count)
            problems.insert("a block-pattern texture with a texture count other than " + std::to_string(count));
        if (layeredEntry)
            problems.insert("layered textures inside a hexagon or brick texture");
        text += " " + texturePatternWord(p);
        for (size_t i = 0; i < t.map.size() && i < count; ++i)
            text += " texture {" + textureBody(t.map[i].texture, childSuffix, exact, problems) + " }";
    } else {
        text += " " + texturePatternWord(p) + " texture_map {";
        for (const Texture::MapEntry& e : t.map)
            text += " [" + number(e.value) +
                    (e.texture.layersAbove.empty() ? textureBody(e.texture, childSuffix, exact, problems)
                                                   : blocks(e.texture)) +
                    "]";
        text += " }";
        text += waveText(p.wave);
    }
    text += turbulenceText(p.turbulence);
    const Pigment d;
    if (!(p.brickSize == d.brickSize))
        text += " brick_size " + vector(p.brickSize);
    if (p.mortar != d.mortar)
        text += " mortar " + number(p.mortar);
    return text + formatSteps(own);
}

std::vector<std::string> textureBlocks(const Texture& t, const std::vector<Step>& suffix, bool& exact,
                                       std::set<std::string>& problems) {
    std::vector<std::string> out;
    if (!t.layersAbove.empty() && hasPatternedLayer(t))
        problems.insert("a layered texture with a patterned layer (the parser refuses it, as POV-Ray)");
    out.push_back("texture {" + textureBody(t, suffix, exact, problems) + " }");
    for (const Texture& layer : t.layersAbove)
        for (std::string& block : textureBlocks(layer, suffix, exact, problems))
            out.push_back(std::move(block));
    return out;
}

std::string finishBody(const Finish& f) {
    const Finish d;
    std::string text;
    if (!(f.ambient == d.ambient))
        text += " ambient " + colorText(f.ambient);
    if (!(f.emission == d.emission))
        text += " emission " + colorText(f.emission);
    if (f.diffuse != d.diffuse)
        text += " diffuse " + number(f.diffuse);
    if (f.brilliance != d.brilliance)
        text += " brilliance " + number(f.brilliance);
    if (f.phong != d.phong)
        text += " phong " + number(f.phong);
    if (f.phongSize != d.phongSize)
        text += " phong_size " + number(f.phongSize);
    if (f.specular != d.specular)
        text += " specular " + number(f.specular);
    if (f.roughness != d.roughness)
        text += " roughness " + number(f.roughness);
    if (f.metallic != d.metallic)
        text += " metallic " + number(f.metallic);
    const bool plainReflection =
        f.reflectionMin == f.reflectionMax && f.reflectionFresnel == d.reflectionFresnel &&
        f.reflectionFalloff == d.reflectionFalloff && f.reflectionMetallic == d.reflectionMetallic;
    if (plainReflection) {
        if (!isBlack(f.reflectionMax))
            text += " reflection " + colorText(f.reflectionMax);
    } else {
        text += " reflection { " + colorText(f.reflectionMin) + ", " + colorText(f.reflectionMax);
        if (f.reflectionFresnel)
            text += " fresnel on";
        if (f.reflectionFalloff != d.reflectionFalloff)
            text += " falloff " + number(f.reflectionFalloff);
        if (f.reflectionMetallic != d.reflectionMetallic)
            text += " metallic " + number(f.reflectionMetallic);
        text += " }";
    }
    if (f.conserveEnergy)
        text += " conserve_energy";
    if (f.reflectionBlur != d.reflectionBlur)
        text += " reflection_blur " + number(f.reflectionBlur);
    if (f.refractionBlur != d.refractionBlur)
        text += " refraction_blur " + number(f.refractionBlur);
    if (f.crand != d.crand)
        text += " crand " + number(f.crand);
    return text;
}

std::string mediaBody(const Media& m, std::set<std::string>& problems) {
    const Media d;
    std::string text;
    if (!(m.absorption == d.absorption))
        text += " absorption " + colorText(m.absorption);
    if (!(m.emission == d.emission))
        text += " emission " + colorText(m.emission);
    if (m.scatteringType != 0) {
        text += " scattering { " + std::to_string(m.scatteringType) + ", " + colorText(m.scattering);
        if (m.eccentricity != d.eccentricity)
            text += " eccentricity " + number(m.eccentricity);
        if (m.extinction != d.extinction)
            text += " extinction " + number(m.extinction);
        text += " }";
    }
    if (m.intervals != d.intervals)
        text += " intervals " + std::to_string(m.intervals);
    if (m.samples != d.samples)
        text += " samples " + std::to_string(m.samples);
    for (const Pigment& p : m.densities) {
        // Densities are in world space, written after every transform of the
        // object; when no text rebuilds the matrix to the last bit, the nearest
        // one is written, as for textures (SceneWriter::object).
        bool exact = true;
        text += " density {" + pigmentBody(p, {}, exact, problems) + " }";
    }
    return text;
}

std::string interiorBody(const Interior& i, std::set<std::string>& problems) {
    const Interior d;
    std::string text;
    if (i.ior != d.ior)
        text += " ior " + number(i.ior);
    if (i.fadeDistance != d.fadeDistance)
        text += " fade_distance " + number(i.fadeDistance);
    if (i.fadePower != d.fadePower)
        text += " fade_power " + number(i.fadePower);
    if (!(i.fadeColor == d.fadeColor))
        text += " fade_color " + colorText(i.fadeColor);
    for (const Media& m : i.media)
        text += " media {" + mediaBody(m, problems) + " }";
    return text;
}

} // namespace drt::writer
