// End-to-end tests of the drt executable: exit statuses, messages, and the
// files it writes. Exit statuses (cli/commands.h): 0 success, 1 scene error,
// 2 usage error, 3 I/O error (a missing scene file is an I/O error);
// compare: 0 pass, 1 warning, 2 failure, 3 size mismatch, 4 file error.
#include "cli/progress.h"
#include "image/image.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace drt {
namespace {

using test::runDrt;

// A small valid scene that renders in milliseconds.
const char* kTinyScene = R"(// test scene
render { width 24 height 16 samples 1 seed 3 }
camera { location <0, 1, -4> look_at <0, 0.5, 0> angle 50 }
light_source { <-3, 5, -4>, color rgb <1, 1, 1> }
background { color rgb <0.2, 0.3, 0.5> }
sphere { <0, 0.5, 0>, 0.5 texture { pigment { color rgb <0.9, 0.2, 0.1> } } }
plane { y, 0 pigment { color rgb <0.7, 0.7, 0.7> } }
)";

// Line 3 has a typo in a keyword: column 1.
const char* kBrokenScene = R"(camera { location <0, 1, -4> look_at <0, 0, 0> }
light_source { <1, 2, -3>, color rgb <1, 1, 1> }
spere { <0, 0, 0>, 1 }
)";

std::string quoted(const std::string& path) {
    return "'" + path + "'";
}

std::string metadataValue(const Metadata& metadata, const std::string& key) {
    for (const auto& [k, v] : metadata)
        if (k == key)
            return v;
    return "<missing>";
}

TEST(CliProgress, DurationsReadNaturally) {
    EXPECT_EQ(cli::formatDuration(0.0342), "34 ms");
    EXPECT_EQ(cli::formatDuration(1.26), "1.3 s");
    EXPECT_EQ(cli::formatDuration(184), "3 min 04 s");
    EXPECT_EQ(cli::formatDuration(3720), "1 h 02 min");
    EXPECT_EQ(cli::formatDuration(-1), "?");
}

TEST(Cli, VersionAndHelp) {
    const auto version = runDrt("--version");
    EXPECT_EQ(version.exitCode, 0);
    EXPECT_NE(version.out.find(std::string("drt ") + DRT_VERSION), std::string::npos) << version.out;

    const auto help = runDrt("--help");
    EXPECT_EQ(help.exitCode, 0);
    for (const char* word : {"render", "check", "compare"})
        EXPECT_NE(help.out.find(word), std::string::npos) << word;
    for (const char* sub : {"render", "check", "compare"}) {
        const auto r = runDrt(std::string(sub) + " --help");
        EXPECT_EQ(r.exitCode, 0) << sub;
        EXPECT_NE(r.out.find("Usage"), std::string::npos) << sub << ": " << r.out;
    }
    EXPECT_NE(runDrt("render --help").out.find("--spp"), std::string::npos);
    EXPECT_NE(runDrt("compare --help").out.find("--fail-percent"), std::string::npos);
}

TEST(Cli, UsageErrorsExitWithTwo) {
    const std::string dir = test::tempDir();
    const std::string scene = test::writeFile(dir + "/tiny.drt", kTinyScene);
    EXPECT_EQ(runDrt("").exitCode, 2);                        // no subcommand
    EXPECT_EQ(runDrt("frobnicate").exitCode, 2);              // unknown subcommand
    EXPECT_EQ(runDrt("render " + quoted(scene)).exitCode, 2); // no -o
    EXPECT_EQ(runDrt("render " + quoted(scene) + " -o x.png --bogus").exitCode, 2);
    EXPECT_EQ(runDrt("render " + quoted(scene) + " -o x.png --spp 0").exitCode, 2);
    EXPECT_EQ(runDrt("render " + quoted(scene) + " -o x.png --width abc").exitCode, 2);
    const auto sampler = runDrt("render " + quoted(scene) + " -o x.png --sampler nonsense");
    EXPECT_EQ(sampler.exitCode, 2);
    EXPECT_NE(sampler.err.find("nonsense"), std::string::npos) << sampler.err;
    EXPECT_EQ(runDrt("compare onlyone.png").exitCode, 2);
}

TEST(Cli, MissingSceneIsAnIoError) {
    const std::string dir = test::tempDir();
    const auto render = runDrt("render " + quoted(dir + "/nothere.drt") + " -o " + quoted(dir + "/out.png"));
    EXPECT_EQ(render.exitCode, 3);
    EXPECT_NE(render.err.find("nothere.drt"), std::string::npos) << render.err;
    EXPECT_FALSE(fs::exists(dir + "/out.png"));
    EXPECT_EQ(runDrt("check " + quoted(dir + "/nothere.drt")).exitCode, 3);
}

TEST(Cli, PovSceneRendersAndItsErrorsShowTheLocation) {
    const std::string dir = test::tempDir();
    const std::string scene = test::writeFile(dir + "/scene.pov",
        "camera { location <0,0,-3> look_at 0 }\nlight_source { <0,5,-5> color rgb 1 }\nsphere { <0,0,0>, 1 pigment { rgb 1 } }\n");
    auto r = runDrt("render " + quoted(scene) + " -o " + quoted(dir + "/out.png") + " --width 16 --height 12 --quiet");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir + "/out.png"));
    const std::string broken = test::writeFile(dir + "/broken.pov", "sphere { <0,0,0> 1 }\nsphere { <0,0,0>, }\n");
    r = runDrt("render " + quoted(broken) + " -o " + quoted(dir + "/broken.png"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("broken.pov:2:"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/broken.png"));
}

TEST(Cli, SyntaxErrorShowsLocationAndCaretAndWritesNothing) {
    const std::string dir = test::tempDir();
    const std::string scene = test::writeFile(dir + "/broken.drt", kBrokenScene);
    const auto r = runDrt("render " + quoted(scene) + " -o " + quoted(dir + "/out.png"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("broken.drt:3:1: error:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("spere { <0, 0, 0>, 1 }"), std::string::npos) << r.err; // the source line
    EXPECT_NE(r.err.find("\n  ^"), std::string::npos) << r.err;                  // the caret under column 1
    EXPECT_FALSE(fs::exists(dir + "/out.png"));

    const auto check = runDrt("check " + quoted(scene));
    EXPECT_EQ(check.exitCode, 1);
    EXPECT_NE(check.err.find("broken.drt:3:1: error:"), std::string::npos) << check.err;
}

TEST(Cli, BinaryFileIsNotAScene) {
    const std::string dir = test::tempDir();
    ASSERT_EQ(writeImage(dir + "/image.png", Image(4, 4, 3)), "");
    const auto r = runDrt("check " + quoted(dir + "/image.png"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_LT(r.err.size(), 200u) << r.err; // one line, not an error per byte
}

TEST(Cli, CheckAcceptsAValidScene) {
    const std::string scene = test::writeFile(test::tempDir() + "/tiny.drt", kTinyScene);
    const auto r = runDrt("check " + quoted(scene));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err, "");
}

TEST(Cli, UnwritableOutputFailsBeforeRendering) {
    const std::string dir = test::tempDir();
    const std::string scene = test::writeFile(dir + "/tiny.drt", kTinyScene);
    const auto missingFolder = runDrt("render " + quoted(scene) + " -o " + quoted(dir + "/no/such/out.png"));
    EXPECT_EQ(missingFolder.exitCode, 3);
    EXPECT_NE(missingFolder.err.find("does not exist"), std::string::npos) << missingFolder.err;
    EXPECT_EQ(missingFolder.err.find("Mrays/s"), std::string::npos)
        << missingFolder.err; // no render happened

    const auto unknownFormat = runDrt("render " + quoted(scene) + " -o " + quoted(dir + "/out.nope"));
    EXPECT_EQ(unknownFormat.exitCode, 3);
    EXPECT_NE(unknownFormat.err.find("unknown image format"), std::string::npos) << unknownFormat.err;

    const auto badVariance = runDrt("render " + quoted(scene) + " -o " + quoted(dir + "/out.png") +
                                    " --variance " + quoted(dir + "/no/var.exr"));
    EXPECT_EQ(badVariance.exitCode, 3);
    EXPECT_FALSE(fs::exists(dir + "/out.png")); // the colour image is not written either
}

TEST(Cli, RenderWritesImageWithMetadataAndVariance) {
    const std::string dir = test::tempDir();
    const std::string scene = test::writeFile(dir + "/tiny.drt", kTinyScene);
    const auto r = runDrt("render " + quoted(scene) + " -o " + quoted(dir + "/out.png") +
                          " --width 20 --height 10 --spp 2 --seed 77 --threads 2 --variance " +
                          quoted(dir + "/out.var.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("Mrays/s"), std::string::npos) << r.err; // the summary line
    EXPECT_NE(r.err.find("2 spp"), std::string::npos) << r.err;
    Image image;
    Metadata metadata;
    ASSERT_EQ(readImage(dir + "/out.png", image, &metadata), "");
    EXPECT_EQ(image.width, 20);
    EXPECT_EQ(image.height, 10);
    EXPECT_EQ(metadataValue(metadata, "drt:version"), DRT_VERSION);
    EXPECT_EQ(metadataValue(metadata, "drt:seed"), "77");
    EXPECT_EQ(metadataValue(metadata, "drt:spp"), "2");
    EXPECT_NE(metadataValue(metadata, "drt:render_seconds"), "<missing>");
    EXPECT_NE(metadataValue(metadata, "drt:sampler"), "<missing>");
    Image variance;
    ASSERT_EQ(readImage(dir + "/out.var.exr", variance), "");
    EXPECT_EQ(variance.width, 20);
    for (float v : variance.pixels)
        EXPECT_GE(v, 0.0f);

    // The scene's own settings apply when the command line does not override them.
    const auto quiet = runDrt("render " + quoted(scene) + " -o " + quoted(dir + "/scene.exr") + " --quiet");
    ASSERT_EQ(quiet.exitCode, 0) << quiet.err;
    EXPECT_EQ(quiet.err, "");
    ASSERT_EQ(readImage(dir + "/scene.exr", image, &metadata), "");
    EXPECT_EQ(image.width, 24);
    EXPECT_EQ(metadataValue(metadata, "drt:seed"), "3");
    // No temporary files are left behind.
    for (const auto& entry : fs::directory_iterator(dir))
        EXPECT_NE(entry.path().filename().string()[0], '.') << entry.path();
}

TEST(Cli, RenderStatsJsonHasTheRayCountsAndRates) {
    const std::string dir = test::tempDir();
    const std::string scene = test::writeFile(dir + "/tiny.drt", kTinyScene);
    const auto r = runDrt("render " + quoted(scene) + " -o " + quoted(dir + "/out.exr") +
                          " --width 20 --height 10 --spp 3 --threads 2 --quiet --stats " +
                          quoted(dir + "/stats.json"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json stats = nlohmann::json::parse(test::readFile(dir + "/stats.json"));
    EXPECT_EQ(stats.at("width"), 20);
    EXPECT_EQ(stats.at("spp"), 3);
    EXPECT_EQ(stats.at("threads"), 2);
    // One camera ray per sample; the light is visible from the floor, so shadow rays are traced too.
    EXPECT_EQ(stats.at("camera_rays"), 20 * 10 * 3);
    EXPECT_EQ(stats.at("pixel_samples"), 20 * 10 * 3);
    EXPECT_GT(stats.at("shadow_rays").get<uint64_t>(), 0u);
    EXPECT_EQ(stats.at("total_rays").get<uint64_t>(),
              stats.at("camera_rays").get<uint64_t>() + stats.at("shadow_rays").get<uint64_t>() +
                  stats.at("secondary_rays").get<uint64_t>());
    const double trace = stats.at("trace_seconds"), rate = stats.at("mrays_per_second");
    EXPECT_NEAR(rate, stats.at("total_rays").get<double>() / trace / 1e6, 1e-6 * rate);
    // The render threads' CPU: some, and no more than 2 threads can use in the render's time.
    const double cpu = stats.at("trace_cpu_seconds");
    EXPECT_GT(cpu, 0.0);
    EXPECT_LE(cpu, 2 * trace + 0.002);
    EXPECT_GE(stats.at("total_seconds").get<double>(), stats.at("render_seconds").get<double>());
    EXPECT_FALSE(fs::exists(dir + "/stats.json.tmp"));

    // A folder that does not exist is an I/O error before rendering: no image either.
    const auto missing = runDrt("render " + quoted(scene) + " -o " + quoted(dir + "/second.exr") + " --stats " +
                                quoted(dir + "/no/such/stats.json"));
    EXPECT_EQ(missing.exitCode, 3);
    EXPECT_NE(missing.err.find("does not exist"), std::string::npos) << missing.err;
    EXPECT_FALSE(fs::exists(dir + "/second.exr"));
}

// OpenImageIO is a module loaded on the first image operation: a command that
// needs no image never loads it, and a missing or foreign module is a clear
// I/O error before any rendering.
TEST(Cli, ImageModuleIsLoadedOnlyForImagesAndItsAbsenceIsAnIoError) {
    const std::string dir = test::tempDir();
    const std::string scene = test::writeFile(dir + "/tiny.drt", kTinyScene);
    // drt children inherit the variable; this test process does no image I/O meanwhile.
    struct ModuleOverride {
        explicit ModuleOverride(const std::string& path) { setenv("DRT_OIIO_MODULE", path.c_str(), 1); }
        ~ModuleOverride() { unsetenv("DRT_OIIO_MODULE"); }
    };
    {
        const ModuleOverride missing(dir + "/no-such-module.so");
        const auto check = runDrt("check " + quoted(scene));
        EXPECT_EQ(check.exitCode, 0) << check.err; // no image involved: the module is not needed
        EXPECT_EQ(runDrt("--version").exitCode, 0);

        const auto render = runDrt("render " + quoted(scene) + " -o " + quoted(dir + "/out.png"));
        EXPECT_EQ(render.exitCode, 3);
        EXPECT_NE(render.err.find("cannot load drt's OpenImageIO module libdrt_oiio.so"), std::string::npos)
            << render.err;
        EXPECT_NE(render.err.find("no-such-module.so: no such file"), std::string::npos) << render.err;
        EXPECT_EQ(render.err.find("Mrays/s"), std::string::npos) << render.err; // nothing rendered
        EXPECT_FALSE(fs::exists(dir + "/out.png"));
    }
    {
        // A shared library that is not drt's module (the C library) is refused.
        const ModuleOverride foreign("/lib/x86_64-linux-gnu/libc.so.6");
        const auto render = runDrt("render " + quoted(scene) + " -o " + quoted(dir + "/out.png"));
        EXPECT_EQ(render.exitCode, 3);
        EXPECT_NE(render.err.find("not a module of this drt build"), std::string::npos) << render.err;
    }
    // Without the override the module is found again.
    EXPECT_EQ(runDrt("render " + quoted(scene) + " -o " + quoted(dir + "/out.png") + " --quiet").exitCode, 0);
    EXPECT_TRUE(fs::exists(dir + "/out.png"));
}

TEST(Cli, CompareExitStatusesEndToEnd) {
    const std::string dir = test::tempDir();
    Image reference(16, 16, 3);
    for (size_t i = 0; i < reference.pixels.size(); ++i)
        reference.pixels[i] = float(i % 7) / 7.0f;
    Image different = reference, nan = reference, slightly = reference;
    different.at(3, 3, 0) += 0.5f;
    nan.at(5, 5, 2) = std::numeric_limits<float>::quiet_NaN();
    slightly.at(7, 7, 1) += 0.01f;
    ASSERT_EQ(writeImage(dir + "/ref.exr", reference), "");
    ASSERT_EQ(writeImage(dir + "/same.exr", reference), "");
    ASSERT_EQ(writeImage(dir + "/different.exr", different), "");
    ASSERT_EQ(writeImage(dir + "/nan.exr", nan), "");
    ASSERT_EQ(writeImage(dir + "/slightly.exr", slightly), "");
    ASSERT_EQ(writeImage(dir + "/small.exr", Image(8, 16, 3)), "");
    auto compare = [&](const std::string& a, const std::string& b, const std::string& extra = "") {
        return runDrt("compare " + quoted(dir + "/" + a) + " " + quoted(dir + "/" + b) + " " + extra);
    };
    EXPECT_EQ(compare("same.exr", "ref.exr").exitCode, 0);
    const auto failed = compare("different.exr", "ref.exr");
    EXPECT_EQ(failed.exitCode, 2);
    EXPECT_NE(failed.out.find("max error:         0.5 at pixel (3, 3) channel R"), std::string::npos)
        << failed.out;
    EXPECT_EQ(compare("nan.exr", "ref.exr", "--fail 1e9 --warn 1e9").exitCode, 2);
    EXPECT_EQ(compare("slightly.exr", "ref.exr", "--fail 0.1 --warn 0.001").exitCode, 1);
    EXPECT_EQ(compare("slightly.exr", "ref.exr", "--fail 0.1 --warn 0.1").exitCode, 0);
    EXPECT_EQ(compare("small.exr", "ref.exr").exitCode, 3);
    EXPECT_EQ(compare("missing.exr", "ref.exr").exitCode, 4);

    const auto json = compare("different.exr", "ref.exr", "--json --diff " + quoted(dir + "/heat.png"));
    EXPECT_EQ(json.exitCode, 2);
    EXPECT_NE(json.out.find("\"status\": \"FAILURE\""), std::string::npos) << json.out;
    EXPECT_NE(json.out.find("\"max_error_pixel\": [3, 3]"), std::string::npos) << json.out;
    Image heat;
    ASSERT_EQ(readImage(dir + "/heat.png", heat), "");
    EXPECT_EQ(heat.width, 16);
    EXPECT_GT(heat.at(3, 3, 0), heat.at(0, 0, 0));

    EXPECT_EQ(compare("same.exr", "ref.exr", "--zmap " + quoted(dir + "/z.png")).exitCode,
              2); // needs a variance
}

TEST(Cli, CompareStatisticalModeEndToEnd) {
    const std::string dir = test::tempDir();
    Image reference(32, 32, 3), variance(32, 32, 3), biased(32, 32, 3);
    for (float& v : reference.pixels)
        v = 0.5f;
    for (float& v : variance.pixels)
        v = 1e-4f; // sigma 0.01 per pixel
    for (float& v : biased.pixels)
        v = 0.505f; // +1%: global z = 0.005 * 32 / 0.01 = 16
    ASSERT_EQ(writeImage(dir + "/ref.exr", reference), "");
    ASSERT_EQ(writeImage(dir + "/var.exr", variance), "");
    ASSERT_EQ(writeImage(dir + "/biased.exr", biased), "");
    const std::string args = quoted(dir + "/ref.exr") + " --variance " + quoted(dir + "/var.exr");
    EXPECT_EQ(runDrt("compare " + quoted(dir + "/ref.exr") + " " + args).exitCode, 0);
    const auto r =
        runDrt("compare " + quoted(dir + "/biased.exr") + " " + args + " --zmap " + quoted(dir + "/z.png"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.out.find("biased"), std::string::npos) << r.out;
    EXPECT_TRUE(fs::exists(dir + "/z.png"));
    EXPECT_EQ(runDrt("compare " + quoted(dir + "/ref.exr") + " " + quoted(dir + "/ref.exr") + " --variance " +
                     quoted(dir + "/nothere.exr"))
                  .exitCode,
              4);
}

} // namespace
} // namespace drt
