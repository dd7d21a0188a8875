#pragma once
// Raised by geometry constructions when their input cannot make the asked-for
// object (too few non-coplanar points, a non-convex polygon). The scene layer
// wraps it into an InputError that names the file and JSON path.

#include <stdexcept>
#include <string>

namespace penumbra {

class GeometryError : public std::runtime_error {
 public:
  // index: the input point the problem is about, or -1.
  explicit GeometryError(const std::string& message, int index = -1)
      : std::runtime_error(message), index_(index) {}

  int index() const { return index_; }

 private:
  int index_;
};

}  // namespace penumbra
