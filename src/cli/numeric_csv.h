#pragma once
// Reading CSV files of numbers whose columns are found by name in the header line
// (DESIGN.md: "columns are found by name, so new columns may be added at the end"):
// the points of `penumbra illuminance --points` and the targets of `relight --fit`.

#include <cstddef>
#include <string>
#include <vector>

namespace penumbra::cli {

struct NumericRow {
  std::size_t line;            // 1-based line number in the file
  std::vector<double> values;  // in the order of the names asked for, all finite
};

// reads file (what names it in messages, e.g. "points file"), returning the named columns
// of every non-blank line. Throws InputError naming the file, the line and the column.
std::vector<NumericRow> read_numeric_csv(const std::string& file,
                                         const std::vector<std::string>& names,
                                         const std::string& what);

// parses a comma-separated list of finite numbers given to option on the command line.
// Throws InputError naming the option.
std::vector<double> parse_number_list(const std::string& text, const std::string& option);

}  // namespace penumbra::cli
