// EULUMDAT files: every shared file loads, symmetry codes Isym 0-4 unfold to the
// planes they name, cd/klm becomes candela with the lamp set's flux, and real files
// integrate to their light output ratio times lamp flux.

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <sstream>

#include "midpoint_flux.h"
#include "penumbra/base/input_error.h"
#include "penumbra/photometry/eulumdat.h"
#include "printing.h"
#include "support/fixtures.h"

namespace tt = boost::test_tools;
using namespace penumbra::photometry;
using penumbra::InputError;
using penumbra::test::photometry_fixture;

namespace {

using test::midpoint_flux;

TableDistribution load(const std::string& name, std::size_t lamp_set = 0) {
  return TableDistribution(candela_grid(read_eulumdat(photometry_fixture(name)), lamp_set),
                           Interpolation::linear);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(eulumdat)

BOOST_AUTO_TEST_CASE(every_shared_ldt_file_loads_and_integrates_like_an_independent_quadrature) {
  for (const std::string folder : {"ldt-formats", "ldt-real"})
    for (const auto& entry : std::filesystem::directory_iterator(photometry_fixture(folder))) {
      BOOST_TEST_CONTEXT(entry.path().filename()) {
        const auto lid = load_eulumdat(entry.path(), Interpolation::linear);
        BOOST_TEST(lid->flux() == midpoint_flux(*lid), tt::tolerance(3e-3));
      }
    }
}

BOOST_AUTO_TEST_CASE(real_luminaires_emit_their_light_output_ratio_times_lamp_flux) {
  // LORL x lamp flux is the manufacturer's luminaire flux; the integral of the
  // candela grid must agree. The projector's file rounds its LORL (84.42%) and
  // its narrow beam is coarsely sampled, hence 2.5%.
  const std::pair<const char*, double> files[] = {
      {"ldt-real/4058075580657_FL_MAX_LUM_900W_757_ASYM_50X110_WAL.ldt", 0.005},
      {"ldt-real/4058075580664_FL_MAX_LUM_1200W_757_SYM_10_WAL.ldt", 0.005},
      {"ldt-real/floor_uplight.ldt", 0.01},
      {"ldt-real/fluorescent_luminaire.ldt", 0.005},
      {"ldt-real/road_luminaire.ldt", 0.005},
      {"ldt-real/demo_two_lamp_sets.ldt", 0.01},
      {"ldt-real/projector.ldt", 0.025}};
  for (const auto& [name, tolerance] : files) {
    BOOST_TEST_CONTEXT(name) {
      const EulumdatFile ldt = read_eulumdat(photometry_fixture(name));
      const double stated = ldt.light_output_ratio / 100 * ldt.lamp_sets[0].flux;
      const TableDistribution lid(candela_grid(ldt), Interpolation::linear);
      BOOST_TEST(lid.flux() == stated, tt::tolerance(tolerance));
    }
  }
}

BOOST_AUTO_TEST_CASE(wiki_templates_load_but_their_numbers_are_not_a_luminaire) {
  // The three "wiki" templates hold illustrative numbers: the batwing's distribution
  // integrates to about 2.9 times the flux of its own lamps (11664 lm from 4000 lm), which
  // no luminaire can do. So they are loaded and checked for shape, not against LORL.
  const TableDistribution batwing = load("ldt-real/wiki-batwing.ldt");
  BOOST_TEST(batwing.flux() > 2.5 * 4000);
  BOOST_TEST(degrees(batwing.max_direction().gamma) == 40.0, tt::tolerance(1e-9));
  BOOST_TEST(load("ldt-real/wiki-spotlight.ldt").symmetry() == Symmetry::axial);
}

BOOST_AUTO_TEST_CASE(cd_per_klm_becomes_candela_with_the_lamp_flux) {
  // absolute.ldt: 2200 cd/klm at nadir, lamp set flux 500 lm: 2200 x 500 / 1000 = 1100 cd.
  const EulumdatFile absolute = read_eulumdat(photometry_fixture("ldt-formats/absolute.ldt"));
  BOOST_TEST(absolute.absolute());
  BOOST_TEST(absolute.lamp_sets[0].count == -2);
  BOOST_TEST(load("ldt-formats/absolute.ldt").intensity(0, 0) == 1100.0, tt::tolerance(1e-12));
  const EulumdatFile relative = read_eulumdat(photometry_fixture("ldt-formats/relative.ldt"));
  BOOST_TEST(!relative.absolute());
  BOOST_TEST(load("ldt-formats/relative.ldt").intensity(0, 0) == 1100.0, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(several_lamp_sets_are_read_and_selectable) {
  const EulumdatFile ldt = read_eulumdat(photometry_fixture("ldt-formats/multiple_lamp_sets.ldt"));
  BOOST_TEST_REQUIRE(ldt.lamp_sets.size() == 3u);
  BOOST_TEST(ldt.lamp_sets[1].type == "Double Lamp");
  BOOST_TEST(ldt.lamp_sets[1].count == 2);
  BOOST_TEST(ldt.lamp_sets[1].flux == 1200.0);
  BOOST_TEST(ldt.lamp_sets[2].colour == "5000");
  // 2200 cd/klm at nadir with set 0 (500 lm) and set 1 (1200 lm).
  BOOST_TEST(load("ldt-formats/multiple_lamp_sets.ldt", 0).intensity(0, 0) == 1100.0,
             tt::tolerance(1e-12));
  BOOST_TEST(load("ldt-formats/multiple_lamp_sets.ldt", 1).intensity(0, 0) == 2640.0,
             tt::tolerance(1e-12));
  BOOST_CHECK_THROW(candela_grid(ldt, 3), InputError);
  const EulumdatFile two = read_eulumdat(photometry_fixture("ldt-real/demo_two_lamp_sets.ldt"));
  BOOST_TEST(two.lamp_sets[1].flux == 10080.0);
}

BOOST_AUTO_TEST_CASE(isym_2_mirrors_about_c0_c180) {
  // symmetry_to_c0c180.ldt stores C0..C180 with I(gamma=0) = 2200 + 37 k at C = 10 k.
  const TableDistribution lid = load("ldt-formats/symmetry_to_c0c180.ldt");
  BOOST_TEST(lid.symmetry() == Symmetry::bilateral_c0_c180);
  BOOST_TEST(lid.intensity(radians(25), radians(30)) == lid.intensity(radians(25), radians(330)),
             tt::tolerance(1e-12));
  BOOST_TEST(lid.intensity(0, radians(300)) * 1000 / 1000 == (2200 + 37 * 6) * 1.0,
             tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(isym_3_stores_c90_to_c270_and_mirrors_about_that_plane) {
  // The same numbers stored under Isym 3 are the planes C90, C100, ..., C270, so the
  // stored value of plane k belongs to C = 90 + 10 k and C = 90 - 10 k is its mirror.
  const TableDistribution lid = load("ldt-formats/symmetry_to_c90c270.ldt");
  BOOST_TEST(lid.symmetry() == Symmetry::bilateral_c90_c270);
  BOOST_TEST(lid.intensity(0, radians(90)) == 2200.0, tt::tolerance(1e-12));
  BOOST_TEST(lid.intensity(0, radians(270)) == 2200 + 37 * 18, tt::tolerance(1e-12));
  BOOST_TEST(lid.intensity(0, radians(0)) == 2200 + 37 * 9, tt::tolerance(1e-12));  // = C180
  BOOST_TEST(lid.intensity(radians(30), radians(40)) == lid.intensity(radians(30), radians(140)),
             tt::tolerance(1e-12));
  BOOST_TEST(lid.intensity(radians(30), radians(300)) == lid.intensity(radians(30), radians(240)),
             tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(isym_3_road_luminaire_throws_its_light_on_the_street_side) {
  // A road luminaire on the kerb is symmetric to the C90-C270 plane across the road and
  // sends more light to the street (C90) than to the houses (C270), with its peaks
  // near the road axis on the street side. Reading Isym 3 as C270..C90 (the other
  // half) would put the peak on the house side: wrong.
  const TableDistribution lid = load("ldt-real/road_luminaire.ldt");
  const double c = degrees(lid.max_direction().c);
  BOOST_TEST(((c > 90 && c < 180) || (c > 0 && c < 90)));
  double street = 0, house = 0;
  for (int g = 0; g <= 90; g += 5) {
    street += lid.intensity(radians(g), radians(90));
    house += lid.intensity(radians(g), radians(270));
  }
  BOOST_TEST(street > house);
}

BOOST_AUTO_TEST_CASE(isym_4_mirrors_into_four_quadrants) {
  const TableDistribution lid = load("ldt-formats/symmetry_to_c0c90c180c270.ldt");
  BOOST_TEST(lid.symmetry() == Symmetry::quadrant);
  for (double c : {0.0, 30.0, 60.0, 90.0}) {
    const double value = lid.intensity(radians(20), radians(c));
    BOOST_TEST(lid.intensity(radians(20), radians(180 - c)) == value, tt::tolerance(1e-12));
    BOOST_TEST(lid.intensity(radians(20), radians(180 + c)) == value, tt::tolerance(1e-12));
    BOOST_TEST(lid.intensity(radians(20), radians(360 - c)) == value, tt::tolerance(1e-12));
  }
  BOOST_TEST(lid.intensity(0, radians(90)) == 2200 + 37 * 9, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(isym_0_and_1_keep_every_plane_and_one_plane) {
  const TableDistribution none = load("ldt-formats/no_symmetry.ldt");
  BOOST_TEST(none.symmetry() == Symmetry::none);
  // 24 planes every 15 degrees, the circle closed on C0: C352.5 lies halfway C345..C360.
  BOOST_TEST(none.intensity(0, radians(345)) == 2200 + 37 * 23, tt::tolerance(1e-12));
  BOOST_TEST(none.intensity(0, radians(352.5)) == 0.5 * (2200 + 37 * 23 + 2200),
             tt::tolerance(1e-12));
  const TableDistribution axial = load("ldt-formats/symmetry_about_vertical_axis.ldt");
  BOOST_TEST(axial.symmetry() == Symmetry::axial);
  BOOST_TEST(axial.intensity(radians(10), 0.2) == axial.intensity(radians(10), 4.0));
}

BOOST_AUTO_TEST_CASE(bad_files_name_the_line) {
  const std::string text =
      penumbra::test::read_text(photometry_fixture("ldt-formats/symmetry_to_c0c180.ldt"));
  auto message = [](const std::string& changed) {
    try {
      parse_eulumdat(changed, "bad.ldt");
    } catch (const InputError& e) {
      return e.location() + ": " + e.message();
    }
    return std::string("no error");
  };
  std::string isym = text;
  isym.replace(isym.find("\n2\n") + 1, 1, "7");
  BOOST_TEST(message(isym) == "line 3: the symmetry indicator Isym must be 0..4, found 7");
  // found by fuzzing (tests/fuzz/regressions/eulumdat/integer-out-of-range.ldt): an integer
  // too large for any integer type was converted before its range was checked
  std::string huge = text;
  huge.replace(huge.find("\n2\n") + 1, 1, "2e115");
  BOOST_TEST(message(huge) ==
             "line 3: the symmetry indicator Isym (line 3) must be an integer, found 2e+115");
  BOOST_TEST(message(text.substr(0, text.size() / 2)).find("the file ends after") !=
             std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
