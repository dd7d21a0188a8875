#pragma once
// The one helper tests use to find data: the repository's fixtures/ and the
// shared photometric files in ../shared/data/photometry/ (STYLE.md habit 9).

#include <filesystem>
#include <string>
#include <utility>

namespace penumbra::test {

// returns the repository's top directory.
std::filesystem::path source_dir();
// returns fixtures/<relative>.
std::filesystem::path fixture(const std::string& relative);
// returns ../shared/data/photometry/<relative>.
std::filesystem::path shared_photometry(const std::string& relative);
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

// reads a whole file.
std::string read_text(const std::filesystem::path& path);

}  // namespace penumbra::test
