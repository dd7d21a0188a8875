// penumbra lid fit from the command line.

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <nlohmann/json.hpp>

#include "exact_integrals.h"
#include "support/fixtures.h"

using penumbra::test::moment_of_legendre;
using penumbra::test::run_penumbra;

BOOST_AUTO_TEST_SUITE(lid_fit_cli)

BOOST_AUTO_TEST_CASE(prints_exact_spot_weights_as_json) {
  const auto result = run_penumbra(
      R"(lid fit '{"cos_power": 10, "spread_deg": 90, "candela": 800}' --degree 8 --sigma --json)");
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  const auto out = nlohmann::json::parse(result.out);
  BOOST_TEST(out["degree"] == 8);
  BOOST_TEST(out["fitted"] == "distribution");
  BOOST_TEST_REQUIRE(out["weights"].size() == 9u);
  BOOST_TEST_REQUIRE(out["sigma"].size() == 9u);
  for (int l = 0; l <= 8; ++l)
    BOOST_TEST(std::abs(out["weights"][l].get<double>() -
                        800 * (2 * l + 1) / 2.0 * moment_of_legendre(10, l)) <= 1e-10);
  BOOST_TEST(out["sigma"][0].get<double>() == 1.0);
  BOOST_TEST(out["error"]["max_cd"].get<double>() > 0);
  BOOST_TEST(out["error"]["rms_relative"].get<double>() < 0.05);
  BOOST_TEST(out.contains("error_without_sigma"));
}

BOOST_AUTO_TEST_CASE(text_output_and_asymmetric_files) {
  const auto text = run_penumbra(R"(lid fit '{"cardioid": true, "candela": 100}' --degree 2)");
  BOOST_TEST_REQUIRE(text.status == 0, text.err);
  BOOST_TEST(text.out.find("Legendre weights") != std::string::npos);
  BOOST_TEST(text.out.find("rms") != std::string::npos);
  const auto file = penumbra::test::photometry_fixture("ldt-formats/symmetry_to_c0c90c180c270.ldt");
  const auto asymmetric = run_penumbra("lid fit '" + file.string() + "' --degree 6 --json");
  BOOST_TEST_REQUIRE(asymmetric.status == 0, asymmetric.err);
  const auto out = nlohmann::json::parse(asymmetric.out);
  BOOST_TEST(out["fitted"] == "azimuthal_average");
  // The SH space of degree N contains every zonal series of degree N, so the L2-best
  // SH fit has the smaller RMS error.
  BOOST_TEST_REQUIRE(out.contains("sh_fit_error"));
  BOOST_TEST(out["sh_fit_error"]["rms_cd"].get<double>() <=
             out["error"]["rms_cd"].get<double>() * (1 + 1e-9));
}

BOOST_AUTO_TEST_CASE(refuses_bad_degrees) {
  BOOST_TEST(run_penumbra(R"(lid fit '{"candela": 1}' --degree -1)").status == 2);
  BOOST_TEST(run_penumbra(R"(lid fit '{"candela": 1}' --degree 61)").status == 2);
  BOOST_TEST(run_penumbra(R"(lid fit '{"candela": 1}')").status == 2);
}

BOOST_AUTO_TEST_SUITE_END()
