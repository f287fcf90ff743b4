// An in-memory float image (linear values, interleaved channels) and the one
// image I/O path, through OpenImageIO.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace drt {

struct Image {
    int width = 0;
    int height = 0;
    int channels = 3;
    std::vector<float> pixels; // row-major, top row first, interleaved

    Image() = default;
    Image(int w, int h, int c = 3) : width(w), height(h), channels(c), pixels(size_t(w) * h * c, 0.0f) {}
    float& at(int x, int y, int c) { return pixels[(size_t(y) * width + x) * channels + c]; }
    float at(int x, int y, int c) const { return pixels[(size_t(y) * width + x) * channels + c]; }
};

using Metadata = std::vector<std::pair<std::string, std::string>>;

// Fails early (before rendering) if `path` cannot be written: missing folder,
// no permission, no OpenImageIO module file, or an extension no OpenImageIO
// writer handles. Returns "" if fine. The common formats (.png, .jpg, .tif,
// .exr, .hdr) are accepted without waiting for the module to load, so a module
// file that is present but cannot be loaded shows only at the first image
// operation.
std::string checkWritable(const std::string& path);

// Starts loading the OpenImageIO module on a background thread, so that its
// dynamic linking (about half a second of CPU with Debian's OpenImageIO and
// the ~260 libraries it pulls in) overlaps a render instead of preceding it.
// The first image operation waits for it. Calling it again does nothing, and
// so does calling it once drt render's image process runs (image/image_process.h:
// the module loads there).
void loadImageIoInBackground();
// True while a load that loadImageIoInBackground or the image process started is running.
bool imageIoLoading();
// Returns when no such load is running (at once if none was started).
void waitForImageIoLoad();

// Writes the image to a temporary file beside `path` and renames it over
// `path` only when complete. 8-bit and 16-bit integer formats are sRGB-encoded
// (clamped to [0, 1]); float formats (EXR, HDR) keep linear values. Returns "" on
// success, else the reason.
std::string writeImage(const std::string& path, const Image& image, const Metadata& metadata = {});

// Reads any format OpenImageIO reads, as linear floats (8-bit sRGB decoded).
// Returns "" on success, else the reason.
std::string readImage(const std::string& path, Image& image, Metadata* metadata = nullptr);

// How a file stores its pixels, for readers that apply their own decoding rules.
struct ImageFileInfo {
    int bitsPerChannel = 8; // 8 or 16 for integer files, 32 for float files
    bool isFloat = false;
    bool srgbEncoded = true; // integer files unless the file says otherwise (a PNG gAMA chunk, "Linear")
    double fileGamma = 0;    // when the file states a plain gamma g: values are decoded as v^g (1: linear)
};

// Reads the values as stored, scaled to [0, 1] for integer files (value / 255,
// value / 65535), without any sRGB decoding. Returns "" on success, else the reason.
std::string readImageEncoded(const std::string& path, Image& image, ImageFileInfo& info);

// The palette index of every pixel of a colour-mapped PNG (width x height, rows
// top first), for POV-Ray's per-index image_map amounts and material_map.
// OpenImageIO expands palettes into colours, so this one read goes through
// libpng. A file that is not a palette PNG leaves `indices` empty. Returns ""
// or the reason; the caller has read the image's colours (and so checked its
// size against the memory limit) first.
std::string readPaletteIndices(const std::string& path, int width, int height, std::vector<uint8_t>& indices);

} // namespace drt
