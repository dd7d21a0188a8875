#include "joint_region.h"

#include <algorithm>

#include "rational_enclosure.h"

namespace penumbra::detail {
namespace {

// A closed convex counter-clockwise polygon of the face's frame.
using Polygon = std::vector<RationalPoint2>;

// the function that is <= 0 on the left of the edge a -> b (the inside of a
// counter-clockwise ring).
Affine2 left_of(const RationalPoint2& a, const RationalPoint2& b) {
  return {b.y() - a.y(), a.x() - b.x(), (b.x() - a.x()) * a.y() - (b.y() - a.y()) * a.x()};
}

// twice the signed area (exact): positive for a counter-clockwise polygon with interior.
Rational twice_area(const Polygon& points) {
  Rational sum = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const RationalPoint2& a = points[k];
    const RationalPoint2& b = points[(k + 1) % points.size()];
    sum += a.x() * b.y() - a.y() * b.x();
  }
  return sum;
}

// the polygon if it has interior, else empty.
Polygon with_interior(Polygon polygon) {
  if (polygon.size() < 3 || !CGAL::is_positive(twice_area(polygon))) return {};
  return polygon;
}

// The parts of a convex polygon with interior on either side of a line: each has interior,
// or is empty.
struct Sides {
  Polygon below, above;  // f <= 0, f >= 0
};

// cuts the polygon (convex, with interior) by the line f = 0 (Sutherland-Hodgman, exact; the
// signs at the vertices certified by f's interval filter when it can), making the part above
// only when asked. A side the line does not enter is the polygon itself, moved, with no
// arithmetic; a side it enters is checked for interior.
Sides cut(Polygon polygon, const FilteredAffine& f, bool above_too) {
  const std::size_t n = polygon.size();
  std::vector<CGAL::Sign> signs(n);
  bool positive = false, negative = false;
  for (std::size_t k = 0; k < n; ++k) {
    signs[k] = f.sign(Probe(polygon[k]));
    positive = positive || signs[k] == CGAL::POSITIVE;
    negative = negative || signs[k] == CGAL::NEGATIVE;
  }
  Sides sides;
  if (!positive) {  // wholly below (touching the line at most)
    sides.below = std::move(polygon);
    return sides;
  }
  if (!negative) {
    if (above_too) sides.above = std::move(polygon);
    return sides;
  }
  for (std::size_t k = 0; k < n; ++k) {
    const RationalPoint2& p = polygon[k];
    const std::size_t next = (k + 1) % n;
    if (signs[k] != CGAL::POSITIVE) sides.below.push_back(p);
    if (above_too && signs[k] != CGAL::NEGATIVE) sides.above.push_back(p);
    if (signs[k] * signs[next] < 0) {  // the edge crosses the line
      const RationalPoint2& q = polygon[next];
      const Rational fp = f.exact()(p), fq = f.exact()(q);
      const RationalPoint2 x = p + (fp / (fp - fq)) * (q - p);
      if (above_too) sides.above.push_back(x);
      sides.below.push_back(x);
    }
  }
  sides.below = with_interior(std::move(sides.below));
  if (above_too) sides.above = with_interior(std::move(sides.above));
  return sides;
}

// the polygon (convex, with interior) clipped to every function's closed half-plane; empty
// when it has no interior.
Polygon clip_to(Polygon polygon, const EndShadow& volume) {
  for (const FilteredAffine& f : volume) {
    polygon = cut(std::move(polygon), f, false).below;
    if (polygon.empty()) return {};
  }
  return polygon;
}

// The enclosing box of a polygon's points (outward rounded): polygons whose boxes are apart
// (touching included) share no interior point.
struct Box {
  double low[2] = {0, 0}, high[2] = {-1, -1};
};

Box box_of(const Polygon& points) {
  Box box;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Interval c[2] = {enclosure(points[k].x()), enclosure(points[k].y())};
    for (int i = 0; i < 2; ++i) {
      box.low[i] = k == 0 ? c[i].inf() : std::min(box.low[i], c[i].inf());
      box.high[i] = k == 0 ? c[i].sup() : std::max(box.high[i], c[i].sup());
    }
  }
  return box;
}

bool apart(const Box& a, const Box& b) {
  for (int i = 0; i < 2; ++i)
    if (a.high[i] <= b.low[i] || b.high[i] <= a.low[i]) return true;
  return false;
}

// true when the convex polygon (with interior) has interior points outside every ring
// rings[order[k]], order[k + 1], ...: each ring's inside is cut off edge by edge, and the
// piece outside an edge and inside the edges before it goes on to the next ring; a ring
// holding the polygon leaves nothing, a ring whose box is apart from it leaves it whole.
// The answer does not depend on the order, only the work does.
bool sticks_out(const Polygon& polygon, const std::vector<ConvexRing>& rings,
                const std::vector<Box>& boxes, const std::vector<std::size_t>& order,
                std::size_t k) {
  const Box box = box_of(polygon);
  for (; k < order.size(); ++k) {
    const ConvexRing& ring = rings[order[k]];
    if (ring.empty() || apart(box, boxes[order[k]])) continue;
    if (std::all_of(polygon.begin(), polygon.end(),
                    [&](const RationalPoint2& p) { return ring.contains(p); }))
      return false;
    Polygon inside = polygon;
    bool split = false;
    const auto& points = ring.points();
    for (std::size_t e = 0; e < points.size() && !inside.empty(); ++e) {
      Sides sides = cut(std::move(inside),
                        FilteredAffine(left_of(points[e], points[(e + 1) % points.size()])), true);
      inside = std::move(sides.below);
      const Polygon& outside = sides.above;
      if (outside.empty()) continue;
      if (inside.empty() && !split) break;  // the ring misses the interior: go on whole
      split = true;
      if (sticks_out(outside, rings, boxes, order, k + 1)) return true;
    }
    if (split) return false;  // every piece outside the ring went on
  }
  return true;
}

// the indices of count umbrae with a's and b's first (a may equal b): they hold most of the
// set where a hides one end and b the other, all of it when a = b (the umbra is where both
// ends are hidden), so sticks_out's cutting ends sooner.
std::vector<std::size_t> own_umbrae_first(std::size_t a, std::size_t b, std::size_t count) {
  std::vector<std::size_t> order;
  if (a < count) order.push_back(a);
  if (b < count && b != a) order.push_back(b);
  for (std::size_t k = 0; k < count; ++k)
    if (k != a && k != b) order.push_back(k);
  return order;
}

}  // namespace

bool may_hide_together(const FaceRegion& face, const std::array<std::vector<EndShadow>, 2>& ends,
                       const std::vector<ConvexRing>& umbrae) {
  std::vector<Box> umbra_boxes;
  for (const ConvexRing& umbra : umbrae) umbra_boxes.push_back(box_of(umbra.points()));
  const std::size_t n = ends[0].size();
  for (const ConvexRing& piece : face.pieces()) {
    if (piece.empty()) continue;
    // each end's point shadows on the piece
    std::array<std::vector<Polygon>, 2> hidden;
    std::array<std::vector<Box>, 2> boxes;
    const Polygon whole = with_interior(piece.points());
    if (whole.empty()) continue;
    for (int end = 0; end < 2; ++end)
      for (std::size_t k = 0; k < n; ++k) {
        hidden[end].push_back(ends[end][k].empty() ? Polygon{} : clip_to(whole, ends[end][k]));
        boxes[end].push_back(box_of(hidden[end].back()));
      }
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = 0; b < n; ++b) {
        if (hidden[0][a].empty() || hidden[1][b].empty() || apart(boxes[0][a], boxes[1][b]))
          continue;
        const Polygon both = clip_to(hidden[0][a], ends[1][b]);
        if (both.empty()) continue;
        if (sticks_out(both, umbrae, umbra_boxes, own_umbrae_first(a, b, umbrae.size()), 0))
          return true;
      }
  }
  return false;
}

}  // namespace penumbra::detail
