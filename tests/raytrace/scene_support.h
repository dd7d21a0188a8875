#pragma once
// Small scenes for the ray tracer's tests, written as scene files and loaded through the
// ordinary loader so the tests exercise the same path as the command line.

#include <fstream>
#include <string>

#include "penumbra/scene/load_scene.h"
#include "support/fixtures.h"

namespace penumbra::test {

// loads a scene from the JSON text (a version-1 scene file written to a scratch directory).
inline Scene scene_from_json(const std::string& name, const std::string& json) {
  const auto path = scratch_dir("raytrace-" + name) / (name + ".json");
  std::ofstream(path) << json;
  return load_scene(path);
}

}  // namespace penumbra::test
