// The POV-Ray front end's fog, sky_sphere, optional commas between vectors,
// a sky parallel to the view, and what it reports as notes rather than
// warnings; plus the .drt syntax for fog and sky_sphere and its writer.
#include "lang/load.h"
#include "lang/writer.h"
#include "pov/load.h"

#include <gtest/gtest.h>

namespace drt {
namespace {

Scene loadPov(const std::string& text, Diagnostics& diags) {
    std::optional<Scene> scene = loadPovSceneText(text, "s.pov", diags, PovOptions{});
    EXPECT_TRUE(scene) << diags.formatAll();
    EXPECT_EQ(diags.errorCount(), 0) << diags.formatAll();
    return scene ? *scene : Scene{};
}

int countSeverity(const Diagnostics& diags, Severity severity) {
    int n = 0;
    for (const Diagnostic& d : diags.all()) n += d.severity == severity;
    return n;
}

TEST(PovAtmosphere, ConstantFogIsKeptWithItsColour) {
    Diagnostics diags;
    const Scene s = loadPov("#version 3.7; fog { distance 150 colour rgbft <0.3, 0.5, 0.2, 1, 0.1> }", diags);
    ASSERT_EQ(s.fogs.size(), 1u);
    EXPECT_EQ(s.fogs[0].type, Fog::Type::Constant);
    EXPECT_DOUBLE_EQ(s.fogs[0].distance, 150);
    EXPECT_DOUBLE_EQ(s.fogs[0].color.rgb.g, 0.5);
    EXPECT_DOUBLE_EQ(s.fogs[0].color.filter, 1);
    EXPECT_DOUBLE_EQ(s.fogs[0].color.transmit, 0.1);
    EXPECT_EQ(countSeverity(diags, Severity::Warning), 0) << diags.formatAll();
}

TEST(PovAtmosphere, GroundFogKeepsItsWorkingSpaceColour) {
    Diagnostics diags;
    const Scene s = loadPov("global_settings { assumed_gamma 2.2 }\n"
                            "fog { fog_type 2 distance 3 color rgb <0.5, 1, 0> fog_offset 1.5 fog_alt 0.25 up z }",
                            diags);
    ASSERT_EQ(s.fogs.size(), 1u);
    EXPECT_EQ(s.fogs[0].type, Fog::Type::Ground);
    EXPECT_DOUBLE_EQ(s.fogs[0].offset, 1.5);
    EXPECT_DOUBLE_EQ(s.fogs[0].altitude, 0.25);
    EXPECT_DOUBLE_EQ(s.fogs[0].up.z, 1);
    // Colours stay in the working space (gamma 2.2); the film decodes the result.
    EXPECT_DOUBLE_EQ(s.fogs[0].color.rgb.r, 0.5);
    EXPECT_DOUBLE_EQ(s.global.assumedGamma, 2.2);
}

TEST(PovAtmosphere, FogTurbulenceIsKeptWithANote) {
    Diagnostics diags;
    const Scene s = loadPov("fog { distance 3 color rgb 1 turbulence 0.2 octaves 4 turb_depth 0.3 }", diags);
    ASSERT_EQ(s.fogs.size(), 1u);
    ASSERT_TRUE(s.fogs[0].turbulence);
    EXPECT_DOUBLE_EQ(s.fogs[0].turbulence->amount.y, 0.2);
    EXPECT_EQ(s.fogs[0].turbulence->octaves, 4);
    EXPECT_DOUBLE_EQ(s.fogs[0].turbDepth, 0.3);
    EXPECT_EQ(countSeverity(diags, Severity::Warning), 0) << diags.formatAll();
    EXPECT_EQ(countSeverity(diags, Severity::Note), 1) << diags.formatAll();
}

TEST(PovAtmosphere, SkySphereKeepsItsPigmentsAndDeclaredSkies) {
    Diagnostics diags;
    const Scene s = loadPov("#declare S = sky_sphere { pigment { gradient y color_map { [0 rgb 1] [1 rgb <0,0,1>] } } "
                            "rotate x*10 }\n"
                            "sky_sphere { S pigment { rgbt <1, 1, 1, 0.5> } }",
                            diags);
    ASSERT_EQ(s.sky.size(), 2u);
    EXPECT_EQ(s.sky[0].pattern, PatternKind::Gradient);
    // The declared rotation turns the pattern.
    const Vec3 p = s.sky[0].toWorld.point({0, 1, 0});
    EXPECT_NEAR(p.z, std::sin(10 * 3.14159265358979 / 180), 1e-9);
    EXPECT_EQ(countSeverity(diags, Severity::Warning), 0) << diags.formatAll();
}

TEST(PovAtmosphere, CommasBetweenVectorsAreOptional) {
    Diagnostics diags;
    const Scene s = loadPov("box { <-32, -1, -32> <32, 0, 32> }", diags);
    ASSERT_EQ(s.objects.size(), 1u);
    const Box& b = std::get<Box>(s.objects[0].shape);
    EXPECT_DOUBLE_EQ(b.corner1.x, -32);
    EXPECT_DOUBLE_EQ(b.corner2.z, 32);
    // A comparison of floats still works.
    Diagnostics d2;
    const Scene t = loadPov("#if (1 < 2) sphere { 0, 1 } #end", d2);
    EXPECT_EQ(t.objects.size(), 1u);
}

TEST(PovAtmosphere, SkyParallelToTheViewKeepsTheRightVector) {
    Diagnostics diags;
    const Scene s = loadPov("camera { location <0, 10, 0> look_at <0, 0, 0> }", diags);
    EXPECT_FALSE(s.camera.lookAt);
    EXPECT_NEAR(s.camera.direction.y, -1, 1e-12);
    ASSERT_TRUE(s.camera.right);
    EXPECT_NEAR(s.camera.right->x, 1.33, 1e-12);
    // up = direction x right = (-y) x x = z (left-handed frame as POV-Ray).
    EXPECT_NEAR(s.camera.up.z, 1, 1e-12);
    EXPECT_EQ(countSeverity(diags, Severity::Warning), 0);
}

TEST(PovAtmosphere, BoundsAndEmptyUnionsAreNotes) {
    Diagnostics diags;
    loadPov("sphere { 0, 1 bounded_by { box { -1, 1 } } }\nunion { }\n", diags);
    EXPECT_EQ(countSeverity(diags, Severity::Warning), 0) << diags.formatAll();
    EXPECT_EQ(countSeverity(diags, Severity::Note), 2) << diags.formatAll();
    Diagnostics clip;
    loadPov("sphere { 0, 1 clipped_by { plane { y, 0 } } }", clip);
    EXPECT_EQ(countSeverity(clip, Severity::Warning), 0) << clip.formatAll(); // clipped_by is supported
}

TEST(PovAtmosphere, DefaultWithoutHashIsTheDefaultDirective) {
    Diagnostics diags;
    const Scene s = loadPov("default { finish { ambient 0.3 } }\nsphere { 0, 1 }", diags);
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_DOUBLE_EQ(s.objects[0].texture->finish.ambient.r, 0.3);
}

TEST(PovAtmosphere, TrailingCommaInAVectorAndJitterBeforeAreaLight) {
    Diagnostics diags;
    const Scene s = loadPov("sphere { <1, 2, 3,>, 1 }\n"
                            "light_source { <0, 5, 0> rgb 1 jitter area_light <1, 0, 0>, <0, 0, 1>, 3, 3 }",
                            diags);
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_DOUBLE_EQ(std::get<Sphere>(s.objects[0].shape).center.z, 3);
    ASSERT_EQ(s.lights.size(), 1u);
    ASSERT_TRUE(s.lights[0].area);
    EXPECT_TRUE(s.lights[0].area->jitter);
    EXPECT_EQ(s.lights[0].area->size1, 3);
}

Scene parseDrt(const std::string& text, Diagnostics& diags) {
    std::optional<Scene> s = loadSceneText(text, "t.drt", diags, ".");
    EXPECT_TRUE(s) << diags.formatAll();
    return s ? *s : Scene{};
}

TEST(DrtAtmosphere, FogAndSkySphereParseAndRoundTrip) {
    Diagnostics diags;
    const Scene s = parseDrt("sky_sphere { pigment { gradient y color_map { [0 rgb 1] [1 rgb <0, 0, 1>] } } }\n"
                             "fog { distance 20 color rgbft <0.5, 0.5, 0.5, 0.2, 0.1> }\n"
                             "fog { fog_type 2 distance 5 color rgb 1 fog_offset 2 fog_alt 0.5 up <0, 0, 1> turbulence 0.4 }\n",
                             diags);
    ASSERT_EQ(s.fogs.size(), 2u);
    ASSERT_EQ(s.sky.size(), 1u);
    EXPECT_EQ(s.sky[0].colorMap.size(), 2u);
    EXPECT_DOUBLE_EQ(s.fogs[0].color.filter, 0.2);
    EXPECT_EQ(s.fogs[1].type, Fog::Type::Ground);
    Diagnostics again;
    const Scene r = parseDrt(writeDrtScene(s), again);
    ASSERT_EQ(r.fogs.size(), 2u);
    ASSERT_EQ(r.sky.size(), 1u);
    EXPECT_EQ(r.sky[0].colorMap.size(), 2u);
    EXPECT_EQ(r.fogs[0].distance, s.fogs[0].distance);
    EXPECT_EQ(r.fogs[0].color, s.fogs[0].color);
    EXPECT_EQ(r.fogs[1].type, Fog::Type::Ground);
    EXPECT_EQ(r.fogs[1].offset, 2);
    EXPECT_EQ(r.fogs[1].altitude, 0.5);
    EXPECT_EQ(r.fogs[1].up.z, 1);
    ASSERT_TRUE(r.fogs[1].turbulence);
    EXPECT_EQ(r.fogs[1].turbulence->amount.x, 0.4);
    EXPECT_EQ(r.fogs[1].turbDepth, 0.5);
}

TEST(DrtAtmosphere, BadFogIsAnErrorWithALocation) {
    Diagnostics diags;
    EXPECT_FALSE(loadSceneText("fog { distance -1 color rgb 1 }", "t.drt", diags, "."));
    EXPECT_NE(diags.formatAll().find("t.drt:1:16"), std::string::npos) << diags.formatAll();
    Diagnostics missing;
    EXPECT_FALSE(loadSceneText("fog { color rgb 1 }", "t.drt", missing, "."));
    EXPECT_NE(missing.formatAll().find("needs a 'distance'"), std::string::npos) << missing.formatAll();
}

} // namespace
} // namespace drt
