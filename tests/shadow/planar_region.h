#pragma once
// Exact point location in a planar polygon with holes given in 3D (a face of a mesh
// model, a shadow or lit polygon of the shadow JSON), for the mesh oracle
// (mesh_oracle.h). Written independently of the engine: no projection, no 2D kernel.
//
// The test is the winding number (Sunday's crossing rule with half-open edges) computed in
// the plane itself. Take an "up" direction w in the plane, w = n x e with e the coordinate
// axis along which the normal n has its smallest component (then w != 0 and w . n = 0),
// and heights h(q) = w . q. With right = w x n, the frame (right, w, n) is right-handed,
// since (w x n) x w = |w|^2 n - (w . n) w = |w|^2 n; so the 2D cross product of in-plane
// vectors u and v in the frame (right, w) is (right . u)(w . v) - (right . v)(w . u) =
// (right x w) . (u x v) = |w|^2 n . (u x v). Its sign is the orientation of (edge, point)
// against the face's normal, the test oracle.h uses for convex polygons. A point lies on a
// ring when that orientation is zero and it lies between the edge's ends.

#include <cstddef>
#include <utility>
#include <vector>

#include "penumbra/geometry/kernel.h"

namespace penumbra::test {

enum class Place { inside, boundary, outside };

class PlanarRegion {
 public:
  // outer and holes: rings of points of one plane with normal `normal` (either
  // orientation: the winding number's sign is not used, only whether it is zero).
  PlanarRegion(const Vector3& normal, const std::vector<Point3>& outer,
               const std::vector<std::vector<Point3>>& holes)
      : normal_(normal) {
    const Exact ax = CGAL::abs(normal.x()), ay = CGAL::abs(normal.y()), az = CGAL::abs(normal.z());
    const Vector3 axis = ax <= ay && ax <= az ? Vector3(1, 0, 0)
                         : ay <= az           ? Vector3(0, 1, 0)
                                              : Vector3(0, 0, 1);
    up_ = CGAL::cross_product(normal, axis);
    rings_.push_back(prepare(outer));
    for (const auto& hole : holes) rings_.push_back(prepare(hole));
  }

  // returns where p, a point of the plane, lies: inside the outer ring and outside every
  // hole, on a ring, or outside.
  Place locate(const Point3& p) const {
    const Exact h = height(p);
    const Place in_outer = ring_place(rings_.front(), p, h);
    if (in_outer != Place::inside) return in_outer;
    for (std::size_t k = 1; k < rings_.size(); ++k) {
      const Place in_hole = ring_place(rings_[k], p, h);
      if (in_hole == Place::boundary) return Place::boundary;
      if (in_hole == Place::inside) return Place::outside;
    }
    return Place::inside;
  }

  const std::vector<Point3>& outer() const { return rings_.front().points; }

 private:
  struct Ring {
    std::vector<Point3> points;
    std::vector<Exact> heights;
  };

  Exact height(const Point3& p) const { return up_ * (p - CGAL::ORIGIN); }

  Ring prepare(const std::vector<Point3>& points) const {
    Ring ring{points, {}};
    for (const Point3& p : points) ring.heights.push_back(height(p));
    return ring;
  }

  // The winding number of the ring around p: an edge going up (h(a) <= h(p) < h(b)) with
  // p on its left counts +1, one going down (h(b) <= h(p) < h(a)) with p on its right
  // counts -1; the half-open rule counts a vertex at p's height once.
  Place ring_place(const Ring& ring, const Point3& p, const Exact& h) const {
    int winding = 0;
    const std::size_t n = ring.points.size();
    for (std::size_t k = 0; k < n; ++k) {
      const Exact& ha = ring.heights[k];
      const Exact& hb = ring.heights[(k + 1) % n];
      if ((h < ha && h < hb) || (h > ha && h > hb)) continue;  // wholly above or below p
      const Point3& a = ring.points[k];
      const Point3& b = ring.points[(k + 1) % n];
      const CGAL::Sign side = CGAL::sign(CGAL::cross_product(b - a, p - a) * normal_);
      if (side == CGAL::ZERO && (p - a) * (p - b) <= 0) return Place::boundary;
      if (ha <= h && h < hb && side == CGAL::POSITIVE) ++winding;
      if (hb <= h && h < ha && side == CGAL::NEGATIVE) --winding;
    }
    return winding != 0 ? Place::inside : Place::outside;
  }

  Vector3 normal_;
  Vector3 up_;
  std::vector<Ring> rings_;  // the outer ring first, then the holes
};

}  // namespace penumbra::test
