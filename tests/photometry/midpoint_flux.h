#pragma once
// An independent flux integration for the photometry tests: the midpoint rule in
// u = cos(gamma) (1440 bands) and C (720 steps) over Distribution::intensity(),
// sharing nothing with the library's own flux integral.

#include <cmath>

#include "penumbra/base/numbers.h"
#include "penumbra/photometry/distribution.h"

namespace penumbra::photometry::test {

inline double midpoint_flux(const Distribution& lid) {
  using penumbra::pi;
  constexpr int nu = 1440, nc = 720;
  double total = 0;
  for (int i = 0; i < nu; ++i) {
    const double gamma = std::acos(1 - (i + 0.5) * 2.0 / nu);
    for (int j = 0; j < nc; ++j) total += lid.intensity(gamma, (j + 0.5) * 2 * pi / nc);
  }
  return total * (2.0 / nu) * (2 * pi / nc);
}

}  // namespace penumbra::photometry::test
