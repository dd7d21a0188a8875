#pragma once
// The part of a linear source q1 + t (q2 - q1), t in [0, 1], that one convex occluder hides
// from a point P (exact_umbra.h): the closed interval of t whose segments P -> source meet
// the closed occluder, found by clipping the triangle (P, q1, q2) to the solid (Nishita 1985
// section 4.2.3 integrates over the complement). Each end is either a clamp (0 or 1, where
// the segment P q1 or P q2 itself is blocked) or fixed by an edge of the occluder: the line
// from P through the edge meets the source there (the end's t as a function of P is
// N_e(P) / D_e(P), both affine: edge_parameter below).

#include <array>
#include <vector>

#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/geometry/exact.h"
#include "penumbra/geometry/interval.h"

namespace penumbra::detail {

// A convex occluder in rationals: its vertices, the closed half-spaces (plane <= 0) whose
// intersection it is (a flat polygon: its plane both ways and a plane through each edge),
// and its edges as vertex index pairs.
struct RationalSolid {
  std::vector<RationalPoint3> vertices;
  std::vector<RationalPlane3> planes;
  std::vector<std::array<int, 2>> edges;
  // the enclosures of the vertices and of the planes' coefficients (interval filters)
  std::vector<IntervalPoint> approx_vertices;
  std::vector<std::array<Interval, 4>> approx_planes;
};

RationalSolid rational_solid(const ConvexPolyhedron& solid);

struct BlockedInterval {
  enum class Kind { none, full, interval };
  Kind kind = Kind::none;
  Rational low = 0, high = 0;
  int low_edge = -1, high_edge = -1;  // -1: the end is a clamp or a constant
};

// returns what solid hides of the source q1q2 from p, which must not lie on a line through
// a vertex of the solid and a point of the source's line (then an end's edge is ambiguous).
BlockedInterval blocked_interval(const RationalSolid& solid, const RationalPoint3& p,
                                 const RationalPoint3& q1, const RationalPoint3& q2);

// returns true when the closed intervals cover [0, 1] (touching intervals cover).
bool covers_source(std::vector<BlockedInterval> intervals);

// The parameter t at which the line through P meeting the edge's line meets the source's
// line: t = (g_n . P + h_n) / (g_d . P + h_d).
struct EdgeParameter {
  RationalVector3 gn, gd;
  Rational hn, hd;
};

EdgeParameter edge_parameter(const RationalPoint3& e0, const RationalPoint3& e1,
                             const RationalPoint3& q1, const RationalPoint3& q2);

// the parameter of each edge of solid (in the order of solid.edges) for the source q1q2.
std::vector<EdgeParameter> edge_parameters(const RationalSolid& solid, const RationalPoint3& q1,
                                           const RationalPoint3& q2);

}  // namespace penumbra::detail
