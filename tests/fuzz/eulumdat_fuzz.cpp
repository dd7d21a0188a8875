// Fuzz target "eulumdat": the EULUMDAT reader on arbitrary text, then the candela grid of
// every lamp set, its table distribution evaluated in a few directions, and the conversion
// to LM-63 read back (penumbra lid convert).

#include <sstream>

#include "fuzz_target.h"
#include "penumbra/photometry/eulumdat.h"

PENUMBRA_FUZZ_TARGET(eulumdat) {
  using namespace penumbra::photometry;
  const EulumdatFile ldt = parse_eulumdat(penumbra::fuzz::text_of(data, size), "fuzz.ldt");
  for (std::size_t set = 0; set < ldt.lamp_sets.size(); ++set) {
    const TableDistribution distribution(candela_grid(ldt, set), Interpolation::linear);
    for (const double gamma : {0.0, 0.7, 1.5707963267948966, 2.9, 3.141592653589793})
      for (const double c : {0.0, 1.1, 3.141592653589793, 5.5})
        (void)distribution.intensity(gamma, c);
    (void)distribution.flux();
    std::ostringstream written;
    write_ies(written, to_ies(ldt, set));
    (void)parse_ies(written.str(), "fuzz-written.ies");
  }
}
