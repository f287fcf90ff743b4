// The .drt parser: what valid scenes turn into (defaults, declarations,
// includes, texture transforms, unions, motion), and robustness on bad input.
// Every error message has its own case in parser_errors_test.cpp.
#include "lang/load.h"
#include "render/pigment.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace drt {
namespace {

struct Parsed {
    std::optional<Scene> scene;
    Diagnostics diags;
};

std::unique_ptr<Parsed> parse(const std::string& text, const std::string& dir = ".") {
    auto p = std::make_unique<Parsed>();
    p->scene = loadSceneText(text, "test.drt", p->diags, dir);
    return p;
}

Scene parseOk(const std::string& text) {
    auto p = parse(text);
    EXPECT_FALSE(p->diags.hasErrors()) << p->diags.formatAll();
    return p->scene ? *p->scene : Scene{};
}

void expectNear(const Vec3& a, const Vec3& b, double eps = 1e-12) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

TEST(Parser, EmptySceneHasPovRayDefaults) {
    const Scene s = parseOk("");
    EXPECT_TRUE(s.objects.empty());
    EXPECT_EQ(s.global.maxTraceLevel, 5);
    EXPECT_EQ(s.background, Color(0));
    EXPECT_FALSE(s.render.width);
}

TEST(Parser, EmptyFinishHasPovRayDefaults) {
    const Scene s = parseOk("sphere { 0, 1 finish { } }");
    ASSERT_EQ(s.objects.size(), 1u);
    const Finish& f = s.objects[0].texture->finish;
    EXPECT_EQ(f.ambient, Color(0.1));
    EXPECT_DOUBLE_EQ(f.diffuse, 0.6);
    EXPECT_DOUBLE_EQ(f.phongSize, 40);
    EXPECT_DOUBLE_EQ(f.roughness, 0.05);
    EXPECT_EQ(f.reflectionMax, Color(0));
    EXPECT_EQ(s.objects[0].texture->pigment.color.rgb, Color(0)); // default pigment black
}

// Colour-map values outside [0, 1] are POV-Ray's (skies.inc uses 1.001): the
// pattern value 0.5 lies between -1 (black) and 1.001 (white), at 1.5 / 2.001.
TEST(Parser, ColorMapValuesMayLieOutsideZeroToOne) {
    const Scene s = parseOk("sphere { 0, 1 pigment { gradient x color_map { [-1 rgb 0] [1.001 rgb 1] } } }");
    const Pigment& p = s.objects.at(0).texture->pigment;
    ASSERT_EQ(p.colorMap.size(), 2u);
    EXPECT_EQ(p.colorMap[0].value, -1);
    EXPECT_NEAR(lookupColorMap(p.colorMap, 0.5).rgb.g, 1.5 / 2.001, 1e-12);
}

TEST(Parser, SphereAndExpressions) {
    const Scene s = parseOk("#declare R = sqrt(16) / 2;\n"
                            "sphere { <1, 2, 3> * 2 - x, R + pow(2, 3) - max(1, 2, 8) }");
    const Sphere& sp = std::get<Sphere>(s.objects.at(0).shape);
    expectNear(sp.center, {1, 4, 6});
    EXPECT_DOUBLE_EQ(sp.radius, 2);
}

TEST(Parser, FunctionsAndConstants) {
    const Scene s = parseOk("sphere { <degrees(pi), atan2(1, 1) * 4 / pi, vlength(<3, 4, 0>)>, "
                            "vdot(x, vcross(y, z)) + mod(7, 4) + floor(1.5) + ceil(0.2) + abs(-1) }");
    const Sphere& sp = std::get<Sphere>(s.objects.at(0).shape);
    expectNear(sp.center, {180, 1, 5});
    EXPECT_DOUBLE_EQ(sp.radius, 1 + 3 + 1 + 1 + 1);
}

TEST(Parser, VectorTimesVectorIsComponentWiseAndFloatsPromote) {
    const Scene s = parseOk("box { <1, 2, 3> * <2, 3, 4>, -(2) } ");
    const Box& b = std::get<Box>(s.objects.at(0).shape);
    expectNear(b.corner1, {2, 6, 12});
    expectNear(b.corner2, {-2, -2, -2});
}

TEST(Parser, ScaleByFloatPromotesToVector) {
    const Scene s = parseOk("sphere { 0, 1 scale 2 }");
    expectNear(s.objects.at(0).transform.point({1, 1, 1}), {2, 2, 2});
}

TEST(Parser, TransformsComposeInOrder) {
    const Scene s = parseOk("sphere { 0, 1 scale 2 translate x rotate <0, 0, 90> }");
    // (1,0,0) -> (2,0,0) -> (3,0,0) -> rotated 90 degrees about z.
    const Transform& t = s.objects.at(0).transform;
    expectNear(t.point({1, 0, 0}), Transform::rotate({0, 0, 90}).point({3, 0, 0}), 1e-12);
}

TEST(Parser, MatrixTakesTwelveNumbers) {
    const Scene s = parseOk("sphere { 0, 1 matrix <1,0,0, 0,1,0, 0,0,1, 4,5,6> }");
    expectNear(s.objects.at(0).transform.point({0, 0, 0}), {4, 5, 6});
}

TEST(Parser, ColoursInAllForms) {
    const Scene s = parseOk(
        "#declare C = rgbft <0.1, 0.2, 0.3, 0.4, 0.5>;\n"
        "sphere { 0, 1 pigment { color rgb <1, 0.5, 0.25> } }\n"
        "sphere { 0, 1 pigment { rgbf <1, 1, 1, 0.3> } }\n"
        "sphere { 0, 1 pigment { rgbt 0.5 } }\n"
        "sphere { 0, 1 pigment { color red 1 green 0.5 blue 0.25 filter 0.1 transmit 0.2 } }\n"
        "sphere { 0, 1 pigment { C } }\n"
        "sphere { 0, 1 pigment { <0.5, 0.25, 0.125> } }\n"
        "sphere { 0, 1 pigment { srgb <1, 0.5, 0> } }\n"
        "sphere { 0, 1 pigment { color rgb 1 * 0.5 } }\n");
    ASSERT_EQ(s.objects.size(), 8u);
    auto color = [&](int i) { return s.objects[i].texture->pigment.color; };
    EXPECT_EQ(color(0).rgb, Color(1, 0.5, 0.25));
    EXPECT_DOUBLE_EQ(color(1).filter, 0.3);
    EXPECT_DOUBLE_EQ(color(2).transmit, 0.5);
    EXPECT_DOUBLE_EQ(color(2).filter, 0);
    EXPECT_EQ(color(3).rgb, Color(1, 0.5, 0.25));
    EXPECT_DOUBLE_EQ(color(3).filter, 0.1);
    EXPECT_DOUBLE_EQ(color(3).transmit, 0.2);
    EXPECT_EQ(color(4).rgb, Color(0.1, 0.2, 0.3));
    EXPECT_DOUBLE_EQ(color(4).transmit, 0.5);
    EXPECT_EQ(color(5).rgb, Color(0.5, 0.25, 0.125));
    // sRGB 0.5 decodes to ((0.5 + 0.055) / 1.055)^2.4 = 0.21404...
    EXPECT_NEAR(color(6).rgb.g, 0.214041, 1e-6);
    EXPECT_DOUBLE_EQ(color(6).rgb.r, 1);
    EXPECT_EQ(color(7).rgb, Color(0.5));
}

TEST(Parser, CameraIsStoredRaw) {
    const Scene s = parseOk("camera { location <0, 1, -3> look_at <0, 1, 0> angle 50 up y sky y "
                            "right x * 1.5 direction z aperture 0.2 focal_point <0, 1, 2> focal_distance 4 "
                            "shutter_open 0 shutter_close 1 }");
    const CameraSpec& c = s.camera;
    expectNear(c.location, {0, 1, -3});
    ASSERT_TRUE(c.lookAt);
    expectNear(*c.lookAt, {0, 1, 0});
    EXPECT_DOUBLE_EQ(*c.angle, 50);
    ASSERT_TRUE(c.right);
    expectNear(*c.right, {1.5, 0, 0});
    EXPECT_DOUBLE_EQ(c.aperture, 0.2);
    expectNear(*c.focalPoint, {0, 1, 2});
    EXPECT_DOUBLE_EQ(*c.focalDistance, 4);
    EXPECT_DOUBLE_EQ(c.shutterClose, 1);
    EXPECT_EQ(c.loc.line, 1);
}

TEST(Parser, LightSourceWithEveryOption) {
    const Scene s = parseOk("light_source { <1, 2, 3>, color rgb <1, 0.5, 0.5> spotlight point_at <0, 0, 0> "
                            "radius 10 falloff 20 tightness 5 fade_distance 3 fade_power 2 shadowless "
                            "area_light <2, 0, 0>, <0, 0, 2>, 4, 3 jitter adaptive 1 circular orient "
                            "area_illumination on }\n"
                            "light_source { <0, 5, 0> rgb 2 translate y }\n"
                            "#declare Power = 3;\nlight_source { 0, Power }");
    ASSERT_EQ(s.lights.size(), 3u);
    EXPECT_EQ(s.lights[2].color, Color(3));
    const Light& l = s.lights[0];
    expectNear(l.position, {1, 2, 3});
    EXPECT_EQ(l.color, Color(1, 0.5, 0.5));
    EXPECT_TRUE(l.spotlight);
    EXPECT_DOUBLE_EQ(l.radius, 10);
    EXPECT_DOUBLE_EQ(l.falloff, 20);
    EXPECT_DOUBLE_EQ(l.tightness, 5);
    EXPECT_DOUBLE_EQ(l.fadeDistance, 3);
    EXPECT_DOUBLE_EQ(l.fadePower, 2);
    EXPECT_TRUE(l.shadowless);
    EXPECT_TRUE(l.areaIllumination);
    ASSERT_TRUE(l.area);
    EXPECT_EQ(l.area->size1, 4);
    EXPECT_EQ(l.area->size2, 3);
    EXPECT_TRUE(l.area->jitter && l.area->circular && l.area->orient);
    EXPECT_EQ(l.area->adaptive, 1);
    expectNear(s.lights[1].position, {0, 6, 0});
    EXPECT_EQ(s.lights[1].color, Color(2));
    EXPECT_FALSE(s.lights[1].area);
    EXPECT_FALSE(s.lights[1].inverseSquare);
}

TEST(Parser, AreaLightModes) {
    // A bare area_light is Cook's full illumination from stratified points.
    const Scene s = parseOk("light_source { 0 area_light x, z, 2, 2 }\n"
                            "light_source { 0 area_light x, z, 2, 2 area_illumination off area_sampling pov_grid }\n"
                            "light_source { 0 area_light x, z, 2, 2 area_sampling solid_angle inverse_square }\n"
                            "light_source { 0 inverse_square off }\n"
                            "light_source { 0 area_light x, z, 3, 3 jitter area_illumination off area_sampling grid }");
    ASSERT_EQ(s.lights.size(), 5u);
    ASSERT_TRUE(s.lights[0].area && s.lights[1].area && s.lights[2].area);
    EXPECT_TRUE(s.lights[0].areaIllumination);
    EXPECT_EQ(s.lights[0].area->sampling, AreaSampling::Stratified);
    EXPECT_FALSE(s.lights[0].inverseSquare);
    EXPECT_FALSE(s.lights[1].areaIllumination);
    EXPECT_EQ(s.lights[1].area->sampling, AreaSampling::PovGrid);
    EXPECT_EQ(s.lights[2].area->sampling, AreaSampling::SolidAngle);
    EXPECT_TRUE(s.lights[2].inverseSquare);
    EXPECT_FALSE(s.lights[3].inverseSquare);
    ASSERT_TRUE(s.lights[4].area);
    EXPECT_EQ(s.lights[4].area->sampling, AreaSampling::Grid);

    auto bad = parse("light_source { 0 area_light x, z, 2, 2 area_sampling cosine }");
    ASSERT_TRUE(bad->diags.hasErrors());
    const auto& d = bad->diags.all()[0];
    EXPECT_EQ(d.message, "expected 'stratified', 'solid_angle', 'grid' or 'pov_grid' after 'area_sampling', found 'cosine'");
    EXPECT_EQ(d.loc.line, 1);
    EXPECT_EQ(d.loc.column, 54);
}

TEST(Parser, SettingsBlocks) {
    const Scene s = parseOk("background { color rgb <0.1, 0.2, 0.3> }\n"
                            "global_settings { max_trace_level 12 ambient_light rgb 0.5 assumed_gamma 2.2 "
                            "adc_bailout 0.01 }\n"
                            "render { width 64 height 48 samples 9 seed 7 sampler \"independent\" filter \"box\" }");
    EXPECT_EQ(s.background, Color(0.1, 0.2, 0.3));
    EXPECT_EQ(s.global.maxTraceLevel, 12);
    EXPECT_EQ(s.global.ambientLight, Color(0.5));
    EXPECT_DOUBLE_EQ(s.global.assumedGamma, 2.2);
    EXPECT_DOUBLE_EQ(s.global.adcBailout, 0.01);
    EXPECT_EQ(*s.render.width, 64);
    EXPECT_EQ(*s.render.height, 48);
    EXPECT_EQ(*s.render.samplesPerPixel, 9);
    EXPECT_EQ(*s.render.seed, 7u);
    EXPECT_EQ(*s.render.sampler, "independent");
    EXPECT_EQ(*s.render.filter, "box");
    EXPECT_EQ(parseOk("background { rgb 1 }").background, Color(1));
    EXPECT_EQ(parseOk("#declare Sky = rgb <0, 0, 1>; background { Sky }").background, Color(0, 0, 1));
}

TEST(Parser, EveryShape) {
    const Scene s = parseOk("plane { <0, 2, 0>, 1 }\n"
                            "cylinder { 0, y, 0.5 open }\n"
                            "cone { 0, 1, y * 2, 0.5 }\n"
                            "disc { 0, y, 2, 1 }\n"
                            "torus { 2, 0.5 }\n"
                            "triangle { 0, x, y }\n"
                            "smooth_triangle { 0, z, x, z, y, z }\n"
                            "mesh { triangle { 0, x, y } triangle { x, y, z } }\n");
    ASSERT_EQ(s.objects.size(), 8u);
    const Plane& p = std::get<Plane>(s.objects[0].shape);
    expectNear(p.normal, {0, 1, 0});
    EXPECT_DOUBLE_EQ(p.distance, 0.5); // POV-Ray divides by |normal|: the plane stays at y = 0.5
    EXPECT_TRUE(std::get<Cylinder>(s.objects[1].shape).open);
    EXPECT_DOUBLE_EQ(std::get<Cone>(s.objects[2].shape).capRadius, 0.5);
    EXPECT_DOUBLE_EQ(std::get<Disc>(s.objects[3].shape).holeRadius, 1);
    EXPECT_DOUBLE_EQ(std::get<Torus>(s.objects[4].shape).minorRadius, 0.5);
    EXPECT_EQ(std::get<Mesh>(s.objects[5].shape).triangles.size(), 1u);
    const Mesh& smooth = std::get<Mesh>(s.objects[6].shape);
    ASSERT_EQ(smooth.normalIndices.size(), 1u);
    expectNear(smooth.normals[smooth.normalIndices[0][1]], {0, 0, 1});
    const IndexedMesh& m = *std::get<Mesh>(s.objects[7].shape).indexed;
    EXPECT_EQ(m.triangleCount(), 2u);
    EXPECT_TRUE(m.normals.empty());
}

TEST(Parser, ObjectFlags) {
    const Scene s = parseOk("sphere { 0, 1 no_shadow hollow inverse interior { ior 1.5 fade_distance 2 "
                            "fade_power 1 fade_color rgb 0.5 } }\nsphere { 0, 1 hollow off }");
    const Object& o = s.objects.at(0);
    EXPECT_TRUE(o.noShadow && o.hollow && o.inverse);
    EXPECT_DOUBLE_EQ(o.interior.ior, 1.5);
    EXPECT_DOUBLE_EQ(o.interior.fadeDistance, 2);
    EXPECT_EQ(o.interior.fadeColor, Color(0.5));
    EXPECT_FALSE(s.objects.at(1).hollow);
}

TEST(Parser, FinishKeywords) {
    const Scene s = parseOk("sphere { 0, 1 finish { ambient 0.2 diffuse 0.7 brilliance 2 phong 0.5 phong_size 60 "
                            "specular 0.3 roughness 0.01 metallic emission rgb <1, 0, 0> reflection 0.4 "
                            "conserve_energy reflection_blur 0.2 refraction_blur 0.1 } }\n"
                            "sphere { 0, 1 finish { reflection { 0.1, 0.9 fresnel falloff 2 metallic 0.5 } } }");
    const Finish& f = s.objects.at(0).texture->finish;
    EXPECT_EQ(f.ambient, Color(0.2));
    EXPECT_DOUBLE_EQ(f.diffuse, 0.7);
    EXPECT_DOUBLE_EQ(f.brilliance, 2);
    EXPECT_DOUBLE_EQ(f.phong, 0.5);
    EXPECT_DOUBLE_EQ(f.phongSize, 60);
    EXPECT_DOUBLE_EQ(f.specular, 0.3);
    EXPECT_DOUBLE_EQ(f.roughness, 0.01);
    EXPECT_DOUBLE_EQ(f.metallic, 1);
    EXPECT_EQ(f.emission, Color(1, 0, 0));
    EXPECT_EQ(f.reflectionMin, Color(0.4));
    EXPECT_EQ(f.reflectionMax, Color(0.4));
    EXPECT_TRUE(f.conserveEnergy);
    EXPECT_DOUBLE_EQ(f.reflectionBlur, 0.2);
    EXPECT_DOUBLE_EQ(f.refractionBlur, 0.1);
    const Finish& g = s.objects.at(1).texture->finish;
    EXPECT_EQ(g.reflectionMin, Color(0.1));
    EXPECT_EQ(g.reflectionMax, Color(0.9));
    EXPECT_TRUE(g.reflectionFresnel);
    EXPECT_DOUBLE_EQ(g.reflectionFalloff, 2);
    EXPECT_DOUBLE_EQ(g.reflectionMetallic, 0.5);
}

TEST(Parser, PatternsAndTheirDefaults) {
    const Scene s = parseOk("plane { y, 0 pigment { checker } }\n"
                            "plane { y, 0 pigment { checker rgb 1, pigment { hexagon } } }\n"
                            "plane { y, 0 pigment { brick brick_size <2, 1, 1> mortar 0.1 } }\n"
                            "plane { y, 0 pigment { gradient x color_map { [0 rgb 0] [0.5 rgb 1] [1 rgb 0] } } }\n"
                            "plane { y, 0 pigment { radial } }\n"
                            "plane { y, 0 pigment { onion } }\n");
    const Pigment& checker = s.objects[0].texture->pigment;
    EXPECT_EQ(checker.pattern, PatternKind::Checker);
    ASSERT_EQ(checker.children.size(), 2u);
    EXPECT_EQ(checker.children[0].color.rgb, Color(0, 0, 1)); // POV-Ray's blue / green
    EXPECT_EQ(checker.children[1].color.rgb, Color(0, 1, 0));
    const Pigment& nested = s.objects[1].texture->pigment;
    EXPECT_EQ(nested.children[0].color.rgb, Color(1));
    EXPECT_EQ(nested.children[1].pattern, PatternKind::Hexagon);
    EXPECT_EQ(nested.children[1].children.size(), 3u);
    const Pigment& brick = s.objects[2].texture->pigment;
    EXPECT_EQ(brick.pattern, PatternKind::Brick);
    expectNear(brick.brickSize, {2, 1, 1});
    EXPECT_DOUBLE_EQ(brick.mortar, 0.1);
    const Pigment& gradient = s.objects[3].texture->pigment;
    EXPECT_EQ(gradient.pattern, PatternKind::Gradient);
    expectNear(gradient.gradientAxis, {1, 0, 0});
    ASSERT_EQ(gradient.colorMap.size(), 3u);
    EXPECT_DOUBLE_EQ(gradient.colorMap[1].value, 0.5);
    EXPECT_EQ(s.objects[4].texture->pigment.colorMap.size(), 4u);
    EXPECT_EQ(s.objects[5].texture->pigment.colorMap.back().color.rgb, Color(1));
}

TEST(Parser, DeclaredValuesOfEveryKind) {
    const Scene s = parseOk("#declare P = pigment { rgb <1, 0, 0> }\n"
                            "#declare F = finish { phong 1 }\n"
                            "#declare I = interior { ior 1.33 }\n"
                            "#declare T = texture { pigment { P } finish { F diffuse 0.9 } }\n"
                            "#declare V = <1, 2, 3>;\n"
                            "sphere { V, 1 texture { T } interior { I } }\n"
                            "sphere { 0, 1 texture { T finish { phong 0.2 } } }\n");
    const Object& a = s.objects.at(0);
    EXPECT_EQ(a.texture->pigment.color.rgb, Color(1, 0, 0));
    EXPECT_DOUBLE_EQ(a.texture->finish.phong, 1);
    EXPECT_DOUBLE_EQ(a.texture->finish.diffuse, 0.9);
    EXPECT_DOUBLE_EQ(a.interior.ior, 1.33);
    expectNear(std::get<Sphere>(a.shape).center, {1, 2, 3});
    EXPECT_DOUBLE_EQ(s.objects.at(1).texture->finish.phong, 0.2);
    EXPECT_DOUBLE_EQ(s.objects.at(1).texture->finish.diffuse, 0.6); // a new finish starts from the defaults
}

TEST(Parser, DeclaredObjectIsReusedWithExtraTransforms) {
    const Scene s = parseOk("#declare Ball = sphere { 0, 1 pigment { rgb 1 } translate y }\n"
                            "object { Ball }\n"
                            "object { Ball translate x * 3 }\n"
                            "#declare Again = Ball\n"
                            "object { Again scale 2 }\n");
    ASSERT_EQ(s.objects.size(), 3u);
    expectNear(s.objects[0].transform.point({0, 0, 0}), {0, 1, 0});
    expectNear(s.objects[1].transform.point({0, 0, 0}), {3, 1, 0});
    expectNear(s.objects[2].transform.point({0, 0, 0}), {0, 2, 0});
    EXPECT_EQ(s.objects[1].texture->pigment.color.rgb, Color(1));
}

// POV-Ray: a texture moves with the object's transforms that come after it,
// not with those before it.
TEST(Parser, TextureFollowsOnlyLaterTransforms) {
    const Scene s = parseOk("sphere { 0, 1 translate x pigment { checker } scale 2 }\n"
                            "sphere { 0, 1 pigment { checker scale 0.5 } translate y }\n"
                            "sphere { 0, 1 texture { pigment { checker } translate z } rotate <0, 90, 0> }\n");
    const Pigment& a = s.objects[0].texture->pigment;
    expectNear(a.toWorld.point({1, 1, 1}), {2, 2, 2}); // scaled, not moved
    expectNear(a.children[0].toWorld.point({1, 1, 1}), {2, 2, 2});
    const Pigment& b = s.objects[1].texture->pigment;
    expectNear(b.toWorld.point({2, 2, 2}), {1, 2, 1});
    const Pigment& c = s.objects[2].texture->pigment;
    expectNear(c.toWorld.point({0, 0, 0}), Transform::rotate({0, 90, 0}).point({0, 0, 1}), 1e-12);
}

TEST(Parser, DeclaredObjectKeepsItsTextureAttached) {
    const Scene s = parseOk("#declare B = box { 0, 1 pigment { checker } }\nobject { B translate <5, 0, 0> }");
    expectNear(s.objects.at(0).texture->pigment.toWorld.point({0, 0, 0}), {5, 0, 0});
}

TEST(Parser, UnionIsFlattenedWithTransformsAndInheritedTexture) {
    const Scene s = parseOk("union {\n"
                            "  sphere { x, 1 }\n"
                            "  sphere { -x, 1 pigment { rgb <0, 1, 0> } }\n"
                            "  pigment { checker }\n"
                            "  translate y * 2\n"
                            "  no_shadow\n"
                            "}\n");
    ASSERT_EQ(s.objects.size(), 2u);
    expectNear(s.objects[0].transform.point(std::get<Sphere>(s.objects[0].shape).center), {1, 2, 0});
    expectNear(s.objects[1].transform.point(std::get<Sphere>(s.objects[1].shape).center), {-1, 2, 0});
    EXPECT_EQ(s.objects[0].texture->pigment.pattern, PatternKind::Checker);
    // The union's pigment moves with the union: its origin is at y = 2 in the world.
    expectNear(s.objects[0].texture->pigment.toWorld.point({0, 0, 0}), {0, 2, 0});
    EXPECT_EQ(s.objects[1].texture->pigment.color.rgb, Color(0, 1, 0)); // own texture kept
    EXPECT_TRUE(s.objects[0].noShadow && s.objects[1].noShadow);
}

TEST(Parser, ClipsMoveOnlyWithLaterTransformsAndReachUnionMembers) {
    const Scene s = parseOk("sphere { 0, 1 translate x clipped_by { box { 0, 1 } plane { y, 0 } } scale 2 }\n"
                            "union { sphere { 0, 1 clipped_by { sphere { 0, 2 translate z } } translate x }\n"
                            "        box { 0, 1 } clipped_by { box { 0, 1 } } translate y }\n");
    ASSERT_EQ(s.objects.size(), 3u);
    // The translate before clipped_by does not move the clips; the scale after it does.
    ASSERT_EQ(s.objects[0].clippedBy.size(), 2u);
    EXPECT_EQ(s.objects[0].clippedBy[0].transform, Transform::scale({2, 2, 2}));
    EXPECT_TRUE(std::holds_alternative<Plane>(s.objects[0].clippedBy[1].shape));
    // Union members: the union's clip, then their own clips (moved by the
    // member's translate after clipped_by and by the union's), in world space.
    ASSERT_EQ(s.objects[1].clippedBy.size(), 2u);
    expectNear(s.objects[1].clippedBy[0].transform.point({0, 0, 0}), {0, 1, 0});
    expectNear(s.objects[1].clippedBy[1].transform.point({0, 0, 0}), {1, 1, 1});
    ASSERT_EQ(s.objects[2].clippedBy.size(), 1u);
    expectNear(s.objects[2].clippedBy[0].transform.point({0, 0, 0}), {0, 1, 0});
}

TEST(Parser, NestedDeclaredUnion) {
    const Scene s = parseOk("#declare Pair = union { sphere { 0, 1 } sphere { x * 3, 1 } }\n"
                            "union { object { Pair } object { Pair translate z * 3 } scale 2 }");
    ASSERT_EQ(s.objects.size(), 4u);
    expectNear(s.objects[3].transform.point(std::get<Sphere>(s.objects[3].shape).center), {6, 0, 6});
}

TEST(Parser, MotionBlock) {
    const Scene s = parseOk("sphere { 0, 1 translate x motion { translate <0, 1, 0> rotate <0, 0, 10> scale 2 } }\n"
                            "sphere { 0, 1 motion { translate x } scale 2 }\n"
                            "union { sphere { 0, 1 } motion { translate y } translate z }\n"
                            "sphere { 0, 1 motion { spline at 0.5 rotate y*180 at 1 rotate y*360 translate x } }\n");
    ASSERT_EQ(s.objects.size(), 4u);
    // One key at time 1, from the identity the parser puts at time 0.
    const Object& a = s.objects[0];
    ASSERT_EQ(a.motion.size(), 1u);
    const Motion& m = a.motion[0].motion;
    ASSERT_EQ(m.keys.size(), 2u);
    EXPECT_EQ(m.keys[0], MotionKey{0});
    EXPECT_EQ(m.keys[1].time, 1);
    expectNear(m.keys[1].translate, {0, 1, 0});
    expectNear(m.keys[1].rotate, {0, 0, 10});
    expectNear(m.keys[1].scale, {2, 2, 2});
    EXPECT_FALSE(m.spline);
    expectNear(a.transform.point({0, 0, 0}), {1, 0, 0}); // the transforms before the motion
    // A transform after the motion goes after it (the motion is scaled too).
    const Object& b = s.objects[1];
    expectNear(b.transform.point({0, 0, 0}), {0, 0, 0});
    expectNear(placementAt(b.transform, b.motion, 1).point({0, 0, 0}), {2, 0, 0});
    expectNear(placementAt(b.transform, b.motion, 0.5).point({0, 0, 0}), {1, 0, 0});
    // A union's motion and later transforms reach its member.
    const Object& c = s.objects[2];
    expectNear(placementAt(c.transform, c.motion, 1).point({0, 0, 0}), {0, 1, 1});
    // Keys with times; an identity key at 0 is added.
    const Motion& d = s.objects[3].motion.at(0).motion;
    ASSERT_EQ(d.keys.size(), 3u);
    EXPECT_TRUE(d.spline);
    EXPECT_EQ(d.keys[0], MotionKey{0});
    EXPECT_EQ(d.keys[1].time, 0.5);
    expectNear(d.keys[2].rotate, {0, 360, 0});
    expectNear(d.keys[2].translate, {1, 0, 0});
    expectNear(d.keys[2].scale, {1, 1, 1});
    EXPECT_TRUE(parseOk("sphere { 0, 1 }").objects.at(0).motion.empty());
}

TEST(Parser, MotionStandsWhereItIsWritten) {
    // Spinning about its own centre c = <3, 0, 0>: moved to the origin, turned, moved back.
    const Scene s = parseOk("sphere { <3, 0, 1>, 0.5 pigment { checker } translate <-3, 0, 0> "
                            "motion { rotate y*360 } translate <3, 0, 0> }\n"
                            "union { sphere { <1, 0, 0>, 0.5 motion { rotate y*90 } } translate <0, 2, 0> rotate x*90 }\n");
    const Object& wheel = s.objects.at(0);
    for (double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        const Transform at = placementAt(wheel.transform, wheel.motion, t);
        expectNear(at.point({3, 0, 0}), {3, 0, 0}); // the centre stays put
        expectNear(at.point({3, 0, 1}), Vec3{3, 0, 0} + Transform::rotate({0, 360 * t, 0}).point({0, 0, 1}));
    }
    // The texture is placed in the rest pose (every motion the identity).
    expectNear(wheel.texture->pigment.toWorld.point({1, 2, 3}), {1, 2, 3});
    // A member of a transformed union turns in the union's own space.
    const Object& member = s.objects.at(1);
    const Transform outer = Transform::translate({0, 2, 0}).then(Transform::rotate({90, 0, 0}));
    for (double t : {0.0, 0.5, 1.0})
        expectNear(placementAt(member.transform, member.motion, t).point({1, 0, 0}),
                   outer.point(Transform::rotate({0, 90 * t, 0}).point({1, 0, 0})));
}

TEST(Parser, ClipsOfAMovingObjectAreInItsRestPose) {
    const Scene s = parseOk("sphere { 0, 1 clipped_by { box { -1, 0 } } translate x motion { rotate y*90 } "
                            "translate <0, 2, 0> }");
    const Object& o = s.objects.at(0);
    ASSERT_EQ(o.clippedBy.size(), 1u);
    expectNear(o.clippedBy[0].transform.point({0, 0, 0}), {1, 2, 0});
    expectNear(restPlacement(o.transform, o.motion).point({0, 0, 0}), {1, 2, 0});
}

TEST(Parser, SemicolonsAndVersionAreAccepted) {
    const Scene s = parseOk("#version 3.7;\n#declare A = sphere { 0, 1 };\nobject { A };\n#local B = 2;\n");
    EXPECT_EQ(s.objects.size(), 1u);
}

TEST(Parser, BooleansAreNumbers) {
    const Scene s = parseOk("sphere { 0, true + yes + on + off + false + no }");
    EXPECT_DOUBLE_EQ(std::get<Sphere>(s.objects.at(0).shape).radius, 3);
}

TEST(Parser, IncludeIsRelativeToTheIncludingFile) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/lib/colors.drt", "#declare Red = rgb <1, 0, 0>;\n#include \"more/size.drt\"\n");
    test::writeFile(dir + "/lib/more/size.drt", "#declare Size = 2;\n");
    const std::string main = test::writeFile(dir + "/scene.drt",
                                             "#include \"lib/colors.drt\"\nsphere { 0, Size pigment { Red } }\n");
    Diagnostics diags;
    const auto scene = loadSceneFile(main, diags);
    ASSERT_TRUE(scene) << diags.formatAll();
    EXPECT_DOUBLE_EQ(std::get<Sphere>(scene->objects.at(0).shape).radius, 2);
    EXPECT_EQ(scene->objects.at(0).texture->pigment.color.rgb, Color(1, 0, 0));
}

TEST(Parser, ErrorInIncludedFileShowsTheIncludeChain) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/inner.drt", "\nsphere { 0, -1 }\n");
    test::writeFile(dir + "/middle.drt", "#include \"inner.drt\"\n");
    const std::string main = test::writeFile(dir + "/main.drt", "// main\n#include \"middle.drt\"\n");
    Diagnostics diags;
    EXPECT_FALSE(loadSceneFile(main, diags));
    ASSERT_EQ(diags.errorCount(), 1);
    const Diagnostic& d = diags.all()[0];
    EXPECT_EQ(d.message, "sphere radius must be positive, got -1");
    EXPECT_EQ(d.loc.line, 2);
    EXPECT_EQ(d.loc.column, 13);
    ASSERT_EQ(d.includedFrom.size(), 2u);
    EXPECT_EQ(d.includedFrom[0].line, 1); // in middle.drt
    EXPECT_EQ(d.includedFrom[1].line, 2); // in main.drt
    const std::string text = diags.format(d);
    EXPECT_NE(text.find("In file included from"), std::string::npos);
    EXPECT_NE(text.find("inner.drt:2:13: error: sphere radius must be positive"), std::string::npos);
}

TEST(Parser, IncludeCycleIsAnError) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/a.drt", "#include \"b.drt\"\n");
    test::writeFile(dir + "/b.drt", "sphere { 0, 1 }\n#include \"a.drt\"\n");
    Diagnostics diags;
    EXPECT_FALSE(loadSceneFile(dir + "/a.drt", diags));
    ASSERT_EQ(diags.errorCount(), 1);
    EXPECT_EQ(diags.all()[0].message, "include cycle: a.drt -> b.drt -> a.drt");
    EXPECT_EQ(diags.all()[0].loc.line, 2);
    EXPECT_EQ(diags.all()[0].loc.column, 10);
}

TEST(Parser, SelfIncludeIsACycle) {
    const std::string dir = test::tempDir();
    const std::string self = test::writeFile(dir + "/self.drt", "#include \"self.drt\"\n");
    Diagnostics diags;
    EXPECT_FALSE(loadSceneFile(self, diags));
    EXPECT_EQ(diags.all().at(0).message, "include cycle: self.drt -> self.drt");
}

TEST(Parser, SameFileIncludedTwiceIsNotACycle) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/ball.drt", "sphere { 0, 1 }\n");
    const std::string main = test::writeFile(dir + "/m.drt", "#include \"ball.drt\"\n#include \"ball.drt\"\n");
    Diagnostics diags;
    const auto scene = loadSceneFile(main, diags);
    ASSERT_TRUE(scene) << diags.formatAll();
    EXPECT_EQ(scene->objects.size(), 2u);
}

TEST(Parser, SeveralErrorsAreReportedInOneRun) {
    auto p = parse("sphear { 0, 1 }\n"
                   "sphere { 0, 1 tranlate x }\n"
                   "camera { location 0 look_at 0 }\n"
                   "box { 0, 1 pigment { rgb 1 }\n" // missing '}'
                   "light_source { <0, 0, 0> colr rgb 1 }\n"
                   "sphere { 0, 1 }\n");
    EXPECT_FALSE(p->scene);
    ASSERT_EQ(p->diags.errorCount(), 5) << p->diags.formatAll();
    EXPECT_EQ(p->diags.all()[0].loc.line, 1);
    EXPECT_EQ(p->diags.all()[1].message, "unknown keyword 'tranlate'; did you mean 'translate'?");
    EXPECT_EQ(p->diags.all()[2].message, "'look_at' is the same point as 'location'");
    EXPECT_EQ(p->diags.all()[3].message, "expected an object modifier or '}' to close 'box', found 'light_source'");
    EXPECT_EQ(p->diags.all()[3].loc.line, 5);
    EXPECT_EQ(p->diags.all()[4].message, "unknown keyword 'colr'; did you mean 'color'?");
}

TEST(Parser, DeepNestingIsAnErrorNotACrash) {
    const std::string parens = "sphere { 0, " + std::string(10000, '(') + "1" + std::string(10000, ')') + " }";
    auto p = parse(parens);
    ASSERT_TRUE(p->diags.hasErrors());
    EXPECT_EQ(p->diags.all()[0].message, "nesting depth 201 is over the limit of 200 (limit nesting_depth = 200; raise it with --limit "
                                            "nesting_depth=N)");
    std::string unions;
    for (int i = 0; i < 5000; ++i) unions += "union { ";
    auto q = parse(unions);
    ASSERT_TRUE(q->diags.hasErrors());
    EXPECT_EQ(q->diags.all()[0].message, "nesting depth 201 is over the limit of 200 (limit nesting_depth = 200; raise it with --limit "
                                            "nesting_depth=N)");
}

TEST(Parser, TruncatedScenesNeverCrashOrHang) {
    const std::string scene = "#declare T = texture { pigment { checker rgb 1, rgb 0 } finish { phong 1 } }\n"
                              "camera { location <0, 2, -5> look_at 0 angle 45 }\n"
                              "light_source { <5, 5, -5>, rgb 1 area_light x, z, 2, 2 }\n"
                              "union { sphere { 0, 1 texture { T } } box { -1, 1 } motion { translate x } }\n"
                              "mesh { triangle { 0, x, y } smooth_triangle { 0, y, x, y, z, y } }\n";
    for (size_t cut = 0; cut <= scene.size(); ++cut) {
        auto p = parse(scene.substr(0, cut));
        EXPECT_EQ(p->scene.has_value(), !p->diags.hasErrors()) << "cut at " << cut;
    }
    // And every single-byte corruption.
    const std::string junk = "{}<>,;()#\"/*=@";
    int withErrors = 0;
    for (size_t i = 0; i < scene.size(); i += 3) {
        std::string bad = scene;
        bad[i] = junk[i % junk.size()];
        auto p = parse(bad);
        EXPECT_EQ(p->scene.has_value(), !p->diags.hasErrors()) << "byte " << i;
        withErrors += p->diags.hasErrors() ? 1 : 0;
    }
    EXPECT_GT(withErrors, 0);
}

TEST(Parser, LoadSceneFileReportsAMissingFile) {
    Diagnostics diags;
    EXPECT_FALSE(loadSceneFile("/nonexistent/scene.drt", diags));
    ASSERT_EQ(diags.errorCount(), 1);
    EXPECT_EQ(diags.all()[0].message, "cannot read scene file: cannot open '/nonexistent/scene.drt': No such file or directory");
}

TEST(Parser, FormattedErrorHasFileLineColumnSourceAndCaret) {
    auto p = parse("#declare Radius = 1;\nsphere {\n  0, Radus\n}\n");
    ASSERT_EQ(p->diags.errorCount(), 1);
    EXPECT_EQ(p->diags.formatAll(), "test.drt:3:6: error: unknown identifier 'Radus'; did you mean 'Radius'?\n"
                                    "    0, Radus\n"
                                    "       ^\n");
}

} // namespace
} // namespace drt

// merge, difference and intersection stay one object holding its members in
// its own space; pigments map to world space like everywhere in the model.
TEST(Parser, SolidCsgKeepsItsMembers) {
    drt::Diagnostics diags;
    auto scene = drt::loadSceneText(R"(
        difference {
          box { <-1, -1, -1>, <1, 1, 1> }
          sphere { <0, 1, 0>, 0.5 translate x }
          pigment { checker color rgb 1, color rgb 0 }
          translate y * 2
        }
        intersection { sphere { 0, 1 } plane { y, 0 } }
        merge { sphere { 0, 1 } sphere { x, 1 } }
    )", "csg.drt", diags);
    ASSERT_TRUE(scene) << diags.formatAll();
    ASSERT_EQ(scene->objects.size(), 3u);
    const auto& difference = std::get<drt::Csg>(scene->objects[0].shape);
    EXPECT_EQ(difference.op, drt::Csg::Op::Difference);
    ASSERT_EQ(difference.children.size(), 2u);
    // The member's own transform stays relative to the CSG...
    EXPECT_EQ(difference.children[1].transform.point({0, 0, 0}), drt::Vec3(1, 0, 0));
    // ...the CSG carries the transform to world space...
    EXPECT_EQ(scene->objects[0].transform.point({0, 0, 0}), drt::Vec3(0, 2, 0));
    // ...and the inherited pigment follows the CSG to world space.
    EXPECT_EQ(difference.children[0].texture->pigment.toWorld.point({0, 0, 0}), drt::Vec3(0, 2, 0));
    EXPECT_EQ(std::get<drt::Csg>(scene->objects[1].shape).op, drt::Csg::Op::Intersection);
    EXPECT_EQ(std::get<drt::Csg>(scene->objects[2].shape).op, drt::Csg::Op::Merge);
}

TEST(Parser, EmptyDifferenceIsAnError) {
    drt::Diagnostics diags;
    EXPECT_FALSE(drt::loadSceneText("difference { translate x }", "empty.drt", diags));
    EXPECT_NE(diags.formatAll().find("empty.drt:1:1: error: difference has no objects"), std::string::npos)
        << diags.formatAll();
}
