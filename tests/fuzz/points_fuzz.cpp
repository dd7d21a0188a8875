// Fuzz target "points": the CSV reader of `illuminance --points` and `relight --fit`
// (columns found by name in the header line) on arbitrary text, and each row made a
// receiving point as `illuminance --points` makes it (a zero or non-finite normal refused).

#include "../../src/cli/numeric_csv.h"
#include "fuzz_target.h"
#include "penumbra/illuminance/scene_illuminance.h"

PENUMBRA_FUZZ_TARGET(points) {
  const std::string file = penumbra::fuzz::scratch_file("points.csv", data, size).string();
  for (const penumbra::cli::NumericRow& row :
       penumbra::cli::read_numeric_csv(file, {"x", "y", "z", "nx", "ny", "nz"}, "points file")) {
    const std::vector<double>& v = row.values;
    (void)penumbra::illuminance::receiving_point({v[0], v[1], v[2], v[3], v[4], v[5]}, file,
                                                 "line " + std::to_string(row.line));
  }
}
