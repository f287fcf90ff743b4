// Cross-checks against POV-Ray 3.7 itself (docs/pov-crosscheck.md): POV-Ray's own focal-blur
// and area-light sample scenes, rendered by `povray` and by drt (through the
// POV front end and the .drt writer, as `drt convert` does) at 160x120, must
// agree within thresholds that a wrong camera, lens, light placement or
// shading term exceeds. Negative controls below show that they do.
//
// Label "crosscheck" (its own executable; povray takes a few seconds a scene).
// With DRT_CROSSCHECK_OUTPUT=DIR the images (drt, POV-Ray, error heatmap) and
// the figures are also written to DIR (tests/pov_crosscheck/regenerate.sh
// builds docs/pov-crosscheck.md from them).
#include "compare/compare.h"
#include "image/image.h"
#include "lang/load.h"
#include "lang/writer.h"
#include "pov/load.h"
#include "render/render.h"
#include "pov_crosscheck/run_renderers.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

namespace drt {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 160, kHeight = 120;
const char* const kExamples = "/usr/share/doc/povray/examples";

// ------------------------------------------------------------ thresholds
// Errors are drt - POV-Ray on linear values, averaged over the channels.
// Noise (POV-Ray's jittered area lights and adaptive focal blur, drt's
// samples) is zero-mean and averages out over the image and mostly over a
// tile; what is left is anti-aliasing along edges, where the two renderers
// sample differently. A wrong camera or lens moves every edge, a wrong light
// moves shadows and highlights, a wrong shading term biases whole surfaces:
// each of them shifts the means below well past these bounds (the negative
// controls measure by how much).
struct Thresholds {
    double meanAbsoluteError = 0.01; // over the image
    double meanSignedError = 0.003;  // |bias| over the image
    double tileSignedError = 0.025;  // largest |bias| of an 8x8 tile
};

struct Figures {
    double meanAbsoluteError = 0;
    double meanSignedError = 0;
    double tileSignedError = 0; // largest |mean signed error| of an 8x8 tile
    int worstTileX = 0, worstTileY = 0;
    double psnr = 0;
    bool within(const Thresholds& t) const {
        return meanAbsoluteError <= t.meanAbsoluteError && std::fabs(meanSignedError) <= t.meanSignedError &&
               tileSignedError <= t.tileSignedError;
    }
};

std::ostream& operator<<(std::ostream& os, const Figures& f) {
    return os << "MAE " << f.meanAbsoluteError << ", mean signed error " << f.meanSignedError
              << ", worst 8x8 tile bias " << f.tileSignedError << " at (" << f.worstTileX << ", "
              << f.worstTileY << "), PSNR " << f.psnr << " dB";
}

Figures measure(const Image& drt, const Image& pov) {
    const CompareResult r = compareImages(drt, pov);
    Figures f;
    f.meanAbsoluteError = r.meanAbsoluteError;
    f.meanSignedError = r.meanSignedError;
    f.psnr = r.psnr;
    const int tile = 8;
    for (int ty = 0; ty + tile <= drt.height; ty += tile)
        for (int tx = 0; tx + tile <= drt.width; tx += tile) {
            double sum = 0;
            for (int y = ty; y < ty + tile; ++y)
                for (int x = tx; x < tx + tile; ++x)
                    for (int c = 0; c < 3; ++c)
                        sum += double(drt.at(x, y, c)) - double(pov.at(x, y, c));
            const double bias = std::fabs(sum / (tile * tile * 3));
            if (bias > f.tileSignedError)
                f.tileSignedError = bias, f.worstTileX = tx, f.worstTileY = ty;
        }
    return f;
}

// ------------------------------------------------------------ running the renderers

using crosscheck::povrayInstalled;

struct CrossCheckScene {
    std::string name;                // e.g. "focalblur"
    std::string file;                // under kExamples, or under the source tree with `ownScene`
    std::vector<std::string> extras; // files the scene includes from its own folder
    int drtSamples;                  // per pixel
    bool ownScene = false;           // a scene of drt's own, in tests/pov_crosscheck/
};

const std::vector<CrossCheckScene>& scenes() {
    static const std::vector<CrossCheckScene> list{
        {"focalblur", "camera/focalblur.pov", {"camera/camera-context.inc"}, 120},
        {"arealit1", "lights/arealit1.pov", {}, 4},
        {"arealit2", "lights/arealit2.pov", {}, 4},
        {"foglyr2", "interior/foglyr2.pov", {}, 4}, // two turbulent ground fogs
        {"ttf1", "objects/ttf1.pov", {}, 4},        // assumed_gamma 1.9: shading in the working space
        {"orthographic", "camera/orthographic.pov", {"camera/camera-context.inc"}, 4},
        {"ultra_wide_angle", "camera/ultra_wide_angle.pov", {"camera/camera-context.inc"}, 4},
        {"panoramic", "camera/panoramic.pov", {"camera/camera-context.inc"}, 4},
        {"cylinder1", "camera/cylinder1.pov", {"camera/camera-context.inc"}, 4},
        {"cylinder2", "camera/cylinder2.pov", {"camera/camera-context.inc"}, 4},
        {"cylinder3", "camera/cylinder3.pov", {"camera/camera-context.inc"}, 4},
        {"cylinder4", "camera/cylinder4.pov", {"camera/camera-context.inc"}, 4},
        {"spherical", "camera/spherical.pov", {"camera/camera-context.inc"}, 4},
        {"soft", "lights/soft.pov", {}, 4}, // clipped_by
        {"fisheye", "camera/fisheye.pov", {"camera/camera-context.inc"}, 4},
        // Layered textures, texture_map, tiles, pigment_map, average (drt's own scene).
        {"layered_textures", "tests/pov_crosscheck/layered_textures.pov", {}, 16, true},
    };
    return list;
}

const CrossCheckScene& sceneNamed(const std::string& name) {
    for (const CrossCheckScene& s : scenes())
        if (s.name == name) return s;
    throw std::out_of_range("no cross-check scene " + name);
}

// A scene copied to a fresh folder, rendered there by POV-Ray.
struct Prepared {
    std::string dir;
    std::string povPath;
    Image pov;
};

Prepared prepare(const CrossCheckScene& s) {
    Prepared p;
    if (!povrayInstalled()) {
        ADD_FAILURE()
            << "`povray` is not installed (the set-up script installs Debian's povray, povray-examples "
               "and povray-includes); the POV-Ray cross-checks cannot run";
        return p;
    }
    const fs::path source = s.ownScene ? fs::path(test::sourcePath(s.file)) : fs::path(kExamples) / s.file;
    if (!fs::exists(source)) {
        ADD_FAILURE() << source << " is missing: install Debian's povray-examples package";
        return p;
    }
    p.dir = test::tempDir();
    p.povPath = (fs::path(p.dir) / source.filename()).string();
    fs::copy_file(source, p.povPath);
    for (const std::string& extra : s.extras)
        fs::copy_file(fs::path(kExamples) / extra, fs::path(p.dir) / fs::path(extra).filename());
    crosscheck::renderPovRay(p.dir, source.filename().string(), kWidth, kHeight, p.pov);
    return p;
}

// The scene as `drt convert` turns it into .drt, loaded back.
std::optional<Scene> convertedScene(const std::string& povPath) {
    Diagnostics diags;
    const std::optional<Scene> scene = loadPovSceneFile(povPath, diags);
    EXPECT_TRUE(scene) << diags.formatAll();
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    if (!scene)
        return std::nullopt;
    EXPECT_TRUE(drtInexpressible(*scene).empty());
    Diagnostics again;
    std::optional<Scene> reloaded =
        loadSceneText(writeDrtScene(test::withAssets(*scene)), "converted.drt", again);
    EXPECT_TRUE(reloaded) << again.formatAll();
    if (!reloaded) return std::nullopt;
    return test::withAssets(std::move(*reloaded));
}

Image renderDrt(const Scene& scene, int samples) {
    return crosscheck::renderDrtClipped(scene, kWidth, kHeight, samples);
}

// Writes the images and a figures line when DRT_CROSSCHECK_OUTPUT is set.
void publish(const std::string& name, const Image& drt, const Image& pov, const Figures& f, int samples) {
    const char* dir = std::getenv("DRT_CROSSCHECK_OUTPUT");
    if (!dir || !*dir)
        return;
    fs::create_directories(dir);
    const std::string base = (fs::path(dir) / name).string();
    EXPECT_EQ(writeImage(base + "-drt.png", drt), "");
    EXPECT_EQ(writeImage(base + "-pov.png", pov), "");
    // Fixed scale so the heatmaps of all scenes read alike: white is an error of 0.25.
    EXPECT_EQ(writeImage(base + "-diff.png", errorHeatmap(drt, pov, 0.25)), "");
    std::ofstream(base + ".figures") << name << " " << samples << " " << f.meanAbsoluteError << " "
                                     << f.meanSignedError << " " << f.tileSignedError << " " << f.psnr
                                     << "\n";
}

// ------------------------------------------------------------ the cross-checks

class PovCrossCheck : public ::testing::TestWithParam<CrossCheckScene> {};

TEST_P(PovCrossCheck, DrtMatchesPovRay) {
    const CrossCheckScene& s = GetParam();
    const Prepared p = prepare(s);
    if (p.pov.pixels.empty())
        return; // the failure is recorded
    const std::optional<Scene> scene = convertedScene(p.povPath);
    ASSERT_TRUE(scene);
    const Image drt = renderDrt(*scene, s.drtSamples);
    const Figures f = measure(drt, p.pov);
    publish(s.name, drt, p.pov, f, s.drtSamples);
    EXPECT_TRUE(f.within(Thresholds{})) << s.name << ": " << f;
    std::cout << "[ figures  ] " << s.name << ": " << f << "\n";
}

INSTANTIATE_TEST_SUITE_P(PovRaySamples, PovCrossCheck, ::testing::ValuesIn(scenes()),
                         [](const auto& info) { return info.param.name; });

// ------------------------------------------------------------ negative controls
// Each control breaks one thing in the converted scene and checks that the
// thresholds catch it against the same POV-Ray image.

// The control renders with the scene's own sample count, so noise alone
// would not make it fail.
Figures brokenFigures(const CrossCheckScene& s, const std::string& what,
                      const std::function<void(Scene&)>& breakIt) {
    const Prepared p = prepare(s);
    if (p.pov.pixels.empty())
        return {};
    std::optional<Scene> scene = convertedScene(p.povPath);
    if (!scene)
        return {};
    breakIt(*scene);
    const Figures f = measure(renderDrt(*scene, s.drtSamples), p.pov);
    std::cout << "[ control  ] " << what << " (" << s.name << "): " << f << "\n";
    return f;
}

TEST(PovCrossCheckControls, AWrongCameraAngleFails) {
    const Figures f = brokenFigures(scenes()[0], "camera angle 10% wider",
                                    [](Scene& scene) { *scene.camera.angle *= 1.1; });
    EXPECT_FALSE(f.within(Thresholds{})) << f;
}

TEST(PovCrossCheckControls, AWrongLensFails) {
    // POV-Ray's lens radius is aperture/4; aperture/2 would double the blur.
    const Figures f = brokenFigures(scenes()[0], "lens radius aperture/2 instead of aperture/4",
                                    [](Scene& scene) { scene.camera.aperture *= 2; });
    EXPECT_FALSE(f.within(Thresholds{})) << f;
}

TEST(PovCrossCheckControls, AMovedLightFails) {
    const Figures f = brokenFigures(scenes()[1], "middle light moved 4 units",
                                    [](Scene& scene) { scene.lights.at(1).position += Vec3(4, 0, 0); });
    EXPECT_FALSE(f.within(Thresholds{})) << f;
}

TEST(PovCrossCheckControls, AWrongAreaLightSizeFails) {
    // The left light of arealit2 (4 x 4 units) made 16 x 16.
    const Figures f = brokenFigures(scenes()[2], "4x4 area light made 16x16", [](Scene& scene) {
        AreaLight& area = *scene.lights.at(0).area;
        area.axis1 = area.axis1 * 4;
        area.axis2 = area.axis2 * 4;
    });
    EXPECT_FALSE(f.within(Thresholds{})) << f;
}

TEST(PovCrossCheckControls, AMissingShadingTermFails) {
    // Drop the highlight (Blinn specular) of every object.
    const Figures f = brokenFigures(scenes()[1], "specular highlights dropped", [](Scene& scene) {
        for (Object& o : scene.objects)
            o.texture.edit().finish.specular = 0;
    });
    EXPECT_FALSE(f.within(Thresholds{})) << f;
}

// ------------------------------------------------------------ text and prism outlines
// Flat white text and prisms (ambient only) on black: the images differ only
// where the outlines differ, so this checks glyph layout (advances, kerning,
// offset, em scale) and spline outlines against POV-Ray's own. A text moved
// by 0.02 em must fail.

const char* const kOutlineScene = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <2.2, 0.35, -6> look_at <2.2, 0.35, 0> angle 45 }
background { color rgb 0 }
#declare White = texture { pigment { color rgb 1 } finish { ambient 1 diffuse 0 } }
text { ttf "timrom.ttf" "Quick AV fox" 0.3, <0.02, 0, 0> texture { White } scale 0.8 }
prism { cubic_spline -0.5, 0.5, 8, <0.6, 0.8>, <1, 0>, <0.3, 0.7>, <-0.8, 0.5>, <-0.5, -0.6>, <1, 0>,
  <0.3, 0.7>, <-0.8, 0.5> rotate -90*x scale 0.6 translate <3, 1.5, 0> texture { White } }
prism { conic_sweep linear_spline 0.5, 1, 4, <0, -1>, <1, 1>, <-1, 1>, <0, -1>
  rotate -90*x translate <0.8, 1.3, 0> texture { White } }
)";

Figures outlineFigures(double textShift) {
    if (!povrayInstalled()) {
        ADD_FAILURE() << "`povray` is not installed; the POV-Ray cross-checks cannot run";
        return {};
    }
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/outlines.pov", kOutlineScene);
    Image pov;
    crosscheck::renderPovRay(dir, "outlines.pov", kWidth, kHeight, pov);
    std::optional<Scene> scene = convertedScene(dir + "/outlines.pov");
    if (!scene || pov.pixels.empty())
        return {};
    for (Object& o : scene->objects)
        if (const Extrusion* e = std::get_if<Extrusion>(&o.shape); e && e->text)
            o.transform = o.transform.then(Transform::translate({textShift, 0, 0}));
    const Image drt = renderDrt(*scene, 16);
    const Figures f = measure(drt, pov);
    if (textShift == 0)
        publish("outlines", drt, pov, f, 16);
    std::cout << "[ figures  ] outlines (text moved by " << textShift << "): " << f << "\n";
    return f;
}

TEST(PovCrossCheckOutlines, TextAndPrismOutlinesMatchPovRay) {
    EXPECT_TRUE(outlineFigures(0).within(Thresholds{}));
}

TEST(PovCrossCheckControls, TextMovedByAFiftiethOfAnEmFails) {
    EXPECT_FALSE(outlineFigures(0.02 * 0.8).within(Thresholds{}));
}

TEST(PovCrossCheckControls, SwappedTextureLayersFail) {
    // Every layered texture (the tiles' entries included) with its layers in reverse order.
    const CrossCheckScene& layered = sceneNamed("layered_textures");
    ASSERT_EQ(layered.name, "layered_textures");
    std::function<void(Texture&)> reverseLayers = [&](Texture& t) {
        for (Texture::MapEntry& e : t.map)
            reverseLayers(e.texture);
        if (t.layersAbove.empty())
            return;
        std::vector<Texture> stack{t};
        stack[0].layersAbove.clear();
        for (const Texture& layer : t.layersAbove)
            stack.push_back(layer);
        Texture reversed = stack.back();
        for (size_t i = stack.size() - 1; i-- > 0;)
            reversed.layersAbove.push_back(stack[i]);
        t = reversed;
    };
    const Figures f = brokenFigures(layered, "texture layers in reverse order", [&](Scene& scene) {
        for (Object& o : scene.objects)
            reverseLayers(o.texture.edit());
    });
    EXPECT_FALSE(f.within(Thresholds{})) << f;
}

TEST(PovCrossCheckControls, FilterTreatedAsTransmitFails) {
    // Layers that filter (P f) as if they only transmitted (f): the orange bands lose their colour.
    const Figures f = brokenFigures(sceneNamed("layered_textures"), "layer filter treated as transmit", [](Scene& scene) {
        std::function<void(Texture&)> unfilter = [&](Texture& t) {
            for (Texture::MapEntry& e : t.map)
                unfilter(e.texture);
            for (Texture& layer : t.layersAbove) {
                std::vector<ColorMapEntry>& map = layer.pigment.colorMap;
                for (ColorMapEntry& c : map)
                    c.color.transmit += c.color.filter, c.color.filter = 0;
                unfilter(layer);
            }
        };
        for (Object& o : scene.objects)
            unfilter(o.texture.edit());
    });
    EXPECT_FALSE(f.within(Thresholds{})) << f;
}

} // namespace
} // namespace drt
