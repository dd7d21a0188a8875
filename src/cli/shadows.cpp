// penumbra shadows SCENE: exact shadow polygons per face and light (Nishita 1985
// sections 3.1-3.2) as JSON, with SVG, DXF and CSV outputs for CAD users.

#include <chrono>
#include <iostream>
#include <memory>
#include <vector>

#include "penumbra/base/atomic_file.h"
#include "penumbra/base/input_error.h"
#include "penumbra/io/shadow_drawing.h"
#include "penumbra/io/shadow_json.h"
#include "penumbra/scene/load_scene.h"
#include "penumbra/scene/object_selection.h"
#include "penumbra/shadow/shadow_map.h"
#include "shadow_diagram.h"
#include "verbs.h"

namespace penumbra::cli {
namespace {

struct ShadowsArguments {
  std::string scene;
  std::string output;
  bool exact = false;
  std::string light;
  std::string svg;
  std::string view = "top";
  bool loops = false;
  std::string dxf;
  std::string report;
  double range_fraction = 1.0 / 256;
  double full_scale_lux = 500;
  double range_lux = 0;
  bool stats = false;
  std::string receivers;
  std::string times;
  std::string dask;
  bool joint_umbrae = false;
};

int run_shadows(const ShadowsArguments& arguments) {
  const auto view = io::parse_svg_view(arguments.view);
  if (!view) throw InputError("", "--view", "expected top, camera or faces");
  using Clock = std::chrono::steady_clock;
  const auto seconds = [](Clock::time_point from, Clock::time_point to) {
    return std::chrono::duration<double>(to - from).count();
  };
  const auto started = Clock::now();
  const Scene& scene = load_scene_until_exit(arguments.scene);
  const auto loaded = Clock::now();
  for (const std::string& warning : scene.warnings)
    std::cerr << "penumbra: warning: " << warning << "\n";
  if (*view == io::SvgView::camera && !arguments.svg.empty() && !scene.camera)
    throw InputError(arguments.scene, "camera", "--view camera needs a camera in the scene");

  ShadowOptions options;
  if (!arguments.light.empty()) options.light = arguments.light;
  options.range_fraction = arguments.range_fraction;
  options.full_scale_lux = arguments.full_scale_lux;
  if (arguments.range_lux > 0) options.range_lux = arguments.range_lux;
  if (!arguments.receivers.empty())
    options.receivers = faces_of_objects(scene, select_objects(scene, arguments.receivers));
  options.joint_umbrae = arguments.joint_umbrae;
  if (!arguments.times.empty()) {
    // A shadow diagram: JSON and a plan-view SVG over several times (shadow_diagram.h).
    for (const auto& [given, name] :
         {std::pair{!arguments.dxf.empty(), "--dxf"},
          std::pair{!arguments.report.empty(), "--report"}, std::pair{arguments.loops, "--loops"},
          std::pair{arguments.view != "top", "--view"}})
      if (given) throw InputError("", name, "is for one time, not with --times");
    return run_shadow_diagram(
        scene, {arguments.scene, arguments.light, arguments.times, arguments.output, arguments.svg,
                arguments.exact, options, arguments.dask});
  }
  if (!arguments.dask.empty()) {
    throw InputError("", "--dask", "is for a shadow diagram (--times) here");
  }
  const ShadowResult& result = keep_until_exit(compute_shadows(scene, options));
  const auto shaded = Clock::now();
  for (const std::string& warning : result.warnings)
    std::cerr << "penumbra: warning: " << warning << "\n";

  const io::ShadowJsonOptions json_options = io::json_options_of(options, arguments.exact);
  // Every output streams face by face: the document is never held whole.
  std::vector<std::unique_ptr<AtomicFile>> files;
  std::vector<std::unique_ptr<io::ShadowDocumentSink>> writers;
  const auto file = [&](const std::string& path) -> std::ostream& {
    files.push_back(std::make_unique<AtomicFile>(path));
    return files.back()->stream();
  };
  if (arguments.output.empty() || arguments.output == "-")
    writers.push_back(std::make_unique<io::ShadowJsonWriter>(std::cout));
  else
    writers.push_back(std::make_unique<io::ShadowJsonWriter>(file(arguments.output)));
  if (!arguments.svg.empty())
    writers.push_back(std::make_unique<io::ShadowSvgWriter>(file(arguments.svg), *view,
                                                            scene.camera, arguments.loops));
  if (!arguments.dxf.empty())
    writers.push_back(std::make_unique<io::ShadowDxfWriter>(file(arguments.dxf)));
  if (!arguments.report.empty())
    writers.push_back(std::make_unique<io::ShadowCsvWriter>(file(arguments.report)));
  std::vector<io::ShadowDocumentSink*> sinks;
  for (const auto& writer : writers) sinks.push_back(writer.get());
  io::stream_shadow_document(scene, result, json_options, sinks);
  for (const auto& finished : files) finished->commit();
  const auto written = Clock::now();

  if (arguments.stats)
    for (const LightShadows& light : result.lights) {
      const ShadowStats& s = light.stats;
      std::cerr << "light " << scene.lights[light.light].name << ": " << s.faces << " faces, "
                << s.faces_away << " facing away, " << s.beyond_range
                << " beyond the sphere of lighting";
      if (s.radius) std::cerr << " (radius " << *s.radius << " m)";
      std::cerr << "; pairs tested " << s.pairs_tested << " of " << s.pairs_possible << ", "
                << s.pairs_shadowing << " with a shadow; " << s.seconds << " s\n";
    }
  if (arguments.stats)
    std::cerr << "time: load " << seconds(started, loaded) << " s, shadows "
              << seconds(loaded, shaded) << " s, outputs " << seconds(shaded, written) << " s\n";
  return 0;
}

}  // namespace

void register_shadows(CLI::App& app) {
  CLI::App* verb = app.add_subcommand(
      "shadows", "exact shadow polygons per face and light (JSON, SVG, DXF, CSV)");
  auto arguments = std::make_shared<ShadowsArguments>();
  verb->add_option("SCENE", arguments->scene, "scene file (JSON)")->required();
  verb->add_option("-o,--output", arguments->output,
                   "shadow loops JSON (default: standard output)");
  verb->add_flag("--exact", arguments->exact,
                 "add exact rational coordinates (\"p/q\") under \"exact\" keys");
  verb->add_option("--light", arguments->light, "only the light of this name");
  verb->add_option("--svg", arguments->svg, "SVG drawing of faces and shadows");
  verb->add_flag("--joint-umbrae", arguments->joint_umbrae,
                 "linear sources: exact umbrae where occluders hide the tube together, with "
                 "conic edges (JSON \"arcs\"; docs/linear-shadows.md)");
  verb->add_flag("--loops", arguments->loops,
                 "SVG: draw the raw penumbra and umbra loops of linear sources with arrows");
  verb->add_option("--view", arguments->view,
                   "SVG view: top (plan), camera, or faces (one panel each)")
      ->check(CLI::IsMember({"top", "camera", "faces"}));
  verb->add_option("--dxf", arguments->dxf,
                   "DXF file: closed LWPOLYLINEs on layers per light and kind");
  verb->add_option("--report", arguments->report,
                   "CSV: shaded area and percentage per face and light");
  verb->add_option("--range-fraction", arguments->range_fraction,
                   "sphere of lighting: threshold illuminance as a fraction of the display's "
                   "full scale (default 1/256; 0: no range culling)")
      ->check(CLI::NonNegativeNumber);
  verb->add_option("--full-scale-lux", arguments->full_scale_lux,
                   "sphere of lighting: the display's full scale in lux (default 500, as "
                   "`penumbra lid info`)")
      ->check(CLI::PositiveNumber);
  verb->add_option(
          "--range-lux", arguments->range_lux,
          "sphere of lighting: absolute threshold illuminance in lux (overrides the fraction)")
      ->check(CLI::PositiveNumber);
  verb->add_option("--receivers", arguments->receivers,
                   "only the faces of these objects: NAME[,NAME...], each a shell pattern "
                   "(e.g. ground or 'building1*'); the others still cast shadows");
  verb->add_option("--times", arguments->times,
                   "shadow diagram of the scene's sun: FROM,TO,STEP (e.g. "
                   "2026-03-21T09:00,2026-03-21T15:00,1h) or T1,T2,...; JSON with a time axis "
                   "and a plan-view SVG with a layer per time");
  verb->add_option("--dask", arguments->dask,
                   "with --times: compute the times on the Dask cluster of this scheduler "
                   "(tcp://host:8786); the outputs are those of one process (docs/python.md)");
  verb->add_flag("--stats", arguments->stats,
                 "print faces, pairs tested and time per light on stderr");
  verb->callback([arguments] { exit_status() = run_shadows(*arguments); });
}

}  // namespace penumbra::cli
