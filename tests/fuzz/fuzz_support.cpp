// The scratch files of the fuzz targets (fuzz_target.h).

#include <unistd.h>

#include <fstream>

#include "fuzz_target.h"

namespace penumbra::fuzz {

std::filesystem::path scratch_file(const std::string& name, const std::uint8_t* data,
                                   std::size_t size) {
  static const std::filesystem::path directory = [] {
    const std::filesystem::path made =
        std::filesystem::temp_directory_path() / ("penumbra-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(made);
    return made;
  }();
  const std::filesystem::path path = directory / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

}  // namespace penumbra::fuzz
