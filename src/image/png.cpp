// PNG encoding through libpng (see png.h). Why libpng rather than our own writer: a PNG
// worth sharing needs real deflate compression and adaptive row filters (the stored
// blocks we wrote before made a 400 x 400 picture 480 kB); libpng is Debian's, well kept,
// and does both.
#include "image/png.h"

#include <png.h>

#include <cmath>
#include <csetjmp>

#include "util/error.h"

namespace rp {

namespace {

void appendToString(png_structp png, png_bytep data, png_size_t length) {
    auto* out = static_cast<std::string*>(png_get_io_ptr(png));
    out->append(reinterpret_cast<const char*>(data), length);
}
void noFlush(png_structp) {}

// The libpng calls, after every C++ object they touch exists: libpng reports errors by
// longjmp, which must not skip a destructor. Returns false on a libpng error.
bool writeRows(png_structp png, png_infop info, int width, int height, png_bytep* rows,
               std::string* out, const std::optional<double>& gamma) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_write_fn(png, out, appendToString, noFlush);
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (gamma)
        png_set_gAMA(png, info, 1.0 / *gamma);
    else
        png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, nullptr);
    return true;
}

}  // namespace

std::string encodePng(int width, int height, const std::vector<uint8_t>& rgb,
                      std::optional<double> gamma) {
    RP_CHECK(width > 0 && height > 0);
    RP_CHECK(rgb.size() == static_cast<size_t>(width) * height * 3);
    std::vector<png_bytep> rows(static_cast<size_t>(height));
    for (int y = 0; y < height; ++y)
        rows[size_t(y)] = const_cast<png_bytep>(rgb.data() + size_t(y) * size_t(width) * 3);
    std::string out;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    const bool ok = png && info && writeRows(png, info, width, height, rows.data(), &out, gamma);
    png_destroy_write_struct(&png, &info);
    if (!ok) throw InputError("PNG encoding failed");
    return out;
}

}  // namespace rp
