#pragma once
// Output files are written whole or not at all (DESIGN.md: "Nothing is written on
// error"): the content goes to a temporary beside the target, renamed into place
// only when writing finished without an exception.

#include <filesystem>
#include <fstream>
#include <functional>
#include <ostream>

namespace penumbra {

// An output file written piece by piece (so that several outputs can be streamed side by
// side): the temporary is renamed into place by commit(), and removed if the object is
// destroyed before, e.g. by an exception.
class AtomicFile {
 public:
  // creates the temporary beside path. Throws InputError when it cannot be created.
  explicit AtomicFile(std::filesystem::path path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& stream() { return out_; }

  // flushes and moves the finished file into place. Throws InputError when writing failed
  // or the file cannot be moved (then nothing is left behind).
  void commit();

 private:
  std::filesystem::path path_;
  std::filesystem::path temporary_;
  std::ofstream out_;
  bool committed_ = false;
};

// writes the file at path with write(stream). Throws InputError when the file
// cannot be created; rethrows write's exceptions, leaving no file behind.
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(std::ostream&)>& write);

}  // namespace penumbra
