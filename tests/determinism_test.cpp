// Determinism: for every example scene, the same scene and seed give
// byte-identical image files whatever the thread count and tile size. Each
// example is rendered small (64x48, 4 spp) through the library and written as
// EXR without metadata (the CLI's metadata holds timings, which differ).
#include "image/image.h"
#include "lang/load.h"
#include "render/render.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fmt/format.h>

namespace fs = std::filesystem;

namespace drt {
namespace {

std::vector<std::string> exampleScenes() {
    std::vector<std::string> scenes;
    for (const auto& entry : fs::directory_iterator(test::sourcePath("examples")))
        if (entry.path().extension() == ".drt") scenes.push_back(entry.path().string());
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

std::string renderToFile(const Scene& scene, int threads, int tileSize, const std::string& path,
                         RenderResult& result) {
    RenderOptions options = resolveRenderOptions(scene, {});
    options.width = 64;
    options.height = 48;
    options.samplesPerPixel = 4;
    options.threads = threads;
    options.tileSize = tileSize;
    result = render(scene, options);
    // OpenEXR stamps the time of writing (capDate) unless the metadata gives one.
    const Metadata fixedDate = {{"DateTime", ""}};
    if (std::string problem = writeImage(path, result.color, fixedDate); !problem.empty()) return problem;
    return writeImage(path + ".var.exr", result.variance, fixedDate);
}

TEST(Determinism, EveryExampleIsByteIdenticalForAnyThreadCountAndTileSize) {
    const std::vector<std::string> scenes = exampleScenes();
    ASSERT_GE(scenes.size(), 3u);
    const std::string dir = test::tempDir();
    // (threads, tile size): the first is the baseline.
    const std::pair<int, int> configurations[] = {{1, 16}, {2, 16}, {8, 16}, {2, 8}, {8, 64}, {2, 5}};
    for (const std::string& scenePath : scenes) {
        SCOPED_TRACE(scenePath);
        Diagnostics diagnostics;
        const std::optional<Scene> scene = loadSceneFile(scenePath, diagnostics);
        ASSERT_TRUE(scene && !diagnostics.hasErrors()) << diagnostics.formatAll();
        const std::string name = fs::path(scenePath).stem().string();
        std::string baseline, baselineVariance;
        RenderResult first;
        for (const auto& [threads, tileSize] : configurations) {
            const std::string path = fmt::format("{}/{}-{}-{}.exr", dir, name, threads, tileSize);
            RenderResult result;
            ASSERT_EQ(renderToFile(*scene, threads, tileSize, path, result), "");
            const std::string bytes = test::readFile(path);
            const std::string varianceBytes = test::readFile(path + ".var.exr");
            ASSERT_GT(bytes.size(), 1000u);
            if (baseline.empty()) {
                baseline = bytes;
                baselineVariance = varianceBytes;
                first = std::move(result);
                continue;
            }
            // The pixels first (a clearer message), then the files.
            EXPECT_TRUE(result.color.pixels == first.color.pixels)
                << "pixels: " << threads << " threads, tile " << tileSize << " differ from 1 thread";
            EXPECT_TRUE(bytes == baseline) << threads << " threads, tile " << tileSize << " differ from 1 thread";
            EXPECT_TRUE(varianceBytes == baselineVariance)
                << "variance: " << threads << " threads, tile " << tileSize << " differ from 1 thread";
        }
    }
    fs::remove_all(dir);
}

} // namespace
} // namespace drt
