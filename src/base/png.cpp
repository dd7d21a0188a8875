#include "penumbra/base/png.h"

#include <png.h>

#include <csetjmp>
#include <ostream>
#include <stdexcept>

#include "penumbra/base/atomic_file.h"
#include "penumbra/base/input_error.h"

namespace penumbra {
namespace {

void write_to_stream(png_structp png, png_bytep data, png_size_t size) {
  auto* out = static_cast<std::ostream*>(png_get_io_ptr(png));
  out->write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

void flush_stream(png_structp png) {
  static_cast<std::ostream*>(png_get_io_ptr(png))->flush();
}

// encodes with libpng; returns false when libpng reported an error. libpng reports errors
// by longjmp, so this function holds no object with a destructor.
bool encode(std::ostream* out, png_uint_32 width, png_uint_32 height, const png_bytep* rows) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, info ? &info : nullptr);
    return false;
  }
  png_set_write_fn(png, out, write_to_stream, flush_stream);
  png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_write_info(png, info);
  png_write_image(png, const_cast<png_bytepp>(rows));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

void write_png(const std::filesystem::path& path, int width, int height,
               const std::vector<std::uint8_t>& rgb) {
  if (width <= 0 || height <= 0 ||
      rgb.size() != 3 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
    throw std::invalid_argument("write_png: the pixel buffer does not match the image size");
  std::vector<png_bytep> rows(static_cast<std::size_t>(height));
  for (std::size_t j = 0; j < rows.size(); ++j)
    rows[j] = const_cast<png_bytep>(rgb.data() + 3 * static_cast<std::size_t>(width) * j);
  write_atomically(path, [&](std::ostream& out) {
    if (!encode(&out, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height),
                rows.data()))
      throw InputError(path.string(), "", "libpng could not encode the image");
  });
}

}  // namespace penumbra
