#include "numeric_csv.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <string_view>

#include "penumbra/base/input_error.h"
#include "penumbra/base/input_file.h"

namespace penumbra::cli {

namespace {

std::string_view trim(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r'))
    text.remove_suffix(1);
  return text;
}

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> fields;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(
        trim(line.substr(start, comma == std::string_view::npos ? comma : comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

}  // namespace

std::vector<NumericRow> read_numeric_csv(const std::string& file,
                                         const std::vector<std::string>& names,
                                         const std::string& what) {
  std::string expected;
  for (const std::string& name : names) expected += (expected.empty() ? "" : ",") + name;
  check_input_file(file, what, file_limits::table);
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file, "", "cannot open the " + what);
  std::string line;
  if (!std::getline(in, line))
    throw InputError(file, "line 1", "empty file: expected a header " + expected);
  if (line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // a UTF-8 byte order mark
  const std::vector<std::string_view> header = split(line);
  std::vector<std::size_t> column;
  for (const std::string& name : names) {
    std::size_t found = header.size();
    for (std::size_t k = 0; k < header.size(); ++k)
      if (header[k] == name) {
        if (found != header.size())
          throw InputError(file, "line 1", "column \"" + name + "\" appears twice");
        found = k;
      }
    if (found == header.size())
      throw InputError(file, "line 1",
                       "missing column \"" + name + "\" (the header must name " + expected + ")");
    column.push_back(found);
  }

  std::vector<NumericRow> rows;
  for (std::size_t number = 2; std::getline(in, line); ++number) {
    if (trim(line).empty()) continue;
    const std::string where = "line " + std::to_string(number);
    const std::vector<std::string_view> fields = split(line);
    if (fields.size() != header.size())
      throw InputError(file, where,
                       "expected " + std::to_string(header.size()) +
                           " fields as in the header, found " + std::to_string(fields.size()));
    NumericRow row{number, {}};
    for (std::size_t c = 0; c < names.size(); ++c) {
      const std::string_view field = fields[column[c]];
      double value = 0;
      const char* end = field.data() + field.size();
      auto [stop, error] = std::from_chars(field.data(), end, value);
      if (field.empty() || error != std::errc() || stop != end)
        throw InputError(file, where + ", column " + names[c],
                         "not a number: \"" + std::string(field) + "\"");
      if (!std::isfinite(value))
        throw InputError(file, where + ", column " + names[c],
                         "not a finite number: \"" + std::string(field) + "\"");
      row.values.push_back(value);
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

std::vector<double> parse_number_list(const std::string& text, const std::string& option) {
  std::vector<double> numbers;
  for (std::string_view field : split(text)) {
    double value = 0;
    const char* end = field.data() + field.size();
    auto [stop, error] = std::from_chars(field.data(), end, value);
    if (field.empty() || error != std::errc() || stop != end || !std::isfinite(value))
      throw InputError("<command line>", option, "not a number: \"" + std::string(field) + "\"");
    numbers.push_back(value);
  }
  return numbers;
}

}  // namespace penumbra::cli
