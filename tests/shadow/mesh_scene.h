#pragma once
// The mesh objects of a scene file, read from its JSON by the test itself (not through the
// scene loader), for the mesh oracle: {"name": "house", "mesh": "house.obj", "up": "y",
// "scale": 0.001, "transform": [16 numbers, row-major], "snap": 1e-6}, every key but
// "mesh" optional. The path is relative to the scene file; the placement keys map one to
// one onto penumbra::Placement (docs/scene-format.md, "Placement"), and the model's exact
// planar faces come from import_model. An object's default name is its kind followed by
// its index, as for every object ("mesh3"). The rest of the scene (convex objects, lights)
// comes from the scene loader, given the file without its mesh objects.

#include <array>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "penumbra/scene/load_scene.h"
#include "penumbra/scene/model_import.h"

namespace penumbra::test {

struct MeshObject {
  std::string name;
  ImportedModel model;

  // returns the part an entry of the shadow JSON names ("house" for a model with one part,
  // "house/<part>" otherwise), or nullptr when it names none of this object's.
  const ModelPart* part(const std::string& object) const {
    if (object == name && model.parts.size() == 1) return &model.parts.front();
    if (object.rfind(name + "/", 0) != 0) return nullptr;
    const std::string part_name = object.substr(name.size() + 1);
    for (const ModelPart& part : model.parts)
      if (part.name == part_name) return &part;
    return nullptr;
  }
};

// returns the placement an object of the scene JSON asks for.
inline Placement placement_of(const nlohmann::json& object) {
  Placement placement;
  if (object.contains("up")) placement.y_up = object.at("up").get<std::string>() == "y";
  if (object.contains("scale")) placement.scale = object.at("scale").get<double>();
  if (object.contains("snap")) placement.snap = object.at("snap").get<double>();
  if (object.contains("transform")) {
    std::array<double, 16> matrix{};
    for (std::size_t k = 0; k < 16; ++k) matrix[k] = object.at("transform").at(k).get<double>();
    placement.transform = matrix;
  }
  return placement;
}

inline nlohmann::json read_json(const std::filesystem::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

// returns the mesh objects of the scene file, each imported as it asks.
inline std::vector<MeshObject> load_mesh_objects(const std::filesystem::path& scene_file) {
  const nlohmann::json scene = read_json(scene_file);
  std::vector<MeshObject> meshes;
  const nlohmann::json& objects =
      scene.contains("objects") ? scene.at("objects") : nlohmann::json::array();
  for (std::size_t k = 0; k < objects.size(); ++k) {
    const nlohmann::json& object = objects[k];
    if (!object.contains("mesh")) continue;
    const std::filesystem::path file = object.at("mesh").get<std::string>();
    const std::filesystem::path path = file.is_absolute() ? file : scene_file.parent_path() / file;
    meshes.push_back({object.value("name", "mesh" + std::to_string(k)),
                      import_model(path, placement_of(object))});
  }
  return meshes;
}

// returns the scene of the file without its mesh objects: its convex objects and lights.
// An unnamed object keeps the default name its index in the whole file gives it.
inline Scene load_scene_without_meshes(const std::filesystem::path& scene_file) {
  nlohmann::json scene = read_json(scene_file);
  if (scene.contains("objects")) {
    nlohmann::json kept = nlohmann::json::array();
    const nlohmann::json& objects = scene.at("objects");
    for (std::size_t k = 0; k < objects.size(); ++k) {
      if (objects[k].contains("mesh")) continue;
      nlohmann::json object = objects[k];
      for (const char* kind : {"box", "convex", "polygon", "sphere"})
        if (!object.contains("name") && object.contains(kind))
          object["name"] = kind + std::to_string(k);
      kept.push_back(object);
    }
    scene["objects"] = kept;
  }
  return parse_scene(scene.dump(), scene_file);
}

}  // namespace penumbra::test
