#include "penumbra/illuminance/scene_illuminance.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "penumbra/base/input_error.h"
#include "penumbra/base/parallel.h"
#include "penumbra/illuminance/point_source.h"
#include "penumbra/photometry/orientation.h"
#include "solver_impl.h"

namespace penumbra::illuminance {

using namespace detail;

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
    } else if (const auto* panel = std::get_if<AreaLight>(&light.source)) {
      impl->cached.emplace_back(cache_area(*panel, impl->occluders));
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

double IlluminanceSolver::Impl::light_at(std::size_t light, const QueryPoint& point,
                                         const Vec3d& normal, OccluderSubset subset) const {
  return std::visit(
      [&](const auto& cached_light) -> double {
        using T = std::decay_t<decltype(cached_light)>;
        if constexpr (std::is_same_v<T, CachedPoint>)
          return point_light(cached_light, point, normal, subset);
        else if constexpr (std::is_same_v<T, CachedLinear>)
          return linear_light(cached_light, point, normal, subset);
        else if constexpr (std::is_same_v<T, CachedArea>)
          return area_light(cached_light, point, normal, subset);
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

ReceivingPoint receiving_point(const std::array<double, 6>& values, const std::string& file,
                               const std::string& where) {
  constexpr double kNormalLengthTolerance = 1e-3;
  for (double value : values)
    if (!std::isfinite(value)) throw InputError(file, where, "a value is not a finite number");
  ReceivingPoint receiver{{values[0], values[1], values[2]}, {values[3], values[4], values[5]}};
  const double length =
      std::sqrt(values[3] * values[3] + values[4] * values[4] + values[5] * values[5]);
  if (length == 0)
    throw InputError(file, where + ", columns nx,ny,nz", "the normal is the zero vector");
  if (std::abs(length - 1) > kNormalLengthTolerance)
    throw InputError(
        file, where + ", columns nx,ny,nz",
        "the normal has length " + std::to_string(length) + "; give a unit vector (within 1e-3)");
  for (double& n : receiver.normal) n /= length;
  return receiver;
}

std::vector<PointIlluminance> illuminance_at_points(
    const IlluminanceSolver& solver, const std::vector<ReceivingPoint>& receivers,
    const std::function<void(std::size_t)>& advance) {
  std::vector<PointIlluminance> values(receivers.size());
  for_each_range(
      receivers.size(), true,
      [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k != end; ++k)
          values[k] = solver.at(receivers[k].point, receivers[k].normal);
        if (advance) advance(end - begin);
      },
      16);
  return values;
}

}  // namespace penumbra::illuminance
