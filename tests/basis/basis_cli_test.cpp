// penumbra radiosity, basis and relight from the command line: outputs, agreement between
// relight and radiosity, and bad input (exit status 2, the file or option named, nothing
// written).

#include <boost/test/unit_test.hpp>
#include <fstream>
#include <map>
#include <sstream>

#include "support/fixtures.h"

using penumbra::test::csv_columns;
using penumbra::test::fixture;
using penumbra::test::read_text;
using penumbra::test::run_penumbra;
using penumbra::test::scratch_dir;

BOOST_AUTO_TEST_SUITE(basis_cli)

BOOST_AUTO_TEST_CASE(basis_relight_and_radiosity_agree) {
  const auto dir = scratch_dir("basis_cli");
  const std::string scene = fixture("scenes/basis-room.json").string();
  const std::string pbl = (dir / "room.pbl").string();
  auto result =
      run_penumbra("basis " + scene + " --degree 2 --patch-size 1 --rays 64 --no-sigma -o " + pbl);
  // --no-sigma belongs to relight: basis refuses it
  BOOST_TEST(result.status == 2);
  result = run_penumbra("basis " + scene + " --degree 2 --patch-size 0.5 --rays 64 -o " + pbl);
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  BOOST_TEST(result.out.find("light corner: degree 2, 9 basis functions") != std::string::npos,
             result.out);

  result = run_penumbra("relight " + pbl + " --patches " + (dir / "relit.csv").string());
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  result = run_penumbra("radiosity " + scene + " --patch-size 0.5 --rays 64 -o " +
                        (dir / "solved.csv").string());
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  const auto relit = csv_columns(read_text(dir / "relit.csv"));
  const auto solved = csv_columns(read_text(dir / "solved.csv"));
  for (const char* name :
       {"object", "face", "x", "y", "z", "nx", "ny", "nz", "area", "E_direct", "E"}) {
    BOOST_TEST_REQUIRE(relit.count(name) == 1u, name);
    BOOST_TEST_REQUIRE(solved.count(name) == 1u, name);
  }
  BOOST_TEST_REQUIRE(relit.at("E").size() == solved.at("E").size());
  BOOST_TEST(relit.at("object") == solved.at("object"), boost::test_tools::per_element());
  // same mesh and form factors; the distributions differ only by the degree-2 series
  // (with sigma factors), whose w_0 is exact: the flux each lamp sends into the closed
  // room is the same, so the direct flux on all patches agrees up to how differently the
  // patch centres sample the two distributions. docs/basis.md ("Radiosity", CIE 171 test
  // 5.8) reports the sampled direct flux within 0.5% of the lamps' flux at 0.5 m patches,
  // so the two sums differ by at most 1% (measured: 0.56%)
  double sum_relit = 0, sum_solved = 0;
  for (std::size_t i = 0; i < relit.at("E").size(); ++i) {
    const double area = std::stod(relit.at("area")[i]);
    sum_relit += area * std::stod(relit.at("E_direct")[i]);
    sum_solved += area * std::stod(solved.at("E_direct")[i]);
  }
  BOOST_TEST(sum_relit == sum_solved, boost::test_tools::tolerance(0.01));

  result = run_penumbra("relight " + pbl +
                        " --aim corner=1,5,0 --scale centre=0.5 --color centre=1,0.8,0.6 -o " +
                        (dir / "relit.png").string() + " --width 64 --height 48");
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  const auto size = penumbra::test::png_size(read_text(dir / "relit.png"));
  BOOST_TEST(size.first == 64u);
  BOOST_TEST(size.second == 48u);
}

BOOST_AUTO_TEST_CASE(fit_prints_a_distribution_that_meets_its_targets) {
  const auto dir = scratch_dir("basis_cli_fit");
  const std::string pbl = (dir / "room.pbl").string();
  BOOST_TEST_REQUIRE(run_penumbra("basis " + fixture("scenes/basis-room.json").string() +
                                  " --degree 3 --patch-size 1 --rays 64 -o " + pbl)
                         .status == 0);
  // targets made by relighting with a curve given at the fit's own control angles (every
  // 10 degrees, joined linearly): that curve is one of the fit's candidates, so the fit
  // must meet every target (to float storage of the basis)
  const std::string curve =
      R"({"table_deg": [0,10,20,30,40,50,60,70,80,90,100,110,120,130,140,150,160,170,180],)"
      R"( "candela": [900,880,820,700,560,420,300,200,120,60,30,10,0,0,0,0,0,0,0]})";
  const std::string relit_csv = (dir / "wanted.csv").string();
  BOOST_TEST_REQUIRE(
      run_penumbra("relight " + pbl + " --lid 'centre=" + curve + "' --patches " + relit_csv)
          .status == 0);
  const auto wanted = csv_columns(read_text(relit_csv));
  std::ofstream targets(dir / "targets.csv");
  targets << "x,y,z,E\n";
  double largest = 0;
  int count = 0;
  for (std::size_t i = 0; i < wanted.at("E").size() && count < 6; i += 5) {
    if (wanted.at("object")[i] != "floor" || std::stod(wanted.at("nz")[i]) < 0.5) continue;
    targets << wanted.at("x")[i] << ',' << wanted.at("y")[i] << ',' << wanted.at("z")[i] << ','
            << wanted.at("E")[i] << '\n';
    largest = std::max(largest, std::stod(wanted.at("E")[i]));
    ++count;
  }
  targets.close();
  BOOST_TEST_REQUIRE(count == 6);
  const auto result =
      run_penumbra("relight " + pbl + " --fit " + (dir / "targets.csv").string() +
                   " --fit-light centre --patches " + (dir / "fitted.csv").string());
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  const auto report = nlohmann::json::parse(result.out);
  BOOST_TEST(report["light"] == "centre");
  BOOST_TEST(report["lid"]["candela"].size() == 19u);
  BOOST_TEST(report["max_residual_lux"].get<double>() < 1e-4 * largest);
  for (const auto& c : report["lid"]["candela"]) BOOST_TEST(c.get<double>() >= 0);
  BOOST_TEST(std::filesystem::exists(dir / "fitted.csv"));
}

BOOST_AUTO_TEST_CASE(bad_input_exits_2_and_names_it) {
  const auto dir = scratch_dir("basis_cli_bad");
  const std::string scene = fixture("scenes/basis-room.json").string();
  const auto refused = [&](const std::string& arguments, const std::string& fragment) {
    const auto result = run_penumbra(arguments);
    BOOST_TEST_CONTEXT(arguments) {
      BOOST_TEST(result.status == 2);
      BOOST_TEST(result.err.find(fragment) != std::string::npos, result.err);
    }
  };
  refused("basis " + scene + " --degree 21 -o " + (dir / "a.pbl").string(), "--degree");
  refused("basis " + scene + " --patch-size 0 -o " + (dir / "a.pbl").string(), "--patch-size");
  refused("basis " + scene + " --light-degree nobody=3 -o " + (dir / "a.pbl").string(), "nobody");
  refused("radiosity " + scene + " --form-factors hemicube -o " + (dir / "a.csv").string(),
          "--form-factors");
  std::ofstream(dir / "junk.pbl") << "not a basis";
  refused("relight " + (dir / "junk.pbl").string() + " -o " + (dir / "a.png").string(), "junk.pbl");
  BOOST_TEST(!std::filesystem::exists(dir / "a.pbl"));
  BOOST_TEST(!std::filesystem::exists(dir / "a.csv"));
  BOOST_TEST(!std::filesystem::exists(dir / "a.png"));
  const std::string pbl = (dir / "ok.pbl").string();
  BOOST_TEST_REQUIRE(
      run_penumbra("basis " + scene + " --degree 1 --patch-size 1.5 --rays 16 -o " + pbl).status ==
      0);
  refused("relight " + pbl + " --aim nobody=1,2,3 -o " + (dir / "a.png").string(), "nobody");
  refused("relight " + pbl + " --aim corner=1,2 -o " + (dir / "a.png").string(), "--aim");
  refused("relight " + pbl + " --lid centre=lamp.txt -o " + (dir / "a.png").string(), "--lid");
  refused("relight " + pbl + " --scale centre=-1 -o " + (dir / "a.png").string(), "--scale");
  refused("relight " + pbl, "-o");
  std::ofstream(dir / "targets.csv") << "x,y,E\n1,2,3\n";
  refused("relight " + pbl + " --fit " + (dir / "targets.csv").string(), "missing column \"z\"");
  std::ofstream(dir / "air.csv") << "x,y,z,E\n4,3,1.5,100\n";
  refused("relight " + pbl + " --fit " + (dir / "air.csv").string(), "no face");
  BOOST_TEST(!std::filesystem::exists(dir / "a.png"));
}

BOOST_AUTO_TEST_SUITE_END()
