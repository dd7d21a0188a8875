#include "radiosity_options.h"

#include <cmath>
#include <iostream>

#include "penumbra/base/input_error.h"
#include "penumbra/scene/scene.h"

namespace penumbra::cli {

void add_radiosity_options(CLI::App* verb, RadiosityArguments& arguments, bool discontinuity_flag) {
  basis::BasisOptions& options = arguments.options;
  verb->add_option("--patch-size", options.patch_size, "largest patch edge (m)")
      ->capture_default_str();
  verb->add_option("--form-factors", arguments.method,
                   "rays (stratified cosine rays per patch) or analytic (point-to-polygon, O(n^2))")
      ->capture_default_str();
  verb->add_option("--rays", options.form_factors.rays, "rays per patch for --form-factors rays")
      ->capture_default_str();
  verb->add_option("--seed", options.form_factors.seed, "seed of the ray directions")
      ->capture_default_str();
  verb->add_option("--tolerance", options.radiosity.tolerance,
                   "stop when a sweep changes E by less than this fraction")
      ->capture_default_str();
  verb->add_option("--max-iterations", options.radiosity.max_iterations, "most sweeps")
      ->capture_default_str();
  if (discontinuity_flag)
    verb->add_flag("!--no-discontinuity", options.discontinuity,
                   "do not cut the patches along the exact shadow edges (discontinuity meshing)");
}

void finish_radiosity_options(RadiosityArguments& arguments) {
  basis::BasisOptions& options = arguments.options;
  if (!(options.patch_size > 0) || !std::isfinite(options.patch_size))
    throw InputError("<command line>", "--patch-size", "must be a positive number of metres");
  if (arguments.method == "rays")
    options.form_factors.method = basis::FormFactorMethod::rays;
  else if (arguments.method == "analytic")
    options.form_factors.method = basis::FormFactorMethod::analytic;
  else
    throw InputError("<command line>", "--form-factors", "must be rays or analytic");
  if (options.form_factors.rays < 1 || options.form_factors.rays > 1 << 24)
    throw InputError("<command line>", "--rays", "must be between 1 and 16777216");
  if (!(options.radiosity.tolerance > 0) || !(options.radiosity.tolerance < 1))
    throw InputError("<command line>", "--tolerance", "must lie in (0, 1)");
  if (options.radiosity.max_iterations < 1)
    throw InputError("<command line>", "--max-iterations", "must be at least 1");
}

void add_indirect_options(CLI::App* verb, std::string& setting, RadiosityArguments& arguments) {
  verb->add_option("--indirect", setting,
                   "add interreflected light from a radiosity solve: auto (when a material "
                   "reflects), on, off")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "on", "off"}));
  arguments.options.discontinuity = false;
  add_radiosity_options(verb, arguments, false);
}

bool wants_indirect(const std::string& setting, const Scene& scene,
                    const RadiosityArguments& arguments) {
  if (setting != "auto") return setting == "on";
  if (scene.lights.empty()) return false;
  bool reflects = false;
  for (const Object& object : scene.objects)
    reflects = reflects || scene.materials[object.material].reflectance > 0;
  if (!reflects) return false;
  const std::size_t patches =
      basis::PatchMesh::subdivide(scene, arguments.options.patch_size).size();
  if (patches <= max_automatic_patches) return true;
  std::cerr << "penumbra: note: no indirect light: the patch mesh would hold " << patches
            << " patches, more than the " << max_automatic_patches
            << " of --indirect auto (--indirect on adds it)\n";
  return false;
}

}  // namespace penumbra::cli
