// The distribution contract and the scene's `lid` forms: isotropic, tables, the
// closed forms of the papers, photometric files, and errors at JSON paths.

#include <boost/test/unit_test.hpp>

#include <cmath>

#include <nlohmann/json.hpp>

#include "penumbra/base/input_error.h"
#include "penumbra/base/numbers.h"
#include "penumbra/photometry/analytic_distribution.h"
#include "penumbra/photometry/distribution.h"
#include "printing.h"
#include "support/fixtures.h"

using penumbra::pi;

namespace tt = boost::test_tools;
using namespace penumbra::photometry;
using nlohmann::json;

namespace {

const SpecContext kContext{"scene.json", "lights[1].lid", penumbra::test::fixture("scenes")};

std::shared_ptr<const Distribution> make(const char* text) {
  return make_distribution(json::parse(text), kContext);
}

std::string error_of(const char* text) {
  try {
    make(text);
  } catch (const penumbra::InputError& e) {
    return e.location() + ": " + e.message();
  }
  return "no error";
}

// Independent flux by Simpson's rule in gamma for axial distributions.
double simpson_flux(const Distribution& lid) {
  constexpr int n = 20000;
  const double h = pi / n;
  double total = 0;
  for (int i = 0; i <= n; ++i) {
    const double g = i * h;
    total += (i == 0 || i == n ? 1 : i % 2 ? 4 : 2) * lid.intensity(g, 0) * std::sin(g);
  }
  return 2 * pi * total * h / 3;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(distribution)

BOOST_AUTO_TEST_CASE(isotropic_is_the_same_in_every_direction) {
  const auto lid = make_isotropic(120);
  for (double gamma : {0.0, 0.5, 1.5, 3.0})
    for (double c : {0.0, 1.0, 4.0}) BOOST_TEST(lid->intensity(gamma, c) == 120.0);
  BOOST_TEST(lid->max_intensity() == 120.0);
  BOOST_TEST(lid->flux() == 4 * pi * 120, tt::tolerance(1e-15));
  BOOST_TEST(make(R"({"candela": 50, "multiplier": 2})")->intensity(1, 1) == 100.0);
}

BOOST_AUTO_TEST_CASE(cos_power_is_dobashi_eq_11) {
  const auto lid = make(R"({"cos_power": 10, "spread_deg": 60, "candela": 800})");
  BOOST_TEST(lid->intensity(radians(30), 0) == 800 * std::pow(std::cos(pi / 6), 10),
             tt::tolerance(1e-14));
  BOOST_TEST(lid->intensity(radians(61), 0) == 0.0);
  // Flux: 2 pi I0 (1 - cos^11 60deg) / 11 = 2 pi 800 (1 - 2^-11) / 11, and by Simpson.
  BOOST_TEST(lid->flux() == 2 * pi * 800 * (1 - std::pow(0.5, 11)) / 11, tt::tolerance(1e-12));
  BOOST_TEST(lid->flux() == simpson_flux(*lid), tt::tolerance(1e-4));
  BOOST_TEST(lid->symmetry() == Symmetry::axial);
  // spread_deg defaults to 90, the paper's example.
  BOOST_TEST(make(R"({"cos_power": 1, "candela": 10})")->flux() == 10 * pi, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(cardioid_is_nishita_one_plus_cos_over_two) {
  const auto lid = make(R"({"cardioid": true, "candela": 100})");
  BOOST_TEST(lid->intensity(0, 0) == 100.0);
  BOOST_TEST(lid->intensity(pi / 2, 0) == 50.0, tt::tolerance(1e-14));
  BOOST_TEST(lid->intensity(radians(120), 0) == 25.0, tt::tolerance(1e-13));
  BOOST_TEST(lid->flux() == 2 * pi * 100, tt::tolerance(1e-15));
  BOOST_TEST(lid->flux() == simpson_flux(*lid), tt::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(tables_and_files_load_from_specs) {
  const auto table =
      make(R"({"table_deg": [0, 90, 180], "candela": [100, 0, 0], "multiplier": 2})");
  BOOST_TEST(table->intensity(radians(45), 0) == 100.0, tt::tolerance(1e-12));
  const auto cosine =
      make(R"({"table_deg": [0, 90, 180], "candela": [100, 0, 0], "interpolation": "cosine"})");
  BOOST_TEST(cosine->intensity(radians(60), 0) == 50.0, tt::tolerance(1e-12));  // t = 1 - cos 60
  // Relative paths resolve beside the scene file (fixtures/scenes here).
  const auto ies = make(R"({"ies": "../photometry/office-downlight.ies"})");
  BOOST_TEST(ies->max_intensity() == 1460.0);
  const auto ldt = make(R"({"ldt": "../photometry/office-uplight.ldt", "multiplier": 0.5})");
  BOOST_TEST(ldt->intensity(pi, 0) == 0.5 * 180 * 2000 / 1000, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(bad_specs_name_the_json_path) {
  BOOST_TEST(error_of(R"({"cos_power": 10, "spread_deg": 120, "candela": 1})") ==
             "lights[1].lid.spread_deg: must lie in (0, 90]: beyond 90 degrees cos^k is negative "
             "or a back lobe");
  BOOST_TEST(error_of(R"({"table_deg": [0, 90], "candela": [1]})") ==
             "lights[1].lid.candela: has 1 values for 2 angles in table_deg");
  BOOST_TEST(error_of(R"({"table_deg": [0, 90, 80], "candela": [1, 2, 3]})") ==
             "lights[1].lid.table_deg[2]: angles must strictly increase");
  BOOST_TEST(error_of(R"({"cos_power": 2, "candela": 1, "spred_deg": 30})")
                 .rfind("lights[1].lid.spred_deg: unknown key for a cos_power lid", 0) == 0);
  BOOST_TEST(error_of(R"({"ies": "x.ies", "ldt": "y.ldt"})") ==
             "lights[1].lid.ldt: a lid has one form, found both \"ies\" and \"ldt\"");
  BOOST_TEST(error_of(R"({"table_deg": [0, 90], "candela": [1, 2], "interpolation": "cubic"})") ==
             "lights[1].lid.interpolation: must be \"linear\" or \"cosine\", found \"cubic\"");
  // A missing file names the scene's path and the file.
  BOOST_TEST(error_of(R"({"ies": "missing.ies"})").find("lights[1].lid.ies: ") == 0);
  BOOST_TEST(error_of(R"({"ies": "missing.ies"})").find("cannot open the photometric file") !=
             std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
