#pragma once
// Isolux lines of a work-plane grid (marching squares) and the levels they are drawn at
// (Nishita 1985 section 5). Drawing only: doubles throughout. The isolux plot that draws
// them is io/isolux_svg.h. See docs/illuminance.md, "Isolux plot".

#include <array>
#include <vector>

#include "penumbra/illuminance/workplane.h"
#include "penumbra/illuminance/workplane_edges.h"

namespace penumbra::illuminance {

struct IsoluxLine {
  double level = 0;  // lux
  std::vector<PlanPoint> points;
  bool closed = false;  // the last point joins the first
};

// returns "nice" contour levels strictly between minimum and maximum: a 1-2-5 series
// when maximum / minimum > 20 (the lowest at or above max(minimum, maximum / 1000)),
// otherwise about eight equal steps of 1, 2 or 5 x 10^k. Empty when maximum <= minimum.
std::vector<double> isolux_levels(double minimum, double maximum);

// returns the levels of a picture's values (lux or cd/m^2, one per pixel that sees
// something; reordered): isolux_levels between the 2nd and the 98th percentile of the
// positive values, so that a few pixels in deep shade or in the sun's glare do not stretch
// the levels past what most of the picture shows. Empty when there are no positive values.
std::vector<double> picture_levels(std::vector<double> values);

// traces the isolux lines of the grid's total illuminance at each level by marching
// squares over the cell centres, interpolating linearly along the square edges. Squares
// with a corner inside an object are skipped; a saddle square is resolved by the mean of
// its corners. Segments are joined into polylines.
std::vector<IsoluxLine> isolux_lines(const WorkplaneValues& values,
                                     const std::vector<double>& levels);

// the same, never across a shadow or umbra boundary (docs/illuminance.md, "Exact isolux
// lines"): the squares of refinement are not traced whole; inside each, the sub-squares no
// boundary meets are traced with the exact values at their corners, so a line stops within
// one sub-square (spacing / refine) of a boundary, and the boundary itself, drawn from the
// exact polygons, is where the field passes the levels between its two sides.
std::vector<IsoluxLine> isolux_lines(const WorkplaneValues& values,
                                     const std::vector<double>& levels,
                                     const WorkplaneRefinement& refinement);

}  // namespace penumbra::illuminance
