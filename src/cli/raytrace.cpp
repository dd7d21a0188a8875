// penumbra raytrace SCENE -o image.png: Whitted's ray tracer (docs/raytrace.md).

#include <chrono>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>

#include "penumbra/base/atomic_file.h"
#include "penumbra/base/csv.h"
#include "penumbra/base/input_error.h"
#include "penumbra/base/png.h"
#include "penumbra/base/tone_map.h"
#include "penumbra/basis/indirect_light.h"
#include "penumbra/raytrace/render.h"
#include "penumbra/scene/load_scene.h"
#include "radiosity_options.h"
#include "verbs.h"

namespace penumbra::cli {
namespace {

struct RaytraceArguments {
  std::string scene;
  std::string output;
  int depth = 8;
  std::string aa = "adaptive";
  int aa_depth = 3;
  double aa_threshold = 0.1;
  bool fresnel = false;
  bool tessellated = false;
  std::string attenuation = "none";
  std::string exposure = "auto";
  std::string values;
  int tube_samples = 16;
  int area_samples = 64;
  std::string indirect = "auto";
  RadiosityArguments radiosity;
};

void write_values(const std::string& path, const Scene& scene,
                  const raytrace::RenderedImage& image) {
  write_atomically(path, [&](std::ostream& out) {
    CsvWriter csv(out, {"px", "py", "object", "R", "G", "B"});
    for (int j = 0; j < image.height; ++j)
      for (int i = 0; i < image.width; ++i) {
        const std::size_t index = static_cast<std::size_t>(j) * image.width + i;
        const long object = image.objects[index];
        csv.integer(i).integer(j).text(
            object >= 0 ? scene.objects[static_cast<std::size_t>(object)].face_owner() : "");
        for (double channel : image.pixels[index]) csv.number(channel);
        csv.end_row();
      }
  });
}

int run_raytrace(RaytraceArguments& args) {
  finish_radiosity_options(args.radiosity);
  const double exposure = parse_exposure(args.exposure);
  const Scene& scene = load_scene_until_exit(args.scene);
  for (const std::string& warning : scene.warnings)
    std::cerr << "penumbra: warning: " << warning << "\n";
  if (!scene.camera) throw InputError(args.scene, "camera", "raytrace needs a camera in the scene");

  raytrace::TraceOptions trace;
  trace.max_depth = args.depth;
  trace.fresnel = args.fresnel;
  if (args.tessellated) trace.patches = raytrace::PatchSurfaces::tessellated;
  trace.attenuation =
      args.attenuation == "linear" ? raytrace::Attenuation::linear : raytrace::Attenuation::none;
  trace.tube_samples = args.tube_samples;
  trace.area_samples = args.area_samples;
  raytrace::RenderOptions render;
  render.anti_aliasing =
      args.aa == "none" ? raytrace::AntiAliasing::none : raytrace::AntiAliasing::adaptive;
  render.aa_depth = args.aa_depth;
  render.aa_threshold = args.aa_threshold;
  if (exposure > 0) render.exposure = exposure;
  render.objects = !args.values.empty();

  const auto start = std::chrono::steady_clock::now();
  std::optional<basis::IndirectLight> indirect;
  if (wants_indirect(args.indirect, scene, args.radiosity)) {
    indirect.emplace(basis::solve_scene_radiosity(scene, args.radiosity.options));
    trace.indirect = [&](std::size_t object, std::size_t face, const Vec3d& point) {
      return indirect->at(object, face, point);
    };
  }
  const auto traced_from = std::chrono::steady_clock::now();
  const raytrace::RayTracer tracer(scene, trace);
  const raytrace::RenderedImage image = raytrace::render(tracer, *scene.camera, render);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - traced_from).count();
  const double radiosity_seconds = std::chrono::duration<double>(traced_from - start).count();

  write_png(args.output, image.width, image.height, to_srgb8(image.pixels, image.exposure));
  if (!args.values.empty()) write_values(args.values, scene, image);

  const raytrace::RayCounts& rays = image.counts;
  const double pixels = static_cast<double>(image.width) * image.height;
  std::cout << "raytrace " << image.width << " x " << image.height << ", aa " << args.aa;
  if (args.aa == "adaptive")
    std::cout << " (depth " << args.aa_depth << ", " << image.subdivided_pixels
              << " pixels subdivided)";
  std::cout << ", ray depth " << args.depth << "\n"
            << "rays " << rays.total() << " (camera " << rays.camera << ", shadow " << rays.shadow
            << ", reflected " << rays.reflected << ", refracted " << rays.refracted << "), "
            << std::setprecision(3) << static_cast<double>(rays.camera) / pixels
            << " camera rays per pixel\n"
            << "exposure " << image.exposure << " per cd/m^2\n";
  if (indirect)
    std::cout << "indirect light: patches " << indirect->solution().mesh.size() << ", sweeps "
              << indirect->solution().iterations << "\n";
  std::cout << "image " << args.output << "\n";
  // times differ from run to run: on standard error, so that standard output does not
  std::cerr << "time " << seconds << " s, " << static_cast<double>(rays.total()) / seconds / 1e6
            << " Mrays/s";
  if (indirect) std::cerr << " (and the radiosity solve " << radiosity_seconds << " s)";
  std::cerr << "\n";
  return 0;
}

}  // namespace

void register_raytrace(CLI::App& app) {
  CLI::App* verb = app.add_subcommand("raytrace", "Whitted ray-traced image (PNG)");
  auto args = std::make_shared<RaytraceArguments>();
  verb->add_option("SCENE", args->scene, "scene file (JSON) with a camera")->required();
  verb->add_option("-o,--output", args->output, "PNG image to write")->required();
  verb->add_option("--depth", args->depth, "deepest reflection/refraction generation")
      ->capture_default_str()
      ->check(CLI::Range(0, 64));
  verb->add_option("--aa", args->aa, "anti-aliasing: adaptive (Whitted section 3) or none")
      ->capture_default_str()
      ->check(CLI::IsMember({"adaptive", "none"}));
  verb->add_option("--aa-depth", args->aa_depth, "adaptive subdivision levels below a pixel")
      ->capture_default_str()
      ->check(CLI::Range(0, 8));
  verb->add_option("--aa-threshold", args->aa_threshold,
                   "corner difference (sRGB display units) that triggers subdivision")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  verb->add_flag("--fresnel", args->fresnel, "k_s, k_t from the dielectric Fresnel equations");
  verb->add_flag("--tessellated", args->tessellated,
                 "trace Bezier patch objects as their tessellation (flat triangles), not the "
                 "patches");
  verb->add_option("--attenuation", args->attenuation,
                   "none, or linear with distance as in Whitted section 2")
      ->capture_default_str()
      ->check(CLI::IsMember({"none", "linear"}));
  verb->add_option("--exposure", args->exposure, "auto, or the scale from cd/m^2 to white")
      ->capture_default_str()
      ->check([](const std::string& text) {
        return parse_exposure(text) < 0 ? "expected 'auto' or a positive number" : "";
      });
  verb->add_option(
          "--tube-samples", args->tube_samples,
          "samples of a tube's Phong highlight per shading point (its diffuse light is exact)")
      ->capture_default_str()
      ->check(CLI::Range(1, 4096));
  verb->add_option("--area-samples", args->area_samples,
                   "stratified shadow rays per area source and shading point")
      ->capture_default_str()
      ->check(CLI::Range(1, 65536));
  verb->add_option("--values", args->values, "CSV of px,py,object,R,G,B (linear luminance)");
  add_indirect_options(verb, args->indirect, args->radiosity);
  verb->callback([args] { exit_status() = run_raytrace(*args); });
}

}  // namespace penumbra::cli
