#pragma once
// The options `penumbra radiosity`, `basis` and `serve` share: the patch mesh, the form
// factors and the solver (docs/basis.md, "Radiosity").

#include <CLI/CLI.hpp>
#include <string>

#include "penumbra/basis/basis_luminances.h"

namespace penumbra::cli {

struct RadiosityArguments {
  basis::BasisOptions options;
  std::string method = "rays";
};

// adds --patch-size, --form-factors, --rays, --seed, --tolerance and --max-iterations.
void add_radiosity_options(CLI::App* verb, RadiosityArguments& arguments);

// checks the values and fills options.form_factors.method; throws InputError.
void finish_radiosity_options(RadiosityArguments& arguments);

}  // namespace penumbra::cli
