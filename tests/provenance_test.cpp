// Provenance metadata (render/provenance.h): what drt records in the files it
// renders, and byte-identical files for the same scene and seed with
// --reproducible (and in drt test's goldens).
#include "image/image.h"
#include "lang/load.h"
#include "core/sha1.h"
#include "render/provenance.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>

namespace fs = std::filesystem;

namespace drt {
namespace {

std::string valueOf(const Metadata& metadata, const std::string& key) {
    for (const auto& [k, v] : metadata)
        if (k == key)
            return v;
    return "<missing>";
}

TEST(Provenance, Sha1OfKnownTexts) {
    // FIPS 180 test vectors.
    EXPECT_EQ(sha1Hex("abc"), "a9993e364706816aba3e25717850c26c9cd0d89d");
    EXPECT_EQ(sha1Hex(""), "da39a3ee5e6b4b0d3255bfef95601890afd80709");
    // 56 bytes: the padding needs a second block.
    EXPECT_EQ(sha1Hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
              "84983e441c3bd26ebaae4aa1f95129e5e54670f1");
    // Many blocks, appended in pieces that straddle block boundaries.
    Sha1 pieces;
    for (int i = 0; i < 10000; ++i)
        pieces.append(std::string(100, 'a'));
    EXPECT_EQ(pieces.hexDigest(), "34aa973cd4c4daa4f61eeb2bdbad27316534016f"); // a million 'a'
}

TEST(Provenance, SceneHashCoversTheSceneAndItsIncludes) {
    const std::string dir = test::tempDir();
    const std::string scene = "#include \"parts.drt\"\nsphere { 0, 1 }\n";
    test::writeFile(dir + "/scene.drt", scene);
    test::writeFile(dir + "/parts.drt", "#declare R = 1;\n");
    Diagnostics diags;
    ASSERT_TRUE(loadSceneFile(dir + "/scene.drt", diags)) << diags.formatAll();
    const std::string first = sceneTextSha1(diags.files());
    // The scene, then the include, each after its length and a newline.
    EXPECT_EQ(first, sha1Hex(std::to_string(scene.size()) + "\n" + scene + "16\n#declare R = 1;\n"));

    test::writeFile(dir + "/parts.drt", "#declare R = 2;\n"); // only the include changes
    Diagnostics again;
    ASSERT_TRUE(loadSceneFile(dir + "/scene.drt", again)) << again.formatAll();
    EXPECT_NE(sceneTextSha1(again.files()), first);
}

TEST(Provenance, SceneHashKeepsTheFilesApart) {
    // The same bytes split differently between a scene and its include are
    // different scenes.
    Diagnostics aThenBc, abThenC;
    aThenBc.files().add("scene", "a");
    aThenBc.files().add("include", "bc");
    abThenC.files().add("scene", "ab");
    abThenC.files().add("include", "c");
    EXPECT_NE(sceneTextSha1(aThenBc.files()), sceneTextSha1(abThenC.files()));
    Diagnostics abc;
    abc.files().add("scene", "abc");
    EXPECT_NE(sceneTextSha1(abc.files()), sceneTextSha1(abThenC.files()));
    EXPECT_EQ(sceneTextSha1(abc.files()), sha1Hex("3\nabc"));
}

TEST(Provenance, CommandLineIsQuotedForTheShell) {
    const char* argv[] = {"drt", "render", "my scene.drt", "-o", "it's.png", "--seed", "7"};
    EXPECT_EQ(shellCommandLine(7, argv), "drt render 'my scene.drt' -o 'it'\\''s.png' --seed 7");
}

TEST(Provenance, ReproducibleMetadataLeavesOutTheRunDetails) {
    RenderOptions options;
    options.width = 8, options.height = 4, options.samplesPerPixel = 16, options.seed = 5;
    Provenance p = renderProvenance("dir/scene.drt", "abc123", options, "box");
    p.identify("drt:crop", "0 0 4 4");
    p.record("drt:resumed_from", "checkpoint 2");
    recordRun(p, options, RenderStats{}, "drt render dir/scene.drt -o x.exr", std::time_t(86400 * 365));

    const Metadata full = p.metadata(false);
    EXPECT_EQ(valueOf(full, "drt:scene"), "scene.drt");
    EXPECT_EQ(valueOf(full, "drt:scene_sha1"), "abc123");
    EXPECT_EQ(valueOf(full, "drt:seed"), "5");
    EXPECT_EQ(valueOf(full, "drt:spp"), "16");
    EXPECT_EQ(valueOf(full, "drt:filter"), "box");
    EXPECT_EQ(valueOf(full, "drt:size"), "8x4");
    EXPECT_EQ(valueOf(full, "drt:version"), DRT_VERSION);
    EXPECT_EQ(valueOf(full, "drt:crop"), "0 0 4 4");
    EXPECT_EQ(valueOf(full, "drt:command_line"), "drt render dir/scene.drt -o x.exr");
    EXPECT_EQ(valueOf(full, "drt:resumed_from"), "checkpoint 2");
    EXPECT_NE(valueOf(full, "drt:threads"), "<missing>");
    EXPECT_EQ(valueOf(full, "drt:started").substr(0, 4), "1971");
    EXPECT_EQ(valueOf(full, "DateTime").substr(0, 5), "1971:");

    const Metadata reproducible = p.metadata(true);
    EXPECT_EQ(valueOf(reproducible, "drt:crop"), "0 0 4 4");
    EXPECT_EQ(valueOf(reproducible, "drt:seed"), "5");
    for (const char* runKey : {"drt:command_line", "drt:threads", "drt:started", "drt:render_seconds",
                               "drt:resumed_from"})
        EXPECT_EQ(valueOf(reproducible, runKey), "<missing>") << runKey;
    EXPECT_EQ(valueOf(reproducible, "DateTime"), "");

    // identify/record replace an earlier value of the same key.
    p.identify("drt:seed", "6");
    EXPECT_EQ(valueOf(p.metadata(true), "drt:seed"), "6");
    EXPECT_EQ(std::count_if(p.identity().begin(), p.identity().end(),
                            [](const auto& e) { return e.first == "drt:seed"; }),
              1);
}

const char* kScene = R"(render { width 24 height 16 samples 2 seed 3 }
camera { location <0, 1, -4> look_at <0, 0.5, 0> angle 50 }
light_source { <-3, 5, -4>, color rgb <1, 1, 1> }
sphere { <0, 0.5, 0>, 0.5 texture { pigment { color rgb <0.9, 0.2, 0.1> } } }
plane { y, 0 pigment { color rgb <0.7, 0.7, 0.7> } }
)";

std::string fileBytes(const std::string& path) { return test::readFile(path); }

TEST(Provenance, RenderRecordsTheRunAndReproducibleFilesAreByteIdentical) {
    const std::string dir = test::tempDir();
    const std::string scene = test::writeFile(dir + "/scene.drt", kScene);
    for (const char* ext : {".exr", ".png"}) {
        const std::string a = dir + "/a" + ext, b = dir + "/b" + ext;
        ASSERT_EQ(test::runDrt("render '" + scene + "' -o '" + a + "' --reproducible --threads 1 -q").exitCode, 0);
        ASSERT_EQ(test::runDrt("render '" + scene + "' -o '" + b + "' --reproducible --threads 2 -q").exitCode, 0);
        EXPECT_EQ(fileBytes(a), fileBytes(b)) << ext;
        Image image;
        Metadata metadata;
        ASSERT_EQ(readImage(a, image, &metadata), "");
        EXPECT_EQ(valueOf(metadata, "drt:scene_sha1"),
                  sha1Hex(std::to_string(std::strlen(kScene)) + "\n" + kScene));
        EXPECT_EQ(valueOf(metadata, "drt:command_line"), "<missing>");
    }
    // Without --reproducible: the command line (with a space in a path), threads and time, in a TIFF too.
    const std::string spaced = dir + "/with space.tif";
    ASSERT_EQ(test::runDrt("render '" + scene + "' -o '" + spaced + "' --threads 2 --seed 9 -q").exitCode, 0);
    Image image;
    Metadata metadata;
    ASSERT_EQ(readImage(spaced, image, &metadata), "");
    const std::string commandLine = valueOf(metadata, "drt:command_line");
    EXPECT_NE(commandLine.find(" render " + scene + " -o '" + spaced + "' --threads 2 --seed 9 -q"),
              std::string::npos)
        << commandLine;
    EXPECT_EQ(valueOf(metadata, "drt:threads"), "2");
    EXPECT_EQ(valueOf(metadata, "drt:seed"), "9");
    EXPECT_EQ(valueOf(metadata, "drt:spp"), "2");
    EXPECT_EQ(valueOf(metadata, "drt:sampler"), "sobol");
    EXPECT_EQ(valueOf(metadata, "drt:filter"), "box");
    EXPECT_NE(valueOf(metadata, "drt:started"), "<missing>");
    EXPECT_NE(valueOf(metadata, "drt:render_seconds"), "<missing>");
}

} // namespace
} // namespace drt
