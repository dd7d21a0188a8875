// Indirect light in the scanline renderer (issue #18; docs/render.md, "Indirect light"): the
// rendered luminance of a surface no lamp sees equals rho E_indirect / pi of the radiosity
// solve within the interpolation bound, the integrating cube's mean holds through the
// interpolated field, and the direct part is the exact one. Also the tone curve and the
// colour scale of false colour and belts.

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <set>

#include "basis/radiosity_scenes.h"
#include "penumbra/base/colour_scale.h"
#include "penumbra/base/numbers.h"
#include "penumbra/base/tone_map.h"
#include "penumbra/basis/indirect_light.h"
#include "penumbra/raytrace/ray_tracer.h"
#include "penumbra/render/isolux_belts.h"
#include "penumbra/render/scanline_renderer.h"
#include "penumbra/scene/camera_frame.h"

using namespace penumbra;
using namespace penumbra::vector_ops;

namespace {

// a closed 4 m room of reflectance 0.5 under a downlight 0.5 m below the ceiling whose
// intensity cos(gamma) stops at the horizontal (Dobashi eq. 11 with spread 90 degrees): the
// ceiling and the walls' top half metre get no direct light. The camera looks up at the
// ceiling.
Scene downlit_room() {
  return test::closed_room(
      4, 0.5,
      R"({"name": "down", "point": [2, 2, 3.5], "axis": [0, 0, -1],
          "lid": {"cos_power": 1, "spread_deg": 90, "candela": 1000}})",
      R"(, "camera": {"eye": [2, 0.6, 1.5], "target": [2, 2.4, 4], "up": [0, 0, 1],
                     "fov_deg": 70, "width": 80, "height": 60})");
}

basis::BasisOptions radiosity_options() {
  basis::BasisOptions options;
  options.patch_size = 0.5;
  options.form_factors.method = basis::FormFactorMethod::rays;
  options.form_factors.rays = 1024;
  options.radiosity.tolerance = 1e-9;
  return options;
}

// the indirect illuminance of patch i of a solve, channel 0: E_total - E_direct.
double patch_indirect(const basis::SceneRadiosity& solved, std::size_t i) {
  const auto row = static_cast<Eigen::Index>(i);
  return solved.total(row, 0) - solved.direct_per_light.row(row).sum();
}

// whether point lies in the convex patch (counter-clockwise about its normal), boundary in.
bool patch_holds(const basis::PatchMesh& mesh, const basis::Patch& patch, const Vec3d& point) {
  const auto& ring = patch.vertices;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Vec3d& a = mesh.vertices()[ring[k]];
    const Vec3d& b = mesh.vertices()[ring[(k + 1) % ring.size()]];
    if (dot(patch.normal, cross(b - a, point - a)) < -1e-12) return false;
  }
  return true;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(indirect_light)

BOOST_AUTO_TEST_CASE(a_ceiling_no_lamp_sees_shows_rho_e_indirect_over_pi) {
  const Scene scene = downlit_room();
  // the reference: the solve read patch by patch, as `penumbra radiosity` writes it
  const basis::SceneRadiosity reference = basis::solve_scene_radiosity(scene, radiosity_options());
  const basis::IndirectLight field(basis::solve_scene_radiosity(scene, radiosity_options()));
  const render::ScanlineRenderer renderer(scene, *scene.camera);
  render::RenderOptions options;
  options.interval = 1;
  const render::RenderedImage direct_only = renderer.render(options);
  options.indirect = [&](std::size_t object, std::size_t face, const Vec3d& point) {
    return field.at(object, face, point);
  };
  const render::RenderedImage image = renderer.render(options);

  const basis::PatchMesh& mesh = reference.mesh;
  std::size_t ceiling_pixels = 0;
  for (int j = 0; j < image.height; ++j)
    for (int i = 0; i < image.width; ++i) {
      const std::size_t pixel = image.index(i, j);
      if (image.visibility.objects[pixel] != 1) continue;  // the ceiling slab
      ++ceiling_pixels;
      BOOST_TEST_CONTEXT("pixel " << i << ", " << j) {
        BOOST_TEST(direct_only.illuminance[pixel] == 0.0);  // no lamp sees it
        const Vec3d point = (*renderer.visible_point(i, j))[0];
        // the patch holding the point and every patch sharing a vertex with it
        std::set<std::uint32_t> vertices;
        for (std::size_t p = 0; p < mesh.size(); ++p) {
          const basis::Patch& patch = mesh.patches()[p];
          if (patch.object == 1 && patch.normal[2] < 0 && patch_holds(mesh, patch, point))
            vertices.insert(patch.vertices.begin(), patch.vertices.end());
        }
        BOOST_TEST_REQUIRE(!vertices.empty());
        double low = INFINITY, high = -INFINITY;
        for (std::size_t p = 0; p < mesh.size(); ++p)
          for (std::uint32_t v : mesh.patches()[p].vertices)
            if (vertices.count(v)) {
              low = std::min(low, patch_indirect(reference, p));
              high = std::max(high, patch_indirect(reference, p));
            }
        const double L = image.luminance[pixel];
        BOOST_TEST(L > 0.0);
        BOOST_TEST(L >= 0.5 * low / pi * (1 - 1e-9));
        BOOST_TEST(L <= 0.5 * high / pi * (1 + 1e-9));
        BOOST_TEST(image.indirect[pixel] == image.illuminance[pixel]);
      }
    }
  BOOST_TEST_MESSAGE("ceiling: " << ceiling_pixels << " pixels within their patches' bounds");
  BOOST_TEST(ceiling_pixels > 1000u);
}

BOOST_AUTO_TEST_CASE(the_ray_tracer_adds_the_same_indirect_light) {
  // raytrace's diffuse term with the field (ray_tracer.h, TraceOptions::indirect): a camera
  // ray through a pixel centre that meets the ceiling brings back rho E_indirect / pi at the
  // point it hits, the luminance the scanline renderer shows at the same pixel.
  const Scene scene = downlit_room();
  const basis::IndirectLight field(basis::solve_scene_radiosity(scene, radiosity_options()));
  const auto indirect = [&](std::size_t object, std::size_t face, const Vec3d& point) {
    return field.at(object, face, point);
  };
  const render::ScanlineRenderer renderer(scene, *scene.camera);
  render::RenderOptions options;
  options.interval = 1;
  options.indirect = indirect;
  const render::RenderedImage image = renderer.render(options);
  raytrace::TraceOptions trace;
  trace.max_depth = 0;
  trace.indirect = indirect;
  const raytrace::RayTracer tracer(scene, trace);
  const CameraFrame view(*scene.camera);
  std::size_t compared = 0;
  for (int j = 0; j < image.height; j += 3)
    for (int i = 0; i < image.width; i += 3) {
      if (image.visibility.objects[image.index(i, j)] != 1) continue;
      raytrace::RayCounts counts;
      const raytrace::TraceResult traced =
          tracer.trace(view.eye(), view.unit_direction(i + 0.5, j + 0.5), 1, counts);
      BOOST_TEST_REQUIRE(traced.object.has_value());
      BOOST_TEST(*traced.object == 1u);
      BOOST_TEST(traced.radiance[0] == image.luminance[image.index(i, j)],
                 boost::test_tools::tolerance(1e-6));
      ++compared;
    }
  BOOST_TEST(compared > 200u);
}

BOOST_AUTO_TEST_CASE(the_direct_part_is_the_exact_illuminance) {
  const Scene scene = downlit_room();
  const basis::IndirectLight field(basis::solve_scene_radiosity(scene, radiosity_options()));
  const render::ScanlineRenderer renderer(scene, *scene.camera);
  render::RenderOptions options;
  const render::RenderedImage direct_only = renderer.render(options);
  options.indirect = [&](std::size_t object, std::size_t face, const Vec3d& point) {
    return field.at(object, face, point);
  };
  const render::RenderedImage image = renderer.render(options);
  std::size_t lit = 0;
  for (std::size_t pixel = 0; pixel < image.illuminance.size(); ++pixel) {
    const double direct = image.illuminance[pixel] - image.indirect[pixel];
    BOOST_TEST(direct == direct_only.illuminance[pixel], boost::test_tools::tolerance(1e-12));
    if (direct_only.illuminance[pixel] > 0) ++lit;
  }
  BOOST_TEST(lit > 100u);  // the walls below the lamp's horizon are in view
}

BOOST_AUTO_TEST_CASE(the_integrating_cube_mean_holds_through_the_interpolated_field) {
  // CIE 171:2006 test case 5.8 as in tests/basis/radiosity_test.cpp: a 4 m cube, 10,000 lm
  // isotropic at its centre; the area mean of the indirect illuminance over the six inner
  // faces (S = 96 m^2) is rho Phi / (S (1 - rho)). Here it is the mean of the field the
  // renderer reads, on a 40 x 40 grid of cell centres on every inner face.
  const double flux = 10000, S = 96, rho = 0.5;
  const Scene scene = test::closed_room(4, rho,
                                        R"({"name": "bulb", "point": [2, 2, 2], "candela": )" +
                                            std::to_string(flux / (4 * pi)) + "}");
  const basis::IndirectLight field(basis::solve_scene_radiosity(scene, radiosity_options()));
  double sum = 0;
  int samples = 0;
  for (std::size_t object = 0; object < 6; ++object) {
    const auto& faces = scene.objects[object].solid.faces();
    for (std::size_t face = 0; face < faces.size(); ++face) {
      const render::FacePlane plane = render::face_plane(faces[face]);
      // the inner face: the room's centre lies on its outer side
      if (!(dot(plane.normal, Vec3d{2, 2, 2}) + plane.offset > 0)) continue;
      int axis = 0;
      for (int a = 1; a < 3; ++a)
        if (std::abs(plane.normal[a]) > std::abs(plane.normal[axis])) axis = a;
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      for (int a = 0; a < 40; ++a)
        for (int b = 0; b < 40; ++b) {
          Vec3d point{};
          point[axis] = -plane.offset / plane.normal[axis];
          point[u] = (a + 0.5) * 0.1;
          point[v] = (b + 0.5) * 0.1;
          sum += field.at(object, face, point)[0];
          ++samples;
        }
    }
  }
  BOOST_TEST(samples == 6 * 1600);
  const double expected = rho * flux / (S * (1 - rho));
  BOOST_TEST_MESSAGE("integrating cube: field mean " << sum / samples << " lx, expected "
                                                     << expected << " lx");
  BOOST_TEST(sum / samples == expected, boost::test_tools::tolerance(2e-2));
}

BOOST_AUTO_TEST_CASE(the_log_average_exposure_and_the_filmic_curve) {
  // Reinhard et al. 2002: the geometric mean of 1 and 100 cd/m^2 is 10, mapped to 0.18.
  const std::vector<Colour> values{{1, 1, 1}, {100, 100, 100}, {0, 0, 0}};
  BOOST_TEST(log_average_exposure(values) == 0.018, boost::test_tools::tolerance(1e-12));
  // the white point: rank floor(0.99 x 1) = 0 of {1, 100}, so 1, at exposure 0.5 below 1: w = 1
  BOOST_TEST(filmic_white(values, 0.5) == 1.0);
  BOOST_TEST(filmic_white({{4, 4, 4}}, 2) == 8.0);
  // T(Y) = Y (1 + Y / w^2) / (1 + Y): T(w) = 1, T(1) = (1 + 1 / w^2) / 2
  const double w = 4;
  const auto grey = [&](double y) { return to_srgb8({{y, y, y}}, 1, ToneCurve::filmic, w)[0]; };
  BOOST_TEST(grey(w) == 255);
  BOOST_TEST(grey(1) == std::lround(255 * srgb_encode((1 + 1 / (w * w)) / 2)));
  BOOST_TEST(grey(0) == 0);
  // the linear curve clips at 1
  BOOST_TEST(to_srgb8({{2, 0.5, 0}}, 1)[0] == 255);
  // hue kept: a colour's channels keep their ratios under the curve (before encoding)
  const auto bytes = to_srgb8({{0.4, 0.2, 0.1}}, 1, ToneCurve::filmic, w);
  const double y = photometric_value({0.4, 0.2, 0.1});
  const double scale = (1 + y / (w * w)) / (1 + y);
  for (int c = 0; c < 3; ++c)
    BOOST_TEST(bytes[c] == std::lround(255 * srgb_encode(scale * std::array{0.4, 0.2, 0.1}[c])));
}

BOOST_AUTO_TEST_CASE(the_colour_scale_is_logarithmic_over_a_wide_series) {
  // levels over more than a factor 20: blue at the lowest level, red at the maximum, the
  // geometric mean half-way (green, 120 degrees)
  const render::LevelScale wide = render::level_scale({100, 200, 500, 1000, 10000}, 40000);
  BOOST_TEST(wide.logarithmic);
  BOOST_TEST((wide.colour(100) == Rgb8{0, 0, 255}));
  BOOST_TEST((wide.colour(50) == Rgb8{0, 0, 255}));
  BOOST_TEST((wide.colour(40000) == Rgb8{255, 0, 0}));
  BOOST_TEST((wide.colour(2000) == Rgb8{0, 255, 0}));
  // a narrow set stays linear from 0
  const render::LevelScale narrow = render::level_scale({20, 50, 100, 200}, 200);
  BOOST_TEST(!narrow.logarithmic);
  BOOST_TEST((narrow.colour(100) == Rgb8{0, 255, 0}));
}

BOOST_AUTO_TEST_SUITE_END()
