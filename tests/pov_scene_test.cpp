// The POV-Ray front end's scene model: camera conventions, lights, focal blur,
// area lights, CSG, textures, gamma rules, warnings and strict mode, and
// POV-Ray's own sample scenes.
#include "pov/load.h"
#include "render/render.h"
#include "test_support.h"

#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>

namespace drt {
namespace {

constexpr const char* kExamples = "/usr/share/doc/povray/examples/";

std::optional<Scene> load(const std::string& text, Diagnostics& diags, PovOptions options = {}) {
    return loadPovSceneText(text, "s.pov", diags, options);
}

Scene loadOk(const std::string& text, PovOptions options = {}) {
    Diagnostics diags;
    std::optional<Scene> scene = load(text, diags, options);
    EXPECT_TRUE(scene) << diags.formatAll();
    EXPECT_EQ(diags.errorCount(), 0) << diags.formatAll();
    return scene ? *scene : Scene{};
}

int warningsContaining(const Diagnostics& diags, const std::string& part) {
    int n = 0;
    for (const Diagnostic& d : diags.all())
        if (d.severity == Severity::Warning && d.message.find(part) != std::string::npos) ++n;
    return n;
}

void expectNear(const Vec3& a, const Vec3& b, double tolerance = 1e-9) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(PovScene, DefaultCameraUsesPovRaysVectors) {
    const Scene s = loadOk("sphere { 0, 1 }");
    ASSERT_TRUE(s.camera.right);
    expectNear(*s.camera.right, {1.33, 0, 0});
    expectNear(s.camera.up, {0, 1, 0});
    expectNear(s.camera.direction, {0, 0, 1});
    expectNear(s.camera.location, {0, 0, 0});
}

TEST(PovScene, CameraItemsAreStoredAsWritten) {
    PovOptions o;
    o.imageWidth = 400;
    o.imageHeight = 200;
    const Scene s = loadOk("camera { location <1, 2, -3> right x*image_width/image_height up y "
                           "sky <0, 1, 0.1> look_at <0, 1, 0> angle 50 }",
                           o);
    expectNear(s.camera.location, {1, 2, -3});
    expectNear(*s.camera.right, {2, 0, 0});
    ASSERT_TRUE(s.camera.lookAt);
    expectNear(*s.camera.lookAt, {0, 1, 0});
    expectNear(s.camera.sky, {0, 1, 0.1});
    ASSERT_TRUE(s.camera.angle);
    EXPECT_DOUBLE_EQ(*s.camera.angle, 50);
    EXPECT_EQ(s.render.width, 400);
    EXPECT_EQ(s.render.height, 200);
}

TEST(PovScene, CameraTransformMovesTheResolvedCamera) {
    const Scene s = loadOk("camera { location <0, 0, -5> look_at 0 rotate y*90 translate x }");
    // The camera at z = -5 looking along +z, turned 90 degrees about y, looks along +x from x = -5.
    expectNear(s.camera.location, {-4, 0, 0});
    EXPECT_FALSE(s.camera.lookAt);
    EXPECT_NEAR(normalize(s.camera.direction).x, 1, 1e-9);
    expectNear(*s.camera.right, {0, 0, -1.33});
}

TEST(PovScene, FocalBlurUsesAQuarterOfTheAperture) {
    const Scene s = loadOk("camera { location <0, 0, -10> look_at 0 aperture 1.2 blur_samples 30 "
                           "focal_point <1, 0, 0> }");
    // POV-Ray's lens radius is aperture/4; the model's aperture is a diameter.
    EXPECT_DOUBLE_EQ(s.camera.aperture, 0.6);
    EXPECT_DOUBLE_EQ(s.camera.aperture / 2, 1.2 / 4);
    ASSERT_TRUE(s.camera.focalPoint);
    expectNear(*s.camera.focalPoint, {1, 0, 0});
    EXPECT_EQ(s.render.samplesPerPixel, 30);
}

TEST(PovScene, ApertureWithoutBlurSamplesIsAPinhole) {
    Diagnostics diags;
    const auto s = load("camera { aperture 2 }", diags);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->camera.aperture, 0);
    EXPECT_EQ(warningsContaining(diags, "blur_samples"), 1);
}

TEST(PovScene, PointAndSpotLights) {
    const Scene s = loadOk("light_source { <1, 2, 3> color rgb <1, 0.5, 0.25> fade_distance 4 fade_power 2 }\n"
                           "light_source { <0, 10, 0>, 1 spotlight point_at <0, 0, 1> radius 10 falloff 20 "
                           "tightness 5 shadowless translate x }");
    ASSERT_EQ(s.lights.size(), 2u);
    const Light& a = s.lights[0];
    expectNear(a.position, {1, 2, 3});
    EXPECT_EQ(a.color, Color(1, 0.5, 0.25));
    EXPECT_EQ(a.fadeDistance, 4);
    EXPECT_EQ(a.fadePower, 2);
    EXPECT_FALSE(a.spotlight);
    const Light& b = s.lights[1];
    EXPECT_TRUE(b.spotlight);
    EXPECT_TRUE(b.shadowless);
    EXPECT_EQ(b.color, Color(1));
    expectNear(b.position, {1, 10, 0});
    expectNear(b.pointAt, {1, 0, 1});
    EXPECT_EQ(b.radius, 10);
    EXPECT_EQ(b.falloff, 20);
    EXPECT_EQ(b.tightness, 5);
}

TEST(PovScene, AreaLightsKeepPovRaysSemantics) {
    const Scene s = loadOk("light_source { 0 rgb 1 area_light <2, 0, 0>, <0, 0, 4>, 3, 5 adaptive 1 jitter "
                           "circular orient }\n"
                           "light_source { 0 rgb 1 area_light x, z, 2, 2 area_illumination on }");
    ASSERT_EQ(s.lights.size(), 2u);
    const Light& a = s.lights[0];
    ASSERT_TRUE(a.area);
    expectNear(a.area->axis1, {2, 0, 0});
    expectNear(a.area->axis2, {0, 0, 4});
    EXPECT_EQ(a.area->size1, 3);
    EXPECT_EQ(a.area->size2, 5);
    EXPECT_EQ(a.area->adaptive, 1);
    EXPECT_TRUE(a.area->jitter);
    EXPECT_TRUE(a.area->circular);
    EXPECT_TRUE(a.area->orient);
    EXPECT_EQ(a.area->sampling, AreaSampling::Grid); // POV-Ray's grid points, one per camera sample
    EXPECT_FALSE(a.areaIllumination); // shadow-only averaging by default
    EXPECT_FALSE(a.inverseSquare);
    EXPECT_TRUE(s.lights[1].areaIllumination);
}

TEST(PovScene, CsgKeepsItsTreeAndInverse) {
    const Scene s = loadOk("difference { box { -1, 1 } sphere { 0, 1.2 inverse } cylinder { -2*x, 2*x, 0.5 } "
                           "translate y }");
    ASSERT_EQ(s.objects.size(), 1u);
    const Csg* csg = std::get_if<Csg>(&s.objects[0].shape);
    ASSERT_TRUE(csg);
    EXPECT_EQ(csg->op, Csg::Op::Difference);
    ASSERT_EQ(csg->children.size(), 3u);
    EXPECT_TRUE(std::holds_alternative<Box>(csg->children[0].shape));
    EXPECT_TRUE(csg->children[1].inverse);
    EXPECT_FALSE(csg->children[0].inverse);
    expectNear(s.objects[0].transform.point({0, 0, 0}), {0, 1, 0});
}

TEST(PovScene, UnionTextureGoesToChildrenWithoutOne) {
    const Scene s = loadOk("union { sphere { 0, 1 } sphere { x, 1 pigment { rgb <1, 0, 0> } } "
                           "pigment { rgb <0, 0, 1> } }");
    const Csg& csg = std::get<Csg>(s.objects[0].shape);
    EXPECT_EQ(csg.children[0].texture->pigment.color.rgb, Color(0, 0, 1));
    EXPECT_EQ(csg.children[1].texture->pigment.color.rgb, Color(1, 0, 0));
}

TEST(PovScene, DeclaredObjectsAreCopiedAndTransformed) {
    const Scene s = loadOk("#declare Ball = sphere { <0, 0, 0>, 2 pigment { checker rgb 1, rgb 0 } }\n"
                           "object { Ball translate <5, 0, 0> }\nobject { Ball scale 2 }");
    ASSERT_EQ(s.objects.size(), 2u);
    expectNear(s.objects[0].transform.point({0, 0, 0}), {5, 0, 0});
    expectNear(s.objects[1].transform.point({1, 0, 0}), {2, 0, 0});
    // The pigment moves with the object it belongs to.
    const Pigment& p = s.objects[0].texture->pigment;
    EXPECT_EQ(p.pattern, PatternKind::Checker);
    ASSERT_EQ(p.children.size(), 2u);
    expectNear(p.toWorld.point({0, 0, 0}), {5, 0, 0});
}

TEST(PovScene, PlaneNormalIsNormalisedWithItsDistance) {
    const Scene s = loadOk("plane { <0, 2, 0>, 1 }");
    const Plane& p = std::get<Plane>(s.objects[0].shape);
    expectNear(p.normal, {0, 1, 0});
    EXPECT_DOUBLE_EQ(p.distance, 0.5);
}

TEST(PovScene, PrimitivesAndMeshes) {
    const Scene s = loadOk("cone { 0, 1, y, 0.5 open }\ndisc { 0, y, 2, 1 }\ntorus { 3, 0.5 }\n"
                           "triangle { 0, x, y }\nsmooth_triangle { 0, z, x, z, y, z }\n"
                           "mesh { triangle { 0, x, y } triangle { x, y, z } }\n"
                           "mesh2 { vertex_vectors { 4, 0, x, y, z } face_indices { 2, <0, 1, 2>, <1, 2, 3> } }");
    ASSERT_EQ(s.objects.size(), 7u);
    EXPECT_TRUE(std::get<Cone>(s.objects[0].shape).open);
    EXPECT_EQ(std::get<Disc>(s.objects[1].shape).holeRadius, 1);
    EXPECT_EQ(std::get<Torus>(s.objects[2].shape).majorRadius, 3);
    EXPECT_EQ(std::get<Mesh>(s.objects[4].shape).normals.size(), 3u);
    EXPECT_EQ(std::get<Mesh>(s.objects[5].shape).indexed->triangleCount(), 2u);
    const IndexedMesh& m2 = *std::get<Mesh>(s.objects[6].shape).indexed;
    EXPECT_EQ(m2.positions.size(), 4u);
    EXPECT_EQ(m2.triangle(1), (std::array<uint32_t, 3>{1, 2, 3}));
}

TEST(PovScene, FinishInteriorAndColourMaps) {
    const Scene s = loadOk("sphere { 0, 1 texture { pigment { gradient y color_map { [0 rgb 0] [0.5, rgb x] "
                           "[0.7 0.9 rgb y rgb z] } } finish { ambient 0.2 diffuse 0.7 phong 0.5 phong_size 60 "
                           "specular 0.3 roughness 0.01 metallic reflection { 0.1, 0.6 fresnel on falloff 2 } "
                           "conserve_energy brilliance 2 } } interior { ior 1.5 fade_distance 2 fade_power 3 } }");
    const Object& o = s.objects[0];
    const Pigment& p = o.texture->pigment;
    EXPECT_EQ(p.pattern, PatternKind::Gradient);
    ASSERT_EQ(p.colorMap.size(), 4u);
    EXPECT_EQ(p.colorMap[1].value, 0.5);
    EXPECT_EQ(p.colorMap[2].value, 0.7);
    EXPECT_EQ(p.colorMap[3].color.rgb, Color(0, 0, 1));
    const Finish& f = o.texture->finish;
    EXPECT_EQ(f.ambient, Color(0.2));
    EXPECT_EQ(f.diffuse, 0.7);
    EXPECT_EQ(f.phong, 0.5);
    EXPECT_EQ(f.phongSize, 60);
    EXPECT_EQ(f.specular, 0.3);
    EXPECT_EQ(f.roughness, 0.01);
    EXPECT_EQ(f.metallic, 1);
    EXPECT_EQ(f.reflectionMin, Color(0.1));
    EXPECT_EQ(f.reflectionMax, Color(0.6));
    EXPECT_TRUE(f.reflectionFresnel);
    EXPECT_EQ(f.reflectionFalloff, 2);
    EXPECT_TRUE(f.conserveEnergy);
    EXPECT_EQ(f.brilliance, 2);
    EXPECT_EQ(o.interior.ior, 1.5);
    EXPECT_EQ(o.interior.fadeDistance, 2);
    EXPECT_EQ(o.interior.fadePower, 3);
}

TEST(PovScene, UnmodelledNoisePatternIsApproximatedByItsMapAverageOnce) {
    Diagnostics diags;
    const auto s = load("sphere { 0, 1 pigment { cells color_map { [0 rgb 0] [1 rgb 1] } } }\n"
                        "sphere { 0, 1 pigment { cells color_map { [0 rgb 0] [1 rgb 1] } } }",
                        diags);
    ASSERT_TRUE(s);
    const Pigment& p = s->objects[0].texture->pigment;
    EXPECT_EQ(p.pattern, PatternKind::Solid);
    EXPECT_NEAR(p.color.rgb.r, 0.5, 1e-12);
    EXPECT_EQ(warningsContaining(diags, "'cells' is approximated"), 1);
}

TEST(PovScene, GammaRules) {
    const std::string body = "sphere { 0, 1 pigment { rgb 0.5 } }\nlight_source { 0 rgb 0.5 }\n";
    // 3.7 default and assumed_gamma 1: linear, unchanged.
    EXPECT_EQ(loadOk("#version 3.7;\n" + body).objects[0].texture->pigment.color.rgb, Color(0.5));
    EXPECT_EQ(loadOk("global_settings { assumed_gamma 1.0 }\n" + body).objects[0].texture->pigment.color.rgb,
              Color(0.5));
    EXPECT_EQ(loadOk("#version 3.7;\n" + body).global.assumedGamma, 1.0);
    // assumed_gamma 2.2: colours are encoded; POV-Ray shades them as written and
    // decodes the pixels, so the model keeps them and carries the gamma.
    const Scene g = loadOk("global_settings { assumed_gamma 2.2 }\n" + body);
    EXPECT_EQ(g.objects[0].texture->pigment.color.rgb, Color(0.5));
    EXPECT_EQ(g.lights[0].color, Color(0.5));
    EXPECT_EQ(g.global.assumedGamma, 2.2);
    // #version 3.6 without assumed_gamma: no gamma handling in POV-Ray, which is gamma 2.2.
    EXPECT_EQ(loadOk("#version 3.6;\n" + body).global.assumedGamma, 2.2);
    // srgb: to linear, then into the working space with the gamma known at that point.
    const double linear = std::pow((0.5 + 0.055) / 1.055, 2.4);
    EXPECT_NEAR(loadOk("global_settings { assumed_gamma 2.2 }\nsphere { 0, 1 pigment { srgb 0.5 } }")
                    .objects[0].texture->pigment.color.rgb.r,
                std::pow(linear, 1 / 2.2), 1e-12);
    EXPECT_NEAR(loadOk("sphere { 0, 1 pigment { srgb 0.5 } }").objects[0].texture->pigment.color.rgb.r, linear, 1e-12);
}

// POV-Ray's working gamma end to end: a surface lit head-on with diffuse 0.6
// and ambient 0.2 has the working value v = 0.5 (0.2 + 0.6) = 0.4, and the
// image holds v^2.2 (POV-Ray shades encoded values and decodes the pixel). The
// old approach, decoding the colour first, would give 0.5^2.2 * 0.8 instead.
TEST(PovScene, AssumedGammaShadesInTheWorkingSpaceAndDecodesThePixel) {
    const std::string scene = "global_settings { assumed_gamma 2.2 }\n"
                              "camera { location <0, 0, -5> look_at 0 angle 10 }\n"
                              "light_source { <0, 0, -1000> rgb 1 }\n"
                              "plane { z, 0 pigment { rgb 0.5 } finish { ambient 0.2 diffuse 0.6 } }\n";
    const Scene s = loadOk(scene);
    RenderOptions options = resolveRenderOptions(s.render);
    options.width = 8;
    options.height = 6;
    options.samplesPerPixel = 1;
    const RenderResult r = render(s, options);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(r.color.at(4, 3, c), std::pow(0.4, 2.2), 1e-4);
}

TEST(PovScene, UnsupportedFeaturesWarnOncePerKindWithLocation) {
    Diagnostics diags;
    const auto s = load("rainbow { angle 42 }\nsphere { 0, 1 normal { facets 0.5 } }\nrainbow { width 3 }\n"
                        "sphere { 0, 1 normal { facets 1 } }",
                        diags);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->objects.size(), 2u);
    EXPECT_EQ(diags.warningCount(), 2);
    ASSERT_EQ(warningsContaining(diags, "'rainbow'"), 1);
    for (const Diagnostic& d : diags.all()) {
        if (d.message.find("'rainbow'") != std::string::npos) {
            EXPECT_EQ(d.loc.line, 1);
            EXPECT_EQ(d.loc.column, 1);
        }
        if (d.message.find("'normal'") != std::string::npos) {
            EXPECT_EQ(d.loc.line, 2);
            EXPECT_EQ(d.loc.column, 15);
        }
    }
}

TEST(PovScene, UnusedDeclarationsDoNotWarnButUsesDo) {
    Diagnostics quiet;
    ASSERT_TRUE(load("#declare T = texture { pigment { cells } normal { facets 1 } }\nsphere { 0, 1 }", quiet));
    EXPECT_EQ(quiet.warningCount(), 0) << quiet.formatAll();
    Diagnostics used;
    ASSERT_TRUE(load("#declare T = texture { pigment { cells } normal { facets 1 } }\nsphere { 0, 1 texture { T } }",
                     used));
    EXPECT_EQ(used.warningCount(), 2) << used.formatAll();
}

TEST(PovScene, StrictModeTurnsWarningsIntoErrors) {
    PovOptions o;
    o.strict = true;
    Diagnostics diags;
    EXPECT_FALSE(load("sphere { 0, 1 }\nrainbow { angle 42 }", diags, o));
    EXPECT_EQ(diags.errorCount(), 1);
    EXPECT_EQ(diags.all()[0].loc.line, 2);
    Diagnostics clean;
    EXPECT_TRUE(load("sphere { 0, 1 }", clean, o));
}

TEST(PovScene, LayeredTexturesPutTheSecondOnTop) {
    Diagnostics diags;
    const auto s = load("sphere { 0, 1 texture { pigment { rgb x } } texture { pigment { rgbt 1 } } }", diags);
    ASSERT_TRUE(s);
    const Texture& t = s->objects[0].texture;
    EXPECT_EQ(t.pigment.color.rgb, Color(1, 0, 0));
    ASSERT_EQ(t.layersAbove.size(), 1u);
    EXPECT_EQ(t.layersAbove[0].pigment.color.transmit, 1);
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
}

TEST(PovScene, LightInsideUnionMovesWithIt) {
    const Scene s = loadOk("union { sphere { 0, 1 } light_source { <0, 2, 0> rgb 1 } translate x }");
    ASSERT_EQ(s.lights.size(), 1u);
    expectNear(s.lights[0].position, {1, 2, 0});
    ASSERT_EQ(s.objects.size(), 1u);
}

TEST(PovScene, ArrayElementsAsTexturesAndPigments) {
    const Scene s = loadOk("#declare T = array[2] { texture { pigment { rgb x } }, texture { pigment { rgb y } } }\n"
                           "#declare C = array[2] { rgb z, pigment { rgb 0.5 } }\n"
                           "sphere { 0, 1 texture { T[1] } }\nsphere { 0, 1 pigment { C[0] } }\n"
                           "sphere { 0, 1 pigment { C[1] } }");
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_EQ(s.objects[0].texture->pigment.color.rgb, Color(0, 1, 0));
    EXPECT_EQ(s.objects[1].texture->pigment.color.rgb, Color(0, 0, 1));
    EXPECT_EQ(s.objects[2].texture->pigment.color.rgb, Color(0.5));
}

TEST(PovScene, DefaultTextureAppliesToLaterObjectsWithoutOne) {
    const Scene s = loadOk("sphere { 0, 1 }\n#default { finish { ambient 0.3 } pigment { rgb y } }\n"
                           "sphere { 0, 1 }\nsphere { 0, 1 pigment { rgb x } }\n"
                           "union { sphere { 0, 1 } pigment { rgb z } }");
    ASSERT_EQ(s.objects.size(), 4u);
    EXPECT_EQ(s.objects[0].texture->finish.ambient, Color(0.1));
    EXPECT_EQ(s.objects[1].texture->finish.ambient, Color(0.3));
    EXPECT_EQ(s.objects[1].texture->pigment.color.rgb, Color(0, 1, 0));
    EXPECT_EQ(s.objects[2].texture->pigment.color.rgb, Color(1, 0, 0));
    EXPECT_EQ(s.objects[2].texture->finish.ambient, Color(0.3));
    EXPECT_EQ(std::get<Csg>(s.objects[3].shape).children[0].texture->pigment.color.rgb, Color(0, 0, 1));
}

// ---------------------------------------------------------------- command line

TEST(PovCli, RenderAndCheckAPovScene) {
    const std::string dir = test::tempDir();
    const std::string scene = test::writeFile(
        dir + "/scene.pov", "camera { location <0, 0, -4> look_at 0 }\nlight_source { <2, 4, -3> rgb 1 }\n"
                            "sphere { 0, 1 pigment { rgb <1, image_width / 1000, 0> } }\n");
    const auto check = test::runDrt("check '" + scene + "'");
    EXPECT_EQ(check.exitCode, 0) << check.err;
    EXPECT_NE(check.out.find("ok (1 objects, 1 lights)"), std::string::npos) << check.out;
    const auto render = test::runDrt("render '" + scene + "' -o '" + dir + "/out.png' --width 40 --height 30 -q");
    EXPECT_EQ(render.exitCode, 0) << render.err;
    EXPECT_TRUE(std::filesystem::exists(dir + "/out.png"));
}

TEST(PovCli, StrictAndIncludePathOptions) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/lib/size.inc", "#declare R = 2;\n");
    const std::string scene = test::writeFile(dir + "/scene.pov", "#include \"size.inc\"\nsphere { 0, R }\n"
                                                                  "rainbow { angle 42 }\n");
    const auto missing = test::runDrt("check '" + scene + "'");
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_NE(missing.err.find("scene.pov:1:10: error: cannot find include file"), std::string::npos) << missing.err;
    const auto found = test::runDrt("check -L '" + dir + "/lib' '" + scene + "'");
    EXPECT_EQ(found.exitCode, 0) << found.err;
    EXPECT_NE(found.err.find("scene.pov:3:1: warning: 'rainbow'"), std::string::npos) << found.err;
    const auto strict = test::runDrt("check --strict -L '" + dir + "/lib' '" + scene + "'");
    EXPECT_EQ(strict.exitCode, 1);
    EXPECT_NE(strict.err.find("scene.pov:3:1: error: 'rainbow'"), std::string::npos) << strict.err;
}

// ---------------------------------------------------------------- POV-Ray's sample scenes

std::optional<Scene> loadExample(const std::string& name, Diagnostics& diags) {
    return loadPovSceneFile(std::string(kExamples) + name, diags);
}

TEST(PovExamples, FocalBlur) {
    Diagnostics diags;
    const auto s = loadExample("camera/focalblur.pov", diags);
    ASSERT_TRUE(s) << diags.formatAll();
    EXPECT_EQ(diags.errorCount(), 0);
    const CameraSpec& c = s->camera;
    expectNear(c.location, {50, 10, 30});
    ASSERT_TRUE(c.lookAt);
    expectNear(*c.lookAt, {0, 10, 0});
    EXPECT_DOUBLE_EQ(*c.angle, 35);
    expectNear(*c.right, {320.0 / 240.0, 0, 0});
    EXPECT_DOUBLE_EQ(c.aperture, 5); // aperture 10: lens radius 2.5
    expectNear(*c.focalPoint, {5, 10, 5});
    EXPECT_EQ(s->render.samplesPerPixel, 120);
    EXPECT_EQ(s->lights.size(), 1u);
}

void expectArealit(const std::string& name, const std::array<double, 3>& axes, const std::array<int, 3>& sizes) {
    Diagnostics diags;
    const auto s = loadExample(name, diags);
    ASSERT_TRUE(s) << diags.formatAll();
    EXPECT_EQ(diags.errorCount(), 0);
    ASSERT_EQ(s->lights.size(), 4u);
    const double pointX[3] = {-20, 0, 20};
    for (int i = 0; i < 3; ++i) {
        const Light& l = s->lights[size_t(i)];
        expectNear(l.position, {0, 40, -40});
        ASSERT_TRUE(l.area);
        expectNear(l.area->axis1, {axes[size_t(i)], 0, 0});
        expectNear(l.area->axis2, {0, axes[size_t(i)], 0});
        EXPECT_EQ(l.area->size1, sizes[size_t(i)]);
        EXPECT_EQ(l.area->size2, sizes[size_t(i)]);
        EXPECT_EQ(l.area->adaptive, 0);
        EXPECT_TRUE(l.area->jitter);
        EXPECT_EQ(l.area->sampling, AreaSampling::Grid);
        EXPECT_FALSE(l.areaIllumination);
        EXPECT_TRUE(l.spotlight);
        expectNear(l.pointAt, {pointX[i], 0, 0});
        EXPECT_EQ(l.radius, 0);
        EXPECT_EQ(l.falloff, 11);
    }
    expectNear(s->lights[3].position, {0, -15, -120});
    EXPECT_NEAR(s->lights[3].color.r, 0.1, 1e-12); // Gray10, assumed_gamma 1: linear
    expectNear(s->camera.location, {0, -15, -120});
    EXPECT_DOUBLE_EQ(*s->camera.angle, 35);
}

TEST(PovExamples, AreaLit1) { expectArealit("lights/arealit1.pov", {8, 8, 8}, {3, 5, 17}); }
TEST(PovExamples, AreaLit2) { expectArealit("lights/arealit2.pov", {4, 8, 16}, {17, 17, 17}); }

} // namespace
} // namespace drt
