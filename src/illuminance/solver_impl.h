#pragma once
// The illuminance solver's state (private to scene_illuminance.cpp and
// linear_visibility.cpp): copies of the scene's objects and lights, the occluders with
// their boxes, what each light caches, and the queries' steps.

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <variant>
#include <vector>

#include "box_cull.h"
#include "interval_filters.h"
#include "penumbra/illuminance/linear_source.h"
#include "penumbra/illuminance/scene_illuminance.h"

namespace penumbra::illuminance {
namespace detail {

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

struct CachedArea {
  const AreaLight* light;
  Box box;  // of the source
  // in_front[f][k]: every vertex of occluder k certainly strictly on the outer side of the
  // plane of the source's face f (intervals), so between that plane and any point that face
  // lights.
  std::array<std::vector<char>, 2> in_front;
};

using CachedLight = std::variant<CachedPoint, CachedLinear, CachedDirectional, CachedArea>;

// returns what the solver caches of a panel among occluders (area_visibility.cpp).
CachedArea cache_area(const AreaLight& panel, const std::vector<Occluder>& occluders);

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

}  // namespace detail

struct IlluminanceSolver::Impl {
  using CachedPoint = detail::CachedPoint;
  using CachedLinear = detail::CachedLinear;
  using CachedDirectional = detail::CachedDirectional;
  using CachedArea = detail::CachedArea;
  using QueryPoint = detail::QueryPoint;
  using OccluderSubset = detail::OccluderSubset;

  std::vector<Object> objects;  // copies: the solver owns what it queries
  std::vector<Light> lights;
  std::vector<detail::Occluder> occluders;
  std::vector<detail::CachedLight> cached;
  detail::BoxGrid solids;  // the occluders that have an interior (not flat), by box

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
  double area_light(const CachedArea& panel, const QueryPoint& point, const Vec3d& normal,
                    OccluderSubset subset) const;
  double light_at(std::size_t light, const QueryPoint& point, const Vec3d& normal,
                  OccluderSubset subset) const;
  std::optional<std::size_t> containing_object(const QueryPoint& point) const;
  PointIlluminance at(const Vec3d& point, const Vec3d& normal,
                      const std::vector<std::vector<std::size_t>>* subsets) const;
};

}  // namespace penumbra::illuminance
