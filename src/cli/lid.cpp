// penumbra lid info|sample|convert|fit FILE|SPEC: photometry from the command line.
// FILE is an LM-63 (.ies) or EULUMDAT (.ldt) file; SPEC is a scene's `lid` JSON object.

#include <algorithm>
#include <cctype>
#include <iomanip>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "lid_fit.h"
#include "penumbra/base/atomic_file.h"
#include "penumbra/base/input_error.h"
#include "penumbra/photometry/eulumdat.h"
#include "penumbra/photometry/figures.h"
#include "penumbra/photometry/ies.h"
#include "penumbra/photometry/table_distribution.h"
#include "verbs.h"

namespace penumbra::cli {
namespace {

using namespace photometry;

// A distribution named on the command line, with the file it came from (if any).
struct Source {
  std::shared_ptr<const Distribution> distribution;
  std::optional<IesFile> ies;
  std::optional<EulumdatFile> ldt;
  nlohmann::json spec;  // null unless a SPEC
};

std::string extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return ext;
}

Source load_source(const std::string& argument, Interpolation interpolation) {
  Source source;
  const auto first = argument.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && argument[first] == '{') {
    try {
      source.spec = nlohmann::json::parse(argument);
    } catch (const nlohmann::json::parse_error& e) {
      throw InputError("<command line>", "SPEC", std::string("malformed JSON: ") + e.what());
    }
    source.distribution = make_distribution(
        source.spec, SpecContext{"<command line>", "lid", std::filesystem::current_path()});
    return source;
  }
  const std::string ext = extension(argument);
  if (ext == ".ies") {
    source.ies = read_ies(argument);
    source.distribution = load_ies(argument, interpolation);
  } else if (ext == ".ldt") {
    source.ldt = read_eulumdat(argument);
    PhotometricGrid grid = candela_grid(*source.ldt);
    source.distribution = std::make_shared<TableDistribution>(std::move(grid), interpolation);
  } else {
    throw InputError(argument, "",
                     "expected an .ies or .ldt file, or a lid JSON object such as "
                     "'{\"cos_power\": 10, \"candela\": 800}'");
  }
  return source;
}

// returns the lumens the file itself states, when it does: lamps x lumens per lamp for
// relative LM-63 photometry, LORL x lamp flux for EULUMDAT.
std::optional<double> stated_lumens(const Source& source) {
  if (source.ies && !source.ies->absolute())
    return source.ies->lamp_count * source.ies->lumens_per_lamp;
  if (source.ldt) return source.ldt->light_output_ratio / 100 * source.ldt->lamp_sets.front().flux;
  return std::nullopt;
}

nlohmann::json figures_json(const Source& source, const Figures& figures) {
  nlohmann::json out;
  out["lumens"] = figures.lumens;
  if (const auto stated = stated_lumens(source)) out["file_lumens"] = *stated;
  out["max_candela"] = figures.max_candela;
  out["max_direction"] = {{"gamma_deg", degrees(figures.max_direction.gamma)},
                          {"c_deg", degrees(figures.max_direction.c)}};
  out["symmetry"] = symmetry_name(figures.symmetry);
  out["beam_angle_deg"] = figures.beam_angle_deg;
  out["field_angle_deg"] = figures.field_angle_deg;
  out["beam_planes_deg"] = {{"through_axis", figures.beam_planes_deg[0]},
                            {"across", figures.beam_planes_deg[1]}};
  out["field_planes_deg"] = {{"through_axis", figures.field_planes_deg[0]},
                             {"across", figures.field_planes_deg[1]}};
  const PartialSphere& sphere = figures.partial_sphere;
  out["partial_sphere"] = {
      {"threshold", sphere.threshold},          {"full_scale_lux", sphere.full_scale_lux},
      {"spread_deg", sphere.spread_deg},        {"radius_m", sphere.radius_m},
      {"two_spheres", sphere.two_spheres},      {"lower_radius_m", sphere.lower_radius_m},
      {"upper_radius_m", sphere.upper_radius_m}};
  if (source.ies) {
    out["format"] = source.ies->format.empty() ? "LM-63-1986" : source.ies->format;
    out["photometric_type"] = std::string(1, "CBA"[source.ies->photometric_type - 1]);
    out["absolute_photometry"] = source.ies->absolute();
  }
  if (source.ldt) {
    out["format"] = "EULUMDAT";
    out["isym"] = source.ldt->symmetry;
    out["absolute_photometry"] = source.ldt->absolute();
    out["lamp_sets"] = source.ldt->lamp_sets.size();
  }
  return out;
}

int run_info(const std::string& argument, bool json, double full_scale_lux,
             Interpolation interpolation) {
  const Source source = load_source(argument, interpolation);
  FigureOptions options;
  options.full_scale_lux = full_scale_lux;
  const Figures figures = compute_figures(*source.distribution, options);
  const nlohmann::json out = figures_json(source, figures);
  if (json) {
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  std::cout << std::setprecision(6);
  std::cout << "lumens " << figures.lumens;
  if (out.contains("file_lumens"))
    std::cout << " (the file states " << out["file_lumens"].get<double>() << ")";
  std::cout << "\nmax " << figures.max_candela << " cd at gamma "
            << degrees(figures.max_direction.gamma) << " deg, C "
            << degrees(figures.max_direction.c) << " deg\n"
            << "symmetry " << symmetry_name(figures.symmetry) << "\n"
            << "beam angle " << figures.beam_angle_deg << " deg (through the axis "
            << figures.beam_planes_deg[0] << ", across " << figures.beam_planes_deg[1] << ")\n"
            << "field angle " << figures.field_angle_deg << " deg (through the axis "
            << figures.field_planes_deg[0] << ", across " << figures.field_planes_deg[1] << ")\n";
  const PartialSphere& sphere = figures.partial_sphere;
  std::cout << "partial sphere of lighting (threshold 1/" << 1 / sphere.threshold << " of "
            << sphere.full_scale_lux << " lx): spread " << sphere.spread_deg << " deg, radius "
            << sphere.radius_m << " m";
  if (sphere.two_spheres)
    std::cout << " (lower " << sphere.lower_radius_m << " m, upper " << sphere.upper_radius_m
              << " m)";
  std::cout << "\n";
  return 0;
}

int run_sample(const std::string& argument, double gamma_deg, double c_deg,
               Interpolation interpolation) {
  if (!(gamma_deg >= 0 && gamma_deg <= 180))
    throw InputError("<command line>", "--gamma", "gamma must lie in 0..180 degrees");
  const Source source = load_source(argument, interpolation);
  std::cout << std::setprecision(17)
            << source.distribution->intensity(radians(gamma_deg), radians(c_deg)) << "\n";
  return 0;
}

// returns the LM-63 file for argument: the file itself, a converted EULUMDAT file, or
// a SPEC sampled on its own angles (tables) or every 0.5 degree (closed forms).
IesFile ies_for(const Source& source) {
  if (source.ies) return *source.ies;
  if (source.ldt) return to_ies(*source.ldt);
  if (const auto* table = dynamic_cast<const TableDistribution*>(source.distribution.get()))
    return ies_from_grid(table->grid(), {"[OTHER] written by penumbra from " + source.spec.dump()});
  PhotometricGrid grid;
  grid.horizontal_deg = {0};
  grid.candela.emplace_back();
  for (int k = 0; k <= 360; ++k) {
    grid.vertical_deg.push_back(0.5 * k);
    grid.candela.back().push_back(source.distribution->intensity(radians(0.5 * k), 0));
  }
  if (source.distribution->symmetry() != Symmetry::axial &&
      source.distribution->symmetry() != Symmetry::isotropic)
    throw InputError("<command line>", "SPEC", "only axial closed forms can be sampled into LM-63");
  return ies_from_grid(grid,
                       {"[OTHER] sampled by penumbra every 0.5 deg from " + source.spec.dump()});
}

int run_convert(const std::string& argument, const std::string& output) {
  if (extension(output) != ".ies")
    throw InputError(output, "",
                     "penumbra lid convert writes LM-63 files: the output must end in .ies");
  const Source source = load_source(argument, Interpolation::linear);
  const IesFile ies = ies_for(source);
  write_atomically(output, [&](std::ostream& out) { write_ies(out, ies); });
  return 0;
}

Interpolation interpolation_named(const std::string& name) {
  if (name == "linear") return Interpolation::linear;
  if (name == "cosine") return Interpolation::cosine;
  throw InputError("<command line>", "--interpolation", "must be linear or cosine");
}

}  // namespace

void register_lid(CLI::App& app) {
  CLI::App* lid =
      app.add_subcommand("lid", "photometry: info, sample, fit and convert distributions");
  lid->require_subcommand(1);
  lid->footer(
      "FILE is an IES LM-63 (.ies) or EULUMDAT (.ldt) file; SPEC a scene's lid JSON object,\n"
      "e.g. '{\"cos_power\": 10, \"spread_deg\": 90, \"candela\": 800}'.");

  struct Options {
    std::string source, output, interpolation = "linear";
    bool json = false;
    double full_scale_lux = 500, gamma = 0, c = 0;
  };
  auto options = std::make_shared<Options>();

  CLI::App* info =
      lid->add_subcommand("info", "flux, maximum, beam and field angles, partial sphere");
  info->add_option("FILE|SPEC", options->source, "photometric file or lid JSON")->required();
  info->add_flag("--json", options->json, "print JSON");
  info->add_option("--full-scale-lux", options->full_scale_lux,
                   "illuminance at display full scale for the partial sphere (default 500)")
      ->check(CLI::PositiveNumber);
  info->add_option("--interpolation", options->interpolation, "linear (default) or cosine");
  info->callback([options] {
    exit_status() = run_info(options->source, options->json, options->full_scale_lux,
                             interpolation_named(options->interpolation));
  });

  CLI::App* sample = lid->add_subcommand("sample", "print the intensity (cd) toward gamma, C");
  sample->add_option("FILE|SPEC", options->source, "photometric file or lid JSON")->required();
  sample->add_option("--gamma", options->gamma, "angle from the axis, degrees")->required();
  sample->add_option("--c", options->c, "azimuth from C = 0, degrees (default 0)");
  sample->add_option("--interpolation", options->interpolation, "linear (default) or cosine");
  sample->callback([options] {
    exit_status() = run_sample(options->source, options->gamma, options->c,
                               interpolation_named(options->interpolation));
  });

  CLI::App* convert = lid->add_subcommand("convert", "write the distribution as an IES LM-63 file");
  convert->add_option("FILE|SPEC", options->source, "photometric file or lid JSON")->required();
  convert->add_option("-o,--output", options->output, "output .ies file")->required();
  convert->callback([options] { exit_status() = run_convert(options->source, options->output); });

  CLI::App* fit = lid->add_subcommand(
      "fit", "Legendre weights, sigma factors and their error over the sphere (docs/basis.md)");
  auto fit_options = std::make_shared<LidFitOptions>();
  fit->add_option("FILE|SPEC", options->source, "photometric file or lid JSON")->required();
  fit->add_option("--degree", fit_options->degree, "highest Legendre degree N, 0..60")->required();
  fit->add_flag("--sigma", fit_options->sigma, "apply the sigma factors of Dobashi eq. (13)");
  fit->add_flag("--json", fit_options->json, "print JSON");
  fit->add_option("--interpolation", options->interpolation, "linear (default) or cosine");
  fit->callback([options, fit_options] {
    fit_options->distribution =
        load_source(options->source, interpolation_named(options->interpolation)).distribution;
    exit_status() = run_lid_fit(*fit_options);
  });
}

}  // namespace penumbra::cli
