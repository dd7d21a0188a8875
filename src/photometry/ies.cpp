#include "penumbra/photometry/ies.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <ostream>

#include "number_format.h"
#include "penumbra/base/input_error.h"
#include "text_tokens.h"

namespace penumbra::photometry {
namespace {

using detail::TokenStream;

std::string upper(std::string text) {
  for (char& ch : text) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return text;
}

// returns whether line is the TILT line: "TILT=" at its start (blanks allowed around
// "="). A label such as "[TEST] TILT=NONE REPORT" or "TILT TEST" is not.
bool is_tilt_line(const std::string& line, std::string& value) {
  const std::string text = detail::trim(line);
  if (upper(text.substr(0, 4)) != "TILT") return false;
  std::size_t i = 4;
  while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
  if (i >= text.size() || text[i] != '=') return false;
  value = detail::trim(text.substr(i + 1));
  return true;
}

// reads the TILT data (LM-63: geometry, pair count, angles, factors).
void read_tilt_data(TokenStream& tokens, IesTilt& tilt) {
  tilt.lamp_to_luminaire_geometry = tokens.integer("the lamp-to-luminaire geometry");
  if (tilt.lamp_to_luminaire_geometry < 1 || tilt.lamp_to_luminaire_geometry > 3)
    tokens.fail("the lamp-to-luminaire geometry must be 1, 2 or 3, found " +
                std::to_string(tilt.lamp_to_luminaire_geometry));
  const int pairs = tokens.integer("the number of tilt angles");
  if (pairs < 1)
    tokens.fail("the number of tilt angles must be positive, found " + std::to_string(pairs));
  tilt.angles_deg = tokens.numbers(static_cast<std::size_t>(pairs), "tilt angles");
  tilt.factors = tokens.numbers(static_cast<std::size_t>(pairs), "tilt multiplying factors");
  for (std::size_t i = 1; i < tilt.angles_deg.size(); ++i)
    if (!(tilt.angles_deg[i - 1] < tilt.angles_deg[i])) tokens.fail("tilt angles must increase");
  for (double factor : tilt.factors)
    if (factor < 0) tokens.fail("a tilt multiplying factor is negative");
}

int positive_count(TokenStream& tokens, const std::string& what) {
  const int count = tokens.integer(what);
  if (count < 1) tokens.fail(what + " must be a positive integer, found " + std::to_string(count));
  return count;
}

void require_increasing(TokenStream& tokens, const std::vector<double>& angles,
                        const std::string& what) {
  for (std::size_t i = 1; i < angles.size(); ++i)
    if (!(angles[i - 1] < angles[i]))
      tokens.fail(what + " must strictly increase (" + detail::format_number(angles[i - 1]) +
                  " then " + detail::format_number(angles[i]) + ")");
}

const char* type_letter(int type) {
  return type == 1 ? "C" : type == 2 ? "B" : "A";
}

}  // namespace

std::string IesFile::keyword(const std::string& key) const {
  const std::string wanted = "[" + upper(key) + "]";
  for (const std::string& line : label_lines) {
    const std::string text = detail::trim(line);
    if (upper(text.substr(0, wanted.size())) == wanted)
      return detail::trim(text.substr(wanted.size()));
  }
  return "";
}

double IesFile::scale() const {
  return candela_multiplier * ballast_factor * (year < 2002 ? ballast_lamp_factor : 1.0);
}

IesFile parse_ies(const std::string& text, const std::filesystem::path& file) {
  IesFile ies;
  ies.file = file.string();
  const std::vector<std::string> lines = detail::split_lines(text);
  auto fail_at = [&](std::size_t line, const std::string& message) {
    throw InputError(ies.file, "line " + std::to_string(line), message);
  };
  if (lines.empty()) throw InputError(ies.file, "", "the file is empty");

  // The format line (absent in LM-63-1986, whose first line is already a label).
  std::size_t next = 0;
  const std::string first = upper(detail::trim(lines[0]));
  const std::pair<const char*, int> formats[] = {{"IESNA:LM-63-1995", 1995},
                                                 {"IESNA91", 1991},
                                                 {"IESNA:LM-63-2002", 2002},
                                                 {"IES:LM-63-2019", 2019},
                                                 {"IESNA:LM-63-2019", 2019}};
  for (const auto& [name, year] : formats)
    if (first.rfind(name, 0) == 0) {
      ies.format = detail::trim(lines[0]);
      ies.year = year;
      next = 1;
    }
  if (next == 0 && first.rfind("IES", 0) == 0 && first.find("LM-63") != std::string::npos)
    fail_at(1, "unknown LM-63 format line \"" + detail::trim(lines[0]) + "\"");

  // Keyword and label lines up to the TILT line.
  std::string tilt_value;
  while (next < lines.size() && !is_tilt_line(lines[next], tilt_value))
    ies.label_lines.push_back(lines[next++]);
  if (next == lines.size())
    throw InputError(ies.file, "line " + std::to_string(lines.size()),
                     "no TILT= line: this is not an LM-63 file, or it is truncated");
  const std::size_t tilt_line = next + 1;
  TokenStream tokens(lines, next + 1, ies.file);

  const std::string tilt_upper = upper(tilt_value);
  if (tilt_upper == "NONE") {
    ies.tilt.mode = "NONE";
  } else if (tilt_upper == "INCLUDE") {
    ies.tilt.mode = "INCLUDE";
    read_tilt_data(tokens, ies.tilt);
  } else if (tilt_value.empty()) {
    fail_at(tilt_line, "TILT= names nothing (expected NONE, INCLUDE or a file name)");
  } else {
    // A TILT file beside the photometric file holds the same data as TILT=INCLUDE.
    ies.tilt.mode = tilt_value;
    const std::filesystem::path tilt_path = file.parent_path() / tilt_value;
    std::string tilt_text;
    try {
      tilt_text = detail::read_file_text(tilt_path);
    } catch (const InputError&) {
      fail_at(tilt_line, "cannot read the TILT file " + tilt_path.string());
    }
    const std::vector<std::string> tilt_lines = detail::split_lines(tilt_text);
    TokenStream tilt_tokens(tilt_lines, 0, tilt_path.string());
    read_tilt_data(tilt_tokens, ies.tilt);
  }

  // Line 10 of LM-63-2002 (after TILT): lamps, lumens per lamp, candela multiplier,
  // counts, photometric type, units and the luminous opening.
  ies.lamp_count = positive_count(tokens, "the number of lamps");
  ies.lumens_per_lamp = tokens.number("the lumens per lamp");
  if (!(ies.lumens_per_lamp > 0) && ies.lumens_per_lamp != -1)
    tokens.fail("the lumens per lamp must be positive, or -1 for absolute photometry; found " +
                detail::format_number(ies.lumens_per_lamp));
  ies.candela_multiplier = tokens.number("the candela multiplier");
  if (!(ies.candela_multiplier > 0))
    tokens.fail("the candela multiplier must be positive, found " +
                detail::format_number(ies.candela_multiplier));
  const int vertical_count = positive_count(tokens, "the number of vertical angles");
  if (vertical_count < 2) tokens.fail("the number of vertical angles must be at least 2, found 1");
  const int horizontal_count = positive_count(tokens, "the number of horizontal angles");
  ies.photometric_type = tokens.integer("the photometric type");
  if (ies.photometric_type < 1 || ies.photometric_type > 3)
    tokens.fail("the photometric type must be 1 (C), 2 (B) or 3 (A), found " +
                std::to_string(ies.photometric_type));
  ies.units_type = tokens.integer("the units type");
  if (ies.units_type != 1 && ies.units_type != 2)
    tokens.fail("the units type must be 1 (feet) or 2 (metres), found " +
                std::to_string(ies.units_type));
  ies.width = tokens.number("the luminous opening width");
  ies.length = tokens.number("the luminous opening length");
  ies.height = tokens.number("the luminous opening height");

  ies.ballast_factor = tokens.number("the ballast factor");
  if (!(ies.ballast_factor > 0))
    tokens.fail("the ballast factor must be positive, found " +
                detail::format_number(ies.ballast_factor));
  ies.ballast_lamp_factor = tokens.number(ies.year < 2002 ? "the ballast-lamp photometric factor"
                                                          : "the future-use field");
  if (ies.year < 2002 && !(ies.ballast_lamp_factor > 0))
    tokens.fail("the ballast-lamp photometric factor must be positive");
  ies.input_watts = tokens.number("the input watts");

  ies.vertical_deg = tokens.numbers(static_cast<std::size_t>(vertical_count), "vertical angles");
  require_increasing(tokens, ies.vertical_deg, "the vertical angles");
  ies.horizontal_deg =
      tokens.numbers(static_cast<std::size_t>(horizontal_count), "horizontal angles");
  require_increasing(tokens, ies.horizontal_deg, "the horizontal angles");

  const std::string type = std::string("type ") + type_letter(ies.photometric_type);
  const double v_low = ies.photometric_type == 1 ? 0 : -90,
               v_high = ies.photometric_type == 1 ? 180 : 90;
  if (ies.vertical_deg.front() < v_low || ies.vertical_deg.back() > v_high)
    tokens.fail("the vertical angles of " + type + " photometry must lie in " +
                detail::format_number(v_low) + ".." + detail::format_number(v_high) + ", found " +
                detail::format_number(ies.vertical_deg.front()) + ".." +
                detail::format_number(ies.vertical_deg.back()));
  const PhotometricType grid_type = ies.photometric_type == 1   ? PhotometricType::c
                                    : ies.photometric_type == 2 ? PhotometricType::b
                                                                : PhotometricType::a;
  if (!horizontal_symmetry(ies.horizontal_deg, grid_type))
    tokens.fail("the horizontal angles " + detail::format_number(ies.horizontal_deg.front()) +
                ".." + detail::format_number(ies.horizontal_deg.back()) +
                " are not an LM-63 range for " + type +
                (ies.photometric_type == 1 ? " (0; 0-90; 0-180; 90-270; 0-360)"
                                           : " (-90..90, or 0..90 for lateral symmetry; at "
                                             "least two angles)"));

  for (int h = 0; h < horizontal_count; ++h) {
    ies.candela.push_back(tokens.numbers(
        static_cast<std::size_t>(vertical_count),
        "candela values of horizontal angle " + detail::format_number(ies.horizontal_deg[h])));
    for (double value : ies.candela.back())
      if (value < 0)
        tokens.fail("a candela value is negative (" + detail::format_number(value) + ")");
  }
  if (!tokens.at_end())
    tokens.fail_next("unexpected text after the last candela value (the counts say " +
                     std::to_string(vertical_count) + " x " + std::to_string(horizontal_count) +
                     " values)");
  return ies;
}

IesFile read_ies(const std::filesystem::path& path) {
  return parse_ies(detail::read_file_text(path), path);
}

PhotometricGrid candela_grid(const IesFile& ies) {
  PhotometricGrid grid;
  grid.type = ies.photometric_type == 1   ? PhotometricType::c
              : ies.photometric_type == 2 ? PhotometricType::b
                                          : PhotometricType::a;
  grid.horizontal_deg = ies.horizontal_deg;
  grid.vertical_deg = ies.vertical_deg;
  // Each value is multiplied once by the file's factors (never squared).
  const double scale = ies.scale();
  for (const auto& block : ies.candela) {
    grid.candela.emplace_back();
    for (double value : block) grid.candela.back().push_back(value * scale);
  }
  return grid;
}

void write_ies(std::ostream& out, const IesFile& ies) {
  // LM-63 lines end in CR LF; values wrap well inside the 132-character limit of 1995.
  const char* eol = "\r\n";
  auto write_values = [&](const std::vector<double>& values) {
    std::size_t width = 0;
    for (std::size_t i = 0; i < values.size(); ++i) {
      const std::string text = detail::format_number(values[i]);
      if (width > 0 && width + 1 + text.size() > 100) {
        out << eol;
        width = 0;
      }
      if (width > 0) {
        out << ' ';
        ++width;
      }
      out << text;
      width += text.size();
    }
    out << eol;
  };
  if (!ies.format.empty()) out << ies.format << eol;
  for (const std::string& line : ies.label_lines) out << line << eol;
  if (ies.tilt.mode == "NONE") {
    out << "TILT=NONE" << eol;
  } else {
    out << "TILT=INCLUDE" << eol << ies.tilt.lamp_to_luminaire_geometry << eol
        << ies.tilt.angles_deg.size() << eol;
    write_values(ies.tilt.angles_deg);
    write_values(ies.tilt.factors);
  }
  using detail::format_number;
  out << ies.lamp_count << ' ' << format_number(ies.lumens_per_lamp) << ' '
      << format_number(ies.candela_multiplier) << ' ' << ies.vertical_deg.size() << ' '
      << ies.horizontal_deg.size() << ' ' << ies.photometric_type << ' ' << ies.units_type << ' '
      << format_number(ies.width) << ' ' << format_number(ies.length) << ' '
      << format_number(ies.height) << eol;
  out << format_number(ies.ballast_factor) << ' ' << format_number(ies.ballast_lamp_factor) << ' '
      << format_number(ies.input_watts) << eol;
  write_values(ies.vertical_deg);
  write_values(ies.horizontal_deg);
  for (const auto& block : ies.candela) write_values(block);
}

std::shared_ptr<const TableDistribution> load_ies(const std::filesystem::path& path,
                                                  Interpolation interpolation, double multiplier) {
  const IesFile ies = read_ies(path);
  PhotometricGrid grid = candela_grid(ies);
  if (interpolation == Interpolation::cosine && grid.type != PhotometricType::c)
    throw InputError(path.string(), "",
                     std::string("cosine interpolation (Nishita eq. 1) applies to gamma angles of "
                                 "type C photometry; this file is type ") +
                         type_letter(ies.photometric_type));
  for (auto& block : grid.candela)
    for (double& value : block) value *= multiplier;
  return std::make_shared<TableDistribution>(std::move(grid), interpolation);
}

IesFile ies_from_grid(const PhotometricGrid& grid, const std::vector<std::string>& label_lines) {
  IesFile ies;
  ies.format = "IESNA:LM-63-2002";
  ies.year = 2002;
  ies.label_lines = label_lines;
  ies.photometric_type = grid.type == PhotometricType::c   ? 1
                         : grid.type == PhotometricType::b ? 2
                                                           : 3;
  ies.vertical_deg = grid.vertical_deg;
  ies.horizontal_deg = grid.horizontal_deg;
  ies.candela = grid.candela;
  return ies;
}

}  // namespace penumbra::photometry
