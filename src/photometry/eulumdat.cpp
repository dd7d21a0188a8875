#include "penumbra/photometry/eulumdat.h"

#include <algorithm>
#include <cmath>

#include "number_format.h"
#include "penumbra/base/input_error.h"
#include "text_tokens.h"

namespace penumbra::photometry {
namespace {

using detail::format_number;

// Reads EULUMDAT's one-field-per-line header; numbers may use a decimal comma.
class LineReader {
 public:
  LineReader(const std::vector<std::string>& lines, std::string file)
      : lines_(lines), file_(std::move(file)) {}

  std::string text(const std::string& what) {
    if (next_ >= lines_.size()) fail_end("the file ends before " + what);
    return detail::trim(lines_[next_++]);
  }
  double number(const std::string& what) {
    std::string value = text(what);
    std::replace(value.begin(), value.end(), ',', '.');
    const std::vector<std::string> one{value};
    detail::TokenStream token(one, 0, file_);
    try {
      const double result = token.number(what);
      if (!token.at_end()) throw InputError(file_, "", "");
      return result;
    } catch (const InputError&) {
      fail(what + ": \"" + value + "\" is not a number");
    }
  }
  int integer(const std::string& what) {
    const double value = number(what);
    // the range first: converting 2e115 to an integer is undefined (found by fuzzing)
    if (!(std::fabs(value) <= 1e9) || value != std::floor(value))
      fail(what + " must be an integer, found " + format_number(value));
    return static_cast<int>(value);
  }
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(file_, "line " + std::to_string(next_), message);
  }
  [[noreturn]] void fail_end(const std::string& message) const {
    throw InputError(file_, "line " + std::to_string(lines_.size()), message);
  }
  std::size_t next() const { return next_; }

 private:
  const std::vector<std::string>& lines_;
  std::string file_;
  std::size_t next_ = 0;
};

}  // namespace

std::vector<double> EulumdatFile::stored_c_deg() const {
  switch (symmetry) {
    case 1:
      return {0};
    case 2:
      return {c_deg.begin(), c_deg.begin() + c_count / 2 + 1};
    case 3:
      return {c_deg.begin() + c_count / 4, c_deg.begin() + 3 * c_count / 4 + 1};
    case 4:
      return {c_deg.begin(), c_deg.begin() + c_count / 4 + 1};
    default:
      return c_deg;
  }
}

EulumdatFile parse_eulumdat(const std::string& text, const std::filesystem::path& file) {
  EulumdatFile ldt;
  ldt.file = file.string();
  const std::vector<std::string> lines = detail::split_lines(text);
  LineReader in(lines, ldt.file);

  ldt.company = in.text("the company identification (line 1)");
  ldt.type_indicator = in.integer("the type indicator Ityp (line 2)");
  if (ldt.type_indicator < 0 || ldt.type_indicator > 3)
    in.fail("the type indicator Ityp must be 0..3, found " + std::to_string(ldt.type_indicator));
  ldt.symmetry = in.integer("the symmetry indicator Isym (line 3)");
  if (ldt.symmetry < 0 || ldt.symmetry > 4)
    in.fail("the symmetry indicator Isym must be 0..4, found " + std::to_string(ldt.symmetry));
  ldt.c_count = in.integer("the number of C planes Nc (line 4)");
  if (ldt.c_count < 1 || ldt.c_count > 721)
    in.fail("the number of C planes Nc must be 1..721, found " + std::to_string(ldt.c_count));
  if ((ldt.symmetry == 2 && ldt.c_count % 2 != 0) ||
      ((ldt.symmetry == 3 || ldt.symmetry == 4) && ldt.c_count % 4 != 0))
    in.fail("Isym " + std::to_string(ldt.symmetry) + " needs Nc divisible by " +
            (ldt.symmetry == 2 ? "2" : "4") + ", found " + std::to_string(ldt.c_count));
  ldt.c_step = in.number("the C plane distance Dc (line 5)");
  ldt.gamma_count = in.integer("the number of intensities per C plane Ng (line 6)");
  if (ldt.gamma_count < 2 || ldt.gamma_count > 361)
    in.fail("the number of gamma angles Ng must be 2..361, found " +
            std::to_string(ldt.gamma_count));
  ldt.gamma_step = in.number("the gamma distance Dg (line 7)");
  ldt.report = in.text("the measurement report number (line 8)");
  ldt.luminaire_name = in.text("the luminaire name (line 9)");
  ldt.luminaire_number = in.text("the luminaire number (line 10)");
  ldt.file_name = in.text("the file name (line 11)");
  ldt.date_user = in.text("the date/user (line 12)");
  ldt.length = in.number("the luminaire length (line 13)");
  ldt.width = in.number("the luminaire width (line 14)");
  ldt.height = in.number("the luminaire height (line 15)");
  ldt.area_length = in.number("the luminous area length (line 16)");
  ldt.area_width = in.number("the luminous area width (line 17)");
  for (int k = 0; k < 4; ++k)
    ldt.area_height[k] = in.number("the luminous area height C" + std::to_string(90 * k) +
                                   " (line " + std::to_string(18 + k) + ")");
  ldt.downward_flux_fraction = in.number("the downward flux fraction (line 22)");
  ldt.light_output_ratio = in.number("the light output ratio LORL (line 23)");
  ldt.intensity_factor = in.number("the conversion factor for luminous intensities (line 24)");
  if (!(ldt.intensity_factor > 0))
    in.fail("the conversion factor for luminous intensities must be positive, found " +
            format_number(ldt.intensity_factor));
  ldt.tilt_deg = in.number("the tilt during measurement (line 25)");
  const int sets = in.integer("the number of lamp sets n (line 26)");
  if (sets < 1 || sets > 20)
    in.fail("the number of lamp sets must be 1..20, found " + std::to_string(sets));
  ldt.lamp_sets.resize(static_cast<std::size_t>(sets));
  // Lines 26a-26f, one block of six per lamp set.
  for (auto& set : ldt.lamp_sets) {
    set.count = in.integer("the number of lamps (line 26a)");
    if (set.count == 0) in.fail("a lamp set has 0 lamps");
    set.type = in.text("the lamp type (line 26b)");
    set.flux = in.number("the total luminous flux of the lamps (line 26c)");
    if (!(set.flux > 0))
      in.fail("the luminous flux of a lamp set must be positive, found " + format_number(set.flux));
    set.colour = in.text("the colour appearance (line 26d)");
    set.colour_rendering = in.text("the colour rendering group (line 26e)");
    set.watts = in.number("the wattage including ballast (line 26f)");
  }

  // The numeric blocks: direct ratios, angles and intensities. Some writers put several
  // values on a line, so they are read as a token stream (decimal commas made points).
  std::vector<std::string> numeric(lines.begin(), lines.end());
  for (std::size_t i = in.next(); i < numeric.size(); ++i)
    std::replace(numeric[i].begin(), numeric[i].end(), ',', '.');
  detail::TokenStream tokens(numeric, std::min(in.next(), numeric.size() - 1), ldt.file);
  if (in.next() >= numeric.size()) in.fail_end("the file ends before the direct ratios");
  const auto ratios = tokens.numbers(10, "direct ratios (line 27)");
  std::copy(ratios.begin(), ratios.end(), ldt.direct_ratios.begin());
  ldt.c_deg = tokens.numbers(static_cast<std::size_t>(ldt.c_count), "C angles (line 28)");
  for (std::size_t i = 0; i < ldt.c_deg.size(); ++i) {
    if (ldt.c_deg[i] < 0 || ldt.c_deg[i] >= 360)
      tokens.fail("C angles must lie in 0..360 (exclusive), found " + format_number(ldt.c_deg[i]));
    if (i > 0 && !(ldt.c_deg[i - 1] < ldt.c_deg[i]))
      tokens.fail("the C angles must strictly increase");
  }
  ldt.gamma_deg =
      tokens.numbers(static_cast<std::size_t>(ldt.gamma_count), "gamma angles (line 29)");
  for (std::size_t i = 0; i < ldt.gamma_deg.size(); ++i) {
    if (ldt.gamma_deg[i] < 0 || ldt.gamma_deg[i] > 180)
      tokens.fail("gamma angles must lie in 0..180, found " + format_number(ldt.gamma_deg[i]));
    if (i > 0 && !(ldt.gamma_deg[i - 1] < ldt.gamma_deg[i]))
      tokens.fail("the gamma angles must strictly increase");
  }

  // The stored planes fix the symmetry's range; check the C list agrees with it.
  const std::vector<double> stored = ldt.stored_c_deg();
  const std::pair<double, double> expected[] = {{0, 0}, {0, 0}, {0, 180}, {90, 270}, {0, 90}};
  if (ldt.symmetry >= 2 && (stored.front() != expected[ldt.symmetry].first ||
                            stored.back() != expected[ldt.symmetry].second))
    tokens.fail("Isym " + std::to_string(ldt.symmetry) + " stores the planes C" +
                format_number(expected[ldt.symmetry].first) + "..C" +
                format_number(expected[ldt.symmetry].second) + ", but the C angles give C" +
                format_number(stored.front()) + "..C" + format_number(stored.back()));
  if (ldt.symmetry == 0 && ldt.c_deg.front() != 0)
    tokens.fail("the first C angle must be 0, found " + format_number(ldt.c_deg.front()));
  for (std::size_t k = 0; k < stored.size(); ++k) {
    ldt.cd_per_klm.push_back(tokens.numbers(static_cast<std::size_t>(ldt.gamma_count),
                                            "intensities of plane C" + format_number(stored[k])));
    for (double value : ldt.cd_per_klm.back())
      if (value < 0) tokens.fail("an intensity is negative (" + format_number(value) + ")");
  }
  if (!tokens.at_end())
    tokens.fail_next("unexpected text after the last intensity (Isym " +
                     std::to_string(ldt.symmetry) + " stores " + std::to_string(stored.size()) +
                     " planes of " + std::to_string(ldt.gamma_count) + " values)");
  return ldt;
}

EulumdatFile read_eulumdat(const std::filesystem::path& path) {
  return parse_eulumdat(detail::read_file_text(path), path);
}

PhotometricGrid candela_grid(const EulumdatFile& ldt, std::size_t lamp_set) {
  if (lamp_set >= ldt.lamp_sets.size())
    throw InputError(ldt.file, "",
                     "lamp set " + std::to_string(lamp_set) + " does not exist (the file has " +
                         std::to_string(ldt.lamp_sets.size()) + ", numbered from 0)");
  const double scale = ldt.intensity_factor * ldt.lamp_sets[lamp_set].flux / 1000.0;
  PhotometricGrid grid;
  grid.type = PhotometricType::c;
  grid.horizontal_deg = ldt.stored_c_deg();
  grid.vertical_deg = ldt.gamma_deg;
  for (const auto& plane : ldt.cd_per_klm) {
    grid.candela.emplace_back();
    for (double value : plane) grid.candela.back().push_back(value * scale);
  }
  if (ldt.symmetry == 0) {
    // Close the circle with C = 360, so that the grid reads as LM-63's 0-360 range.
    grid.horizontal_deg.push_back(360);
    grid.candela.push_back(grid.candela.front());
  }
  if (ldt.symmetry == 1 && grid.horizontal_deg.size() != 1) grid.horizontal_deg = {0};
  return grid;
}

std::shared_ptr<const TableDistribution> load_eulumdat(const std::filesystem::path& path,
                                                       Interpolation interpolation,
                                                       std::size_t lamp_set, double multiplier) {
  PhotometricGrid grid = candela_grid(read_eulumdat(path), lamp_set);
  for (auto& block : grid.candela)
    for (double& value : block) value *= multiplier;
  return std::make_shared<TableDistribution>(std::move(grid), interpolation);
}

IesFile to_ies(const EulumdatFile& ldt, std::size_t lamp_set) {
  const PhotometricGrid grid = candela_grid(ldt, lamp_set);
  const LampSet& set = ldt.lamp_sets[lamp_set];
  std::vector<std::string> labels = {
      "[TEST] " + ldt.report,
      "[MANUFAC] " + ldt.company,
      "[LUMINAIRE] " + ldt.luminaire_name,
      "[LUMCAT] " + ldt.luminaire_number,
      "[LAMP] " + std::to_string(std::abs(set.count)) + " x " + set.type,
      "[OTHER] converted by penumbra from EULUMDAT " + ldt.file_name + " (lamp set " +
          std::to_string(lamp_set) + ", " + format_number(set.flux) + " lm)"};
  IesFile ies = ies_from_grid(grid, labels);
  // LM-63 length runs along C0-C180, width along C90-C270; EULUMDAT gives millimetres.
  ies.units_type = 2;
  ies.length = ldt.area_length / 1000;
  ies.width = (ldt.area_width == 0 ? -ldt.area_length : ldt.area_width) / 1000;
  if (ldt.area_width == 0) ies.length = -ldt.area_length / 1000;  // round: negative diameter
  ies.height = ldt.area_height[0] / 1000;
  ies.input_watts = set.watts;
  return ies;
}

}  // namespace penumbra::photometry
