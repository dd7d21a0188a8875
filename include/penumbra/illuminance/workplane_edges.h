#pragma once
// The lines across which the work plane's illuminance may jump (issue #18; docs/illuminance.md,
// "Exact isolux lines"): the edges of the exact shadow regions of every light on the plane
// (and, for linear sources, of the umbrae, where the field's slope jumps), computed by
// compute_shadows on a receiving face laid over the plan region, and the grid squares they
// meet refined so that isolux lines are traced only inside the smooth pieces between them.

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "penumbra/illuminance/workplane.h"

namespace penumbra::illuminance {

using PlanPoint = std::array<double, 2>;

// A straight piece of a shadow or umbra boundary on the work plane: its exact end points
// rounded to doubles (plan metres).
struct PlanEdge {
  PlanPoint a, b;
  std::size_t light = 0;  // index into Scene::lights
  bool umbra = false;     // an umbra boundary of a linear source
};

struct WorkplaneEdges {
  std::vector<PlanEdge> edges;
  std::vector<std::string> warnings;  // lights whose boundaries could not be computed
};

// returns the edges of the exact shadow regions (and umbrae of linear sources) of every light
// on the plane z = height over region: compute_shadows on the upper face of a flat polygon
// (the region's rectangle) added to a copy of scene, with the sphere of lighting of `penumbra
// shadows` (a light whose sphere the rectangle lies wholly outside has no edges). A light
// whose shadows compute_shadows refuses (a tube touching an occluder) is named in warnings.
WorkplaneEdges workplane_shadow_edges(const Scene& scene, double height, const PlanRegion& region);

// One square of the grid (between the centres of cells (i, j) and (i + 1, j + 1)) that an
// edge meets, cut into refine x refine sub-squares with the illuminance at their corners.
struct RefinedSquare {
  std::size_t i = 0, j = 0;
  std::vector<double> values;  // (refine + 1)^2 corner values, row by row from (i, j); NaN:
                               // inside an object
  std::vector<char> cut;       // refine^2 sub-squares, row by row: 1 where an edge meets it
};

struct WorkplaneRefinement {
  int refine = 8;
  std::vector<RefinedSquare> squares;
  std::size_t evaluations = 0;  // exact illuminance evaluations added

  // returns the corner (a, b), 0 <= a, b <= refine, of a refined square in plan metres.
  static PlanPoint corner(const WorkplaneGrid& grid, const RefinedSquare& square, int refine, int a,
                          int b);
};

// refines the squares of values' grid that an edge meets (or touches: the test is made on
// the square grown by 1e-9 of the spacing, so rounding cannot miss one) with the solver's
// illuminance at the new corners (normal +z, in parallel). Precondition: refine >= 1.
WorkplaneRefinement refine_workplane(const IlluminanceSolver& solver, const WorkplaneValues& values,
                                     const std::vector<PlanEdge>& edges, int refine = 8);

}  // namespace penumbra::illuminance
