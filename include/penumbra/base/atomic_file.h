#pragma once
// Output files are written whole or not at all (DESIGN.md: "Nothing is written on
// error"): the content goes to a temporary beside the target, renamed into place
// only when writing finished without an exception.

#include <filesystem>
#include <functional>
#include <ostream>

namespace penumbra {

// writes the file at path with write(stream). Throws InputError when the file
// cannot be created; rethrows write's exceptions, leaving no file behind.
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(std::ostream&)>& write);

}  // namespace penumbra
