#include "text_tokens.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

#include "penumbra/base/input_error.h"
#include "penumbra/base/input_file.h"

namespace penumbra::photometry::detail {

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::string line;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char ch = text[i];
    if (ch == '\n' || ch == '\r') {
      lines.push_back(line);
      line.clear();
      if (ch == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
    } else {
      line += ch;
    }
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

std::string read_file_text(const std::filesystem::path& path) {
  return read_input_file(path, "photometric file", file_limits::photometric);
}

std::string trim(const std::string& text) {
  const char* blanks = " \t\f\v\x1a";  // \x1a: the DOS end-of-file mark some tools append
  const auto first = text.find_first_not_of(blanks);
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(blanks);
  return text.substr(first, last - first + 1);
}

TokenStream::TokenStream(const std::vector<std::string>& lines, std::size_t first_line,
                         std::string file)
    : lines_(lines), file_(std::move(file)), line_(first_line) {}

bool TokenStream::advance() {
  if (pending_) return true;
  while (line_ < lines_.size()) {
    const std::string& line = lines_[line_];
    while (column_ < line.size() && (std::isspace(static_cast<unsigned char>(line[column_])) ||
                                     line[column_] == '\x1a' || line[column_] == ','))
      ++column_;
    if (column_ < line.size()) {
      const std::size_t start = column_;
      while (column_ < line.size() && !std::isspace(static_cast<unsigned char>(line[column_])) &&
             line[column_] != ',')
        ++column_;
      token_ = line.substr(start, column_ - start);
      pending_ = true;
      return true;
    }
    if (line_ + 1 == lines_.size()) break;  // stay on the last line for messages
    ++line_;
    column_ = 0;
  }
  return false;
}

bool TokenStream::at_end() {
  return !advance();
}

double TokenStream::number(const std::string& what) {
  if (!advance()) fail("the file ends before " + what);
  pending_ = false;
  char* end = nullptr;
  const double value = std::strtod(token_.c_str(), &end);
  if (end == token_.c_str() || *end != '\0') fail(what + ": \"" + token_ + "\" is not a number");
  if (!std::isfinite(value)) fail(what + ": \"" + token_ + "\" is not a finite number");
  return value;
}

int TokenStream::integer(const std::string& what) {
  const double value = number(what);
  if (value != std::floor(value) || std::fabs(value) > 1e9)
    fail(what + " must be an integer, found " + token_);
  return static_cast<int>(value);
}

std::vector<double> TokenStream::numbers(std::size_t count, const std::string& what) {
  std::vector<double> values;
  // not count: a file may claim a billion angles and hold three (found by fuzzing); the
  // vector grows with what is really there, bounded by the file's size limit.
  values.reserve(std::min<std::size_t>(count, 4096));
  for (std::size_t i = 0; i < count; ++i) {
    if (!advance())
      fail("the file ends after " + std::to_string(i) + " of " + std::to_string(count) + " " +
           what);
    values.push_back(number(what));
  }
  return values;
}

void TokenStream::fail(const std::string& message) const {
  throw InputError(file_, "line " + std::to_string(line()), message);
}

void TokenStream::fail_next(const std::string& message) {
  advance();
  fail(message);
}

}  // namespace penumbra::photometry::detail
