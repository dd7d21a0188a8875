#include "penumbra/illuminance/occlusion.h"

#include "penumbra/geometry/exact.h"
#include "penumbra/geometry/interval.h"

#include <algorithm>
#include <array>

namespace penumbra::illuminance {
namespace {

// narrows the open interval (low, high) of u to where value_at_a + u slope < 0;
// returns false when it becomes empty.
bool clip_below_zero(const Exact& value_at_a, const Exact& slope, Exact& low, Exact& high) {
  if (CGAL::is_zero(slope)) return CGAL::is_negative(value_at_a);
  const Exact crossing = -value_at_a / slope;
  if (CGAL::is_positive(slope)) {
    if (crossing < high) high = crossing;
  } else if (crossing > low) {
    low = crossing;
  }
  return low < high;
}

// true when x, a point of the flat polygon's plane, is strictly inside the polygon:
// strictly on the same side of every edge line (the polygon is convex).
bool in_relative_interior(const Face& face, const Point3& x) {
  const Vector3 normal = face.normal();
  const std::size_t n = face.vertices.size();
  CGAL::Orientation first = CGAL::COPLANAR;
  for (std::size_t i = 0; i < n; ++i) {
    const Point3& from = face.vertices[i];
    const CGAL::Orientation side =
        CGAL::orientation(from, face.vertices[(i + 1) % n], from + normal, x);
    if (side == CGAL::COPLANAR) return false;
    if (i == 0)
      first = side;
    else if (side != first)
      return false;
  }
  return true;
}

}  // namespace

bool HiddenRegion::contains(const Point3& x) const {
  return everywhere || (!volume.planes.empty() && volume.contains(x));
}

HiddenRegion hidden_region(const ConvexPolyhedron& occluder, const Point3& apex) {
  HiddenRegion region;
  if (occluder.is_flat()) {
    // Apex off the polygon's plane: the open pyramid behind the polygon; in the plane:
    // the open segment leaves the plane at once, so nothing is hidden (no contour).
    region.volume = point_shadow_volume(occluder, apex);
    return region;
  }
  switch (occluder.bounded_side(apex)) {
    case CGAL::ON_BOUNDED_SIDE:
      region.everywhere = true;
      break;
    case CGAL::ON_BOUNDARY:
      // For small t > 0, apex + t (X - apex) is interior iff it goes strictly inward
      // through every face holding the apex; F(X) = n.(X - apex) for those faces, and
      // convexity carries "interior near the apex" to the whole open segment.
      for (const Face& face : occluder.faces())
        if (face.plane.oriented_side(apex) == CGAL::ON_ORIENTED_BOUNDARY)
          region.volume.planes.push_back(face.plane);
      break;
    default:
      region.volume = point_shadow_volume(occluder, apex);
      break;
  }
  return region;
}

std::optional<ExactInterval> hidden_interval(const HiddenRegion& region, const Point3& a,
                                             const Point3& b) {
  if (region.everywhere) return ExactInterval{0, 1};
  if (region.volume.planes.empty()) return std::nullopt;
  // Filter: with interval arithmetic on the planes' approximations, a plane that has the
  // whole source on its closed positive side certifies a miss (the common case: most
  // occluders near a source hide none of it), and a plane that has it strictly on its
  // negative side constrains nothing. Only the remaining planes are clipped exactly.
  std::vector<const Plane3*> uncertain;
  {
    const CGAL::Protect_FPU_rounding<true> upward;
    const auto& a_approx = a.approx();
    const auto& b_approx = b.approx();
    for (const Plane3& plane : region.volume.planes) {
      const auto& h = plane.approx();
      const auto at_a = plane_value(h, a_approx);
      const auto at_b = plane_value(h, b_approx);
      if (at_a.inf() >= 0 && at_b.inf() >= 0) return std::nullopt;
      if (at_a.sup() < 0 && at_b.sup() < 0) continue;
      uncertain.push_back(&plane);
    }
  }
  // Section 4.2.3 in object space: clip the source against each open half-space of the
  // pyramid from the receiving point through the occluder's contour. Along the source
  // F(Q(u)) = F(a) + u (F(b) - F(a)). In the exact rationals directly (no lazy nodes).
  using Rational = Exact::ET;
  const auto& exact_a = exact_value(a);
  const auto& exact_b = exact_value(b);
  Rational low = 0, high = 1;
  for (const Plane3* plane : uncertain) {
    const auto& h = exact_value(*plane);
    const Rational at_a = plane_value(h, exact_a);
    const Rational at_b = plane_value(h, exact_b);
    const Rational slope = at_b - at_a;
    const int slope_sign = CGAL::sign(slope);
    if (slope_sign == 0) {
      if (CGAL::sign(at_a) >= 0) return std::nullopt;
      continue;
    }
    const Rational crossing = -at_a / slope;
    if (slope_sign > 0) {
      if (crossing < high) high = crossing;
    } else if (crossing > low) {
      low = crossing;
    }
    if (!(low < high)) return std::nullopt;
  }
  return ExactInterval{Exact(low), Exact(high)};
}

HiddenIntervalBounds hidden_interval_filter(const ConvexPolyhedron& occluder, const Vec3d& apex,
                                            const Vec3d& a, const Vec3d& b) {
  HiddenIntervalBounds unknown;
  if (occluder.is_flat()) return unknown;
  // Section 4.2.3 in the plane of the triangle (apex, a, b): X = w apex + y a + z b with
  // w + y + z = 1 is on the open segment from the apex to Q(u) = a + u (b - a) for
  // y = t (1 - u), z = t u, w = 1 - t, 0 < t < 1, so u = z / (y + z). Each face plane is
  // affine: F(X) = w F(apex) + y F(a) + z F(b). The closed triangle w, y, z >= 0 clipped
  // by every F <= 0 is a convex polygon whose interior, when it has area and no face plane
  // holds the triangle (then some F would vanish on the whole polygon), is the set of
  // points of those segments inside the occluder; the hidden parameters run between the
  // least and the largest u of its vertices (u is monotone along each edge). Vertices keep
  // all three weights, so a vertex on a plane through the source's end points gets the
  // exact value 0 there and is not left uncertain.
  struct Vertex {
    Interval w, y, z;
  };
  constexpr std::size_t capacity = 64;
  if (occluder.faces().size() + 3 > capacity) return unknown;
  std::array<Vertex, capacity> polygon_a, polygon_b;
  std::array<Vertex, capacity>* polygon = &polygon_a;
  std::array<Vertex, capacity>* clipped = &polygon_b;
  std::size_t count = 3;
  polygon_a[0] = {Interval(1), Interval(0), Interval(0)};
  polygon_a[1] = {Interval(0), Interval(1), Interval(0)};
  polygon_a[2] = {Interval(0), Interval(0), Interval(1)};
  const CGAL::Protect_FPU_rounding<true> upward;
  bool apex_outside = false;
  std::array<Interval, capacity> values;
  for (const Face& face : occluder.faces()) {
    const auto& h = face.plane.approx();
    const auto value = [&](const Vec3d& x) { return plane_value(h, x); };
    const Interval at_apex = value(apex), at_a = value(a), at_b = value(b);
    if (at_apex.inf() > 0) apex_outside = true;
    // A face plane that holds the whole triangle: every segment runs in the occluder's
    // boundary, never its interior, so nothing is hidden. The polygon below would still
    // have area, so this case is decided here; a plane that only may hold it is left to
    // the exact functions.
    const auto may_be_zero = [](const Interval& x) { return x.inf() <= 0 && x.sup() >= 0; };
    if (may_be_zero(at_apex) && may_be_zero(at_a) && may_be_zero(at_b)) {
      const auto is_zero = [](const Interval& x) { return x.inf() == 0 && x.sup() == 0; };
      if (is_zero(at_apex) && is_zero(at_a) && is_zero(at_b))
        return {HiddenIntervalBounds::Verdict::nothing};
      return unknown;
    }
    // Every vertex certainly inside (F <= 0) or certainly outside (F > 0) the closed
    // half-space, or the filter gives up.
    bool all_inside = true;
    for (std::size_t k = 0; k < count; ++k) {
      const Vertex& v = (*polygon)[k];
      values[k] = v.w * at_apex + v.y * at_a + v.z * at_b;
      if (!(values[k].sup() <= 0 || values[k].inf() > 0)) return unknown;
      all_inside = all_inside && values[k].sup() <= 0;
    }
    if (all_inside) continue;
    // Sutherland-Hodgman against F <= 0.
    std::size_t kept = 0;
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t next = (k + 1) % count;
      const Vertex& p = (*polygon)[k];
      const Vertex& q = (*polygon)[next];
      const bool p_in = values[k].sup() <= 0, q_in = values[next].sup() <= 0;
      if (p_in) (*clipped)[kept++] = p;
      if (p_in != q_in) {
        // The crossing, strictly between p and q unless the inside end is on the plane.
        const Interval& inside_value = p_in ? values[k] : values[next];
        if (inside_value.inf() == 0 && inside_value.sup() == 0) continue;
        const Interval s = values[k] / (values[k] - values[next]);
        (*clipped)[kept++] = {p.w + s * (q.w - p.w), p.y + s * (q.y - p.y), p.z + s * (q.z - p.z)};
      }
    }
    std::swap(polygon, clipped);
    count = kept;
    if (count == 0) return {HiddenIntervalBounds::Verdict::nothing};
  }
  // An apex inside or on the closed occluder is hidden_region's other cases.
  if (!apex_outside) return unknown;
  // The polygon must certainly have area (twice the area in (y, z), counter-clockwise).
  Interval area(0);
  for (std::size_t k = 0; k < count; ++k) {
    const Vertex& p = (*polygon)[k];
    const Vertex& q = (*polygon)[(k + 1) % count];
    area += p.y * q.z - p.z * q.y;
  }
  if (!(area.inf() > 0)) return unknown;
  HiddenIntervalBounds bounds;
  bounds.verdict = HiddenIntervalBounds::Verdict::interval;
  bool first = true;
  for (std::size_t k = 0; k < count; ++k) {
    const Vertex& v = (*polygon)[k];
    Interval u;
    if (v.z.inf() == 0 && v.z.sup() == 0)
      u = Interval(0);
    else if (v.y.inf() == 0 && v.y.sup() == 0)
      u = Interval(1);
    else {
      const Interval sum = v.y + v.z;
      if (!(sum.inf() > 0)) return unknown;
      u = v.z / sum;
    }
    if (first) {
      bounds.low = bounds.high = u;
      first = false;
    } else {
      bounds.low = CGAL::min(bounds.low, u);
      bounds.high = CGAL::max(bounds.high, u);
    }
  }
  // hidden_interval's interval lies in (0, 1).
  bounds.low = CGAL::max(bounds.low, Interval(0));
  bounds.high = CGAL::min(bounds.high, Interval(1));
  return bounds;
}

std::optional<ExactInterval> outer_side_interval_exact(const Point3& point, const Vector3& normal,
                                                       const Point3& a, const Point3& b) {
  // n.(Q(u) - point) > 0  <=>  -n.(a - point) - u n.(b - a) < 0.
  Exact low = 0, high = 1;
  if (!clip_below_zero(-(normal * (a - point)), -(normal * (b - a)), low, high))
    return std::nullopt;
  return ExactInterval{low, high};
}

std::vector<ExactInterval> visible_intervals(const ExactInterval& within,
                                             std::vector<ExactInterval> hidden) {
  std::sort(hidden.begin(), hidden.end(),
            [](const ExactInterval& x, const ExactInterval& y) { return x.low < y.low; });
  std::vector<ExactInterval> visible;
  Exact cursor = within.low;
  for (const ExactInterval& blocked : hidden) {
    if (!(cursor < within.high)) break;
    if (cursor < blocked.low) {
      const Exact end = blocked.low < within.high ? blocked.low : within.high;
      visible.push_back({cursor, end});
    }
    if (cursor < blocked.high) cursor = blocked.high;
  }
  if (cursor < within.high) visible.push_back({cursor, within.high});
  return visible;
}

bool ray_hidden(const ConvexPolyhedron& occluder, const Point3& point, const Vector3& toward) {
  if (occluder.is_flat()) {
    // The ray crosses the polygon's plane once, at t > 0, inside the polygon.
    const Face& face = occluder.faces().front();
    const Exact at_point = plane_value(face.plane, point);
    const Exact slope = face.normal() * toward;
    if (CGAL::is_zero(slope) || CGAL::sign(at_point) != CGAL::opposite(CGAL::sign(slope)))
      return false;
    return in_relative_interior(face, point + (-at_point / slope) * toward);
  }
  // The open ray point + t toward, t > 0, meets the interior iff some t > 0 has every
  // F < 0: a one-dimensional clip, unbounded above until a face bounds it.
  Exact low = 0;
  std::optional<Exact> high;
  for (const Face& face : occluder.faces()) {
    const Exact at_point = plane_value(face.plane, point);
    const Exact slope = face.normal() * toward;
    if (CGAL::is_zero(slope)) {
      if (!CGAL::is_negative(at_point)) return false;
      continue;
    }
    const Exact crossing = -at_point / slope;
    if (CGAL::is_positive(slope)) {
      if (!high || crossing < *high) high = crossing;
    } else if (crossing > low) {
      low = crossing;
    }
    if (high && !(low < *high)) return false;
  }
  return !high || low < *high;
}

}  // namespace penumbra::illuminance
