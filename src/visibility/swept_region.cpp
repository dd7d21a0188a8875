#include "penumbra/visibility/swept_region.h"

#include <algorithm>

namespace penumbra {
namespace {

// returns normal . (x - origin). Needs upward rounding.
Interval dot_from(const IntervalPoint& normal, const IntervalPoint& x,
                  const IntervalPoint& origin) {
  return dot(normal, minus(x, origin));
}

// returns (to_a - origin) x (to_b - origin). Needs upward rounding.
IntervalPoint cross_from(const IntervalPoint& origin, const IntervalPoint& to_a,
                         const IntervalPoint& to_b) {
  return cross(minus(to_a, origin), minus(to_b, origin));
}

}  // namespace

SweptRegion::SweptRegion(const Face& face, const Point3& q1, const Point3& q2)
    : SweptRegion(face, q1 == q2 ? std::vector<Point3>{q1} : std::vector<Point3>{q1, q2}) {}

SweptRegion::SweptRegion(const Face& face, const std::vector<Point3>& source)
    : SweptRegion(face.vertices, source) {}

SweptRegion::SweptRegion(const std::vector<Point3>& receiver, const std::vector<Point3>& source) {
  for (const Point3& v : receiver) points_.push_back(interval_point(v));
  const std::size_t n = points_.size();
  for (const Point3& q : source) points_.push_back(interval_point(q));
  const std::size_t m = source.size();
  // Candidate planes: through a source edge and a face vertex; through a face edge and a
  // source vertex; the face's plane and the source's. The points each plane is built through
  // lie on it exactly and decide nothing (their intervals straddle 0).
  const std::size_t source_edges = m < 2 ? 0 : m == 2 ? 1 : m;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t next = (k + 1) % n;
    const IntervalPoint& v = points_[k];
    const IntervalPoint& w = points_[next];
    for (std::size_t e = 0; e < source_edges; ++e) {
      const std::size_t a = n + e, b = n + (e + 1) % m;
      add(v, cross_from(points_[a], points_[b], v), {a, b, k});
    }
    for (std::size_t q = n; q < n + m; ++q) add(v, cross_from(v, w, points_[q]), {k, next, q});
  }
  std::vector<std::size_t> face_points(n), source_points(m);
  for (std::size_t k = 0; k < n; ++k) face_points[k] = k;
  for (std::size_t k = 0; k < m; ++k) source_points[k] = n + k;
  if (n >= 3) add(points_[0], cross_from(points_[0], points_[1], points_[2]), face_points);
  if (m >= 3)
    add(points_[n], cross_from(points_[n], points_[n + 1], points_[n + 2]), source_points);
}

SweptRegion::SweptRegion(const Face& face, const LightPosition& light) {
  if (!light.at_infinity()) {
    *this = SweptRegion(face, light.point(), light.point());
    return;
  }
  for (const Point3& v : face.vertices) points_.push_back(interval_point(v));
  const IntervalPoint travel = interval_point(light.travel());
  const CGAL::Protect_FPU_rounding<true> upward;
  const IntervalPoint s = {-travel[0], -travel[1], -travel[2]};
  toward_sun_ = s;
  // The prism's sides: through each edge, along s (so orthogonal to s exactly).
  const std::size_t n = points_.size();
  for (std::size_t k = 0; k < n; ++k) {
    const IntervalPoint& v = points_[k];
    const IntervalPoint& w = points_[(k + 1) % n];
    const Interval e[3] = {w[0] - v[0], w[1] - v[1], w[2] - v[2]};
    add(v, {e[1] * s[2] - e[2] * s[1], e[2] * s[0] - e[0] * s[2], e[0] * s[1] - e[1] * s[0]},
        {k, (k + 1) % n});
  }
  // Its base: the face's plane, the prism on the side the sun is on.
  if (n >= 3) {
    const IntervalPoint normal = cross_from(points_[0], points_[1], points_[2]);
    const Interval rise = normal[0] * s[0] + normal[1] * s[1] + normal[2] * s[2];
    if (rise.inf() > 0)
      planes_.push_back({points_[0], {-normal[0], -normal[1], -normal[2]}});
    else if (rise.sup() < 0)
      planes_.push_back({points_[0], normal});
  }
}

bool SweptRegion::separated_from(const ConvexPolyhedron& solid) const {
  const CGAL::Protect_FPU_rounding<true> upward;
  for (const Face& face : solid.faces()) {
    const auto& h = face.plane.approx();
    // The prism toward the sun stays on the positive side only if it does not run back.
    if (toward_sun_) {
      const IntervalPoint& s = *toward_sun_;
      if ((h.a() * s[0] + h.b() * s[1] + h.c() * s[2]).inf() < 0) continue;
    }
    if (std::all_of(points_.begin(), points_.end(),
                    [&](const IntervalPoint& x) { return plane_value(h, x).inf() > 0; }))
      return true;
  }
  std::vector<IntervalPoint> vertices;
  for (const Point3& v : solid.vertices()) vertices.push_back(interval_point(v));
  for (const auto& plane : planes_)  // not a structured binding: the lambda captures it (C++17)
    if (std::all_of(vertices.begin(), vertices.end(), [&](const IntervalPoint& x) {
          return dot_from(plane.second, x, plane.first).inf() > 0;
        }))
      return true;
  return false;
}

bool SweptRegion::separated_from(const CGAL::Bbox_3& box) const {
  const CGAL::Protect_FPU_rounding<true> upward;
  for (const auto& [origin, normal] : planes_) {
    // The least of normal . (x - origin) over the box is the sum over the axes of the least
    // of its two ends' terms; each term's interval holds both ends, so the sum's interval
    // holds the least value.
    Interval least = 0;
    for (int i = 0; i < 3; ++i) {
      const Interval low = normal[i] * (Interval(box.min(i)) - origin[i]);
      const Interval high = normal[i] * (Interval(box.max(i)) - origin[i]);
      least += Interval(std::min(low.inf(), high.inf()), std::max(low.sup(), high.sup()));
    }
    if (least.inf() > 0) return true;
  }
  return false;
}

void SweptRegion::add(const IntervalPoint& origin, const IntervalPoint& normal,
                      const std::vector<std::size_t>& on_plane) {
  const CGAL::Protect_FPU_rounding<true> upward;
  if (std::all_of(normal.begin(), normal.end(),
                  [](const Interval& c) { return c.inf() == 0 && c.sup() == 0; }))
    return;
  bool non_positive = true, non_negative = true;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    if (std::find(on_plane.begin(), on_plane.end(), i) != on_plane.end()) continue;
    const Interval value = dot_from(normal, points_[i], origin);
    non_positive = non_positive && value.sup() <= 0;
    non_negative = non_negative && value.inf() >= 0;
  }
  if (non_positive)
    planes_.push_back({origin, normal});
  else if (non_negative)
    planes_.push_back({origin, {-normal[0], -normal[1], -normal[2]}});
}

}  // namespace penumbra
