// Image I/O through OpenImageIO: every image drt reads or writes is decoded
// or encoded here. Built as the module libdrt_oiio.so, which image/image.cpp
// loads on the first image operation (image/image_io_module.h says why); the
// file handling around it (temporary names, renames, clean-up on a signal)
// stays in image/image.cpp.
#include "image/image.h"
#include "image/image_io_module.h"

#include "image/srgb.h"

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <system_error>

namespace fs = std::filesystem;

namespace drt::oiio {

namespace {

// How pixels are stored in a format: float formats keep linear values, integer
// formats store sRGB-encoded values.
OIIO::TypeDesc storageType(const std::string& path) {
    const std::string ext = lowerExtension(path);
    if (ext == ".exr" || ext == ".hdr" || ext == ".rgbe" || ext == ".pfm")
        return OIIO::TypeDesc::FLOAT;
    if (ext == ".tif" || ext == ".tiff")
        return OIIO::TypeDesc::UINT16;
    return OIIO::TypeDesc::UINT8;
}

bool isIntegerType(OIIO::TypeDesc type) {
    return type.basetype != OIIO::TypeDesc::FLOAT && type.basetype != OIIO::TypeDesc::HALF &&
           type.basetype != OIIO::TypeDesc::DOUBLE;
}

// TIFF and JPEG keep only the description writeImage composes, "drt" then one
// "key=value" per line (files written before values could hold spaces separate
// the items by spaces): recover the keys the file did not keep.
void recoverFromDescription(const std::string& description, Metadata& metadata) {
    if (description.rfind("drt\n", 0) != 0 && description.rfind("drt ", 0) != 0)
        return;
    const char separator = description[3];
    size_t start = 4;
    while (start < description.size()) {
        size_t end = description.find(separator, start);
        if (end == std::string::npos)
            end = description.size();
        const std::string item = description.substr(start, end - start);
        start = end + 1;
        const size_t equals = item.find('=');
        if (equals == std::string::npos)
            continue;
        std::string key = item.substr(0, equals);
        bool present = false;
        for (const auto& entry : metadata)
            present = present || entry.first == key;
        if (!present)
            metadata.emplace_back(std::move(key), item.substr(equals + 1));
    }
}

} // namespace

bool hasWriter(const std::string& path) {
    auto output = OIIO::ImageOutput::create(path);
    if (!output)
        OIIO::geterror(); // clear OpenImageIO's pending message
    return bool(output);
}

std::string writeFile(const std::string& file, const std::string& path, const Image& image,
                      const Metadata& metadata) {
    auto output = OIIO::ImageOutput::create(path);
    if (!output) {
        OIIO::geterror();
        return "unknown image format '" + lowerExtension(path) + "'";
    }
    const OIIO::TypeDesc type = storageType(path);
    const bool encode = isIntegerType(type);
    OIIO::ImageSpec spec(image.width, image.height, image.channels, type);
    spec.attribute("oiio:ColorSpace", encode ? "sRGB" : "Linear");
    // OpenEXR: lossless zip at zlib's fastest level rather than OpenImageIO's 4.
    // After OpenEXR's predictor the two differ by about 0.3% in size, and level
    // 1 takes a third less time (docs/performance.md, "The image process as a
    // program of its own"): a short render's last serial step.
    if (lowerExtension(path) == ".exr")
        spec.attribute("compression", "zip:1");
    std::string description = "drt";
    for (const auto& [key, value] : metadata) {
        spec.attribute(key, value);
        if (key.rfind("drt:", 0) == 0)
            description += "\n" + key + "=" + value;
    }
    // Formats that drop unknown attributes (TIFF, JPEG) still keep a description.
    if (!metadata.empty())
        spec.attribute("ImageDescription", description);

    // 8/16-bit: sRGB-encode, clamp, round; the quantisation itself is OpenImageIO's
    // (round to nearest) when it converts our [0, 1] floats to the file's type.
    // Float files take the pixels as they are: no copy.
    std::vector<float> encoded;
    if (encode) {
        encoded.reserve(image.pixels.size());
        for (const float v : image.pixels)
            encoded.push_back(static_cast<float>(srgbEncode(v)));
    }
    const float* stored = encode ? encoded.data() : image.pixels.data();
    if (!output->open(file, spec) || !output->write_image(OIIO::TypeDesc::FLOAT, stored) || !output->close())
        return output->geterror();
    return "";
}

// "" or why the header's image is refused: no pixels, or more memory than the budget.
std::string headerSizeProblem(const std::string& path, const OIIO::ImageSpec& spec, const ReadBudget& budget) {
    if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1 || spec.depth > 1)
        return fmt::format("cannot read '{}': its header gives a {} x {} image with {} channels", path, spec.width,
                           spec.height, spec.nchannels);
    // In double: no overflow for any header (ints up to 2^31 each).
    const double megabytes = std::ceil(double(spec.width) * double(spec.height) * double(spec.nchannels) *
                                       double(sizeof(float)) / double(1 << 20));
    if (megabytes > double(budget.megabytes))
        return fmt::format("cannot read '{}': its header gives a {} x {} image, which needs {:.0f} MB, over the limit "
                           "of {} MB ({})",
                           path, spec.width, spec.height, megabytes, budget.megabytes, budget.hint);
    return "";
}

// Opens `path` (with `config`, if any), checks its header against `budget` and
// reads every channel as float into `pixels`; `spec` is the file's. Returns ""
// or why not.
std::string readPixels(const std::string& path, const OIIO::ImageSpec* config, const ReadBudget& budget,
                       Image& pixels, OIIO::ImageSpec& spec) {
    std::error_code ec;
    if (!fs::exists(path, ec))
        return "cannot read '" + path + "': no such file";
    auto input = OIIO::ImageInput::open(path, config);
    if (!input) {
        std::string reason = OIIO::geterror();
        return "cannot read '" + path + "': " + (reason.empty() ? "unknown image format" : reason);
    }
    spec = input->spec();
    if (std::string problem = headerSizeProblem(path, spec, budget); !problem.empty()) return problem;
    Image result(spec.width, spec.height, spec.nchannels);
    if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, result.pixels.data()))
        return "cannot read '" + path + "': " + input->geterror();
    input->close();
    pixels = std::move(result);
    return "";
}

std::string readImageEncoded(const std::string& path, Image& image, ImageFileInfo& info, const ReadBudget& budget) {
    // Colour as stored, not multiplied by alpha (OpenImageIO's default for PNG).
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    OIIO::ImageSpec spec;
    Image result;
    if (std::string problem = readPixels(path, &config, budget, result, spec); !problem.empty()) return problem;
    info.isFloat = !isIntegerType(spec.format);
    const int bits = spec.get_int_attribute("oiio:BitsPerSample", 0);
    info.bitsPerChannel = info.isFloat ? 32 : (bits > 0 ? bits : int(spec.format.size()) * 8);
    const std::string colorSpace = spec.get_string_attribute("oiio:ColorSpace");
    info.srgbEncoded = !info.isFloat && colorSpace != "Linear" && colorSpace.rfind("Gamma", 0) != 0;
    if (colorSpace == "Linear")
        info.fileGamma = 1;
    else if (colorSpace.rfind("Gamma", 0) == 0)
        info.fileGamma = spec.get_float_attribute("oiio:Gamma", 0);
    image = std::move(result);
    return "";
}

std::string readImage(const std::string& path, Image& image, Metadata* metadata, const ReadBudget& budget) {
    OIIO::ImageSpec spec;
    Image result;
    if (std::string problem = readPixels(path, nullptr, budget, result, spec); !problem.empty()) return problem;
    // Integer files hold sRGB-encoded colour (the inverse of writeImage); alpha stays linear.
    const std::string colorSpace = spec.get_string_attribute("oiio:ColorSpace");
    if (isIntegerType(spec.format) && colorSpace != "Linear") {
        for (size_t i = 0; i < result.pixels.size(); ++i)
            if (int(i % result.channels) != spec.alpha_channel)
                result.pixels[i] = static_cast<float>(srgbDecode(result.pixels[i]));
    }
    if (metadata) {
        metadata->clear();
        for (const OIIO::ParamValue& p : spec.extra_attribs)
            metadata->emplace_back(p.name().string(), p.get_string(1024));
        recoverFromDescription(spec.get_string_attribute("ImageDescription"), *metadata);
    }
    image = std::move(result);
    return "";
}

} // namespace drt::oiio

extern "C" const drt::ImageIoModule* drt_image_io_module() {
    static const drt::ImageIoModule module = {drt::kImageIoModuleVersion, &drt::oiio::hasWriter,
                                              &drt::oiio::writeFile, &drt::oiio::readImage,
                                              &drt::oiio::readImageEncoded};
    return &module;
}
