#pragma once
// Illuminance on a horizontal work plane: a grid of receiving points with normal +z,
// its statistics (minimum, average, maximum, uniformity U0 = Emin / Eavg) and the
// values the isolux plot contours. See docs/illuminance.md, "Work plane".
//
// The region is cut into the fewest equal cells no wider than the spacing in each
// direction, and each cell is represented by its centre (as in EN 12464-1 and CIE
// grids), so the average is an area average and no point lies on the region's edge.

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "penumbra/illuminance/scene_illuminance.h"

namespace penumbra::illuminance {

// A rectangle of the plan (metres): x0 < x1, y0 < y1.
struct PlanRegion {
  double x0, y0, x1, y1;
};

struct WorkplaneGrid {
  double height = 0;        // z of the plane
  PlanRegion region{};      // the area covered
  std::size_t columns = 0;  // cells along x
  std::size_t rows = 0;     // cells along y
  double cell_width = 0;    // (x1 - x0) / columns <= spacing
  double cell_depth = 0;    // (y1 - y0) / rows <= spacing

  std::size_t size() const { return columns * rows; }
  // returns the centre of cell (column, row); points are stored row by row.
  Vec3d point(std::size_t column, std::size_t row) const;
  Vec3d point(std::size_t index) const { return point(index % columns, index / columns); }
};

// builds the grid of `region` at `height` with cells no wider than `spacing`.
// Preconditions (std::invalid_argument otherwise): finite values, spacing > 0, a region of
// positive width and depth, at most 10^8 points.
WorkplaneGrid make_workplane_grid(double height, double spacing, const PlanRegion& region);

// returns the scene's bounding box in x and y (the union of its objects' boxes), or {}
// for a scene without objects.
std::optional<PlanRegion> plan_bounds(const Scene& scene);

struct WorkplaneValues {
  WorkplaneGrid grid;
  std::vector<PointIlluminance> values;  // values[k] at grid.point(k)
};

// returns the grid's points, row by row, each with the normal +z.
std::vector<ReceivingPoint> workplane_points(const WorkplaneGrid& grid);

// computes the illuminance at every grid point (normal +z), in parallel (TBB).
// `advance`, when given, is called with the number of points finished (from several
// threads) for a progress display.
WorkplaneValues evaluate_workplane(const IlluminanceSolver& solver, const WorkplaneGrid& grid,
                                   const std::function<void(std::size_t)>& advance = {});

struct WorkplaneStatistics {
  std::size_t points = 0;    // grid points counted
  std::size_t excluded = 0;  // grid points strictly inside an object, not counted
  double minimum = 0, average = 0, maximum = 0;  // lux
  // U0 = Emin / Eavg; 0 when Eavg is 0.
  double uniformity = 0;
  // the same for each light alone (in Scene::lights order)
  std::vector<std::array<double, 3>> per_light;  // {minimum, average, maximum}
};

// returns the statistics of the points not inside an object; all zero when there are none.
WorkplaneStatistics workplane_statistics(const WorkplaneValues& values);

}  // namespace penumbra::illuminance
