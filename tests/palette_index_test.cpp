// POV-Ray's palette indices (image/palette_png.cpp, assets/image_map_load.cpp,
// render/image_pattern.h): the per-index `filter i, f` / `transmit i, t` of an
// image_map and the `material_map` texture, in both dialects; the red value as
// the index of an image without a palette; the .drt writer; located errors.
// Every colour checked is a closed form: ambient-only textures seen head-on
// by an orthographic camera, one sample in the middle of each texel.
#include "assets/assets.h"
#include "image/image.h"
#include "image/srgb.h"
#include "lang/load.h"
#include "lang/writer.h"
#include "pov/load.h"
#include "render/render.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <png.h>

#include <cstdio>
#include <filesystem>

namespace drt {
namespace {

// Writes a colour-mapped PNG of `bits` bits per index (1, 2, 4 or 8) with the
// given palette (RGB triples) and indices (rows top first).
std::string writePalettePng(const std::string& path, int w, int h, int bits, const std::vector<uint8_t>& palette,
                            const std::vector<uint8_t>& indices) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    EXPECT_TRUE(f);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        ADD_FAILURE() << "libpng could not write " << path;
        png_destroy_write_struct(&png, &info);
        std::fclose(f);
        return path;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, png_uint_32(w), png_uint_32(h), bits, PNG_COLOR_TYPE_PALETTE, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    std::vector<png_color> colors;
    for (size_t i = 0; i + 2 < palette.size(); i += 3) colors.push_back({palette[i], palette[i + 1], palette[i + 2]});
    png_set_PLTE(png, info, colors.data(), int(colors.size()));
    png_write_info(png, info);
    png_set_packing(png); // one byte per index in, `bits` per index in the file
    for (int y = 0; y < h; ++y) png_write_row(png, &indices[size_t(y) * size_t(w)]);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
    return path;
}

std::string freshDir(const std::string& name) {
    const std::string dir = test::tempDir() + "/palette-" + name;
    std::filesystem::create_directories(dir);
    return dir;
}

// 4 x 1 texels, palette of 4 greys in a scrambled order, so that an index is
// not its colour: indices 2, 0, 3, 1 from left to right.
std::string stripPng(const std::string& dir, int bits = 4) {
    return writePalettePng(dir + "/strip.png", 4, 1, bits, {10, 10, 10, 200, 200, 200, 60, 60, 60, 250, 250, 250},
                           {2, 0, 3, 1});
}

RenderOptions stripOptions() {
    RenderOptions o = test::tinyRenderOptions();
    o.width = 4;
    o.height = 1;
    o.seed = 1;
    return o;
}

// An orthographic camera over the unit square (one pixel per texel, x 0..1,
// y 0..0.25), the plane z = 0 holding `texture` (POV-Ray's unit square is the map).
std::string stripScene(const std::string& texture, bool pov) {
    std::string s = pov ? "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n" : "";
    s += "camera { orthographic location <0.5, 0.125, -5> look_at <0.5, 0.125, 0> right x up 0.25*y }\n";
    s += "background { color rgb <0, 0, 1> }\n";
    s += "plane { z, 0 " + texture + " }\n";
    return s;
}

std::optional<Scene> load(const std::string& text, bool pov, const std::string& dir, Diagnostics& diags) {
    std::optional<Scene> s = pov ? loadPovSceneText(text, "s.pov", diags, PovOptions{}, dir)
                                 : loadSceneText(text, "s.drt", diags, dir);
    if (s && !resolveAssets(*s, diags)) return std::nullopt;
    return s;
}

std::vector<Color> renderStrip(const Scene& scene) {
    const Image image = render(scene, stripOptions()).color;
    std::vector<Color> out;
    for (int x = 0; x < image.width; ++x) out.push_back({image.at(x, 0, 0), image.at(x, 0, 1), image.at(x, 0, 2)});
    return out;
}

std::vector<Color> renderStrip(const std::string& text, bool pov, const std::string& dir) {
    Diagnostics diags;
    const std::optional<Scene> s = load(text, pov, dir, diags);
    EXPECT_TRUE(s) << diags.formatAll();
    if (!s) return {};
    return renderStrip(*s);
}

void expectColors(const std::vector<Color>& got, const std::vector<Color>& want, const std::string& what) {
    ASSERT_EQ(got.size(), want.size()) << what;
    for (size_t i = 0; i < got.size(); ++i) {
        EXPECT_NEAR(got[i].r, want[i].r, 1e-5) << what << ", texel " << i;
        EXPECT_NEAR(got[i].g, want[i].g, 1e-5) << what << ", texel " << i;
        EXPECT_NEAR(got[i].b, want[i].b, 1e-5) << what << ", texel " << i;
    }
}

const std::string kRed = "texture { pigment { color rgb <1, 0, 0> } finish { ambient 1 diffuse 0 } }";
const std::string kGreen = "texture { pigment { color rgb <0, 1, 0> } finish { ambient 1 diffuse 0 } }";
const std::string kGrey = "texture { pigment { color rgb 0.5 } finish { ambient 1 diffuse 0 } }";

TEST(PaletteIndex, IndicesOfAPalettePngAreReadAsStoredAtEveryBitDepth) {
    const std::string dir = freshDir("depths");
    for (int bits : {2, 4, 8}) {
        const std::string path = stripPng(dir, bits);
        std::vector<uint8_t> indices;
        EXPECT_EQ(readPaletteIndices(path, 4, 1, indices), "");
        EXPECT_EQ(indices, (std::vector<uint8_t>{2, 0, 3, 1})) << bits << " bits";
    }
    // Not a palette image: no indices, no error.
    const std::string rgb = dir + "/rgb.png";
    Image image(2, 1, 3);
    ASSERT_EQ(writeImage(rgb, image), "");
    std::vector<uint8_t> indices{7};
    EXPECT_EQ(readPaletteIndices(rgb, 2, 1, indices), "");
    EXPECT_TRUE(indices.empty());
    // A size other than the colour image's is refused.
    EXPECT_NE(readPaletteIndices(stripPng(dir), 5, 1, indices), "");
}

TEST(PaletteIndex, MaterialMapPicksTheTextureOfEachTexelsIndexModuloTheirCount) {
    const std::string dir = freshDir("material");
    stripPng(dir);
    for (bool pov : {true, false}) {
        const std::string file = pov ? "png \"strip.png\"" : "\"strip.png\"";
        // Three textures: indices 2, 0, 3, 1 pick grey, red, red (3 mod 3 = 0), green.
        const std::vector<Color> got =
            renderStrip(stripScene("texture { material_map { " + file + " " + kRed + " " + kGreen + " " + kGrey +
                                       " } }",
                                   pov),
                        pov, dir);
        expectColors(got, {Color(0.5), Color(1, 0, 0), Color(1, 0, 0), Color(0, 1, 0)},
                     pov ? "POV-Ray dialect" : ".drt dialect");
    }
}

TEST(PaletteIndex, WithoutAPaletteTheRedValueIsTheIndex) {
    const std::string dir = freshDir("red");
    // Red values 0, 1, 2, 5 (of 255): with two textures, 0, 1, 0, 1.
    Image image(4, 1, 3);
    const float reds[4] = {0, 1, 2, 5};
    for (int x = 0; x < 4; ++x) image.at(x, 0, 0) = float(srgbDecode(reds[x] / 255.0));
    ASSERT_EQ(writeImage(dir + "/reds.png", image), "");
    const std::vector<Color> got =
        renderStrip(stripScene("texture { material_map { png \"reds.png\" " + kRed + " " + kGreen + " } }", true),
                    true, dir);
    expectColors(got, {Color(1, 0, 0), Color(0, 1, 0), Color(1, 0, 0), Color(0, 1, 0)}, "red value as index");
}

TEST(PaletteIndex, OffAOnceMapTheFirstTextureShows) {
    const std::string dir = freshDir("once");
    stripPng(dir);
    // The map scaled to the left half: the right half is off the map.
    const std::vector<Color> got = renderStrip(
        stripScene("texture { material_map { png \"strip.png\" once " + kGreen + " " + kGrey + " } scale <0.5, 1, 1> }",
                   true),
        true, dir);
    // Left half: texels 0 and 2 of the map (indices 2, 3 -> 0, 1); right half: texture 0.
    expectColors(got, {Color(0, 1, 0), Color(0.5), Color(0, 1, 0), Color(0, 1, 0)}, "once");
}

TEST(PaletteIndex, PerIndexTransmitAndFilterApplyToTheirIndexOnly) {
    const std::string dir = freshDir("amounts");
    stripPng(dir);
    const double g[4] = {60 / 255.0, 10 / 255.0, 250 / 255.0, 200 / 255.0}; // sRGB-coded greys of indices 2, 0, 3, 1
    std::vector<Color> grey;
    for (double v : g) grey.push_back(Color(srgbDecode(v)));
    for (bool pov : {true, false}) {
        const std::string file = pov ? "png \"strip.png\"" : "\"strip.png\"";
        // Index 3 (third texel) fully transmits: the blue background shows there.
        std::vector<Color> want = grey;
        want[2] = Color(0, 0, 1);
        expectColors(renderStrip(stripScene("pigment { image_map { " + file + " transmit 3, 1 } } finish { ambient 1 "
                                            "diffuse 0 }",
                                            pov),
                                 pov, dir),
                     want, pov ? "transmit, POV-Ray" : "transmit, .drt");
        // Index 3 (third texel) filters fully: the background through its own grey (bright enough for the
        // filtered ray to pass adc_bailout).
        want = grey;
        want[2] = Color(0, 0, grey[2].b);
        expectColors(renderStrip(stripScene("pigment { image_map { " + file + " filter 3, 1 } } finish { ambient 1 "
                                            "diffuse 0 }",
                                            pov),
                                 pov, dir),
                     want, pov ? "filter, POV-Ray" : "filter, .drt");
    }
}

TEST(PaletteIndex, TheDrtWriterKeepsMaterialMapsAndPerIndexAmounts) {
    const std::string dir = freshDir("writer");
    stripPng(dir);
    const std::string text =
        stripScene("texture { material_map { png \"strip.png\" " + kRed + " " + kGreen + " " + kGrey + " } }", true) +
        "plane { z, 1 pigment { image_map { png \"strip.png\" transmit 3, 1 filter 0, 0.5 } } }\n";
    Diagnostics diags;
    const std::optional<Scene> pov = load(text, true, dir, diags);
    ASSERT_TRUE(pov) << diags.formatAll();
    const std::string drt = writeDrtScene(*pov);
    EXPECT_NE(drt.find("material_map {"), std::string::npos) << drt;
    EXPECT_NE(drt.find("transmit 3, 1"), std::string::npos) << drt;
    EXPECT_NE(drt.find("filter 0, 0.5"), std::string::npos) << drt;
    Diagnostics again;
    const std::optional<Scene> back = load(drt, false, dir, again);
    ASSERT_TRUE(back) << again.formatAll() << "\n" << drt;
    expectColors(renderStrip(*back), renderStrip(*pov), "round trip");
}

TEST(PaletteIndex, BadIndicesAndEmptyMaterialMapsAreLocatedErrors) {
    const std::string dir = freshDir("errors");
    stripPng(dir);
    {
        Diagnostics diags;
        EXPECT_FALSE(load("sphere { 0, 1 pigment { image_map { png \"strip.png\" transmit 256, 1 } } }", true, dir,
                          diags));
        test::expectErrorAt(diags, "s.pov", 1, 62, "a palette index runs from 0 to 255, got 256");
    }
    {
        Diagnostics diags; // .drt wants the comma
        EXPECT_FALSE(load("sphere { 0, 1 pigment { image_map { \"strip.png\" filter 2 0.5 } } }", false, dir, diags));
        ASSERT_TRUE(diags.hasErrors());
        EXPECT_EQ(diags.all().front().loc.line, 1);
        EXPECT_EQ(diags.all().front().loc.column, 58);
    }
    {
        Diagnostics diags;
        EXPECT_FALSE(load("sphere { 0, 1 texture { material_map { png \"strip.png\" } } }", true, dir, diags));
        test::expectErrorAt(diags, "s.pov", 1, 25, "a material_map needs at least one texture");
    }
    {
        // Per-index amounts on an image without a palette: a warning at the file name, and the image as it is.
        Image image(1, 1, 3);
        ASSERT_EQ(writeImage(dir + "/plain.png", image), "");
        Diagnostics diags;
        EXPECT_TRUE(load("sphere { 0, 1 pigment { image_map { png \"plain.png\" transmit 0, 1 } } }", true, dir, diags));
        bool warned = false;
        for (const Diagnostic& d : diags.all())
            warned = warned || (d.severity == Severity::Warning && d.loc.line == 1 && d.loc.column == 41 &&
                                d.message.find("has no palette") != std::string::npos);
        EXPECT_TRUE(warned) << diags.formatAll();
    }
}

} // namespace
} // namespace drt
