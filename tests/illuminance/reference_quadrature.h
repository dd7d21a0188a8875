#pragma once
// Reference integrations for the illuminance tests, written independently of the library's
// kernels: Gauss-Legendre nodes by Newton's method, and surface integrals of an illuminance
// function over the inner faces of a box.

#include <array>
#include <cmath>
#include <functional>
#include <utility>
#include <vector>
#include "penumbra/base/numbers.h"

namespace penumbra::test {

// returns the n Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n, Golub-Welsch
// free; accurate to a few ulps for the n used here).
inline std::vector<std::pair<double, double>> gauss_legendre(int n) {
  using penumbra::pi;
  std::vector<std::pair<double, double>> rule;
  for (int i = 0; i < n; ++i) {
    double x = std::cos(pi * (i + 0.75) / (n + 0.5));
    double derivative = 0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = n * (x * p1 - p0) / (x * x - 1);
      const double step = p1 / derivative;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    rule.emplace_back(x, 2 / ((1 - x * x) * derivative * derivative));
  }
  return rule;
}

using Point = std::array<double, 3>;

// integrates `illuminance(point, normal)` over the six inner faces of the box [lo, hi]
// (normals pointing into the box): each face is cut into panels x panels squares, and each
// square is integrated with a tensor Gauss-Legendre rule of `order` points and split into
// four while the split changes the result by more than `tolerance` lux x its area (E has a
// conical kink where the line of a linear source pierces a face, since sin(theta) ~ h/r).
// Returns the flux in lumen if illuminance is in lux.
inline double flux_into_box(const std::function<double(const Point&, const Point&)>& illuminance,
                            const Point& lo, const Point& hi, int panels, int order,
                            double tolerance = 1e-11) {
  const auto rule = gauss_legendre(order);
  double flux = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3;
    const int v = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      Point normal{0, 0, 0};
      normal[axis] = side == 0 ? 1 : -1;  // the face at lo looks up the axis, into the box
      Point point{0, 0, 0};
      point[axis] = side == 0 ? lo[axis] : hi[axis];
      auto square = [&](double u0, double u1, double v0, double v1) {
        double sum = 0;
        for (const auto& [x, wx] : rule)
          for (const auto& [y, wy] : rule) {
            point[u] = u0 + (u1 - u0) * 0.5 * (x + 1);
            point[v] = v0 + (v1 - v0) * 0.5 * (y + 1);
            sum += wx * wy * illuminance(point, normal);
          }
        return 0.25 * (u1 - u0) * (v1 - v0) * sum;
      };
      std::function<double(double, double, double, double, double, int)> refine =
          [&](double u0, double u1, double v0, double v1, double whole, int depth) {
            const double um = 0.5 * (u0 + u1), vm = 0.5 * (v0 + v1);
            const double q[4] = {square(u0, um, v0, vm), square(um, u1, v0, vm),
                                 square(u0, um, vm, v1), square(um, u1, vm, v1)};
            const double split = q[0] + q[1] + q[2] + q[3];
            if (depth >= 12 || std::abs(split - whole) <= tolerance * (u1 - u0) * (v1 - v0))
              return split;
            return refine(u0, um, v0, vm, q[0], depth + 1) +
                   refine(um, u1, v0, vm, q[1], depth + 1) +
                   refine(u0, um, vm, v1, q[2], depth + 1) +
                   refine(um, u1, vm, v1, q[3], depth + 1);
          };
      const double du = (hi[u] - lo[u]) / panels;
      const double dv = (hi[v] - lo[v]) / panels;
      for (int i = 0; i < panels; ++i)
        for (int j = 0; j < panels; ++j) {
          const double u0 = lo[u] + du * i, u1 = lo[u] + du * (i + 1);
          const double v0 = lo[v] + dv * j, v1 = lo[v] + dv * (j + 1);
          flux += refine(u0, u1, v0, v1, square(u0, u1, v0, v1), 0);
        }
    }
  }
  return flux;
}

}  // namespace penumbra::test
