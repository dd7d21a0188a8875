#pragma once
// Hidden-surface removal by scan lines (Nishita 1985, Appendix A1, after Nishita and
// Nakamae 1974): the front faces of the scene's convex polyhedra are cut by the scan
// plane of every pixel-centre row, giving one span per face; on each scan line the
// spans are split where their ends fall, and in each piece the face nearest the eye is
// chosen by depth at the piece's ends (a painter's order per scan line; where two faces
// exchange order inside a piece, it is split where their depths are equal). Doubles
// throughout: this decides which face a pixel shows, not where a shadow lies.
//
// Image coordinates are those of DESIGN.md: x in [0, width] to the right, y in
// [0, height] downward; pixel (i, j) is sampled through its centre (i + 0.5, j + 0.5).
// A span [x_left, x_right) covers the pixels whose centres lie in it.

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "penumbra/scene/camera_frame.h"
#include "penumbra/scene/scene.h"

namespace penumbra::render {

// A face's plane in doubles: unit outward normal n and offset d, n.Q + d = 0.
struct FacePlane {
  Vec3d normal;
  double offset;
};

// returns the plane of a face, rounded to doubles and normalised.
FacePlane face_plane(const Face& face);

// The visible surface of every pixel, row by row from the top.
struct VisibilityMap {
  int width = 0;
  int height = 0;
  std::vector<long> objects;  // index into Scene::objects, -1 where nothing is seen
  std::vector<int> faces;     // index into that object's faces(), -1 where nothing is seen
  std::size_t spans = 0;      // face spans over all scan lines
  std::size_t pieces = 0;     // pieces of scan line whose visibility was decided

  std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * width + i; }
};

// computes the visible (object, face) of every pixel of camera's image of scene by scan
// lines. Deterministic; rows run in parallel when parallel is set.
VisibilityMap scanline_visibility(const Scene& scene, const Camera& camera, bool parallel = true);

}  // namespace penumbra::render
