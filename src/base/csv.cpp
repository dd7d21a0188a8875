#include "penumbra/base/csv.h"

#include <charconv>

namespace penumbra {

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string format_double(double value) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

CsvWriter::CsvWriter(std::ostream& out, const std::vector<std::string>& columns) : out_(out) {
  for (const std::string& column : columns) text(column);
  end_row();
}

void CsvWriter::separate() {
  if (row_started_) out_ << ',';
  row_started_ = true;
}

CsvWriter& CsvWriter::text(const std::string& value) {
  separate();
  out_ << csv_field(value);
  return *this;
}

CsvWriter& CsvWriter::number(double value) {
  separate();
  out_ << format_double(value);
  return *this;
}

CsvWriter& CsvWriter::integer(long long value) {
  separate();
  out_ << value;
  return *this;
}

CsvWriter& CsvWriter::boolean(bool value) {
  separate();
  out_ << (value ? "true" : "false");
  return *this;
}

CsvWriter& CsvWriter::blank() {
  separate();
  return *this;
}

void CsvWriter::end_row() {
  out_ << '\n';
  row_started_ = false;
}

}  // namespace penumbra
