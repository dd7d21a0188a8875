// Fuzz target "scene": the scene loader (docs/scene-format.md) on arbitrary JSON text, read
// as if it were a file of fixtures/scenes/, so that a seed's relative references (meshes,
// photometric files, patch files) resolve to the fixtures they name.

#include "fuzz_target.h"
#include "penumbra/scene/load_scene.h"

PENUMBRA_FUZZ_TARGET(scene) {
  static const std::filesystem::path file =
      std::filesystem::path(PENUMBRA_SOURCE_DIR) / "fixtures" / "scenes" / "fuzz.json";
  penumbra::parse_scene(penumbra::fuzz::text_of(data, size), file);
}
