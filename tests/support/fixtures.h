#pragma once
// The one helper tests use to find data: the repository's fixtures/, photometric files
// included (STYLE.md habit 9). Nothing outside the repository is read.

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace penumbra::test {

// returns the repository's top directory.
std::filesystem::path source_dir();
// returns fixtures/<relative>.
std::filesystem::path fixture(const std::string& relative);
// returns fixtures/photometry/<relative>: real photometric files (their provenance in
// fixtures/photometry/README.md).
std::filesystem::path photometry_fixture(const std::string& relative);
// returns a decompressed copy of fixtures/<relative>.gz in the build's temporary area
// (a real model too large for the repository is kept gzip-compressed; the copy has
// relative's file name, so readers still choose the format by its extension).
std::filesystem::path gunzip_fixture(const std::string& relative);
// returns the built penumbra executable (from CTest's environment).
std::filesystem::path penumbra_binary();

// result of running a command: exit status and what it printed.
struct CommandResult {
  int status;
  std::string out;
  std::string err;
};
// runs the penumbra executable with arguments (a shell-quoted string).
CommandResult run_penumbra(const std::string& arguments);

// returns a fresh empty directory under the build's temporary area.
std::filesystem::path scratch_dir(const std::string& name);

// returns a PNG's width and height, read from its IHDR chunk.
std::pair<unsigned, unsigned> png_size(const std::string& bytes);

// An 8-bit RGB image as read back from a PNG file.
struct PngImage {
  unsigned width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // 3 bytes per pixel, rows from the top

  std::array<int, 3> at(unsigned i, unsigned j) const {
    const std::size_t k = 3 * (static_cast<std::size_t>(j) * width + i);
    return {rgb[k], rgb[k + 1], rgb[k + 2]};
  }
};
// reads an 8-bit RGB PNG through libpng (an independent reader of what the writer wrote).
PngImage read_png(const std::filesystem::path& path);

// reads a whole file.
std::string read_text(const std::filesystem::path& path);
// returns the columns of a CSV text with a header line, by name (plain fields: no quoting).
std::map<std::string, std::vector<std::string>> csv_columns(const std::string& text);

}  // namespace penumbra::test
