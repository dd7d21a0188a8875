// penumbra radiosity SCENE -o patches.csv: one interreflected solve of the scene as lit
// (Dobashi 1995 eq. 14; docs/basis.md, "Radiosity").

#include <iomanip>
#include <iostream>

#include "penumbra/base/atomic_file.h"
#include "penumbra/basis/scene_radiosity.h"
#include "penumbra/io/patches_csv.h"
#include "penumbra/scene/load_scene.h"
#include "radiosity_options.h"
#include "verbs.h"

namespace penumbra::cli {
namespace {

struct Arguments {
  std::string scene;
  std::string output;
  RadiosityArguments radiosity;
};

int run(Arguments& args) {
  finish_radiosity_options(args.radiosity);
  const Scene& scene = load_scene_until_exit(args.scene);
  for (const std::string& warning : scene.warnings)
    std::cerr << "penumbra: warning: " << warning << "\n";
  const basis::SceneRadiosity solved = basis::solve_scene_radiosity(scene, args.radiosity.options);
  write_atomically(args.output, [&](std::ostream& out) {
    io::write_patches_csv(
        out, solved.mesh, [&](std::size_t object) { return scene.objects[object].name; },
        [&](std::size_t i) {
          const auto row = static_cast<Eigen::Index>(i);
          return io::PatchIlluminance{
              solved.direct_per_light.row(row).sum(),
              basis::photometric(solved.total(row, 0), solved.total(row, 1), solved.total(row, 2)),
              {solved.total(row, 0), solved.total(row, 1), solved.total(row, 2)}};
        },
        solved.channels == 3);
  });
  std::cout << "patches " << solved.mesh.size() << ", form factor entries "
            << solved.form_factor_entries << ", sweeps " << solved.iterations << ", channels "
            << solved.channels << "\n";
  // times differ from run to run: on standard error, so that standard output does not
  std::cerr << std::setprecision(3) << "time: mesh " << solved.timings.mesh_s << " s, form factors "
            << solved.timings.form_factors_s << " s, direct " << solved.timings.direct_s
            << " s, solve " << solved.timings.solve_s << " s\n";
  return 0;
}

}  // namespace

void register_radiosity(CLI::App& app) {
  auto args = std::make_shared<Arguments>();
  CLI::App* verb = app.add_subcommand("radiosity", "interreflected illuminance on patches (CSV)");
  verb->add_option("SCENE", args->scene, "scene file (JSON)")->required();
  verb->add_option("-o,--output", args->output,
                   "patches CSV: object,face,x,y,z,nx,ny,nz,area,E_direct,E")
      ->required();
  add_radiosity_options(verb, args->radiosity);
  verb->callback([args] { exit_status() = run(*args); });
}

}  // namespace penumbra::cli
