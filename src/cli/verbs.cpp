#include "verbs.h"

#include <iostream>
#include <string>

#include "penumbra/base/input_error.h"
#include "penumbra/scene/load_scene.h"

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

std::vector<std::shared_ptr<void>>& kept_until_exit() {
  static auto* kept = new std::vector<std::shared_ptr<void>>;  // never destroyed, on purpose
  return *kept;
}

const Scene& load_scene_until_exit(const std::string& path) {
  return keep_until_exit(load_scene(path));
}

}  // namespace penumbra::cli
