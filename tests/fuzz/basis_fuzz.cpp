// Fuzz target "basis": the basis-file reader (.pbl, docs/basis.md, "Basis file") on arbitrary
// bytes, then what relight and serve do first with a file it accepts: the default lighting
// recombined over every patch and vertex. Reading checks every size and index, so a file it
// accepts must relight without reading out of bounds.

#include "fuzz_target.h"
#include "penumbra/basis/basis_file.h"
#include "penumbra/basis/relight.h"

PENUMBRA_FUZZ_TARGET(basis) {
  using namespace penumbra::basis;
  const BasisLuminances basis = read_basis(penumbra::fuzz::scratch_file("basis.pbl", data, size));
  (void)relight(basis, default_lighting(basis));
}
