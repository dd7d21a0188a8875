#pragma once
// Small double-precision vector helpers of the renderer (private).

#include <array>
#include <cmath>

namespace penumbra::render::detail {

using V3 = std::array<double, 3>;

inline V3 operator-(const V3& p, const V3& q) {
  return {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
}
inline V3 operator+(const V3& p, const V3& q) {
  return {p[0] + q[0], p[1] + q[1], p[2] + q[2]};
}
inline V3 operator*(double s, const V3& v) {
  return {s * v[0], s * v[1], s * v[2]};
}
inline double dot(const V3& p, const V3& q) {
  return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
}
inline V3 cross(const V3& p, const V3& q) {
  return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}
inline V3 normalized(const V3& v) {
  return (1 / std::sqrt(dot(v, v))) * v;
}

}  // namespace penumbra::render::detail
