// The seam between drt and OpenImageIO. Every image drt reads or writes goes
// through OpenImageIO, but OpenImageIO is not linked into drt: it lives in the
// module libdrt_oiio.so (src/image/oiio/), which image/image.cpp loads with
// dlopen on the first image operation. Debian's OpenImageIO 2.4 pulls in about
// 250 shared libraries (OpenCV, FFmpeg, DCMTK, OpenVDB, GStreamer, ...) whose
// loading and relocation cost about 0.45 s of CPU and 120 MiB of memory before
// main() runs; linked in, every `drt --version` and `drt check` paid for them
// (docs/performance.md, "Start-up"). drt render loads it in a process of its
// own and sends it the table's calls (image/image_process.h).
#pragma once

#include "image/image.h"

#include <cctype>
#include <cstdint>
#include <filesystem>
#include <string>

namespace drt {

// Bumped whenever this table changes: a module from another build is refused.
inline constexpr int kImageIoModuleVersion = 2;

// The memory a decoded image may take (core/limits.h's image_memory_mb; the
// module does not link drt's core library, so image/image.cpp passes it in).
struct ReadBudget {
    uint64_t megabytes;
    std::string hint; // how to raise the limit
};

// The module does the OpenImageIO work only; the files around it (temporary
// names, renames, removal on a signal) are handled by image/image.cpp.
struct ImageIoModule {
    int version;
    // True if OpenImageIO has a writer for the format `path`'s extension names.
    bool (*hasWriter)(const std::string& path);
    // Encodes `image` into `file` in the format `path`'s extension names
    // (integer formats sRGB-encoded). Returns "" or OpenImageIO's reason.
    std::string (*writeFile)(const std::string& file, const std::string& path, const Image& image,
                             const Metadata& metadata);
    // As image/image.h's readImage and readImageEncoded. A file whose header
    // gives an image of more than `budget.megabytes` (as floats) is refused
    // before anything is allocated, the message ending in `budget.hint`.
    std::string (*readImage)(const std::string& path, Image& image, Metadata* metadata, const ReadBudget& budget);
    std::string (*readImageEncoded)(const std::string& path, Image& image, ImageFileInfo& info,
                                    const ReadBudget& budget);
};

// The extension of `path`, lower case ("" if none): it names the format.
inline std::string lowerExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

// The file name of the module, and the symbol it exports
// (extern "C" const ImageIoModule* drt_image_io_module()).
inline constexpr const char* kImageIoModuleFile = "libdrt_oiio.so";
inline constexpr const char* kImageIoModuleSymbol = "drt_image_io_module";

} // namespace drt
