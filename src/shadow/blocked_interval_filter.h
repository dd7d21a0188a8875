#pragma once
// The filter in front of blocked_interval (blocked_interval.h): the same clipping of the
// triangle (P, q1, q2) to a convex solid in interval arithmetic ("exact numbers only where
// needed", docs/performance.md). Each clipped vertex carries where it lies (the triangle's
// sides, the solid's planes), so the edge that fixes an end of the blocked interval is named
// combinatorially, not by a geometric test. A result is certain: every sign and every
// comparison it rests on is certified by the intervals; otherwise nullopt, and the caller
// asks the exact function. Needs upward rounding (CGAL::Protect_FPU_rounding<true>).

#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "blocked_interval.h"
#include "penumbra/geometry/interval.h"

namespace penumbra::detail {

// A solid for the filter: its planes as intervals, each plane's geometric id (a flat
// polygon's two faces share one), and the edge on which two geometric planes meet.
struct IntervalSolid {
  std::vector<std::array<Interval, 4>> planes;
  std::vector<int> geometric;
  std::map<std::pair<int, int>, int> edge_of;  // (smaller id, larger id) -> edge index
  // for one source, each edge's parameter t(P) = (g_n . P + h_n) / (g_d . P + h_d)
  // (edge_parameter in blocked_interval.h) enclosed: g_n, h_n, g_d, h_d; empty: not made
  std::vector<std::array<Interval, 8>> edge_parameters;
};

// the filter of a solid made by rational_solid (its enclosures filled).
IntervalSolid interval_solid(const RationalSolid& solid);

// fills solid.edge_parameters with the enclosures of edges (edge_parameters() of its solid
// for one source).
void enclose_edge_parameters(IntervalSolid& solid, const std::vector<EdgeParameter>& edges);

// returns the interval enclosure of a rational point.
IntervalPoint interval_point(const RationalPoint3& p);

// What the filter certifies of the blocked interval: kind, the ends' edges (-1 for a
// clamp), and enclosures of the ends (exactly 0 or 1 for a clamp).
struct BlockedBounds {
  BlockedInterval::Kind kind = BlockedInterval::Kind::none;
  Interval low = 0, high = 0;
  int low_edge = -1, high_edge = -1;
  bool low_clamped = false, high_clamped = false;
};

// returns the certified blocked interval of the source q1q2 from p (outside the solid), or
// nullopt when the intervals cannot decide. An end fixed by an edge is enclosed both from
// the clipped vertex and, when the solid has them for this source, from the edge's
// parameter at p, which does not grow with the clipping's steps.
std::optional<BlockedBounds> blocked_bounds(const IntervalSolid& solid, const IntervalPoint& p,
                                            const IntervalPoint& q1, const IntervalPoint& q2);

// returns whether the closed intervals cover [0, 1] (covers_source), or nullopt when the
// intervals cannot decide.
std::optional<bool> covers_source(const std::vector<BlockedBounds>& intervals);

}  // namespace penumbra::detail
