#pragma once
// Display of relit patches (Dobashi 1995 section 3.5, step 4: "luminance mapping"): the
// patch mesh drawn from the scene camera with a depth buffer, luminance interpolated
// across each triangle from its vertices (Gouraud), perspective-correct. Triangles are
// clipped at a near plane, so a camera inside a room sees the walls around it. Faces turned
// away from the eye are not drawn (so the two sides of a flat polygon do not fight).

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "penumbra/base/tone_map.h"
#include "penumbra/scene/camera.h"

namespace penumbra::basis {

class PatchMesh;

struct GouraudImage {
  int width = 0, height = 0;
  std::vector<Colour> radiance;     // cd/m^2 per channel, row by row from the top
  std::vector<std::int64_t> patch;  // the patch seen through each pixel centre, or -1
};

// draws mesh with per-vertex luminance (vertices x 3) as camera sees it; pixel (i, j) is
// sampled at its centre.
GouraudImage gouraud_image(const PatchMesh& mesh, const Eigen::MatrixX3f& vertex_luminance,
                           const Camera& camera);

}  // namespace penumbra::basis
