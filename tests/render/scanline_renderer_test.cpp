// Shading along spans (Nishita 1985 section 3.3): exact illuminance at every pixel at
// interval 1, bounded interpolation error at intervals 3 and 5, and a hand-derived
// shadow edge landing on the right pixel at every interval.

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>

#include "../shadow/solids.h"
#include "penumbra/base/numbers.h"
#include "penumbra/illuminance/scene_illuminance.h"
#include "penumbra/render/scanline_renderer.h"
#include "penumbra/scene/load_scene.h"
#include "penumbra/shadow/exact_umbra.h"
#include "penumbra/shadow/shadow_map.h"
#include "support/fixtures.h"

using penumbra::pi;

namespace {

using penumbra::Scene;
using penumbra::Vec3d;
using penumbra::test::fixture;
using namespace penumbra::render;

using namespace penumbra::vector_ops;

Scene resized(const char* name, int width, int height) {
  Scene scene = penumbra::load_scene(fixture(name));
  scene.camera->width = width;
  scene.camera->height = height;
  return scene;
}

// The error of an interpolated image against the exact one, relative to the largest E.
struct InterpolationError {
  double max = 0;
  double mean = 0;
};

InterpolationError interpolation_error(const RenderedImage& exact, const RenderedImage& coarse) {
  const double top = *std::max_element(exact.illuminance.begin(), exact.illuminance.end());
  InterpolationError error;
  std::size_t seen = 0;
  for (std::size_t pixel = 0; pixel < exact.illuminance.size(); ++pixel) {
    if (exact.visibility.objects[pixel] < 0) continue;
    const double difference = std::abs(coarse.illuminance[pixel] - exact.illuminance[pixel]) / top;
    error.max = std::max(error.max, difference);
    error.mean += difference;
    ++seen;
  }
  error.mean /= static_cast<double>(seen);
  return error;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(scanline_renderer)

BOOST_AUTO_TEST_CASE(interval_one_equals_the_solver_at_the_visible_point) {
  // the visible point comes from a ray-plane intersection computed here, on the face the
  // pixel shows, lifted by surface_lift (1 + max |coordinate|) as the renderer documents.
  for (const char* name : {"scenes/office.json", "scenes/render-room-linear.json"}) {
    const Scene scene = resized(name, 96, 72);
    const ScanlineRenderer renderer(scene, *scene.camera);
    RenderOptions options;
    options.interval = 1;
    const RenderedImage image = renderer.render(options);
    const penumbra::illuminance::IlluminanceSolver solver(scene);
    const penumbra::Camera& camera = *scene.camera;
    const Vec3d forward = normalized(camera.target - camera.eye);
    const Vec3d right = normalized(cross(forward, camera.up));
    const Vec3d up = cross(right, forward);
    const double half_height = std::tan(camera.fov_deg * pi / 360);
    const double half_width = half_height * camera.width / camera.height;
    std::size_t checked = 0, lit = 0, wrong = 0;
    for (int j = 0; j < image.height; ++j)
      for (int i = 0; i < image.width; ++i) {
        const std::size_t pixel = image.index(i, j);
        const long object = image.visibility.objects[pixel];
        if (object < 0) {
          BOOST_TEST(image.illuminance[pixel] == 0.0);
          continue;
        }
        const auto& face = scene.objects[object].solid.faces()[image.visibility.faces[pixel]];
        const Vec3d a = penumbra::to_double(face.vertices[0]);
        const Vec3d normal = normalized(cross(penumbra::to_double(face.vertices[1]) - a,
                                              penumbra::to_double(face.vertices[2]) - a));
        const Vec3d direction =
            forward + (((2 * (i + 0.5) / camera.width - 1) * half_width) * right +
                       ((1 - 2 * (j + 0.5) / camera.height) * half_height) * up);
        const double t = dot(normal, a - camera.eye) / dot(normal, direction);
        Vec3d p = camera.eye + t * direction;
        const double magnitude = std::max({std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
        p = p + (surface_lift * (1 + magnitude)) * normal;
        const double expected = solver.at(p, normal).total;
        ++checked;
        if (expected > 0) ++lit;
        if (std::abs(image.illuminance[pixel] - expected) > 1e-9 * std::max(expected, 1e-3)) {
          if (++wrong <= 5)
            BOOST_TEST_MESSAGE(name << " pixel (" << i << ", " << j
                                    << "): " << image.illuminance[pixel] << " lx, solver "
                                    << expected << " lx");
        }
      }
    BOOST_TEST_MESSAGE(name << ": " << checked << " pixels, " << lit << " lit, " << wrong
                            << " differ");
    BOOST_TEST(wrong == 0u, name);
    BOOST_TEST(lit > checked / 2, name);
    BOOST_TEST(image.evaluations == checked);
  }
}

BOOST_AUTO_TEST_CASE(interpolation_error_at_intervals_three_and_five_is_bounded) {
  for (const char* name :
       {"scenes/office.json", "scenes/render-interior.json", "scenes/render-room-linear.json"}) {
    const Scene scene = resized(name, 240, 180);
    const ScanlineRenderer renderer(scene, *scene.camera);
    RenderOptions options;
    options.interval = 1;
    const RenderedImage exact = renderer.render(options);
    for (int interval : {3, 5}) {
      options.interval = interval;
      const RenderedImage coarse = renderer.render(options);
      const InterpolationError error = interpolation_error(exact, coarse);
      BOOST_TEST_MESSAGE(name << " interval " << interval << ": max error " << error.max
                              << ", mean " << error.mean << " of the largest E; evaluations "
                              << coarse.evaluations << " of " << exact.evaluations);
      // shadow edges are sampled on both sides, so what is left is the curvature of E
      // between samples: measured at 240 x 180, max 0.029 (render-room-linear, interval 5),
      // mean at most 1.9e-4 (docs/render.md)
      BOOST_TEST(error.max < 0.05, name << " interval " << interval);
      BOOST_TEST(error.mean < 0.002, name << " interval " << interval);
      BOOST_TEST(coarse.evaluations < exact.evaluations / 2);
    }
  }
}

BOOST_AUTO_TEST_CASE(shadow_edges_land_on_the_derived_pixels) {
  // render-shadow-edge: sun travelling (1.23, 0, -1), a plate over [-0.5, 0.5]^2 at z = 1,
  // the floor at z = 0. The plate's shadow on the floor is the plate shifted by 1.23 in x:
  // X in [0.73, 1.73]. The camera at (0, 0, 10) looks straight down (right = +x, up = +y),
  // fov 90 deg, 200 x 200, so a floor point X lies at image x = 100 + 100 X / 10.
  const Scene scene = penumbra::load_scene(fixture("scenes/render-shadow-edge.json"));
  const ScanlineRenderer renderer(scene, *scene.camera);
  const double lit_lux = 80000 / std::sqrt(1 + 1.23 * 1.23);  // E_n cos(alpha)
  const auto image_x = [](double world_x) { return 100 + 10 * world_x; };
  // the pixel whose centre is the last one left of each edge
  const int before_left_edge = static_cast<int>(std::floor(image_x(0.73) - 0.5));   // 106
  const int before_right_edge = static_cast<int>(std::floor(image_x(1.73) - 0.5));  // 116
  BOOST_TEST(before_left_edge == 106);
  BOOST_TEST(before_right_edge == 116);
  for (int interval : {1, 3, 5, 7}) {
    RenderOptions options;
    options.interval = interval;
    const RenderedImage image = renderer.render(options);
    for (int j : {96, 100, 103}) {
      const auto e = [&](int i) { return image.illuminance[image.index(i, j)]; };
      BOOST_TEST(e(before_left_edge) == lit_lux, boost::test_tools::tolerance(1e-12));
      for (int i = before_left_edge + 1; i <= before_right_edge; ++i)
        BOOST_TEST(e(i) == 0.0, "interval " << interval << " pixel " << i);
      BOOST_TEST(e(before_right_edge + 1) == lit_lux, boost::test_tools::tolerance(1e-12));
      // the floor ends at X = 4 (x = 140): well inside it, past the shadow, still lit
      BOOST_TEST(e(135) == lit_lux, boost::test_tools::tolerance(1e-12));
    }
  }
}

// Issue #17: with joint umbrae the exact umbra's curved edges bound the interpolation. The
// two boards of linear-joint-umbra hide the tube together beyond the upright (y < -1); a
// camera at the floor's side, below the shelf, sees that floor. At interval 7 every pixel
// whose visible point lies in the joint part of the umbra (in the exact curved umbra and
// out of the straight one, decided exactly at the point) is exactly 0, as the solver gives
// there; without the curved edges the interpolation bridges them and some of those pixels
// are not 0.
BOOST_AUTO_TEST_CASE(joint_umbrae_bound_the_interpolation_along_their_conics) {
  Scene scene = penumbra::load_scene(fixture("scenes/linear-joint-umbra.json"));
  scene.camera = penumbra::Camera{{-5.5, -3.5, 1.5}, {0, -3, 0}, {0, 0, 1}, 70, 160, 120};
  penumbra::ShadowOptions options;
  options.joint_umbrae = true;
  const penumbra::ShadowResult shadows = penumbra::compute_shadows(scene, options);
  const penumbra::FaceShadow* floor = nullptr;
  const penumbra::Face* face = nullptr;
  for (std::size_t r = 0; r < shadows.receivers.size(); ++r)
    if (shadows.lights[0].faces[r].curved) {
      floor = &shadows.lights[0].faces[r];
      const auto& receiver = shadows.receivers[r];
      face = &scene.objects[receiver.object].solid.faces()[receiver.face];
    }
  BOOST_TEST_REQUIRE(floor != nullptr);
  RenderOptions coarse;
  coarse.interval = 7;
  const RenderedImage with = ScanlineRenderer(scene, *scene.camera, true, true).render(coarse);
  const RenderedImage without = ScanlineRenderer(scene, *scene.camera, true, false).render(coarse);
  const ScanlineRenderer renderer(scene, *scene.camera);
  int joint = 0, bridged = 0;
  for (int j = 0; j < with.height; ++j)
    for (int i = 0; i < with.width; ++i) {
      const auto seen = renderer.visible_point(i, j);
      if (!seen || (*seen)[1][2] < 0.5) continue;  // the floor's top only
      const penumbra::Point2 q = face->frame.to_frame(penumbra::to_exact((*seen)[0]));
      if (!floor->curved->contains(q) ||
          penumbra::test::side_of(floor->umbra, q) != CGAL::ON_UNBOUNDED_SIDE)
        continue;
      ++joint;
      BOOST_TEST(with.illuminance[with.index(i, j)] == 0.0, "pixel " << i << " " << j);
      bridged += without.illuminance[without.index(i, j)] > 0;
    }
  BOOST_TEST(joint >= 50);
  BOOST_TEST(bridged > 0);
  BOOST_TEST_MESSAGE(joint << " pixels in the joint umbra, " << bridged
                           << " bridged without its curved edges");
}

BOOST_AUTO_TEST_CASE(luminance_is_reflectance_times_illuminance_over_pi) {
  const Scene scene = resized("scenes/office.json", 64, 48);
  const RenderedImage image = render_scanline(scene, *scene.camera);
  for (std::size_t pixel = 0; pixel < image.luminance.size(); ++pixel) {
    const long object = image.visibility.objects[pixel];
    if (object < 0) continue;
    const penumbra::Material& material = scene.materials[scene.objects[object].material];
    BOOST_TEST(image.luminance[pixel] == material.reflectance * image.illuminance[pixel] / pi,
               boost::test_tools::tolerance(1e-12));
    BOOST_TEST(image.radiance[pixel][0] == image.luminance[pixel] * material.color[0],
               boost::test_tools::tolerance(1e-12));
  }
}

BOOST_AUTO_TEST_SUITE_END()
