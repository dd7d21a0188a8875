#include "penumbra/illuminance/linear_source.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "adaptive_quadrature.h"
#include "line_frame.h"
#include "penumbra/base/vec3d.h"

namespace penumbra::illuminance {

using namespace vector_ops;

namespace detail {

LineFrame line_frame(const Vec3d& point, const Vec3d& normal, const Vec3d& a, const Vec3d& b) {
  LineFrame frame;
  const Vec3d along = b - a;
  frame.length = length(along);
  if (!(frame.length > 0)) return frame;
  frame.axis = (1 / frame.length) * along;
  // Measure the foot of the perpendicular from the endpoint nearer to P, so that the
  // perpendicular w loses as little as possible to cancellation.
  const Vec3d from_a = a - point;
  const Vec3d from_b = b - point;
  const bool use_b = dot(from_b, from_b) < dot(from_a, from_a);
  const Vec3d& base = use_b ? from_b : from_a;
  const double t_base = dot(base, frame.axis);
  frame.t_a = use_b ? t_base - frame.length : t_base;
  frame.perpendicular = base - t_base * frame.axis;
  frame.distance = length(frame.perpendicular);
  frame.axial = dot(normal, frame.axis);
  frame.lateral = frame.distance > 0 ? dot(normal, frame.perpendicular) / frame.distance : 0;
  return frame;
}

}  // namespace detail

namespace {

using namespace detail;

// returns (atan(z) - z) / z for z >= 0 without cancellation: its Taylor series
// -z^2/3 + z^4/5 - ... for small z (terms below 0.2^24 ~ 1.7e-17 dropped), else directly.
double atan_ratio_minus_one(double z) {
  if (z < 0.2) {
    const double z2 = z * z;
    double sum = 0;
    for (int k = 12; k >= 1; --k) sum = z2 * ((k % 2 == 1 ? -1.0 : 1.0) / (2 * k + 1) + sum);
    return sum;
  }
  return std::atan(z) / z - 1;
}

// returns the integral over 0 <= t0 <= t <= t1 (t1 - t0 = delta) of
//     h (axial t + lateral h) / (t^2 + h^2)^2,
// i.e. axial * J1 + lateral * J0 with (docs/illuminance.md, "Derivation")
//     J1 = [-cos^2(phi) / (2h)],  J0 = [(phi + sin(phi) cos(phi)) / (2h)],  phi = atan(t / h),
// evaluated so that no step cancels catastrophically.
double half_line_integral(double axial, double lateral, double h, double t0, double t1,
                          double delta) {
  const double h2 = h * h;
  const double r0_squared = t0 * t0 + h2;
  const double r1_squared = t1 * t1 + h2;
  // J1 = h (t1^2 - t0^2) / (2 r0^2 r1^2): the difference of the two cos^2 terms factored.
  const double j1 = 0.5 * (h / r0_squared) * (delta / r1_squared) * (t1 + t0);
  double j0;
  if (t0 * t1 <= h2) {
    // Both angles within pi/4 of each other around the foot: the angle difference is
    // atan2(cross, dot) of (h, t0) and (h, t1), and sin(phi)cos(phi) = t h / r^2 differs by
    // h delta (h^2 - t0 t1) / (r0^2 r1^2) >= 0; the two terms add, nothing cancels.
    const double angle = std::atan2(h * delta, h2 + t0 * t1);
    const double product = (h / r0_squared) * (delta / r1_squared) * (h2 - t0 * t1);
    j0 = (angle + product) / (2 * h);
  } else {
    // Far along the line both angles approach pi/2 and phi + sin(phi)cos(phi) ~ pi/2 - (2/3)
    // psi^3 (psi = pi/2 - phi) would cancel. With x = h / t = tan(psi):
    //     phi + sin cos = pi/2 - g(x),  g(x) = atan(x) - x / (1 + x^2),
    // and g(x0) - g(x1) = dx * numerator / denominator with dx = x0 - x1,
    // z = dx / (1 + x0 x1), A = atan(z) / z:
    //     numerator = (A - 1)(1 + x0^2)(1 + x1^2) + x0^2 + x1^2 + 2 x0^2 x1^2,
    //     denominator = (1 + x0 x1)(1 + x0^2)(1 + x1^2).
    // Since dx^2 <= x0^2 + x1^2 and A - 1 ~ -z^2/3, the numerator's terms do not cancel.
    const double x0 = h / t0;
    const double x1 = h / t1;
    const double dx = x0 * (delta / t1);
    const double x0_squared = x0 * x0;
    const double x1_squared = x1 * x1;
    const double product = x0 * x1;
    const double z = dx / (1 + product);
    const double both = (1 + x0_squared) * (1 + x1_squared);
    const double numerator =
        atan_ratio_minus_one(z) * both + x0_squared + x1_squared + 2 * x0_squared * x1_squared;
    j0 = dx * numerator / ((1 + product) * both) / (2 * h);
  }
  return axial * j1 + lateral * j0;
}

// returns E / I over the source parameters [u0, u1] (already inside the outer-side
// interval), the closed form of eq. (5) for any orientation.
double closed_form(const LineFrame& frame, double u0, double u1) {
  const double h = frame.distance;
  // P on the line of the source: sin(theta) = 0 for every element. (Also when h^2
  // underflows, h < 1e-154 m, which no scene in metres produces.)
  if (!(h * h > 0)) return 0;
  const double delta = (u1 - u0) * frame.length;
  if (!(delta > 0)) return 0;
  const double t0 = frame.t_a + u0 * frame.length;
  const double t1 = frame.t_a + u1 * frame.length;
  double sum;
  // Split at the foot of the perpendicular (t = 0) so each piece has t of one sign; the
  // piece at negative t maps to positive t by t -> -t, which flips the axial term.
  if (t0 >= 0) {
    sum = half_line_integral(frame.axial, frame.lateral, h, t0, t1, delta);
  } else if (t1 <= 0) {
    sum = half_line_integral(-frame.axial, frame.lateral, h, -t1, -t0, delta);
  } else {
    sum = half_line_integral(-frame.axial, frame.lateral, h, 0, -t0, -t0) +
          half_line_integral(frame.axial, frame.lateral, h, 0, t1, t1);
  }
  // The integrand is >= 0 on the outer-side interval; only rounding at a clipped end can
  // make the sum a few ulps negative.
  return std::max(0.0, sum);
}

void check_intervals(const std::vector<SourceInterval>& visible) {
  for (const auto& [first, second] : visible)
    if (!(0 <= first && first <= second && second <= 1))
      throw std::invalid_argument("linear source interval must satisfy 0 <= first <= second <= 1");
}

// calls add(u0, u1) for each visible interval clipped to the outer-side interval.
template <class Add>
void for_each_lit_interval(const std::optional<SourceInterval>& outer,
                           const std::vector<SourceInterval>& visible, Add add) {
  if (!outer) return;
  for (const auto& [first, second] : visible) {
    const double lo = std::max(first, outer->first);
    const double hi = std::min(second, outer->second);
    if (hi > lo) add(lo, hi);
  }
}

// returns the eq. (5) integrand (without I) at the element Q with Q - P = v, computed
// straight from the vectors: sin(theta) cos(alpha) / r^2 = |d x v| (N . v) / r^4.
double eq5_integrand(const Vec3d& axis, const Vec3d& normal, const Vec3d& v) {
  const double signed_distance = dot(normal, v);
  if (!(signed_distance > 0)) return 0;
  const double r_squared = dot(v, v);
  return length(cross(axis, v)) * signed_distance / (r_squared * r_squared);
}

double quadrature(const LineFrame& frame, const Vec3d& normal, double u0, double u1,
                  const QuadratureOptions& options) {
  const QuadratureSpan span = quadrature_span(frame, u0, u1);
  // The integrand peaks at the foot of the perpendicular with width h.
  return integrate_adaptive(
      [&](double sigma) {
        return eq5_integrand(frame.axis, normal, span.origin + sigma * frame.axis);
      },
      graded_breakpoints(span.lo, span.hi, span.foot, frame.distance), options);
}

}  // namespace

std::optional<SourceInterval> outer_side_interval(const Vec3d& point, const Vec3d& normal,
                                                  const Vec3d& a, const Vec3d& b) {
  // Nishita 1985 Fig. 7: F(S_f, Q) = N . (Q - P) is linear along the source; keep where > 0.
  const double at_a = dot(normal, a - point);
  const double at_b = dot(normal, b - point);
  const bool a_outside = at_a > 0;
  const bool b_outside = at_b > 0;
  if (a_outside && b_outside) return SourceInterval{0.0, 1.0};
  if (!a_outside && !b_outside) return std::nullopt;
  const double crossing = std::clamp(at_a / (at_a - at_b), 0.0, 1.0);
  return a_outside ? SourceInterval{0.0, crossing} : SourceInterval{crossing, 1.0};
}

double linear_illuminance(const Vec3d& point, const Vec3d& normal, const Vec3d& a, const Vec3d& b,
                          double candela_per_metre) {
  const auto outer = outer_side_interval(point, normal, a, b);
  if (!outer) return 0;
  const LineFrame frame = line_frame(point, normal, a, b);
  if (!(frame.length > 0)) return 0;
  return candela_per_metre * closed_form(frame, outer->first, outer->second);
}

double linear_illuminance(const Vec3d& point, const Vec3d& normal, const Vec3d& a, const Vec3d& b,
                          double candela_per_metre, const std::vector<SourceInterval>& visible) {
  check_intervals(visible);
  const auto outer = outer_side_interval(point, normal, a, b);
  if (!outer) return 0;
  const LineFrame frame = line_frame(point, normal, a, b);
  if (!(frame.length > 0)) return 0;
  double sum = 0;
  for_each_lit_interval(outer, visible,
                        [&](double lo, double hi) { sum += closed_form(frame, lo, hi); });
  return candela_per_metre * sum;
}

double linear_illuminance_quadrature(const Vec3d& point, const Vec3d& normal, const Vec3d& a,
                                     const Vec3d& b, double candela_per_metre,
                                     const QuadratureOptions& options) {
  return linear_illuminance_quadrature(point, normal, a, b, candela_per_metre, {{0.0, 1.0}},
                                       options);
}

double linear_illuminance_quadrature(const Vec3d& point, const Vec3d& normal, const Vec3d& a,
                                     const Vec3d& b, double candela_per_metre,
                                     const std::vector<SourceInterval>& visible,
                                     const QuadratureOptions& options) {
  check_intervals(visible);
  const LineFrame frame = line_frame(point, normal, a, b);
  if (!(frame.length > 0)) return 0;
  double sum = 0;
  for_each_lit_interval(
      outer_side_interval(point, normal, a, b), visible,
      [&](double lo, double hi) { sum += quadrature(frame, normal, lo, hi, options); });
  return candela_per_metre * sum;
}

}  // namespace penumbra::illuminance
