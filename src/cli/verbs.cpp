#include "verbs.h"

#include <iostream>
#include <string>

namespace penumbra::cli {

int& exit_status() {
  static int status = 0;
  return status;
}

double parse_exposure(const std::string& text) {
  if (text == "auto") return 0;
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return -1;
  }
  return used == text.size() && value > 0 ? value : -1;
}

}  // namespace penumbra::cli
