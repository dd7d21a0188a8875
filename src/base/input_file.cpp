// Reading input files within their limits (include/penumbra/base/input_file.h).

#include "penumbra/base/input_file.h"

#include <fstream>

#include <nlohmann/json.hpp>

#include "penumbra/base/input_error.h"

namespace penumbra {

std::uintmax_t check_input_file(const std::filesystem::path& path, const std::string& what,
                                std::uintmax_t limit) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status))
    throw InputError(path.string(), "", "cannot open the " + what + ": it does not exist");
  if (std::filesystem::is_directory(status))
    throw InputError(path.string(), "", "cannot open the " + what + ": it is a directory");
  if (!std::filesystem::is_regular_file(status))
    throw InputError(path.string(), "",
                     "cannot open the " + what + ": it is not a regular file (a device or a pipe)");
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error)
    throw InputError(path.string(), "", "cannot read the " + what + ": " + error.message());
  if (size > limit)
    throw InputError(path.string(), "",
                     "the " + what + " is " + std::to_string(size) + " bytes, over the limit of " +
                         std::to_string(limit) + " (docs/reliability.md, \"Limits\")");
  return size;
}

std::string read_input_file(const std::filesystem::path& path, const std::string& what,
                            std::uintmax_t limit) {
  const std::uintmax_t size = check_input_file(path, what, limit);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "", "cannot open the " + what);
  std::string content(static_cast<std::size_t>(size), '\0');
  in.read(content.data(), static_cast<std::streamsize>(size));
  // a file that changed size since: read what is there now
  content.resize(static_cast<std::size_t>(in.gcount()));
  if (in.bad()) throw InputError(path.string(), "", "cannot read the " + what);
  return content;
}

namespace {

// returns "line L, column C" of a byte offset in text.
std::string line_and_column(const std::string& text, std::size_t byte) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// returns the byte offset where an array or object opens more than max_json_depth deep
// outside strings, or npos. A scan of the brackets before parsing: nlohmann's parser
// callback could count the depth too, but parsing with it took the 10,000-building city's
// 3.8 MB three times as long (0.17 s instead of 0.06 s; the scan takes 0.004 s).
std::size_t too_deep_at(const std::string& text) {
  int depth = 0;
  bool in_string = false, escaped = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > max_json_depth) return i;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return std::string::npos;
}

}  // namespace

nlohmann::json parse_input_json(const std::string& text, const std::string& file) {
  const std::size_t deep = too_deep_at(text);
  if (deep != std::string::npos)
    throw InputError(file, line_and_column(text, deep),
                     "arrays and objects nested more than " + std::to_string(max_json_depth) +
                         " deep (docs/reliability.md, \"Limits\")");
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& error) {
    throw InputError(file, line_and_column(text, error.byte == 0 ? 0 : error.byte - 1),
                     std::string("malformed JSON: ") + error.what());
  } catch (const nlohmann::json::exception& error) {
    // Numbers too large for a double (1e999) are refused while parsing, without a position.
    throw InputError(file, "", std::string("malformed JSON: ") + error.what());
  }
}

}  // namespace penumbra
