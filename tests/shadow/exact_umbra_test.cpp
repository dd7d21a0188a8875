// The exact umbra of a linear source with joint occlusion (issue #17): membership against
// a per-point oracle written here from the illuminance layer's exact blocked intervals
// (a different construction: shadow volumes from the point, not the triangle clipping of
// the shadow layer), a hand-derived conic, and areas against the straight single-occluder
// umbra and against sampling.

#include <boost/test/unit_test.hpp>

#include <unsupported/Eigen/Polynomials>

#include <algorithm>
#include <fstream>
#include <random>
#include <sstream>

#include <nlohmann/json.hpp>

#include "penumbra/illuminance/occlusion.h"
#include "penumbra/illuminance/scene_illuminance.h"
#include "penumbra/scene/load_scene.h"
#include "penumbra/shadow/exact_umbra.h"
#include "penumbra/shadow/linear_face_shadow.h"
#include "penumbra/shadow/shadow_map.h"
#include "solids.h"
#include "support/fixtures.h"
#include "support/heavy.h"

using namespace penumbra;

namespace {

using test::box;
using test::face_with_plane;

// The oracle: x is in the umbra when the visible part of the source (the part strictly
// outside the face's plane) minus the union of every solid's hidden open interval leaves
// nothing of positive length.
bool oracle_covered(const Face& face, const Point3& q1, const Point3& q2,
                    const std::vector<ConvexPolyhedron>& solids, const Point3& x) {
  const auto within = illuminance::outer_side_interval_exact(x, face.normal(), q1, q2);
  if (!within) return true;
  std::vector<illuminance::ExactInterval> hidden;
  for (const ConvexPolyhedron& solid : solids)
    if (const auto h = illuminance::hidden_interval(illuminance::hidden_region(solid, x), q1, q2))
      hidden.push_back(*h);
  return illuminance::visible_intervals(*within, hidden).empty();
}

// returns the exact umbra of the solids, and checks that its area and the penumbra's add up
// to the straight shadow's exact area (the sweep's quadrature against the polygon sets).
// returns the signed area of a ring's polyline (frame units) and adds its world length.
double polyline_area(const CurvedRing& ring, double& length) {
  double sum = 0;
  for (std::size_t i = 0, n = ring.points.size(); i < n; ++i) {
    const auto& a = ring.points[i];
    const auto& b = ring.points[(i + 1) % n];
    sum += a[0] * b[1] - a[1] * b[0];
    length += std::hypot(b[0] - a[0], b[1] - a[1]) * 144;  // bounded by the largest axis
  }
  return sum / 2;
}

// x is in the shadow when some solid hides part of the visible source (an open interval).
bool oracle_shadowed(const Face& face, const Point3& q1, const Point3& q2,
                     const std::vector<ConvexPolyhedron>& solids, const Point3& x) {
  const auto within = illuminance::outer_side_interval_exact(x, face.normal(), q1, q2);
  if (!within) return true;
  return std::any_of(solids.begin(), solids.end(), [&](const ConvexPolyhedron& solid) {
    const auto h = illuminance::hidden_interval(illuminance::hidden_region(solid, x), q1, q2);
    return h && h->high > within->low && h->low < within->high;
  });
}

// the face's single-occluder shadows under the tube, and its occluders for exact_umbra.
std::pair<FaceShadow, std::vector<UmbraOccluder>> single_shadows(
    const Face& face, const Point3& q1, const Point3& q2,
    const std::vector<ConvexPolyhedron>& solids) {
  std::vector<Occluder> occluders;
  for (std::size_t k = 0; k < solids.size(); ++k) occluders.push_back({k, &solids[k]});
  FaceShadow shadow = linear_face_shadow(face, q1, q2, occluders);
  std::vector<UmbraOccluder> umbra_occluders;
  for (const OccluderShadow& o : shadow.occluders)
    umbra_occluders.push_back({&solids[o.occluder], o.polygon, o.umbra});
  return {std::move(shadow), std::move(umbra_occluders)};
}

ExactUmbra umbra_of(const Face& face, const Point3& q1, const Point3& q2,
                    const std::vector<ConvexPolyhedron>& solids) {
  const auto [shadow, umbra_occluders] = single_shadows(face, q1, q2, solids);
  ExactUmbra umbra = exact_umbra(face, q1, q2, umbra_occluders);
  const double shadow_area = CGAL::to_double(shadow.shadow.area);
  BOOST_TEST(std::abs(umbra.area() + umbra.penumbra_area() - shadow_area) <=
             1e-12 * CGAL::to_double(face.area));
  BOOST_TEST(umbra.area() >= CGAL::to_double(shadow.umbra.area) * (1 - 1e-12));
  // The chained rings enclose the integrated areas, to the densification's error (chords
  // within 1e-6 m of the arcs: at most 1e-6 m times the rings' length).
  for (const auto* polygons : {&umbra.umbra_polygons(), &umbra.penumbra_polygons()}) {
    double ring_area = 0, length = 0;
    for (const CurvedPolygon& polygon : *polygons) {
      ring_area += polyline_area(polygon.outer, length);
      for (const CurvedRing& hole : polygon.holes) ring_area += polyline_area(hole, length);
    }
    const double expected =
        polygons == &umbra.umbra_polygons() ? umbra.area() : umbra.penumbra_area();
    const double scale =
        std::sqrt(CGAL::to_double(face.frame.squared_u() * face.frame.squared_v()));
    BOOST_TEST(std::abs(ring_area - expected) * scale <= 1e-6 * length + 1e-12,
               "rings " << ring_area << " against " << expected);
  }
  return umbra;
}

// The exact box of points (a Bbox_2 of lazy points depends on which were evaluated before),
// and its point at the fractions i / n and j / n of its sides.
struct ExactBox {
  explicit ExactBox(const std::vector<Point2>& points)
      : low_s(points[0].x()), high_s(low_s), low_t(points[0].y()), high_t(low_t) {
    for (const Point2& p : points) {
      low_s = std::min(low_s, p.x()), high_s = std::max(high_s, p.x());
      low_t = std::min(low_t, p.y()), high_t = std::max(high_t, p.y());
    }
  }
  Point2 at(int i, int j, int n) const {
    return Point2(low_s + (high_s - low_s) * Exact(i) / n, low_t + (high_t - low_t) * Exact(j) / n);
  }
  Exact low_s, high_s, low_t, high_t;
};

// compares contains() with the oracle at random rational points of the face's frame box;
// returns the number of points in the umbra.
int compare_with_oracle(const Face& face, const Point3& q1, const Point3& q2,
                        const std::vector<ConvexPolyhedron>& solids, const ExactUmbra& umbra,
                        int samples, unsigned seed, int* mismatches = nullptr) {
  std::mt19937 random(seed);
  const ExactBox box(face.ring);
  std::uniform_int_distribution<int> step(1, 4095);
  int inside = 0, wrong = 0;
  for (int k = 0; k < samples; ++k) {
    const Point2 p = box.at(step(random), step(random), 4096);
    if (CGAL::Polygon_2<Kernel>(face.ring.begin(), face.ring.end()).bounded_side(p) !=
        CGAL::ON_BOUNDED_SIDE)
      continue;
    const bool expected = oracle_covered(face, q1, q2, solids, face.frame.to_world(p));
    const bool got = umbra.contains(p);
    const bool shadowed = oracle_shadowed(face, q1, q2, solids, face.frame.to_world(p));
    BOOST_TEST((got || umbra.in_penumbra(p)) == shadowed, "shadow membership at " << p);
    if (got != expected) ++wrong;
    BOOST_TEST(got == expected, "umbra membership at " << p << ": oracle " << expected);
    inside += expected;
  }
  if (mismatches) *mismatches += wrong;
  return inside;
}

// For the middle of every curved boundary piece: brackets the exact crossing of its conic
// along the piece's normal by bisection on the conic's exact sign (root isolation to 2^-40
// of 1e-5), and checks that the points just either side, on opposite sides of the conic,
// are classified as the oracle says, one in the umbra and one out. Returns the pieces seen.
int check_across_arcs(const Face& face, const Point3& q1, const Point3& q2,
                      const std::vector<ConvexPolyhedron>& solids, const ExactUmbra& umbra) {
  int checked = 0;
  for (const UmbraArc& arc : umbra.boundary()) {
    if (arc.straight || arc.points.size() < 3) continue;
    const auto& c = arc.curve;
    const auto conic = [&](const Point2& p) {
      return c[0] * p.x() * p.x() + c[1] * p.x() * p.y() + c[2] * p.y() * p.y() + c[3] * p.x() +
             c[4] * p.y() + c[5];
    };
    const std::size_t m = arc.points.size() / 2;
    const auto& a = arc.points[m - 1];
    const auto& b = arc.points[m + 1];
    const double tx = b[0] - a[0], ty = b[1] - a[1], length = std::hypot(tx, ty);
    const Point2 middle(arc.points[m][0], arc.points[m][1]);
    const Vector2 normal(-ty / length * 1e-5, tx / length * 1e-5);  // to the left: the umbra
    Point2 low = middle - normal, high = middle + normal;
    const CGAL::Sign low_sign = CGAL::sign(conic(low));
    if (low_sign == CGAL::ZERO || low_sign == CGAL::sign(conic(high))) continue;
    for (int step = 0; step < 40; ++step) {
      const Point2 mid = CGAL::midpoint(low, high);
      const CGAL::Sign sign = CGAL::sign(conic(mid));
      if (sign == CGAL::ZERO) break;
      (sign == low_sign ? low : high) = mid;
    }
    const bool out = oracle_covered(face, q1, q2, solids, face.frame.to_world(low));
    const bool in = oracle_covered(face, q1, q2, solids, face.frame.to_world(high));
    BOOST_TEST(umbra.contains(low) == out, "right of the arc at " << low);
    BOOST_TEST(umbra.contains(high) == in, "left of the arc at " << high);
    BOOST_TEST(in);
    BOOST_TEST(!out);
    ++checked;
  }
  return checked;
}

// The floor: the top face of a slab, 12 m square.
const ConvexPolyhedron& floor_slab() {
  static const ConvexPolyhedron slab = box(-6, -6, -1, 6, 6, 0);
  return slab;
}

const Face& floor_face() {
  return face_with_plane(floor_slab(), Plane3(0, 0, 1, 0));
}

ConvexPolyhedron board(std::vector<Point3> corners) {
  return ConvexPolyhedron::flat_polygon(corners);
}

// A random scene: two to six solids, hulls of six random points of a 2 x 2 x 1 cell on a
// quarter-metre grid (edges in every direction, close enough together to hide a tube
// jointly), and a tube above them.
struct RandomScene {
  std::vector<ConvexPolyhedron> solids;
  Point3 q1, q2;
};

RandomScene random_scene(std::mt19937& random) {
  std::uniform_int_distribution<int> corner(-3, 2), count(2, 6), quarter(0, 8), end(-12, 12);
  RandomScene scene;
  const int n = count(random);
  for (int k = 0; k < n; ++k) {
    const int x = corner(random), y = corner(random);
    std::vector<Point3> points;
    for (int p = 0; p < 6; ++p)
      points.emplace_back(x + quarter(random) / 4.0, y + quarter(random) / 4.0,
                          2 + quarter(random) / 8.0);
    try {
      scene.solids.push_back(ConvexPolyhedron::hull(points));
    } catch (const std::exception&) {  // coplanar draws: none with the seeds used
    }
  }
  scene.q1 = Point3(end(random) / 4.0, end(random) / 4.0, 4.5);
  scene.q2 = Point3(end(random) / 4.0, end(random) / 4.0, 5);
  return scene;
}

// calls visit(k, scene) for count random scenes drawn from seed (fixed: failures must
// reproduce).
template <class Visit>
void for_random_scenes(unsigned seed, int count, Visit visit) {
  std::mt19937 random(seed);
  for (int scene = 0; scene < count; ++scene) visit(scene, random_scene(random));
}

// The value of an exact coordinate in doubles, found apart from the library: the root-th
// real root of its polynomial by Eigen's companion-matrix eigenvalues.
double value_of(const AlgebraicCoordinate& x) {
  if (x.value) return CGAL::to_double(*x.value);
  double largest = 0;
  for (const Exact& c : x.polynomial) largest = std::max(largest, std::abs(CGAL::to_double(c)));
  Eigen::VectorXd coefficients(x.polynomial.size());
  for (std::size_t k = 0; k < x.polynomial.size(); ++k)
    coefficients[k] = CGAL::to_double(x.polynomial[k]) / largest;
  const Eigen::PolynomialSolver<double, Eigen::Dynamic> solver(coefficients);
  std::vector<double> roots;
  solver.realRoots(roots, 1e-9);
  std::sort(roots.begin(), roots.end());
  BOOST_TEST_REQUIRE(x.root < int(roots.size()));
  return roots[x.root];
}

// a s^2 + b s t + c t^2 + d s + e t + f and the sum of its terms' magnitudes.
std::pair<double, double> conic_at(const std::array<Exact, 6>& curve, double s, double t) {
  const double terms[6] = {s * s, s * t, t * t, s, t, 1};
  double value = 0, size = 0;
  for (int k = 0; k < 6; ++k) {
    value += CGAL::to_double(curve[k]) * terms[k];
    size += std::abs(CGAL::to_double(curve[k]) * terms[k]);
  }
  return {value, size};
}

// the exact polygons written out with every rational, to compare two computations.
std::string written(const std::vector<ExactCurvedPolygon>& polygons) {
  std::ostringstream out;
  const auto coordinate = [&](const AlgebraicCoordinate& x) {
    if (x.value) out << CGAL::exact(*x.value) << " ";
    for (const Exact& c : x.polynomial) out << CGAL::exact(c) << ",";
    out << "#" << x.root << " ";
  };
  const auto ring = [&](const std::vector<ExactEdge>& edges) {
    for (const ExactEdge& edge : edges) {
      coordinate(edge.from.s);
      coordinate(edge.from.t);
      for (const Exact& c : edge.curve) out << CGAL::exact(c) << " ";
      out << edge.joint << "; ";
    }
    out << "| ";
  };
  for (const ExactCurvedPolygon& polygon : polygons) {
    ring(polygon.outer);
    for (const auto& hole : polygon.holes) ring(hole);
    out << "\n";
  }
  return out.str();
}

// A fixture scene's shadows with and without joint umbrae.
struct BothWays {
  explicit BothWays(const std::string& name)
      : scene(load_scene(std::string(PENUMBRA_SOURCE_DIR) + "/fixtures/scenes/" + name + ".json")),
        with(compute_shadows(scene, joint())),
        without(compute_shadows(scene)) {}
  static ShadowOptions joint() {
    ShadowOptions options;
    options.joint_umbrae = true;
    return options;
  }
  Scene scene;
  ShadowResult with, without;
};

// Membership at random rational points (seed) of the faces of a joint-umbra run against the
// oracles over every solid of the scene: the curved sets where a face has them, else (unless
// only_curved) the straight ones, which are exact where the umbra has no joint part. Points on
// a straight set's boundary or on a hole's ring are left out; points in a mesh face's holes
// belong to no set. The points lie on a grid of 1,023ths of the face's exact box: the scenes'
// coordinates are quarters, and on their lines the pointwise oracle and the regularised sets
// may differ (a sight line through the common edge of two flat pieces is blocked by neither).
struct OracleTally {
  int mesh_faces = 0, checked = 0, in_holes = 0, umbra = 0, mismatches = 0;
};

OracleTally against_the_oracles(const BothWays& computed, bool only_curved, unsigned seed) {
  const Scene& scene = computed.scene;
  const ShadowResult& with = computed.with;
  const auto& tube = std::get<LinearLight>(scene.lights[0].source);
  const Point3 q1 = to_exact(tube.start), q2 = to_exact(tube.end);
  std::vector<ConvexPolyhedron> solids;
  for (const Object& object : scene.objects) solids.push_back(object.solid);
  std::mt19937 random(seed);  // fixed: failures must reproduce
  std::uniform_int_distribution<int> step(1, 1022);
  OracleTally tally;
  using Polygon = CGAL::Polygon_2<Kernel>;
  for (std::size_t r = 0; r < with.receivers.size(); ++r) {
    const FaceShadow& shadow = with.lights[0].faces[r];
    if (only_curved && !shadow.curved) continue;
    if (shadow.faces_away || shadow.beyond_range) continue;
    // the face: plane, frame, outer ring and holes in its frame
    Face face;
    std::vector<Polygon> holes;
    const std::size_t m = with.mesh_faces.empty() ? kNoMeshFace : with.mesh_faces[r];
    if (m != kNoMeshFace && scene.mesh_faces[m].pieces.size() > 1) {
      const MeshFace& mesh = scene.mesh_faces[m];
      face.plane = mesh.plane;
      face.frame = mesh.frame;
      face.ring = mesh.ring;
      for (const auto& hole : mesh.holes) {
        Polygon ring;
        for (const Point3& p : hole) ring.push_back(mesh.frame.to_frame(p));
        holes.push_back(ring);
      }
      tally.mesh_faces += shadow.curved != nullptr;
    } else {
      face = scene.objects[with.receivers[r].object].solid.faces()[with.receivers[r].face];
    }
    // membership: the curved sets, or the straight ones (nullopt on their boundaries)
    const auto in = [&](const Point2& p, bool umbra) -> std::optional<bool> {
      if (shadow.curved) return umbra ? shadow.curved->contains(p) : shadow.curved->in_penumbra(p);
      const auto side = test::side_of(umbra ? shadow.umbra : shadow.penumbra, p);
      if (side == CGAL::ON_BOUNDARY) return std::nullopt;
      return side == CGAL::ON_BOUNDED_SIDE;
    };
    const Polygon outer(face.ring.begin(), face.ring.end());
    const ExactBox box(face.ring);
    for (int k = 0; k < 300; ++k) {
      const Point2 p = box.at(step(random), step(random), 1023);
      if (outer.bounded_side(p) != CGAL::ON_BOUNDED_SIDE) continue;
      bool in_hole = false, on_edge = false;
      for (const Polygon& hole : holes) {
        const auto side = hole.bounded_side(p);
        in_hole = in_hole || side == CGAL::ON_BOUNDED_SIDE;
        on_edge = on_edge || side == CGAL::ON_BOUNDARY;
      }
      if (on_edge) continue;
      if (in_hole) {
        ++tally.in_holes;
        BOOST_TEST(!in(p, true).value_or(false));
        BOOST_TEST(!in(p, false).value_or(false));
        continue;
      }
      const std::optional<bool> umbra = in(p, true), penumbra = in(p, false);
      if (!umbra || !penumbra) continue;
      const Point3 x = face.frame.to_world(p);
      const bool expected = oracle_covered(face, q1, q2, solids, x);
      tally.mismatches += *umbra != expected;
      tally.umbra += expected;
      BOOST_TEST(*umbra == expected, "umbra at " << x);
      BOOST_TEST((*umbra || *penumbra) == oracle_shadowed(face, q1, q2, solids, x),
                 "shadow at " << x);
      ++tally.checked;
    }
  }
  BOOST_TEST_MESSAGE(tally.mesh_faces << " mesh faces with joint parts, " << tally.checked
                                      << " points checked, " << tally.in_holes << " in holes, "
                                      << tally.umbra << " in the umbra");
  return tally;
}
}  // namespace

BOOST_AUTO_TEST_SUITE(exact_umbra)

// A tube along x at height 4 above y = 0; a vertical board in the plane y = -1 for x <= 1/5
// and a horizontal board at z = 2 for x >= -1/5. From P = (x, y, 0) with y < -1 the sight
// line to L(t) = (2t - 1, 0, 4) crosses y = -1 at the fraction mu = (1 + y) / y of the way
// and z = 2 halfway, so the vertical board hides t <= t_A = ((1/5 - x) / mu + x + 1) / 2 and
// the horizontal one t >= t_B = ((-1/5 - x) * 2 + x + 1) / 2. The gap closes where t_A = t_B:
// (1/5 - x)(-y) / (-1 - y) = 2 (-1/5 - x), i.e. 10 x y + 20 x + 6 y + 4 = 0, a hyperbola,
// reached inside the tube for t in (0, 1/5) and (3/5, 1): with tau = t_A = t_B,
// x = 3/5 - 2 tau, mu = (tau - 1/5) / (2 tau - 4/5), y = 1 / (mu - 1).
BOOST_AUTO_TEST_CASE(two_boards_close_the_gap_along_the_derived_hyperbola) {
  const Point3 q1(-1, 0, 4), q2(1, 0, 4);
  const std::vector<ConvexPolyhedron> solids{
      board({Point3(-3, -1, Exact(1) / 4), Point3(Exact(1) / 5, -1, Exact(1) / 4),
             Point3(Exact(1) / 5, -1, Exact(15) / 4), Point3(-3, -1, Exact(15) / 4)}),
      board({Point3(-Exact(1) / 5, -5, 2), Point3(3, -5, 2), Point3(3, 3, 2),
             Point3(-Exact(1) / 5, 3, 2)})};
  const Face& face = floor_face();
  const ExactUmbra umbra = umbra_of(face, q1, q2, solids);
  BOOST_TEST(umbra.joint());

  // Points of the derived curve on both branches, exact.
  std::vector<Point2> on_curve;
  for (const Exact& tau :
       {Exact(1) / 20, Exact(1) / 10, Exact(3) / 20, Exact(7) / 10, Exact(4) / 5, Exact(9) / 10}) {
    const Exact mu = (tau - Exact(1) / 5) / (2 * tau - Exact(4) / 5);
    const Exact x = Exact(3) / 5 - 2 * tau, y = 1 / (mu - 1);
    BOOST_TEST(CGAL::is_zero(10 * x * y + 20 * x + 6 * y + 4));  // the derivation agrees
    on_curve.push_back(face.frame.to_frame(Point3(x, y, 0)));
  }
  // A joint arc of the boundary lies on that conic: it vanishes at every derived point
  // (five points fix a conic).
  int found = 0;
  for (const UmbraArc& arc : umbra.boundary()) {
    if (!arc.joint || arc.straight) continue;
    const auto& c = arc.curve;
    bool all = true;
    for (const Point2& p : on_curve)
      all = all && CGAL::is_zero(c[0] * p.x() * p.x() + c[1] * p.x() * p.y() +
                                 c[2] * p.y() * p.y() + c[3] * p.x() + c[4] * p.y() + c[5]);
    found += all;
  }
  BOOST_TEST(found >= 1);
  BOOST_TEST(check_across_arcs(face, q1, q2, solids, umbra) >= 1);
  // Off the curve on either side of the upper branch at tau = 4/5 (x = -1, mu = 3/4, y = -4):
  // nearer the tube (y = -39/10, mu = 29/39) t_A = 117/145 > 4/5 = t_B, the gap
  // is closed; farther (y = -41/10, mu = 31/41) t_A = 123/155 < 4/5, it is open.
  BOOST_TEST(umbra.contains(face.frame.to_frame(Point3(-1, Exact(-39) / 10, 0))));
  BOOST_TEST(!umbra.contains(face.frame.to_frame(Point3(-1, Exact(-41) / 10, 0))));
  compare_with_oracle(face, q1, q2, solids, umbra, 600, 17);
}

// Eight random scenes drawn from seed, each with what add puts in: membership at 200 random
// points (the oracle's seeds from first_point) and across every arc against the oracle, with
// joint parts in at least three scenes and at least three arcs crossed.
template <class Add>
void random_scenes_agree_with_the_oracle(unsigned seed, unsigned first_point, Add add) {
  const Face& face = floor_face();
  int mismatches = 0, joint = 0, arcs = 0;
  for_random_scenes(seed, 8, [&](int scene, RandomScene drawn) {
    auto& [solids, q1, q2] = drawn;
    add(drawn);
    const ExactUmbra umbra = umbra_of(face, q1, q2, solids);
    joint += umbra.joint();
    compare_with_oracle(face, q1, q2, solids, umbra, 200, first_point + scene, &mismatches);
    arcs += check_across_arcs(face, q1, q2, solids, umbra);
  });
  BOOST_TEST(mismatches == 0);
  BOOST_TEST(joint >= 3);
  BOOST_TEST(arcs >= 3);
  BOOST_TEST_MESSAGE(joint << " scenes with joint umbrae, " << arcs << " curved pieces crossed");
}

BOOST_AUTO_TEST_CASE(random_scenes_of_two_to_six_solids_agree_with_the_oracle) {
  random_scenes_agree_with_the_oracle(23, 100, [](RandomScene&) {});
}

// The sweep leaves out a whole shadow's edge where it lies strictly inside another whole
// shadow and outside W, and every line strictly inside a single umbra (Sweep::relevant): a
// veil, a small cube just under one end of the tube, casts a whole shadow over the floor under
// the random scenes (so every other shadow's edges lie inside it), and a plate low over the
// floor casts a single umbra across part of them. Membership and the arcs against the oracle
// as above, with joint parts inside the veil's shadow.
BOOST_AUTO_TEST_CASE(shadow_edges_inside_other_shadows_are_left_out_only_outside_w) {
  random_scenes_agree_with_the_oracle(29, 300, [](RandomScene& drawn) {
    const double x = CGAL::to_double(drawn.q1.x()), y = CGAL::to_double(drawn.q1.y());
    drawn.solids.push_back(box(x - 0.125, y - 0.125, 4.25, x + 0.125, y + 0.125, 4.375));
    drawn.solids.push_back(box(-1, -3, 0.25, 0.5, -1.5, 0.3125));
  });
}

// joint_umbra (what `shadows --joint-umbrae` asks) leaves the sweep out only where it would
// find no joint part: over random scenes (fixed seed), nullopt comes only where exact_umbra
// finds none, and otherwise it is exact_umbra's set (the same areas and pieces of boundary).
// One occluder alone, or each of the random scenes' solids alone, never hides the tube jointly.
BOOST_AUTO_TEST_CASE(joint_umbra_leaves_out_only_faces_without_joint_parts) {
  const Face& face = floor_face();
  int left_out = 0, joint = 0, wrongly = 0;
  for_random_scenes(31, penumbra::test::samples(40), [&](int scene, const RandomScene& drawn) {
    const auto& [solids, q1, q2] = drawn;
    const auto occluders = single_shadows(face, q1, q2, solids).second;
    const ExactUmbra swept = penumbra::exact_umbra(face, q1, q2, occluders);
    const std::optional<ExactUmbra> asked = joint_umbra(face, q1, q2, occluders);
    joint += swept.joint();
    if (!asked) {
      ++left_out;
      wrongly += swept.joint();
    } else {
      BOOST_TEST(asked->joint() == swept.joint());
      BOOST_TEST(asked->area() == swept.area());
      BOOST_TEST(asked->penumbra_area() == swept.penumbra_area());
      BOOST_TEST(asked->boundary().size() == swept.boundary().size());
    }
    for (const UmbraOccluder& alone : occluders)
      BOOST_TEST(!joint_umbra(face, q1, q2, {alone}), "scene " << scene);
  });
  BOOST_TEST(wrongly == 0);
  BOOST_TEST(joint >= penumbra::test::samples(5));
  BOOST_TEST(left_out >= penumbra::test::samples(5));
  BOOST_TEST_MESSAGE(joint << " of " << penumbra::test::samples(40) << " scenes with joint umbrae, "
                           << left_out << " left out");
}

// The exact form of the curved regions (shadows --exact, check): every corner, computed
// again in doubles from its description alone (Eigen's roots of its polynomials), lies on
// both curves that meet there and on the densified rings; rational corners lie on both
// exactly; edges alternate curves; and the form does not depend on the order of the
// occluders (the same text with the solids reversed).
BOOST_AUTO_TEST_CASE(exact_rings_name_each_corner_on_its_two_curves_in_any_order) {
  std::mt19937 random(29);  // fixed: failures must reproduce
  const Face& face = floor_face();
  int corners = 0, algebraic = 0, scenes = 0;
  for (int scene = 0; scene < 6; ++scene) {
    auto [solids, q1, q2] = random_scene(random);
    const ExactUmbra umbra = umbra_of(face, q1, q2, solids);
    if (!umbra.joint()) continue;
    ++scenes;
    std::vector<std::array<double, 2>> points;  // every point of the densified rings
    for (const auto* polygons : {&umbra.umbra_polygons(), &umbra.penumbra_polygons()})
      for (const CurvedPolygon& polygon : *polygons) {
        points.insert(points.end(), polygon.outer.points.begin(), polygon.outer.points.end());
        for (const CurvedRing& hole : polygon.holes)
          points.insert(points.end(), hole.points.begin(), hole.points.end());
      }
    const auto exact_umbra = umbra.exact_umbra_polygons();
    const auto exact_penumbra = umbra.exact_penumbra_polygons();
    BOOST_TEST(exact_umbra.size() == umbra.umbra_polygons().size());
    for (const auto* polygons : {&exact_umbra, &exact_penumbra})
      for (const ExactCurvedPolygon& polygon : *polygons) {
        std::vector<const std::vector<ExactEdge>*> rings{&polygon.outer};
        for (const auto& hole : polygon.holes) rings.push_back(&hole);
        for (const auto* ring : rings) {
          BOOST_TEST_REQUIRE(ring->size() >= 2u);
          for (std::size_t k = 0; k < ring->size(); ++k) {
            const ExactEdge& edge = (*ring)[k];
            const ExactEdge& before = (*ring)[(k + ring->size() - 1) % ring->size()];
            BOOST_TEST((edge.curve != before.curve));
            ++corners;
            if (edge.from.s.value && edge.from.t.value) {
              const Exact s = *edge.from.s.value, t = *edge.from.t.value;
              for (const auto* curve : {&edge.curve, &before.curve}) {
                const auto& c = *curve;
                BOOST_TEST(CGAL::is_zero(c[0] * s * s + c[1] * s * t + c[2] * t * t + c[3] * s +
                                         c[4] * t + c[5]));
              }
            } else {
              ++algebraic;
            }
            const double s = value_of(edge.from.s), t = value_of(edge.from.t);
            for (const auto* curve : {&edge.curve, &before.curve}) {
              const auto [value, size] = conic_at(*curve, s, t);
              BOOST_TEST(std::abs(value) <= 1e-9 * size, "corner " << s << " " << t);
            }
            double nearest = 1e300;
            for (const auto& p : points)
              nearest = std::min(nearest, std::hypot(p[0] - s, p[1] - t));
            BOOST_TEST(nearest <= 1e-9, "corner " << s << " " << t);
          }
        }
      }
    std::reverse(solids.begin(), solids.end());
    const ExactUmbra reversed = umbra_of(face, q1, q2, solids);
    BOOST_TEST(written(reversed.exact_umbra_polygons()) == written(exact_umbra));
    BOOST_TEST(written(reversed.exact_penumbra_polygons()) == written(exact_penumbra));
  }
  BOOST_TEST(scenes >= 3);
  BOOST_TEST(algebraic >= 10);
  BOOST_TEST_MESSAGE(scenes << " scenes with joint umbrae, " << corners << " corners, " << algebraic
                            << " irrational");
}

// Occluders whose whole shadows do not overlap hide nothing together: the umbra is the
// union of the single umbrae, and so is its area (to the quadrature's error).
BOOST_AUTO_TEST_CASE(apart_occluders_give_the_straight_umbra) {
  const Point3 q1(-1, 0.25, 5), q2(2, 0.5, 5.5);
  const std::vector<ConvexPolyhedron> solids{box(-5, -5, 2, -4, -4, 3), box(3, 3, 2, 4, 4, 3)};
  const Face& face = floor_face();
  std::vector<Occluder> occluders{{0, &solids[0]}, {1, &solids[1]}};
  const FaceShadow shadow = linear_face_shadow(face, q1, q2, occluders);
  BOOST_TEST(!shadow.joint_occlusion);
  const ExactUmbra umbra = umbra_of(face, q1, q2, solids);
  BOOST_TEST(!umbra.joint());
  BOOST_TEST(std::all_of(umbra.boundary().begin(), umbra.boundary().end(),
                         [](const UmbraArc& arc) { return arc.straight && !arc.joint; }));
  const double expected = CGAL::to_double(shadow.umbra.area);
  BOOST_TEST(std::abs(umbra.area() - expected) <= 1e-12 * expected);
  compare_with_oracle(face, q1, q2, solids, umbra, 200, 3);
}

// Occluders in groups whose shadows are strictly apart are swept group by group (exact_umbra.h):
// two pairs of boards at opposite corners of the floor, each pair closing its gap under a
// tube parallel to the floor, so each group has a joint part of its own. Membership agrees
// with the oracle across the floor and across every arc, and the sets are the disjoint unions
// of the groups' own sets (the exact polygons, in canonical order, and the areas).
BOOST_AUTO_TEST_CASE(groups_whose_shadows_are_apart_are_swept_apart) {
  const Face& face = floor_face();
  const Point3 q1(-1, 0, 4), q2(1, 0, 4);
  const std::vector<ConvexPolyhedron> near{box(-5, -5, 1.5, -4.1, -2, 2),
                                           box(-4, -5, 1.5, -3, -2, 2)};
  const std::vector<ConvexPolyhedron> far{box(3, 2, 1.5, 4, 5, 2), box(4.1, 2, 1.5, 5, 5, 2)};
  std::vector<ConvexPolyhedron> solids = near;
  solids.insert(solids.end(), far.begin(), far.end());
  // The groups' shadows are apart: the straight shadow has one polygon per group.
  std::vector<Occluder> occluders;
  for (std::size_t k = 0; k < solids.size(); ++k) occluders.push_back({k, &solids[k]});
  BOOST_TEST(linear_face_shadow(face, q1, q2, occluders).shadow.polygons.size() == 2u);
  const ExactUmbra umbra = umbra_of(face, q1, q2, solids);
  const ExactUmbra near_umbra = umbra_of(face, q1, q2, near);
  const ExactUmbra far_umbra = umbra_of(face, q1, q2, far);
  BOOST_TEST(near_umbra.joint());
  BOOST_TEST(far_umbra.joint());
  int mismatches = 0;
  const int inside = compare_with_oracle(face, q1, q2, solids, umbra, 1500, 41, &mismatches);
  BOOST_TEST(mismatches == 0);
  BOOST_TEST(inside >= 20);
  const int arcs = check_across_arcs(face, q1, q2, solids, umbra);
  BOOST_TEST(arcs >= 2);
  BOOST_TEST_MESSAGE(inside << " sampled points in the umbra, " << arcs << " arcs crossed");
  // The union, written out: each group's polygons, sorted together.
  for (const bool penumbra : {false, true}) {
    const auto exact = [&](const ExactUmbra& u) {
      return penumbra ? u.exact_penumbra_polygons() : u.exact_umbra_polygons();
    };
    auto both = exact(near_umbra);
    const auto other = exact(far_umbra);
    both.insert(both.end(), other.begin(), other.end());
    BOOST_TEST(both.size() == exact(umbra).size());
    std::sort(both.begin(), both.end(),
              [&](const auto& a, const auto& b) { return written({a}) < written({b}); });
    auto whole = exact(umbra);
    std::sort(whole.begin(), whole.end(),
              [&](const auto& a, const auto& b) { return written({a}) < written({b}); });
    BOOST_TEST(written(whole) == written(both));
  }
  const double expected = near_umbra.area() + far_umbra.area();
  BOOST_TEST(std::abs(umbra.area() - expected) <= 1e-12 * expected);
  // Occluders prepared for this source (as shadows --joint-umbrae prepares them once for all
  // faces) give the same sets; prepared for another source they are not used.
  const FaceShadow shadow = linear_face_shadow(face, q1, q2, occluders);
  for (const Point3& other_end : {q2, Point3(1, 1, 4)}) {
    std::vector<UmbraOccluder> prepared;
    for (const OccluderShadow& o : shadow.occluders)
      prepared.push_back({&solids[o.occluder], o.polygon, o.umbra,
                          prepare_umbra_solid(solids[o.occluder], q1, other_end)});
    const ExactUmbra again = penumbra::exact_umbra(face, q1, q2, prepared);
    BOOST_TEST(written(again.exact_umbra_polygons()) == written(umbra.exact_umbra_polygons()));
    BOOST_TEST(written(again.exact_penumbra_polygons()) ==
               written(umbra.exact_penumbra_polygons()));
  }
}

BOOST_AUTO_TEST_CASE(an_l_shaped_occluder_in_two_pieces_and_a_row_of_slats) {
  const Face& face = floor_face();
  // An L of two boxes sharing the face x = 0: pieces of one object, blocking together.
  const std::vector<ConvexPolyhedron> l_shape{box(-2, -1, 2, 0, 1, 3), box(0, -1, 2, 1, 3, 3)};
  const Point3 q1(-2, 0, 5), q2(2, 1, 5);  // parallel to the floor
  const ExactUmbra l_umbra = umbra_of(face, q1, q2, l_shape);
  BOOST_TEST(l_umbra.joint());
  int mismatches = 0;
  compare_with_oracle(face, q1, q2, l_shape, l_umbra, 600, 5, &mismatches);
  check_across_arcs(face, q1, q2, l_shape, l_umbra);
  // Louvres: five boards 0.75 m wide and 1.5 m deep across a tube, 0.5 m apart: a gap
  // hides the tube from sight lines steeper than 1/3 from the vertical, so beside the
  // louvres the tube is hidden by several boards together.
  std::vector<ConvexPolyhedron> slats;
  for (int k = 0; k < 5; ++k) slats.push_back(box(-3 + 1.25 * k, -4, 2, -2.25 + 1.25 * k, 4, 3.5));
  const Point3 t1(-3, 0, 4), t2(3, 0, 4.5);  // its line meets the floor's plane
  const ExactUmbra slat_umbra = umbra_of(face, t1, t2, slats);
  BOOST_TEST(slat_umbra.joint());
  compare_with_oracle(face, t1, t2, slats, slat_umbra, 600, 6, &mismatches);
  check_across_arcs(face, t1, t2, slats, slat_umbra);
  BOOST_TEST(mismatches == 0);
}

// A face wholly in the joint umbra (the sweep's certificate, certify_whole_umbra): the
// square |x|, |y| <= 1/8 at z = 0 under the tube (2t - 1, 0, 8); box A (x <= 3/8,
// -1 <= y <= 1/16, 4 <= z <= 5) and box B (x >= -3/8, |y| <= 1, 6 <= z <= 7). The sight line
// from P = (p, y, 0) to (q, 0, 8) is at x(z) = p + (q - p) z / 8 and y(z) = y (1 - z / 8), within
// both boxes' y (A's top y = 1/16 is reached at z = 4 from y = 1/8: the corners with y = 1/8
// lie on the planes through the tube's line and A's top corners, where the interval filter
// cannot decide and the exact clipping does). A hides q where min(x(4), x(5)) <= 3/8: for
// every p in [-1/8, 1/8] at least q <= 5/8 (p = 1/8, z = 4); B hides q where
// max(x(6), x(7)) >= -3/8: at least q >= -11/24 (p = -1/8, z = 6). Together they hide the
// whole tube from every point of the square; alone neither does (A lets q = 1 through, B
// q = -1). With B at x >= 5/8 instead, from p = 1/8 it hides only q >= 39/56 (z = 7) and A
// q <= 5/8: the tube shows between them there, while from p = -1/8 A hides q <= 7/8 and B
// q >= 41/56, all of it. The certificate must not fire on that face.
BOOST_AUTO_TEST_CASE(a_face_wholly_in_a_joint_umbra_is_the_whole_face) {
  const ConvexPolyhedron slab = box(-0.125, -0.125, -1, 0.125, 0.125, 0);
  const Face& face = face_with_plane(slab, Plane3(0, 0, 1, 0));
  const Point3 q1(-1, 0, 8), q2(1, 0, 8);
  const ConvexPolyhedron a = box(-3, -1, 4, 0.375, 0.0625, 5);
  const std::vector<ConvexPolyhedron> covering{a, box(-0.375, -1, 6, 3, 1, 7)};
  const ExactUmbra whole = umbra_of(face, q1, q2, covering);
  BOOST_TEST(whole.joint());
  BOOST_TEST(whole.area() == CGAL::to_double(face.area), boost::test_tools::tolerance(1e-12));
  BOOST_TEST(whole.penumbra_area() == 0);
  BOOST_TEST(whole.penumbra_polygons().empty());
  BOOST_TEST_REQUIRE(whole.umbra_polygons().size() == 1u);
  BOOST_TEST(whole.umbra_polygons()[0].outer.points.size() == 4u);  // the face's corners only
  // Certified, the sweep ran with the face's edges alone. The tube is parallel to the face,
  // so the pencil's lines run along x; the edges y = +-1/8 are two of them (the seams of one
  // slab) and x = +-1/8 cross each line once: three cells along it, the middle one the face.
  BOOST_TEST(whole.cells() <= 3u);
  int mismatches = 0;
  BOOST_TEST(compare_with_oracle(face, q1, q2, covering, whole, 400, 31, &mismatches) > 0);
  // A wall C (1/8 <= x <= 1/4, z <= 3) standing on the square's plane along its edge x = 1/8
  // takes B's place. From the corners on that edge (on C's boundary, where only the exact
  // blocked interval decides) the directions strictly into C hide q > 1/8; from those at
  // p = -1/8 the sight line reaches x = 1/8 below z = 3 when q >= 13/24. C hides at least
  // q >= 13/24 from every corner and A q <= 5/8: together, again, the whole tube.
  const std::vector<ConvexPolyhedron> wall{a, box(0.125, -1, 0, 0.25, 1, 3)};
  const ExactUmbra walled = umbra_of(face, q1, q2, wall);
  BOOST_TEST(walled.joint());
  BOOST_TEST(walled.cells() <= 3u);
  BOOST_TEST(walled.area() == CGAL::to_double(face.area), boost::test_tools::tolerance(1e-12));
  BOOST_TEST_REQUIRE(walled.umbra_polygons().size() == 1u);
  BOOST_TEST(walled.umbra_polygons()[0].outer.points.size() == 4u);
  BOOST_TEST(compare_with_oracle(face, q1, q2, wall, walled, 400, 33, &mismatches) > 0);
  const std::vector<ConvexPolyhedron> gap{a, box(0.625, -1, 6, 3, 1, 7)};
  const ExactUmbra partial = umbra_of(face, q1, q2, gap);
  BOOST_TEST(partial.area() > 0);
  BOOST_TEST(partial.area() < CGAL::to_double(face.area) - 1e-6);
  BOOST_TEST(partial.contains(face.frame.to_frame(Point3(-0.125, 0, 0))));
  BOOST_TEST(!partial.contains(face.frame.to_frame(Point3(0.125, 0, 0))));
  compare_with_oracle(face, q1, q2, gap, partial, 400, 32, &mismatches);
  BOOST_TEST(mismatches == 0);
}

// The area against a sampling estimate of the oracle's umbra, within five binomial sigmas.
BOOST_AUTO_TEST_CASE(the_joint_area_agrees_with_sampling) {
  const Face& face = floor_face();
  const std::vector<ConvexPolyhedron> solids{box(-3, -1, 2, -0.25, 1, 3),
                                             box(0.25, -2, 1, 3, 2, 2)};
  const Point3 q1(-2, 0, 5), q2(2, Exact(1) / 2, 5);
  const ExactUmbra umbra = umbra_of(face, q1, q2, solids);
  BOOST_TEST(umbra.joint());
  const int samples = 4000;
  const int inside = compare_with_oracle(face, q1, q2, solids, umbra, samples, 9);
  const double face_area = 144;  // frame units of the floor's face: its frame is unit
  const double p = double(inside) / samples, estimate = p * face_area;
  const double sigma = std::sqrt(p * (1 - p) / samples) * face_area;
  const double scale = CGAL::to_double(face.frame.squared_u() * face.frame.squared_v());
  BOOST_TEST(std::abs(umbra.area() * std::sqrt(scale) - estimate) <= 5 * sigma + 1e-9);
}

// The scene pipeline (shadows --joint-umbrae): the two boards as a fixture; the floor's
// joint_occlusion flag now says that its umbra has joint parts, and the curved sets are
// those of exact_umbra; without the option the flag says only that shadows overlap.
BOOST_AUTO_TEST_CASE(the_shadows_pipeline_carries_the_joint_umbrae) {
  const BothWays computed("linear-joint-umbra");
  const Scene& scene = computed.scene;
  const ShadowResult &with = computed.with, &without = computed.without;
  int curved = 0;
  for (std::size_t r = 0; r < with.receivers.size(); ++r) {
    const FaceShadow& exact = with.lights[0].faces[r];
    const FaceShadow& straight = without.lights[0].faces[r];
    BOOST_TEST(exact.joint_occlusion == bool(exact.curved));
    BOOST_TEST((!exact.joint_occlusion || straight.joint_occlusion));
    if (!exact.curved) continue;
    ++curved;
    BOOST_TEST(scene.objects[with.receivers[r].object].name == "floor");
    BOOST_TEST(exact.curved->area() > CGAL::to_double(straight.umbra.area));
    BOOST_TEST(!exact.curved->umbra_polygons().empty());
    // The illuminance layer integrates the visible parts of the tube exactly: 0 in the
    // umbra, joint parts included, and positive in the penumbra (random points on a
    // 1/64 m grid, decided by the curved sets).
    const illuminance::IlluminanceSolver solver(scene);
    const Face& face =
        scene.objects[with.receivers[r].object].solid.faces()[with.receivers[r].face];
    std::mt19937 random(31);
    std::uniform_int_distribution<int> grid(-383, 383);
    int dark = 0, joint_dark = 0, lit = 0;
    for (int k = 0; k < 400; ++k) {
      const Vec3d p{grid(random) / 64.0, grid(random) / 64.0, 0};
      const Point2 q = face.frame.to_frame(to_exact(p));
      const double e = solver.light_at(0, p, {0, 0, 1});
      if (exact.curved->contains(q)) {
        BOOST_TEST(e == 0.0, "E at " << p[0] << " " << p[1]);
        ++dark;
        joint_dark += test::side_of(straight.umbra, q) == CGAL::ON_UNBOUNDED_SIDE;
      } else if (exact.curved->in_penumbra(q)) {
        BOOST_TEST(e > 0.0, "E at " << p[0] << " " << p[1]);
        ++lit;
      }
    }
    BOOST_TEST(joint_dark > 0);
    BOOST_TEST(lit > 0);
    BOOST_TEST_MESSAGE(dark << " points in the umbra (" << joint_dark << " in joint parts), " << lit
                            << " in the penumbra");
  }
  BOOST_TEST(curved == 1);
}

// A mesh face of several pieces (issue #17): the top of the through-hole block (a square
// with a square hole, cut into four trapezoids) under two boards that hide the tube
// together (fixtures/scenes/linear-joint-mesh.json). Its exact umbra is computed on the
// whole face: at random rational points of every face with joint parts, mesh faces
// included, umbra and shadow membership agree with the oracles over every solid of the
// scene; points in the hole belong to no set; and the top face's umbra is larger than the
// straight one (the joint parts).
BOOST_AUTO_TEST_CASE(a_mesh_face_with_a_hole_has_one_exact_umbra) {
  const BothWays computed("linear-joint-mesh");
  const OracleTally tally = against_the_oracles(computed, true, 37);
  BOOST_TEST(tally.mesh_faces >= 1);
  BOOST_TEST(tally.in_holes > 0);
  BOOST_TEST(tally.mismatches == 0);
  for (std::size_t r = 0; r < computed.with.receivers.size(); ++r) {
    const std::size_t m =
        computed.with.mesh_faces.empty() ? kNoMeshFace : computed.with.mesh_faces[r];
    const FaceShadow& shadow = computed.with.lights[0].faces[r];
    if (shadow.curved && m != kNoMeshFace && computed.scene.mesh_faces[m].part == "block" &&
        !computed.scene.mesh_faces[m].holes.empty())
      BOOST_TEST(shadow.curved->area() >
                 CGAL::to_double(computed.without.lights[0].faces[r].umbra.area));
  }
}

// Pieces of a closed part turned away from the whole tube are left out of joint umbrae
// (src/shadow/back_pieces.h): the through-hole block lies below the tube, so its bottom and
// the walls of its hole that face away are dropped. On every face, curved or straight, the
// sets agree with the oracles over every solid of the scene, those pieces included, and the
// ground names fewer occluders than without joint umbrae (the single umbrae keep every piece).
BOOST_AUTO_TEST_CASE(pieces_turned_away_from_the_tube_change_no_exact_umbra) {
  const BothWays computed("linear-joint-mesh");
  const OracleTally tally = against_the_oracles(computed, false, 41);
  BOOST_TEST(tally.mismatches == 0);
  BOOST_TEST(tally.checked > 1000);
  std::size_t fewer = 0;
  for (std::size_t r = 0; r < computed.with.receivers.size(); ++r)
    fewer += computed.with.lights[0].faces[r].occluders.size() <
             computed.without.lights[0].faces[r].occluders.size();
  BOOST_TEST(fewer > 0);
}

// A tube inside the block's material (fixtures/scenes/linear-tube-inside-mesh.json, in the
// wall x in [0, 1], within the part's bounding box): every piece is kept, since from inside a
// closed solid the faces turned away are the ones that hide. All the ground is umbra (the
// tube is enclosed), as the oracle over every solid says point by point.
BOOST_AUTO_TEST_CASE(a_tube_inside_a_closed_part_keeps_every_piece) {
  const BothWays computed("linear-tube-inside-mesh");
  const OracleTally tally = against_the_oracles(computed, false, 43);
  BOOST_TEST(tally.mismatches == 0);
  BOOST_TEST(tally.umbra > 100);
}

// A tube in the block's wall x in [0, 1] from y = 1/2 to 7/2
// (fixtures/scenes/linear-tube-cut-by-walls.json): the planes of the hole's walls y = 1 and
// y = 3 cut it, and the pieces beside those walls have edges in the same planes, so a plane
// through the cut point and such an edge holds the wall. Every sight line from those walls to
// the part of the tube they see runs through the material x < 1: both are all umbra (the limit
// of linear_volumes.h; before it, all penumbra), as the oracle over every solid says.
BOOST_AUTO_TEST_CASE(walls_whose_planes_cut_the_tube_at_a_pieces_edge_are_umbra) {
  const BothWays computed("linear-tube-cut-by-walls");
  const OracleTally tally = against_the_oracles(computed, false, 47);
  BOOST_TEST(tally.mismatches == 0);
  BOOST_TEST(tally.umbra > 100);
  int walls = 0;
  for (const ShadowResult* result : {&computed.with, &computed.without})
    for (std::size_t r = 0; r < result->receivers.size(); ++r) {
      const FaceShadow& shadow = result->lights[0].faces[r];
      if (!shadow.source_clipped) continue;
      const Face& face = computed.scene.objects[result->receivers[r].object]
                             .solid.faces()[result->receivers[r].face];
      ++walls;
      BOOST_TEST(shadow.umbra.area == face.area);
      BOOST_TEST(shadow.penumbra.empty());
    }
  BOOST_TEST(walls == 4);  // y = 1 and y = 3, with and without joint umbrae
}

// The real model of issue #17 (docs/performance.md, "A real model"): the KIT house read
// without "up" (lying on its side, 20,334 convex pieces) on a ground box under an 8 m tube
// 14 m up. The ground's top is shadowed by 1,335 pieces (the 487 turned away from the tube
// left out) in one touching group, and their joint umbra covers 8 m² more than the single
// umbrae. At random rational points of the box of the house's shadow on the ground (a 27 m x
// 5 m band), umbra and shadow membership agree with the oracles over the solids of the scene
// that can meet the segments from the point to the tube (those whose boxes meet the box of
// the triangle: the pieces turned away included).
BOOST_AUTO_TEST_CASE(ifc_house_ground_agrees_with_the_oracle, PENUMBRA_LONG_TEST) {
  const auto path = test::gunzip_fixture("meshes/AC14-FZK-Haus.ifc");
  const nlohmann::json document = {
      {"penumbra", 1},
      {"objects",
       {{{"name", "ground"}, {"box", {{"min", {-15, -25, -1.5}}, {"max", {30, 20, -1.0}}}}},
        {{"name", "house"}, {"mesh", path.string()}}}},
      {"lights",
       {{{"name", "tube"}, {"linear", {{2, -2, 14}, {10, -2, 14}}}, {"candela_per_metre", 100}}}}};
  const auto file = test::scratch_dir("joint-ifc-house") / "scene.json";
  std::ofstream(file) << document.dump();
  const Scene scene = load_scene(file);
  ShadowOptions options = BothWays::joint();
  const Face* top = nullptr;
  for (std::size_t f = 0; f < scene.objects[0].solid.faces().size(); ++f)
    if (scene.objects[0].solid.faces()[f].plane == Plane3(0, 0, 1, 1)) {
      options.receivers = std::vector<Receiver>{{0, f}};
      top = &scene.objects[0].solid.faces()[f];
    }
  BOOST_TEST_REQUIRE(top != nullptr);
  const ShadowResult result = compute_shadows(scene, options);
  const FaceShadow& shadow = result.lights[0].faces[0];
  BOOST_TEST_REQUIRE(shadow.curved != nullptr);
  BOOST_TEST(shadow.joint_occlusion);
  // (frame units: the joint parts add a tenth to the single umbrae's 68.4 m²)
  BOOST_TEST(shadow.curved->area() > 1.1 * CGAL::to_double(shadow.umbra.area));
  const auto& tube = std::get<LinearLight>(scene.lights[0].source);
  const Point3 q1 = to_exact(tube.start), q2 = to_exact(tube.end);
  std::vector<CGAL::Bbox_3> boxes;
  for (const Object& object : scene.objects) boxes.push_back(object.solid.bbox());
  // the exact box of the straight shadow (frame coordinates), on a grid of 4,095ths
  std::vector<Point2> corners;
  for (const Polygon2& polygon : shadow.shadow.polygons)
    corners.insert(corners.end(), polygon.outer.begin(), polygon.outer.end());
  const ExactBox band(corners);
  std::mt19937 random(53);  // fixed: failures must reproduce
  std::uniform_int_distribution<int> step(1, 4094);
  int checked = 0, in_umbra = 0, in_shadow = 0, mismatches = 0;
  for (int k = 0; k < 600; ++k) {
    const Point2 p = band.at(step(random), step(random), 4095);
    const Point3 x = top->frame.to_world(p);
    const CGAL::Bbox_3 reach = x.bbox() + q1.bbox() + q2.bbox();
    std::vector<ConvexPolyhedron> near;
    for (std::size_t o = 1; o < scene.objects.size(); ++o)
      if (CGAL::do_overlap(boxes[o], reach)) near.push_back(scene.objects[o].solid);
    const bool umbra = oracle_covered(*top, q1, q2, near, x);
    const bool shadowed = oracle_shadowed(*top, q1, q2, near, x);
    mismatches += shadow.curved->contains(p) != umbra;
    BOOST_TEST(shadow.curved->contains(p) == umbra, "umbra at " << x);
    BOOST_TEST((shadow.curved->contains(p) || shadow.curved->in_penumbra(p)) == shadowed,
               "shadow at " << x);
    ++checked;
    in_umbra += umbra;
    in_shadow += shadowed;
  }
  BOOST_TEST(mismatches == 0);
  BOOST_TEST(in_umbra > 20);
  BOOST_TEST(in_shadow > in_umbra);
  BOOST_TEST_MESSAGE("IFC house's ground: " << checked << " points, " << in_shadow
                                            << " in the shadow, " << in_umbra << " in the umbra");
}

BOOST_AUTO_TEST_SUITE_END()
