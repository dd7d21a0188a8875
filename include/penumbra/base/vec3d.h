#pragma once
// Double-precision 3-vectors for magnitudes (illuminance, rendering, ray tracing):
// no geometric decision is taken with them (DESIGN.md, "Exactness"). The operators
// live in penumbra::vector_ops; code that wants them says
// `using namespace penumbra::vector_ops;` in its own namespace.

#include <array>
#include <cmath>

namespace penumbra {

using Vec3d = std::array<double, 3>;

namespace vector_ops {

inline Vec3d operator+(const Vec3d& a, const Vec3d& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
inline Vec3d operator-(const Vec3d& a, const Vec3d& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline Vec3d operator-(const Vec3d& a) {
  return {-a[0], -a[1], -a[2]};
}
inline Vec3d operator*(double s, const Vec3d& a) {
  return {s * a[0], s * a[1], s * a[2]};
}
inline Vec3d operator*(const Vec3d& a, double s) {
  return s * a;
}
inline double dot(const Vec3d& a, const Vec3d& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double length(const Vec3d& a) {
  return std::sqrt(dot(a, a));
}
inline Vec3d normalized(const Vec3d& a) {
  return (1 / length(a)) * a;
}

}  // namespace vector_ops
}  // namespace penumbra
