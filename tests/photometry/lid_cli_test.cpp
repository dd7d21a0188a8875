// penumbra lid end to end: info (text and JSON), sample, convert round trips, fit
// pending, and errors with file and line and exit status 2.

#include <boost/test/unit_test.hpp>

#include <fstream>

#include <nlohmann/json.hpp>

#include "penumbra/photometry/ies.h"
#include "support/fixtures.h"

namespace tt = boost::test_tools;
using penumbra::test::photometry_fixture;
using penumbra::test::run_penumbra;

namespace {

std::string quoted(const std::filesystem::path& path) {
  return "'" + path.string() + "'";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(lid_cli)

BOOST_AUTO_TEST_CASE(info_json_has_the_documented_keys) {
  const auto result =
      run_penumbra("lid info --json " + quoted(photometry_fixture("ies-real/7.IES")));
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  const auto out = nlohmann::json::parse(result.out);
  for (const char* key :
       {"lumens", "max_candela", "symmetry", "beam_angle_deg", "field_angle_deg", "partial_sphere"})
    BOOST_TEST(out.contains(key), key);
  BOOST_TEST(out["lumens"].get<double>() == 532.0, tt::tolerance(0.01));  // [_ABSOLUTELUMENS]532
  BOOST_TEST(out["max_candela"].get<double>() == 269.0);
  BOOST_TEST(out["symmetry"] == "axial");
  BOOST_TEST(out["partial_sphere"]["threshold"].get<double>() == 1.0 / 256);
}

BOOST_AUTO_TEST_CASE(info_reads_a_spec_and_an_ldt_file) {
  const auto spec =
      run_penumbra(R"(lid info --json '{"cos_power": 1, "spread_deg": 90, "candela": 100}')");
  BOOST_TEST_REQUIRE(spec.status == 0, spec.err);
  BOOST_TEST(nlohmann::json::parse(spec.out)["lumens"].get<double>() == 100 * 3.14159265358979,
             tt::tolerance(1e-12));
  const auto ldt =
      run_penumbra("lid info " + quoted(penumbra::test::fixture("photometry/office-uplight.ldt")));
  BOOST_TEST_REQUIRE(ldt.status == 0, ldt.err);
  BOOST_TEST(ldt.out.find("lumens 1667.38 (the file states 1667.4)") != std::string::npos, ldt.out);
}

BOOST_AUTO_TEST_CASE(sample_prints_the_intensity) {
  const auto result =
      run_penumbra(R"(lid sample '{"table_deg": [0, 10, 20], "candela": [100, 50, 0]}' --gamma 5)");
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  BOOST_TEST(std::stod(result.out) == 75.0, tt::tolerance(1e-12));
  // C = 360 on a full C-gamma file is C = 0.
  const auto at0 = run_penumbra("lid sample " + quoted(photometry_fixture("ies-real/3.IES")) +
                                " --gamma 30 --c 0");
  const auto at360 = run_penumbra("lid sample " + quoted(photometry_fixture("ies-real/3.IES")) +
                                  " --gamma 30 --c 360");
  BOOST_TEST(std::stod(at0.out) == 3954.03 * 1.0043784, tt::tolerance(1e-12));
  BOOST_TEST(std::stod(at360.out) == std::stod(at0.out), tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(convert_round_trips_an_ies_file_and_converts_ldt) {
  const auto dir = penumbra::test::scratch_dir("lid-convert");
  const auto source = photometry_fixture("ies-real/italo-1-5p5-s05.ies");
  const auto result =
      run_penumbra("lid convert " + quoted(source) + " -o " + quoted(dir / "out.ies"));
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  const auto original = penumbra::photometry::read_ies(source);
  const auto again = penumbra::photometry::read_ies(dir / "out.ies");
  BOOST_TEST((again.candela == original.candela));
  BOOST_TEST(again.vertical_deg == original.vertical_deg);
  BOOST_TEST(again.label_lines == original.label_lines);
  // EULUMDAT to LM-63: the same intensities in candela, and the same flux.
  const auto ldt = photometry_fixture("ldt-real/road_luminaire.ldt");
  BOOST_TEST_REQUIRE(
      run_penumbra("lid convert " + quoted(ldt) + " -o " + quoted(dir / "road.ies")).status == 0);
  const auto a = run_penumbra("lid sample " + quoted(ldt) + " --gamma 65 --c 170");
  const auto b = run_penumbra("lid sample " + quoted(dir / "road.ies") + " --gamma 65 --c 170");
  BOOST_TEST(std::stod(a.out) == std::stod(b.out), tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(errors_name_file_and_line_and_leave_no_output) {
  const auto dir = penumbra::test::scratch_dir("lid-errors");
  std::ofstream(dir / "bad.ies")
      << "IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 3 1 1 2 0 0 0\n1 1 1\n0 45 90\n0\n10 x 0\n";
  const auto result =
      run_penumbra("lid convert " + quoted(dir / "bad.ies") + " -o " + quoted(dir / "out.ies"));
  BOOST_TEST(result.status == 2);
  BOOST_TEST(result.err.find(
                 "bad.ies: line 7: candela values of horizontal angle 0: \"x\" is not a number") !=
                 std::string::npos,
             result.err);
  BOOST_TEST(!std::filesystem::exists(dir / "out.ies"));
  BOOST_TEST(run_penumbra("lid info " + quoted(dir / "missing.ldt")).status == 2);
  BOOST_TEST(run_penumbra(R"(lid info '{"cos_power": 1}')").status == 2);
}

BOOST_AUTO_TEST_CASE(fit_of_a_missing_file_exits_2) {
  // lid fit itself is tested with the basis layer (tests/basis/); here only that it
  // shares the verb's error path.
  const auto result = run_penumbra("lid fit anything.ies --degree 4");
  BOOST_TEST(result.status == 2);
  BOOST_TEST(result.err.find("anything.ies") != std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
