// The shadow map of a face under a linear source: unions over occluders checked
// against the exact oracles (issue #4 item 8a), the source cut by the face's plane
// (Fig. 7, S3), faces turned away (S2) and the joint-occlusion flag.

#include <boost/test/unit_test.hpp>

#include <CGAL/Polygon_2.h>

#include <optional>
#include <random>

#include "linear_oracle.h"
#include "penumbra/shadow/exact_umbra.h"
#include "penumbra/shadow/face_shadow.h"
#include "penumbra/shadow/linear_face_shadow.h"
#include "solids.h"

using namespace penumbra;

namespace {

using test::box;
using test::face_with_plane;
using test::side_of;

// shadow and umbra are the closures of the oracles' open sets: interior points must
// satisfy the oracle, exterior points must not. An interior point where the light grazes a
// solid (test::simplex_grazes) may be unblocked: the lit line between shadows that abut
// there is dropped by regularization (docs/shadows.md). Returns 1 for a decisive sample.
int check(const char* name, const Region2& region, const Point2& p, bool expected, bool grazing) {
  const CGAL::Bounded_side side = side_of(region, p);
  if (side == CGAL::ON_BOUNDED_SIDE && !grazing) BOOST_TEST(expected, name << " at " << p);
  if (side == CGAL::ON_UNBOUNDED_SIDE) BOOST_TEST(!expected, name << " at " << p);
  return side == CGAL::ON_UNBOUNDED_SIDE || (side == CGAL::ON_BOUNDED_SIDE && !grazing);
}

// lit and penumbra are differences of closed sets: only their interiors are
// decisive (a point outside lit may lie on the shadow's boundary, unblocked).
void check_interior(const char* name, const Region2& region, const Point2& p, bool expected,
                    bool grazing) {
  if (!grazing && side_of(region, p) == CGAL::ON_BOUNDED_SIDE)
    BOOST_TEST(expected, name << " at " << p);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(linear_face_shadow)

BOOST_AUTO_TEST_CASE(random_scenes_agree_with_the_oracles) {
  std::mt19937 random(4);  // fixed: failures must reproduce
  std::uniform_int_distribution<int> corner(-4, 3), size(1, 2), height(1, 3), quarter(-24, 24);
  const auto floor = box(-6, -6, -1, 6, 6, 0);
  const Face& top = face_with_plane(floor, Plane3(0, 0, 1, 0));
  int samples = 0, joint = 0, graze_count = 0;
  for (int scene = 0; scene < 25; ++scene) {
    std::vector<ConvexPolyhedron> solids;
    for (int k = 0; k < 4; ++k) {
      const int x = corner(random), y = corner(random), z = height(random);
      const int width = size(random), depth = size(random);  // drawn in this order
      solids.push_back(box(x, y, z, x + width, y + depth, z + 1));
    }
    const int x1 = corner(random), y1 = corner(random), x2 = corner(random), y2 = corner(random);
    const Point3 q1(x1, y1, 6), q2(x2, y2, 7);
    std::vector<Occluder> occluders;
    for (std::size_t k = 0; k < solids.size(); ++k) occluders.push_back({k, &solids[k]});
    FaceShadow shadow;
    try {
      shadow = penumbra::linear_face_shadow(top, q1, q2, occluders);
    } catch (const std::domain_error&) {
      continue;  // random boxes may overlap the tube's height range: not this test's subject
    }
    joint += shadow.joint_occlusion;
    for (int s = 0; s < 200; ++s) {
      const int u = quarter(random), v = quarter(random);
      const Point3 x(Exact(u) / 4, Exact(v) / 4, 0);
      const Point2 p = top.frame.to_frame(x);
      bool blocked = false, umbra = false, grazing = false;
      for (const ConvexPolyhedron& solid : solids) {
        blocked = blocked || test::triangle_blocked(x, q1, q2, solid);
        umbra = umbra || (test::segment_meets_interior(x, q1, solid) &&
                          test::segment_meets_interior(x, q2, solid));
        grazing = grazing || test::simplex_grazes({x, q1, q2}, solid) ||
                  test::simplex_grazes({x, q1}, solid) || test::simplex_grazes({x, q2}, solid);
      }
      graze_count += grazing;
      samples += check("shadow", shadow.shadow, p, blocked, grazing);
      check("umbra", shadow.umbra, p, umbra, grazing);
      check_interior("lit", shadow.lit, p, !blocked, grazing);
      check_interior("penumbra", shadow.penumbra, p, blocked && !umbra, grazing);
    }
    // lit and shadow partition the face: their areas add up to the face's.
    BOOST_TEST(shadow.lit.area + shadow.shadow.area == signed_area(face_ring(top)));
    BOOST_TEST(shadow.penumbra.area + shadow.umbra.area == shadow.shadow.area);
  }
  BOOST_TEST_MESSAGE("decisive samples " << samples << ", scenes with joint occlusion " << joint
                                         << ", grazing samples " << graze_count);
  BOOST_TEST(samples > 3000);
  BOOST_TEST(joint > 0);
}

BOOST_AUTO_TEST_CASE(a_face_whose_plane_cuts_the_source_sees_only_its_outer_part) {
  // The wall x = 0 (face +x of a thin box) and a tube crossing its plane from
  // x = -1 to x = 1: only the part with x > 0 lights the face, so the effective
  // source runs from (0, 0.5, 2) to (1, 0.5, 2) (Fig. 7, S3).
  const auto wall = box(-0.1, -3, 0, 0, 3, 4);
  const Face& face = face_with_plane(wall, Plane3(1, 0, 0, 0));
  const auto shadow = penumbra::linear_face_shadow(face, Point3(-1, 0.5, 2), Point3(1, 0.5, 2), {});
  BOOST_TEST(shadow.source_clipped);
  BOOST_TEST(!shadow.faces_away);
  const auto source = visible_source(face, Point3(-1, 0.5, 2), Point3(1, 0.5, 2));
  BOOST_TEST_REQUIRE(source.has_value());
  BOOST_TEST((source->q1 == Point3(0, 0.5, 2)));
  BOOST_TEST((source->q2 == Point3(1, 0.5, 2)));
  BOOST_TEST(shadow.shadow.empty());
  BOOST_TEST(shadow.lit.area == signed_area(face_ring(face)));
}

// The wall y = 0 facing -y (x in [-2, 2], z in [0, 2]) and a tube along y from (-1, -1, h)
// to (-1, 1, h): its plane cuts the tube at c = (-1, 0, h), and only the part y < 0 lights
// it. An occluder box [-3/4, -1/4] x [-2, 0] x [0, top] has edges in the wall's plane, so
// the plane through c and such an edge is the wall's own plane: the side of the wall it
// keeps is the limit as c moves into the tube (docs/linear-shadows.md, "The face and the
// source"). Checks the umbra against the polygon expected, derived by the caller, exactly in
// area and at random rational points of the wall; the penumbra is empty (whether a sight line
// X -> (-1, y, h) meets the box does not depend on y: see the callers).
namespace {

void check_wall_umbra(double top, int h, const Ring2& expected, unsigned seed) {
  const auto wall = box(-2, 0, 0, 2, 1, 2);
  const Face& face = face_with_plane(wall, Plane3(0, -1, 0, 0));
  const auto occluder = box(-0.75, -2, 0, -0.25, 0, top);
  const Point3 q1(-1, -1, h), q2(-1, 1, h);
  const FaceShadow shadow = penumbra::linear_face_shadow(face, q1, q2, {{0, &occluder}});
  BOOST_TEST(shadow.source_clipped);
  BOOST_TEST(shadow.penumbra.area == 0);
  BOOST_TEST_REQUIRE(shadow.occluders.size() == 1u);
  // The sweep of exact umbrae, run here though one occluder has no joint part: its blocked
  // intervals are closed, and reach the cut point without a limit.
  const ExactUmbra swept = exact_umbra(
      face, q1, q2, {{&occluder, shadow.occluders[0].polygon, shadow.occluders[0].umbra}});
  Ring2 ring;  // expected in the wall's frame
  for (const Point2& p : expected) ring.push_back(face.frame.to_frame(Point3(p.x(), 0, p.y())));
  const CGAL::Polygon_2<Kernel> polygon(ring.begin(), ring.end());
  BOOST_TEST(shadow.umbra.area == CGAL::abs(polygon.area()));
  std::mt19937 random(seed);  // fixed: failures must reproduce
  std::uniform_int_distribution<int> along(-255, 255), up(1, 255);
  int inside = 0;
  for (int k = 0; k < 1000; ++k) {
    const Point2 p =
        face.frame.to_frame(Point3(Exact(along(random)) / 128, 0, Exact(up(random)) / 128));
    const auto side = polygon.bounded_side(p);
    if (side == CGAL::ON_BOUNDARY) continue;
    inside += side == CGAL::ON_BOUNDED_SIDE;
    BOOST_TEST((side_of(shadow.umbra, p) == side), "at " << face.frame.to_world(p));
    BOOST_TEST(swept.contains(p) == (side == CGAL::ON_BOUNDED_SIDE),
               "at " << face.frame.to_world(p));
    BOOST_TEST(!swept.in_penumbra(p), "at " << face.frame.to_world(p));
  }
  BOOST_TEST(inside > 50);
  BOOST_TEST(swept.area() == CGAL::to_double(shadow.umbra.area),
             boost::test_tools::tolerance(1e-12));
}

}  // namespace

// A low box (top = 1) under the tube at h = 2, touching the wall along x in [-3/4, -1/4],
// z in [0, 1]. From X = (x, 0, z): for x < -3/4 the sight line to (-1, y, 2) stays at
// x < -3/4, clear of the box; for x in (-3/4, -1/4) it enters the box at once when z < 1 (X
// is on its face y = 0) and rises clear of it when z > 1; for x > -1/4 it is at height
// z + (2 - z)(x - s)/(x + 1) where it crosses x = s, lowest at s = -1/4, and at depth
// y (x - s)/(x + 1) in (-2, 0): it meets the box iff z + (2 - z)(x + 1/4)/(x + 1) < 1, i.e.
// z < 2 (1 - 2x) / 3. The umbra is (-3/4, 0), (1/2, 0), (-1/4, 1), (-3/4, 1) in (x, z);
// before the limit, the plane through c and the box's edges in y = 0 (one of its umbra
// planes) kept none of the wall.
BOOST_AUTO_TEST_CASE(an_edge_in_the_plane_that_cuts_the_tube_keeps_the_umbra) {
  check_wall_umbra(1, 2,
                   {Point2(-Exact(3) / 4, 0), Point2(Exact(1) / 2, 0), Point2(-Exact(1) / 4, 1),
                    Point2(-Exact(3) / 4, 1)},
                   5);
}

// A box as high as the wall (top = 2) under the tube at h = 3, touching the wall along
// x in [-3/4, -1/4]. From X = (x, 0, z): for x < -3/4 the sight line to (-1, y, 3) stays at
// x < -3/4, clear of the box; for x in (-3/4, -1/4) it enters the box at once (X is on its face
// y = 0); for x > -1/4 it meets it iff z + (3 - z)(x + 1/4)/(x + 1) < 2, i.e.
// z < (5 - 4x) / 3. The umbra is (-3/4, 0), (5/4, 0), (-1/4, 2), (-3/4, 2): its side x = -3/4
// lies on the limit of the plane through c and the box's edge x = -3/4, y = 0 (turned the
// other way, it would keep x < -3/4 and leave no umbra).
BOOST_AUTO_TEST_CASE(the_limit_plane_keeps_the_side_behind_the_edge) {
  check_wall_umbra(2, 3,
                   {Point2(-Exact(3) / 4, 0), Point2(Exact(5) / 4, 0), Point2(-Exact(1) / 4, 2),
                    Point2(-Exact(3) / 4, 2)},
                   6);
}

BOOST_AUTO_TEST_CASE(a_face_behind_both_ends_is_wholly_unlit) {
  const auto wall = box(-0.1, -3, 0, 0, 3, 4);
  const Face& face = face_with_plane(wall, Plane3(1, 0, 0, 0));
  // Both ends behind the plane, and one end in it with the other behind: unlit.
  for (const auto& ends : {std::make_pair(Point3(-1, 0, 2), Point3(-2, 1, 2)),
                           std::make_pair(Point3(0, 0, 2), Point3(-2, 1, 2))}) {
    const auto shadow = penumbra::linear_face_shadow(face, ends.first, ends.second, {});
    BOOST_TEST(shadow.faces_away);
    BOOST_TEST(shadow.shadow.area == signed_area(face_ring(face)));
    BOOST_TEST(shadow.lit.empty());
  }
}

BOOST_AUTO_TEST_CASE(the_lit_line_between_abutting_shadows_is_dropped) {
  // A tube in the plane x = 0, from (0, -2, 5) to (0, 2, 5), and two boxes on either side of
  // that plane: A = [0, 1] x [-1, 1] x [2, 3] and B = [-1, 0] x [-1, 1] x [1, 3/2]. From a
  // floor point (0, y, 0) the triangle to the tube lies in x = 0, which holds a face of each
  // box: the light grazes both and nothing blocks it. A point (e, 0, 0) with e > 0 sees the
  // tube's middle (0, 0, 5) through A (at z in (2, 3) the segment is at x = e (1 - z/5) in
  // (0, 1), y = 0), and (-e, 0, 0) through B likewise: the line x = 0 is an unblocked line
  // between two shadows, and regularization drops it (docs/shadows.md, abutting shadows).
  const auto floor = box(-6, -6, -1, 6, 6, 0);
  const Face& top = face_with_plane(floor, Plane3(0, 0, 1, 0));
  const std::vector<ConvexPolyhedron> solids{box(0, -1, 2, 1, 1, 3), box(-1, -1, 1, 0, 1, 1.5)};
  const Point3 q1(0, -2, 5), q2(0, 2, 5);
  const std::vector<Occluder> occluders{{0, &solids[0]}, {1, &solids[1]}};
  const FaceShadow shadow = penumbra::linear_face_shadow(top, q1, q2, occluders);
  const Point3 x(0, 0, 0), east(Exact(1) / 8, 0, 0), west(-Exact(1) / 8, 0, 0);
  for (const ConvexPolyhedron& solid : solids) {
    BOOST_TEST(!test::triangle_blocked(x, q1, q2, solid));
    BOOST_TEST(test::simplex_grazes({x, q1, q2}, solid));
  }
  BOOST_TEST(test::triangle_blocked(east, q1, q2, solids[0]));
  BOOST_TEST(test::triangle_blocked(west, q1, q2, solids[1]));
  BOOST_TEST((side_of(shadow.shadow, top.frame.to_frame(x)) == CGAL::ON_BOUNDED_SIDE));
  BOOST_TEST((side_of(shadow.lit, top.frame.to_frame(x)) == CGAL::ON_UNBOUNDED_SIDE));
}

BOOST_AUTO_TEST_CASE(two_plates_under_a_tube_overlap_in_penumbra_only) {
  // Two plates at z = 2 side by side, x in [0, 1] and [1.5, 2.5], y in [0, 1], under
  // a tube at z = 4 from x = 0 to x = 2.5. Each alone leaves an umbra; their
  // penumbrae overlap between them, so joint occlusion is possible there.
  const auto a = ConvexPolyhedron::flat_polygon({{0, 0, 2}, {1, 0, 2}, {1, 1, 2}, {0, 1, 2}});
  const auto b =
      ConvexPolyhedron::flat_polygon({{1.5, 0, 2}, {2.5, 0, 2}, {2.5, 1, 2}, {1.5, 1, 2}});
  const auto floor = box(-6, -6, -1, 6, 6, 0);
  const Face& top = face_with_plane(floor, Plane3(0, 0, 1, 0));
  const auto shadow =
      penumbra::linear_face_shadow(top, Point3(0, 0.5, 4), Point3(2.5, 0.5, 4), {{1, &b}, {0, &a}});
  BOOST_TEST(shadow.joint_occlusion);
  BOOST_TEST_REQUIRE(shadow.occluders.size() == 2u);
  BOOST_TEST(shadow.occluders[0].occluder == 1u);  // in the order given
  BOOST_TEST(shadow.occluders[1].occluder == 0u);
  // Plate a from Q1 = (0, .5, 4) covers x in [0, 2] (X = 2v - Q); from Q2 = (2.5, .5, 4)
  // x in [-2.5, -0.5]: disjoint, so a alone casts no umbra.
  BOOST_TEST(!shadow.occluders[1].umbra.has_value());
}

BOOST_AUTO_TEST_CASE(an_occluders_whole_source_volumes_serve_only_faces_that_see_all_of_it) {
  // A scene makes each occluder's volumes under the whole tube once (source_occlusion) and
  // hands them to every face: the maps must be those made without them, on the floor (which
  // sees the whole tube) and on a wall whose plane cuts the tube (Fig. 7, S3: its visible
  // part is shorter, so the whole tube's volumes must not be used there).
  std::mt19937 random(11);  // fixed: failures must reproduce
  std::uniform_int_distribution<int> corner(-4, 3), size(1, 2), height(1, 3);
  const auto floor = box(-6, -6, -1, 6, 6, 0);
  const Face& top = face_with_plane(floor, Plane3(0, 0, 1, 0));
  const auto wall = box(-6, -6, 0, -5, 6, 8);
  const Face& inner = face_with_plane(wall, Plane3(1, 0, 0, 5));  // x = -5, facing +x
  const Point3 q1(-7, 1, 6), q2(4, -1, 7);                        // crosses the wall's plane x = -5
  int compared = 0;
  for (int scene = 0; scene < 20; ++scene) {
    std::vector<ConvexPolyhedron> solids;
    for (int k = 0; k < 4; ++k) {
      const int x = corner(random), y = corner(random), z = height(random);
      solids.push_back(box(x, y, z, x + size(random), y + size(random), z + 1));
    }
    std::vector<SourceOcclusion> whole;
    for (const auto& solid : solids) whole.push_back(source_occlusion(solid, q1, q2));
    for (const Face* face : {&top, &inner}) {
      std::vector<Occluder> plain, prepared;
      for (std::size_t k = 0; k < solids.size(); ++k) {
        plain.push_back({k, &solids[k]});
        prepared.push_back({k, &solids[k], &whole[k]});
      }
      std::optional<FaceShadow> expected;
      try {
        expected = penumbra::linear_face_shadow(*face, q1, q2, plain);
      } catch (const std::domain_error&) {
        BOOST_CHECK_THROW(penumbra::linear_face_shadow(*face, q1, q2, prepared), std::domain_error);
        continue;
      }
      const FaceShadow got = penumbra::linear_face_shadow(*face, q1, q2, prepared);
      BOOST_TEST((got.shadow == expected->shadow), "scene " << scene);
      BOOST_TEST((got.umbra == expected->umbra), "scene " << scene);
      BOOST_TEST((got.penumbra == expected->penumbra), "scene " << scene);
      BOOST_TEST((got.lit == expected->lit), "scene " << scene);
      BOOST_TEST(got.occluders.size() == expected->occluders.size());
      BOOST_TEST(got.source_clipped == (face == &inner));
      compared += !expected->occluders.empty();
    }
  }
  BOOST_TEST(compared >= 10);  // the scenes cast shadows on both faces, not only nothing
}

BOOST_AUTO_TEST_SUITE_END()
