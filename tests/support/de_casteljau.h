#pragma once
// An independent evaluation of bicubic Bézier patches for the tests (issue #23): repeated
// linear interpolation (de Casteljau) instead of the Bernstein sums of
// geometry/bezier_patch.h, derivatives from the hodographs (the differences of the control
// points, times the degree), and random patches with fixed seeds.

#include <array>
#include <cmath>

#include "penumbra/base/random.h"
#include "penumbra/geometry/bezier_patch.h"

namespace penumbra::test {

using Point = std::array<double, 3>;

inline Point lerp(const Point& a, const Point& b, double t) {
  return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}

// the point at t of the Bézier curve of degree points.size() - 1 (at most 3), by de Casteljau.
template <std::size_t N>
Point casteljau(std::array<Point, N> p, double t) {
  for (std::size_t level = N - 1; level > 0; --level)
    for (std::size_t k = 0; k < level; ++k) p[k] = lerp(p[k], p[k + 1], t);
  return p[0];
}

// The surface and its first derivatives at (u, v), evaluated curve by curve: each row
// i (fixed i, j = 0..3) at v, then the resulting cubic in u; derivatives through the
// hodograph 3 (Q_(k+1) - Q_k).
struct SurfacePoint {
  Point point, du, dv;
};
inline SurfacePoint casteljau_patch(const BezierPatch& patch, double u, double v) {
  std::array<Point, 4> rows, columns;
  for (int i = 0; i < 4; ++i) {
    std::array<Point, 4> row, column;
    for (int j = 0; j < 4; ++j) row[j] = patch.at(i, j), column[j] = patch.at(j, i);
    rows[i] = casteljau(row, v);
    columns[i] = casteljau(column, u);
  }
  const auto hodograph = [](const std::array<Point, 4>& q) {
    std::array<Point, 3> d;
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) d[k][c] = 3 * (q[k + 1][c] - q[k][c]);
    return d;
  };
  return {casteljau(rows, u), casteljau(hodograph(rows), u), casteljau(hodograph(columns), v)};
}

// A random patch over [x0, x0 + size]^2 (in x, y) with heights up to bump: a control grid
// jittered in the plane and in height, so rays meet it from any side.
inline BezierPatch random_patch(SplitMix64& random, double size = 2, double bump = 1) {
  BezierPatch patch;
  const double x0 = 4 * random.uniform() - 2, y0 = 4 * random.uniform() - 2;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      patch.points[4 * i + j] = {x0 + size * (i + 0.3 * (random.uniform() - 0.5)) / 3,
                                 y0 + size * (j + 0.3 * (random.uniform() - 0.5)) / 3,
                                 bump * (2 * random.uniform() - 1)};
  return patch;
}

}  // namespace penumbra::test
