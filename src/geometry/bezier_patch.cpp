#include "penumbra/geometry/bezier_patch.h"

#include <algorithm>
#include <cmath>

namespace penumbra {

using namespace vector_ops;
namespace {

// The cubic Bernstein polynomials and their derivatives at t.
struct Basis {
  std::array<double, 4> value, slope;
  explicit Basis(double t) {
    const double s = 1 - t;
    value = {s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t};
    slope = {-3 * s * s, 3 * s * s - 6 * t * s, 6 * t * s - 3 * t * t, 3 * t * t};
  }
};

// returns the cubic through p0..p3 split at t = 1/2 (de Casteljau): the left and right
// control points.
std::pair<std::array<Vec3d, 4>, std::array<Vec3d, 4>> halves(const std::array<Vec3d, 4>& p) {
  const Vec3d a = 0.5 * (p[0] + p[1]), b = 0.5 * (p[1] + p[2]), c = 0.5 * (p[2] + p[3]);
  const Vec3d ab = 0.5 * (a + b), bc = 0.5 * (b + c);
  const Vec3d mid = 0.5 * (ab + bc);
  return {{p[0], a, ab, mid}, {mid, bc, c, p[3]}};
}

}  // namespace

Vec3d BezierPatch::point(double u, double v) const {
  return jet(u, v).point;
}

BezierPatch::Jet BezierPatch::jet(double u, double v) const {
  const Basis bu(u), bv(v);
  Jet jet{};
  for (int i = 0; i < 4; ++i) {
    // Row i as a curve in v, and its slope; then the rows combined along u.
    Vec3d row{}, row_slope{};
    for (int j = 0; j < 4; ++j) {
      row = row + bv.value[j] * at(i, j);
      row_slope = row_slope + bv.slope[j] * at(i, j);
    }
    jet.point = jet.point + bu.value[i] * row;
    jet.du = jet.du + bu.slope[i] * row;
    jet.dv = jet.dv + bu.value[i] * row_slope;
    jet.duv = jet.duv + bu.slope[i] * row_slope;
  }
  return jet;
}

Vec3d BezierPatch::normal(double u, double v) const {
  const Jet j = jet(u, v);
  const Vec3d n = cross(j.du, j.dv);
  const double larger = std::max(length(j.du), length(j.dv));
  // A product small against the larger factor squared: a factor vanishes (a collapsed edge)
  // or the two are parallel. The relative threshold only chooses between two formulas for
  // the same limit.
  if (length(n) > 1e-9 * larger * larger) return normalized(n);
  Vec3d limit;
  if (length(j.dv) <= length(j.du))
    limit = (u < 0.5 ? 1.0 : -1.0) * cross(j.du, j.duv);  // S_v = (u - u0) S_uv + ...
  else
    limit = (v < 0.5 ? 1.0 : -1.0) * cross(j.duv, j.dv);  // S_u = (v - v0) S_uv + ...
  const double l = length(limit);
  return l > 0 ? (1 / l) * limit : Vec3d{0, 0, 0};
}

std::pair<BezierPatch, BezierPatch> BezierPatch::split(bool along_u) const {
  BezierPatch first, second;
  for (int k = 0; k < 4; ++k) {
    std::array<Vec3d, 4> curve;
    for (int m = 0; m < 4; ++m) curve[m] = along_u ? at(m, k) : at(k, m);
    const auto [left, right] = halves(curve);
    for (int m = 0; m < 4; ++m) {
      const std::size_t index = static_cast<std::size_t>(along_u ? 4 * m + k : 4 * k + m);
      first.points[index] = left[m];
      second.points[index] = right[m];
    }
  }
  return {first, second};
}

double BezierPatch::flatness() const {
  double worst = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double a = i / 3.0, b = j / 3.0;
      const Vec3d bilinear = (1 - a) * (1 - b) * at(0, 0) + a * (1 - b) * at(3, 0) +
                             (1 - a) * b * at(0, 3) + a * b * at(3, 3);
      worst = std::max(worst, length(at(i, j) - bilinear));
    }
  return worst;
}

std::pair<Vec3d, Vec3d> BezierPatch::bounds() const {
  Vec3d low = points[0], high = points[0];
  for (const Vec3d& p : points)
    for (int k = 0; k < 3; ++k) {
      low[k] = std::min(low[k], p[k]);
      high[k] = std::max(high[k], p[k]);
    }
  return {low, high};
}

int tessellation_segments(const BezierPatch& patch, double tolerance) {
  double uu = 0, uv = 0, vv = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      if (i + 2 < 4)
        uu = std::max(uu, length(patch.at(i + 2, j) - 2 * patch.at(i + 1, j) + patch.at(i, j)));
      if (j + 2 < 4)
        vv = std::max(vv, length(patch.at(i, j + 2) - 2 * patch.at(i, j + 1) + patch.at(i, j)));
      if (i + 1 < 4 && j + 1 < 4)
        uv = std::max(uv, length(patch.at(i + 1, j + 1) - patch.at(i + 1, j) - patch.at(i, j + 1) +
                                 patch.at(i, j)));
    }
  const double second = 6 * uu + 2 * 9 * uv + 6 * vv;  // n^2 8 |S - L| <= second
  const double n = std::ceil(std::sqrt(second / (8 * tolerance)));
  return static_cast<int>(std::clamp(n, 1.0, 1024.0));
}

}  // namespace penumbra
