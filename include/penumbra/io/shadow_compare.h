#pragma once
// Exact comparison of two shadow loops documents (DESIGN.md, "Shadow loops
// output"), for `penumbra check`: faces, lights, shadow and lit polygon sets and
// occluder polygons are compared through their exact rational coordinates, so a
// boundary moved by one ulp is a difference.

#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace penumbra::io {

// returns one readable line per difference between golden and computed (empty when
// they are equal). With objects, only the golden faces of those objects are compared
// (computed holds just theirs). Throws InputError (naming golden_file and the JSON path)
// when golden is not a shadow loops document written with exact coordinates.
std::vector<std::string> compare_shadow_json(const nlohmann::json& golden,
                                             const nlohmann::json& computed,
                                             const std::string& golden_file,
                                             const std::set<std::string>* objects = nullptr);

}  // namespace penumbra::io
