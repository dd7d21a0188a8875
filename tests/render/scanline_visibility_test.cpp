// The scanline visibility pass against a ray cast written here: every pixel's ray is
// intersected with every face plane in double precision and kept when the hit lies
// inside the (convex) face; the nearest hit wins. Pixels where the ray cast itself is
// ambiguous (a hit within 1e-9 of a face's edge, or two objects within 1e-9 in depth)
// are not compared.

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <optional>

#include "penumbra/base/numbers.h"
#include "penumbra/render/scanline_visibility.h"
#include "penumbra/scene/load_scene.h"
#include "support/fixtures.h"

using penumbra::pi;

namespace {

using penumbra::Scene;
using penumbra::Vec3d;
using penumbra::test::fixture;

using namespace penumbra::vector_ops;

struct Hit {
  long object = -1;
  int face = -1;
  double t = INFINITY;
  bool ambiguous = false;
};

// casts the ray eye + t direction against every face of scene (DESIGN.md camera).
Hit cast(const Scene& scene, const Vec3d& eye, const Vec3d& direction) {
  Hit best;
  double second_t = INFINITY;  // nearest hit of another object
  bool near_edge = false;
  for (std::size_t object = 0; object < scene.objects.size(); ++object) {
    const auto& faces = scene.objects[object].solid.faces();
    for (std::size_t face = 0; face < faces.size(); ++face) {
      std::vector<Vec3d> vertices;
      for (const auto& vertex : faces[face].vertices)
        vertices.push_back(penumbra::to_double(vertex));
      Vec3d normal = normalized(cross(vertices[1] - vertices[0], vertices[2] - vertices[0]));
      const double denominator = dot(normal, direction);
      if (!(denominator < 0)) continue;  // back face or edge-on
      const double t = dot(normal, vertices[0] - eye) / denominator;
      if (!(t > 0)) continue;
      const Vec3d p = eye + t * direction;
      // inside the convex face: left of every edge (counter-clockwise seen from outside)
      double margin = INFINITY;
      for (std::size_t k = 0; k < vertices.size(); ++k) {
        const Vec3d edge = vertices[(k + 1) % vertices.size()] - vertices[k];
        margin = std::min(margin, dot(cross(normalized(edge), p - vertices[k]), normal));
      }
      if (margin < -1e-9) continue;
      const bool edge_hit = margin < 1e-9;
      if (t < best.t) {
        if (best.object != static_cast<long>(object)) second_t = best.t;
        best.object = static_cast<long>(object);
        best.face = static_cast<int>(face);
        best.t = t;
        near_edge = edge_hit;
      } else if (static_cast<long>(object) != best.object) {
        second_t = std::min(second_t, t);
      } else if (std::abs(t - best.t) < 1e-9 * t) {
        near_edge = true;
      }
    }
  }
  best.ambiguous = near_edge || second_t - best.t < 1e-9 * best.t;
  return best;
}

// compares the scanline map of a scene's camera (optionally resized) with the ray cast.
void compare_with_ray_cast(const Scene& scene, int width, int height, std::size_t& compared) {
  penumbra::Camera camera = *scene.camera;
  camera.width = width;
  camera.height = height;
  const auto map = penumbra::render::scanline_visibility(scene, camera);
  // the camera of DESIGN.md, derived here again
  const Vec3d forward = normalized(camera.target - camera.eye);
  const Vec3d right = normalized(cross(forward, camera.up));
  const Vec3d up = cross(right, forward);
  const double half_height = std::tan(camera.fov_deg * pi / 360);
  const double half_width = half_height * width / height;
  std::size_t mismatches = 0, ambiguous = 0;
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const double across = (2 * (i + 0.5) / width - 1) * half_width;
      const double down = (1 - 2 * (j + 0.5) / height) * half_height;
      const Vec3d direction = forward + (across * right + down * up);
      const Hit hit = cast(scene, camera.eye, direction);
      if (hit.ambiguous) {
        ++ambiguous;
        continue;
      }
      ++compared;
      const std::size_t pixel = map.index(i, j);
      if (map.objects[pixel] != hit.object || map.faces[pixel] != hit.face) {
        if (++mismatches <= 5)
          BOOST_TEST_MESSAGE("pixel (" << i << ", " << j << "): scanline " << map.objects[pixel]
                                       << "/" << map.faces[pixel] << ", ray cast " << hit.object
                                       << "/" << hit.face);
      }
    }
  BOOST_TEST_MESSAGE(scene.file.filename().string()
                     << ": " << compared << " pixels compared, " << ambiguous << " ambiguous");
  BOOST_TEST(mismatches == 0u);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(scanline_visibility)

BOOST_AUTO_TEST_CASE(default_scene_matches_a_ray_cast_on_every_pixel) {
  const Scene scene = penumbra::load_scene(fixture("scenes/office.json"));
  std::size_t compared = 0;
  compare_with_ray_cast(scene, 320, 240, compared);
  BOOST_TEST(compared > 320u * 240u * 99 / 100);
}

BOOST_AUTO_TEST_CASE(figure_11_scenes_match_a_ray_cast) {
  for (const char* name : {"scenes/render-interior.json", "scenes/render-outdoor.json",
                           "scenes/render-room-linear.json", "scenes/render-shadow-edge.json"}) {
    const Scene scene = penumbra::load_scene(fixture(name));
    std::size_t compared = 0;
    compare_with_ray_cast(scene, 160, 120, compared);
    BOOST_TEST(compared > 160u * 120u * 98 / 100, name);
  }
}

BOOST_AUTO_TEST_CASE(camera_inside_the_scene_sees_faces_passing_behind_it) {
  // the eye stands inside the room, 0.3 m above the floor: the floor and walls pass
  // behind it, so their scan segments are clipped in front of the eye.
  Scene scene = penumbra::load_scene(fixture("scenes/office.json"));
  scene.camera->eye = {3.0, 3.6, 0.3};
  scene.camera->target = {0.5, 0.2, 1.2};
  std::size_t compared = 0;
  compare_with_ray_cast(scene, 200, 150, compared);
  BOOST_TEST(compared > 0u);
}

BOOST_AUTO_TEST_CASE(plate_hides_the_floor_where_the_perspective_says) {
  // render-shadow-edge: eye (0,0,10) looking down, fov 90, 200 x 200: image x = 100 + 100 X/depth.
  // The plate's edge X = 0.5 at depth 9 lands at x = 105.56: pixel 105 (centre 105.5) sees the
  // plate, pixel 106 (centre 106.5) the floor.
  const Scene scene = penumbra::load_scene(fixture("scenes/render-shadow-edge.json"));
  const auto map = penumbra::render::scanline_visibility(scene, *scene.camera);
  const long floor = 0, plate = 1;  // objects in file order
  BOOST_TEST(scene.objects[0].name == "floor");
  BOOST_TEST(map.objects[map.index(105, 100)] == plate);
  BOOST_TEST(map.objects[map.index(106, 100)] == floor);
  BOOST_TEST(map.objects[map.index(94, 100)] == plate);  // X = -0.5: x = 94.44
  BOOST_TEST(map.objects[map.index(93, 100)] == floor);
}

BOOST_AUTO_TEST_SUITE_END()
