#include "penumbra/shadow/linear_volumes.h"

#include "penumbra/geometry/interval.h"

#include <algorithm>
#include <stdexcept>

#include "penumbra/shadow/contour.h"

namespace penumbra {
namespace {

// A point strictly inside the solid (or, for a flat polygon, in its relative
// interior), the mean of its vertices: strictly on the negative side of every bounding
// plane built below.
template <class Point>
Point inner_point(const std::vector<Point>& vertices) {
  typename CGAL::Kernel_traits<Point>::Kernel::Vector_3 sum = CGAL::NULL_VECTOR;
  for (const Point& p : vertices) sum = sum + (p - CGAL::ORIGIN);
  return CGAL::ORIGIN + sum / static_cast<int>(vertices.size());
}

// returns the plane through a, b, c with inside on its negative side.
template <class Point>
auto plane_away_from(const Point& a, const Point& b, const Point& c, const Point& inside) {
  const typename CGAL::Kernel_traits<Point>::Kernel::Plane_3 plane(a, b, c);
  return plane.oriented_side(inside) == CGAL::ON_POSITIVE_SIDE ? plane.opposite() : plane;
}

// adds plane unless planes holds it already; returns its index.
template <class Plane>
std::size_t add_unique(std::vector<Plane>& planes, const Plane& plane) {
  const std::size_t index = std::find(planes.begin(), planes.end(), plane) - planes.begin();
  if (index == planes.size()) planes.push_back(plane);
  return index;
}

// point_shadow_volume's planes, built from the solid's vertices and its faces' planes as
// given (Epeck's, or their exact rational values: the same planes in the same order), into
// planes: string(a, b, inside) adds the plane through q and each contour edge ab.
template <class Point, class Plane, class String>
void shadow_planes(const ConvexPolyhedron& solid, const std::vector<Point>& vertices,
                   const std::vector<Plane>& face_planes, const Point3& q,
                   std::vector<Plane>& planes, String string) {
  const std::vector<int> loop = contour(solid, q);
  if (loop.empty()) return;
  const Point inside = inner_point(vertices);
  for (std::size_t i = 0; i < loop.size(); ++i)
    string(vertices[loop[i]], vertices[loop[(i + 1) % loop.size()]], inside);
  for (std::size_t f = 0; f < solid.faces().size(); ++f)
    if (turned_toward(solid.faces()[f], q)) add_unique(planes, face_planes[f]);
}

// adds the plane through q and the edge ab away from inside, and when q is an open end of the
// source (into: the direction from it into the source) the limit standing for that plane on a
// face in it (PlaneLimit, linear_volumes.h).
void add_string_plane(OpenVolume& volume, const Point3& q, const Point3& a, const Point3& b,
                      const Point3& inside, const Vector3* into) {
  const Plane3 through(q, a, b);
  const bool flip = through.oriented_side(inside) == CGAL::ON_POSITIVE_SIDE;
  const Plane3 plane = flip ? through.opposite() : through;
  const std::size_t index = add_unique(volume.planes, plane);
  if (!into) return;
  const Plane3 limit(a, b, a + *into);  // normal (b - a) x d
  volume.limits.push_back({index, flip ? limit.opposite() : limit});
}

// appends the planes through q and the contour edges from vertex `from` to vertex
// `to`, walking the (clockwise) contour forward.
void add_string_planes(OpenVolume& volume, const ConvexPolyhedron& solid, const Point3& q,
                       const std::vector<int>& contour, int from, int to, const Point3& inside,
                       const Vector3* into) {
  const std::size_t n = contour.size();
  std::size_t i = std::find(contour.begin(), contour.end(), from) - contour.begin();
  while (contour[i] != to) {
    const std::size_t next = (i + 1) % n;
    add_string_plane(volume, q, solid.vertices()[contour[i]], solid.vertices()[contour[next]],
                     inside, into);
    i = next;
  }
}

bool on_contour(const std::vector<int>& contour, int vertex) {
  return std::find(contour.begin(), contour.end(), vertex) != contour.end();
}

}  // namespace

std::optional<std::pair<Exact, Exact>> line_in_solid(const ConvexPolyhedron& solid,
                                                     const Point3& q1, const Point3& q2) {
  if (solid.is_flat()) {
    // A two-sided polygon is not the slab between its two (opposite) planes: the
    // line meets it at its crossing with the plane, if that lies in the polygon.
    const Plane3& plane = solid.faces().front().plane;
    const Exact f1 = plane_value(plane, q1);
    const Exact f2 = plane_value(plane, q2);
    if (f1 == f2) return std::nullopt;  // parallel (a line in the plane casts no contour)
    const Exact t = f1 / (f1 - f2);
    if (solid.bounded_side(q1 + t * (q2 - q1)) == CGAL::ON_UNBOUNDED_SIDE) return std::nullopt;
    return std::make_pair(t, t);
  }
  std::optional<Exact> low, high;
  const Vector3 direction = q2 - q1;
  for (const Face& face : solid.faces()) {
    // F(q1 + t d) = F(q1) + t n.d <= 0.
    const Exact at_q1 = plane_value(face.plane, q1);
    const Exact slope = face.normal() * direction;
    if (CGAL::is_zero(slope)) {
      if (CGAL::is_positive(at_q1)) return std::nullopt;
      continue;
    }
    const Exact t = -at_q1 / slope;
    if (CGAL::is_positive(slope)) {
      if (!high || t < *high) high = t;
    } else {
      if (!low || t > *low) low = t;
    }
  }
  // A closed convex solid is bounded: both ends are set unless the line is parallel
  // to every face, which cannot happen for a solid (a flat polygon gives both signs too).
  if (!low || !high || *low > *high) return std::nullopt;
  return std::make_pair(*low, *high);
}

bool OpenVolume::contains(const Point3& x) const {
  return std::all_of(planes.begin(), planes.end(), [&](const Plane3& plane) {
    return plane.oriented_side(x) == CGAL::ON_NEGATIVE_SIDE;
  });
}

OpenVolume point_shadow_volume(const ConvexPolyhedron& solid, const Point3& q,
                               const Vector3* into) {
  std::vector<Plane3> face_planes;
  for (const Face& face : solid.faces()) face_planes.push_back(face.plane);
  OpenVolume volume;
  shadow_planes(solid, solid.vertices(), face_planes, q, volume.planes,
                [&](const Point3& a, const Point3& b, const Point3& inside) {
                  add_string_plane(volume, q, a, b, inside, into);
                });
  return volume;
}

std::vector<RationalPlane3> exact_point_shadow_planes(
    const ConvexPolyhedron& solid, const std::vector<RationalPoint3>& vertices,
    const std::vector<RationalPlane3>& face_planes, const Point3& q) {
  std::vector<RationalPlane3> planes;
  const RationalPoint3& at = exact_value(q);
  shadow_planes(
      solid, vertices, face_planes, q, planes,
      [&](const RationalPoint3& a, const RationalPoint3& b, const RationalPoint3& inside) {
        add_unique(planes, plane_away_from(at, a, b, inside));
      });
  return planes;
}

std::pair<std::vector<int>, std::vector<int>> tangent_vertices(const ConvexPolyhedron& solid,
                                                               const Point3& q1, const Point3& q2) {
  const std::vector<int> c1 = contour(solid, q1);
  const std::vector<int> c2 = contour(solid, q2);
  std::vector<int> left, right;
  const auto& vertices = solid.vertices();
  for (int v = 0; v < static_cast<int>(vertices.size()); ++v) {
    if (!on_contour(c1, v) || !on_contour(c2, v) || CGAL::collinear(q1, q2, vertices[v])) continue;
    bool non_negative = true, non_positive = true;
    for (const Point3& x : vertices) {
      const CGAL::Orientation side = CGAL::orientation(q1, q2, vertices[v], x);
      non_negative = non_negative && side != CGAL::NEGATIVE;
      non_positive = non_positive && side != CGAL::POSITIVE;
    }
    // App. A2 eqs. (9)-(10): all of V on one side of the plane [Q1, Q2, P]. The
    // scan writes F >= 0 for P_L, with the triangle [Q1, Q2, P] ordered as its
    // clockwise contours are; with our counter-clockwise planes (F positive where
    // Q1, Q2, P turn counter-clockwise) the inequalities flip. The labels are fixed
    // by the paper's strings: the penumbra takes C1 from P_L to P_R, which the hull
    // construction and the exact oracles confirm only with this reading.
    if (non_positive) left.push_back(v);
    if (non_negative) right.push_back(v);
  }
  return {left, right};
}

std::pair<OpenVolume, OpenVolume> case_a_volumes(const ConvexPolyhedron& solid, const Point3& q1,
                                                 const Point3& q2, const std::vector<int>& contour1,
                                                 const std::vector<int>& contour2, int left,
                                                 int right, OpenEnd open) {
  const Point3 inside = inner_point(solid.vertices());
  const auto& vertices = solid.vertices();
  // The directions from an open end into the source, for its string planes' limits.
  const Vector3 into1 = q2 - q1, into2 = q1 - q2;
  const Vector3* open1 = open == OpenEnd::q1 ? &into1 : nullptr;
  const Vector3* open2 = open == OpenEnd::q2 ? &into2 : nullptr;
  OpenVolume penumbra, umbra;
  // App. A2 penumbra (i): Q1 with C1 from P_L to P_R; (ii): Q2 with C2 from P_R to
  // P_L; (iii): the planes [Q2, Q1, P_L] and [Q1, Q2, P_R] tangent to V.
  add_string_planes(penumbra, solid, q1, contour1, left, right, inside, open1);
  add_string_planes(penumbra, solid, q2, contour2, right, left, inside, open2);
  add_unique(penumbra.planes, plane_away_from(q2, q1, vertices[left], inside));
  add_unique(penumbra.planes, plane_away_from(q1, q2, vertices[right], inside));
  // Umbra (i): Q1 with C1 from P_R to P_L; (ii): Q2 with C2 from P_L to P_R.
  add_string_planes(umbra, solid, q1, contour1, right, left, inside, open1);
  add_string_planes(umbra, solid, q2, contour2, left, right, inside, open2);
  // Penumbra (iv): faces visible from the whole source (from both ends, since F is
  // linear along it); umbra (iii): faces visible from either end.
  for (const Face& face : solid.faces()) {
    const bool from_q1 = turned_toward(face, q1), from_q2 = turned_toward(face, q2);
    if (from_q1 && from_q2) add_unique(penumbra.planes, face.plane);
    if (from_q1 || from_q2) add_unique(umbra.planes, face.plane);
  }
  return {penumbra, umbra};
}

std::optional<LinearVolumes> linear_volumes(const ConvexPolyhedron& solid, const Point3& q1,
                                            const Point3& q2, OpenEnd open) {
  LinearVolumes volumes;
  volumes.contour1 = contour(solid, q1);
  volumes.contour2 = contour(solid, q2);
  if (volumes.contour1.empty() && volumes.contour2.empty()) return std::nullopt;
  const Vector3 into1 = q2 - q1, into2 = q1 - q2;
  volumes.shadow1 = point_shadow_volume(solid, q1, open == OpenEnd::q1 ? &into1 : nullptr);
  volumes.shadow2 = point_shadow_volume(solid, q2, open == OpenEnd::q2 ? &into2 : nullptr);

  if (const auto inside = line_in_solid(solid, q1, q2)) {
    // Case B: the line meets V beyond one end point, whose shadow volume encloses
    // the other's (App. A2 (2): "Q2 within the pyramid formed by Q1 and C1").
    volumes.kind = LinearCase::B;
    volumes.nearer_is_q1 = CGAL::is_negative(inside->second);
    volumes.penumbra = volumes.nearer_is_q1 ? volumes.shadow1 : volumes.shadow2;
    volumes.umbra = volumes.nearer_is_q1 ? volumes.shadow2 : volumes.shadow1;
    return volumes;
  }
  volumes.kind = LinearCase::A;
  const auto [left, right] = tangent_vertices(solid, q1, q2);
  // No vertex on both contours: an end of the source lies in the plane of a flat occluder
  // (a polygon, a piece of a model's face), which that end sees edge-on. Not supported.
  if (left.empty() || right.empty())
    throw std::domain_error("an end of the linear source lies in the plane of a flat occluder");
  volumes.left = left.front();
  volumes.right = right.front();
  std::tie(volumes.penumbra, volumes.umbra) = case_a_volumes(
      solid, q1, q2, volumes.contour1, volumes.contour2, volumes.left, volumes.right, open);
  return volumes;
}

std::vector<Plane3> penumbra_planes_by_hull(const ConvexPolyhedron& solid, const Point3& q1,
                                            const Point3& q2) {
  // conv(U1 ∪ U2) is swept by the rays from Q1 and Q2 through V; its facets that
  // touch V are the same in any truncation beyond V (here: 4 times as far).
  std::vector<Point3> points = solid.vertices();
  for (const Point3& v : solid.vertices())
    for (const Point3* q : {&q1, &q2}) points.push_back(*q + 4 * (v - *q));
  const ConvexPolyhedron hull = ConvexPolyhedron::hull(points);
  std::vector<Plane3> planes;
  for (const Face& face : hull.faces()) {
    const bool touches =
        std::any_of(face.vertices.begin(), face.vertices.end(), [&](const Point3& p) {
          return std::binary_search(solid.vertices().begin(), solid.vertices().end(), p,
                                    [](const Point3& a, const Point3& b) {
                                      return CGAL::compare_xyz(a, b) == CGAL::SMALLER;
                                    });
        });
    if (touches) planes.push_back(face.plane);
  }
  return planes;
}

}  // namespace penumbra
