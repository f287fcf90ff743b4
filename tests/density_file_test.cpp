// POV-Ray's density_file pattern: a df3 voxel file over the unit cube, read
// after parsing (assets), evaluated with no, trilinear or tricubic
// interpolation, in pigments, texture patterns, normals and media densities,
// in both dialects, and written back by the .drt writer.
//
// The reference rows below were measured on POV-Ray 3.7: a 4 x 2 x 1 df3 file
// (8-bit voxels, row y = 0: 51 85 170 255, row y = 1: 255 0 255 0) under
// `pigment { density_file df3 "w.df3" interpolate N color_map { [0 rgb 0] [1 rgb 1] } }`
// on the plane z = 0.5, an orthographic camera showing x and y from -0.25 to
// 1.25 at 24 x 24 pixels, 16-bit linear PNG; the values are pixel row 19
// (y = 0.03125), pixels 4 to 19 (x = 0.03125 + k / 16), printed to 3 decimals.
#include "assets/assets.h"
#include "lang/load.h"
#include "lang/writer.h"
#include "render/pigment.h"
#include "scene/density_file.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <fstream>

namespace drt {
namespace {

std::string writeDf3(const std::string& path, int nx, int ny, int nz, const std::vector<uint32_t>& voxels, int bytes) {
    std::ofstream out(path, std::ios::binary);
    const unsigned char header[6] = {uint8_t(nx >> 8), uint8_t(nx), uint8_t(ny >> 8), uint8_t(ny), uint8_t(nz >> 8),
                                     uint8_t(nz)};
    out.write(reinterpret_cast<const char*>(header), 6);
    for (uint32_t v : voxels)
        for (int b = bytes - 1; b >= 0; --b) out.put(char((v >> (8 * b)) & 0xff));
    return path;
}

std::string measuredFile(const std::string& dir) {
    return writeDf3(dir + "/w.df3", 4, 2, 1, {51, 85, 170, 255, 255, 0, 255, 0}, 1);
}

std::optional<Scene> loadResolved(const std::string& text, const std::string& name, const std::string& dir,
                                  Diagnostics& diags) {
    std::optional<Scene> s = loadSceneText(text, name, diags, LoadOptions{}, dir);
    if (s && !resolveAssets(*s, diags)) return std::nullopt;
    return s;
}

std::string greyPlane(int interpolation) {
    return "plane { z, 0.5 pigment { density_file df3 \"w.df3\" interpolate " + std::to_string(interpolation) +
           " color_map { [0 rgb 0] [1 rgb 1] } } }";
}

TEST(DensityFile, ValuesAreThoseOfPovRaysRenders) {
    const std::string dir = test::tempDir();
    measuredFile(dir);
    const double trilinear[16] = {0.258, 0.273, 0.289, 0.305, 0.359, 0.453, 0.547, 0.641,
                                  0.719, 0.781, 0.844, 0.906, 0.852, 0.680, 0.508, 0.336};
    const double tricubic[16] = {0.179, 0.179, 0.229, 0.298, 0.362, 0.442, 0.535, 0.627,
                                 0.719, 0.840, 0.951, 0.002, 0.938, 0.737, 0.484, 0.271};
    const double none[16] = {0.2, 0.2, 0.2, 0.2, 1 / 3.0, 1 / 3.0, 1 / 3.0, 1 / 3.0,
                             2 / 3.0, 2 / 3.0, 2 / 3.0, 2 / 3.0, 1, 1, 1, 1};
    for (const char* name : {"s.pov", "s.drt"})
        for (int interpolation = 0; interpolation <= 2; ++interpolation) {
            Diagnostics diags;
            const auto s = loadResolved(greyPlane(interpolation), name, dir, diags);
            ASSERT_TRUE(s) << diags.formatAll();
            EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
            const Pigment& pigment = s->objects.at(0).texture->pigment;
            ASSERT_EQ(pigment.pattern, PatternKind::DensityFile);
            const double* expected = interpolation == 0 ? none : interpolation == 1 ? trilinear : tricubic;
            for (int k = 0; k < 16; ++k) {
                const Vec3 p(0.03125 + k / 16.0, 0.03125, 0.5);
                // 5e-4: POV-Ray's figures are printed to 3 decimals. Tricubic at
                // k = 11 overshoots 1 and wraps (fmod(v, 1.00001), as every pattern).
                EXPECT_NEAR(evaluatePigment(pigment, p).rgb.g, expected[k], 5.1e-4)
                    << name << " interpolate " << interpolation << " x = " << p.x;
            }
            // Outside the unit cube the pattern is 0, on every side.
            for (const Vec3 p : {Vec3(-0.01, 0.5, 0.5), Vec3(1.0, 0.5, 0.5), Vec3(0.5, 1.2, 0.5), Vec3(0.5, 0.5, -3)})
                EXPECT_EQ(evaluatePigment(pigment, p).rgb.g, 0) << name << " " << p.x << " " << p.y << " " << p.z;
        }
}

TEST(DensityFile, TrilinearIsTheBlendOfTheEightVoxelsAroundThePoint) {
    // Voxel i sits at grid coordinate i; past the last one the first follows.
    const std::string dir = test::tempDir();
    measuredFile(dir);
    Diagnostics diags;
    const auto s = loadResolved(greyPlane(1), "s.pov", dir, diags);
    ASSERT_TRUE(s) << diags.formatAll();
    const Pigment& pigment = s->objects.at(0).texture->pigment;
    const double v[2][4] = {{0.2, 85 / 255.0, 170 / 255.0, 1}, {1, 0, 1, 0}};
    const auto lerp = [](double a, double b, double t) { return a + t * (b - a); };
    // x = 0.3: grid 1.2, between voxels 1 and 2; y = 0.3: grid 0.6, between rows 0 and 1.
    EXPECT_NEAR(evaluatePigment(pigment, Vec3(0.3, 0.3, 0.5)).rgb.r,
                lerp(lerp(v[0][1], v[0][2], 0.2), lerp(v[1][1], v[1][2], 0.2), 0.6), 1e-6);
    // x = 0.9: grid 3.6, between voxel 3 and voxel 0 (wrapped); y = 0.8: grid 1.6, row 1 then row 0.
    EXPECT_NEAR(evaluatePigment(pigment, Vec3(0.9, 0.8, 0.5)).rgb.r,
                lerp(lerp(v[1][3], v[1][0], 0.6), lerp(v[0][3], v[0][0], 0.6), 0.6), 1e-6);
}

TEST(DensityFile, SixteenAndThirtyTwoBitVoxels) {
    const std::string dir = test::tempDir();
    writeDf3(dir + "/w.df3", 2, 1, 1, {0, 32768}, 2);
    writeDf3(dir + "/w32.df3", 2, 1, 1, {0xffffffffu, 0x40000000u}, 4);
    Diagnostics diags;
    const auto s = loadResolved(greyPlane(0) + "plane { z, 0.5 pigment { density_file df3 \"w32.df3\" } }", "s.pov",
                                dir, diags);
    ASSERT_TRUE(s) << diags.formatAll();
    EXPECT_NEAR(evaluatePigment(s->objects.at(0).texture->pigment, Vec3(0.75, 0.5, 0.5)).rgb.r, 32768 / 65535.0, 1e-6);
    const Pigment& big = s->objects.at(1).texture->pigment;
    EXPECT_NEAR(samplePattern(big, Vec3(0.25, 0.5, 0.5)).value, 1.0, 1e-6);
    EXPECT_NEAR(samplePattern(big, Vec3(0.75, 0.5, 0.5)).value, 0.25, 1e-6);
}

TEST(DensityFile, TexturePatternNormalAndMediaDensity) {
    const std::string dir = test::tempDir();
    measuredFile(dir);
    Diagnostics diags;
    const auto s = loadResolved(
        "sphere { 0, 1 texture { density_file df3 \"w.df3\" interpolate 1 texture_map { [0 pigment { rgb 0 }]"
        " [1 pigment { rgb 1 }] } } }\n"
        "sphere { 0, 1 pigment { rgb 1 } normal { density_file df3 \"w.df3\" , 2.6 interpolate 2 } }\n"
        "sphere { 0, 1 hollow pigment { rgbt 1 } interior { media { emission 1"
        " density { density_file df3 \"w.df3\" } } } }\n",
        "s.pov", dir, diags);
    ASSERT_TRUE(s) << diags.formatAll();
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    const Pigment& pattern = s->objects.at(0).texture->pigment;
    ASSERT_EQ(pattern.pattern, PatternKind::DensityFile);
    ASSERT_TRUE(pattern.densityFile);
    EXPECT_EQ(pattern.densityFile->interpolation, DensityFile::Interpolation::Trilinear);
    EXPECT_EQ(pattern.densityFile->values.size(), 8u);
    ASSERT_TRUE(s->objects.at(1).texture->normal);
    const Normal& normal = *s->objects.at(1).texture->normal;
    EXPECT_EQ(normal.pattern, PatternKind::DensityFile);
    EXPECT_DOUBLE_EQ(normal.amount, 2.6);
    ASSERT_TRUE(normal.densityFile);
    EXPECT_EQ(normal.densityFile->interpolation, DensityFile::Interpolation::Tricubic);
    EXPECT_EQ(normal.densityFile->values.size(), 8u); // the normal's file is read too
    const Pigment& density = s->objects.at(2).interior.media.at(0).densities.at(0);
    ASSERT_TRUE(density.densityFile);
    EXPECT_NEAR(samplePattern(density, Vec3(0.3, 0.7, 0.5)).value, 0.0, 1e-12); // voxel (1, 1): 0
    EXPECT_NEAR(samplePattern(density, Vec3(0.6, 0.2, 0.5)).value, 170 / 255.0, 1e-6);
    EXPECT_TRUE(assetsResolved(*s));
}

TEST(DensityFile, AConvertedSceneNamesTheFileAndKeepsTheValues) {
    const std::string dir = test::tempDir();
    measuredFile(dir);
    Diagnostics diags;
    const auto pov = loadResolved(greyPlane(2) + "\nsphere { 0, 1 normal { density_file df3 \"w.df3\" 1.5 interpolate 1 } }",
                                  "s.pov", dir, diags);
    ASSERT_TRUE(pov) << diags.formatAll();
    const std::string text = writeDrtScene(*pov);
    EXPECT_NE(text.find("density_file df3 \"" + dir + "/w.df3\" interpolate 2"), std::string::npos) << text;
    Diagnostics again;
    const auto drt = loadResolved(text, "converted.drt", "/", again);
    ASSERT_TRUE(drt) << text << "\n" << again.formatAll();
    for (const Vec3 p : {Vec3(0.1, 0.1, 0.5), Vec3(0.6, 0.3, 0.5), Vec3(0.95, 0.9, 0.2)})
        EXPECT_EQ(evaluatePigment(drt->objects.at(0).texture->pigment, p).rgb.r,
                  evaluatePigment(pov->objects.at(0).texture->pigment, p).rgb.r)
            << text;
    ASSERT_TRUE(drt->objects.at(1).texture->normal);
    EXPECT_DOUBLE_EQ(drt->objects.at(1).texture->normal->amount, 1.5);
    EXPECT_EQ(drt->objects.at(1).texture->normal->densityFile->interpolation, DensityFile::Interpolation::Trilinear);
}

TEST(DensityFile, ErrorsAreLocated) {
    const std::string dir = test::tempDir();
    measuredFile(dir);
    test::writeFile(dir + "/short.df3", "\x01\x02");
    writeDf3(dir + "/odd.df3", 2, 2, 2, {1, 2, 3}, 1); // 3 bytes for 8 voxels
    writeDf3(dir + "/huge.df3", 2048, 2048, 2048, {}, 1);
    struct Case {
        const char* name;
        std::string text;
        const char* message;
    };
    const std::vector<Case> cases = {
        {"s.pov", "plane { z, 0 pigment { density_file \"w.df3\" } }", "s.pov:1:37: error: expected 'df3' (the file's format) after 'density_file'"},
        {"s.pov", "plane { z, 0 pigment { density_file df3 \"none.df3\" } }", "s.pov:1:41: error: cannot find density file 'none.df3'"},
        {"s.drt", "plane { z, 0 pigment { density_file df3 \"w.df3\" interpolate 3 } }", "s.drt:1:61: error: density_file interpolate must be 0 (none), 1 (trilinear) or 2 (tricubic), got 3"},
        {"s.pov", "plane { z, 0 pigment { density_file df3 \"short.df3\" } }", "s.pov:1:41: error: '"},
        {"s.pov", "plane { z, 0 pigment { density_file df3 \"odd.df3\" } }", "is not a df3 file: 3 bytes after the header for 2 x 2 x 2 voxels"},
        {"s.pov", "plane { z, 0 normal { density_file df3 \"odd.df3\" } }", "s.pov:1:40: error:"},
        {"s.pov", "plane { z, 0 pigment { density_file df3 \"huge.df3\" } }", "is not a df3 file: 0 bytes after the header for 2048 x 2048 x 2048 voxels"},
    };
    for (const Case& c : cases) {
        Diagnostics diags;
        EXPECT_FALSE(loadResolved(c.text, c.name, dir, diags)) << c.text;
        EXPECT_NE(diags.formatAll().find(c.message), std::string::npos) << c.text << "\n" << diags.formatAll();
    }
    // In a .pov scene an unknown interpolation is a warning, and none is used.
    Diagnostics lenient;
    const auto s = loadResolved("plane { z, 0 pigment { density_file df3 \"w.df3\" interpolate 7 } }", "s.pov", dir, lenient);
    ASSERT_TRUE(s) << lenient.formatAll();
    EXPECT_EQ(s->objects.at(0).texture->pigment.densityFile->interpolation, DensityFile::Interpolation::None);
    EXPECT_NE(lenient.formatAll().find("interpolate 7 is not known"), std::string::npos) << lenient.formatAll();
}

TEST(DensityFile, AFileOverTheMemoryLimitIsRefusedBeforeItIsRead) {
    const std::string dir = test::tempDir();
    writeDf3(dir + "/big.df3", 512, 512, 16, std::vector<uint32_t>(512 * 512 * 16, 7), 1); // 4M voxels, 16 MB as floats
    Diagnostics diags;
    Limits limits = diags.limits();
    limits.memoryMB = 8;
    diags.setLimits(limits);
    EXPECT_FALSE(loadResolved("plane { z, 0 pigment { density_file df3 \"big.df3\" } }", "s.pov", dir, diags));
    EXPECT_NE(diags.formatAll().find("512 x 512 x 16 voxels, 16 MB in memory: over the limit of 8 MB"), std::string::npos)
        << diags.formatAll();
}

} // namespace
} // namespace drt
