// POV-Ray fidelity: small scenes of drt's own (tests/pov_crosscheck/fidelity/),
// each built around one rule drt once got wrong, rendered by `povray` and by
// drt (the .pov read directly) at 160x120 and compared by the wide
// cross-check's figure (pov_crosscheck/wide_figure.h: mean absolute sRGB
// difference after 4x4 downsampling). Each threshold sits well below what the
// old rule gave (quoted per scene) and above the noise and anti-aliasing
// differences of a correct render.
//
// Label "crosscheck" (runs in the drt_crosscheck_tests executable).
#include "image/image.h"
#include "pov/load.h"
#include "pov_crosscheck/run_renderers.h"
#include "pov_crosscheck/wide_figure.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace drt {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 160, kHeight = 120, kSamples = 16;

struct FidelityScene {
    const char* name;  // tests/pov_crosscheck/fidelity/NAME.pov
    double threshold;  // largest figure that passes
};

// The figure of the fix's scene before the fix, for the record:
//   camera_along_sky 0.600 (a camera straight above look_at kept its old direction and saw nothing)
//   checker_edge     0.366 (cell tolerance 1e-3: the floor just below y = 0 took the cells above)
//   fractal_patterns (failed: 'interior' in a pigment was an error, and mandel, julia and magnet were the
//                    average colour of their maps; 0.004 with them)
//   function_pattern (function patterns were the average colour of their maps; 0.0006 with them)
//   isosurface       (isosurfaces were left out; 0.0008 with them)
//   julia_fractal    (julia fractals were left out; 0.0015 with them)
//   interior_fade    0.028 (fade_power 1000+ taken as a power law; shadow rays not faded)
//   light_group      (failed: 'light_group' was an unknown keyword)
//   leopard_normal   0.061 (normals tilted by the world-space gradient: steep at small scales)
//   normal_gradient  0.077 (gradient normals were ignored)
//   parallel_light   0.108 (parallel lights were point lights)
//   place_patterns   0.126 (planar, cylindrical and boxed were the average colour of their maps)
//   projected_through 0.370 (projected_through was ignored: an ordinary light, shadowed by the placed shape)
//   quilted          0.054 (quilted was the average colour of its map; its normal was left out)
//   radiosity        0.167 (radiosity was left out)
//   slope_map        0.061 (a normal with a slope_map was left out; 0.039 with slopes per unit of
//                    pattern value instead of per entry interval)
//   waves            0.065 (invented wave sources and weights)
const FidelityScene kScenes[] = {
    {"camera_along_sky", 0.01},
    {"checker_edge", 0.01},
    {"fractal_patterns", 0.012},
    {"function_pattern", 0.005},
    {"interior_fade", 0.012},
    {"isosurface", 0.005},
    {"julia_fractal", 0.006},
    {"light_group", 0.01},
    {"leopard_normal", 0.015},
    {"normal_gradient", 0.02},
    {"parallel_light", 0.01},
    {"place_patterns", 0.005},
    {"projected_through", 0.005},
    {"quilted", 0.012},
    {"radiosity", 0.015},
    {"slope_map", 0.02},
    {"waves", 0.025},
};

bool renderDrt(const std::string& povPath, Image& out) {
    Diagnostics diags;
    std::optional<Scene> scene = loadPovSceneFile(povPath, diags);
    EXPECT_TRUE(scene) << diags.formatAll();
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    if (!scene) return false;
    out = crosscheck::renderDrtClipped(test::withAssets(std::move(*scene)), kWidth, kHeight, kSamples);
    return true;
}

class PovFidelity : public ::testing::TestWithParam<FidelityScene> {};

TEST_P(PovFidelity, AgreesWithPovRay) {
    const FidelityScene& s = GetParam();
    ASSERT_TRUE(crosscheck::povrayInstalled()) << "`povray` is not installed (the set-up script installs Debian's povray)";
    const std::string dir = test::tempDir();
    const std::string povPath = dir + "/" + s.name + ".pov";
    fs::copy_file(test::sourcePath(std::string("tests/pov_crosscheck/fidelity/") + s.name + ".pov"), povPath);
    Image pov, drt;
    ASSERT_TRUE(crosscheck::renderPovRay(dir, fs::path(povPath).filename().string(), kWidth, kHeight, pov));
    ASSERT_TRUE(renderDrt(povPath, drt));
    const double figure = wide::meanAbsoluteSrgbDifference(drt, pov);
    std::printf("[ fidelity ] %s: %.5f (threshold %.3f)\n", s.name, figure, s.threshold);
    EXPECT_LE(figure, s.threshold);
}

INSTANTIATE_TEST_SUITE_P(Scenes, PovFidelity, ::testing::ValuesIn(kScenes),
                         [](const auto& info) { return std::string(info.param.name); });

} // namespace
} // namespace drt
