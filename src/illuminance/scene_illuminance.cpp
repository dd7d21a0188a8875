#include "penumbra/illuminance/scene_illuminance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>

#include "penumbra/illuminance/linear_source.h"
#include "penumbra/illuminance/point_source.h"
#include "penumbra/photometry/orientation.h"

namespace penumbra::illuminance {
namespace {

// === Bounding-box culls. They only skip exact tests that cannot find a blocker: every
// box is closed and rounded outward, so touching counts as meeting.

struct Box {
  Vec3d low;
  Vec3d high;
};

Box box_of(const CGAL::Bbox_3& box) {
  return {{box.xmin(), box.ymin(), box.zmin()}, {box.xmax(), box.ymax(), box.zmax()}};
}

// the box of a few points given as doubles (exact: no arithmetic).
Box box_of(std::initializer_list<const Vec3d*> points) {
  Box box{**points.begin(), **points.begin()};
  for (const Vec3d* p : points)
    for (int i = 0; i < 3; ++i) {
      box.low[i] = std::min(box.low[i], (*p)[i]);
      box.high[i] = std::max(box.high[i], (*p)[i]);
    }
  return box;
}

bool overlap(const Box& a, const Box& b) {
  for (int i = 0; i < 3; ++i)
    if (a.high[i] < b.low[i] || b.high[i] < a.low[i]) return false;
  return true;
}

// returns false only when the ray origin + t direction, t >= 0, certainly misses box.
// A slab test in doubles on a box widened by 1e-9 of the coordinates' magnitude, far
// more than the rounding of the slab parameters (a few ulps of |t|), so no ray that
// meets the true box is dropped.
bool ray_may_meet(const Box& box, const Vec3d& origin, const Vec3d& direction) {
  double t_low = 0, t_high = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const double margin =
        1e-9 * (1 + std::abs(box.low[i]) + std::abs(box.high[i]) + std::abs(origin[i]));
    const double low = box.low[i] - margin, high = box.high[i] + margin;
    if (direction[i] == 0) {
      if (origin[i] < low || origin[i] > high) return false;
      continue;
    }
    double t0 = (low - origin[i]) / direction[i], t1 = (high - origin[i]) / direction[i];
    if (t0 > t1) std::swap(t0, t1);
    t_low = std::max(t_low, t0);
    t_high = std::min(t_high, t1);
    if (t_low > t_high) return false;
  }
  return true;
}

// === Interval filters, as in CGAL's filtered predicates: interval arithmetic on the
// approximations of the exact objects and on the query's doubles certifies most signs;
// a sign it cannot certify is left to the exact test. No epsilon decides anything: an
// uncertain interval only costs the time of the exact test.

using Interval = CGAL::Interval_nt<false>;

// A filter's verdict: certainly not, certainly, or "ask the exact test".
enum class Certainly { no, yes, unknown };

// F(x) = n.x + d for a plane's approximation. Needs Protect_FPU_rounding.
template <class PlaneApproximation>
Interval value_at(const PlaneApproximation& plane, const Vec3d& x) {
  return plane.a() * x[0] + plane.b() * x[1] + plane.c() * x[2] + plane.d();
}

// n.(to - from) with n and both points given as doubles. Needs Protect_FPU_rounding.
Interval dot_difference(const Vec3d& n, const Vec3d& to, const Vec3d& from) {
  return Interval(n[0]) * (Interval(to[0]) - from[0]) +
         Interval(n[1]) * (Interval(to[1]) - from[1]) +
         Interval(n[2]) * (Interval(to[2]) - from[2]);
}

// whether x is strictly on the negative side of plane_of(item) for every item: inside an
// open convex volume (its planes), or a solid's interior (its faces). Precondition: items
// is not empty.
template <class Items, class PlaneOf>
Certainly negative_everywhere(const Items& items, PlaneOf plane_of, const Vec3d& x) {
  const CGAL::Protect_FPU_rounding<true> upward;
  Certainly answer = Certainly::yes;
  for (const auto& item : items) {
    const Interval value = value_at(plane_of(item).approx(), x);
    if (value.inf() >= 0) return Certainly::no;
    if (!(value.sup() < 0)) answer = Certainly::unknown;
  }
  return answer;
}

Certainly inside_open_volume(const std::vector<Plane3>& planes, const Vec3d& x) {
  return negative_everywhere(
      planes, [](const Plane3& plane) -> const Plane3& { return plane; }, x);
}

Certainly inside_solid(const ConvexPolyhedron& solid, const Vec3d& x) {
  return negative_everywhere(
      solid.faces(), [](const Face& face) -> const Plane3& { return face.plane; }, x);
}

// whether n.(target - point) > 0: target strictly on the outer side of the receiving plane.
Certainly outer_side(const Vec3d& normal, const Vec3d& target, const Vec3d& point) {
  const CGAL::Protect_FPU_rounding<true> upward;
  const Interval value = dot_difference(normal, target, point);
  if (value.inf() > 0) return Certainly::yes;
  if (value.sup() <= 0) return Certainly::no;
  return Certainly::unknown;
}

// whether the open ray point + t toward, t > 0 (with `end`: the open segment from point to
// end, 0 < t < 1, toward = end - point), meets the interior of a solid (not flat):
// ray_hidden's one-dimensional clip by the face planes, in intervals.
Certainly ray_meets_solid(const ConvexPolyhedron& solid, const Vec3d& point, const Vec3d& toward,
                          const Vec3d* end = nullptr) {
  const CGAL::Protect_FPU_rounding<true> upward;
  Interval low(0);
  std::optional<Interval> high;
  if (end) high = Interval(1);
  bool certain = true;
  for (const Face& face : solid.faces()) {
    const auto& plane = face.plane.approx();
    const Interval at_point = value_at(plane, point);
    const Interval slope =
        end ? value_at(plane, *end) - at_point
            : plane.a() * toward[0] + plane.b() * toward[1] + plane.c() * toward[2];
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

// whether the open ray point + t toward, t > 0, meets the relative interior of a flat
// polygon: it crosses the plane once, at t > 0, strictly inside every edge (ray_hidden).
Certainly ray_meets_polygon(const ConvexPolyhedron& polygon, const Vec3d& point,
                            const Vec3d& toward) {
  const CGAL::Protect_FPU_rounding<true> upward;
  const Face& face = polygon.faces().front();
  const auto& plane = face.plane.approx();
  const Interval at_point = value_at(plane, point);
  const Interval slope = plane.a() * toward[0] + plane.b() * toward[1] + plane.c() * toward[2];
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

// === Occluders

struct Occluder {
  const ConvexPolyhedron* solid;
  Box box;
};

using IntervalVector = std::array<Interval, 3>;

IntervalVector cross(const IntervalVector& a, const IntervalVector& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// true when intervals certify that no open segment from point to a point of the source
// a b meets the occluder's interior (a flat polygon's relative interior), by a separating
// axis of the closed triangle (point, a, b) and the occluder: one of the occluder's face
// normals (the triangle on the closed outer side of the face; strictly for a flat
// polygon, whose relative interior lies on its plane), or, against the occluder's box,
// the triangle's normal and the cross products of its edges with x, y and z
// (Akenine-Moller's triangle-box test). Touching projections separate: the interior
// projects to an open interval.
bool misses_triangle(const Occluder& occluder, const Vec3d& point, const Vec3d& a, const Vec3d& b) {
  const CGAL::Protect_FPU_rounding<true> upward;
  const ConvexPolyhedron& solid = *occluder.solid;
  for (const Face& face : solid.faces()) {
    const auto& plane = face.plane.approx();
    const Interval at_point = value_at(plane, point), at_a = value_at(plane, a),
                   at_b = value_at(plane, b);
    if (solid.is_flat() ? at_point.inf() > 0 && at_a.inf() > 0 && at_b.inf() > 0
                        : at_point.inf() >= 0 && at_a.inf() >= 0 && at_b.inf() >= 0)
      return true;
  }
  // Against the box, relative to point: the triangle is (0, to_a, to_b).
  IntervalVector to_a, to_b, centre, half;
  for (int i = 0; i < 3; ++i) {
    to_a[i] = Interval(a[i]) - point[i];
    to_b[i] = Interval(b[i]) - point[i];
    centre[i] = (Interval(occluder.box.low[i]) + occluder.box.high[i]) / 2 - point[i];
    half[i] = (Interval(occluder.box.high[i]) - occluder.box.low[i]) / 2;
  }
  const auto separates = [&](const IntervalVector& axis) {
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
  const IntervalVector source{to_b[0] - to_a[0], to_b[1] - to_a[1], to_b[2] - to_a[2]};
  for (int i = 0; i < 3; ++i) {
    IntervalVector unit{Interval(0), Interval(0), Interval(0)};
    unit[i] = Interval(1);
    for (const IntervalVector* edge : std::array<const IntervalVector*, 3>{&to_a, &to_b, &source})
      if (separates(cross(*edge, unit))) return true;
  }
  return false;
}

// What the cheap tests say of one occluder and a tube seen from point, before any exact
// work: it certainly hides nothing (its box misses the triangle's, or a separating axis),
// certainly hides the whole tube (a solid meeting both rays to the tube's ends, when the
// whole tube is on the outer side: the hidden points of one convex occluder form an
// interval), or must be examined.
enum class TubeCull { misses, hides_all, examine };

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

// === A uniform grid over the solids' boxes, for the containing-object query: the cell of a
// point lists every solid whose closed box can hold it. Cells are computed from
// coordinates by one monotone expression (a difference and a division, rounded to
// nearest, then floor), so a point inside a box falls in a cell between those of the
// box's corners: no box that holds the point is missed.

class BoxGrid {
 public:
  BoxGrid() = default;
  // indexes boxes[k] for each k in members (increasing).
  BoxGrid(const std::vector<Box>& boxes, const std::vector<std::size_t>& members) {
    if (members.empty()) return;
    bounds_ = boxes[members.front()];
    for (std::size_t k : members)
      for (int i = 0; i < 3; ++i) {
        bounds_.low[i] = std::min(bounds_.low[i], boxes[k].low[i]);
        bounds_.high[i] = std::max(bounds_.high[i], boxes[k].high[i]);
      }
    // About two cells per member, shaped like the bounds.
    const double target = 2.0 * static_cast<double>(members.size());
    std::array<double, 3> extent;
    double volume = 1;
    int dimensions = 0;
    for (int i = 0; i < 3; ++i) {
      extent[i] = bounds_.high[i] - bounds_.low[i];
      if (extent[i] > 0) {
        volume *= extent[i];
        ++dimensions;
      }
    }
    const double side = dimensions ? std::pow(volume / target, 1.0 / dimensions) : 1;
    for (int i = 0; i < 3; ++i) {
      cells_[i] = extent[i] > 0 ? static_cast<int>(std::clamp(extent[i] / side, 1.0, 256.0)) : 1;
      size_[i] = extent[i] > 0 ? extent[i] / cells_[i] : 1;
    }
    buckets_.resize(static_cast<std::size_t>(cells_[0]) * cells_[1] * cells_[2]);
    for (std::size_t k : members) {
      const auto low = cell(boxes[k].low), high = cell(boxes[k].high);
      for (int x = low[0]; x <= high[0]; ++x)
        for (int y = low[1]; y <= high[1]; ++y)
          for (int z = low[2]; z <= high[2]; ++z) buckets_[index(x, y, z)].push_back(k);
    }
  }

  // returns the members whose box may hold point (increasing), or none.
  const std::vector<std::size_t>& near(const Vec3d& point) const {
    static const std::vector<std::size_t> none;
    if (buckets_.empty()) return none;
    for (int i = 0; i < 3; ++i)
      if (point[i] < bounds_.low[i] || point[i] > bounds_.high[i]) return none;
    const auto at = cell(point);
    return buckets_[index(at[0], at[1], at[2])];
  }

 private:
  std::array<int, 3> cell(const Vec3d& x) const {
    std::array<int, 3> at;
    for (int i = 0; i < 3; ++i)
      at[i] = static_cast<int>(
          std::clamp(std::floor((x[i] - bounds_.low[i]) / size_[i]), 0.0, cells_[i] - 1.0));
    return at;
  }
  std::size_t index(int x, int y, int z) const {
    return (static_cast<std::size_t>(z) * cells_[1] + y) * cells_[0] + x;
  }

  Box bounds_{};
  std::array<int, 3> cells_{1, 1, 1};
  std::array<double, 3> size_{1, 1, 1};
  std::vector<std::vector<std::size_t>> buckets_;
};

// === Per-light data cached by the solver

struct CachedPoint {
  Point3 position;
  const PointLight* light;
  std::vector<HiddenRegion> hidden;  // hidden[k]: the region occluder k hides from the lamp
};

struct CachedLinear {
  Point3 start, end;
  const LinearLight* light;
  Box box;  // of the source
};

struct CachedDirectional {
  Vector3 toward_sun;  // -direction, exact
  Vec3d toward_sun_double;
  const DirectionalLight* light;
};

using CachedLight = std::variant<CachedPoint, CachedLinear, CachedDirectional>;

// The occluders one query tests: every object (nullptr) or a caller's subset of them.
using OccluderSubset = const std::vector<std::size_t>*;

// calls stop(k) for each occluder k to test, in order, until it returns true; returns
// whether one did.
template <class Stop>
bool any_occluder(std::size_t count, OccluderSubset subset, Stop&& stop) {
  if (subset) return std::any_of(subset->begin(), subset->end(), stop);
  for (std::size_t k = 0; k < count; ++k)
    if (stop(k)) return true;
  return false;
}

// The receiving point of one query: the doubles given, and the exact point they denote,
// built only when a filter leaves a question to the exact test.
class QueryPoint {
 public:
  explicit QueryPoint(const Vec3d& point) : point_(point) {}
  const Vec3d& doubles() const { return point_; }
  const Point3& exact() const {
    if (!exact_) exact_ = to_exact(point_);
    return *exact_;
  }

 private:
  Vec3d point_;
  mutable std::optional<Point3> exact_;
};

}  // namespace

struct IlluminanceSolver::Impl {
  std::vector<Object> objects;  // copies: the solver owns what it queries
  std::vector<Light> lights;
  std::vector<Occluder> occluders;
  std::vector<CachedLight> cached;
  BoxGrid solids;  // the occluders that have an interior (not flat), by box

  double point_light(const CachedPoint& lamp, const QueryPoint& point, const Vec3d& normal,
                     OccluderSubset subset) const;
  double directional_light(const CachedDirectional& sun, const QueryPoint& point,
                           const Vec3d& normal, OccluderSubset subset) const;
  std::vector<ExactInterval> linear_visible(const CachedLinear& tube, const QueryPoint& point,
                                            const Vec3d& normal, OccluderSubset subset) const;
  std::optional<std::vector<SourceInterval>> linear_visible_filtered(const CachedLinear& tube,
                                                                     const QueryPoint& point,
                                                                     const Vec3d& normal,
                                                                     OccluderSubset subset) const;
  double linear_light(const CachedLinear& tube, const QueryPoint& point, const Vec3d& normal,
                      OccluderSubset subset) const;
  double light_at(std::size_t light, const QueryPoint& point, const Vec3d& normal,
                  OccluderSubset subset) const;
  std::optional<std::size_t> containing_object(const QueryPoint& point) const;
  PointIlluminance at(const Vec3d& point, const Vec3d& normal,
                      const std::vector<std::vector<std::size_t>>* subsets) const;
};

IlluminanceSolver::IlluminanceSolver(const Scene& scene) {
  auto impl = std::make_shared<Impl>();
  impl->objects = scene.objects;
  impl->lights = scene.lights;
  for (const Object& object : impl->objects)
    impl->occluders.push_back({&object.solid, box_of(object.solid.bbox())});
  {
    std::vector<Box> boxes;
    std::vector<std::size_t> members;
    for (std::size_t k = 0; k < impl->occluders.size(); ++k) {
      boxes.push_back(impl->occluders[k].box);
      // A flat polygon has no interior.
      if (!impl->occluders[k].solid->is_flat()) members.push_back(k);
    }
    impl->solids = BoxGrid(boxes, members);
  }
  for (const Light& light : impl->lights) {
    if (const auto* point = std::get_if<PointLight>(&light.source)) {
      CachedPoint lamp{to_exact(point->position), point, {}};
      for (const Occluder& occluder : impl->occluders)
        lamp.hidden.push_back(hidden_region(*occluder.solid, lamp.position));
      impl->cached.emplace_back(std::move(lamp));
    } else if (const auto* tube = std::get_if<LinearLight>(&light.source)) {
      impl->cached.emplace_back(CachedLinear{to_exact(tube->start), to_exact(tube->end), tube,
                                             box_of({&tube->start, &tube->end})});
    } else {
      const auto& sun = std::get<DirectionalLight>(light.source);
      const Vec3d toward{-sun.direction[0], -sun.direction[1], -sun.direction[2]};
      impl->cached.emplace_back(CachedDirectional{to_exact_vector(toward), toward, &sun});
    }
  }
  impl_ = std::move(impl);
}

std::size_t IlluminanceSolver::light_count() const {
  return impl_->lights.size();
}

double IlluminanceSolver::Impl::point_light(const CachedPoint& lamp, const QueryPoint& point,
                                            const Vec3d& normal, OccluderSubset subset) const {
  // Eq. (2)'s tie-break, exactly: the lamp strictly on the outer side of the receiving plane.
  const PointLight& light = *lamp.light;
  const Certainly facing = outer_side(normal, light.position, point.doubles());
  if (facing == Certainly::no) return 0;
  if (facing == Certainly::unknown &&
      !CGAL::is_positive(to_exact_vector(normal) * (lamp.position - point.exact())))
    return 0;
  const Box segment = box_of({&point.doubles(), &light.position});
  // The region hidden from the lamp by occluder k holds exactly the points whose open
  // segment to the lamp meets the occluder (the relation is symmetric).
  if (any_occluder(occluders.size(), subset, [&](std::size_t k) {
        const HiddenRegion& hidden = lamp.hidden[k];
        if (hidden.empty() || !overlap(occluders[k].box, segment)) return false;
        if (hidden.everywhere) return true;
        const Certainly inside = inside_open_volume(hidden.volume.planes, point.doubles());
        return inside == Certainly::unknown ? hidden.contains(point.exact())
                                            : inside == Certainly::yes;
      }))
    return 0;
  return point_illuminance(point.doubles(), normal, light.position, [&](const Vec3d& direction) {
    return photometry::intensity_toward(*light.distribution, light.axis, light.c0, direction);
  });
}

double IlluminanceSolver::Impl::directional_light(const CachedDirectional& sun,
                                                  const QueryPoint& point, const Vec3d& normal,
                                                  OccluderSubset subset) const {
  const Vec3d origin{0, 0, 0};
  const Certainly facing = outer_side(normal, sun.toward_sun_double, origin);
  if (facing == Certainly::no) return 0;
  if (facing == Certainly::unknown && !CGAL::is_positive(to_exact_vector(normal) * sun.toward_sun))
    return 0;
  if (any_occluder(occluders.size(), subset, [&](std::size_t k) {
        const Occluder& occluder = occluders[k];
        if (!ray_may_meet(occluder.box, point.doubles(), sun.toward_sun_double)) return false;
        const Certainly meets =
            occluder.solid->is_flat()
                ? ray_meets_polygon(*occluder.solid, point.doubles(), sun.toward_sun_double)
                : ray_meets_solid(*occluder.solid, point.doubles(), sun.toward_sun_double);
        return meets == Certainly::unknown
                   ? ray_hidden(*occluder.solid, point.exact(), sun.toward_sun)
                   : meets == Certainly::yes;
      }))
    return 0;
  return directional_illuminance(normal, sun.light->direction, sun.light->illuminance);
}

std::vector<ExactInterval> IlluminanceSolver::Impl::linear_visible(const CachedLinear& tube,
                                                                   const QueryPoint& point,
                                                                   const Vec3d& normal,
                                                                   OccluderSubset subset) const {
  const LinearLight& light = *tube.light;
  // Fig. 7, S3: only the part strictly on the outer side of the receiving plane can light P.
  std::optional<ExactInterval> outer;
  const Certainly start_out = outer_side(normal, light.start, point.doubles());
  const Certainly end_out = outer_side(normal, light.end, point.doubles());
  const bool whole_source = start_out == Certainly::yes && end_out == Certainly::yes;
  if (whole_source)
    outer = ExactInterval{0, 1};
  else if (start_out == Certainly::no && end_out == Certainly::no)
    return {};
  else
    outer = outer_side_interval_exact(point.exact(), to_exact_vector(normal), tube.start, tube.end);
  if (!outer) return {};
  // Section 4.2.3: each occluder near the triangle (P, Q1, Q2) hides an open sub-segment,
  // the source clipped by the pyramid from P through its contour. Occluders whose boxes
  // miss the triangle's box, or that the triangle certainly misses, are skipped first.
  const Box triangle = box_of({&point.doubles(), &light.start, &light.end});
  std::vector<ExactInterval> hidden;
  const bool umbra = any_occluder(occluders.size(), subset, [&](std::size_t k) {
    const Occluder& occluder = occluders[k];
    const TubeCull cull = cull_for_tube(occluder, triangle, point.doubles(), light, whole_source);
    if (cull != TubeCull::examine) return cull == TubeCull::hides_all;
    const HiddenRegion region = hidden_region(*occluder.solid, point.exact());
    if (region.empty()) return false;
    const auto blocked = hidden_interval(region, tube.start, tube.end);
    if (!blocked) return false;
    // One occluder hides the whole outer part: umbra.
    if (!(outer->low < blocked->low) && !(blocked->high < outer->high)) return true;
    hidden.push_back(*blocked);
    return false;
  });
  if (umbra) return {};
  return visible_intervals(*outer, std::move(hidden));
}

std::optional<std::vector<SourceInterval>> IlluminanceSolver::Impl::linear_visible_filtered(
    const CachedLinear& tube, const QueryPoint& point, const Vec3d& normal,
    OccluderSubset subset) const {
  const LinearLight& light = *tube.light;
  const CGAL::Protect_FPU_rounding<true> upward;
  // The outer part (Fig. 7, S3) as in linear_visible, its cut u* = F(a) / (F(a) - F(b))
  // with F = n.(Q - P) in intervals.
  const Certainly start_out = outer_side(normal, light.start, point.doubles());
  const Certainly end_out = outer_side(normal, light.end, point.doubles());
  if (start_out == Certainly::unknown || end_out == Certainly::unknown) return std::nullopt;
  if (start_out == Certainly::no && end_out == Certainly::no) return std::vector<SourceInterval>{};
  const bool whole_source = start_out == Certainly::yes && end_out == Certainly::yes;
  Interval outer_low(0), outer_high(1);
  if (!whole_source) {
    const Interval at_start = dot_difference(normal, light.start, point.doubles());
    const Interval at_end = dot_difference(normal, light.end, point.doubles());
    const Interval cut = at_start / (at_start - at_end);
    (start_out == Certainly::yes ? outer_high : outer_low) = cut;
  }
  const Box triangle = box_of({&point.doubles(), &light.start, &light.end});
  std::vector<std::array<Interval, 2>> hidden;
  bool certain = true;
  const bool umbra = any_occluder(occluders.size(), subset, [&](std::size_t k) {
    const Occluder& occluder = occluders[k];
    const TubeCull cull = cull_for_tube(occluder, triangle, point.doubles(), light, whole_source);
    if (cull != TubeCull::examine) return cull == TubeCull::hides_all;
    const HiddenIntervalBounds blocked =
        hidden_interval_filter(*occluder.solid, point.doubles(), light.start, light.end);
    if (blocked.verdict == HiddenIntervalBounds::Verdict::nothing) return false;
    if (blocked.verdict == HiddenIntervalBounds::Verdict::unknown) {
      certain = false;
      return true;
    }
    // One occluder hides the whole outer part: umbra (certainly, or certainly not).
    if (blocked.low.sup() <= outer_low.inf() && outer_high.sup() <= blocked.high.inf()) return true;
    if (!(blocked.low.inf() > outer_low.sup() || blocked.high.sup() < outer_high.inf())) {
      certain = false;
      return true;
    }
    hidden.push_back({blocked.low, blocked.high});
    return false;
  });
  if (!certain) return std::nullopt;
  if (umbra) return std::vector<SourceInterval>{};
  // visible_intervals in intervals: every comparison certain, or the exact path decides.
  std::sort(hidden.begin(), hidden.end(),
            [](const auto& x, const auto& y) { return x[0].inf() < y[0].inf(); });
  for (std::size_t k = 0; k + 1 < hidden.size(); ++k)
    if (!(hidden[k][0].sup() <= hidden[k + 1][0].inf())) return std::nullopt;
  const auto less = [&](const Interval& x, const Interval& y) -> std::optional<bool> {
    if (x.sup() < y.inf()) return true;
    if (x.inf() >= y.sup()) return false;
    return std::nullopt;
  };
  std::vector<std::array<Interval, 2>> visible;
  Interval cursor = outer_low;
  for (const auto& blocked : hidden) {
    const auto open = less(cursor, outer_high);
    if (!open) return std::nullopt;
    if (!*open) break;
    const auto before = less(cursor, blocked[0]);
    if (!before) return std::nullopt;
    if (*before) {
      const auto inside = less(blocked[0], outer_high);
      if (!inside) return std::nullopt;
      visible.push_back({cursor, *inside ? blocked[0] : outer_high});
    }
    const auto extends = less(cursor, blocked[1]);
    if (!extends) return std::nullopt;
    if (*extends) cursor = blocked[1];
  }
  const auto rest = less(cursor, outer_high);
  if (!rest) return std::nullopt;
  if (*rest) visible.push_back({cursor, outer_high});
  // The ends become doubles to integrate, as the exact path's do: known here to within
  // 1e-12 of the piece's length, or the exact path gives them.
  std::vector<SourceInterval> parts;
  for (const auto& piece : visible) {
    const double length = piece[1].inf() - piece[0].sup();
    if (!(piece[0].sup() - piece[0].inf() + piece[1].sup() - piece[1].inf() <= 1e-12 * length))
      return std::nullopt;
    parts.emplace_back(CGAL::to_double(piece[0]), CGAL::to_double(piece[1]));
  }
  return parts;
}

double IlluminanceSolver::Impl::linear_light(const CachedLinear& tube, const QueryPoint& point,
                                             const Vec3d& normal, OccluderSubset subset) const {
  const LinearLight& light = *tube.light;
  // Decided in intervals whenever they are certain (the same parts, up to the rounding of
  // their ends); the exact construction otherwise.
  if (const auto parts = linear_visible_filtered(tube, point, normal, subset)) {
    if (parts->empty()) return 0;
    return linear_illuminance(point.doubles(), normal, light.start, light.end,
                              light.candela_per_metre, *parts);
  }
  const std::vector<ExactInterval> visible = linear_visible(tube, point, normal, subset);
  if (visible.empty()) return 0;
  // The exact interval ends become doubles only here, to integrate the closed form.
  std::vector<SourceInterval> parts;
  parts.reserve(visible.size());
  for (const ExactInterval& part : visible)
    parts.emplace_back(CGAL::to_double(part.low), CGAL::to_double(part.high));
  return linear_illuminance(point.doubles(), normal, light.start, light.end,
                            light.candela_per_metre, parts);
}

double IlluminanceSolver::Impl::light_at(std::size_t light, const QueryPoint& point,
                                         const Vec3d& normal, OccluderSubset subset) const {
  return std::visit(
      [&](const auto& cached_light) -> double {
        using T = std::decay_t<decltype(cached_light)>;
        if constexpr (std::is_same_v<T, CachedPoint>)
          return point_light(cached_light, point, normal, subset);
        else if constexpr (std::is_same_v<T, CachedLinear>)
          return linear_light(cached_light, point, normal, subset);
        else
          return directional_light(cached_light, point, normal, subset);
      },
      cached.at(light));
}

std::optional<std::size_t> IlluminanceSolver::Impl::containing_object(
    const QueryPoint& point) const {
  for (std::size_t k : solids.near(point.doubles())) {
    const ConvexPolyhedron& solid = *occluders[k].solid;
    if (!overlap(occluders[k].box, box_of({&point.doubles()}))) continue;
    const Certainly inside = inside_solid(solid, point.doubles());
    if (inside == Certainly::yes || (inside == Certainly::unknown &&
                                     solid.bounded_side(point.exact()) == CGAL::ON_BOUNDED_SIDE))
      return k;
  }
  return std::nullopt;
}

PointIlluminance IlluminanceSolver::Impl::at(
    const Vec3d& point, const Vec3d& normal,
    const std::vector<std::vector<std::size_t>>* subsets) const {
  const QueryPoint receiver(point);
  PointIlluminance result;
  result.inside = containing_object(receiver);
  result.per_light.assign(lights.size(), 0.0);
  if (result.inside) return result;
  for (std::size_t light = 0; light < lights.size(); ++light) {
    result.per_light[light] =
        light_at(light, receiver, normal, subsets ? &(*subsets)[light] : nullptr);
    result.total += result.per_light[light];
  }
  return result;
}

double IlluminanceSolver::light_at(std::size_t light, const Vec3d& point,
                                   const Vec3d& normal) const {
  return impl_->light_at(light, QueryPoint(point), normal, nullptr);
}

std::vector<ExactInterval> IlluminanceSolver::visible_parts(std::size_t light, const Vec3d& point,
                                                            const Vec3d& normal) const {
  const auto* tube = std::get_if<CachedLinear>(&impl_->cached.at(light));
  if (!tube) throw std::invalid_argument("visible_parts: light is not linear");
  return impl_->linear_visible(*tube, QueryPoint(point), normal, nullptr);
}

std::optional<std::size_t> IlluminanceSolver::containing_object(const Vec3d& point) const {
  return impl_->containing_object(QueryPoint(point));
}

PointIlluminance IlluminanceSolver::at(const Vec3d& point, const Vec3d& normal) const {
  return impl_->at(point, normal, nullptr);
}

PointIlluminance IlluminanceSolver::at(
    const Vec3d& point, const Vec3d& normal,
    const std::vector<std::vector<std::size_t>>& occluders) const {
  if (occluders.size() != impl_->lights.size())
    throw std::invalid_argument("IlluminanceSolver::at: one occluder list per light expected");
  for (const auto& list : occluders)
    for (std::size_t k : list)
      if (k >= impl_->occluders.size())
        throw std::invalid_argument("IlluminanceSolver::at: no object " + std::to_string(k));
  return impl_->at(point, normal, &occluders);
}

PointIlluminance illuminance_at(const Scene& scene, const Vec3d& point, const Vec3d& normal) {
  return IlluminanceSolver(scene).at(point, normal);
}

}  // namespace penumbra::illuminance
