// Mesh objects in scenes (docs/scene-format.md, "Mesh objects"): closed convex parts are
// solids; every other part becomes convex pieces (objects) and the MeshFaces they make up,
// one side for a closed solid, two for an open surface; the placement keys move the model
// exactly; bad models are refused naming the scene, the object and the file.

#include <boost/test/unit_test.hpp>

#include <fstream>

#include "penumbra/base/input_error.h"
#include "penumbra/scene/load_scene.h"
#include "snap_grid.h"
#include "support/fixtures.h"

using namespace penumbra;

namespace {

// writes a scene with one mesh object (extra keys after the file name) beside the model text.
std::filesystem::path scene_with_model(const std::string& name, const std::string& model,
                                       const std::string& keys = "") {
  const auto dir = test::scratch_dir("mesh-objects-" + name);
  std::ofstream(dir / name) << model;
  std::ofstream(dir / "scene.json") << "{\"penumbra\": 1, \"objects\": [{\"name\": \"m\", "
                                       "\"mesh\": \""
                                    << name << "\"" << keys << "}]}";
  return dir / "scene.json";
}

std::string fixture_text(const std::string& relative) {
  std::ifstream in(test::fixture(relative));
  return {std::istreambuf_iterator<char>(in), {}};
}

// The world area of a planar polygon with holes, exactly, by the shoelace formula in the
// coordinate plane the normal is largest across (the projection scales areas by |n_k| / |n|,
// the same factor for every ring, so the comparison below is of projected areas).
Exact projected_area(const std::vector<Point3>& ring, int axis) {
  Exact twice = 0;
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Point3& a = ring[k];
    const Point3& b = ring[(k + 1) % ring.size()];
    twice += a[i] * b[j] - b[i] * a[j];
  }
  return twice;
}

// A 4 x 4 square in z = 0 with a 2 x 2 hole, as the eight triangles of its ring (open).
const char* const square_with_hole =
    "o plate\n"
    "v 0 0 0\nv 4 0 0\nv 4 4 0\nv 0 4 0\nv 1 1 0\nv 3 1 0\nv 3 3 0\nv 1 3 0\n"
    "f 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";

}  // namespace

BOOST_AUTO_TEST_SUITE(mesh_objects)

BOOST_AUTO_TEST_CASE(a_non_convex_solid_becomes_pieces_receiving_on_its_outside) {
  // notched.obj: a unit cube whose top is a dent of four triangles: 9 faces, none coplanar
  // with another, each one convex piece; the dent makes the part non-convex.
  const Scene scene =
      load_scene(scene_with_model("notched.obj", fixture_text("meshes/notched.obj")));
  BOOST_TEST_REQUIRE(scene.objects.size() == 9u);
  BOOST_TEST_REQUIRE(scene.mesh_faces.size() == 9u);
  for (std::size_t k = 0; k < scene.objects.size(); ++k) {
    const Object& piece = scene.objects[k];
    BOOST_TEST(piece.name == "m#" + std::to_string(k));
    BOOST_TEST(piece.part == "m");
    BOOST_TEST(piece.solid.is_flat());
    // One side receives (the outside), the other faces into the solid.
    BOOST_TEST(piece.receives(0) != piece.receives(1));
  }
  for (std::size_t m = 0; m < scene.mesh_faces.size(); ++m) {
    const MeshFace& face = scene.mesh_faces[m];
    BOOST_TEST(face.part == "m");
    BOOST_TEST(face.index == m);
    BOOST_TEST(face.holes.empty());
    BOOST_TEST_REQUIRE(face.pieces.size() == 1u);
    // The receiving side faces out of the cube: its centre (1/2, 1/2, 1/2) is behind it.
    BOOST_TEST(face.plane.oriented_side(Point3(0.5, 0.5, 0.5)) == CGAL::ON_NEGATIVE_SIDE);
  }
}

BOOST_AUTO_TEST_CASE(an_open_face_with_a_hole_receives_on_both_sides) {
  const Scene scene = load_scene(scene_with_model("plate.obj", square_with_hole));
  BOOST_TEST_REQUIRE(scene.mesh_faces.size() == 2u);
  const MeshFace& front = scene.mesh_faces[0];
  const MeshFace& back = scene.mesh_faces[1];
  BOOST_TEST(front.part == "m");
  BOOST_TEST((front.index == 0 && back.index == 1));
  BOOST_TEST((front.plane.opposite() == back.plane));
  BOOST_TEST_REQUIRE((front.holes.size() == 1 && back.holes.size() == 1));
  // 16 - 4 = 12 square metres on either side; the pieces' areas add up to it.
  const int axis = 2;
  const Exact up = CGAL::sign(front.plane.c()) > 0 ? 1 : -1;
  BOOST_TEST((up * (projected_area(front.outer, axis) + projected_area(front.holes[0], axis)) ==
              Exact(24)));
  Exact pieces = 0;
  for (const auto& [object, face] : front.pieces) {
    BOOST_TEST(scene.objects[object].receives(0));
    BOOST_TEST(scene.objects[object].receives(1));
    pieces += up * projected_area(scene.objects[object].solid.faces()[face].vertices, axis);
  }
  BOOST_TEST(pieces == Exact(24));
  BOOST_TEST(front.pieces.size() == back.pieces.size());
  BOOST_TEST(front.pieces.size() >= 4u);  // the four reflex corners of the hole
}

BOOST_AUTO_TEST_CASE(placement_keys_move_the_model_exactly) {
  // chair.obj's seat spans x, y in [0, 0.45], z in [0.42, 0.47]. Scale 2, then Y-up turns
  // (x, y, z) to (x, -z, y), then the transform moves x by 5: the seat's smallest vertex
  // (lexicographic) is (5, -0.94, 0) on the snap grid (2 x 0.47f rounded to 2^-20 m).
  const Scene scene = load_scene(scene_with_model(
      "chair.obj", fixture_text("meshes/chair.obj"),
      ", \"scale\": 2, \"up\": \"y\", \"transform\": [1,0,0,5, 0,1,0,0, 0,0,1,0, 0,0,0,1]"));
  const Object* seat = scene.find_object("m/seat");
  BOOST_TEST_REQUIRE(seat);
  BOOST_TEST((seat->solid.vertices().front() == Point3(5, -test::on_default_grid(2.0 * 0.47f), 0)));
  BOOST_TEST((seat->solid.vertices().back() == Point3(5 + test::on_default_grid(2.0 * 0.45f),
                                                      -test::on_default_grid(2.0 * 0.42f),
                                                      test::on_default_grid(2.0 * 0.45f))));
}

BOOST_AUTO_TEST_CASE(bad_models_name_the_scene_the_object_and_the_file) {
  const auto error = [](const std::filesystem::path& scene) -> std::string {
    try {
      load_scene(scene);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  };
  const auto empty = scene_with_model("empty.obj", "v 0 0 0\nv 1 0 0\n");
  BOOST_TEST(error(empty).find("objects[0].mesh: ") != std::string::npos, error(empty));
  BOOST_TEST(error(empty).find("empty.obj") != std::string::npos, error(empty));
  const auto nan = scene_with_model("nan.obj", "o bad\nv nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  BOOST_TEST(error(nan).find("nan.obj: part bad: mesh 0, vertex 0: a coordinate is not finite") !=
                 std::string::npos,
             error(nan));
  const auto sliver = scene_with_model("sliver.obj", "o s\nv 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
  BOOST_TEST(error(sliver).find("part s: every face has fewer than 3") != std::string::npos,
             error(sliver));
  const auto format = scene_with_model("model.xyz", "1 2 3\n");
  BOOST_TEST(error(format).find("unsupported model format") != std::string::npos, error(format));
}

BOOST_AUTO_TEST_SUITE_END()
