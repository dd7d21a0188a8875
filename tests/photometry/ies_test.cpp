// IES LM-63 files: every shared file loads, fluxes agree with an independent
// integration and with the file's own lumens, the bugs of other parsers do not occur,
// errors name the line, and the writer round-trips every value.

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "midpoint_flux.h"
#include "penumbra/base/input_error.h"
#include "penumbra/base/numbers.h"
#include "penumbra/photometry/ies.h"
#include "printing.h"
#include "support/fixtures.h"

using penumbra::pi;

namespace tt = boost::test_tools;
using namespace penumbra::photometry;
using penumbra::InputError;
using penumbra::test::photometry_fixture;

namespace {

using test::midpoint_flux;

std::vector<std::filesystem::path> files_in(const std::string& folder) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(photometry_fixture(folder)))
    files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// A small valid LM-63-2002 body after the TILT line: 1 lamp, 1000 lm, 3 vertical, 1 horizontal.
const char* kBody =
    "1 1000 1 3 1 1 2 0 0 0\n"
    "1 1 10\n"
    "0 45 90\n"
    "0\n"
    "100 50 0\n";

IesFile parse(const std::string& text) {
  return parse_ies(text, "test.ies");
}

// returns the "line N" of the InputError text throws.
std::string error_location(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e.location() + ": " + e.message();
  }
  return "no error";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(ies)

BOOST_AUTO_TEST_CASE(every_shared_ies_file_loads_and_integrates_like_an_independent_quadrature) {
  for (const std::string folder : {"ies-real", "ies-formats"})
    for (const auto& path : files_in(folder)) {
      BOOST_TEST_CONTEXT(path.filename()) {
        const auto lid = load_ies(path, Interpolation::linear);
        BOOST_TEST(lid->flux() > 0);
        // Tolerance: the midpoint rule's own error on these tables is below 0.1%.
        BOOST_TEST(lid->flux() == midpoint_flux(*lid), tt::tolerance(2e-3));
      }
    }
}

BOOST_AUTO_TEST_CASE(real_files_integrate_to_the_lumens_their_labs_state) {
  // [_ABSOLUTELUMENS] of the RAB files, and 1 lamp x 1000 lm of the relative Maxwell files.
  // Labs sum zonal lumens over their own zones, so 1% apart is agreement; the flood
  // light is type B, integrated here in its own (H, V) grid.
  const std::pair<const char*, double> stated[] = {{"1.IES", 9217},
                                                   {"2.IES", 5834},
                                                   {"4.IES", 5822},
                                                   {"7.IES", 532},
                                                   {"8.IES", 828},
                                                   {"flood-2.1.IES", 10601},
                                                   {"maxwell-8-t4-cie.ies", 1000},
                                                   {"maxwell-8-t4-iesna.ies", 1000}};
  for (const auto& [name, lumens] : stated) {
    BOOST_TEST_CONTEXT(name) {
      const IesFile ies = read_ies(photometry_fixture(std::string("ies-real/") + name));
      if (ies.keyword("_ABSOLUTELUMENS").empty() == false)
        BOOST_TEST(std::stod(ies.keyword("_ABSOLUTELUMENS")) == lumens);
      const TableDistribution lid(candela_grid(ies), Interpolation::linear);
      BOOST_TEST(lid.flux() == lumens, tt::tolerance(0.01));
    }
  }
}

BOOST_AUTO_TEST_CASE(type_b_files_convert_to_c_gamma_with_the_beam_on_the_axis) {
  const IesFile ies = read_ies(photometry_fixture("ies-real/flood-2.2.ies"));
  BOOST_TEST(ies.photometric_type == 2);
  const TableDistribution lid(candela_grid(ies), Interpolation::linear);
  // H = 0, V = 0 is the 23rd value of the 23rd block (both lists are -90..90 with 0 at
  // index 22): the beam axis.
  BOOST_TEST(lid.intensity(0, 0) == ies.candela[22][22], tt::tolerance(1e-12));
  // H = -90 (C = 270, gamma = 90) is the pole, 1.79 cd for every V in the file.
  BOOST_TEST(lid.intensity(pi / 2, 1.5 * pi) == 1.79, tt::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(the_multiplier_scales_candela_once_not_squared) {
  const IesFile plain = read_ies(photometry_fixture("ies-formats/ies95-relative_photometry.ies"));
  const IesFile scaled =
      read_ies(photometry_fixture("ies-formats/ies95-relative_photometry_with_multiplier.ies"));
  BOOST_TEST(scaled.candela_multiplier == 1.5);
  const auto a = candela_grid(plain), b = candela_grid(scaled);
  for (std::size_t v = 0; v < a.vertical_deg.size(); ++v)
    BOOST_TEST(b.candela[0][v] == 1.5 * a.candela[0][v], tt::tolerance(1e-15));
  BOOST_TEST(b.candela[0][0] == 3300.0);  // 2200 x 1.5, not 2200 x 2.25
}

BOOST_AUTO_TEST_CASE(minus_one_lumens_is_absolute_photometry) {
  const IesFile ies = read_ies(photometry_fixture("ies-formats/ies95-absolute_photometry.ies"));
  BOOST_TEST(ies.absolute());
  BOOST_TEST(candela_grid(ies).candela[0][0] == 2200.0);
  BOOST_TEST(!read_ies(photometry_fixture("ies-formats/ies95-relative_photometry.ies")).absolute());
  BOOST_TEST(
      error_location(
          std::string(
              "IESNA:LM-63-2002\nTILT=NONE\n1 -2 1 3 1 1 2 0 0 0\n1 1 10\n0 45 90\n0\n1 2 3\n"))
          .rfind("line 3: the lumens per lamp must be positive, or -1", 0) == 0);
}

BOOST_AUTO_TEST_CASE(negative_opening_dimensions_are_kept) {
  const IesFile round = read_ies(photometry_fixture("ies-formats/ies95-round_opening.ies"));
  BOOST_TEST(round.width == -0.12);
  const IesFile sphere = read_ies(photometry_fixture("ies-formats/ies95-sphere_opening.ies"));
  BOOST_TEST(sphere.height == -0.12);
  BOOST_TEST(read_ies(photometry_fixture("ies-formats/ies95-imperial_units.ies")).units_type == 1);
}

BOOST_AUTO_TEST_CASE(label_lines_mentioning_tilt_do_not_end_the_header) {
  const std::string text = std::string(
                               "IESNA:LM-63-2002\n[TEST] TILT=NONE was not measured\n"
                               "TILT TEST LABEL\n[OTHER] see TILT=INCLUDE below\nTILT=NONE\n") +
                           kBody;
  const IesFile ies = parse(text);
  BOOST_TEST(ies.label_lines.size() == 3u);
  BOOST_TEST(ies.keyword("TEST") == "TILT=NONE was not measured");
  BOOST_TEST(ies.candela[0][1] == 50.0);
  const IesFile shipped = read_ies(photometry_fixture("ies-formats/ies95-label_lines.ies"));
  BOOST_TEST(shipped.keyword("MULTILINE") == "Test multiline metadata");
}

BOOST_AUTO_TEST_CASE(tilt_include_and_tilt_file_are_read) {
  const std::string include =
      std::string("IESNA:LM-63-1995\nTILT=INCLUDE\n1\n3\n0 45 90\n1 0.9 0.8\n") + kBody;
  const IesFile ies = parse(include);
  BOOST_TEST(ies.tilt.lamp_to_luminaire_geometry == 1);
  BOOST_TEST(ies.tilt.factors[2] == 0.8);
  BOOST_TEST(ies.candela[0][0] == 100.0);
  const auto dir = penumbra::test::scratch_dir("ies-tilt");
  std::ofstream(dir / "lamp.tlt") << "2\n2\n0 90\n1 0.5\n";
  std::ofstream(dir / "lamp.ies") << "IESNA:LM-63-2002\nTILT=lamp.tlt\n" << kBody;
  const IesFile with_file = read_ies(dir / "lamp.ies");
  BOOST_TEST(with_file.tilt.mode == "lamp.tlt");
  BOOST_TEST(with_file.tilt.factors[1] == 0.5);
  // The writer inlines it, so the written file stands alone.
  std::ostringstream out;
  write_ies(out, with_file);
  BOOST_TEST(parse(out.str()).tilt.mode == "INCLUDE");
  BOOST_TEST(parse(out.str()).tilt.factors == with_file.tilt.factors);
}

BOOST_AUTO_TEST_CASE(every_format_generation_is_recognised) {
  BOOST_TEST(parse(std::string("IESNA:LM-63-2002\nTILT=NONE\n") + kBody).year == 2002);
  BOOST_TEST(parse(std::string("IES:LM-63-2019\nTILT=NONE\n") + kBody).year == 2019);
  BOOST_TEST(parse(std::string("IESNA:LM-63-1995\nTILT=NONE\n") + kBody).year == 1995);
  // LM-63-1991 and -1986 carry a ballast-lamp photometric factor that scales candela.
  const IesFile v1991 = parse(
      "IESNA91\n[TEST] x\nTILT=NONE\n1 1000 1 3 1 1 2 0 0 0\n0.9 0.5 10\n0 45 90\n0\n100 50 0\n");
  BOOST_TEST(v1991.year == 1991);
  BOOST_TEST(candela_grid(v1991).candela[0][0] == 45.0, tt::tolerance(1e-12));  // 100 x 0.9 x 0.5
  const IesFile v1986 =
      parse(std::string("SOME LAB REPORT 1234\nA DOWNLIGHT\nTILT=NONE\n") + kBody);
  BOOST_TEST(v1986.year == 1986);
  BOOST_TEST(v1986.format.empty());
  BOOST_TEST(v1986.label_lines.size() == 2u);
}

BOOST_AUTO_TEST_CASE(every_horizontal_symmetry_and_vertical_range_loads) {
  const std::pair<const char*, Symmetry> cases[] = {{"0", Symmetry::axial},
                                                    {"0 90", Symmetry::quadrant},
                                                    {"0 90 180", Symmetry::bilateral_c0_c180},
                                                    {"90 180 270", Symmetry::bilateral_c90_c270},
                                                    {"0 90 180 270 360", Symmetry::none}};
  for (const auto& [angles, symmetry] : cases) {
    std::istringstream in(angles);
    int count = 0;
    for (double a; in >> a;) ++count;
    std::string text = "IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 3 " + std::to_string(count) +
                       " 1 2 0 0 0\n1 1 10\n90 135 180\n" + angles + "\n";
    for (int h = 0; h < count; ++h) text += "0 50 100\n";
    const TableDistribution lid(candela_grid(parse(text)), Interpolation::linear);
    BOOST_TEST(lid.symmetry() == symmetry, angles);
    // Range 90-180: dark below the horizon, the table above it.
    BOOST_TEST(lid.intensity(radians(60), 1.0) == 0.0);
    BOOST_TEST(lid.intensity(radians(157.5), 1.0) == 75.0, tt::tolerance(1e-12));
  }
}

BOOST_AUTO_TEST_CASE(bad_files_name_the_line_and_what_is_wrong) {
  const std::string head = "IESNA:LM-63-2002\n[TEST] x\nTILT=NONE\n";
  BOOST_TEST(error_location(head + "1 1000 1 3 1 1 2 0 0 0\n1 1 10\n0 45 90\n0\n100 50\n") ==
             "line 8: the file ends after 2 of 3 candela values of horizontal angle 0");
  BOOST_TEST(error_location(head + "1 1000 1 -3 1 1 2 0 0 0\n") ==
             "line 4: the number of vertical angles must be a positive integer, found -3");
  BOOST_TEST(error_location(head + "1 1000 1 3 1 1 2 0 0 0\n1 1 10\n0 4x5 90\n") ==
             "line 6: vertical angles: \"4x5\" is not a number");
  BOOST_TEST(error_location(head + "1 1000 1 3 1 4 2 0 0 0\n") ==
             "line 4: the photometric type must be 1 (C), 2 (B) or 3 (A), found 4");
  BOOST_TEST(error_location(head + "1 1000 1 3 1 1 2 0 0 0\n1 1 10\n0 45 90\n0\n100 50 0 7\n") ==
             "line 8: unexpected text after the last candela value (the counts say 3 x 1 values)");
  BOOST_TEST(error_location(head + "1 1000 1 3 2 1 2 0 0 0\n1 1 10\n0 45 90\n0 45\n") ==
             "line 7: the horizontal angles 0..45 are not an LM-63 range for type C (0; 0-90; "
             "0-180; 90-270; 0-360)");
  // found by fuzzing (tests/fuzz/regressions/ies/type-a-one-lateral-angle.ies): one lateral
  // angle of type A or B gave a grid that interpolation read beyond
  for (const char* type : {"2", "3"})
    BOOST_TEST(
        error_location(head + "1 1000 1 3 1 " + type + " 2 0 0 0\n1 1 10\n0 45 90\n0\n1 2 3\n") ==
        std::string("line 7: the horizontal angles 0..0 are not an LM-63 range for type ") +
            (type[0] == '2' ? "B" : "A") +
            " (-90..90, or 0..90 for lateral symmetry; at least two angles)");
  // found by fuzzing (regressions/ies/huge-angle-count.ies): a count far beyond what the
  // file holds was reserved before reading (5 GB), and now ends in the truncation error
  BOOST_TEST(error_location(head + "1 1000 1 672120362 1 1 2 0 0 0\n1 1 10\n0 45 90\n") ==
             "line 6: the file ends after 3 of 672120362 vertical angles");
  BOOST_TEST(error_location("IESNA:LM-63-2002\n[TEST] truncated before TILT\n") ==
             "line 2: no TILT= line: this is not an LM-63 file, or it is truncated");
}

BOOST_AUTO_TEST_CASE(writer_round_trips_every_value_of_every_shared_file) {
  for (const std::string folder : {"ies-real", "ies-formats"})
    for (const auto& path : files_in(folder)) {
      BOOST_TEST_CONTEXT(path.filename()) {
        const IesFile original = read_ies(path);
        std::ostringstream out;
        write_ies(out, original);
        const IesFile again = parse(out.str());
        BOOST_TEST(again.format == original.format);
        BOOST_TEST(again.label_lines == original.label_lines);
        BOOST_TEST(again.lamp_count == original.lamp_count);
        BOOST_TEST(again.lumens_per_lamp == original.lumens_per_lamp);
        BOOST_TEST(again.candela_multiplier == original.candela_multiplier);
        BOOST_TEST(again.photometric_type == original.photometric_type);
        BOOST_TEST(again.units_type == original.units_type);
        BOOST_TEST((again.width == original.width && again.length == original.length &&
                    again.height == original.height));
        BOOST_TEST((again.ballast_factor == original.ballast_factor &&
                    again.ballast_lamp_factor == original.ballast_lamp_factor &&
                    again.input_watts == original.input_watts));
        BOOST_TEST(again.vertical_deg == original.vertical_deg);
        BOOST_TEST(again.horizontal_deg == original.horizontal_deg);
        BOOST_TEST((again.candela == original.candela));
      }
    }
}

BOOST_AUTO_TEST_SUITE_END()
