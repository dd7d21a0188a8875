// The replay program: runs fuzz targets (fuzz_target.h) over files, without libFuzzer, so
// that the ordinary build and CTest check the kept corpus and every input that once failed.
//
//   penumbra_fuzz_replay --list               the targets' names, one a line
//   penumbra_fuzz_replay TARGET PATH...       the target on each file (or each file under a
//                                             directory, in name order)
//
// An input passes when the target returns or throws InputError; another exception fails it
// (a crash ends the program, which CTest reports). Exit status: 0 all passed, 1 some failed
// or there were no inputs at all, 2 bad arguments.

#include <algorithm>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <vector>

#include "fuzz_target.h"

namespace penumbra::fuzz {

namespace {

std::map<std::string, TargetFunction>& targets() {
  static std::map<std::string, TargetFunction> table;
  return table;
}

// returns the files under path in name order: path itself when it is a file, none when it
// does not exist (a target with no regression yet has no directory for them).
std::vector<std::filesystem::path> files_under(const std::filesystem::path& path) {
  std::vector<std::filesystem::path> files;
  if (!std::filesystem::exists(path)) return files;
  if (std::filesystem::is_directory(path)) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(path))
      if (entry.is_regular_file()) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
  } else {
    files.push_back(path);
  }
  return files;
}

}  // namespace

bool register_target(const char* name, TargetFunction function) {
  targets()[name] = function;
  return true;
}

}  // namespace penumbra::fuzz

int main(int argc, char** argv) {
  using namespace penumbra::fuzz;
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.size() == 1 && args[0] == "--list") {
    for (const auto& [name, function] : targets()) std::cout << name << "\n";
    return 0;
  }
  if (args.size() < 2 || targets().count(args[0]) == 0) {
    std::cerr << "usage: penumbra_fuzz_replay --list | TARGET PATH...\n";
    return 2;
  }
  const TargetFunction function = targets()[args[0]];
  std::size_t inputs = 0, failed = 0;
  for (std::size_t k = 1; k < args.size(); ++k)
    for (const std::filesystem::path& file : files_under(args[k])) {
      std::ifstream in(file, std::ios::binary);
      const std::string bytes{std::istreambuf_iterator<char>(in), {}};
      ++inputs;
      try {
        run(function, reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
      } catch (const std::exception& error) {
        ++failed;
        std::cerr << args[0] << ": " << file.string() << ": uncaught exception: " << error.what()
                  << "\n";
      }
    }
  std::cout << args[0] << ": " << inputs << " inputs, " << failed << " failed\n";
  if (inputs == 0) std::cerr << args[0] << ": no inputs (a misspelt directory?)\n";
  return failed == 0 && inputs > 0 ? 0 : 1;
}
