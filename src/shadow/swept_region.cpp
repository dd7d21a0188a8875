#include "swept_region.h"

#include <algorithm>

namespace penumbra::detail {
namespace {

// returns normal . (x - origin). Needs upward rounding.
Interval dot_from(const IntervalPoint& normal, const IntervalPoint& x,
                  const IntervalPoint& origin) {
  return normal[0] * (x[0] - origin[0]) + normal[1] * (x[1] - origin[1]) +
         normal[2] * (x[2] - origin[2]);
}

// returns (to_a - origin) x (to_b - origin). Needs upward rounding.
IntervalPoint cross_from(const IntervalPoint& origin, const IntervalPoint& to_a,
                         const IntervalPoint& to_b) {
  const Interval a[3] = {to_a[0] - origin[0], to_a[1] - origin[1], to_a[2] - origin[2]};
  const Interval b[3] = {to_b[0] - origin[0], to_b[1] - origin[1], to_b[2] - origin[2]};
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace

SweptRegion::SweptRegion(const Face& face, const Point3& q1, const Point3& q2) {
  for (const Point3& v : face.vertices) points_.push_back(interval_point(v));
  const std::size_t n = points_.size();
  points_.push_back(interval_point(q1));
  points_.push_back(interval_point(q2));
  const IntervalPoint& a = points_[n];
  const IntervalPoint& b = points_[n + 1];
  // Candidate planes: through the tube and a face vertex; through a face edge and an end
  // of the tube; the face's own plane.
  for (std::size_t k = 0; k < n; ++k) {
    const IntervalPoint& v = points_[k];
    const IntervalPoint& w = points_[(k + 1) % n];
    add(v, cross_from(a, b, v));
    add(v, cross_from(v, w, a));
    add(v, cross_from(v, w, b));
  }
  if (n >= 3) add(points_[0], cross_from(points_[0], points_[1], points_[2]));
}

bool SweptRegion::separated_from(const ConvexPolyhedron& solid) const {
  const CGAL::Protect_FPU_rounding<true> upward;
  for (const Face& face : solid.faces()) {
    const auto& h = face.plane.approx();
    if (std::all_of(points_.begin(), points_.end(),
                    [&](const IntervalPoint& x) { return plane_value(h, x).inf() > 0; }))
      return true;
  }
  std::vector<IntervalPoint> vertices;
  for (const Point3& v : solid.vertices()) vertices.push_back(interval_point(v));
  for (const auto& [origin, normal] : planes_)
    if (std::all_of(vertices.begin(), vertices.end(),
                    [&](const IntervalPoint& x) { return dot_from(normal, x, origin).inf() > 0; }))
      return true;
  return false;
}

void SweptRegion::add(const IntervalPoint& origin, const IntervalPoint& normal) {
  const CGAL::Protect_FPU_rounding<true> upward;
  if (std::all_of(normal.begin(), normal.end(),
                  [](const Interval& c) { return c.inf() == 0 && c.sup() == 0; }))
    return;
  bool non_positive = true, non_negative = true;
  for (const IntervalPoint& x : points_) {
    const Interval value = dot_from(normal, x, origin);
    non_positive = non_positive && value.sup() <= 0;
    non_negative = non_negative && value.inf() >= 0;
  }
  if (non_positive)
    planes_.push_back({origin, normal});
  else if (non_negative)
    planes_.push_back({origin, {-normal[0], -normal[1], -normal[2]}});
}

}  // namespace penumbra::detail
