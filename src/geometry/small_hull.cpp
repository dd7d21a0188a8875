#include "small_hull.h"

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <cstdint>
#include <map>

#include "dyadic_vector.h"

namespace penumbra::detail {
namespace {

using Point = std::array<double, 3>;

// returns the sign of det(q - p, r - p, s - p): POSITIVE when s lies on the side of the
// plane (p, q, r) that (q - p) x (r - p) points to (CGAL::orientation's convention).
int orientation(const Point& p, const Point& q, const Point& r, const Point& s) {
  {
    CGAL::Protect_FPU_rounding<true> upward;
    using I = CGAL::Interval_nt<false>;
    I a[3], b[3], c[3];
    for (int i = 0; i < 3; ++i) {
      a[i] = I(q[i]) - I(p[i]);
      b[i] = I(r[i]) - I(p[i]);
      c[i] = I(s[i]) - I(p[i]);
    }
    const I det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                  a[2] * (b[0] * c[1] - b[1] * c[0]);
    if (det.inf() > 0) return 1;
    if (det.sup() < 0) return -1;
  }
  const Dyadic3 normal = cross(difference(q, p), difference(r, p));
  return static_cast<int>(dot(normal, difference(s, p)).sign());
}

// true when b lies strictly between a and c on their common line (the three collinear).
bool between(const Point& a, const Point& b, const Point& c) {
  for (int i = 0; i < 3; ++i)
    if (a[i] != c[i]) return (a[i] < b[i] && b[i] < c[i]) || (c[i] < b[i] && b[i] < a[i]);
  return false;
}

}  // namespace

std::vector<std::vector<std::size_t>> small_hull(const std::vector<Point>& points) {
  const std::size_t n = points.size();
  // Faces by the set of points on their plane (a bit mask), with a point strictly inside.
  std::map<std::uint32_t, std::size_t> faces;  // mask -> a point strictly behind the face
  std::vector<int> side(n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) {
        bool positive = false, negative = false;
        std::uint32_t mask = 0;
        std::size_t behind = n;
        for (std::size_t m = 0; m < n && !(positive && negative); ++m) {
          side[m] = (m == i || m == j || m == k)
                        ? 0
                        : orientation(points[i], points[j], points[k], points[m]);
          if (side[m] == 0)
            mask |= std::uint32_t{1} << m;
          else if (behind == n)
            behind = m;
          positive |= side[m] > 0;
          negative |= side[m] < 0;
        }
        // Collinear i, j, k make every point coplanar: no face.
        if ((positive && negative) || behind == n) continue;
        faces.emplace(mask, behind);
      }

  std::vector<std::vector<std::size_t>> cycles;
  for (const auto& face : faces) {
    // named copies, not a structured binding: the lambda below captures them (C++17).
    const auto mask = face.first;
    const auto inside = face.second;
    std::vector<std::size_t> on;
    for (std::size_t m = 0; m < n; ++m)
      if (mask >> m & 1) on.push_back(m);
    // a, b, c counter-clockwise seen from outside: the inside point is on the negative side.
    const auto turn = [&](std::size_t a, std::size_t b, std::size_t c) {
      return -orientation(points[a], points[b], points[c], points[inside]);
    };
    // Jarvis's march from the smallest point (an extreme point): the next vertex is the one
    // with every other point to its left, the farthest when several are collinear.
    const std::size_t start = *std::min_element(
        on.begin(), on.end(), [&](std::size_t a, std::size_t b) { return points[a] < points[b]; });
    std::vector<std::size_t> cycle;
    std::size_t current = start;
    do {
      cycle.push_back(current);
      std::size_t next = on[0] == current ? on[1] : on[0];
      for (std::size_t m : on) {
        if (m == current || m == next) continue;
        const int t = turn(current, next, m);
        if (t < 0 || (t == 0 && between(points[current], points[next], points[m]))) next = m;
      }
      current = next;
    } while (current != start && cycle.size() <= on.size());
    cycles.push_back(std::move(cycle));
  }
  return cycles;
}

}  // namespace penumbra::detail
