// Palette indices of PNG files through libpng: POV-Ray's height_field uses the
// index of a colour-mapped image, which OpenImageIO does not expose.
#include "image/image.h"

#include <png.h>

#include <csetjmp>
#include <cstdio>

namespace drt {

namespace {

// libpng's default handlers print; a file that is not a palette PNG is an ordinary "no".
void quietError(png_structp png, png_const_charp) { png_longjmp(png, 1); }
void quietWarning(png_structp, png_const_charp) {}

} // namespace

bool readPngPaletteIndices(const std::string& path, int& width, int& height, std::vector<unsigned char>& indices) {
    FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) return false;
    png_byte signature[8] = {};
    if (std::fread(signature, 1, 8, file) != 8 || png_sig_cmp(signature, 0, 8) != 0) {
        std::fclose(file);
        return false;
    }
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, quietError, quietWarning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    std::vector<png_bytep> rows;
    std::vector<unsigned char> pixels;
    bool ok = false;
    if (png && info && !setjmp(png_jmpbuf(png))) {
        png_init_io(png, file);
        png_set_sig_bytes(png, 8);
        png_read_info(png, info);
        if (png_get_color_type(png, info) == PNG_COLOR_TYPE_PALETTE &&
            png_get_interlace_type(png, info) == PNG_INTERLACE_NONE) {
            if (png_get_bit_depth(png, info) < 8) png_set_packing(png); // one index per byte
            png_read_update_info(png, info);
            const png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
            if (png_get_rowbytes(png, info) == w) {
                pixels.resize(size_t(w) * h);
                rows.resize(h);
                for (png_uint_32 y = 0; y < h; ++y) rows[y] = pixels.data() + size_t(y) * w;
                png_read_image(png, rows.data());
                width = int(w), height = int(h);
                indices = std::move(pixels);
                ok = true;
            }
        }
    }
    png_destroy_read_struct(png ? &png : nullptr, info ? &info : nullptr, nullptr);
    std::fclose(file);
    return ok;
}

} // namespace drt
