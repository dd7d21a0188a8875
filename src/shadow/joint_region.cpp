#include "joint_region.h"

#include <algorithm>

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

// clips the polygon to the closed half-plane f <= 0 (Sutherland-Hodgman, exact; the signs
// at the vertices certified by f's interval filter when it can).
Polygon clip_below(const Polygon& polygon, const FilteredAffine& f) {
  const std::size_t n = polygon.size();
  std::vector<CGAL::Sign> signs(n);
  for (std::size_t k = 0; k < n; ++k) signs[k] = f.sign(Probe(polygon[k]));
  Polygon result;
  for (std::size_t k = 0; k < n; ++k) {
    const RationalPoint2& p = polygon[k];
    const RationalPoint2& q = polygon[(k + 1) % n];
    if (signs[k] != CGAL::POSITIVE) result.push_back(p);
    if (signs[k] * signs[(k + 1) % n] < 0) {  // the edge crosses the line
      const Rational fp = f.exact()(p), fq = f.exact()(q);
      result.push_back(p + (fp / (fp - fq)) * (q - p));
    }
  }
  return result;
}

// the polygon clipped to every function's closed half-plane; empty when it has no interior.
Polygon clip_to(Polygon polygon, const EndShadow& volume) {
  for (const FilteredAffine& f : volume) {
    polygon = clip_below(polygon, f);
    if (polygon.size() < 3) return {};
  }
  return with_interior(std::move(polygon));
}

// The enclosing box of a polygon's points (outward rounded): polygons whose boxes are apart
// (touching included) share no interior point.
struct Box {
  double low[2] = {0, 0}, high[2] = {-1, -1};
};

Box box_of(const Polygon& points) {
  Box box;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const std::pair<double, double> c[2] = {CGAL::to_interval(points[k].x()),
                                            CGAL::to_interval(points[k].y())};
    for (int i = 0; i < 2; ++i) {
      box.low[i] = k == 0 ? c[i].first : std::min(box.low[i], c[i].first);
      box.high[i] = k == 0 ? c[i].second : std::max(box.high[i], c[i].second);
    }
  }
  return box;
}

bool apart(const Box& a, const Box& b) {
  for (int i = 0; i < 2; ++i)
    if (a.high[i] <= b.low[i] || b.high[i] <= a.low[i]) return true;
  return false;
}

// true when the convex polygon (with interior) has interior points outside every ring from
// rings[k] on: each ring's inside is cut off edge by edge, and the piece outside an edge and
// inside the edges before it goes on to the next ring; a ring holding the polygon leaves
// nothing, a ring whose box is apart from it leaves it whole.
bool sticks_out(const Polygon& polygon, const std::vector<ConvexRing>& rings,
                const std::vector<Box>& boxes, std::size_t k) {
  const Box box = box_of(polygon);
  for (; k < rings.size(); ++k) {
    const ConvexRing& ring = rings[k];
    if (ring.empty() || apart(box, boxes[k])) continue;
    if (std::all_of(polygon.begin(), polygon.end(),
                    [&](const RationalPoint2& p) { return ring.contains(p); }))
      return false;
    Polygon inside = polygon;
    bool split = false;
    const auto& points = ring.points();
    for (std::size_t e = 0; e < points.size() && !inside.empty(); ++e) {
      const Affine2 f = left_of(points[e], points[(e + 1) % points.size()]);
      const Polygon outside = with_interior(clip_below(inside, FilteredAffine({-f.d, -f.e, -f.f})));
      inside = with_interior(clip_below(inside, FilteredAffine(f)));
      if (outside.empty()) continue;
      if (inside.empty() && !split) break;  // the ring misses the interior: go on whole
      split = true;
      if (sticks_out(outside, rings, boxes, k + 1)) return true;
    }
    if (split) return false;  // every piece outside the ring went on
  }
  return true;
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
    for (int end = 0; end < 2; ++end)
      for (std::size_t k = 0; k < n; ++k) {
        hidden[end].push_back(ends[end][k].empty() ? Polygon{}
                                                   : clip_to(piece.points(), ends[end][k]));
        boxes[end].push_back(box_of(hidden[end].back()));
      }
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = 0; b < n; ++b) {
        if (hidden[0][a].empty() || hidden[1][b].empty() || apart(boxes[0][a], boxes[1][b]))
          continue;
        const Polygon both = clip_to(hidden[0][a], ends[1][b]);
        if (!both.empty() && sticks_out(both, umbrae, umbra_boxes, 0)) return true;
      }
  }
  return false;
}

}  // namespace penumbra::detail
