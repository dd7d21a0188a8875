// Fuzz target "patches": the bicubic Bézier patch files (.bpt, docs/bezier-patches.md) on
// arbitrary text, loaded as a scene's bezier_patches object (reading, placement and
// tessellation into convex pieces). Fuzzing wants many inputs rather than large ones: the
// tolerance is 2 cm rather than the default 1 mm, and a file whose tessellation would
// exceed 2,000 triangles is only read (the loader's own limit is 2,000,000, checked by
// tests/scene; near it one input takes minutes under the sanitizers, and 20,000 triangles of
// exact convex pieces already took 30 s, which libFuzzer reports as a hang).

#include "../../src/scene/bezier_objects.h"
#include "fuzz_target.h"
#include "penumbra/scene/load_scene.h"

PENUMBRA_FUZZ_TARGET(patches) {
  constexpr double tolerance = 0.02;
  const std::filesystem::path patches = penumbra::fuzz::scratch_file("patches.bpt", data, size);
  const std::vector<penumbra::BezierPatch> read = penumbra::detail::read_bezier_file(patches);
  const double segments = penumbra::detail::grid_segments(read, tolerance);
  if (2 * segments * segments * static_cast<double>(read.size()) > 2000) return;
  const std::string scene =
      R"({"penumbra": 1, "objects": [{"name": "p", "bezier_patches": "patches.bpt",
          "tolerance": 0.02}], "lights": [{"name": "l", "point": [0, 0, 10], "candela": 100}]})";
  penumbra::parse_scene(scene, patches.parent_path() / "scene.json");
}
