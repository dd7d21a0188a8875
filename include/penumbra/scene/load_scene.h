#pragma once
// Reads a version-1 scene file (docs/scene-format.md). Every problem is an
// InputError naming the file, the JSON path and what is wrong.

#include <filesystem>
#include <string>

#include "penumbra/scene/scene.h"

namespace penumbra {

// loads the scene file at path.
Scene load_scene(const std::filesystem::path& path);

// parses scene text as if it were read from file (relative paths resolve beside file).
Scene parse_scene(const std::string& text, const std::filesystem::path& file);

}  // namespace penumbra
