// penumbra relight basis.pbl: recombine basis luminances for other distributions, aimings,
// dimmings and colours (Dobashi 1995 section 3.5, eq. 18; docs/basis.md, "Relighting").

#include <charconv>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "numeric_csv.h"
#include "penumbra/base/atomic_file.h"
#include "penumbra/base/input_error.h"
#include "penumbra/base/numbers.h"
#include "penumbra/base/png.h"
#include "penumbra/base/tone_map.h"
#include "penumbra/basis/basis_file.h"
#include "penumbra/basis/gouraud_image.h"
#include "penumbra/basis/inverse_lighting.h"
#include "penumbra/basis/relight.h"
#include "penumbra/basis/scene_radiosity.h"
#include "penumbra/io/patches_csv.h"
#include "penumbra/photometry/distribution.h"
#include "verbs.h"

namespace penumbra::cli {
namespace {

struct Arguments {
  std::string basis;
  std::vector<std::string> lids, aims, scales, colours;
  bool no_sigma = false;
  std::string output, patches, exposure = "auto";
  std::string fit, fit_light;
  int fit_intervals = 18;
  int width = 0, height = 0;
};

// splits NAME=VALUE and finds the light; throws InputError naming the option.
std::pair<std::size_t, std::string> named(const basis::BasisLuminances& basis,
                                          const std::string& entry, const std::string& option) {
  const auto equals = entry.find('=');
  if (equals == std::string::npos)
    throw InputError("<command line>", option, "expected NAME=VALUE: \"" + entry + "\"");
  const std::string name = entry.substr(0, equals);
  for (std::size_t k = 0; k < basis.lights.size(); ++k)
    if (basis.lights[k].columns.name == name) return {k, entry.substr(equals + 1)};
  throw InputError("<command line>", option, "no light named \"" + name + "\" in the basis");
}

// parses count comma-separated finite numbers.
std::vector<double> numbers(const std::string& text, std::size_t count, const std::string& option) {
  const std::vector<double> values = parse_number_list(text, option);
  if (values.size() != count)
    throw InputError("<command line>", option,
                     "expected " + std::to_string(count) + " numbers: \"" + text + "\"");
  return values;
}

// the distribution of --lid NAME=FILE|SPEC: a lid JSON object, or an .ies / .ldt file.
std::shared_ptr<const photometry::Distribution> lid_argument(const std::string& text) {
  nlohmann::json spec;
  const auto first = text.find_first_not_of(" \t");
  if (first != std::string::npos && text[first] == '{') {
    try {
      spec = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
      throw InputError("<command line>", "--lid", std::string("malformed JSON: ") + e.what());
    }
  } else {
    std::string ext = std::filesystem::path(text).extension().string();
    for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (ext != ".ies" && ext != ".ldt")
      throw InputError("<command line>", "--lid",
                       "expected an .ies or .ldt file or a lid JSON object: \"" + text + "\"");
    spec = {{ext.substr(1), text}};
  }
  return photometry::make_distribution(
      spec, {"<command line>", "--lid", std::filesystem::current_path()});
}

// The lighting the options ask for, and each light's axis (for --fit).
struct Choice {
  basis::Lighting lighting;
  std::vector<Vec3d> axes;
};

Choice lighting_of(const basis::BasisLuminances& basis, const Arguments& args) {
  basis::Lighting lighting = basis::default_lighting(basis);
  // per point light: its distribution (null: keep the stored coefficients) and frame
  std::vector<std::shared_ptr<const photometry::Distribution>> distributions(basis.lights.size());
  std::vector<Vec3d> axes, c0s;
  for (const basis::BasisLight& light : basis.lights)
    axes.push_back(light.axis), c0s.push_back(light.c0);
  // the stored coefficients carry the basis's sigma choice; another choice recomputes them
  const bool sigma = !args.no_sigma;
  std::vector<bool> changed(basis.lights.size(), sigma != basis.options.sigma);
  for (const std::string& entry : args.lids) {
    const auto [k, value] = named(basis, entry, "--lid");
    if (basis.lights[k].columns.kind != basis::LightKind::point)
      throw InputError("<command line>", "--lid",
                       "light \"" + basis.lights[k].columns.name + "\" is not a point light");
    distributions[k] = lid_argument(value);
    changed[k] = true;
  }
  for (const std::string& entry : args.aims) {
    const auto [k, value] = named(basis, entry, "--aim");
    const basis::BasisLight& light = basis.lights[k];
    if (light.columns.kind != basis::LightKind::point)
      throw InputError("<command line>", "--aim",
                       "light \"" + light.columns.name + "\" is not a point light");
    const std::vector<double> p = numbers(value, 3, "--aim");
    using namespace vector_ops;
    const Vec3d axis = Vec3d{p[0], p[1], p[2]} - light.position;
    if (length(axis) == 0)
      throw InputError("<command line>", "--aim", "the aim point is the lamp's position");
    axes[k] = normalized(axis);
    c0s[k] = basis::reaimed_c0(axes[k], light.c0);
    changed[k] = true;
  }
  for (std::size_t k = 0; k < basis.lights.size(); ++k) {
    const basis::BasisLight& light = basis.lights[k];
    if (!changed[k] || light.columns.kind != basis::LightKind::point) continue;
    if (!distributions[k])
      distributions[k] = light.lid.is_null()
                             ? photometry::make_isotropic(light.coefficients[0] /
                                                          std::sqrt(4 * pi))  // Y_00 = 1/sqrt(4 pi)
                             : photometry::make_distribution(
                                   light.lid, {args.basis, "lights." + light.columns.name + ".lid",
                                               light.lid_base});
    lighting[k].coefficients =
        basis::world_coefficients(*distributions[k], light.columns.degree, axes[k], c0s[k], sigma);
  }
  for (const std::string& entry : args.scales) {
    const auto [k, value] = named(basis, entry, "--scale");
    lighting[k].scale = numbers(value, 1, "--scale")[0];
    if (lighting[k].scale < 0)
      throw InputError("<command line>", "--scale", "must not be negative");
  }
  for (const std::string& entry : args.colours) {
    const auto [k, value] = named(basis, entry, "--color");
    const std::vector<double> c = numbers(value, 3, "--color");
    for (int ch = 0; ch < 3; ++ch) {
      if (c[ch] < 0) throw InputError("<command line>", "--color", "channels must not be negative");
      lighting[k].colour[ch] = c[ch];
    }
  }
  return {lighting, axes};
}

// --fit: the distribution of one point light that best gives the targets' illuminances.
void fit(const basis::BasisLuminances& basis, const Arguments& args, Choice& choice) {
  std::size_t light = basis.lights.size();
  for (std::size_t k = 0; k < basis.lights.size(); ++k)
    if (basis.lights[k].columns.kind == basis::LightKind::point &&
        (args.fit_light.empty() || basis.lights[k].columns.name == args.fit_light)) {
      light = k;
      break;
    }
  if (light == basis.lights.size())
    throw InputError("<command line>", "--fit-light",
                     args.fit_light.empty() ? "the basis has no point light"
                                            : "no point light named \"" + args.fit_light + "\"");
  if (args.fit_intervals < 1 || args.fit_intervals > 180)
    throw InputError("<command line>", "--fit-intervals", "must be from 1 to 180");
  // a target must lie on a face: within 1 mm of a patch's plane
  std::vector<basis::FitTarget> targets;
  std::vector<Vec3d> points;
  for (const NumericRow& row : read_numeric_csv(args.fit, {"x", "y", "z", "E"}, "targets file")) {
    const Vec3d p{row.values[0], row.values[1], row.values[2]};
    const std::optional<std::uint32_t> patch = basis.mesh.nearest_patch(p, 1e-3);
    if (!patch)
      throw InputError(args.fit, "line " + std::to_string(row.line),
                       "the point lies on no face of the scene");
    targets.push_back({*patch, row.values[3]});
    points.push_back(p);
  }
  if (targets.empty()) throw InputError(args.fit, "", "no targets");
  const basis::DistributionFit result =
      basis::fit_distribution(basis, choice.lighting, light, choice.axes[light], targets,
                              args.fit_intervals, !args.no_sigma);
  choice.lighting[light] = result.setting;
  nlohmann::json report = {{"light", basis.lights[light].columns.name},
                           {"lid", {{"table_deg", result.angles_deg}, {"candela", result.candela}}},
                           {"legendre_weights", result.weights},
                           {"rms_residual_lux", result.rms_residual},
                           {"max_residual_lux", result.max_residual}};
  for (std::size_t t = 0; t < targets.size(); ++t)
    report["targets"].push_back(
        {{"point", points[t]}, {"E_target", targets[t].illuminance}, {"E", result.achieved[t]}});
  std::cout << report.dump(2) << "\n";
}

void write_patches(const std::string& path, const basis::BasisLuminances& basis,
                   const basis::Relit& relit) {
  write_atomically(path, [&](std::ostream& out) {
    io::write_patches_csv(
        out, basis.mesh,
        [&](std::size_t object) {
          return object < basis.object_names.size() ? basis.object_names[object]
                                                    : std::to_string(object);
        },
        [&](std::size_t i) {
          const auto row = static_cast<Eigen::Index>(i);
          return io::PatchIlluminance{
              basis::photometric(relit.direct(row, 0), relit.direct(row, 1), relit.direct(row, 2)),
              basis::photometric(relit.total(row, 0), relit.total(row, 1), relit.total(row, 2)),
              {relit.total(row, 0), relit.total(row, 1), relit.total(row, 2)}};
        },
        true);
  });
}

int run(const Arguments& args) {
  if (!args.output.empty() && !args.patches.empty())
    throw InputError("<command line>", "-o", "give one of -o image.png and --patches patches.csv");
  if (args.output.empty() && args.patches.empty() && args.fit.empty())
    throw InputError("<command line>", "-o",
                     "give -o image.png, --patches patches.csv or --fit targets.csv");
  const double exposure_given = parse_exposure(args.exposure);
  if (exposure_given < 0)
    throw InputError("<command line>", "--exposure", "must be auto or a positive number");
  const basis::BasisLuminances basis = basis::read_basis(args.basis);
  Choice choice = lighting_of(basis, args);
  if (!args.fit.empty()) fit(basis, args, choice);
  if (args.output.empty() && args.patches.empty()) return 0;
  const basis::Lighting& lighting = choice.lighting;
  const auto start = std::chrono::steady_clock::now();
  const basis::Relit relit = basis::relight(basis, lighting, args.patches.empty());
  const double relight_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!args.patches.empty()) {
    write_patches(args.patches, basis, relit);
  } else {
    if (!basis.camera)
      throw InputError(args.basis, "camera", "the scene of this basis has no camera");
    Camera camera = *basis.camera;
    if (args.width > 0) camera.width = args.width;
    if (args.height > 0) camera.height = args.height;
    if (const std::string problem = image_size_problem(camera.width, camera.height);
        !problem.empty())
      throw InputError("<command line>", "--width, --height", problem);
    const basis::GouraudImage image =
        basis::gouraud_image(basis.mesh, relit.vertex_luminance, camera);
    const double exposure = exposure_given > 0 ? exposure_given : auto_exposure(image.radiance);
    write_png(args.output, image.width, image.height, to_srgb8(image.radiance, exposure));
  }
  if (args.fit.empty()) {
    std::cout << "relit " << basis.mesh.size() << " patches\n";
    // times differ from run to run: on standard error, so that standard output does not
    std::cerr << std::setprecision(3) << "time " << relight_ms << " ms\n";
  }
  return 0;
}

}  // namespace

void register_relight(CLI::App& app) {
  auto args = std::make_shared<Arguments>();
  CLI::App* verb = app.add_subcommand("relight", "relight from basis luminances (eq. 18)");
  verb->add_option("BASIS", args->basis, "basis file written by penumbra basis (.pbl)")->required();
  verb->add_option("--lid", args->lids, "NAME=FILE|SPEC: another distribution for a point light");
  verb->add_option("--aim", args->aims, "NAME=x,y,z: aim a point light at this point");
  verb->add_option("--scale", args->scales, "NAME=k: dim or boost a light");
  verb->add_option("--color", args->colours, "NAME=r,g,b: colour of a light");
  verb->add_flag("--no-sigma", args->no_sigma,
                 "plain Legendre weights: no sigma factors (eq. 12) against ringing");
  verb->add_option("-o,--output", args->output,
                   "image (PNG), Gouraud-shaded from the scene camera");
  verb->add_option("--patches", args->patches,
                   "patches CSV: object,face,x,y,z,nx,ny,nz,area,E_direct,E,...");
  verb->add_option("--fit", args->fit,
                   "targets CSV x,y,z,E: fit a point light's distribution to these illuminances");
  verb->add_option("--fit-light", args->fit_light, "the point light to fit (default: the first)");
  verb->add_option("--fit-intervals", args->fit_intervals, "control intervals over 0-180 degrees")
      ->capture_default_str();
  verb->add_option("--exposure", args->exposure, "auto or 1/(cd/m^2)")->capture_default_str();
  verb->add_option("--width", args->width, "image width (default: the camera's)")
      ->check(CLI::Range(1, max_image_side));
  verb->add_option("--height", args->height, "image height (default: the camera's)")
      ->check(CLI::Range(1, max_image_side));
  verb->callback([args] { exit_status() = run(*args); });
}

}  // namespace penumbra::cli
