#pragma once
// Private helper: numbers written so that reading them back gives the same double.

#include <charconv>
#include <string>

namespace penumbra::photometry::detail {

// returns the shortest decimal text that reads back as exactly value.
inline std::string format_number(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

}  // namespace penumbra::photometry::detail
