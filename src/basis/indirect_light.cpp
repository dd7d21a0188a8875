#include "penumbra/basis/indirect_light.h"

#include <algorithm>
#include <limits>

namespace penumbra::basis {

using namespace vector_ops;

IndirectLight::IndirectLight(SceneRadiosity solved) : solved_(std::move(solved)) {
  const Eigen::VectorXd direct = solved_.direct_per_light.rowwise().sum();
  per_patch_ = (solved_.total.colwise() - direct).cwiseMax(0.0);
  per_vertex_ = solved_.mesh.vertex_average(per_patch_);
}

Colour IndirectLight::at(std::size_t object, std::size_t face, const Vec3d& point) const {
  const PatchMesh& mesh = solved_.mesh;
  const std::optional<std::uint32_t> found =
      mesh.locate(static_cast<std::uint32_t>(object), static_cast<std::uint32_t>(face), point);
  if (!found) return {0, 0, 0};
  const Patch& patch = mesh.patches()[*found];
  const std::vector<std::uint32_t>& ring = patch.vertices;
  const auto corner = [&](std::size_t k) { return mesh.vertices()[ring[k]]; };
  // the fan triangle (0, k, k + 1) whose smallest barycentric coordinate is largest: the one
  // holding point, or the nearest when rounding puts point just outside every one
  double best = -std::numeric_limits<double>::infinity();
  std::array<std::uint32_t, 3> triangle{};
  std::array<double, 3> weights{};
  for (std::size_t k = 1; k + 1 < ring.size(); ++k) {
    const Vec3d a = corner(0), b = corner(k), c = corner(k + 1);
    const double twice_area = dot(patch.normal, cross(b - a, c - a));
    if (!(twice_area > 0)) continue;
    const std::array<double, 3> l{dot(patch.normal, cross(c - b, point - b)) / twice_area,
                                  dot(patch.normal, cross(a - c, point - c)) / twice_area,
                                  dot(patch.normal, cross(b - a, point - a)) / twice_area};
    const double smallest = std::min({l[0], l[1], l[2]});
    if (smallest > best) {
      best = smallest;
      triangle = {ring[0], ring[k], ring[k + 1]};
      weights = l;
    }
  }
  if (best == -std::numeric_limits<double>::infinity()) {
    const auto row = per_patch_.row(static_cast<Eigen::Index>(*found));
    return {row(0), row(1), row(2)};
  }
  double sum = 0;
  for (double& w : weights) sum += (w = std::max(w, 0.0));
  Colour out{0, 0, 0};
  for (int v = 0; v < 3; ++v)
    for (int c = 0; c < 3; ++c)
      out[c] += weights[v] / sum * per_vertex_(static_cast<Eigen::Index>(triangle[v]), c);
  return out;
}

}  // namespace penumbra::basis
