// Fuzz target "ies": the IES LM-63 reader on arbitrary text, then what a scene does with a
// file it accepts: the candela grid and the table distribution, evaluated in a few
// directions and integrated, and the file written back as LM-63 and read again (penumbra lid
// convert).

#include <sstream>

#include "fuzz_target.h"
#include "penumbra/photometry/ies.h"

PENUMBRA_FUZZ_TARGET(ies) {
  using namespace penumbra::photometry;
  const IesFile ies = parse_ies(penumbra::fuzz::text_of(data, size), "fuzz.ies");
  const PhotometricGrid grid = candela_grid(ies);
  for (const Interpolation interpolation : {Interpolation::linear, Interpolation::cosine}) {
    if (interpolation == Interpolation::cosine && grid.type != PhotometricType::c) continue;
    const TableDistribution distribution(PhotometricGrid(grid), interpolation);
    for (const double gamma : {0.0, 0.7, 1.5707963267948966, 2.9, 3.141592653589793})
      for (const double c : {0.0, 1.1, 3.141592653589793, 5.5})
        (void)distribution.intensity(gamma, c);
    (void)distribution.flux();
  }
  std::ostringstream written;
  write_ies(written, ies);
  (void)parse_ies(written.str(), "fuzz-written.ies");
}
