#include "penumbra/base/atomic_file.h"

#include <random>
#include <system_error>

#include "penumbra/base/input_error.h"

namespace penumbra {

AtomicFile::AtomicFile(std::filesystem::path path) : path_(std::move(path)) {
  std::random_device entropy;
  temporary_ = path_;
  temporary_ += ".tmp-" + std::to_string(entropy());
  out_.open(temporary_, std::ios::binary);
  if (!out_) throw InputError(path_.string(), "", "cannot create the output file");
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  out_.close();
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
}

void AtomicFile::commit() {
  out_.flush();
  if (!out_) throw InputError(path_.string(), "", "writing the output file failed");
  out_.close();
  std::error_code error;
  std::filesystem::rename(temporary_, path_, error);
  if (error) throw InputError(path_.string(), "", "cannot move the finished output into place");
  committed_ = true;
}

void write_atomically(const std::filesystem::path& path,
                      const std::function<void(std::ostream&)>& write) {
  AtomicFile file(path);
  write(file.stream());
  file.commit();
}

}  // namespace penumbra
