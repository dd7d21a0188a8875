#include "penumbra/base/atomic_file.h"

#include <fstream>
#include <random>
#include <system_error>

#include "penumbra/base/input_error.h"

namespace penumbra {

void write_atomically(const std::filesystem::path& path,
                      const std::function<void(std::ostream&)>& write) {
  std::random_device entropy;
  std::filesystem::path temporary = path;
  temporary += ".tmp-" + std::to_string(entropy());
  {
    std::ofstream out(temporary, std::ios::binary);
    if (!out) throw InputError(path.string(), "", "cannot create the output file");
    try {
      write(out);
      out.flush();
      if (!out) throw InputError(path.string(), "", "writing the output file failed");
    } catch (...) {
      out.close();
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      throw;
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    throw InputError(path.string(), "", "cannot move the finished output into place");
  }
}

}  // namespace penumbra
