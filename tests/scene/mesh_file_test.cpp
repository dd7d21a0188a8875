// The OBJ and OFF readers and the exact convexity check of mesh components.

#include <boost/test/unit_test.hpp>

#include <fstream>

#include "penumbra/base/input_error.h"
#include "penumbra/scene/mesh_file.h"
#include "support/fixtures.h"

using namespace penumbra;

namespace {

std::filesystem::path write_file(const std::string& name, const std::string& text) {
  const auto path = test::scratch_dir("mesh-" + name) / name;
  std::ofstream(path) << text;
  return path;
}

// returns the location of the InputError reading (and splitting) the mesh raises.
std::string error_location(const std::filesystem::path& path) {
  try {
    convex_parts(read_mesh(path));
  } catch (const InputError& e) {
    return e.location() + ": " + e.message();
  }
  return "no error";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mesh_file)

BOOST_AUTO_TEST_CASE(obj_with_two_components_gives_two_convex_parts) {
  const MeshFile mesh = read_mesh(test::fixture("meshes/chair.obj"));
  BOOST_TEST(mesh.vertices.size() == 16u);
  BOOST_TEST(mesh.faces.size() == 12u);
  BOOST_TEST(mesh.face_lines.front() == 12);
  const auto parts = convex_parts(mesh);
  BOOST_TEST_REQUIRE(parts.size() == 2u);
  for (const auto& part : parts) {
    BOOST_TEST(part.vertices().size() == 8u);
    BOOST_TEST(part.faces().size() == 6u);
  }
}

BOOST_AUTO_TEST_CASE(off_tetrahedron) {
  const MeshFile mesh = read_mesh(test::fixture("meshes/tetra.off"));
  BOOST_TEST(mesh.vertices.size() == 4u);
  BOOST_TEST((mesh.faces[0] == std::vector<int>{0, 2, 1}));
  const auto parts = convex_parts(mesh);
  BOOST_TEST_REQUIRE(parts.size() == 1u);
  BOOST_TEST(parts[0].faces().size() == 4u);
}

BOOST_AUTO_TEST_CASE(obj_corner_forms_and_negative_indices) {
  // v/vt/vn corners, v//vn corners and negative (relative) indices all name vertices.
  const auto path = write_file("forms.obj",
                               "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvn 0 0 1\n"
                               "f 1/1/1 3/1/1 2/1/1\nf 1//1 2//1 4//1\nf -4 -1 -2\nf 2 3 4\n");
  const MeshFile mesh = read_mesh(path);
  BOOST_TEST((mesh.faces[2] == std::vector<int>{0, 3, 2}));
  BOOST_TEST(convex_parts(mesh).size() == 1u);
}

BOOST_AUTO_TEST_CASE(off_counts_on_the_header_line) {
  const auto path = write_file("inline.off",
                               "OFF 4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                               "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  BOOST_TEST(read_mesh(path).faces.size() == 4u);
}

BOOST_AUTO_TEST_CASE(bad_meshes_name_the_line) {
  BOOST_TEST(error_location(test::fixture("meshes/notched.obj")) ==
             "line 16: the mesh component of this face is not convex (the face is not on its "
             "convex hull)");
  BOOST_TEST(error_location(write_file("bad.obj", "v 0 0 0\nv 1 x 0\n")) ==
             "line 2: expected a number for y coordinate, found \"x\"");
  BOOST_TEST(error_location(write_file("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n")) ==
             "line 4: vertex index 7 is out of range");
  BOOST_TEST(error_location(write_file("short.off", "OFF\n4 4 6\n0 0 0\n1 0 0\n")) ==
             "line 4: the file ends before vertex 2");
  BOOST_TEST(error_location(write_file("flat.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"))
                 .find("line 4: the component of this face is flat") == 0);
  BOOST_TEST(error_location(write_file("nan.off", "OFF\n1 0 0\nnan 0 0\n")) ==
             "line 3: the x coordinate is not finite");
  BOOST_TEST(error_location(write_file("mesh.stl", "solid")) ==
             ": unknown mesh format \".stl\" (expected .obj or .off)");
}

BOOST_AUTO_TEST_SUITE_END()
