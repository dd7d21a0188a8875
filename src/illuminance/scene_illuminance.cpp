#include "penumbra/illuminance/scene_illuminance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
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

// === Per-light data cached by the solver

struct Occluder {
  const ConvexPolyhedron* solid;
  Box box;
  std::array<Point3, 8> corners;  // of the box, exact
};

std::array<Point3, 8> corners_of(const Box& box) {
  std::array<Point3, 8> corners;
  for (int k = 0; k < 8; ++k)
    corners[k] = Point3((k & 1) ? box.high[0] : box.low[0], (k & 2) ? box.high[1] : box.low[1],
                        (k & 4) ? box.high[2] : box.low[2]);
  return corners;
}

// true when the box lies strictly on one side of the plane through p, a, b: then it
// cannot meet any segment from p to the source a b, which all lie in that plane. False
// when p, a, b are collinear.
bool beside_plane(const std::array<Point3, 8>& corners, const Point3& p, const Point3& a,
                  const Point3& b) {
  const CGAL::Orientation first = CGAL::orientation(p, a, b, corners[0]);
  if (first == CGAL::COPLANAR) return false;
  for (int k = 1; k < 8; ++k)
    if (CGAL::orientation(p, a, b, corners[k]) != first) return false;
  return true;
}

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

}  // namespace

struct IlluminanceSolver::Impl {
  std::vector<Object> objects;  // copies: the solver owns what it queries
  std::vector<Light> lights;
  std::vector<Occluder> occluders;
  std::vector<CachedLight> cached;

  double point_light(const CachedPoint& lamp, const Vec3d& point, const Vec3d& normal) const;
  double directional_light(const CachedDirectional& sun, const Vec3d& point,
                           const Vec3d& normal) const;
  std::vector<ExactInterval> linear_visible(const CachedLinear& tube, const Vec3d& point,
                                            const Vec3d& normal) const;
  double linear_light(const CachedLinear& tube, const Vec3d& point, const Vec3d& normal) const;
  double light_at(std::size_t light, const Vec3d& point, const Vec3d& normal) const;
};

IlluminanceSolver::IlluminanceSolver(const Scene& scene) {
  auto impl = std::make_shared<Impl>();
  impl->objects = scene.objects;
  impl->lights = scene.lights;
  for (const Object& object : impl->objects) {
    const Box box = box_of(object.solid.bbox());
    impl->occluders.push_back({&object.solid, box, corners_of(box)});
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

double IlluminanceSolver::Impl::point_light(const CachedPoint& lamp, const Vec3d& point,
                                            const Vec3d& normal) const {
  const Point3 receiver = to_exact(point);
  // Eq. (2)'s tie-break, exactly: the lamp strictly on the outer side of the receiving plane.
  if (!CGAL::is_positive(to_exact_vector(normal) * (lamp.position - receiver))) return 0;
  const Box segment = box_of({&point, &lamp.light->position});
  for (std::size_t k = 0; k < occluders.size(); ++k) {
    if (lamp.hidden[k].empty() || !overlap(occluders[k].box, segment)) continue;
    // The region hidden from the lamp by occluder k holds exactly the points whose open
    // segment to the lamp meets the occluder (the relation is symmetric).
    if (lamp.hidden[k].contains(receiver)) return 0;
  }
  const PointLight& light = *lamp.light;
  return point_illuminance(point, normal, light.position, [&](const Vec3d& direction) {
    return photometry::intensity_toward(*light.distribution, light.axis, light.c0, direction);
  });
}

double IlluminanceSolver::Impl::directional_light(const CachedDirectional& sun, const Vec3d& point,
                                                  const Vec3d& normal) const {
  if (!CGAL::is_positive(to_exact_vector(normal) * sun.toward_sun)) return 0;
  const Point3 receiver = to_exact(point);
  for (const Occluder& occluder : occluders)
    if (ray_may_meet(occluder.box, point, sun.toward_sun_double) &&
        ray_hidden(*occluder.solid, receiver, sun.toward_sun))
      return 0;
  return directional_illuminance(normal, sun.light->direction, sun.light->illuminance);
}

std::vector<ExactInterval> IlluminanceSolver::Impl::linear_visible(const CachedLinear& tube,
                                                                   const Vec3d& point,
                                                                   const Vec3d& normal) const {
  const Point3 receiver = to_exact(point);
  // Fig. 7, S3: only the part strictly on the outer side of the receiving plane can light P.
  const auto outer =
      outer_side_interval_exact(receiver, to_exact_vector(normal), tube.start, tube.end);
  if (!outer) return {};
  // Section 4.2.3: each occluder near the triangle (P, Q1, Q2) hides an open sub-segment,
  // the source clipped by the pyramid from P through its contour. Occluders whose boxes
  // miss the triangle's box or lie wholly on one side of its plane are skipped first.
  const Box triangle = box_of({&point, &tube.light->start, &tube.light->end});
  std::vector<ExactInterval> hidden;
  for (const Occluder& occluder : occluders) {
    if (!overlap(occluder.box, triangle) ||
        beside_plane(occluder.corners, receiver, tube.start, tube.end))
      continue;
    const HiddenRegion region = hidden_region(*occluder.solid, receiver);
    if (region.empty()) continue;
    const auto blocked = hidden_interval(region, tube.start, tube.end);
    if (!blocked) continue;
    // One occluder hides the whole outer part: umbra.
    if (!(outer->low < blocked->low) && !(blocked->high < outer->high)) return {};
    hidden.push_back(*blocked);
  }
  return visible_intervals(*outer, std::move(hidden));
}

double IlluminanceSolver::Impl::linear_light(const CachedLinear& tube, const Vec3d& point,
                                             const Vec3d& normal) const {
  const std::vector<ExactInterval> visible = linear_visible(tube, point, normal);
  if (visible.empty()) return 0;
  // The exact interval ends become doubles only here, to integrate the closed form.
  std::vector<SourceInterval> parts;
  parts.reserve(visible.size());
  for (const ExactInterval& part : visible)
    parts.emplace_back(CGAL::to_double(part.low), CGAL::to_double(part.high));
  const LinearLight& light = *tube.light;
  return linear_illuminance(point, normal, light.start, light.end, light.candela_per_metre, parts);
}

double IlluminanceSolver::Impl::light_at(std::size_t light, const Vec3d& point,
                                         const Vec3d& normal) const {
  return std::visit(
      [&](const auto& cached_light) -> double {
        using T = std::decay_t<decltype(cached_light)>;
        if constexpr (std::is_same_v<T, CachedPoint>)
          return point_light(cached_light, point, normal);
        else if constexpr (std::is_same_v<T, CachedLinear>)
          return linear_light(cached_light, point, normal);
        else
          return directional_light(cached_light, point, normal);
      },
      cached.at(light));
}

double IlluminanceSolver::light_at(std::size_t light, const Vec3d& point,
                                   const Vec3d& normal) const {
  return impl_->light_at(light, point, normal);
}

std::vector<ExactInterval> IlluminanceSolver::visible_parts(std::size_t light, const Vec3d& point,
                                                            const Vec3d& normal) const {
  const auto* tube = std::get_if<CachedLinear>(&impl_->cached.at(light));
  if (!tube) throw std::invalid_argument("visible_parts: light is not linear");
  return impl_->linear_visible(*tube, point, normal);
}

std::optional<std::size_t> IlluminanceSolver::containing_object(const Vec3d& point) const {
  const Point3 exact = to_exact(point);
  for (std::size_t k = 0; k < impl_->occluders.size(); ++k) {
    const Box& box = impl_->occluders[k].box;
    if (!overlap(box, box_of({&point}))) continue;
    if (impl_->occluders[k].solid->bounded_side(exact) == CGAL::ON_BOUNDED_SIDE) return k;
  }
  return std::nullopt;
}

PointIlluminance IlluminanceSolver::at(const Vec3d& point, const Vec3d& normal) const {
  PointIlluminance result;
  result.inside = containing_object(point);
  result.per_light.assign(impl_->lights.size(), 0.0);
  if (result.inside) return result;
  for (std::size_t light = 0; light < impl_->lights.size(); ++light) {
    result.per_light[light] = impl_->light_at(light, point, normal);
    result.total += result.per_light[light];
  }
  return result;
}

PointIlluminance illuminance_at(const Scene& scene, const Vec3d& point, const Vec3d& normal) {
  return IlluminanceSolver(scene).at(point, normal);
}

}  // namespace penumbra::illuminance
