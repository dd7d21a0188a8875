#pragma once
// The exact umbra of a linear source on one face, joint occlusion included (issue #17,
// docs/linear-shadows.md "Joint umbrae"). A point P of the face is in the umbra when the
// blocked parts of the source (one closed interval of the source's parameter per convex
// occluder) together cover the whole visible source (Nishita 1985 section 4.1.2, the
// source cut by the face's plane as in Fig. 7, S3). Where two occluders block the tube
// together, the umbra ends where the gap between their intervals closes: the end of one
// interval is fixed by an edge e of the first occluder, the start of the next by an edge f
// of the second, and the lines through P that meet the source's line, e and f form a
// regulus: the boundary is the conic in which that quadric meets the face's plane, with
// rational coefficients. Every decision is exact: CGAL's algebraic kernel isolates the
// conics' crossings, and every cell of the decomposition is labelled at a rational point.
//
// The set is the closure of the open set of covered points (regularized, as every region
// of DESIGN.md): intervals that only touch still cover, as abutting shadows merge.

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/shadow/region.h"

namespace penumbra {

// An occluder prepared once for a source, for every face it shadows (exact_umbra.cpp).
struct UmbraSolid;

// prepares solid for the source q1q2 (the end points in the order exact_umbra gets them).
std::shared_ptr<const UmbraSolid> prepare_umbra_solid(const ConvexPolyhedron& solid,
                                                      const Point3& q1, const Point3& q2);

// One convex occluder of the face: the solid and its whole shadow (penumbra and umbra) on
// the face, a convex ring in the face's frame (OccluderShadow::polygon).
struct UmbraOccluder {
  const ConvexPolyhedron* solid;
  Ring2 shadow;
  std::optional<Ring2> umbra;  // its single umbra (OccluderShadow::umbra), convex
  // optional: the solid prepared for the source (used when the face's plane does not cut it)
  std::shared_ptr<const UmbraSolid> prepared{};
};

// A piece of the umbra's boundary: part of a line or a conic of the face's frame,
// a s^2 + b s t + c t^2 + d s + e t + f = 0 in frame coordinates (s, t); a = b = c = 0 for
// a segment. points runs along the piece with the umbra on its left, densified so that the
// chords stay within the tolerance given to exact_umbra (world units) of the curve.
struct UmbraArc {
  std::array<Exact, 6> curve;
  bool straight = true;
  bool joint = false;  // the gap between two occluders' blocked intervals closes here
  std::vector<std::array<double, 2>> points;
};

// A ring of a curved region: its points (frame coordinates, doubles) counter-clockwise for
// an outer boundary and clockwise for a hole, the curved pieces densified as in UmbraArc;
// arcs names the curved edges: points[first..last] lie on the conic (last may be
// points.size(): the arc ends at the ring's first point).
struct RingArc {
  std::size_t first, last;
  std::array<Exact, 6> curve;
  bool joint = false;
};

struct CurvedRing {
  std::vector<std::array<double, 2>> points;
  std::vector<RingArc> arcs;
};

struct CurvedPolygon {
  CurvedRing outer;
  std::vector<CurvedRing> holes;
};

// A real algebraic coordinate of a corner, exactly: its rational value, or else the root-th
// (from 0, increasing) real root of polynomial (integer coefficients, lowest degree first,
// squarefree, primitive, leading coefficient positive).
struct AlgebraicCoordinate {
  std::optional<Exact> value;
  std::vector<Exact> polynomial;
  int root = 0;
};

// A corner of a curved ring in frame coordinates (s, t). Rational (value) where both edges
// meeting there are straight; otherwise s is a root of the resultant of the two edges'
// curves eliminating t, and t of the one eliminating s (their squarefree, primitive parts),
// written as its value when that part is linear.
struct ExactCorner {
  AlgebraicCoordinate s, t;
};

// An edge of an exact curved ring: from its corner along curve (a s^2 + b s t + c t^2 + d s +
// e t + f = 0, scaled so that its first nonzero coefficient is 1) to the next edge's corner.
// Consecutive edges lie on different curves, or on one degenerate conic (a pair of lines).
struct ExactEdge {
  ExactCorner from;
  std::array<Exact, 6> curve;
  bool joint = false;
};

// A curved polygon in canonical form: each ring starts at its lexicographically smallest
// corner (s, then t), the outer ring counter-clockwise and holes clockwise; holes, and the
// polygons of a region, in the order of their rings (corner by corner).
struct ExactCurvedPolygon {
  std::vector<ExactEdge> outer;
  std::vector<std::vector<ExactEdge>> holes;
};

class ExactUmbra {
 public:
  struct Impl;
  explicit ExactUmbra(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

  // returns true when p (frame coordinates) lies in the closed umbra. Exact.
  bool contains(const Point2& p) const;
  // returns true when p lies in the closed penumbra (shadow - umbra, regularized). Exact.
  bool in_penumbra(const Point2& p) const;
  // the umbra's area in frame units (world area = area |u| |v|), by Gauss-Legendre
  // quadrature over s of the exact cells' bounds (1e-13 relative per column).
  double area() const;
  // the umbra's boundary, piece by piece (not chained into rings).
  const std::vector<UmbraArc>& boundary() const;
  // the penumbra (shadow - umbra): its area and boundary, alike.
  double penumbra_area() const;
  const std::vector<UmbraArc>& penumbra_boundary() const;
  // the umbra and the penumbra as polygons with holes: the pieces chained through their
  // exact ends (the same line of the pencil and the same r, compared exactly).
  const std::vector<CurvedPolygon>& umbra_polygons() const;
  const std::vector<CurvedPolygon>& penumbra_polygons() const;
  // the umbra and the penumbra exactly, in canonical form (computed on each call: root
  // isolation per corner).
  std::vector<ExactCurvedPolygon> exact_umbra_polygons() const;
  std::vector<ExactCurvedPolygon> exact_penumbra_polygons() const;
  // true when some part of the umbra is covered by no single occluder alone.
  bool joint() const;
  // the number of cells of the decomposition (columns x cells), for benchmarks.
  std::size_t cells() const;

 private:
  std::shared_ptr<const Impl> impl_;
};

// computes the exact umbra and penumbra of the source q1q2 on face (the source cut by the
// face's plane, Fig. 7 S3) under the convex occluders: the single umbrae (straight, the
// occluders' umbra rings) and the joint part, which the sweep finds where two occluders'
// whole shadows overlap and both ends of the source are hidden (elsewhere at most one
// occluder hides anything, or some end is seen). Occluders whose shadows are strictly apart
// are swept in separate groups, in parallel (docs/linear-shadows.md, "Groups swept apart").
// tolerance: the densified boundary's chord error, in world units. Precondition: the visible
// part of the source meets no occluder.
ExactUmbra exact_umbra(const Face& face, const Point3& q1, const Point3& q2,
                       const std::vector<UmbraOccluder>& occluders, double tolerance = 1e-6);

// the same on a face made of convex pieces (a mesh face, which may be non-convex and have
// holes: scene.h, MeshFace): face gives the plane, the frame and the area, pieces the closed
// convex pieces that tile it and boundary its rings (outer, then holes), all in face's
// frame; each occluder's shadow and umbra are convex rings that agree with its whole shadow
// and single umbra on the face.
ExactUmbra exact_umbra(const Face& face, const std::vector<Ring2>& pieces,
                       const std::vector<Ring2>& boundary, const Point3& q1, const Point3& q2,
                       const std::vector<UmbraOccluder>& occluders, double tolerance = 1e-6);

// exact_umbra, made only when the umbra may have a joint part: nullopt when no touching group
// of occluders may hide the source together anywhere on the face (docs/linear-shadows.md,
// "Groups without W"), and then the straight single umbrae are the exact umbra. What the
// shadows pipeline asks; the sweep is left out where it would find nothing joint.
std::optional<ExactUmbra> joint_umbra(const Face& face, const Point3& q1, const Point3& q2,
                                      const std::vector<UmbraOccluder>& occluders,
                                      double tolerance = 1e-6);

}  // namespace penumbra
