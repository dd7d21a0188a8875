#include "penumbra/io/shadow_compare.h"

#include <map>
#include <sstream>

#include "penumbra/base/input_error.h"

namespace penumbra::io {
namespace {

using nlohmann::json;

class Comparison {
 public:
  explicit Comparison(std::string file) : file_(std::move(file)) {}

  // returns node[key], or throws InputError naming path.
  const json& need(const json& node, const std::string& key, const std::string& path) const {
    if (!node.is_object() || !node.contains(key))
      throw InputError(
          file_, path,
          "missing \"" + key + "\"" + (key == "exact" ? " (write golden files with --exact)" : ""));
    return node.at(key);
  }

  // the exact rings of a region, or of an occluder ("polygon"); of a curved region (shadows
  // --joint-umbrae), its canonical exact polygons (docs/shadows.md).
  json exact_region(const json& region, const std::string& path) const {
    if (region.is_object() && region.contains("axes"))
      return json{{"curved", need(region, "exact", path)}};
    json rings = json::array();
    const json& polygons = need(region, "polygons", path);
    for (std::size_t k = 0; k < polygons.size(); ++k)
      rings.push_back(need(polygons[k], "exact", path + ".polygons[" + std::to_string(k) + "]"));
    return rings;
  }

  static std::string summary(const json& region) {
    std::ostringstream text;
    const std::size_t count = region.contains("polygons") ? region["polygons"].size() : 0;
    text << count << " polygon" << (count == 1 ? "" : "s") << ", area "
         << region.value("area", 0.0);
    return text.str();
  }

  // compares the per-light entries of one face.
  void compare_light(const std::string& where, const json& golden, const json& computed,
                     const std::string& path, std::vector<std::string>& out) const {
    for (const char* flag : {"faces_away", "beyond_range"}) {
      const bool a = golden.value(flag, false), b = computed.value(flag, false);
      if (a != b)
        out.push_back(where + ": " + flag + " was " + (a ? "true" : "false") + ", now " +
                      (b ? "true" : "false"));
    }
    if (computed.value("beyond_range", false) || golden.value("beyond_range", false)) return;
    for (const char* kind : {"shadow", "umbra", "penumbra", "lit"}) {
      const json& a = need(golden, kind, path);
      if (exact_region(a, path + "." + kind) != exact_region(computed.at(kind), kind))
        out.push_back(where + ": " + kind + " differs: golden " + summary(a) + "; computed " +
                      summary(computed.at(kind)));
    }
    std::map<std::string, json> before, after;
    const json& occluders = need(golden, "occluders", path);
    for (std::size_t k = 0; k < occluders.size(); ++k) {
      const std::string at = path + ".occluders[" + std::to_string(k) + "]";
      before[need(occluders[k], "object", at).get<std::string>()] = need(occluders[k], "exact", at);
    }
    for (const json& o : computed.at("occluders")) after[o.at("object")] = o.at("exact");
    for (const auto& [name, polygon] : before) {
      const auto it = after.find(name);
      if (it == after.end())
        out.push_back(where + ": occluder " + name + " no longer casts a shadow");
      else if (it->second != polygon)
        out.push_back(where + ": the shadow polygon of occluder " + name + " differs");
    }
    for (const auto& [name, polygon] : after)
      if (!before.count(name)) out.push_back(where + ": occluder " + name + " now casts a shadow");
  }

 private:
  std::string file_;
};

std::string key_of(const json& face) {
  return face.at("object").get<std::string>() + " face " +
         std::to_string(face.at("face").get<int>());
}

}  // namespace

std::vector<std::string> compare_shadow_json(const json& golden, const json& computed,
                                             const std::string& golden_file,
                                             const std::set<std::string>* objects) {
  const Comparison compare(golden_file);
  if (!golden.is_object() || golden.value("penumbra_shadows", 0) != 1)
    throw InputError(golden_file, "", "not a shadow loops file (\"penumbra_shadows\": 1)");
  std::vector<std::string> out;

  std::map<std::string, std::pair<const json*, std::string>> golden_faces;
  const json& faces = compare.need(golden, "faces", "");
  for (std::size_t k = 0; k < faces.size(); ++k) {
    const std::string path = "faces[" + std::to_string(k) + "]";
    const json& object = compare.need(faces[k], "object", path);
    compare.need(faces[k], "face", path);
    if (objects && !objects->count(object.get<std::string>())) continue;
    golden_faces[key_of(faces[k])] = {&faces[k], path};
  }
  std::map<std::string, const json*> computed_faces;
  for (const json& face : computed.at("faces")) computed_faces[key_of(face)] = &face;

  for (const auto& [key, entry] : golden_faces) {
    const auto& [face, path] = entry;
    const auto it = computed_faces.find(key);
    if (it == computed_faces.end()) {
      out.push_back(key + ": in the golden file but not in the scene");
      continue;
    }
    const json& now = *it->second;
    if (compare.need(*face, "exact", path) != now.at("exact"))
      out.push_back(key + ": the face's plane or boundary differs");
    std::map<std::string, std::pair<const json*, std::string>> golden_lights;
    const json& lights = compare.need(*face, "lights", path);
    for (std::size_t k = 0; k < lights.size(); ++k) {
      const std::string at = path + ".lights[" + std::to_string(k) + "]";
      golden_lights[compare.need(lights[k], "light", at).get<std::string>()] = {&lights[k], at};
    }
    std::map<std::string, const json*> now_lights;
    for (const json& light : now.at("lights")) now_lights[light.at("light")] = &light;
    for (const auto& [name, light] : golden_lights) {
      const auto found = now_lights.find(name);
      if (found == now_lights.end())
        out.push_back(key + ": light " + name + " is in the golden file but not computed");
      else
        compare.compare_light(key + ", light " + name, *light.first, *found->second, light.second,
                              out);
    }
    for (const auto& [name, light] : now_lights)
      if (!golden_lights.count(name)) out.push_back(key + ": light " + name + " is new");
  }
  for (const auto& [key, face] : computed_faces)
    if (!golden_faces.count(key)) out.push_back(key + ": in the scene but not in the golden file");
  return out;
}

}  // namespace penumbra::io
