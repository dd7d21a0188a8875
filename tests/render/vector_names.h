#pragma once
// The vector helpers of include/penumbra/vec3d.h under the names the render tests use.

#include "penumbra/vec3d.h"

namespace penumbra::test {

using penumbra::vector_ops::cross;
using penumbra::vector_ops::dot;
inline Vec3d sub(const Vec3d& a, const Vec3d& b) {
  return penumbra::vector_ops::operator-(a, b);
}
inline Vec3d add(const Vec3d& a, const Vec3d& b) {
  return penumbra::vector_ops::operator+(a, b);
}
inline Vec3d scale(double s, const Vec3d& a) {
  return penumbra::vector_ops::operator*(s, a);
}
inline Vec3d unit(const Vec3d& a) {
  return penumbra::vector_ops::normalized(a);
}

}  // namespace penumbra::test
