#pragma once
// Basis luminances (Dobashi 1995 sections 3.4-3.5): for every light, the interreflected
// illuminance of every patch for each of its basis functions, computed once per scene,
// so that any distribution and aiming of a point lamp is afterwards a weighted sum (eq. 18,
// relight.h). Stored per patch and, for Gouraud display, as luminance per vertex.
//
// Colour (section 3.2): a material's reflectance per channel is reflectance x colour. When
// every patch has equal channels the system is solved once (channels = 1); otherwise once
// per channel (channels = 3). A light's colour is applied when relighting.
//
// Compression (beyond the paper, its section 6): a block of basis values, n rows by the
// light's columns, may be kept as a truncated SVD U S V^T whose rank is the smallest with
// relative Frobenius error below a bound; relighting then costs O(n r) instead of O(n M).

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "penumbra/basis/direct_lighting.h"
#include "penumbra/basis/form_factors.h"
#include "penumbra/basis/patch_mesh.h"
#include "penumbra/basis/radiosity.h"
#include "penumbra/scene/camera.h"

namespace penumbra {
struct Scene;
}

namespace penumbra::basis {

// A matrix of basis values (rows: patches or vertices; columns: one light's basis
// functions), full or as a truncated SVD. Single precision: the basis values are
// magnitudes read off a display, and relighting sums at most a few hundred of them.
class BasisBlock {
 public:
  BasisBlock() = default;
  explicit BasisBlock(Eigen::MatrixXf full) : full_(std::move(full)) {}
  // keeps the rank-r truncation of values with r the smallest giving relative Frobenius
  // error <= max_error (0 keeps the full matrix). The error is recorded.
  static BasisBlock compressed(const Eigen::MatrixXd& values, double max_error);
  static BasisBlock low_rank(Eigen::MatrixXf left, Eigen::MatrixXf right, double error);

  Eigen::Index rows() const { return compressed_ ? left_.rows() : full_.rows(); }
  Eigen::Index cols() const { return compressed_ ? right_.rows() : full_.cols(); }
  bool is_compressed() const { return compressed_; }
  Eigen::Index rank() const { return compressed_ ? left_.cols() : full_.cols(); }
  double error() const { return error_; }  // relative Frobenius error of the truncation

  // returns values x weights (weights: cols() entries), accumulated into out (rows()).
  void accumulate(const Eigen::VectorXf& weights, float scale, Eigen::VectorXf& out) const;
  // returns the values as a full matrix (for tests and files).
  Eigen::MatrixXf full() const;

  const Eigen::MatrixXf& full_values() const { return full_; }
  const Eigen::MatrixXf& left() const { return left_; }    // U S, rows x r
  const Eigen::MatrixXf& right() const { return right_; }  // V, cols x r

 private:
  bool compressed_ = false;
  Eigen::MatrixXf full_;
  Eigen::MatrixXf left_, right_;
  double error_ = 0;
};

// One light as the basis knows it.
struct BasisLight {
  LightColumns columns;
  Vec3d position{};  // point lights
  Vec3d axis{0, 0, -1}, c0{1, 0, 0};
  nlohmann::json lid;            // the scene's `lid` as written (null: isotropic candela)
  std::string lid_base;          // directory the lid's file paths are relative to
  Eigen::VectorXd coefficients;  // the scene's own distribution: world SH coefficients
                                 // (point; with sigma factors when options.sigma), or [1]
                                 // (linear, directional)
  // direct illuminance of each patch (n x count): the same in every channel
  BasisBlock direct;
  // per channel: total illuminance of each patch (n x count) and luminance rho E / pi of
  // each vertex (vertices x count)
  std::vector<BasisBlock> total, vertex_luminance;
};

struct BasisOptions {
  double patch_size = 0.5;                                 // m
  int degree = 5;                                          // SH degree of point lights
  std::vector<std::pair<std::string, int>> light_degrees;  // overrides by light name
  FormFactorOptions form_factors;
  RadiosityOptions radiosity;
  double compression = 0;  // max relative Frobenius error of each block; 0 = none
  bool sigma = true;       // the stored coefficients use the sigma factors (eq. 12)
  bool parallel = true;
  // cut the mesh along the exact shadow edges of every light (discontinuity_mesh.h)
  bool discontinuity = true;
};

struct BasisTimings {
  double mesh_s = 0, form_factors_s = 0, direct_s = 0, solve_s = 0, compress_s = 0;
};

struct BasisLuminances {
  PatchMesh mesh;
  std::vector<BasisLight> lights;
  int channels = 1;
  std::optional<Camera> camera;
  std::string scene_file;
  std::vector<std::string> object_names;  // Scene::objects' names, for outputs
  BasisOptions options;
  BasisTimings timings;
  int iterations = 0;  // radiosity sweeps (largest over channels)
  std::size_t form_factor_entries = 0;

  // returns the light named name, or nullptr.
  const BasisLight* find_light(const std::string& name) const;
};

// computes the basis luminances of scene. Progress on a terminal (base/progress.h).
BasisLuminances compute_basis(const Scene& scene, const BasisOptions& options);

}  // namespace penumbra::basis
