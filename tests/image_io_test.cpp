// Image I/O through OpenImageIO: sRGB encoding of integer formats, exact
// floats in EXR, metadata, atomic writes and early checks.
#include "image/image.h"
#include "image/srgb.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <random>

namespace fs = std::filesystem;

namespace drt {
namespace {

std::string metadataValue(const Metadata& metadata, const std::string& key) {
    for (const auto& [k, v] : metadata)
        if (k == key)
            return v;
    return "<missing>";
}

// The raw 8-bit values stored in a file, bypassing readImage's decoding.
std::vector<unsigned char> rawBytes(const std::string& path) {
    auto input = OIIO::ImageInput::open(path);
    if (!input)
        return {};
    const OIIO::ImageSpec& spec = input->spec();
    std::vector<unsigned char> bytes(size_t(spec.width) * spec.height * spec.nchannels);
    input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, bytes.data());
    return bytes;
}

std::vector<std::string> filesIn(const std::string& dir) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir))
        names.push_back(entry.path().filename().string());
    return names;
}

TEST(SrgbCurve, EncodeDecodeAreInverseAndMatchTheStandard) {
    EXPECT_NEAR(srgbEncode(0.5), 0.7353569, 1e-6);
    EXPECT_NEAR(srgbEncode(0.0031308), 0.04045, 1e-5); // where the linear and power pieces meet
    EXPECT_DOUBLE_EQ(srgbEncode(-1), 0);
    EXPECT_DOUBLE_EQ(srgbEncode(7), 1);
    EXPECT_DOUBLE_EQ(srgbEncode(std::nan("")), 0);
    for (double v = 0; v <= 1; v += 1.0 / 64)
        EXPECT_NEAR(srgbDecode(srgbEncode(v)), v, 1e-12);
}

TEST(ImageIo, PngStoresRoundedSrgbBytes) {
    const std::string path = test::tempDir() + "/bytes.png";
    // Linear values and their 8-bit sRGB codes round(255 * srgbEncode(v)), by hand:
    // 0.5 -> 187.52 -> 188; 0.0031308 -> 10.31 -> 10; 0.2 -> 124.2 -> 124; clamped: -1 -> 0, 2 -> 255.
    Image image(6, 1, 1);
    image.pixels = {0.0f, 0.5f, 0.0031308f, 0.2f, -1.0f, 2.0f};
    ASSERT_EQ(writeImage(path, image), "");
    EXPECT_EQ(rawBytes(path), (std::vector<unsigned char>{0, 188, 10, 124, 0, 255}));
}

TEST(ImageIo, PngRoundTripWithinOneCode) {
    const std::string path = test::tempDir() + "/round.png";
    Image image(16, 8, 3);
    for (size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = float(i) / float(image.pixels.size() - 1);
    ASSERT_EQ(writeImage(path, image), "");
    Image back;
    ASSERT_EQ(readImage(path, back), "");
    ASSERT_EQ(back.width, 16);
    ASSERT_EQ(back.height, 8);
    ASSERT_EQ(back.channels, 3);
    for (size_t i = 0; i < image.pixels.size(); ++i)
        EXPECT_NEAR(srgbEncode(back.pixels[i]), srgbEncode(image.pixels[i]), 0.5 / 255 + 1e-6) << i;
}

TEST(ImageIo, Tiff16BitRoundTripWithinOneCode) {
    const std::string path = test::tempDir() + "/round.tif";
    Image image(7, 5, 3);
    for (size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = float(i) / float(image.pixels.size());
    ASSERT_EQ(writeImage(path, image), "");
    Image back;
    ASSERT_EQ(readImage(path, back), "");
    for (size_t i = 0; i < image.pixels.size(); ++i)
        EXPECT_NEAR(srgbEncode(back.pixels[i]), srgbEncode(image.pixels[i]), 0.5 / 65535 + 1e-6) << i;
}

TEST(ImageIo, ExrKeepsExactLinearFloats) {
    const std::string path = test::tempDir() + "/exact.exr";
    Image image(9, 4, 3);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> value(-4.0f, 40.0f);
    for (float& v : image.pixels)
        v = value(rng);
    image.pixels[0] = 1e-30f;
    image.pixels[1] = 3e30f;
    ASSERT_EQ(writeImage(path, image), "");
    Image back;
    ASSERT_EQ(readImage(path, back), "");
    ASSERT_EQ(back.pixels.size(), image.pixels.size());
    EXPECT_EQ(std::memcmp(back.pixels.data(), image.pixels.data(), image.pixels.size() * sizeof(float)), 0);
    // Stored as 32-bit floats with zip, OpenEXR's lossless compression (at
    // zlib's fastest level, which the file does not record).
    auto input = OIIO::ImageInput::open(path);
    ASSERT_TRUE(input);
    EXPECT_EQ(input->spec().format, OIIO::TypeDesc::FLOAT);
    EXPECT_EQ(input->spec().get_string_attribute("compression"), "zip");
}

TEST(ImageIo, MetadataSurvivesInEveryFormatThatCanHoldIt) {
    const std::string dir = test::tempDir();
    const Metadata metadata{{"drt:version", "0.1.0"}, {"drt:seed", "42"}, {"drt:spp", "16"}};
    Image image(4, 4, 3);
    for (const char* name : {"m.png", "m.exr", "m.tif", "m.jpg"}) {
        const std::string path = dir + "/" + name;
        ASSERT_EQ(writeImage(path, image, metadata), "") << name;
        Image back;
        Metadata read;
        ASSERT_EQ(readImage(path, back, &read), "") << name;
        EXPECT_EQ(metadataValue(read, "drt:version"), "0.1.0") << name;
        EXPECT_EQ(metadataValue(read, "drt:seed"), "42") << name;
        EXPECT_EQ(metadataValue(read, "drt:spp"), "16") << name;
    }
}

TEST(ImageIo, HdrKeepsLinearValuesAboveOne) {
    const std::string path = test::tempDir() + "/bright.hdr";
    Image image(2, 1, 3);
    image.pixels = {4.0f, 2.0f, 1.0f, 0.25f, 0.5f, 8.0f};
    ASSERT_EQ(writeImage(path, image), "");
    Image back;
    ASSERT_EQ(readImage(path, back), "");
    for (size_t i = 0; i < image.pixels.size(); ++i)
        EXPECT_NEAR(back.pixels[i], image.pixels[i], image.pixels[i] * 0.01) << i; // RGBE: 8-bit mantissas
}

TEST(ImageIo, FailedWriteLeavesNoFileAndKeepsTheOldOne) {
    const std::string dir = test::tempDir();
    // The target is a folder: the final rename fails after the data was written.
    fs::create_directory(dir + "/taken.png");
    Image image(4, 4, 3);
    EXPECT_NE(writeImage(dir + "/taken.png", image), "");
    EXPECT_EQ(filesIn(dir), std::vector<std::string>{"taken.png"});
    EXPECT_TRUE(fs::is_directory(dir + "/taken.png"));

    // A format that cannot hold the image fails in OpenImageIO; the old file stays.
    const std::string old = dir + "/old.hdr";
    ASSERT_EQ(writeImage(old, image), "");
    const auto oldSize = fs::file_size(old);
    Image fiveChannels(4, 4, 5);
    EXPECT_NE(writeImage(old, fiveChannels), "");
    EXPECT_EQ(fs::file_size(old), oldSize);
    EXPECT_EQ(filesIn(dir).size(), 2u);

    // A malformed image is refused before anything is created.
    Image malformed(4, 4, 3);
    malformed.pixels.resize(5);
    EXPECT_NE(writeImage(dir + "/bad.png", malformed), "");
    EXPECT_FALSE(fs::exists(dir + "/bad.png"));
}

TEST(ImageIo, CheckWritableCatchesProblemsEarly) {
    const std::string dir = test::tempDir();
    EXPECT_EQ(checkWritable(dir + "/fine.png"), "");
    EXPECT_EQ(checkWritable(dir + "/fine.EXR"), "");
    EXPECT_TRUE(filesIn(dir).empty()); // the probe file is gone

    const std::string missing = checkWritable(dir + "/no/such/folder/out.png");
    EXPECT_NE(missing.find("does not exist"), std::string::npos) << missing;

    test::writeFile(dir + "/file.txt", "x");
    const std::string notFolder = checkWritable(dir + "/file.txt/out.png");
    EXPECT_NE(notFolder.find("is not a folder"), std::string::npos) << notFolder;

    const std::string unknown = checkWritable(dir + "/out.xyz");
    EXPECT_NE(unknown.find("unknown image format"), std::string::npos) << unknown;

    // /proc refuses new files even to root, where permission bits do not.
    EXPECT_NE(checkWritable("/proc/drt-test-output.png"), "");

    fs::create_directory(dir + "/sub.png");
    EXPECT_NE(checkWritable(dir + "/sub.png"), "");
}

// checkWritable accepts the common formats without waiting for the
// OpenImageIO module (it may still be loading in the background): each of them
// must then really be written and read back by it, whatever the letter case.
TEST(ImageIo, FormatsAcceptedBeforeTheModuleLoadsAreWritten) {
    loadImageIoInBackground(); // as a render does; the operations below wait for it
    loadImageIoInBackground(); // a second call changes nothing
    waitForImageIoLoad();      // returns once it is loaded
    EXPECT_FALSE(imageIoLoading());
    const std::string dir = test::tempDir();
    Image image(6, 4, 3);
    for (size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = float(i % 5) / 5.0f;
    for (const char* name : {"a.png", "a.jpg", "a.JPEG", "a.tif", "a.tiff", "a.exr", "a.hdr"}) {
        const std::string path = dir + "/" + name;
        EXPECT_EQ(checkWritable(path), "") << name;
        ASSERT_EQ(writeImage(path, image), "") << name;
        Image back;
        ASSERT_EQ(readImage(path, back), "") << name;
        EXPECT_EQ(back.width, 6) << name;
        EXPECT_EQ(back.height, 4) << name;
    }
}

TEST(ImageIo, ReadErrorsNameTheFile) {
    const std::string dir = test::tempDir();
    Image image;
    const std::string missing = readImage(dir + "/missing.png", image);
    EXPECT_NE(missing.find("missing.png"), std::string::npos) << missing;
    test::writeFile(dir + "/garbage.png", "this is not a PNG file");
    EXPECT_NE(readImage(dir + "/garbage.png", image), "");
}

} // namespace
} // namespace drt
