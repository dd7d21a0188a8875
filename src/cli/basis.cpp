// penumbra basis SCENE --degree N -o basis.pbl: basis luminances for relighting (Dobashi
// 1995 sections 3.4-3.5; docs/basis.md, "Basis luminances").

#include <charconv>
#include <iomanip>
#include <iostream>

#include "penumbra/base/input_error.h"
#include "penumbra/basis/basis_file.h"
#include "penumbra/scene/load_scene.h"
#include "radiosity_options.h"
#include "verbs.h"

namespace penumbra::cli {
namespace {

constexpr int kMaxDegree = 20;

struct Arguments {
  std::string scene;
  std::string output;
  int degree = 5;
  std::vector<std::string> light_degrees;
  double compression = 0;
  RadiosityArguments radiosity;
};

int parse_degree(const std::string& text, const std::string& option) {
  int degree = -1;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), degree);
  if (error != std::errc() || end != text.data() + text.size() || degree < 0 || degree > kMaxDegree)
    throw InputError("<command line>", option,
                     "the degree must be an integer from 0 to " + std::to_string(kMaxDegree) +
                         ": \"" + text + "\"");
  return degree;
}

int run(Arguments& args) {
  finish_radiosity_options(args.radiosity);
  basis::BasisOptions& options = args.radiosity.options;
  if (args.degree < 0 || args.degree > kMaxDegree)
    throw InputError("<command line>", "--degree",
                     "the degree must be from 0 to " + std::to_string(kMaxDegree));
  options.degree = args.degree;
  if (!(args.compression >= 0) || !(args.compression < 1))
    throw InputError("<command line>", "--compress", "must lie in [0, 1)");
  options.compression = args.compression;
  const Scene& scene = load_scene_until_exit(args.scene);
  for (const std::string& warning : scene.warnings)
    std::cerr << "penumbra: warning: " << warning << "\n";
  for (const std::string& entry : args.light_degrees) {
    const auto equals = entry.find('=');
    if (equals == std::string::npos)
      throw InputError("<command line>", "--light-degree", "expected NAME=N: \"" + entry + "\"");
    const std::string name = entry.substr(0, equals);
    if (!scene.find_light(name))
      throw InputError("<command line>", "--light-degree", "no light named \"" + name + "\"");
    options.light_degrees.emplace_back(name,
                                       parse_degree(entry.substr(equals + 1), "--light-degree"));
  }
  const basis::BasisLuminances basis = basis::compute_basis(scene, options);
  basis::write_basis(args.output, basis);
  std::cout << "patches " << basis.mesh.size() << ", vertices " << basis.mesh.vertices().size()
            << ", channels " << basis.channels << ", form factor entries "
            << basis.form_factor_entries << ", sweeps " << basis.iterations << "\n";
  for (const basis::BasisLight& light : basis.lights) {
    std::cout << "light " << light.columns.name << ": ";
    if (light.columns.kind == basis::LightKind::point)
      std::cout << "degree " << light.columns.degree << ", " << light.columns.count
                << " basis functions";
    else
      std::cout << "1 column (scaled when relighting)";
    if (light.total[0].is_compressed())
      std::cout << ", rank " << light.total[0].rank() << " (error " << light.total[0].error()
                << ")";
    std::cout << "\n";
  }
  const basis::BasisTimings& t = basis.timings;
  // times differ from run to run: on standard error, so that standard output does not
  std::cerr << std::setprecision(3) << "time: mesh " << t.mesh_s << " s, form factors "
            << t.form_factors_s << " s, direct " << t.direct_s << " s, solve " << t.solve_s
            << " s, blocks " << t.compress_s << " s\n";
  return 0;
}

}  // namespace

void register_basis(CLI::App& app) {
  auto args = std::make_shared<Arguments>();
  CLI::App* verb = app.add_subcommand("basis", "basis luminances for relighting (.pbl)");
  verb->add_option("SCENE", args->scene, "scene file (JSON)")->required();
  verb->add_option("-o,--output", args->output, "basis file (.pbl)")->required();
  verb->add_option("--degree", args->degree,
                   "spherical-harmonic degree N of point lights ((N+1)^2 functions)")
      ->capture_default_str();
  verb->add_option("--light-degree", args->light_degrees, "NAME=N: another degree for one light");
  verb->add_option("--compress", args->compression,
                   "keep truncated SVDs with this relative Frobenius error (0: exact)")
      ->capture_default_str();
  add_radiosity_options(verb, args->radiosity);
  verb->callback([args] { exit_status() = run(*args); });
}

}  // namespace penumbra::cli
