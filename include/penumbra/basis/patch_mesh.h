#pragma once
// The radiosity mesh (Dobashi 1995 section 3.4; Cohen and Greenberg 1985): every face of
// every object cut into patches no larger than a given size, with shared vertices per
// face for Gouraud display (section 3.5, step 4). Doubles only: a patch boundary is a
// sampling choice, not a shadow boundary, so no geometric decision is taken here.
//
// Each face is cut in its own frame (geometry/face_frame.h: u along its first edge) by a
// grid of n_u x n_v equal cells over its bounding rectangle, n = ceil(extent / size); every
// cell is clipped to the (convex) face and kept when its area is positive. A rectangle
// aligned with its first edge is so cut into n_u x n_v equal rectangles.

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "penumbra/base/colour.h"
#include "penumbra/base/vec3d.h"

namespace penumbra {

struct Scene;

namespace basis {

struct Patch {
  std::uint32_t object = 0;             // index into Scene::objects
  std::uint32_t face = 0;               // index into the object's faces
  Vec3d centre{};                       // area centroid (m)
  Vec3d normal{};                       // unit outward normal of the face
  double area = 0;                      // m^2
  Colour reflectance{};                 // per channel: material reflectance x colour
  std::vector<std::uint32_t> vertices;  // convex polygon, counter-clockwise from outside
};

// Discontinuity meshing (docs/basis.md, "Discontinuity meshing"): the exact shadow regions of
// the lights on one face, each as its rings (outer boundaries and holes, world points rounded
// to doubles). subdivide() splits the patches of the face along the lines of the rings' edges
// and shares a vertex only between patches on the same side of every region, so Gouraud
// shading jumps at the edges instead of ramping across a patch.
struct FaceBreaks {
  std::vector<std::vector<std::vector<Vec3d>>> regions;  // region -> rings -> points
};
using MeshBreaks = std::map<std::pair<std::uint32_t, std::uint32_t>, FaceBreaks>;

// How one face was cut: its frame and grid, so a point on the face finds its patch.
struct FaceGrid {
  std::uint32_t object = 0, face = 0;
  Vec3d origin{}, u{}, v{};               // the face frame (u, v unit)
  double u0 = 0, v0 = 0, du = 1, dv = 1;  // cell (a, b) spans [u0 + a du, u0 + (a+1) du] x ...
  int nu = 0, nv = 0;
  std::vector<std::int64_t> cells;    // nu * nv entries, a + nu b: first patch index or -1
  std::vector<std::uint32_t> pieces;  // per cell, its patches (consecutive from cells[k]);
                                      // empty: one each
};

// The most patches a mesh may have (docs/reliability.md, "Limits"): a basis holds, per patch
// and light, (degree + 1)^2 values a channel, about a kilobyte at degree 8.
inline constexpr std::uint64_t max_patches = 500'000;

class PatchMesh {
 public:
  // cuts every face of scene into patches of edge at most patch_size (m, > 0), each cut
  // further along the breaks of its face (discontinuity meshing) when given.
  // Throws std::invalid_argument when patch_size is not positive and finite, InputError
  // ("--patch-size") when the faces' grids would hold more than max_patches cells.
  static PatchMesh subdivide(const Scene& scene, double patch_size, const MeshBreaks& breaks = {});

  // assembles a mesh from its parts (used when reading a basis file). Such a mesh has no
  // grids: locate() finds nothing, nearest_patch() works.
  PatchMesh(std::vector<Vec3d> vertices, std::vector<Patch> patches);
  PatchMesh() = default;

  const std::vector<Vec3d>& vertices() const { return vertices_; }
  const std::vector<Patch>& patches() const { return patches_; }
  const std::vector<FaceGrid>& grids() const { return grids_; }
  std::size_t size() const { return patches_.size(); }

  // returns the triangles (fans of the patches) and, for each, its patch: what a
  // Gouraud renderer draws.
  std::vector<std::array<std::uint32_t, 3>> triangles(
      std::vector<std::uint32_t>* triangle_patch = nullptr) const;

  // returns the patch of face (object, face) that contains point (a point on or very near
  // the face), or {} when the face has no patch there.
  std::optional<std::uint32_t> locate(std::uint32_t object, std::uint32_t face,
                                      const Vec3d& point) const;

  // returns the patch whose centre is nearest to point among the patches whose face plane
  // passes within tolerance (m) of it, or {} when there is none. O(n).
  std::optional<std::uint32_t> nearest_patch(const Vec3d& point, double tolerance) const;

  // returns, per vertex, the area-weighted mean of values over the patches that use it
  // (values has one row per patch): Gouraud vertex values (section 3.5).
  template <typename Matrix>
  Matrix vertex_average(const Matrix& per_patch) const;

  // the per-vertex weights of vertex_average: for vertex v, the (patch, weight) pairs
  // with weights summing to 1.
  const std::vector<std::vector<std::pair<std::uint32_t, double>>>& vertex_weights() const {
    return vertex_weights_;
  }

 private:
  // fills vertex_weights_ and the (object, face) -> grid lookup.
  void index();

  std::vector<Vec3d> vertices_;
  std::vector<Patch> patches_;
  std::vector<std::vector<std::pair<std::uint32_t, double>>> vertex_weights_;
  std::vector<FaceGrid> grids_;          // one per face, in (object, face) order
  std::vector<std::size_t> first_grid_;  // per object: index of its face 0's grid
};

template <typename Matrix>
Matrix PatchMesh::vertex_average(const Matrix& per_patch) const {
  Matrix out = Matrix::Zero(static_cast<Eigen::Index>(vertices_.size()), per_patch.cols());
  for (std::size_t v = 0; v < vertex_weights_.size(); ++v)
    for (const auto& [patch, weight] : vertex_weights_[v])
      out.row(static_cast<Eigen::Index>(v)) +=
          static_cast<typename Matrix::Scalar>(weight) * per_patch.row(patch);
  return out;
}

}  // namespace basis
}  // namespace penumbra
