// Layered textures, patterned textures (texture_map, checker / tiles of
// textures), pigment_map and average: closed-form pixels for POV-Ray 3.7's
// layer model (render/texture_shading.h), the .drt syntax and its writer
// round trip, and the POV front end.
#include "lang/load.h"
#include "lang/writer.h"
#include "pov/load.h"
#include "render/pigment.h"
#include "render/render.h"
#include "render/texture_shading.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace drt {
namespace {

Texture solid(Color rgb, double filter = 0, double transmit = 0) {
    Texture t;
    t.pigment.color = ColorFT{rgb, filter, transmit};
    return t;
}

// Only ambient (1) and emission-free: the pixel is P alpha.
Texture ambientOnly(Color rgb, double filter = 0, double transmit = 0) {
    Texture t = solid(rgb, filter, transmit);
    t.finish.ambient = Color(1);
    t.finish.diffuse = 0;
    return t;
}

Texture layered(Texture bottom, Texture top) {
    addLayerOnTop(bottom, std::move(top));
    return bottom;
}

Object plane(Vec3 normal, double distance, Texture texture) {
    Object o;
    o.shape = Plane{normal, distance};
    o.texture = std::move(texture);
    return o;
}

Light pointLight(Vec3 position, Color color) {
    Light l;
    l.position = position;
    l.color = color;
    return l;
}

// Every ray leaves `location` along `direction`: a 1x1 image samples one known ray.
CameraSpec needleCamera(Vec3 location, Vec3 direction, Vec3 upHint = {0, 0, 1}) {
    CameraSpec c;
    c.location = location;
    c.direction = direction;
    c.up = normalize(upHint) * 1e-9;
    c.right = normalize(cross(upHint, direction)) * 1e-9;
    return c;
}

RenderOptions onePixel() {
    RenderOptions o;
    o.width = 1;
    o.height = 1;
    o.samplesPerPixel = 1;
    o.threads = 1;
    return o;
}

Color pixel(const RenderResult& r) { return {r.color.at(0, 0, 0), r.color.at(0, 0, 1), r.color.at(0, 0, 2)}; }

void expectColorNear(const Color& a, const Color& b, double tolerance = 1e-6) {
    EXPECT_NEAR(a.r, b.r, tolerance);
    EXPECT_NEAR(a.g, b.g, tolerance);
    EXPECT_NEAR(a.b, b.b, tolerance);
}

// A floor y = 0 seen straight down from (x, 1, 0).
Scene floorScene(Texture texture, double x = 0) {
    Scene scene;
    scene.objects.push_back(plane({0, 1, 0}, 0, std::move(texture)));
    scene.camera = needleCamera({x, 1, 0}, {0, -1, 0});
    return scene;
}

// ---------------------------------------------------------------- layers

TEST(LayeredTexture, AmbientOnlyTwoLayers) {
    // Top: P_t (filter 0.3, transmit 0.2), alpha 0.5, over an opaque bottom P_b.
    const Color pt(0.2, 0.4, 0.6), pb(0.8, 0.6, 0.4);
    const Scene scene = floorScene(layered(ambientOnly(pb), ambientOnly(pt, 0.3, 0.2)));
    // P_t alpha + F P_b, F = P_t f + t; the bottom lets nothing through.
    const Color f = pt * 0.3 + Color(0.2);
    expectColorNear(pixel(render(scene, onePixel())), pt * 0.5 + f * pb);
}

TEST(LayeredTexture, OneLightTwoLayers) {
    const Color pt(0.9, 0.5, 0.1), pb(0.3, 0.6, 0.9);
    Texture bottom = solid(pb), top = solid(pt, 0.5, 0.25);
    bottom.finish.ambient = top.finish.ambient = Color(0);
    bottom.finish.diffuse = 0.6;
    top.finish.diffuse = 0.8;
    Scene scene = floorScene(layered(bottom, top));
    scene.lights.push_back(pointLight({3, 4, 0}, Color(1, 0.5, 0.25)));
    // Each layer: diffuse (N.L = 4/5) alpha P I, the bottom's seen through F.
    const Color light(1, 0.5, 0.25);
    const Color f = pt * 0.5 + Color(0.25);
    const Color expected = pt * light * (0.8 * 0.8 * 0.25) + f * pb * light * (0.6 * 0.8);
    expectColorNear(pixel(render(scene, onePixel())), expected);
}

TEST(LayeredTexture, EachLayerReflectsWithItsOwnWeight) {
    // A half-transparent black mirror (0.3) over an opaque black mirror (0.5),
    // under a uniform sky B: 0.3 B + 0.5 B (a lower layer's reflection is not
    // scaled by the filter of the layers above it, as in POV-Ray).
    Texture bottom = ambientOnly(Color(0)), top = ambientOnly(Color(0), 0, 0.5);
    bottom.finish.reflectionMin = bottom.finish.reflectionMax = Color(0.5);
    top.finish.reflectionMin = top.finish.reflectionMax = Color(0.3);
    Scene scene = floorScene(layered(bottom, top));
    scene.background = Color(0.2, 0.4, 0.8);
    const RenderResult r = render(scene, onePixel());
    expectColorNear(pixel(r), scene.background * 0.8);
    EXPECT_EQ(r.stats.secondaryRays, 2u); // two reflected rays, no transmitted one
}

TEST(LayeredTexture, TransmittedRayHasTheProductOfTheFilters) {
    // Two see-through layers over the sky: the transmitted ray carries
    // (P1 f1 + t1)(P2 f2 + t2).
    const Color p1(1, 0.5, 0.25), p2(0.5, 1, 1);
    Scene scene = floorScene(layered(ambientOnly(p1, 0.8, 0), ambientOnly(p2, 0, 0.5)));
    scene.background = Color(1);
    scene.camera = needleCamera({0, 1, 0}, {0, -1, 0});
    const Color local = p2 * 0.5 + (Color(0.5)) * (p1 * 0.2); // P alpha of each, the bottom through F
    const Color through = (p1 * 0.8) * Color(0.5);
    expectColorNear(pixel(render(scene, onePixel())), local + through);
}

TEST(LayeredTexture, ShadowsAreFilteredByEveryLayer) {
    // A white floor lit from straight above through a blocker plane at y = 2
    // with two layers: the light reaching the floor is (P1 f1 + t1)(P2 f2 + t2).
    Texture floorTexture = solid(Color(1));
    floorTexture.finish.ambient = Color(0);
    floorTexture.finish.diffuse = 1;
    Scene scene;
    scene.objects.push_back(plane({0, 1, 0}, 0, floorTexture));
    scene.objects.push_back(
        plane({0, 1, 0}, 2, layered(solid(Color(1, 0.5, 0.25), 0.8, 0), solid(Color(1), 0, 0.5))));
    scene.lights.push_back(pointLight({0, 4, 0}, Color(1)));
    scene.camera = needleCamera({0, 1, 0}, {0, -1, 0});
    expectColorNear(pixel(render(scene, onePixel())), Color(0.8, 0.4, 0.2) * 0.5);
    EXPECT_EQ(textureFilter(scene.objects[1].texture, Vec3(0, 2, 0)), Color(0.8, 0.4, 0.2) * 0.5);
}

TEST(LayeredTexture, AnOpaqueTopLayerHidesTheLayersBelow) {
    const Scene scene = floorScene(layered(ambientOnly(Color(0, 1, 0)), ambientOnly(Color(1, 0, 0))));
    const RenderResult r = render(scene, onePixel());
    EXPECT_EQ(pixel(r), Color(1, 0, 0));
    EXPECT_EQ(r.stats.secondaryRays, 0u);
}

TEST(LayeredTexture, OneLayerIsBitIdenticalToAPlainTexture) {
    // A layer on top that is fully transparent and black changes nothing but
    // passes through the layered code path: the bottom is seen through F = 1.
    Texture plain = solid(Color(0.7, 0.3, 0.2));
    plain.finish.phong = 0.5;
    Scene a = floorScene(plain);
    a.lights.push_back(pointLight({1, 3, -2}, Color(1)));
    Scene b = a;
    b.objects[0].texture = layered(plain, ambientOnly(Color(0), 0, 1));
    EXPECT_EQ(pixel(render(a, onePixel())), pixel(render(b, onePixel())));
}

// ---------------------------------------------------------------- patterned textures

Texture gradientXMap(Texture low, Texture high) {
    Texture t;
    t.pigment.pattern = PatternKind::Gradient;
    t.pigment.gradientAxis = {1, 0, 0};
    t.map.push_back({0.0, std::move(low)});
    t.map.push_back({1.0, std::move(high)});
    return t;
}

// TextureLayers lists layersTopFirst's layers in a reused per-thread buffer;
// lists alive at once (a patterned layer's layered entries, listed while the
// layers above it are being shaded) must not disturb each other.
TEST(LayeredTexture, LayerListsAliveAtOnceKeepTheirOwnLayers) {
    Texture a = solid(Color(1, 0, 0));
    a.layersAbove = {solid(Color(0, 1, 0), 0.5), solid(Color(0, 0, 1), 0, 0.5)};
    Texture b = solid(Color(0.5, 0.5, 0.5));
    b.layersAbove = {solid(Color(0.1, 0.2, 0.3), 0.2), solid(Color(0.3, 0.2, 0.1), 0.3), solid(Color(1), 0.4)};
    const auto expected = [](const Texture& t) {
        std::vector<const Texture*> layers;
        layersTopFirst(t, layers);
        return layers;
    };
    const auto listed = [](const TextureLayers& l) { return std::vector<const Texture*>(l.begin(), l.end()); };
    for (int round = 0; round < 3; ++round) { // the buffers are reused from round to round
        const TextureLayers outer(a);
        ASSERT_EQ(listed(outer), expected(a));
        {
            const TextureLayers inner(b);
            const TextureLayers innermost(round == 1 ? a : b);
            EXPECT_EQ(listed(inner), expected(b));
            EXPECT_EQ(listed(innermost), expected(round == 1 ? a : b));
            EXPECT_EQ(listed(outer), expected(a));
        }
        const TextureLayers again(b);
        EXPECT_EQ(listed(again), expected(b));
        EXPECT_EQ(listed(outer), expected(a));
        EXPECT_EQ(outer.size(), 3u);
    }
}

TEST(PatternedTexture, TextureMapBlendsTwoFullyShadedTextures) {
    // gradient x at x = 0.25: 0.75 of a red ambient texture, 0.25 of a black
    // mirror (reflection 0.5) of the sky: 0.75 red + 0.25 * 0.5 sky.
    Texture mirror = ambientOnly(Color(0));
    mirror.finish.reflectionMin = mirror.finish.reflectionMax = Color(0.5);
    Scene scene = floorScene(gradientXMap(ambientOnly(Color(1, 0, 0)), mirror), 0.25);
    scene.background = Color(0.4, 0.8, 0.2);
    expectColorNear(pixel(render(scene, onePixel())), Color(0.75, 0, 0) + scene.background * (0.25 * 0.5));
}

TEST(PatternedTexture, ShadowsThroughATextureMapBlendTheFilters) {
    const Texture t = gradientXMap(solid(Color(1), 0, 1), solid(Color(1), 0, 0));
    EXPECT_EQ(textureFilter(t, Vec3(0.25, 0, 0)), Color(0.75));
}

TEST(PatternedTexture, CheckerOfTexturesPicksOneByCell) {
    Texture t;
    t.pigment.pattern = PatternKind::Checker;
    t.map.push_back({0, ambientOnly(Color(1, 0, 0))});
    t.map.push_back({1, ambientOnly(Color(0, 0, 1))});
    EXPECT_EQ(pixel(render(floorScene(t, 0.5), onePixel())), Color(1, 0, 0));
    EXPECT_EQ(pixel(render(floorScene(t, 1.5), onePixel())), Color(0, 0, 1));
}

TEST(PatternedTexture, AverageWeighsEveryEntry) {
    Texture t;
    t.pigment.pattern = PatternKind::Average;
    t.map.push_back({1, ambientOnly(Color(1, 0, 0))});
    t.map.push_back({3, ambientOnly(Color(0, 0, 1))});
    expectColorNear(pixel(render(floorScene(t), onePixel())), Color(0.25, 0, 0.75));
}

TEST(PatternedTexture, AMappedLayerIsSeenThroughTheLayersAbove) {
    // A checker texture under a half-transparent white top layer.
    Texture checker;
    checker.pigment.pattern = PatternKind::Checker;
    checker.map.push_back({0, ambientOnly(Color(1, 0, 0))});
    checker.map.push_back({1, ambientOnly(Color(0, 0, 1))});
    const Scene scene = floorScene(layered(checker, ambientOnly(Color(1), 0, 0.5)), 0.5);
    expectColorNear(pixel(render(scene, onePixel())), Color(0.5) + Color(0.5, 0, 0));
}

// ---------------------------------------------------------------- pigment_map and average

TEST(PigmentMap, BlendsTheTwoEntriesAroundTheValue) {
    Pigment p;
    p.pattern = PatternKind::Gradient;
    p.gradientAxis = {1, 0, 0};
    Pigment red, checker;
    red.color = ColorFT{Color(1, 0, 0), 0, 0};
    checker.pattern = PatternKind::Checker;
    checker.children = {Pigment{}, Pigment{}};
    checker.children[0].color = ColorFT{Color(0, 1, 0), 0, 0};
    checker.children[1].color = ColorFT{Color(0, 0, 1), 0, 0};
    p.pigmentMap = {{0.0, red}, {0.5, checker}};
    const ColorFT c = evaluatePigment(p, Vec3(0.25, 0.5, 0.5)); // halfway; checker cell 0 there
    EXPECT_EQ(c.rgb, Color(0.5, 0.5, 0));
    EXPECT_EQ(evaluatePigment(p, Vec3(0.75, 0.5, 0.5)).rgb, Color(0, 1, 0)); // past the last entry
}

TEST(PigmentMap, AverageIsTheWeightedMean) {
    Pigment p;
    p.pattern = PatternKind::Average;
    Pigment a, b;
    a.color = ColorFT{Color(1, 0, 0), 0, 0.5};
    b.color = ColorFT{Color(0, 0, 1), 0, 0};
    p.pigmentMap = {{1, a}, {3, b}};
    const ColorFT c = evaluatePigment(p, Vec3(0.3, 0.2, 0.1));
    EXPECT_EQ(c.rgb, Color(0.25, 0, 0.75));
    EXPECT_EQ(c.transmit, 0.125);
}

// ---------------------------------------------------------------- .drt syntax and the writer

Scene loadDrt(const std::string& text) {
    Diagnostics diags;
    std::optional<Scene> scene = loadSceneText(text, "t.drt", diags);
    EXPECT_TRUE(scene) << diags.formatAll();
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    return scene ? *scene : Scene{};
}

const char* const kCamera =
    "camera { location <0, 2, -4> look_at <0, 0.5, 0> angle 50 }\n"
    "light_source { <-3, 5, -4> color rgb 1 }\nbackground { rgb <0.2, 0.3, 0.5> }\n";

TEST(LayeredTextureSyntax, SecondTextureIsALayerOnTop) {
    const Scene s = loadDrt(std::string(kCamera) +
                            "sphere { 0, 1 texture { pigment { rgb x } } texture { pigment { rgbt <1, 1, 1, 0.5> } }"
                            " scale 2 texture { pigment { rgbf <0, 1, 0, 1> } } }\n"
                            "#declare T = texture { pigment { rgb y } } texture { pigment { rgbt 1 } }\n"
                            "sphere { 0, 1 texture { T } }");
    ASSERT_EQ(s.objects.size(), 2u);
    const Texture& t = s.objects[0].texture;
    EXPECT_EQ(t.pigment.color.rgb, Color(1, 0, 0));
    ASSERT_EQ(t.layersAbove.size(), 2u);
    EXPECT_EQ(t.layersAbove[0].pigment.color.transmit, 0.5);
    EXPECT_EQ(t.layersAbove[1].pigment.color.filter, 1);
    ASSERT_EQ(s.objects[1].texture->layersAbove.size(), 1u);
}

// A layer goes onto the object's own texture in place: the objects that use
// the same declared texture or copy the same declared object keep theirs, and
// the members of a CSG each get the layer.
TEST(LayeredTextureSyntax, ALayerOnASharedTextureLeavesTheOtherHoldersAlone) {
    const Scene s = loadDrt(std::string(kCamera) +
                            "#declare T = texture { pigment { rgb y } }\n"
                            "#declare S = sphere { 0, 1 texture { T } }\n"
                            "sphere { 0, 1 texture { T } texture { pigment { rgbt 1 } } texture { pigment { rgbf 1 } } }\n"
                            "sphere { 0, 1 texture { T } }\n"
                            "object { S }\n"
                            "object { S texture { pigment { rgbt 0.5 } } }\n"
                            "union { sphere { 0, 1 } sphere { x, 1 } texture { T } texture { pigment { rgbt 0.25 } } }\n");
    ASSERT_GE(s.objects.size(), 5u); // the union's members may be placed as objects of their own
    ASSERT_EQ(s.objects[0].texture->layersAbove.size(), 2u);
    EXPECT_EQ(s.objects[0].texture->layersAbove[1].pigment.color.filter, 1);
    EXPECT_EQ(s.objects[1].texture->layersAbove.size(), 0u);
    EXPECT_EQ(s.objects[2].texture->layersAbove.size(), 0u);
    // object { S texture {...} } replaces S's texture, as in POV-Ray; S's other copy keeps its own.
    EXPECT_EQ(s.objects[3].texture->layersAbove.size(), 0u);
    EXPECT_EQ(s.objects[3].texture->pigment.color.transmit, 0.5);
    int members = 0;
    for (size_t i = 4; i < s.objects.size(); ++i) {
        const Csg* csg = std::get_if<Csg>(&s.objects[i].shape);
        for (const Object& member : csg ? csg->children : std::vector<Object>{s.objects[i]}) {
            ++members;
            ASSERT_EQ(member.texture->layersAbove.size(), 1u);
            EXPECT_EQ(member.texture->layersAbove[0].pigment.color.transmit, 0.25);
        }
    }
    EXPECT_EQ(members, 2);
}

TEST(LayeredTextureSyntax, TextureMapTilesAndPigmentMapParse) {
    const Scene s = loadDrt(std::string(kCamera) +
                            "plane { y, 0 texture { gradient x texture_map { [0.25 pigment { rgb 1 }] "
                            "[0.75 pigment { rgb 0 } finish { reflection 0.5 }] } scale 2 } }\n"
                            "sphere { 0, 1 texture { tiles { texture { pigment { rgb x } } texture { pigment { rgbt 1 } }"
                            " tile2 texture { pigment { rgb y } } } } }\n"
                            "sphere { 0, 1 pigment { average pigment_map { [1 rgb x] [3 checker rgb 1, rgb 0] } } }");
    ASSERT_EQ(s.objects.size(), 3u);
    const Texture& map = s.objects[0].texture;
    ASSERT_EQ(map.map.size(), 2u);
    EXPECT_EQ(map.pigment.pattern, PatternKind::Gradient);
    EXPECT_EQ(map.map[1].value, 0.75);
    EXPECT_EQ(map.map[1].texture.finish.reflectionMax, Color(0.5));
    // The pattern and the entries both moved by `scale 2`.
    EXPECT_EQ(map.pigment.toWorld.point(Vec3(1, 0, 0)), Vec3(2, 0, 0));
    EXPECT_EQ(map.map[0].texture.pigment.toWorld.point(Vec3(1, 0, 0)), Vec3(2, 0, 0));
    const Texture& tiles = s.objects[1].texture;
    EXPECT_EQ(tiles.pigment.pattern, PatternKind::Checker);
    ASSERT_EQ(tiles.map.size(), 2u);
    // POV-Ray puts tile2 where checker puts its first texture.
    EXPECT_EQ(tiles.map[1].texture.layersAbove.size(), 1u);
    EXPECT_EQ(tiles.map[0].texture.pigment.color.rgb, Color(0, 1, 0));
    const Pigment& avg = s.objects[2].texture->pigment;
    EXPECT_EQ(avg.pattern, PatternKind::Average);
    ASSERT_EQ(avg.pigmentMap.size(), 2u);
    EXPECT_EQ(avg.pigmentMap[1].pigment.pattern, PatternKind::Checker);
}

// Written back and read again, each scene renders bit-identically.
TEST(LayeredTextureSyntax, WriterRoundTripsEveryConstructBitForBit) {
    const std::vector<std::pair<std::string, std::string>> scenes{
        {"layers", "sphere { 0, 1 texture { pigment { marble color_map { [0 rgb 1] [1 rgb <0.3, 0.3, 0.4>] } "
                   "turbulence 0.5 } } texture { pigment { gradient y color_map { [0 rgbt 1] [0.5 rgbf <1, 0.5, 0, 0.6>]"
                   " [1 rgbt 1] } scale 0.3 } finish { phong 0.8 reflection 0.2 } } rotate <10, 20, 0> translate x }"},
        {"texture_map", "plane { y, 0 texture { gradient x texture_map { [0.2 pigment { rgb <1, 0.2, 0.1> } finish { phong 0.5 }]"
                        " [0.8 pigment { checker rgb 1, rgb 0 scale 0.25 } finish { reflection 0.4 }] } turbulence 0.3 "
                        "rotate y * 30 } }"},
        {"layered_entry", "plane { y, 0 texture { gradient z texture_map { [0.3 pigment { rgb <0.2, 0.3, 0.9> }]"
                          " [0.7 texture { pigment { rgb 1 } } texture { pigment { checker rgbt 1, rgbf <1, 0, 0, 0.5>"
                          " scale 0.3 } finish { phong 0.5 } }] } scale 3 } }"},
                {"checker", "plane { y, 0 texture { checker texture { pigment { rgb 1 } } texture { pigment { rgb <0.1, 0.2, 0.6> } "
                    "finish { reflection 0.3 } } scale 0.7 } }"},
        {"tiles", "box { -1, 1 texture { tiles { texture { pigment { rgb x } } texture { pigment { rgbt <1, 1, 1, 0.6> } }"
                  " tile2 texture { pigment { rgb y } } } scale 0.5 } rotate y * 30 }"},
        {"pigment_map", "sphere { 0, 1 pigment { gradient y pigment_map { [0 rgb x] [0.5 checker rgb 1, rgb 0 scale 0.2]"
                        " [1 bozo color_map { [0 rgb 0] [1 rgb z] } scale 0.3] } scale 2 } translate <0.5, 0.5, 0> }"},
        {"average", "sphere { 0, 1 pigment { average pigment_map { [1 gradient x] [2 gradient y] [1 rgb <1, 0.5, 0>] } } "
                    "texture { average texture_map { [1 pigment { rgb x }] [2 pigment { rgb z } finish { phong 1 }] } } }"},
    };
    for (const auto& [name, body] : scenes) {
        SCOPED_TRACE(name);
        const Scene original = loadDrt(std::string(kCamera) + body);
        EXPECT_TRUE(drtInexpressible(original).empty());
        const std::string written = writeDrtScene(original);
        const Scene reread = loadDrt(written);
        RenderOptions o;
        o.width = 32;
        o.height = 24;
        o.samplesPerPixel = 1;
        o.threads = 1;
        const Image a = render(original, o).color, b = render(reread, o).color;
        EXPECT_EQ(a.pixels, b.pixels) << written;
    }
}

// ---------------------------------------------------------------- POV front end

Scene loadPov(const std::string& text, Diagnostics& diags) {
    std::optional<Scene> scene = loadPovSceneText(text, "s.pov", diags);
    EXPECT_TRUE(scene) << diags.formatAll();
    return scene ? *scene : Scene{};
}

TEST(PovLayeredTexture, LayersMapsTilesAndPigmentMapsLoadWithoutWarnings) {
    Diagnostics diags;
    const Scene s = loadPov(
        "#declare T = texture { pigment { rgb 1 } } texture { pigment { rgbt <1, 0, 0, 0.5> } }\n"
        "sphere { 0, 1 texture { T } }\n"
        "plane { y, 0 texture { gradient x texture_map { [0 T] [1 pigment { rgb y } finish { phong 1 }] } } }\n"
        "box { -1, 1 texture { tiles { texture { pigment { rgb x } } tile2 texture { pigment { rgb z } } } } }\n"
        "sphere { 0, 1 texture { checker texture { pigment { rgb 1 } }, texture { pigment { rgb 0 } } } }\n"
        "sphere { 0, 1 pigment { average pigment_map { [1, gradient x] [1, rgb <1, 0, 0>] } } }\n"
        "sphere { 0, 1 pigment { gradient y pigment_map { [0 rgb x] [1 checker rgb 1, rgb 0] } } }\n",
        diags);
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    ASSERT_EQ(s.objects.size(), 6u);
    EXPECT_EQ(s.objects[0].texture->layersAbove.size(), 1u);
    EXPECT_EQ(s.objects[1].texture->map.size(), 2u);
    EXPECT_EQ(s.objects[1].texture->map[0].texture.layersAbove.size(), 1u);
    EXPECT_EQ(s.objects[2].texture->pigment.pattern, PatternKind::Checker);
    EXPECT_EQ(s.objects[3].texture->map.size(), 2u);
    EXPECT_EQ(s.objects[4].texture->pigment.pigmentMap.size(), 2u);
    EXPECT_EQ(s.objects[5].texture->pigment.pigmentMap[1].pigment.pattern, PatternKind::Checker);
}

TEST(PovLayeredTexture, ObjectPigmentAndFinishChangeTheTopLayer) {
    // Measured with POV-Ray 3.7: red under rgbt <0,0,1,0.5>, then `pigment { rgbt <0,1,0,0.5> }` on the
    // object, ambient 1: the pixel is (0.5, 0.5, 0), green over red.
    Diagnostics diags;
    Scene s = loadPov("#default { finish { ambient 1 diffuse 0 } }\n"
                      "plane { y, 0 texture { pigment { rgb x } } texture { pigment { rgbt <0, 0, 1, 0.5> } }"
                      " pigment { rgbt <0, 1, 0, 0.5> } }",
                      diags);
    ASSERT_EQ(s.objects.size(), 1u);
    s.camera = needleCamera({0, 1, 0}, {0, -1, 0});
    expectColorNear(pixel(render(s, onePixel())), Color(0.5, 0.5, 0));
    const Scene d = loadDrt("plane { y, 0 texture { pigment { rgb x } } texture { pigment { rgbt <0, 0, 1, 0.5> } }"
                            " pigment { rgbt <0, 1, 0, 0.5> } finish { phong 1 } }");
    ASSERT_EQ(d.objects[0].texture->layersAbove.size(), 1u);
    EXPECT_EQ(d.objects[0].texture->layersAbove[0].pigment.color.rgb, Color(0, 1, 0));
    EXPECT_EQ(d.objects[0].texture->layersAbove[0].finish.phong, 1);
    EXPECT_EQ(d.objects[0].texture->pigment.color.rgb, Color(1, 0, 0));
}

TEST(PovLayeredTexture, RadialWithoutAColourMapTakesPovRaysDefaultMap) {
    // As in pigment_map entries like `[0.4 radial frequency 10]` (pigmap.pov): cyan, yellow, magenta, cyan.
    Diagnostics diags;
    const Scene s = loadPov("sphere { 0, 1 pigment { gradient y pigment_map { [0 radial] [1 rgb 1] } } }", diags);
    ASSERT_EQ(s.objects.size(), 1u);
    const std::vector<ColorMapEntry>& map = s.objects[0].texture->pigment.pigmentMap.at(0).pigment.colorMap;
    ASSERT_EQ(map.size(), 4u);
    EXPECT_EQ(map[0].color.rgb, Color(0, 1, 1));
    EXPECT_EQ(map[1].color.rgb, Color(1, 1, 0));
    EXPECT_EQ(map[2].color.rgb, Color(1, 0, 1));
}

TEST(PovLayeredTexture, UnsupportedTexturePatternAveragesItsEntriesWithAWarning) {
    Diagnostics diags;
    const Scene s = loadPov("sphere { 0, 1 texture { spiral1 5 texture_map { [0 pigment { rgb x }] "
                            "[1 pigment { rgb y }] } } }",
                            diags);
    EXPECT_EQ(diags.warningCount(), 1) << diags.formatAll();
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.objects[0].texture->pigment.pattern, PatternKind::Average);
    EXPECT_EQ(s.objects[0].texture->map.size(), 2u);
}

TEST(PovLayeredTexture, LayeringPatternedTexturesIsAnErrorAsInPovRay) {
    // POV-Ray 3.7: "Cannot layer over a patterned texture" / "Cannot layer a patterned texture over".
    const char* const checker = "texture { checker texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } }";
    Diagnostics over;
    EXPECT_FALSE(loadPovSceneText(std::string("sphere { 0, 1 ") + checker + "\n texture { pigment { rgbt 1 } } }",
                                  "s.pov", over));
    ASSERT_EQ(over.errorCount(), 1) << over.formatAll();
    EXPECT_EQ(over.all()[0].message, "cannot layer over a patterned texture (as POV-Ray)");
    EXPECT_EQ(over.all()[0].loc.line, 2);
    EXPECT_EQ(over.all()[0].loc.column, 2);
    Diagnostics under;
    EXPECT_FALSE(loadPovSceneText(std::string("#declare T = texture { pigment { rgb 1 } }\n  texture ") +
                                      (checker + 8) + "\nsphere { 0, 1 texture { T } }",
                                  "s.pov", under));
    ASSERT_GE(under.errorCount(), 1) << under.formatAll();
    EXPECT_EQ(under.all()[0].message, "cannot layer a patterned texture over another texture (as POV-Ray)");
    EXPECT_EQ(under.all()[0].loc.line, 2);
    EXPECT_EQ(under.all()[0].loc.column, 3);
}

TEST(PovLayeredTexture, ConvertedLayersRenderLikeThePovScene) {
    // The POV front end's model, written as .drt and read back, renders bit-identically.
    Diagnostics diags;
    const Scene pov = loadPov(std::string("camera { location <0, 2, -4> look_at <0, 0.5, 0> }\n"
                                          "light_source { <-3, 5, -4> rgb 1 }\n"
                                          "plane { y, 0 texture { tiles { texture { pigment { rgb 1 } } "
                                          "texture { pigment { gradient x color_map { [0 rgbt 1] [1 rgbf <1, 0, 0, 0.5>] } } }"
                                          " tile2 texture { pigment { rgb 0.1 } finish { reflection 0.3 } } } scale 0.7 } }\n"
                                          "sphere { y, 1 texture { pigment { rgb <0.2, 0.4, 0.8> } } texture { pigment { "
                                          "gradient y color_map { [0 rgbt 1] [0.5 rgbf <1, 0.6, 0, 0.5>] [1 rgbt 1] } scale 0.3 } "
                                          "finish { phong 0.8 } } rotate y * 20 }\n"
                                          "sphere { <2, 1, 0>, 0.8 pigment { gradient x pigment_map { [0 rgb x] [1 checker rgb 1,"
                                          " rgb 0 scale 0.2] } } }\n"),
                              diags);
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    EXPECT_TRUE(drtInexpressible(pov).empty());
    const Scene drt = loadDrt(writeDrtScene(pov));
    RenderOptions o;
    o.width = 40;
    o.height = 30;
    o.samplesPerPixel = 1;
    o.threads = 1;
    EXPECT_EQ(render(pov, o).color.pixels, render(drt, o).color.pixels);
}

} // namespace
} // namespace drt
