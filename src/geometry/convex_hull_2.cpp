#include "convex_hull_2.h"

#include <algorithm>
#include <numeric>
#include "penumbra/geometry/exact.h"

namespace penumbra::detail {

std::vector<int> convex_hull_2(const std::vector<Point2>& points) {
  std::vector<int> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return CGAL::compare_xy(points[a], points[b]) == CGAL::SMALLER; });
  order.erase(
      std::unique(order.begin(), order.end(), [&](int a, int b) { return points[a] == points[b]; }),
      order.end());
  if (order.size() < 3) return order;

  // Lower hull left to right, then upper hull right to left; a point is kept only
  // when it makes a strict left turn, so collinear points fall out.
  std::vector<int> hull;
  auto add = [&](int index, std::size_t floor) {
    while (hull.size() > floor &&
           CGAL::orientation(points[hull[hull.size() - 2]], points[hull.back()], points[index]) !=
               CGAL::LEFT_TURN)
      hull.pop_back();
    hull.push_back(index);
  };
  for (int index : order) add(index, 1);
  const std::size_t lower_size = hull.size();
  for (auto it = order.rbegin() + 1; it != order.rend(); ++it) add(*it, lower_size);
  hull.pop_back();  // the first point closes the upper hull
  return hull;
}

bool direction_less(const Vector3& a, const Vector3& b) {
  {
    const CGAL::Protect_FPU_rounding<true> upward;
    try {
      // Comparisons of overlapping intervals throw Uncertain_conversion_exception.
      return direction_less(a.approx(), b.approx());
    } catch (const CGAL::Uncertain_conversion_exception&) {
    }
  }
  return direction_less(exact_value(a), exact_value(b));
}

Vector3 in_plane_direction(const Vector3& normal) {
  // Cross with the coordinate axis least aligned with the normal: never parallel.
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (CGAL::abs(normal[i]) < CGAL::abs(normal[axis])) axis = i;
  const Vector3 e(axis == 0 ? 1 : 0, axis == 1 ? 1 : 0, axis == 2 ? 1 : 0);
  return CGAL::cross_product(normal, e);
}

}  // namespace penumbra::detail
