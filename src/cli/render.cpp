// penumbra render SCENE -o image.png: the scanline renderer with isolux colour belts
// (docs/render.md; Nishita 1985 sections 3.3, 4.2.2, 5 and Appendix A1).

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "penumbra/base/atomic_file.h"
#include "penumbra/base/csv.h"
#include "penumbra/base/input_error.h"
#include "penumbra/base/png.h"
#include "penumbra/base/tone_map.h"
#include "penumbra/basis/indirect_light.h"
#include "penumbra/illuminance/isolux.h"
#include "penumbra/render/isolux_belts.h"
#include "penumbra/render/scanline_renderer.h"
#include "penumbra/scene/load_scene.h"
#include "radiosity_options.h"
#include "verbs.h"

namespace penumbra::cli {
namespace {

struct RenderArguments {
  std::string scene;
  std::string output;
  int interval = 3;
  std::string exposure = "auto";
  bool isolux = false;
  bool joint_umbrae = false;
  std::string levels;
  std::string values;
  int width = 0;
  int height = 0;
  std::string indirect = "auto";
  RadiosityArguments radiosity;
  std::string tone = "filmic";
  std::string false_colour = "none";
};

// returns the levels of --levels, increasing and distinct; each must be a positive number.
std::vector<double> parse_levels(const std::string& text) {
  std::vector<double> levels;
  std::stringstream stream(text);
  std::string field;
  while (std::getline(stream, field, ',')) {
    double value = 0;
    const char* end = field.data() + field.size();
    const auto [stop, error] = std::from_chars(field.data(), end, value);
    if (field.empty() || error != std::errc() || stop != end || !std::isfinite(value) || value <= 0)
      throw InputError("", "--levels", "not a positive number: \"" + field + "\"");
    levels.push_back(value);
  }
  std::sort(levels.begin(), levels.end());
  levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
  return levels;
}

void write_values(const std::string& path, const Scene& scene, const render::RenderedImage& image) {
  write_atomically(path, [&](std::ostream& out) {
    CsvWriter csv(out, {"px", "py", "object", "face", "E", "L", "E_indirect"});
    for (int j = 0; j < image.height; ++j)
      for (int i = 0; i < image.width; ++i) {
        const std::size_t pixel = image.index(i, j);
        const long object = image.visibility.objects[pixel];
        csv.integer(i).integer(j);
        if (object >= 0)
          csv.text(scene.objects[static_cast<std::size_t>(object)].name)
              .integer(image.visibility.faces[pixel]);
        else
          csv.blank().blank();
        csv.number(image.illuminance[pixel])
            .number(image.luminance[pixel])
            .number(image.indirect[pixel]);
        csv.end_row();
      }
  });
}

int run_render(RenderArguments& args) {
  finish_radiosity_options(args.radiosity);
  if (args.isolux && args.false_colour != "none")
    throw InputError("<command line>", "--isolux, --false-colour",
                     "give one or the other: each draws its own legend");
  const double exposure_given = parse_exposure(args.exposure);
  std::vector<double> levels = parse_levels(args.levels);
  const Scene& scene = load_scene_until_exit(args.scene);
  for (const std::string& warning : scene.warnings)
    std::cerr << "penumbra: warning: " << warning << "\n";
  if (!scene.camera) throw InputError(args.scene, "camera", "render needs a camera in the scene");
  Camera camera = *scene.camera;
  if (args.width > 0) camera.width = args.width;
  if (args.height > 0) camera.height = args.height;
  if (const std::string problem = image_size_problem(camera.width, camera.height); !problem.empty())
    throw InputError("<command line>", "--width, --height", problem);

  const auto start = std::chrono::steady_clock::now();
  std::optional<basis::IndirectLight> indirect;
  if (wants_indirect(args.indirect, scene, args.radiosity))
    indirect.emplace(basis::solve_scene_radiosity(scene, args.radiosity.options));
  const auto solved = std::chrono::steady_clock::now();
  const render::ScanlineRenderer renderer(scene, camera, true, args.joint_umbrae);
  const auto prepared = std::chrono::steady_clock::now();
  render::RenderOptions options;
  options.interval = args.interval;
  if (indirect)
    options.indirect = [&](std::size_t object, std::size_t face, const Vec3d& point) {
      return indirect->at(object, face, point);
    };
  const render::RenderedImage image = renderer.render(options);
  const auto finished = std::chrono::steady_clock::now();

  // docs/render.md, "Exposure": the log-average luminance to mid-grey (Reinhard et al.
  // 2002, key 0.18) and the filmic curve's white at the 99th percentile
  const ToneCurve curve = args.tone == "linear" ? ToneCurve::linear : ToneCurve::filmic;
  const double exposure =
      exposure_given > 0 ? exposure_given : log_average_exposure(image.radiance);
  std::vector<std::uint8_t> rgb =
      to_srgb8(image.radiance, exposure, curve, filmic_white(image.radiance, exposure));
  double maximum = 0, minimum = 0;
  std::vector<double> seen_illuminance, seen_luminance;
  for (std::size_t pixel = 0; pixel < image.illuminance.size(); ++pixel) {
    if (image.visibility.objects[pixel] < 0) continue;
    const double e = image.illuminance[pixel];
    maximum = std::max(maximum, e);
    if (e > 0 && (minimum == 0 || e < minimum)) minimum = e;
    seen_illuminance.push_back(e);
    seen_luminance.push_back(image.luminance[pixel]);
  }
  std::string false_colour_line;
  if (args.false_colour != "none") {
    // docs/render.md, "False colour": every seen pixel in the colour of its value on the
    // levels' scale, up to the largest value seen
    const bool lux = args.false_colour == "illuminance";
    const std::vector<double>& values = lux ? image.illuminance : image.luminance;
    std::vector<double> false_levels = levels;
    if (false_levels.empty())
      false_levels = illuminance::picture_levels(lux ? seen_illuminance : seen_luminance);
    double top = false_levels.empty() ? 0.0 : false_levels.back();
    for (std::size_t pixel = 0; pixel < values.size(); ++pixel)
      if (image.visibility.objects[pixel] >= 0) top = std::max(top, values[pixel]);
    render::paint_false_colour(rgb, image, values, render::level_scale(false_levels, top));
    render::draw_isolux_legend(rgb, image.width, image.height, false_levels, top,
                               lux ? "lx" : "cd/m2");
    false_colour_line = "false colour " + args.false_colour + " levels";
    for (double level : false_levels) false_colour_line += ' ' + render::level_text(level);
    false_colour_line += lux ? " lx\n" : " cd/m^2\n";
  }
  if (args.isolux) {
    if (levels.empty()) levels = illuminance::picture_levels(seen_illuminance);
    const double top = std::max(maximum, levels.empty() ? 0.0 : levels.back());
    render::paint_isolux_belts(rgb, image, levels);
    render::draw_isolux_legend(rgb, image.width, image.height, levels, top);
  }
  write_png(args.output, image.width, image.height, rgb);
  if (!args.values.empty()) write_values(args.values, scene, image);

  const auto seconds = [](auto from, auto to) {
    return std::chrono::duration<double>(to - from).count();
  };
  std::cout << "render " << image.width << " x " << image.height << ", interval " << args.interval
            << "\n"
            << "spans " << image.visibility.spans << ", pieces " << image.visibility.pieces
            << ", illuminance evaluations " << image.evaluations << " (" << std::setprecision(3)
            << static_cast<double>(image.evaluations) / (image.width * image.height)
            << " per pixel), shadow boundary crossings " << image.boundary_crossings << "\n"
            << "E " << minimum << " .. " << maximum << " lx on visible faces, exposure " << exposure
            << " per cd/m^2, tone " << args.tone << "\n";
  if (indirect) {
    const basis::SceneRadiosity& solution = indirect->solution();
    double largest = 0;
    for (double e : image.indirect) largest = std::max(largest, e);
    std::cout << "indirect light: patches " << solution.mesh.size() << ", sweeps "
              << solution.iterations << ", E_indirect up to " << largest << " lx\n";
  }
  // times differ from run to run: on standard error, so that standard output does not
  std::cerr << "time " << seconds(start, finished) << " s (radiosity " << seconds(start, solved)
            << " s, visibility and shadows " << seconds(solved, prepared) << " s, shading "
            << seconds(prepared, finished) << " s)\n";
  std::cout << false_colour_line;
  if (args.isolux) {
    std::cout << "isolux levels";
    for (double level : levels) std::cout << ' ' << render::level_text(level);
    std::cout << " lx\n";
  }
  std::cout << "image " << args.output << "\n";
  return 0;
}

}  // namespace

void register_render(CLI::App& app) {
  CLI::App* verb = app.add_subcommand("render", "scanline image with isolux colour belts");
  auto args = std::make_shared<RenderArguments>();
  verb->add_option("SCENE", args->scene, "scene file (JSON) with a camera")->required();
  verb->add_option("-o,--output", args->output, "PNG image to write")->required();
  verb->add_option("--interval", args->interval,
                   "evaluate illuminance every K pixels along a span (1: every pixel)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  verb->add_option("--exposure", args->exposure, "auto, or the scale from cd/m^2 to white")
      ->capture_default_str()
      ->check([](const std::string& text) {
        return parse_exposure(text) < 0 ? "expected 'auto' or a positive number" : "";
      });
  verb->add_flag("--isolux", args->isolux, "superimpose isolux colour belts and a legend");
  verb->add_flag("--joint-umbrae", args->joint_umbrae,
                 "tubes: keep evaluation points on both sides of the exact umbrae's curved "
                 "edges where occluders hide a tube together (shadows --joint-umbrae)");
  verb->add_option("--levels", args->levels,
                   "isolux levels in lux, e.g. 100,200,500 (default: chosen)");
  verb->add_option("--values", args->values, "CSV of px,py,object,face,E,L,E_indirect per pixel");
  add_indirect_options(verb, args->indirect, args->radiosity);
  verb->add_option("--tone", args->tone,
                   "tone curve: filmic (highlights roll off) or linear (clip)")
      ->capture_default_str()
      ->check(CLI::IsMember({"filmic", "linear"}));
  verb->add_option("--false-colour,--false-color", args->false_colour,
                   "none, illuminance (lux) or luminance (cd/m^2): paint values on a colour "
                   "scale with a legend")
      ->capture_default_str()
      ->check(CLI::IsMember({"none", "illuminance", "luminance"}));
  verb->add_option("--width", args->width, "image width in pixels (default: the camera's)")
      ->check(CLI::Range(1, max_image_side));
  verb->add_option("--height", args->height, "image height in pixels (default: the camera's)")
      ->check(CLI::Range(1, max_image_side));
  verb->callback([args] { exit_status() = run_render(*args); });
}

}  // namespace penumbra::cli
