#pragma once
// The objects a command computes for (`--receivers NAME[,NAME...]`, DESIGN.md "Command
// line"): a comma-separated list of object names, each a shell-style pattern (`*` any run
// of characters, `?` one character, `[...]` one of a set; fnmatch(3) without flags), so
// that `building1*` names a group and `house/*` every part of a model.

#include <cstddef>
#include <string>
#include <vector>

#include "penumbra/scene/scene.h"

namespace penumbra {

// returns the indices (increasing) of the objects of scene whose names (for a piece of a mesh
// face, its part's name) match one of the patterns. Throws InputError naming option when the
// list is empty or a pattern matches no object.
std::vector<std::size_t> select_objects(const Scene& scene, const std::string& patterns,
                                        const std::string& option = "--receivers");

}  // namespace penumbra
