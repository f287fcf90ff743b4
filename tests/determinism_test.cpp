// Determinism: for every example scene, the same scene and seed give
// byte-identical image files whatever the thread count and tile size. Each
// example is rendered small (64x48, 4 spp) through the library and written as
// EXR without timings or date (the CLI's metadata holds timings, which differ).
// And a step toward the same pixels on every CPU: triangle hits do not carry
// Embree's float (kernel-dependent) values but are solved again in double.
#include "accel/accel.h"
#include "image/image.h"
#include "lang/load.h"
#include "render/render.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <random>
#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#endif

namespace fs = std::filesystem;

namespace drt {
namespace {

std::vector<std::string> exampleScenes() {
    std::vector<std::string> scenes;
    for (const auto& entry : fs::directory_iterator(test::sourcePath("examples")))
        if (entry.path().extension() == ".drt")
            scenes.push_back(entry.path().string());
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

std::string renderToFile(const Scene& scene, int threads, int tileSize, const std::string& path,
                         RenderResult& result) {
    RenderOptions options = resolveRenderOptions(scene.render);
    options.width = 64;
    options.height = 48;
    options.samplesPerPixel = 4;
    options.threads = threads;
    options.tileSize = tileSize;
    result = render(scene, options);
    // OpenEXR stamps the time of writing (capDate) unless the metadata gives one.
    const Metadata fixedDate = {{"DateTime", ""}};
    if (std::string problem = writeImage(path, result.color, fixedDate); !problem.empty())
        return problem;
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
        std::optional<Scene> scene = loadSceneFile(scenePath, diagnostics);
        ASSERT_TRUE(scene && !diagnostics.hasErrors()) << diagnostics.formatAll();
        scene = test::withAssets(std::move(*scene));
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
            EXPECT_TRUE(bytes == baseline)
                << threads << " threads, tile " << tileSize << " differ from 1 thread";
            EXPECT_TRUE(varianceBytes == baselineVariance)
                << "variance: " << threads << " threads, tile " << tileSize << " differ from 1 thread";
        }
    }
    fs::remove_all(dir);
}

TEST(Determinism, TriangleHitsAreSolvedInDoubleFromTheVertices) {
    // A tilted triangle at awkward coordinates, where float barycentrics and a
    // float t are off by about 1e-7 relative.
    Mesh mesh;
    mesh.vertices = {{0.1, 0.2, 3.3}, {1.7, 0.3, 2.9}, {0.4, 1.9, 3.7}};
    mesh.triangles = {{0, 1, 2}};
    Object object;
    object.shape = mesh;
    Scene scene;
    scene.objects.push_back(object);
    const Accelerator accel(scene);

    const Vec3 &p0 = mesh.vertices[0], &p1 = mesh.vertices[1], &p2 = mesh.vertices[2];
    const Vec3 origin{0.013, -0.021, -1.3};
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> uniform(0.05, 0.45);
    for (int i = 0; i < 200; ++i) {
        const double a = uniform(rng), b = uniform(rng);
        const Vec3 target = (1 - a - b) * p0 + a * p1 + b * p2;
        Ray ray;
        ray.origin = origin;
        ray.direction = target - origin;
        Hit hit;
        ASSERT_TRUE(accel.intersect(ray, hit));
        // The exact answer: t where the ray meets the plane n . (x - p0) = 0.
        const Vec3 n = cross(p1 - p0, p2 - p0);
        const double t = dot(n, p0 - origin) / dot(n, ray.direction);
        EXPECT_NEAR(hit.t, t, 1e-12 * t) << i;
        const Vec3 exact = origin + t * ray.direction;
        EXPECT_LT(length(hit.point - exact), 1e-12) << i;
    }
}

#if defined(__SSE__) || defined(__x86_64__)
// A thread's denormal mode (MXCSR flush-to-zero, denormals-are-zero) must not
// reach the image: a colour of 1e-39 is a denormal float, which FTZ would
// store as 0 on whichever thread happens to run the tile.
TEST(Determinism, ThreadDenormalModeDoesNotReachTheImage) {
    Diagnostics diagnostics;
    const std::optional<Scene> scene = loadSceneText(
        "camera { location <0, 0, -3> look_at 0 }\n"
        "plane { z, 0 pigment { rgb <1e-39, 0.5, 0.5> } finish { ambient 1 diffuse 0 } }",
        "denormal.drt", diagnostics);
    ASSERT_TRUE(scene) << diagnostics.formatAll();
    RenderOptions options = resolveRenderOptions(scene->render);
    options.width = 8;
    options.height = 6;
    options.samplesPerPixel = 1;
    const float expected = static_cast<float>(1e-39);
    ASSERT_GT(expected, 0.0f);
    const unsigned saved = _mm_getcsr();
    for (int threads : {1, 2}) {
        options.threads = threads;
        _mm_setcsr(saved | 0x8040); // flush-to-zero and denormals-are-zero on the calling thread
        const RenderResult r = render(*scene, options);
        _mm_setcsr(saved);
        EXPECT_EQ(r.color.at(4, 3, 0), expected) << threads << " threads";
    }
}
#endif

} // namespace
} // namespace drt
