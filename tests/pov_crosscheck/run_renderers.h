// Running POV-Ray 3.7 and drt the same way for every cross-check: POV-Ray with
// +A0.3 (its adaptive anti-aliasing), -D (no display) and +FN (PNG); drt at a
// fixed sample count with seed 1, its linear floats clipped to [0, 1] as
// POV-Ray's 8-bit PNG (and drt's own) would hold them.
#pragma once

#include "image/image.h"
#include "render/render.h"
#include "scene/scene.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>

namespace drt::crosscheck {

inline bool povrayInstalled() { return std::system("command -v povray >/dev/null 2>&1") == 0; }

// Renders `dir`/`file` with povray into `dir`/pov.png and reads it; false
// (with a test failure naming POV-Ray's log) if either step fails.
inline bool renderPovRay(const std::string& dir, const std::string& file, int width, int height, Image& out) {
    const std::string command = "cd '" + dir + "' && povray +I" + file + " +Opov.png +W" + std::to_string(width) +
                                " +H" + std::to_string(height) + " -D +A0.3 +FN >povray.log 2>&1";
    if (std::system(command.c_str()) != 0) {
        ADD_FAILURE() << "povray failed:\n" << test::readFile(dir + "/povray.log");
        return false;
    }
    const std::string problem = readImage(dir + "/pov.png", out);
    EXPECT_EQ(problem, "");
    return problem.empty();
}

inline Image renderDrtClipped(const Scene& scene, int width, int height, int samples) {
    RenderOptions options = resolveRenderOptions(scene.render);
    options.width = width;
    options.height = height;
    options.samplesPerPixel = samples;
    options.adaptive = false;
    options.seed = 1;
    Image image = render(scene, options).color;
    for (float& v : image.pixels) v = std::clamp(v, 0.0f, 1.0f);
    return image;
}

} // namespace drt::crosscheck
