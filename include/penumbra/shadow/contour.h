#pragma once
// The contour line (silhouette) of a convex polyhedron seen from a point source:
// Nishita 1985 section 4.1.1, C_r "the silhouette contour of V when viewed from an
// end point Q_r", defined clockwise seen from the source (section 4.1.2).

#include <vector>

#include "penumbra/geometry/convex_polyhedron.h"

namespace penumbra {

// returns the contour of solid seen from source as vertex ids, clockwise seen from
// the source, starting at the smallest id. The contour runs along the edges between
// faces turned toward the source (F(S, Q) > 0) and the others; a face whose plane
// holds the source is edge-on and counts as not turned toward it, so the contour
// keeps that face's near vertices (several may be collinear seen from the source).
// Empty when no face is turned toward the source: the source is inside or on the
// solid, or in the plane of a flat polygon.
std::vector<int> contour(const ConvexPolyhedron& solid, const Point3& source);

// returns true when face f of solid is turned toward source: F(S_f, Q) > 0.
inline bool turned_toward(const Face& face, const Point3& source) {
  return face.plane.oriented_side(source) == CGAL::ON_POSITIVE_SIDE;
}

}  // namespace penumbra
