#include "dask_driver.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include "penumbra/base/input_error.h"

namespace penumbra::cli {
namespace {

namespace fs = std::filesystem;

// A directory of its own for the request and result files, removed at exit.
struct Scratch {
  fs::path directory;
  Scratch() {
    std::string pattern = (fs::temp_directory_path() / "penumbra-dask-XXXXXX").string();
    if (!mkdtemp(pattern.data()))
      throw InputError("", "--dask",
                       "cannot make a scratch directory in " + fs::temp_directory_path().string());
    directory = pattern;
  }
  ~Scratch() {
    std::error_code ignored;
    fs::remove_all(directory, ignored);
  }
};

Scratch& scratch() {
  static Scratch made;
  return made;
}

// where the module is: $PENUMBRA_PYTHONPATH, else the build tree's package, else the
// installed one (both known when this program was built).
std::string module_directory() {
  if (const char* given = std::getenv("PENUMBRA_PYTHONPATH")) return given;
#ifdef PENUMBRA_PYTHON_BUILD_DIR
  if (fs::exists(fs::path(PENUMBRA_PYTHON_BUILD_DIR) / "penumbra" / "_driver.py"))
    return PENUMBRA_PYTHON_BUILD_DIR;
#endif
#ifdef PENUMBRA_PYTHON_INSTALL_DIR
  return PENUMBRA_PYTHON_INSTALL_DIR;
#else
  throw InputError("", "--dask", "this penumbra was built without its Python module");
#endif
}

}  // namespace

std::string dask_scratch_file(const std::string& name) {
  return (scratch().directory / name).string();
}

std::string run_on_dask(const std::string& scheduler, nlohmann::json request) {
  const std::string python_path = module_directory();
  request["scheduler"] = scheduler;
  const std::string request_file = dask_scratch_file("request.json");
  const std::string result_file = dask_scratch_file("result");
  std::ofstream(request_file) << request.dump();
#ifdef PENUMBRA_PYTHON_EXECUTABLE
  const std::string python = PENUMBRA_PYTHON_EXECUTABLE;
#else
  const std::string python = "python3";
#endif
  std::vector<std::string> words{python, "-m", "penumbra._driver", request_file, result_file};
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  const char* old = std::getenv("PYTHONPATH");
  const std::string path = python_path + (old && *old ? ":" + std::string(old) : "");
  const pid_t child = fork();
  if (child == 0) {
    setenv("PYTHONPATH", path.c_str(), 1);
    execvp(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  if (child < 0 || waitpid(child, &status, 0) < 0)
    throw InputError("", "--dask", "cannot start " + python);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
      throw InputError("", "--dask", "cannot run " + python);
    throw InputError("", "--dask", "the job on " + scheduler + " failed (the message above)");
  }
  return result_file;
}

}  // namespace penumbra::cli
