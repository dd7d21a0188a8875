#pragma once
// The one CSV writer of every verb (DESIGN.md: "CSV files have a header line; columns are
// found by name"): RFC 4180 quoting (a field with a comma, a quote or a line break is
// quoted, quotes doubled), so any object or light name round-trips, and one number format,
// the shortest text that reads back as the same double (std::to_chars).

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace penumbra {

// returns text as one CSV field: unchanged, or quoted with its quotes doubled.
std::string csv_field(const std::string& text);

// returns the shortest decimal text that reads back as value exactly ("nan", "inf" and
// "-inf" for the non-finite).
std::string format_double(double value);

// Writes a CSV table row by row: a header line first, then fields separated by commas and
// rows ended by '\n'.
class CsvWriter {
 public:
  // writes the header line of columns.
  CsvWriter(std::ostream& out, const std::vector<std::string>& columns);

  // === Fields of the current row, in column order

  CsvWriter& text(const std::string& value);  // quoted when needed
  CsvWriter& number(double value);            // shortest round-trip
  CsvWriter& integer(long long value);
  CsvWriter& boolean(bool value);  // true / false
  CsvWriter& blank();              // an empty field

  // ends the current row.
  void end_row();

 private:
  void separate();

  std::ostream& out_;
  bool row_started_ = false;
};

}  // namespace penumbra
