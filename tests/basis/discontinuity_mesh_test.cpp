// Discontinuity meshing (issue #18; docs/basis.md, "Discontinuity meshing"): the relit image's
// luminance jumps at the exact shadow edge's projection, within one pixel, where the uniform
// patch grid ramps across patches; and the mesh's pieces never straddle a shadow edge.

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <map>
#include <set>

#include "penumbra/basis/discontinuity_mesh.h"
#include "penumbra/basis/patch_mesh.h"
#include "penumbra/scene/load_scene.h"
#include "support/fixtures.h"

using penumbra::test::fixture;
using penumbra::test::run_penumbra;
using penumbra::test::scratch_dir;

namespace {

// the linear value of an 8-bit sRGB value (IEC 61966-2-1).
double linear(int byte) {
  const double v = byte / 255.0;
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

// relights render-shadow-edge.json's basis (the sun alone) with exposure 1e-4 and returns
// the linear green values of row 100, pixels 95 to 129.
std::vector<double> relit_row(const std::string& name, const std::string& options) {
  const auto dir = scratch_dir("discontinuity-" + name);
  const std::string pbl = (dir / "edge.pbl").string(), png = (dir / "edge.png").string();
  auto result = run_penumbra("basis " + fixture("scenes/render-shadow-edge.json").string() +
                             " -o " + pbl + options);
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  result = run_penumbra("relight " + pbl + " -o " + png + " --exposure 1e-4");
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  const auto image = penumbra::test::read_png(png);
  BOOST_TEST_REQUIRE((image.width == 200u && image.height == 200u));
  std::vector<double> row;
  for (unsigned i = 95; i < 130; ++i) row.push_back(linear(image.at(i, 100)[1]));
  return row;
}

// returns the pixels (95 + k) whose value lies strictly between 10 % and 90 % of the way from
// the shadow's value (pixel 112) to the lit value (pixel 100).
std::set<unsigned> ramp(const std::vector<double>& row) {
  const double lit = row[100 - 95], dark = row[112 - 95];
  std::set<unsigned> between;
  for (std::size_t k = 0; k < row.size(); ++k) {
    const double s = (row[k] - dark) / (lit - dark);
    if (s > 0.1 && s < 0.9) between.insert(static_cast<unsigned>(95 + k));
  }
  return between;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(discontinuity_mesh)

BOOST_AUTO_TEST_CASE(the_relit_shadow_edge_jumps_within_one_pixel) {
  // render-shadow-edge.json: a plate [-0.5, 0.5]^2 at z = 1 over the floor z = 0, the sun along
  // (1.23, 0, -1): the shadow is x in [0.73, 1.73], |y| <= 0.5. The camera 10 m above with a
  // 90 degree view over 200 pixels: pixel i's centre sees x = (i + 0.5 - 100) / 10, so the
  // centres of pixels 107 to 116 lie in the shadow and those of 106 and 117 outside; row 100
  // sees y = -0.05, inside the shadow's span in y.
  const std::vector<double> row = relit_row("on", "");
  const double lit = row[100 - 95], dark = row[112 - 95];
  BOOST_TEST_REQUIRE(lit > 4 * dark);
  const double half = (lit + dark) / 2;
  BOOST_TEST(row[106 - 95] > half);
  BOOST_TEST(row[107 - 95] < half);
  BOOST_TEST(row[116 - 95] < half);
  BOOST_TEST(row[117 - 95] > half);
  // at most the one pixel each edge crosses (its centre on one side) is between the plateaus:
  // none here, as every pixel centre is a clear 0.03 m or more from the edge
  BOOST_TEST(ramp(row).empty());

  // the uniform grid (0.5 m patches, --no-discontinuity) ramps over several pixels
  const std::vector<double> uniform = relit_row("off", " --no-discontinuity");
  BOOST_TEST_MESSAGE("pixels between the plateaus: " << ramp(row).size() << " cut along the edges, "
                                                     << ramp(uniform).size() << " uniform");
  BOOST_TEST(ramp(uniform).size() >= 4u);
}

BOOST_AUTO_TEST_CASE(no_patch_straddles_a_shadow_edge) {
  // Every patch of the floor's top face lies on one side of the sun's exact shadow: its
  // vertices are all inside the closed shadow rectangle [0.73, 1.73] x [-0.5, 0.5] or all
  // outside its interior (tolerance 1e-9 m for the rounding of the cut points); and a
  // vertex on the edge is not shared between the two sides.
  const penumbra::Scene scene =
      penumbra::load_scene(fixture("scenes/render-shadow-edge.json").string());
  const auto mesh =
      penumbra::basis::PatchMesh::subdivide(scene, 0.5, penumbra::basis::shadow_breaks(scene));
  const double e = 1e-9;
  std::size_t inside = 0, outside = 0;
  std::map<std::uint32_t, std::set<bool>> sides;
  for (const auto& patch : mesh.patches()) {
    if (scene.objects[patch.object].name != "floor" || patch.normal[2] < 0.5) continue;
    bool any_in = false, any_out = false;
    for (std::uint32_t v : patch.vertices) {
      const auto& p = mesh.vertices()[v];
      any_in = any_in || (p[0] > 0.73 + e && p[0] < 1.73 - e && std::abs(p[1]) < 0.5 - e);
      any_out = any_out || (p[0] < 0.73 - e || p[0] > 1.73 + e || std::abs(p[1]) > 0.5 + e);
    }
    BOOST_TEST(!(any_in && any_out));
    const bool in_shadow =
        patch.centre[0] > 0.73 && patch.centre[0] < 1.73 && std::abs(patch.centre[1]) < 0.5;
    (in_shadow ? inside : outside) += 1;
    for (std::uint32_t v : patch.vertices) sides[v].insert(in_shadow);
  }
  BOOST_TEST(inside >= 4u);  // the 1 x 1 m shadow over 0.5 m cells: at least four pieces
  BOOST_TEST(outside > 100u);
  for (const auto& [vertex, on] : sides) BOOST_TEST(on.size() == 1u, "vertex " << vertex);
}

BOOST_AUTO_TEST_SUITE_END()
