#pragma once
// The default snap grid as docs/scene-format.md ("Snapping") states it, computed here
// without the importer: a file's single-precision coordinate (times the scale) goes to the
// nearest multiple of 2^-20 m, the largest power of two not above 1e-6, ties away from zero.

#include <cmath>

#include "penumbra/geometry/kernel.h"

namespace penumbra::test {

// the grid point the importer must give the file's value x (already scaled; a double
// holding the file's float exactly, e.g. 2.0 * 0.47f).
inline Exact on_default_grid(double x) {
  const double step = std::ldexp(1.0, -20);
  return Exact(std::round(x / step)) * Exact(step);
}

}  // namespace penumbra::test
