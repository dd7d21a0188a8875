#include "penumbra/geometry/convex_polyhedron.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "convex_hull_2.h"
#include "dyadic_vector.h"
#include "penumbra/geometry/dyadic_plane.h"
#include "penumbra/geometry/exact.h"
#include "penumbra/geometry/geometry_error.h"
#include "penumbra/geometry/point_order.h"

namespace penumbra {
namespace {

// returns the coordinates of the points when all are doubles (their intervals single
// values), or nothing.
std::optional<std::vector<Double3>> doubles_of(const std::vector<Point3>& points) {
  std::vector<Double3> coordinates;
  for (const Point3& p : points) {
    const auto x = double_coordinates(p);
    if (!x) return std::nullopt;
    coordinates.push_back(*x);
  }
  return coordinates;
}

// returns the points without their collinear ones when flat, their projection, is certainly a
// convex polygon turning `turn`: every turn that way or straight and every fan triangle from
// the first point too (so the cycle winds once). Nothing when a test fails.
template <typename FlatPoint>
std::optional<std::vector<Point3>> convex_cycle(const std::vector<Point3>& points,
                                                const std::vector<FlatPoint>& flat,
                                                CGAL::Orientation turn) {
  const std::size_t n = flat.size();
  std::vector<Point3> kept;
  for (std::size_t k = 0; k < n; ++k) {
    const CGAL::Orientation o =
        CGAL::orientation(flat[(k + n - 1) % n], flat[k], flat[(k + 1) % n]);
    if (o != turn && o != CGAL::COLLINEAR) return std::nullopt;
    if (o == CGAL::COLLINEAR) {
      // a straight point between its neighbours is dropped; a spike (turning back) is not convex
      if (!CGAL::collinear_are_ordered_along_line(flat[(k + n - 1) % n], flat[k],
                                                  flat[(k + 1) % n]))
        return std::nullopt;
      continue;
    }
    kept.push_back(points[k]);
  }
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const CGAL::Orientation o = CGAL::orientation(flat[0], flat[k], flat[k + 1]);
    if (o != turn && o != CGAL::COLLINEAR) return std::nullopt;
  }
  if (kept.size() < 3) return std::nullopt;
  return kept;
}

// returns the cycle without its collinear points when it is certainly a convex polygon turning
// counter-clockwise about normal (the points distinct and coplanar), tested seen along the
// largest component of normal, where projecting keeps or reverses every orientation alike.
// Nothing when a test fails: the caller's full check then decides (and names the point).
std::optional<std::vector<Point3>> convex_cycle(const std::vector<Point3>& points,
                                                const Vector3& normal) {
  int axis = -1;
  double largest = 0;
  for (int k = 0; k < 3; ++k) {
    const double size = std::abs(CGAL::to_double(normal[k]));
    if (size > largest && !CGAL::is_zero(normal[k])) largest = size, axis = k;
  }
  if (axis < 0) return std::nullopt;
  const CGAL::Orientation turn =
      CGAL::is_positive(normal[axis]) ? CGAL::LEFT_TURN : CGAL::RIGHT_TURN;
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  // Points with double coordinates (a model's, snapped) are tested as doubles: Epick's
  // predicates are exact on them, and no lazy number is made.
  if (const auto coordinates = doubles_of(points)) {
    std::vector<CGAL::Epick::Point_2> flat;
    for (const Double3& x : *coordinates) flat.emplace_back(x[i], x[j]);
    return convex_cycle(points, flat, turn);
  }
  std::vector<Point2> flat;
  for (const Point3& p : points) flat.emplace_back(p[i], p[j]);
  return convex_cycle(points, flat, turn);
}

// fills face's plane, frame and ring from its cycle of points given as doubles, in dyadic
// floating point (CGAL::Mpzf: sums and products of doubles are exact, with no gcd to
// reduce), each value converted to rationals once. The values are those of the lazy
// constructions (Plane_3 of the first three vertices, CGAL's formula; the frame of
// face_frame.h), so every later decision is the same.
void build_from_doubles(Face& face, const std::vector<std::array<double, 3>>& x) {
  using detail::cross;
  using detail::dot;
  using detail::Dyadic;
  using detail::Dyadic3;
  using detail::rational_vector;
  const auto difference = [&](std::size_t k) { return detail::difference(x[k], x[0]); };
  // Plane through p, q, r: (a, b, c) = (q - p) x (r - p), d = -(a, b, c).p.
  const Dyadic3 u = difference(1), normal = cross(u, difference(2));
  const Dyadic d = -dot(normal, detail::dyadic(x[0]));
  face.plane = from_exact<Plane3>(
      RationalPlane3(Rational(normal[0]), Rational(normal[1]), Rational(normal[2]), Rational(d)));
  // The frame: origin p, u = q - p, v = n x u.
  const Dyadic3 v = cross(normal, u);
  const Dyadic uu = dot(u, u), vv = dot(v, v);
  const Rational uu_rational(uu), vv_rational(vv);
  face.frame =
      FaceFrame(face.vertices[0], rational_vector(u), rational_vector(v), uu_rational, vv_rational);
  // Frame coordinates s = (x - p).u / uu, t = (x - p).v / vv: numerators in dyadics.
  std::vector<std::array<Dyadic, 2>> numerators;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const std::array<Dyadic, 3> offset = difference(k);
    numerators.push_back({dot(offset, u), dot(offset, v)});
    face.ring.push_back(from_exact<Point2>(RationalPoint2(
        Rational(numerators[k][0]) / uu_rational, Rational(numerators[k][1]) / vv_rational)));
  }
  // The shoelace sum over the numerators, divided once: area = sum / (2 uu vv).
  Dyadic twice = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const auto& a = numerators[k];
    const auto& b = numerators[(k + 1) % x.size()];
    twice = twice + (a[0] * b[1] - b[0] * a[1]);
  }
  face.area = exact_number(Rational(twice) / (2 * uu_rational * vv_rational));
}

}  // namespace

ConvexPolyhedron ConvexPolyhedron::from_faces(std::vector<std::vector<Point3>> face_cycles,
                                              bool flat) {
  ConvexPolyhedron solid;
  solid.flat_ = flat;
  std::vector<Face> faces;
  for (auto& cycle : face_cycles) {
    start_at_smallest(cycle);
    solid.vertices_.insert(solid.vertices_.end(), cycle.begin(), cycle.end());
    // Three consecutive vertices of a strictly convex counter-clockwise cycle give
    // the outward orientation (Nishita eq. 3: F positive outside).
    Face face;
    face.vertices = std::move(cycle);
    if (const auto coordinates = doubles_of(face.vertices)) {
      build_from_doubles(face, *coordinates);
    } else {
      face.plane = Plane3(face.vertices[0], face.vertices[1], face.vertices[2]);
      face.frame = FaceFrame(face.vertices[0], face.vertices[1] - face.vertices[0],
                             face.plane.orthogonal_vector());
      for (const Point3& p : face.vertices) face.ring.push_back(face.frame.to_frame(p));
      Rational twice = 0;
      for (std::size_t k = 0; k < face.ring.size(); ++k) {
        const RationalPoint2& a = exact_value(face.ring[k]);
        const RationalPoint2& b = exact_value(face.ring[(k + 1) % face.ring.size()]);
        twice += a.x() * b.y() - b.x() * a.y();
      }
      face.area = exact_number(twice / 2);
    }
    faces.push_back(std::move(face));
  }
  std::sort(solid.vertices_.begin(), solid.vertices_.end(), point_less);
  solid.vertices_.erase(std::unique(solid.vertices_.begin(), solid.vertices_.end()),
                        solid.vertices_.end());
  std::vector<Vector3> normals;
  for (const Face& face : faces) normals.push_back(face.normal());
  std::vector<std::size_t> order(faces.size());
  for (std::size_t f = 0; f < order.size(); ++f) order[f] = f;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return detail::direction_less(normals[a], normals[b]);
  });
  for (std::size_t f : order) solid.faces_.push_back(std::move(faces[f]));

  std::map<std::pair<int, int>, int> face_of_edge;
  for (std::size_t f = 0; f < solid.faces_.size(); ++f) {
    Face& face = solid.faces_[f];
    for (const Point3& p : face.vertices) {
      const auto it =
          std::lower_bound(solid.vertices_.begin(), solid.vertices_.end(), p, point_less);
      face.vertex_ids.push_back(static_cast<int>(it - solid.vertices_.begin()));
    }
    const std::size_t n = face.vertex_ids.size();
    for (std::size_t k = 0; k < n; ++k)
      face_of_edge[{face.vertex_ids[k], face.vertex_ids[(k + 1) % n]}] = static_cast<int>(f);
  }
  for (Face& face : solid.faces_) {
    const std::size_t n = face.vertex_ids.size();
    for (std::size_t k = 0; k < n; ++k) {
      const auto it = face_of_edge.find({face.vertex_ids[(k + 1) % n], face.vertex_ids[k]});
      face.neighbours.push_back(it == face_of_edge.end() ? -1 : it->second);
    }
  }
  return solid;
}

ConvexPolyhedron ConvexPolyhedron::flat_polygon(const std::vector<Point3>& cycle) {
  // Drop repeated consecutive points (cyclically); keep each point's input index.
  std::vector<Point3> points;
  std::vector<int> input_index;
  for (std::size_t k = 0; k < cycle.size(); ++k) {
    if (!points.empty() && points.back() == cycle[k]) continue;
    points.push_back(cycle[k]);
    input_index.push_back(static_cast<int>(k));
  }
  while (points.size() > 1 && points.front() == points.back()) {
    points.pop_back();
    input_index.pop_back();
  }

  // A plane from the first three non-collinear points.
  std::size_t third = 2;
  while (third < points.size() && CGAL::collinear(points[0], points[1], points[third])) ++third;
  if (points.size() < 3 || third == points.size())
    throw GeometryError("a polygon needs at least 3 points that are not all collinear");
  const Vector3 normal = CGAL::cross_product(points[1] - points[0], points[third] - points[0]);
  for (std::size_t k = 0; k < points.size(); ++k)
    if (!CGAL::coplanar(points[0], points[1], points[third], points[k]))
      throw GeometryError("the polygon is not planar: this point is off the plane of the others",
                          input_index[k]);

  // Usually the cycle is convex as given (the pieces of a model's faces are): decided by
  // predicates alone, without the frame and hull below.
  if (auto front = convex_cycle(points, normal)) {
    std::vector<Point3> back(front->rbegin(), front->rend());
    return from_faces({std::move(*front), std::move(back)}, true);
  }

  const FaceFrame frame(points[0], detail::in_plane_direction(normal), normal);
  std::vector<Point2> flat_points;
  for (const Point3& p : points) flat_points.push_back(frame.to_frame(p));
  const std::vector<int> hull = detail::convex_hull_2(flat_points);

  // Convex position along the cycle: the points are distinct, and each consecutive
  // pair lies on one edge of the hull (so the cycle walks the hull's boundary once).
  auto on_hull_edge = [&](const Point2& p, const Point2& q) {
    for (std::size_t i = 0; i < hull.size(); ++i) {
      const Segment2 edge(flat_points[hull[i]], flat_points[hull[(i + 1) % hull.size()]]);
      if (edge.has_on(p) && edge.has_on(q)) return true;
    }
    return false;
  };
  for (std::size_t k = 0; k < points.size(); ++k) {
    for (std::size_t j = 0; j < k; ++j)
      if (points[j] == points[k])
        throw GeometryError("the polygon is not simple: this point repeats an earlier one",
                            input_index[k]);
    if (!on_hull_edge(flat_points[k], flat_points[(k + 1) % points.size()]))
      throw GeometryError("the polygon is not convex: this point is a reflex or crossing vertex",
                          input_index[(k + 1) % points.size()]);
  }

  std::vector<Point3> front;
  for (int index : hull) front.push_back(points[index]);
  std::vector<Point3> back(front.rbegin(), front.rend());
  return from_faces({std::move(front), std::move(back)}, true);
}

CGAL::Bbox_3 ConvexPolyhedron::bbox() const {
  CGAL::Bbox_3 box;
  for (const Point3& p : vertices_) box += p.bbox();
  return box;
}

CGAL::Bounded_side ConvexPolyhedron::bounded_side(const Point3& p) const {
  if (flat_) {
    const Face& face = faces_.front();
    if (face.plane.oriented_side(p) != CGAL::ON_ORIENTED_BOUNDARY) return CGAL::ON_UNBOUNDED_SIDE;
    const Point2 q = face.frame.to_frame(p);
    const std::size_t n = face.ring.size();
    for (std::size_t k = 0; k < n; ++k)
      if (CGAL::orientation(face.ring[k], face.ring[(k + 1) % n], q) == CGAL::RIGHT_TURN)
        return CGAL::ON_UNBOUNDED_SIDE;
    return CGAL::ON_BOUNDARY;
  }
  bool on_boundary = false;
  for (const Face& face : faces_) {
    const CGAL::Oriented_side side = face.plane.oriented_side(p);
    if (side == CGAL::ON_POSITIVE_SIDE) return CGAL::ON_UNBOUNDED_SIDE;
    if (side == CGAL::ON_ORIENTED_BOUNDARY) on_boundary = true;
  }
  return on_boundary ? CGAL::ON_BOUNDARY : CGAL::ON_BOUNDED_SIDE;
}

}  // namespace penumbra
