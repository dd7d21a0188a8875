#pragma once
// PNG output through libpng: 8-bit RGB, tagged sRGB, written whole or not at all
// (write_atomically).

#include <cstdint>
#include <filesystem>
#include <vector>

namespace penumbra {

// writes an 8-bit sRGB image of width x height pixels; rgb holds 3 bytes per pixel, rows
// from the top. Throws InputError when the file cannot be written (nothing is left behind).
// Precondition: rgb.size() == 3 * width * height.
void write_png(const std::filesystem::path& path, int width, int height,
               const std::vector<std::uint8_t>& rgb);

}  // namespace penumbra
