#include "joint_region.h"

#include <algorithm>
#include <memory>
#include <optional>

namespace penumbra::detail {
namespace {

// The polygons of the test are cut from the face's pieces by lines, so every vertex is a
// piece's vertex or the crossing of an edge with a line. A vertex carries the enclosure of
// its coordinates and how it was made; its rational value is made only when a sign on it
// is one the intervals cannot certify (a tie, which is frequent: the point shadows of an
// occluder standing on the face share its foot's corners and edges with its umbra).

// A line of the test: the function d x + e y + f, <= 0 on its inside, as the enclosures of
// its coefficients, with the rational function made when needed: an end's point shadow's
// own (filtered) function, or the one on the left of a ring's edge. Its intervals, like the
// vertices', need upward rounding (joint_parts sets it).
class Line {
 public:
  explicit Line(const FilteredAffine& f) : approx_(f.enclosures()), filtered_(&f) {}
  Line(const ConvexRing& ring, std::size_t k) : ring_(&ring), edge_(k) {
    const auto& a = ring.enclosures()[k];
    const auto& b = ring.enclosures()[(k + 1) % ring.size()];
    approx_ = {b[1] - a[1], a[0] - b[0], (b[0] - a[0]) * a[1] - (b[1] - a[1]) * a[0]};
  }
  // the enclosure of the value at p (upward rounding).
  Interval value(const std::array<Interval, 2>& p) const {
    return approx_[0] * p[0] + approx_[1] * p[1] + approx_[2];
  }
  Affine2 exact() const {
    if (filtered_) return filtered_->exact();
    const RationalPoint2& a = ring_->points()[edge_];
    const RationalPoint2& b = ring_->points()[(edge_ + 1) % ring_->size()];
    return {b.y() - a.y(), a.x() - b.x(), (b.x() - a.x()) * a.y() - (b.y() - a.y()) * a.x()};
  }

 private:
  std::array<Interval, 3> approx_;
  const FilteredAffine* filtered_ = nullptr;
  const ConvexRing* ring_ = nullptr;
  std::size_t edge_ = 0;
};

struct Crossing;

// A vertex: a piece's corner (its rational value given), or where a line crosses the
// segment between two vertices (its value made when first asked for).
class Vertex {
 public:
  Vertex(const RationalPoint2& given, const std::array<Interval, 2>& at)
      : at_(at), given_(&given) {}
  // the crossing of the segment p q with the line f = 0, where f's signs at p and q are
  // strictly opposite (certified or exact).
  Vertex(const Vertex& p, const Vertex& q, const Line& f);

  const std::array<Interval, 2>& at() const { return at_; }
  const RationalPoint2& exact() const;

 private:
  std::array<Interval, 2> at_;
  const RationalPoint2* given_ = nullptr;
  std::shared_ptr<Crossing> made_;
};

struct Crossing {
  Vertex p, q;
  Line f;
  std::optional<RationalPoint2> value;
};

Vertex::Vertex(const Vertex& p, const Vertex& q, const Line& f)
    : made_(std::make_shared<Crossing>(Crossing{p, q, f, {}})) {
  // x = p + t (q - p) with 0 < t < 1, t = f(p) / (f(p) - f(q)) where the intervals can
  // bound it (when a sign was decided in rationals, they may not).
  const Interval fp = f.value(p.at_), fq = f.value(q.at_);
  Interval t(0, 1);
  if (!CGAL::possibly(fp == fq)) {
    const Interval ratio = fp / (fp - fq);
    t = Interval(std::max(0.0, ratio.inf()), std::min(1.0, ratio.sup()));
  }
  at_ = {p.at_[0] + t * (q.at_[0] - p.at_[0]), p.at_[1] + t * (q.at_[1] - p.at_[1])};
}

const RationalPoint2& Vertex::exact() const {
  if (given_) return *given_;
  Crossing& x = *made_;
  if (!x.value) {
    const Affine2 line = x.f.exact();
    const RationalPoint2 &p = x.p.exact(), &q = x.q.exact();
    const Rational fp = line(p), fq = line(q);
    x.value = p + (fp / (fp - fq)) * (q - p);
  }
  return *x.value;
}

// the sign of f at v: certified by the intervals, or else made in rationals.
CGAL::Sign sign(const Line& f, const Vertex& v) {
  const Interval value = f.value(v.at());
  if (value.inf() > 0) return CGAL::POSITIVE;
  if (value.sup() < 0) return CGAL::NEGATIVE;
  if (value.inf() == 0 && value.sup() == 0) return CGAL::ZERO;
  return CGAL::sign(f.exact()(v.exact()));
}

// A closed convex counter-clockwise polygon of the face's frame.
using Polygon = std::vector<Vertex>;

// the polygon if it has interior (twice its signed area is positive), else empty.
Polygon with_interior(Polygon polygon) {
  if (polygon.size() < 3) return {};
  const std::size_t n = polygon.size();
  Interval sum = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const auto& a = polygon[k].at();
    const auto& b = polygon[(k + 1) % n].at();
    sum += a[0] * b[1] - a[1] * b[0];
  }
  if (sum.inf() > 0) return polygon;
  if (sum.sup() <= 0) return {};
  Rational exact = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const RationalPoint2& a = polygon[k].exact();
    const RationalPoint2& b = polygon[(k + 1) % n].exact();
    exact += a.x() * b.y() - a.y() * b.x();
  }
  if (!CGAL::is_positive(exact)) return {};
  return polygon;
}

// true when the closed ring holds v.
bool contains(const ConvexRing& ring, const Vertex& v) {
  if (const std::optional<bool> in = ring.maybe_contains(v.at())) return *in;
  CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);  // for the rationals' enclosures
  return ring.contains(v.exact());
}

// The parts of a convex polygon with interior on either side of a line: each has interior,
// or is empty.
struct Sides {
  Polygon below, above;  // f <= 0, f >= 0
};

// cuts the polygon (convex, with interior) by the line f = 0 (Sutherland-Hodgman), making the
// part above only when asked. A side the line does not enter is the polygon itself, moved, with no
// arithmetic; a side it enters is checked for interior.
Sides cut(Polygon polygon, const Line& f, bool above_too) {
  const std::size_t n = polygon.size();
  std::vector<CGAL::Sign> signs(n);
  bool positive = false, negative = false;
  for (std::size_t k = 0; k < n; ++k) {
    signs[k] = sign(f, polygon[k]);
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
    const std::size_t next = (k + 1) % n;
    if (signs[k] != CGAL::POSITIVE) sides.below.push_back(polygon[k]);
    if (above_too && signs[k] != CGAL::NEGATIVE) sides.above.push_back(polygon[k]);
    if (signs[k] * signs[next] < 0) {  // the edge crosses the line
      const Vertex x(polygon[k], polygon[next], f);
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
    polygon = cut(std::move(polygon), Line(f), false).below;
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
    const auto& c = points[k].at();
    for (int i = 0; i < 2; ++i) {
      box.low[i] = k == 0 ? c[i].inf() : std::min(box.low[i], c[i].inf());
      box.high[i] = k == 0 ? c[i].sup() : std::max(box.high[i], c[i].sup());
    }
  }
  return box;
}

// the ring's corners as vertices.
Polygon corners(const ConvexRing& ring) {
  Polygon polygon;
  for (std::size_t k = 0; k < ring.size(); ++k)
    polygon.emplace_back(ring.points()[k], ring.enclosures()[k]);
  return polygon;
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
                    [&](const Vertex& p) { return contains(ring, p); }))
      return false;
    Polygon inside = polygon;
    bool split = false;
    for (std::size_t e = 0; e < ring.size() && !inside.empty(); ++e) {
      Sides sides = cut(std::move(inside), Line(ring, e), true);
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

std::vector<EnclosedPolygon> joint_parts(const FaceRegion& face,
                                         const std::array<std::vector<EndShadow>, 2>& ends,
                                         const std::vector<ConvexRing>& umbrae) {
  CGAL::Protect_FPU_rounding<true> upward;
  std::vector<EnclosedPolygon> parts;
  std::vector<Box> umbra_boxes;
  for (const ConvexRing& umbra : umbrae) umbra_boxes.push_back(box_of(corners(umbra)));
  const std::size_t n = ends[0].size();
  for (const ConvexRing& piece : face.pieces()) {
    if (piece.empty()) continue;
    // each end's point shadows on the piece
    std::array<std::vector<Polygon>, 2> hidden;
    std::array<std::vector<Box>, 2> boxes;
    const Polygon whole = with_interior(corners(piece));
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
        if (!sticks_out(both, umbrae, umbra_boxes, own_umbrae_first(a, b, umbrae.size()), 0))
          continue;
        EnclosedPolygon corners;
        for (const Vertex& v : both) corners.push_back(v.at());
        parts.push_back(std::move(corners));
      }
  }
  return parts;
}

std::array<Interval, 2> box_of(const EnclosedPolygon& polygon) {
  std::array<Interval, 2> box = polygon.front();
  for (const auto& at : polygon)
    for (int i = 0; i < 2; ++i)
      box[i] = Interval(std::min(box[i].inf(), at[i].inf()), std::max(box[i].sup(), at[i].sup()));
  return box;
}

bool may_meet(const std::array<Interval, 3>& line, const std::vector<EnclosedPolygon>& polygons) {
  CGAL::Protect_FPU_rounding<true> upward;
  return std::any_of(polygons.begin(), polygons.end(), [&](const EnclosedPolygon& polygon) {
    bool below = false, above = false;  // a corner's box that may reach either side
    for (const auto& at : polygon) {
      const Interval value = line[0] * at[0] + line[1] * at[1] + line[2];
      below = below || value.inf() <= 0;
      above = above || value.sup() >= 0;
    }
    return below && above;
  });
}

}  // namespace penumbra::detail
