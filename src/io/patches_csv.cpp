#include "penumbra/io/patches_csv.h"

#include "penumbra/base/csv.h"

namespace penumbra::io {

void write_patches_csv(std::ostream& out, const basis::PatchMesh& mesh,
                       const std::function<std::string(std::size_t object)>& object_name,
                       const std::function<PatchIlluminance(std::size_t patch)>& values,
                       bool colour) {
  std::vector<std::string> columns{"object", "face", "x",    "y",        "z", "nx",
                                   "ny",     "nz",   "area", "E_direct", "E"};
  if (colour) columns.insert(columns.end(), {"E_r", "E_g", "E_b"});
  CsvWriter csv(out, columns);
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const basis::Patch& patch = mesh.patches()[i];
    const PatchIlluminance value = values(i);
    csv.text(object_name(patch.object)).integer(patch.face);
    for (double x : patch.centre) csv.number(x);
    for (double n : patch.normal) csv.number(n);
    csv.number(patch.area).number(value.direct).number(value.total);
    if (colour)
      for (double channel : value.channels) csv.number(channel);
    csv.end_row();
  }
}

}  // namespace penumbra::io
