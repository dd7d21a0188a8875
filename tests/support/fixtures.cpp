#include "support/fixtures.h"

#include <png.h>
#include <sys/wait.h>
#include <unistd.h>
#include <zlib.h>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace penumbra::test {

std::filesystem::path source_dir() {
  if (const char* dir = std::getenv("PENUMBRA_SOURCE_DIR")) return dir;
  return PENUMBRA_SOURCE_DIR;
}

std::filesystem::path fixture(const std::string& relative) {
  return source_dir() / "fixtures" / relative;
}

std::filesystem::path photometry_fixture(const std::string& relative) {
  return fixture("photometry/" + relative);
}

std::filesystem::path gunzip_fixture(const std::string& relative) {
  const auto source = fixture(relative + ".gz");
  gzFile in = gzopen(source.string().c_str(), "rb");
  if (!in) throw std::runtime_error("cannot open " + source.string());
  const auto name = std::filesystem::path(relative).filename();
  const auto target = scratch_dir("gunzip-" + name.string()) / name;
  std::ofstream out(target, std::ios::binary);
  char buffer[1 << 16];
  int count = 0;
  while ((count = gzread(in, buffer, sizeof buffer)) > 0) out.write(buffer, count);
  const bool failed = count < 0;
  gzclose(in);
  if (failed || !out) throw std::runtime_error("cannot decompress " + source.string());
  return target;
}

std::filesystem::path penumbra_binary() {
  if (const char* binary = std::getenv("PENUMBRA_BINARY")) return binary;
  return "penumbra";
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::pair<unsigned, unsigned> png_size(const std::string& bytes) {
  // Width and height are big-endian words at bytes 16..23 (IHDR).
  const auto word = [&](std::size_t at) {
    unsigned value = 0;
    for (std::size_t k = 0; k < 4; ++k)
      value = (value << 8) | static_cast<unsigned char>(bytes[at + k]);
    return value;
  };
  return {word(16), word(20)};
}

PngImage read_png(const std::filesystem::path& path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.string().c_str()))
    throw std::runtime_error("cannot read " + path.string() + ": " + image.message);
  image.format = PNG_FORMAT_RGB;
  PngImage result;
  result.width = image.width;
  result.height = image.height;
  result.rgb.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, result.rgb.data(), 0, nullptr))
    throw std::runtime_error("cannot decode " + path.string() + ": " + image.message);
  return result;
}

std::filesystem::path scratch_dir(const std::string& name) {
  // One directory per process: CTest runs the layers' executables in parallel.
  const auto dir = std::filesystem::temp_directory_path() /
                   ("penumbra-test-" + std::to_string(getpid()) + "-" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

CommandResult run_penumbra(const std::string& arguments) {
  const auto dir = scratch_dir("command");
  const std::string command = "'" + penumbra_binary().string() + "' " + arguments + " >'" +
                              (dir / "out").string() + "' 2>'" + (dir / "err").string() + "'";
  const int raw = std::system(command.c_str());
  const int status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return {status, read_text(dir / "out"), read_text(dir / "err")};
}

std::map<std::string, std::vector<std::string>> csv_columns(const std::string& text) {
  std::istringstream in(text);
  std::string line, field;
  std::getline(in, line);
  std::vector<std::string> names;
  for (std::istringstream header(line); std::getline(header, field, ',');) names.push_back(field);
  std::map<std::string, std::vector<std::string>> out;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    for (const std::string& name : names) {
      std::getline(row, field, ',');
      out[name].push_back(field);
    }
  }
  return out;
}

}  // namespace penumbra::test
