// The mesh oracle (mesh_oracle.h) on its own, against positions derived by hand, so that a
// disagreement in mesh_oracle_test.cpp points at the engine: point location in faces with
// holes and notches, sampling, and verdicts on the courtyard, the block with a hole and both
// sides of the canopy. Then the mesh fixtures are checked to be worth comparing: in each,
// the oracle finds points that the model itself shades while they face the light, and
// ground both lit and shaded by the model.

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <memory>

#include "mesh_oracle.h"
#include "mesh_scene.h"
#include "support/fixtures.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

std::vector<Point3> on_plane_z(const std::vector<std::array<double, 2>>& xy) {
  std::vector<Point3> ring;
  for (const auto& p : xy) ring.emplace_back(p[0], p[1], 0);
  return ring;
}

// A scene's oracle: its models imported as the scene asks, and its convex objects.
struct OracleScene {
  std::vector<MeshObject> meshes;
  Scene rest;
  std::unique_ptr<MeshOracle> oracle;

  explicit OracleScene(const std::string& name)
      : meshes(load_mesh_objects(fixture("scenes/" + name))),
        rest(load_scene_without_meshes(fixture("scenes/" + name))) {
    std::vector<const ConvexPolyhedron*> convex;
    for (const Object& object : rest.objects) convex.push_back(&object.solid);
    std::vector<const ImportedModel*> models;
    for (const MeshObject& mesh : meshes) models.push_back(&mesh.model);
    oracle = std::make_unique<MeshOracle>(convex, models);
  }

  Verdict at(const Plane3& plane, const Point3& x, const std::string& light) const {
    return oracle->verdict(plane, x, *rest.find_light(light));
  }
};

}  // namespace

BOOST_AUTO_TEST_SUITE(mesh_oracle_self)

BOOST_AUTO_TEST_CASE(points_locate_in_faces_with_holes_and_notches) {
  // A 4 x 4 square with a 2 x 2 hole in the tilted plane z = x (normal (-1, 0, 1)).
  const auto lift = [](double x, double y) { return Point3(x, y, x); };
  const std::vector<Point3> outer = {lift(0, 0), lift(4, 0), lift(4, 4), lift(0, 4)};
  const std::vector<Point3> hole = {lift(1, 1), lift(1, 3), lift(3, 3), lift(3, 1)};
  for (const Vector3& normal : {Vector3(-1, 0, 1), Vector3(1, 0, -1)}) {
    const PlanarRegion square(normal, outer, {hole});
    BOOST_TEST((square.locate(lift(0.5, 0.5)) == Place::inside));
    BOOST_TEST((square.locate(lift(3.5, 2)) == Place::inside));
    BOOST_TEST((square.locate(lift(2, 2)) == Place::outside));  // in the hole
    BOOST_TEST((square.locate(lift(5, 1)) == Place::outside));
    BOOST_TEST((square.locate(lift(1, 2)) == Place::boundary));  // the hole's edge
    BOOST_TEST((square.locate(lift(3, 3)) == Place::boundary));  // the hole's corner
    BOOST_TEST((square.locate(lift(2, 0)) == Place::boundary));
    BOOST_TEST((square.locate(lift(4, 4)) == Place::boundary));
  }
  // The L footprint of the courtyard building, either way round: its notch is outside, and
  // points level with its vertices (the half-open rule) are decided right.
  std::vector<Point3> l_ring = on_plane_z({{0, 0}, {10, 0}, {10, 4}, {4, 4}, {4, 10}, {0, 10}});
  for (int turn = 0; turn < 2; ++turn) {
    const PlanarRegion l_shape(Vector3(0, 0, 1), l_ring, {});
    BOOST_TEST((l_shape.locate(Point3(6, 6, 0)) == Place::outside));
    BOOST_TEST((l_shape.locate(Point3(2, 8, 0)) == Place::inside));
    BOOST_TEST((l_shape.locate(Point3(2, 4, 0)) == Place::inside));
    BOOST_TEST((l_shape.locate(Point3(12, 4, 0)) == Place::outside));
    BOOST_TEST((l_shape.locate(Point3(-1, 4, 0)) == Place::outside));
    BOOST_TEST((l_shape.locate(Point3(4, 6, 0)) == Place::boundary));
    BOOST_TEST((l_shape.locate(Point3(7, 4, 0)) == Place::boundary));
    BOOST_TEST((l_shape.locate(Point3(4, 4, 0)) == Place::boundary));
    std::reverse(l_ring.begin(), l_ring.end());
  }
}

BOOST_AUTO_TEST_CASE(samples_lie_strictly_inside_and_on_the_plane) {
  SplitMix64 random(5);
  const Plane3 tilted(-1, 0, 1, 0);
  const auto lift = [](double x, double y) { return Point3(x, y, x); };
  const PlanarRegion square(tilted.orthogonal_vector(),
                            {lift(0, 0), lift(4, 0), lift(4, 4), lift(0, 4)},
                            {{lift(1, 1), lift(1, 3), lift(3, 3), lift(3, 1)}});
  const std::vector<Point3> points = sample_region(tilted, square, 400, random);
  BOOST_TEST(points.size() == 400u);
  std::size_t off_plane = 0, in_hole = 0, left = 0;
  for (const Point3& p : points) {
    off_plane += !tilted.has_on(p);
    in_hole += p.x() > 1 && p.x() < 3 && p.y() > 1 && p.y() < 3;
    left += p.x() < 1;
  }
  BOOST_TEST(off_plane == 0u);
  BOOST_TEST(in_hole == 0u);
  BOOST_TEST(left > 50u);  // a quarter of the face's area: about 100
}

BOOST_AUTO_TEST_CASE(verdicts_match_hand_derived_segments) {
  // mesh-courtyard.json: the L turned a quarter about z and moved +10 in x, so its wings are
  // x in [6, 10] x y in [0, 10] and x in [0, 10] x y in [0, 4], 6 m high; the courtyard is
  // x < 6, y > 4. Sun along (1, 1, -0.5), lamp at (-4, 2, 3).
  const OracleScene court("mesh-courtyard.json");
  const Plane3 wall(-1, 0, 0, 6), ground(0, 0, 1, 0), roof(0, 0, 1, -6);
  // Toward the sun, (6, 5, 1) + s (-1, -1, 0.5) enters the second wing at s = 1, (5, 4, 1.5).
  BOOST_TEST((court.at(wall, Point3(6, 5, 1), "sun") == Verdict::shadow));
  // (6, 9, 5) reaches y = 4 at height 7.5, above the roof.
  BOOST_TEST((court.at(wall, Point3(6, 9, 5), "sun") == Verdict::lit));
  BOOST_TEST((court.at(ground, Point3(5, 6, 0), "sun") == Verdict::shadow));
  BOOST_TEST((court.at(roof, Point3(8, 8, 6), "sun") == Verdict::lit));
  BOOST_TEST((court.at(roof, Point3(8, 8, 6), "lamp") == Verdict::shadow));  // lamp below
  // Toward the lamp, (6, 5, 1) reaches y = 4 at x = 2.67, z = 1.67: inside the second wing.
  BOOST_TEST((court.at(wall, Point3(6, 5, 1), "lamp") == Verdict::shadow));
  BOOST_TEST((court.at(ground, Point3(-2, 8, 0), "lamp") == Verdict::lit));
  // (4, 6, 0) to (-4, 2, 3) passes through the wing's vertical edge (0, 4, 1.5) and nowhere
  // into it: on a ring, measure zero.
  BOOST_TEST((court.at(ground, Point3(4, 6, 0), "lamp") == Verdict::degenerate));

  // mesh-through-hole.json: the block x, y in [0, 4], z in [1, 3], hole x, y in [1, 3].
  const OracleScene block("mesh-through-hole.json");
  BOOST_TEST((block.at(ground, Point3(2, 2, 0), "lamp") == Verdict::lit));  // through the hole
  BOOST_TEST((block.at(ground, Point3(0.5, 0.5, 0), "lamp") == Verdict::shadow));
  // (2.8, 2.2, 0) + s (-0.5, -0.25, 1) is at (2.3, 1.95) at z = 1 and (1.3, 1.45) at z = 3.
  BOOST_TEST((block.at(ground, Point3(2.8, 2.2, 0), "sun") == Verdict::lit));
  // (4, 3, 0) + s (-0.5, -0.25, 1) meets the block's bottom at (3.5, 2.75, 1), beside the hole.
  BOOST_TEST((block.at(ground, Point3(4, 3, 0), "sun") == Verdict::shadow));

  // mesh-canopy.json: the north slope's plane is y + 2 z = 8; its underside is the open
  // surface's other side. From (2.5, 2.1, 2.95) the lamp (2.5, -2, 1.8) is seen through the
  // south slope (crossing z = 2 + y / 2 at y = 1.64); from (2.5, 3.8, 2.1) the segment
  // passes under the south eave (crossing its plane at y = -0.22).
  const OracleScene canopy("mesh-canopy.json");
  const Plane3 north(0, 1, 2, -8), underside = north.opposite();
  BOOST_TEST((canopy.at(underside, Point3(2.5, 2.1, 2.95), "lamp") == Verdict::shadow));
  BOOST_TEST((canopy.at(underside, Point3(2.5, 3.8, 2.1), "lamp") == Verdict::lit));
  BOOST_TEST((canopy.at(underside, Point3(2.5, 3, 2.5), "sun") == Verdict::shadow));
  BOOST_TEST((canopy.at(north, Point3(2.5, 3, 2.5), "sun") == Verdict::lit));
}

BOOST_AUTO_TEST_CASE(mesh_fixtures_shade_themselves_and_the_ground) {
  // At random points of every receiving side of every model face and of the ground's top,
  // count by the oracle alone what each fixture is for.
  std::uint64_t seed = 41;
  for (const char* name : {"mesh-courtyard.json", "mesh-through-hole.json", "mesh-staircase.json",
                           "mesh-window.json", "mesh-canopy.json", "mesh-noisy.json"}) {
    BOOST_TEST_CONTEXT(name) {
      const OracleScene scene(name);
      SplitMix64 random(seed++);
      std::size_t self_shaded = 0, ground_shaded = 0, ground_lit = 0, model_lit = 0;
      for (const MeshObject& mesh : scene.meshes)
        for (const ModelPart& part : mesh.model.parts)
          for (const PlanarFace& face : part.faces)
            for (const Plane3& side : {face.plane, face.plane.opposite()}) {
              if (side != face.plane && face.solid) continue;  // a solid's face: outer side only
              const PlanarRegion region(side.orthogonal_vector(), face.outer, face.holes);
              for (const Point3& x : sample_region(side, region, 60, random))
                for (const Light& light : scene.rest.lights) {
                  const Verdict verdict = scene.oracle->verdict(side, x, light);
                  model_lit += verdict == Verdict::lit;
                  self_shaded += verdict == Verdict::shadow && strictly_outside(side, light);
                }
            }
      const Plane3 ground(0, 0, 1, 0);
      // the ground around the models (the box's top is larger)
      const PlanarRegion top(Vector3(0, 0, 1), on_plane_z({{-3, -3}, {12, -3}, {12, 12}, {-3, 12}}),
                             {});
      for (const Point3& x : sample_region(ground, top, 2000, random))
        for (const Light& light : scene.rest.lights) {
          const Verdict verdict = scene.oracle->verdict(ground, x, light);
          ground_lit += verdict == Verdict::lit;
          ground_shaded += verdict == Verdict::shadow;
        }
      BOOST_TEST_MESSAGE(name << ": model faces " << model_lit << " lit, " << self_shaded
                              << " shaded while facing the light; ground " << ground_lit << " lit, "
                              << ground_shaded << " in shadow");
      BOOST_TEST(model_lit > 100u);
      BOOST_TEST(ground_lit > 1000u);
      BOOST_TEST(ground_shaded > 20u);
      if (std::string(name) != "mesh-noisy.json") BOOST_TEST(self_shaded >= 20u);
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()
