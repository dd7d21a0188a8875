#pragma once
// The isolux plot of a work plane as SVG: coloured belts between the isolux lines (Nishita
// 1985 section 5, in the colour scale of base/colour_scale.h), the lines with lux labels, a
// colour legend and the plan of the objects seen from above. Drawing only. See
// docs/illuminance.md, "Isolux plot".

#include <ostream>
#include <vector>

#include "penumbra/illuminance/isolux.h"
#include "penumbra/illuminance/workplane.h"

namespace penumbra::io {

// writes the isolux plot of values over the plan of scene (x to the right, y up) with lines
// at levels (lux, increasing).
void write_isolux_svg(std::ostream& out, const Scene& scene,
                      const illuminance::WorkplaneValues& values,
                      const std::vector<double>& levels);

}  // namespace penumbra::io
