#pragma once
// The isolux plot of a work plane as SVG: coloured belts between the isolux lines (Nishita
// 1985 section 5, in the colour scale of base/colour_scale.h), the lines with lux labels, a
// colour legend and the plan of the objects seen from above. Drawing only. See
// docs/illuminance.md, "Isolux plot".

#include <ostream>
#include <vector>

#include "penumbra/illuminance/isolux.h"
#include "penumbra/illuminance/workplane.h"
#include "penumbra/illuminance/workplane_edges.h"

namespace penumbra::io {

// The exact boundaries of a work plane (illuminance/workplane_edges.h): drawn as lines,
// the squares they meet drawn and contoured at the refinement's resolution.
struct IsoluxBoundaries {
  std::vector<illuminance::PlanEdge> edges;
  illuminance::WorkplaneRefinement refinement;
};

// writes the isolux plot of values over the plan of scene (x to the right, y up) with lines
// at levels (lux, increasing); with boundaries, the shadow and umbra edges are drawn (group
// "shadow-boundaries": one line per edge, umbra edges dashed) and no isolux line crosses
// them (docs/illuminance.md, "Exact isolux lines").
void write_isolux_svg(std::ostream& out, const Scene& scene,
                      const illuminance::WorkplaneValues& values, const std::vector<double>& levels,
                      const IsoluxBoundaries& boundaries = {});

}  // namespace penumbra::io
