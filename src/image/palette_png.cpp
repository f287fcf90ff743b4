// The palette indices of a colour-mapped PNG (image/image.h readPaletteIndices).
//
// OpenImageIO expands a palette into colours as it reads, and POV-Ray's
// per-index image_map amounts and material_map need the index itself. libpng
// (which OpenImageIO and cairo already load) reads the file once more, without
// the expansion: each pixel one byte, its index into the PLTE chunk.
#include "image/image.h"

#include <csetjmp>
#include <cstdio>
#include <memory>
#include <png.h>

namespace drt {

namespace {

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};

void onPngError(png_structp png, png_const_charp message) {
    auto* reason = static_cast<std::string*>(png_get_error_ptr(png));
    if (reason) *reason = message ? message : "unknown libpng error";
    png_longjmp(png, 1);
}

void onPngWarning(png_structp, png_const_charp) {}

// The read itself, with nothing in its frame that needs destroying: libpng
// reports errors by longjmp.
bool readIndices(std::FILE* file, int width, int height, std::vector<uint8_t>& indices, bool& isPalette,
                 std::string& reason) {
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &reason, onPngError, onPngWarning);
    if (!png) return reason = "libpng could not start", false;
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_read_struct(&png, nullptr, nullptr);
        return reason = "libpng could not start", false;
    }
    std::vector<png_bytep>* rows = nullptr;
    if (setjmp(png_jmpbuf(png))) {
        delete rows;
        png_destroy_read_struct(&png, &info, nullptr);
        return false;
    }
    png_init_io(png, file);
    png_read_info(png, info);
    isPalette = png_get_color_type(png, info) == PNG_COLOR_TYPE_PALETTE;
    if (!isPalette) {
        png_destroy_read_struct(&png, &info, nullptr);
        return true;
    }
    if (int(png_get_image_width(png, info)) != width || int(png_get_image_height(png, info)) != height) {
        png_destroy_read_struct(&png, &info, nullptr);
        return reason = "the palette's image size differs from the colour image's", false;
    }
    png_set_packing(png); // 1, 2 and 4-bit indices become one byte each
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    indices.assign(size_t(width) * size_t(height), 0);
    rows = new std::vector<png_bytep>(size_t(height));
    for (int y = 0; y < height; ++y) (*rows)[size_t(y)] = &indices[size_t(y) * size_t(width)];
    png_read_image(png, rows->data());
    png_read_end(png, nullptr);
    delete rows;
    png_destroy_read_struct(&png, &info, nullptr);
    return true;
}

} // namespace

std::string readPaletteIndices(const std::string& path, int width, int height, std::vector<uint8_t>& indices) {
    indices.clear();
    const std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
    if (!file) return "cannot open '" + path + "' to read its palette";
    png_byte signature[8] = {};
    if (std::fread(signature, 1, 8, file.get()) != 8 || png_sig_cmp(signature, 0, 8) != 0) return ""; // not a PNG
    std::rewind(file.get());
    bool isPalette = false;
    std::string reason;
    if (!readIndices(file.get(), width, height, indices, isPalette, reason)) {
        indices.clear();
        return "cannot read the palette indices of '" + path + "': " + reason;
    }
    return "";
}

} // namespace drt
