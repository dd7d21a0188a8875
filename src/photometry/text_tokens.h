#pragma once
// Private helpers of the photometric file readers: text split into lines, and a
// stream of numeric tokens that remembers the line each came from, so that every
// error names the file and line.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace penumbra::photometry::detail {

// returns the lines of text without their terminators (LF, CR LF or CR).
std::vector<std::string> split_lines(const std::string& text);

// reads the whole file at path; throws InputError when it cannot.
std::string read_file_text(const std::filesystem::path& path);

// returns text without leading and trailing blanks.
std::string trim(const std::string& text);

class TokenStream {
 public:
  // reads whitespace-separated tokens from lines[first_line..] (0-based index);
  // messages name file and 1-based line numbers.
  TokenStream(const std::vector<std::string>& lines, std::size_t first_line, std::string file);

  // returns the next token as a finite number; what names it in messages
  // ("the candela multiplier"). Throws InputError when the text ends or the token is
  // not a number.
  double number(const std::string& what);
  // returns the next token as an integer (a number with no fractional part).
  int integer(const std::string& what);
  // reads count numbers.
  std::vector<double> numbers(std::size_t count, const std::string& what);

  bool at_end();
  // the 1-based line of the token last read (or of the end of the text).
  std::size_t line() const { return line_ + 1; }
  // throws InputError at the current line.
  [[noreturn]] void fail(const std::string& message) const;
  // throws InputError at the line of the next unread token.
  [[noreturn]] void fail_next(const std::string& message);

 private:
  bool advance();  // moves to the next token; false at the end of the text

  const std::vector<std::string>& lines_;
  std::string file_;
  std::size_t line_;
  std::size_t column_ = 0;
  std::string token_;
  bool pending_ = false;
};

}  // namespace penumbra::photometry::detail
