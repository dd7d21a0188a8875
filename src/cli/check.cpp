// penumbra check SCENE --golden loops.json: recompute the shadows and compare them
// exactly (rational coordinates) with a golden shadow loops file.

#include <iostream>
#include <memory>
#include <set>

#include "penumbra/base/input_error.h"
#include "penumbra/base/input_file.h"
#include "penumbra/io/shadow_compare.h"
#include "penumbra/io/shadow_json.h"
#include "penumbra/scene/load_scene.h"
#include "penumbra/scene/object_selection.h"
#include "penumbra/shadow/shadow_map.h"
#include "verbs.h"

namespace penumbra::cli {
namespace {

nlohmann::json read_golden(const std::string& path) {
  return parse_input_json(read_input_file(path, "golden file", file_limits::document), path);
}

int run_check(const std::string& scene_path, const std::string& golden_path,
              const std::string& receivers) {
  const nlohmann::json golden = read_golden(golden_path);
  const Scene& scene = load_scene_until_exit(scene_path);

  // Recompute as the golden file was computed: its culling and its lights.
  ShadowOptions options;
  if (golden.contains("culling") && golden["culling"].is_object()) {
    const auto& culling = golden["culling"];
    if (culling.contains("range_lux")) options.range_lux = culling["range_lux"].get<double>();
    options.range_fraction = culling.value("range_fraction", options.range_fraction);
    options.full_scale_lux = culling.value("full_scale_lux", options.full_scale_lux);
  }
  options.joint_umbrae = golden.value("joint_umbrae", false);
  const io::ShadowJsonOptions json_options = io::json_options_of(options, true);
  std::set<std::string> lights;
  if (golden.contains("lights") && golden["lights"].is_array())
    for (const auto& light : golden["lights"]) lights.insert(light.value("name", ""));
  if (lights.size() == 1 && scene.find_light(*lights.begin())) options.light = *lights.begin();

  // --receivers: those objects' faces only, compared with the golden file's faces of them.
  std::set<std::string> objects;
  if (!receivers.empty()) {
    const std::vector<std::size_t> selected = select_objects(scene, receivers);
    for (std::size_t object : selected) objects.insert(scene.objects[object].face_owner());
    options.receivers = faces_of_objects(scene, selected);
  }
  ShadowResult result = compute_shadows(scene, options);
  std::vector<LightShadows> kept;
  for (LightShadows& light : result.lights)
    if (lights.empty() || lights.count(scene.lights[light.light].name))
      kept.push_back(std::move(light));
  result.lights = std::move(kept);

  const auto differences =
      io::compare_shadow_json(golden, io::shadow_json(scene, result, json_options), golden_path,
                              receivers.empty() ? nullptr : &objects);
  for (const std::string& line : differences) std::cout << line << "\n";
  if (!differences.empty()) {
    std::cout << "check: " << differences.size() << " difference"
              << (differences.size() == 1 ? "" : "s") << " from " << golden_path << "\n";
    return 1;
  }
  std::cout << "check: " << result.receivers.size() << " faces, " << result.lights.size()
            << " light" << (result.lights.size() == 1 ? "" : "s") << ": equal to " << golden_path
            << "\n";
  return 0;
}

}  // namespace

void register_check(CLI::App& app) {
  CLI::App* verb =
      app.add_subcommand("check", "recompute shadows and compare exactly with a golden file");
  auto scene = std::make_shared<std::string>();
  auto golden = std::make_shared<std::string>();
  verb->add_option("SCENE", *scene, "scene file (JSON)")->required();
  verb->add_option("--golden", *golden, "golden shadow loops file written with --exact")
      ->required();
  auto receivers = std::make_shared<std::string>();
  verb->add_option("--receivers", *receivers,
                   "check only the faces of these objects: NAME[,NAME...], shell patterns");
  verb->callback(
      [scene, golden, receivers] { exit_status() = run_check(*scene, *golden, *receivers); });
}

}  // namespace penumbra::cli
