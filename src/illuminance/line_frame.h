#pragma once
// The line of a linear source seen from a receiving point (private; docs/illuminance.md):
// Q(u) - P = (t_a + u L) d + w with d the unit axis, w perpendicular to d, h = |w|.

#include "penumbra/base/vec3d.h"
#include "penumbra/illuminance/linear_source.h"

namespace penumbra::illuminance::detail {

using namespace vector_ops;

struct LineFrame {
  double length = 0;             // L = |B - A|; 0 for a degenerate source (the rest is unset)
  Vec3d axis{0, 0, 0};           // d = (B - A) / L
  double t_a = 0;                // t of A along d, measured from the foot of the perpendicular
  Vec3d perpendicular{0, 0, 0};  // w, from P to the foot of the perpendicular on the line
  double distance = 0;           // h = |w|, distance from P to the line
  double axial = 0;              // N . d
  double lateral = 0;            // N . w / h (0 when h = 0)
};

// computes the frame of the line a -> b as seen from `point` with unit `normal`.
LineFrame line_frame(const Vec3d& point, const Vec3d& normal, const Vec3d& a, const Vec3d& b);

// The sub-segment [u0, u1] parametrised for quadrature: Q - P = origin + sigma d for sigma
// in [lo, hi], with origin the element of the sub-segment nearest to the foot. Nodes are
// then small offsets from an exactly stored origin, so neither a sharp peak at the foot
// (sigma = foot, width h) nor a tiny sub-segment far away is blurred by the rounding of
// large parameters.
struct QuadratureSpan {
  Vec3d origin;
  double lo, hi;  // sigma range
  double foot;    // sigma of the foot of the perpendicular (may lie outside [lo, hi])
};

inline QuadratureSpan quadrature_span(const LineFrame& frame, double u0, double u1) {
  const double t0 = frame.t_a + u0 * frame.length;
  const double t1 = frame.t_a + u1 * frame.length;
  const double span = (u1 - u0) * frame.length;
  QuadratureSpan result;
  if (t0 >= 0) {
    result = {t0 * frame.axis + frame.perpendicular, 0, span, -t0};
  } else if (t1 <= 0) {
    result = {t1 * frame.axis + frame.perpendicular, -span, 0, -t1};
  } else {
    result = {frame.perpendicular, t0, t1, 0};
  }
  return result;
}

}  // namespace penumbra::illuminance::detail
