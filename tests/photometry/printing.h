#pragma once
// Lets Boost.Test print the photometry layer's enumerations in failure messages.

#include <ostream>

#include "penumbra/photometry/distribution.h"

namespace penumbra::photometry {

inline std::ostream& operator<<(std::ostream& out, Symmetry symmetry) {
  return out << symmetry_name(symmetry);
}

}  // namespace penumbra::photometry
