#pragma once
// Shadow volumes of a convex occluder V under a linear source Q1Q2: Nishita 1985
// section 4.1.1 and Appendix A2. U_r is the shadow volume from the end point Q_r;
// the umbra volume is U1 ∩ U2; the penumbra volume is the smallest convex volume
// containing U1 and U2. Case A: U1 and U2 cross, the two planes through the line
// Q1Q2 tangent to V touch it at P_L and P_R. Case B: the line Q1Q2 meets V, and
// the shadow volume of the end point nearer to V encloses the other.
//
// Every volume is open: the points X with plane(X) < 0 for each of its planes.
//
// An end of the source may be open: the cut point of a source clipped by a receiving face's
// plane (Fig. 7, S3), where the light is grazing. The volumes are then the limits of those of
// the segments whose end approaches the cut point from inside the source. A plane through that
// end and an edge of V is the limit of planes turning about the edge; where it holds the
// receiving face (the edge lies in the face's plane too), every point of the face is on it, and
// the side of the face it keeps is decided by the first-order turn (docs/linear-shadows.md,
// "The face and the source"): OpenVolume::limits.

#include <optional>
#include <utility>
#include <vector>

#include "penumbra/geometry/convex_polyhedron.h"

namespace penumbra {

enum class LinearCase { A, B };

// The half-space that stands for planes[plane] on a receiving face lying in that plane: the
// plane through the edge ab of V and the direction d from the open end q into the source,
// oriented as planes[plane]'s perturbation is. Plane [q + e d, a, b] has the normal
// (a - q) x (b - q) + e (b - a) x d, exactly (d x d = 0), so on the plane [q, a, b] its sign
// is that of e ((b - a) x d) . (X - a) for every e > 0.
struct PlaneLimit {
  std::size_t plane;
  Plane3 limit;
};

struct OpenVolume {
  std::vector<Plane3> planes;  // oriented so that the volume is on their negative sides
  // One per edge whose plane passes through an open end of the source; several for one plane
  // when edges in the face's plane give the same plane through that end.
  std::vector<PlaneLimit> limits;

  // returns true when x is strictly inside every plane.
  bool contains(const Point3& x) const;
};

struct LinearVolumes {
  LinearCase kind;
  std::vector<int> contour1;  // C1, vertex ids, clockwise seen from Q1
  std::vector<int> contour2;  // C2, clockwise seen from Q2
  int left = -1;              // P_L (Case A), a vertex id common to C1 and C2
  int right = -1;             // P_R (Case A)
  bool nearer_is_q1 = false;  // Case B: Q1 is the end point nearer to V
  OpenVolume shadow1;         // U1
  OpenVolume shadow2;         // U2
  OpenVolume umbra;           // App. A2 umbra planes (Case A) or U of the farther end (Case B)
  OpenVolume penumbra;        // App. A2 penumbra planes (Case A) or U of the nearer end (Case B)
};

// returns the parameter interval [t0, t1] of the line q1 + t (q2 - q1) inside the
// closed solid (for a two-sided polygon, the closed polygon), or nullopt when the
// line misses it. Precondition: q1 != q2.
std::optional<std::pair<Exact, Exact>> line_in_solid(const ConvexPolyhedron& solid,
                                                     const Point3& q1, const Point3& q2);

// Which end of the source q1q2 is open (the cut point of a clipped source), if any.
enum class OpenEnd { none, q1, q2 };

// returns the shadow volume U_r of solid from the point source q: the planes
// through q and each contour edge, and the planes of the faces turned toward q
// (section 4.1.1). Empty planes (no shadow) when no face is turned toward q. When into is
// given, q is an open end and *into the direction from it into the source: the planes through
// q get their limits.
OpenVolume point_shadow_volume(const ConvexPolyhedron& solid, const Point3& q,
                               const Vector3* into = nullptr);

// point_shadow_volume's planes as exact rationals, made in rationals from the solid's
// vertices and its faces' planes given exactly (face_planes[f] the plane of face f; more
// may follow): the same planes in the same order, without Epeck's lazy constructions.
std::vector<RationalPlane3> exact_point_shadow_planes(
    const ConvexPolyhedron& solid, const std::vector<RationalPoint3>& vertices,
    const std::vector<RationalPlane3>& face_planes, const Point3& q);

// returns the vertices that may serve as P_L and as P_R (App. A2, eqs. 9-10):
// vertices common to C1 and C2 whose plane [Q1, Q2, P] (CGAL orientation of Q1, Q2, P, X)
// has every vertex X of the solid on its non-positive side (P_L) or non-negative side
// (P_R): the scan's inequalities flipped, see linear_volumes.cpp. Several qualify
// when the line Q1Q2 is coplanar with contour edges. Both empty in Case B.
std::pair<std::vector<int>, std::vector<int>> tangent_vertices(const ConvexPolyhedron& solid,
                                                               const Point3& q1, const Point3& q2);

// returns the penumbra and umbra volumes of Case A for a given choice of P_L and P_R.
// open: which end is open (its string planes get their limits).
std::pair<OpenVolume, OpenVolume> case_a_volumes(const ConvexPolyhedron& solid, const Point3& q1,
                                                 const Point3& q2, const std::vector<int>& contour1,
                                                 const std::vector<int>& contour2, int left,
                                                 int right, OpenEnd open = OpenEnd::none);

// classifies the occluder and builds its volumes, choosing the smallest vertex ids
// among the candidates for P_L and P_R (the result does not depend on the choice:
// tests/shadow/linear_volumes_test.cpp). Returns nullopt when solid casts no shadow
// from either end point. Precondition: q1 != q2 and the closed segment q1q2 does not
// meet the closed solid. open: which end is the open cut point of a clipped source.
std::optional<LinearVolumes> linear_volumes(const ConvexPolyhedron& solid, const Point3& q1,
                                            const Point3& q2, OpenEnd open = OpenEnd::none);

// returns the penumbra volume a second way: the facets, touching the solid, of the
// exact convex hull of the solid's vertices and their images pushed away from Q1
// and from Q2 (conv(U1 ∪ U2) truncated). Used to check the App. A2 construction.
std::vector<Plane3> penumbra_planes_by_hull(const ConvexPolyhedron& solid, const Point3& q1,
                                            const Point3& q2);

}  // namespace penumbra
