#include "interval_filters.h"

#include <algorithm>
#include <array>
#include <optional>

namespace penumbra::illuminance::detail {
namespace {

// whether x is strictly on the negative side of plane_of(item) for every item: inside an
// open convex volume (its planes), or a solid's interior (its faces). Precondition: items
// is not empty.
template <class Items, class PlaneOf>
Certainly negative_everywhere(const Items& items, PlaneOf plane_of, const Vec3d& x) {
  const CGAL::Protect_FPU_rounding<true> upward;
  Certainly answer = Certainly::yes;
  for (const auto& item : items) {
    const Interval value = plane_value(plane_of(item).approx(), x);
    if (value.inf() >= 0) return Certainly::no;
    if (!(value.sup() < 0)) answer = Certainly::unknown;
  }
  return answer;
}

}  // namespace

Interval dot_difference(const Vec3d& n, const Vec3d& to, const Vec3d& from) {
  return Interval(n[0]) * (Interval(to[0]) - from[0]) +
         Interval(n[1]) * (Interval(to[1]) - from[1]) +
         Interval(n[2]) * (Interval(to[2]) - from[2]);
}

Certainly inside_open_volume(const std::vector<Plane3>& planes, const Vec3d& x) {
  return negative_everywhere(
      planes, [](const Plane3& plane) -> const Plane3& { return plane; }, x);
}

Certainly inside_solid(const ConvexPolyhedron& solid, const Vec3d& x) {
  return negative_everywhere(
      solid.faces(), [](const Face& face) -> const Plane3& { return face.plane; }, x);
}

Certainly outer_side(const Vec3d& normal, const Vec3d& target, const Vec3d& point) {
  const CGAL::Protect_FPU_rounding<true> upward;
  const Interval value = dot_difference(normal, target, point);
  if (value.inf() > 0) return Certainly::yes;
  if (value.sup() <= 0) return Certainly::no;
  return Certainly::unknown;
}

Certainly ray_meets_solid(const ConvexPolyhedron& solid, const Vec3d& point, const Vec3d& toward,
                          const Vec3d* end) {
  const CGAL::Protect_FPU_rounding<true> upward;
  Interval low(0);
  std::optional<Interval> high;
  if (end) high = Interval(1);
  bool certain = true;
  for (const Face& face : solid.faces()) {
    const auto& plane = face.plane.approx();
    const Interval at_point = plane_value(plane, point);
    const Interval slope = end ? plane_value(plane, *end) - at_point : normal_dot(plane, toward);
    // On the closed outer side and not heading in: the ray never enters.
    if (at_point.inf() >= 0 && slope.inf() >= 0) return Certainly::no;
    if (slope.inf() > 0) {
      const Interval crossing = -at_point / slope;
      high = high ? Interval(std::min(high->inf(), crossing.inf()),
                             std::min(high->sup(), crossing.sup()))
                  : crossing;
    } else if (slope.sup() < 0) {
      const Interval crossing = -at_point / slope;
      low = Interval(std::max(low.inf(), crossing.inf()), std::max(low.sup(), crossing.sup()));
    } else {
      certain = false;
      continue;
    }
    // The clip by some of the planes is already empty: so is the clip by all.
    if (high && low.inf() >= high->sup()) return Certainly::no;
  }
  if (certain && (!high || low.sup() < high->inf())) return Certainly::yes;
  return Certainly::unknown;
}

Certainly ray_meets_polygon(const ConvexPolyhedron& polygon, const Vec3d& point,
                            const Vec3d& toward) {
  const CGAL::Protect_FPU_rounding<true> upward;
  const Face& face = polygon.faces().front();
  const auto& plane = face.plane.approx();
  const Interval at_point = plane_value(plane, point);
  const Interval slope = normal_dot(plane, toward);
  // Parallel, or the plane not ahead: no crossing at t > 0.
  if ((slope.inf() == 0 && slope.sup() == 0) || (at_point.inf() >= 0 && slope.inf() >= 0) ||
      (at_point.sup() <= 0 && slope.sup() <= 0))
    return Certainly::no;
  if (!(at_point.inf() > 0 || at_point.sup() < 0) || !(slope.inf() > 0 || slope.sup() < 0))
    return Certainly::unknown;
  const Interval t = -at_point / slope;
  const Interval x[3] = {point[0] + t * toward[0], point[1] + t * toward[1],
                         point[2] + t * toward[2]};
  const Interval normal[3] = {plane.a(), plane.b(), plane.c()};
  int left = 0, right = 0;
  const std::size_t n = face.vertices.size();
  for (std::size_t k = 0; k < n; ++k) {
    const auto& from = face.vertices[k].approx();
    const auto& to = face.vertices[(k + 1) % n].approx();
    const Interval edge[3] = {to.x() - from.x(), to.y() - from.y(), to.z() - from.z()};
    const Interval offset[3] = {x[0] - from.x(), x[1] - from.y(), x[2] - from.z()};
    // (edge x normal) . offset: the side of x from the edge line, within the plane.
    const Interval side = (edge[1] * normal[2] - edge[2] * normal[1]) * offset[0] +
                          (edge[2] * normal[0] - edge[0] * normal[2]) * offset[1] +
                          (edge[0] * normal[1] - edge[1] * normal[0]) * offset[2];
    left += side.sup() < 0;
    right += side.inf() > 0;
  }
  if (left > 0 && right > 0) return Certainly::no;
  if (left == static_cast<int>(n) || right == static_cast<int>(n)) return Certainly::yes;
  return Certainly::unknown;
}

bool misses_triangle(const Occluder& occluder, const Vec3d& point, const Vec3d& a, const Vec3d& b) {
  const CGAL::Protect_FPU_rounding<true> upward;
  const ConvexPolyhedron& solid = *occluder.solid;
  for (const Face& face : solid.faces()) {
    const auto& plane = face.plane.approx();
    const Interval at_point = plane_value(plane, point), at_a = plane_value(plane, a),
                   at_b = plane_value(plane, b);
    if (solid.is_flat() ? at_point.inf() > 0 && at_a.inf() > 0 && at_b.inf() > 0
                        : at_point.inf() >= 0 && at_a.inf() >= 0 && at_b.inf() >= 0)
      return true;
  }
  // Against the box, relative to point: the triangle is (0, to_a, to_b).
  IntervalPoint to_a, to_b, centre, half;
  for (int i = 0; i < 3; ++i) {
    to_a[i] = Interval(a[i]) - point[i];
    to_b[i] = Interval(b[i]) - point[i];
    centre[i] = (Interval(occluder.box.low[i]) + occluder.box.high[i]) / 2 - point[i];
    half[i] = (Interval(occluder.box.high[i]) - occluder.box.low[i]) / 2;
  }
  const auto separates = [&](const IntervalPoint& axis) {
    const Interval along_a = axis[0] * to_a[0] + axis[1] * to_a[1] + axis[2] * to_a[2];
    const Interval along_b = axis[0] * to_b[0] + axis[1] * to_b[1] + axis[2] * to_b[2];
    const Interval middle = axis[0] * centre[0] + axis[1] * centre[1] + axis[2] * centre[2];
    const Interval radius =
        CGAL::abs(axis[0]) * half[0] + CGAL::abs(axis[1]) * half[1] + CGAL::abs(axis[2]) * half[2];
    const double box_low = (middle - radius).inf(), box_high = (middle + radius).sup();
    const double triangle_low = std::min({0.0, along_a.inf(), along_b.inf()});
    const double triangle_high = std::max({0.0, along_a.sup(), along_b.sup()});
    // A zero axis (parallel edges, a degenerate triangle) separates nothing.
    const bool zero = std::all_of(axis.begin(), axis.end(),
                                  [](const Interval& c) { return c.inf() <= 0 && c.sup() >= 0; });
    return !zero && (solid.is_flat() ? triangle_high < box_low || box_high < triangle_low
                                     : triangle_high <= box_low || box_high <= triangle_low);
  };
  if (separates(cross(to_a, to_b))) return true;
  const IntervalPoint source{to_b[0] - to_a[0], to_b[1] - to_a[1], to_b[2] - to_a[2]};
  for (int i = 0; i < 3; ++i) {
    IntervalPoint unit{Interval(0), Interval(0), Interval(0)};
    unit[i] = Interval(1);
    for (const IntervalPoint* edge : std::array<const IntervalPoint*, 3>{&to_a, &to_b, &source})
      if (separates(cross(*edge, unit))) return true;
  }
  return false;
}

TubeCull cull_for_tube(const Occluder& occluder, const Box& triangle, const Vec3d& point,
                       const LinearLight& light, bool whole_source) {
  if (!overlap(occluder.box, triangle) || misses_triangle(occluder, point, light.start, light.end))
    return TubeCull::misses;
  if (whole_source && !occluder.solid->is_flat() &&
      ray_meets_solid(*occluder.solid, point, {}, &light.start) == Certainly::yes &&
      ray_meets_solid(*occluder.solid, point, {}, &light.end) == Certainly::yes)
    return TubeCull::hides_all;
  return TubeCull::examine;
}

}  // namespace penumbra::illuminance::detail
