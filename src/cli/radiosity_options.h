#pragma once
// The options `penumbra radiosity`, `basis` and `serve` share: the patch mesh, the form
// factors and the solver (docs/basis.md, "Radiosity").

#include <CLI/CLI.hpp>
#include <string>

#include "penumbra/basis/basis_luminances.h"

namespace penumbra {
struct Scene;
}

namespace penumbra::cli {

struct RadiosityArguments {
  basis::BasisOptions options;
  std::string method = "rays";
};

// adds --patch-size, --form-factors, --rays, --seed, --tolerance and --max-iterations, and
// with discontinuity_flag --no-discontinuity (discontinuity meshing is on by default).
void add_radiosity_options(CLI::App* verb, RadiosityArguments& arguments,
                           bool discontinuity_flag = true);

// checks the values and fills options.form_factors.method; throws InputError.
void finish_radiosity_options(RadiosityArguments& arguments);

// adds --indirect auto|on|off (into setting) and the radiosity options: `render` and
// `raytrace` add the interreflected light of a radiosity solve (docs/render.md, step 5), on a
// mesh without discontinuity meshing (the indirect light is smooth; the direct light is
// exact at every pixel anyway).
void add_indirect_options(CLI::App* verb, std::string& setting, RadiosityArguments& arguments);

// The most patches `--indirect auto` solves; beyond, it says so and leaves indirect light off
// (a finely tessellated model makes one patch a facet: the teapot's 34,000 patches take 10 s).
inline constexpr std::size_t max_automatic_patches = 20'000;

// returns whether to add indirect light: setting "on", or "auto" with a light, a material
// that reflects and a patch mesh of at most max_automatic_patches (a note on standard error
// otherwise).
bool wants_indirect(const std::string& setting, const Scene& scene,
                    const RadiosityArguments& arguments);

}  // namespace penumbra::cli
