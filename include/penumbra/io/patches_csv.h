#pragma once
// The patches CSV of `penumbra radiosity -o` and `penumbra relight --patches` (DESIGN.md):
// object,face,x,y,z,nx,ny,nz,area,E_direct,E and, for coloured results, E_r,E_g,E_b; one
// row per radiosity patch (basis/patch_mesh.h), written through base/csv.h.

#include <cstddef>
#include <functional>
#include <ostream>
#include <string>

#include "penumbra/base/colour.h"
#include "penumbra/basis/patch_mesh.h"

namespace penumbra::io {

// The illuminance of one patch (lux): direct, total (direct + interreflected) and the
// total per colour channel.
struct PatchIlluminance {
  double direct = 0;
  double total = 0;
  Colour channels{};
};

// writes the patches CSV of mesh: object_name(k) names object k, values(i) gives patch i's
// illuminance; the E_r,E_g,E_b columns only when colour.
void write_patches_csv(std::ostream& out, const basis::PatchMesh& mesh,
                       const std::function<std::string(std::size_t object)>& object_name,
                       const std::function<PatchIlluminance(std::size_t patch)>& values,
                       bool colour);

}  // namespace penumbra::io
