// Fuzz target "model": the mesh importer (docs/scene-format.md, "Mesh import") on arbitrary
// files of each format it is used for. The first byte chooses the format (the file's
// extension, which is how Assimp chooses its reader); the rest is the file. The model is
// loaded the way a scene loads it, as a mesh object of a scene, so that placement, face
// merging and the convex pieces run on what the importer returns.

#include <array>

#include "fuzz_target.h"
#include "penumbra/scene/load_scene.h"

PENUMBRA_FUZZ_TARGET(model) {
  static constexpr std::array<const char*, 6> extensions = {"obj", "stl", "ply",
                                                            "off", "glb", "gltf"};
  if (size == 0) return;
  const std::string name = std::string("model.") + extensions[data[0] % extensions.size()];
  const std::filesystem::path model = penumbra::fuzz::scratch_file(name, data + 1, size - 1);
  const std::string scene =
      R"({"penumbra": 1, "objects": [{"name": "m", "mesh": ")" + name +
      R"("}], "lights": [{"name": "l", "point": [0, 0, 10], "candela": 100}]})";
  penumbra::parse_scene(scene, model.parent_path() / "scene.json");
}
