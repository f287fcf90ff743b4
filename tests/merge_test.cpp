// drt render --crop and drt merge through the executable: crops (with their
// variance and samples-per-pixel images) merge into the full render bit for
// bit, in EXR and PNG; every refusal has its exit status and message.
#include "image/image.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fmt/format.h>
#include <sstream>

namespace fs = std::filesystem;

namespace drt {
namespace {

const std::string kSettings = " --width 36 --height 27 --spp 2 --seed 3 --tile-size 8 -q";

std::string scene() { return fmt::format("'{}'", test::sourcePath("examples/soft_shadows.drt")); }

// Renders `name` (with extra options) into `dir`; expects success.
void renderTo(const std::string& dir, const std::string& name, const std::string& options,
              const std::string& settings = kSettings) {
    const test::CommandResult r = test::runDrt("render " + scene() + " -o '" + dir + "/" + name + "'" + settings +
                                               " " + options);
    ASSERT_EQ(r.exitCode, 0) << r.err;
}

Image pixelsOf(const std::string& path) {
    Image image;
    EXPECT_EQ(readImage(path, image), "");
    return image;
}

TEST(Merge, CropsAndTheirVarianceImagesMergeIntoTheFullRenderBitForBit) {
    const std::string dir = test::tempDir();
    renderTo(dir, "full.exr", "--variance '" + dir + "/full.var.exr' --spp-image '" + dir + "/full.spp.exr'");
    // Three crops of unequal shapes, one of them as fractions.
    const std::pair<std::string, std::string> crops[] = {
        {"a", "--crop 0,20,0,11"}, {"b", "--crop 20,36,0,11"}, {"c", "--crop 0.0,1.0,0.4,1.0"}};
    std::string parts;
    for (const auto& [name, crop] : crops) {
        renderTo(dir, name + ".exr",
                 crop + " --variance '" + dir + "/" + name + ".var.exr' --spp-image '" + dir + "/" + name +
                     ".spp.exr'");
        parts += " '" + dir + "/" + name + ".exr' '" + dir + "/" + name + ".var.exr' '" + dir + "/" + name +
                 ".spp.exr'";
    }
    const test::CommandResult r = test::runDrt("merge" + parts + " -o '" + dir + "/merged.exr' --variance '" + dir +
                                               "/merged.var.exr' --spp-image '" + dir + "/merged.spp.exr'");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("3 parts"), std::string::npos) << r.out;
    for (const char* kind : {"", ".var", ".spp"}) {
        SCOPED_TRACE(kind);
        EXPECT_TRUE(pixelsOf(dir + "/merged" + kind + ".exr").pixels == pixelsOf(dir + "/full" + kind + ".exr").pixels);
    }
    Metadata metadata;
    Image image;
    ASSERT_EQ(readImage(dir + "/a.exr", image, &metadata), "");
    bool hasCrop = false;
    for (const auto& [key, value] : metadata) hasCrop = hasCrop || (key == "drt:crop" && value == "0,20,0,11");
    EXPECT_TRUE(hasCrop) << "the crop window is in the crop's metadata";
    fs::remove_all(dir);
}

TEST(Merge, PngCropsMergeIntoTheSameBytesOfPixels) {
    const std::string dir = test::tempDir();
    renderTo(dir, "full.png", "");
    renderTo(dir, "top.png", "--crop 0,36,0,13");
    renderTo(dir, "bottom.png", "--crop 0,36,13,27");
    const test::CommandResult r =
        test::runDrt("merge '" + dir + "/top.png' '" + dir + "/bottom.png' -o '" + dir + "/merged.png'");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(pixelsOf(dir + "/merged.png").pixels == pixelsOf(dir + "/full.png").pixels);
    fs::remove_all(dir);
}

TEST(Merge, RefusesPartsThatDoNotFormOneImageOfOneRender) {
    const std::string dir = test::tempDir();
    renderTo(dir, "left.exr", "--crop 0,18,0,27 --variance '" + dir + "/left.var.exr'");
    renderTo(dir, "right.exr", "--crop 18,36,0,27 --variance '" + dir + "/right.var.exr'");
    renderTo(dir, "overlap.exr", "--crop 10,36,0,27");
    const auto replaced = [](std::string text, const std::string& from, const std::string& to) {
        return text.replace(text.find(from), from.size(), to);
    };
    renderTo(dir, "seed.exr", "--crop 18,36,0,27", replaced(kSettings, "--seed 3", "--seed 4"));
    renderTo(dir, "size.exr", "--crop 18,36,0,27", replaced(kSettings, "--width 36", "--width 40"));
    renderTo(dir, "whole.exr", "");
    test::writeFile(dir + "/other.drt", test::readFile(test::sourcePath("examples/soft_shadows.drt")) + "\n// x\n");
    ASSERT_EQ(test::runDrt("render '" + dir + "/other.drt' -o '" + dir + "/scene.exr' --crop 18,36,0,27" + kSettings)
                  .exitCode,
              0);
    const auto merge = [&](const std::string& parts, const std::string& extra = "") {
        std::string args;
        std::istringstream names(parts);
        for (std::string name; names >> name;) args += " '" + dir + "/" + name + "'";
        return test::runDrt("merge" + args + " -o '" + dir + "/out.exr'" + extra);
    };
    struct Case {
        std::string parts, extra;
        int status;
        std::string message;
    };
    const Case cases[] = {
        {"left.exr", "", 1, "leave 486 of the 36x27 image's pixels uncovered, first at (18, 0)"},
        {"left.exr right.exr overlap.exr", "", 1, "overlap, first at pixel (10, 0)"},
        {"left.exr seed.exr", "", 1, "has other settings: seed=4 there, seed=3 here"},
        {"left.exr size.exr", "", 1, "size=40x27 there, size=36x27 here"},
        {"left.exr scene.exr", "", 1, "is of another scene"},
        {"left.exr whole.exr", "", 1, "is not a crop (it was rendered without --crop)"},
        {"left.exr right.exr left.var.exr right.var.exr", "", 2, "name their output with --variance"},
        {"left.exr right.exr left.var.exr", " --variance '" + dir + "/v.exr'", 1,
         "the variance parts leave 486 of the 36x27 image's pixels uncovered"},
        {"left.exr right.exr", " --variance '" + dir + "/v.exr'", 2, "but no part is one"},
        {"left.exr missing.exr", "", 3, "no such file"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.parts + c.extra);
        const test::CommandResult r = merge(c.parts, c.extra);
        EXPECT_EQ(r.exitCode, c.status) << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir + "/out.exr")) << "a refused merge writes nothing";
    }
    fs::remove_all(dir);
}

// The merged file keeps the parts' provenance (the scene's SHA-1 over its
// includes, seed, settings) with the merge's own command line; a part whose
// included file was edited is of another scene, though the scene file is not.
TEST(Merge, KeepsProvenanceAndAnEditedIncludeMakesAnotherScene) {
    const std::string dir = test::tempDir();
    fs::create_directories(dir + "/include");
    test::writeFile(dir + "/scene.drt", test::readFile(test::sourcePath("examples/declare_include.drt")));
    const std::string materials = test::readFile(test::sourcePath("examples/include/materials.drt"));
    test::writeFile(dir + "/include/materials.drt", materials);
    const auto crop = [&](const std::string& name, const std::string& window) {
        return test::runDrt("render '" + dir + "/scene.drt' -o '" + dir + "/" + name + "' --crop " + window +
                            kSettings)
            .exitCode;
    };
    ASSERT_EQ(crop("top.exr", "0,36,0,13"), 0);
    ASSERT_EQ(crop("bottom.exr", "0,36,13,27"), 0);
    const test::CommandResult merged =
        test::runDrt("merge '" + dir + "/top.exr' '" + dir + "/bottom.exr' -o '" + dir + "/merged.exr'");
    ASSERT_EQ(merged.exitCode, 0) << merged.err;
    Metadata part, whole;
    Image image;
    ASSERT_EQ(readImage(dir + "/top.exr", image, &part), "");
    ASSERT_EQ(readImage(dir + "/merged.exr", image, &whole), "");
    const auto value = [](const Metadata& m, const std::string& key) {
        for (const auto& [k, v] : m)
            if (k == key) return v;
        return std::string("(none)");
    };
    EXPECT_EQ(value(whole, "drt:scene_sha1"), value(part, "drt:scene_sha1"));
    EXPECT_EQ(value(whole, "drt:scene_sha1").size(), 40u);
    EXPECT_EQ(value(whole, "drt:seed"), "3");
    EXPECT_EQ(value(whole, "drt:settings"), value(part, "drt:settings"));
    EXPECT_EQ(value(whole, "drt:crop"), "(none)");
    EXPECT_NE(value(whole, "drt:command_line").find(" merge "), std::string::npos) << value(whole, "drt:command_line");
    EXPECT_NE(value(part, "drt:command_line").find("--crop"), std::string::npos) << value(part, "drt:command_line");

    test::writeFile(dir + "/include/materials.drt", materials + "\n// edited\n");
    ASSERT_EQ(crop("edited.exr", "0,36,13,27"), 0);
    const test::CommandResult refused =
        test::runDrt("merge '" + dir + "/top.exr' '" + dir + "/edited.exr' -o '" + dir + "/refused.exr'");
    EXPECT_EQ(refused.exitCode, 1) << refused.err;
    EXPECT_NE(refused.err.find("is of another scene"), std::string::npos) << refused.err;
    EXPECT_FALSE(fs::exists(dir + "/refused.exr"));
    fs::remove_all(dir);
}

TEST(Merge, RenderRefusesABadCropWindow) {
    const std::string dir = test::tempDir();
    const test::CommandResult outside =
        test::runDrt("render " + scene() + " -o '" + dir + "/x.exr'" + kSettings + " --crop 0,50,0,5");
    EXPECT_EQ(outside.exitCode, 2);
    EXPECT_NE(outside.err.find("is not a non-empty part of the 36x27 image"), std::string::npos) << outside.err;
    const test::CommandResult malformed =
        test::runDrt("render " + scene() + " -o '" + dir + "/x.exr'" + kSettings + " --crop 0,5");
    EXPECT_EQ(malformed.exitCode, 2);
    EXPECT_NE(malformed.err.find("four values"), std::string::npos) << malformed.err;
    EXPECT_FALSE(fs::exists(dir + "/x.exr"));
    fs::remove_all(dir);
}

} // namespace
} // namespace drt
