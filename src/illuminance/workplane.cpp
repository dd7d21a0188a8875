#include "penumbra/illuminance/workplane.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace penumbra::illuminance {
namespace {

// the fewest cells of width <= spacing across length. The quotient is rounded, so a
// length that is a multiple of the spacing to within rounding (6.1 / 0.1 =
// 60.999999999999993) gets exactly that many cells.
std::size_t cells_across(double length, double spacing) {
  const double quotient = length / spacing;
  const double nearest = std::round(quotient);
  const double cells =
      std::abs(quotient - nearest) <= 1e-9 * nearest ? nearest : std::ceil(quotient);
  return static_cast<std::size_t>(std::max(1.0, cells));
}

}  // namespace

Vec3d WorkplaneGrid::point(std::size_t column, std::size_t row) const {
  return {region.x0 + (static_cast<double>(column) + 0.5) * cell_width,
          region.y0 + (static_cast<double>(row) + 0.5) * cell_depth, height};
}

WorkplaneGrid make_workplane_grid(double height, double spacing, const PlanRegion& region) {
  for (double value : {height, spacing, region.x0, region.y0, region.x1, region.y1})
    if (!std::isfinite(value)) throw std::invalid_argument("work plane: values must be finite");
  if (!(spacing > 0)) throw std::invalid_argument("work plane: spacing must be positive");
  if (!(region.x1 > region.x0) || !(region.y1 > region.y0))
    throw std::invalid_argument("work plane: the region must have x0 < x1 and y0 < y1");
  WorkplaneGrid grid;
  grid.height = height;
  grid.region = region;
  grid.columns = cells_across(region.x1 - region.x0, spacing);
  grid.rows = cells_across(region.y1 - region.y0, spacing);
  if (static_cast<double>(grid.columns) * static_cast<double>(grid.rows) > 1e8)
    throw std::invalid_argument("work plane: more than 10^8 points");
  grid.cell_width = (region.x1 - region.x0) / static_cast<double>(grid.columns);
  grid.cell_depth = (region.y1 - region.y0) / static_cast<double>(grid.rows);
  return grid;
}

std::optional<PlanRegion> plan_bounds(const Scene& scene) {
  if (scene.objects.empty()) return std::nullopt;
  CGAL::Bbox_3 box = scene.objects.front().solid.bbox();
  for (const Object& object : scene.objects) box += object.solid.bbox();
  return PlanRegion{box.xmin(), box.ymin(), box.xmax(), box.ymax()};
}

std::vector<ReceivingPoint> workplane_points(const WorkplaneGrid& grid) {
  std::vector<ReceivingPoint> points;
  points.reserve(grid.size());
  for (std::size_t k = 0; k < grid.size(); ++k) points.push_back({grid.point(k), {0, 0, 1}});
  return points;
}

WorkplaneValues evaluate_workplane(const IlluminanceSolver& solver, const WorkplaneGrid& grid,
                                   const std::function<void(std::size_t)>& advance) {
  return {grid, illuminance_at_points(solver, workplane_points(grid), advance)};
}

WorkplaneStatistics workplane_statistics(const WorkplaneValues& values) {
  WorkplaneStatistics statistics;
  const std::size_t lights = values.values.empty() ? 0 : values.values.front().per_light.size();
  const double infinity = std::numeric_limits<double>::infinity();
  double minimum = infinity, maximum = -infinity, sum = 0;
  std::vector<std::array<double, 3>> per_light(lights, {infinity, 0, -infinity});
  for (const PointIlluminance& value : values.values) {
    if (value.inside) {
      ++statistics.excluded;
      continue;
    }
    ++statistics.points;
    minimum = std::min(minimum, value.total);
    maximum = std::max(maximum, value.total);
    sum += value.total;
    for (std::size_t light = 0; light < lights; ++light) {
      auto& [low, total, high] = per_light[light];
      low = std::min(low, value.per_light[light]);
      total += value.per_light[light];
      high = std::max(high, value.per_light[light]);
    }
  }
  statistics.per_light.assign(lights, {0, 0, 0});
  if (statistics.points == 0) return statistics;
  const double count = static_cast<double>(statistics.points);
  statistics.minimum = minimum;
  statistics.maximum = maximum;
  statistics.average = sum / count;
  statistics.uniformity = statistics.average > 0 ? minimum / statistics.average : 0;
  for (std::size_t light = 0; light < lights; ++light)
    statistics.per_light[light] = {per_light[light][0], per_light[light][1] / count,
                                   per_light[light][2]};
  return statistics;
}

}  // namespace penumbra::illuminance
