#pragma once
// Exact predicates on rings whose exact values are usually known already (shadow
// polygons from receiver_clip.h), made of same_point (exact.h).

#include "penumbra/geometry/exact.h"
#include "penumbra/shadow/region.h"

namespace penumbra::detail {

// returns true when the rings have the same points in the same order.
inline bool same_ring(const Ring2& a, const Ring2& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (!same_point(a[k], b[k])) return false;
  return true;
}

}  // namespace penumbra::detail
