#pragma once
// Shadow volumes of a convex occluder V under a convex polygonal (area) source S with
// vertices Q_1 ... Q_n (docs/area-sources.md, Nishita and Nakamae's area-source case).
// U_i is the shadow volume from the vertex Q_i (linear_volumes.h: point_shadow_volume).
//
// - Penumbra volume (the points some point of S cannot see because of V): conv(U_1 ∪ ... ∪
//   U_n). It is bounded by the planes that separate V from S, and it is their intersection:
//   the points on V's side of every plane with V on one closed side and S on the other. Those
//   planes form a convex cone whose extreme members pass through three vertices of V and S
//   together: a face of V, the plane of S, or an edge of one and a vertex of the other.
// - Umbra volume (the points that see nothing of S because of V): U_1 ∩ ... ∩ U_n. The part
//   of S that V hides from a point is convex (a central projection of V), so V hides all of
//   S exactly when it hides every vertex.
//
// Every volume is open, as in linear_volumes.h; faces report their closures.

#include <optional>
#include <vector>

#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/shadow/linear_volumes.h"

namespace penumbra {

struct AreaVolumes {
  OpenVolume penumbra;  // conv(U_1 ∪ ... ∪ U_n)
  // U_1 ∩ ... ∩ U_n: the planes of every U_i; nullopt when some vertex of S sees no face of V
  // (V hides that vertex from nowhere: no umbra).
  std::optional<OpenVolume> umbra;
};

// returns true when the closed convex polygon source (vertices in cycle order) meets the
// closed solid.
bool polygon_meets_solid(const std::vector<Point3>& source, const ConvexPolyhedron& solid);

// returns the planes separating solid from the convex polygon source (vertices in cycle
// order, no three on a line), oriented with solid on their closed negative side and source
// on their closed positive side, without repeats: the penumbra volume's planes. Empty when
// solid and source lie in one plane. Precondition: they do not meet.
std::vector<Plane3> separating_planes(const ConvexPolyhedron& solid,
                                      const std::vector<Point3>& source);

// builds the volumes of solid under the source, or nullopt when it casts nothing (no face
// of solid is turned toward a vertex of the source, or both lie in one plane). Throws
// std::domain_error when the closed source meets the closed solid.
std::optional<AreaVolumes> area_volumes(const ConvexPolyhedron& solid,
                                        const std::vector<Point3>& source);

}  // namespace penumbra
