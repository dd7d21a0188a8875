#include "penumbra/shadow/exact_umbra.h"

// The sweep (docs/linear-shadows.md, "Joint umbrae"): in pencil coordinates (pencil.h) every
// candidate boundary is a curve r = -num(s) / den(s) or a line of the pencil. The lines
// where an occluder's blocked interval changes form (its whole shadow's edges, the planes
// of its point shadows from each end of the source, its faces' planes, and the pencil
// lines through its vertices) cut the face into slabs in which their order is fixed; at a
// rational point of each piece between them the blocked intervals name the edges that fix
// their ends, hence the conics (t_high of one occluder = t_low of another) that can bound
// the umbra there. Their crossings, isolated exactly by CGAL's algebraic kernel, cut the
// slab into columns in which no two curves cross, and each cell of a column (between two
// consecutive curves) is labelled lit, penumbra or umbra at a rational point: by the
// straight single shadows and umbrae, and inside the region W where occluders may hide the
// source together by the union of the blocked intervals (interval filter, then exact).

#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <numeric>
#include <set>
#include <stdexcept>
#include <tuple>
#include <unordered_map>

#include "algebraic.h"
#include "blocked_interval.h"
#include "blocked_interval_filter.h"
#include "box_grid.h"
#include "convex_ring.h"
#include "exact_corner.h"
#include "joint_region.h"
#include "pencil.h"
#include "penumbra/base/gauss_legendre.h"
#include "penumbra/base/parallel.h"
#include "penumbra/geometry/exact.h"
#include "penumbra/geometry/interval.h"
#include "penumbra/shadow/linear_face_shadow.h"
#include "penumbra/shadow/linear_volumes.h"
#include "rational_enclosure.h"
#include "receiver_clip.h"
#include "region_set.h"

namespace penumbra {
namespace {

using detail::Affine2;
using detail::BlockedInterval;
using detail::ConvexRing;
using detail::DoubleCurve;
using detail::Pencil;
using detail::PencilCurve;
using detail::Poly;
using detail::Probe;
using detail::Quadratic2;
using detail::RationalVector2;

using detail::algebraic;
using detail::Algebraic;
using detail::algebraic_kernel;
using detail::all_roots;
using detail::approximate;
using detail::integer_polynomial;
using detail::rational_between;

RationalPoint2 rational_point(const Point2& p) {
  return exact_value(p);
}

// the affine function g . P + h of the face's points, in frame coordinates (the frames of
// axis-aligned faces are mostly zeros: sparse_dot skips them).
Affine2 on_face(const FaceFrame& frame, const RationalVector3& g, const Rational& h) {
  const RationalVector3& u = exact_value(frame.u());
  const RationalVector3& v = exact_value(frame.v());
  const RationalPoint3& o = exact_value(frame.origin());
  return {detail::sparse_dot(g, u), detail::sparse_dot(g, v), detail::sparse_dot(g, o) + h};
}

Affine2 on_face(const FaceFrame& frame, const RationalPlane3& plane) {
  return on_face(frame, RationalVector3(plane.a(), plane.b(), plane.c()), plane.d());
}

// the enclosures of a line's coefficients.
std::array<Interval, 3> enclosures(const Affine2& line) {
  return {detail::enclosure(line.d), detail::enclosure(line.e), detail::enclosure(line.f)};
}

// the line through a and b.
Affine2 line_through(const RationalPoint2& a, const RationalPoint2& b) {
  return {a.y() - b.y(), b.x() - a.x(), a.x() * b.y() - a.y() * b.x()};
}

// Where a line of the sweep matters (closed sets, Sweep::relevant): the face's boundary
// anywhere in the face (ring null); an edge of occluder owner's whole shadow (ring) where it
// bounds the union of the shadows, or in W; an edge of its single umbra (ring) anywhere
// outside the other umbrae; when in_w, in W within owner's whole shadow (ring). None matters
// strictly inside a single umbra.
struct LineRole {
  enum Kind : char { kFace, kShadow, kUmbra, kJoint };
  const ConvexRing* ring;
  Kind kind;
  std::size_t owner;
};

struct SweepLine {
  Affine2 line;
  std::vector<LineRole> roles;
  std::array<Interval, 3> approx;  // the enclosures of line's d, e, f
};

// What a cell of the sweep is: outside every shadow, penumbra, or umbra.
enum Label : char { kLit = 0, kPenumbra = 1, kUmbra = 2 };

// The labels of a column's cells by the curves (ids) below and above each: those of the last
// column of a slab while they may carry over the next seam (Sweep::slab).
using Carried = std::map<std::pair<int, int>, Label>;

struct Curve {
  PencilCurve f;
  Quadratic2 q;
  bool joint = false;
};

struct Column {
  Algebraic low, high;
  Rational sample;
  std::vector<int> curves;   // increasing r at the sample, distinct
  std::vector<char> labels;  // cell k lies below curves[k]; labels.back() above the last
};

struct Sector {
  Pencil pencil;
  std::vector<Column> columns;
  std::vector<Rational> seams;         // the slab bounds (rational), increasing
  std::vector<Algebraic> seam_values;  // the same as algebraic numbers, made once
};

// the value of a curve of a column at s: nullopt at a pole.
std::optional<Rational> r_at(const Curve& curve, const Rational& s) {
  const Rational den = curve.f.den(s);
  if (CGAL::is_zero(den)) return std::nullopt;
  return -curve.f.num(s) / den;
}

// An end of a boundary piece, exactly: on the line s of the pencil of sector (an algebraic
// s), on curve (an id) or, for a piece of a pencil line (curve -1), at the rational r.
struct PieceEnd {
  int sector;
  Algebraic s;
  int curve;
  std::optional<Rational> r;
  std::optional<Rational> ray_s;  // s, for a piece of a pencil line (always rational)
};

struct BoundaryPiece {
  UmbraArc arc;
  PieceEnd start, end;
};

// A piece of a chained ring, for its exact form (exact_corner.h): where it starts, its curve.
struct RingPiece {
  PieceEnd start;
  std::array<Exact, 6> curve;
  bool joint = false;
};
// the rings of one polygon: the outer ring, then its holes.
using PolygonPieces = std::vector<std::vector<RingPiece>>;

}  // namespace

// An occluder prepared for one source: its exact and interval forms, and in world
// coordinates the planes of its point shadow volumes from each end and the plane through the
// source and each vertex (where the solid's slice by the planes through the source changes).
struct UmbraSolid {
  RationalPoint3 q1, q2;
  detail::RationalSolid solid;
  std::array<std::vector<RationalPlane3>, 2> ends;
  std::array<std::vector<std::array<Interval, 4>>, 2> end_enclosures;  // of a, b, c, d
  std::vector<RationalPlane3> rays;

  // The interval filter of the solid with each edge's parameter for this source, and those
  // parameters in rationals: made when a sweep first asks (a face whose occluders cannot
  // hide the source together, the usual case, never does), once for every thread.
  const detail::IntervalSolid& filter() const {
    make_edges();
    return filter_;
  }
  const std::vector<detail::EdgeParameter>& edges() const {
    make_edges();
    return edges_;
  }

 private:
  void make_edges() const {
    std::call_once(edges_made_, [this] {
      edges_ = detail::edge_parameters(solid, q1, q2);
      filter_ = detail::interval_solid(solid);
      detail::enclose_edge_parameters(filter_, edges_);
    });
  }

  mutable std::once_flag edges_made_;
  mutable detail::IntervalSolid filter_;
  mutable std::vector<detail::EdgeParameter> edges_;
};

std::shared_ptr<const UmbraSolid> prepare_umbra_solid(const ConvexPolyhedron& solid,
                                                      const Point3& q1, const Point3& q2) {
  auto prepared = std::make_shared<UmbraSolid>();
  prepared->q1 = exact_value(q1);
  prepared->q2 = exact_value(q2);
  prepared->solid = detail::rational_solid(solid);
  // (the rational solid's planes begin with its faces', in order)
  for (int end = 0; end < 2; ++end) {
    prepared->ends[end] = exact_point_shadow_planes(solid, prepared->solid.vertices,
                                                    prepared->solid.planes, end ? q2 : q1);
    for (const RationalPlane3& h : prepared->ends[end])
      prepared->end_enclosures[end].push_back(detail::enclosure(h));
  }
  const RationalVector3 d = prepared->q2 - prepared->q1;
  for (const RationalPoint3& v : prepared->solid.vertices) {
    const RationalVector3 g = CGAL::cross_product(d, v - prepared->q1);
    prepared->rays.emplace_back(g.x(), g.y(), g.z(), -(g * (prepared->q1 - CGAL::ORIGIN)));
  }
  return prepared;
}

namespace {

// The sweep of one group of occluders whose whole shadows touch (exact_umbra: groups whose
// shadows are strictly apart cannot hide the source together, so each is swept alone).
struct SweptPart {
  bool whole = false;  // no part of the source is visible: the whole face
  detail::FaceRegion face;
  FaceFrame frame;
  std::deque<Curve> curves;  // (ids index it; a deque grows without copying the rationals)
  std::vector<Sector> sectors;
  std::optional<RationalPoint2> centre;  // x0 when finite
  bool centre_label = false;
  double area = 0, penumbra_area = 0;
  std::vector<UmbraArc> boundary, penumbra_boundary;
  std::vector<CurvedPolygon> umbra_polygons, penumbra_polygons;
  std::vector<PolygonPieces> umbra_pieces, penumbra_pieces;  // alike, piece by piece
  bool joint = false;
  std::size_t cells = 0;

  // the label of the cell of column at (s, r), s in the column's closed range: true when
  // an umbra cell of the column holds or touches the point.
  bool label_at(const Column& column, const Rational& s, const Rational& r,
                char kind = kUmbra) const {
    return label_at(column, values_at(column, s), r, kind);
  }

  // the values at s of the column's curves (nullopt at a pole: the curve is far away).
  std::vector<std::optional<Rational>> values_at(const Column& column, const Rational& s) const {
    std::vector<std::optional<Rational>> values;
    for (int id : column.curves) values.push_back(r_at(curves[id], s));
    return values;
  }

  // the labels between consecutive breaks (increasing, distinct, holding every value) on
  // the line s where the column's curves take the values: what label_at says there.
  std::vector<char> labels_between(const Column& column,
                                   const std::vector<std::optional<Rational>>& values,
                                   const std::vector<Rational>& breaks) const {
    std::vector<std::pair<const Rational*, std::size_t>> sorted;
    for (std::size_t k = 0; k < values.size(); ++k)
      if (values[k]) sorted.emplace_back(&*values[k], k);
    std::sort(sorted.begin(), sorted.end(),
              [](const auto& a, const auto& b) { return *a.first < *b.first; });
    std::vector<char> result;
    std::size_t next = 0, below = 0;
    for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
      // every value <= breaks[k] lies below the gap, every other one above it
      for (; next < sorted.size() && *sorted[next].first <= breaks[k]; ++next)
        below = std::max(below, sorted[next].second + 1);
      result.push_back(column.labels[below]);
    }
    return result;
  }

  // a box of rationals that holds the point where a piece ends (exact_corner.h).
  std::optional<detail::RationalBox> enclose(const PieceEnd& end, int bits) const {
    const Pencil& pencil = sectors[end.sector].pencil;
    const auto exactly = [](const RationalPoint2& p) {
      return detail::RationalBox{std::pair{p.x(), p.x()}, std::pair{p.y(), p.y()}};
    };
    if (end.curve < 0) return exactly(pencil.point(*end.ray_s, *end.r));
    const Curve& curve = curves[end.curve];
    if (end.s.is_rational()) {
      const Rational s = detail::rational(end.s.rational());
      if (const auto r = r_at(curve, s)) return exactly(pencil.point(s, *r));
    }
    const auto [low, high] = detail::enclosure(end.s, bits);
    const std::array<Poly, 3> point = pencil.curve_point(curve.f);
    const auto s = detail::ratio_range(point[0], point[2], low, high);
    const auto t = detail::ratio_range(point[1], point[2], low, high);
    if (!s || !t) return std::nullopt;
    return detail::RationalBox{*s, *t};
  }

  // the polygons of pieces in exact form (each ring canonical; their order is not).
  std::vector<ExactCurvedPolygon> exact_polygons(const std::vector<PolygonPieces>& pieces) const {
    const auto ring = [&](const std::vector<RingPiece>& traced) {
      std::vector<detail::TracedEdge> edges;
      for (const RingPiece& piece : traced) {
        const auto& c = piece.curve;
        edges.push_back({{exact_value(c[0]), exact_value(c[1]), exact_value(c[2]),
                          exact_value(c[3]), exact_value(c[4]), exact_value(c[5])},
                         piece.joint,
                         [this, end = piece.start](int bits) { return enclose(end, bits); }});
      }
      return detail::exact_ring(edges);
    };
    std::vector<ExactCurvedPolygon> result;
    for (const PolygonPieces& polygon : pieces) {
      ExactCurvedPolygon exact{ring(polygon.front()), {}};
      for (std::size_t k = 1; k < polygon.size(); ++k) exact.holes.push_back(ring(polygon[k]));
      result.push_back(std::move(exact));
    }
    return result;
  }

  // label_at with the column's curves' values at s given.
  bool label_at(const Column& column, const std::vector<std::optional<Rational>>& values,
                const Rational& r, char kind) const {
    std::size_t below = 0;
    for (std::size_t k = 0; k < values.size(); ++k) {
      if (!values[k]) continue;
      if (*values[k] == r) return column.labels[k] == kind || column.labels[k + 1] == kind;
      if (*values[k] < r) below = k + 1;
    }
    return column.labels[below] == kind;
  }
};

class Sweep {
 public:
  Sweep(SweptPart& impl, const Face& face, const RationalPoint3& q1, const RationalPoint3& q2,
        const std::vector<UmbraOccluder>& occluders)
      : impl_(impl), face_(face), q1_(q1), q2_(q2) {
    for (const UmbraOccluder& occluder : occluders) {
      // prepared for this source (the face's plane does not cut it), or made here
      const auto& ready = occluder.prepared;
      prepared_.push_back(ready && ready->q1 == q1 && ready->q2 == q2
                              ? ready
                              : prepare_umbra_solid(*occluder.solid, from_exact<Point3>(q1),
                                                    from_exact<Point3>(q2)));
      std::vector<RationalPoint2> ring;
      for (const Point2& p : occluder.shadow) ring.push_back(rational_point(p));
      shadows_.emplace_back(std::move(ring));
      std::vector<RationalPoint2> umbra;
      if (occluder.umbra)
        for (const Point2& p : *occluder.umbra) umbra.push_back(rational_point(p));
      umbrae_.emplace_back(std::move(umbra));
    }
    std::vector<std::array<Interval, 2>> boxes;
    for (const ConvexRing& shadow : shadows_) boxes.push_back(shadow.box());
    shadow_index_ = detail::BoxGrid(boxes);
    find_w();
  }

  // false when the group's occluders surely hide the source together nowhere on the face
  // (W has no interior: joint_parts), so no cell of its sweep is a joint part.
  bool may_be_joint() const { return covered_whole_ ? impl_.joint : !end_shadows_[0].empty(); }

  void run(Sector& sector) {
    if (!lines_collected_) collect_lines();
    const Pencil& pencil = sector.pencil;
    std::vector<Rational> seams{pencil.s_low(), pencil.s_high()};
    std::vector<Rational> along;  // the seams a line of the sweep runs along
    auto add_rays = [&](const Poly& rays, bool line) {
      if (rays.degree() != 1) return;
      // (degree 2: a degenerate conic's pair of pencil lines; none among straight lines)
      seams.push_back(-rays.c[0] / rays.c[1]);
      if (line) along.push_back(seams.back());
    };
    std::vector<std::size_t> line_curves;  // indices into lines_ of lines met once per ray
    std::vector<PencilCurve> line_traces;
    for (std::size_t k = 0; k < lines_.size(); ++k) {
      const detail::PencilTrace trace = pencil.trace(lines_[k].line.line());
      add_rays(trace.rays, true);
      if (!trace.curve) continue;
      if (trace.curve->den.degree() == 1)
        seams.push_back(-trace.curve->den.c[0] / trace.curve->den.c[1]);
      line_curves.push_back(k);
      line_traces.push_back(*trace.curve);
    }
    for (const Affine2& ray : rays_) add_rays(pencil.trace(ray.line()).rays, false);
    for (const RationalPoint2& p : impl_.face.points())
      if (const auto c = pencil.coordinates(p)) seams.push_back(c->first);
    // Crossings of two lines inside the face and inside a region of each: only lines whose
    // reaches meet (in s, then in their boxes) can cross where both matter. Taken in
    // increasing low s, each line meets those after it up to its high s.
    std::vector<Reach> reaches;
    {
      std::map<const ConvexRing*, Reach> rings;
      for (std::size_t k : line_curves) reaches.push_back(reach(pencil, lines_[k], rings));
    }
    std::vector<std::size_t> by_low(line_curves.size());
    std::iota(by_low.begin(), by_low.end(), std::size_t(0));
    std::sort(by_low.begin(), by_low.end(),
              [&](std::size_t a, std::size_t b) { return reaches[a].low < reaches[b].low; });
    for (std::size_t x = 0; x < by_low.size(); ++x)
      for (std::size_t y = x + 1;
           y < by_low.size() && reaches[by_low[y]].low <= reaches[by_low[x]].high; ++y) {
        const std::size_t i = by_low[x], j = by_low[y];
        if (reaches[i].apart(reaches[j])) continue;
        if (surely_apart(lines_[line_curves[i]], lines_[line_curves[j]])) continue;
        const Affine2& a = lines_[line_curves[i]].line;
        const Affine2& b = lines_[line_curves[j]].line;
        const Rational det = a.d * b.e - a.e * b.d;
        if (CGAL::is_zero(det)) continue;
        const RationalPoint2 p((a.e * b.f - a.f * b.e) / det, (a.f * b.d - a.d * b.f) / det);
        if (!relevant(lines_[line_curves[i]], p) || !relevant(lines_[line_curves[j]], p)) continue;
        if (const auto c = pencil.coordinates(p)) seams.push_back(c->first);
      }
    std::sort(seams.begin(), seams.end());
    seams.erase(std::unique(seams.begin(), seams.end()), seams.end());
    seams.erase(std::remove_if(
                    seams.begin(), seams.end(),
                    [&](const Rational& s) { return s < pencil.s_low() || s > pencil.s_high(); }),
                seams.end());
    sector.seams = seams;
    for (const Rational& s : seams) sector.seam_values.push_back(algebraic(s));
    std::sort(along.begin(), along.end());

    // Curves of the lines, registered once per sector.
    std::vector<int> line_ids;
    std::vector<detail::IntervalCurve> line_enclosures;
    known_.clear();
    conics_.clear();
    crossings_.clear();
    for (std::size_t k = 0; k < line_curves.size(); ++k) {
      line_ids.push_back(register_curve(line_traces[k], lines_[line_curves[k]].line.line(), false));
      line_enclosures.emplace_back(line_traces[k]);
    }
    // Each slab asks only the lines whose reach in s holds its middle (the middles increase).
    std::vector<std::size_t> active, here;
    std::size_t next = 0;
    Carried carried;
    for (std::size_t k = 0; k + 1 < seams.size(); ++k) {
      const Rational middle = detail::simplest_between(seams[k], seams[k + 1]);
      const Interval m = detail::enclosure(middle);
      for (; next < by_low.size() && reaches[by_low[next]].low <= m.sup(); ++next)
        active.push_back(by_low[next]);
      active.erase(std::remove_if(active.begin(), active.end(),
                                  [&](std::size_t i) { return reaches[i].high < m.inf(); }),
                   active.end());
      here = active;
      std::sort(here.begin(), here.end());
      // The last column's labels carry over the seam unless a line runs along it.
      if (std::binary_search(along.begin(), along.end(), seams[k])) carried.clear();
      slab(sector, k, middle, here, line_curves, line_ids, line_enclosures, carried);
    }
  }

 private:
  // true when p lies in two occluders' whole shadows and both ends of the source are hidden
  // from it, each by some occluder (closed sets): only there can occluders hide the whole
  // source together (the sweep's region W). Each set is bounded by lines of the sweep.
  // (An occluder's point shadows lie in its whole shadow: only those holding p are asked.)
  bool shared(const Probe& p) const {
    if (end_shadows_[0].empty()) return false;
    const std::vector<std::size_t> under = holding(p);
    if (under.size() < 2) return false;
    for (const auto& hidden : end_shadows_)
      if (std::none_of(under.begin(), under.end(), [&](std::size_t k) {
            const detail::EndShadow& volume = hidden[k];
            return !volume.empty() &&
                   std::all_of(volume.begin(), volume.end(), [&](const detail::FilteredAffine& f) {
                     return f.sign(p) != CGAL::POSITIVE;
                   });
          }))
        return false;
    return true;
  }

  // the occluders whose whole shadows' boxes meet the enclosure at, increasing: the only ones
  // whose whole shadows, single umbrae and point shadows can hold a point there.
  std::vector<std::size_t> near(const std::array<Interval, 2>& at) const {
    std::vector<std::size_t> result;
    shadow_index_.query(at, result);
    return result;
  }

  // the occluders whose whole shadows hold p (closed), increasing.
  std::vector<std::size_t> holding(const Probe& p) const {
    std::vector<std::size_t> result = near(p.at);
    result.erase(std::remove_if(result.begin(), result.end(),
                                [&](std::size_t k) { return !shadows_[k].contains(p); }),
                 result.end());
    return result;
  }

  // true when the line matters at point (LineRole). Strictly inside a single umbra every cell
  // around is umbra; strictly inside another occluder's whole shadow and outside W an edge of
  // a whole shadow has shadow on both sides, and the label there (penumbra or umbra) does not
  // depend on it. Where a line's relevance changes it crosses a line that matters there: a
  // seam of the sweep.
  bool relevant(const SweepLine& line, const RationalPoint2& point) const {
    const Probe p(point);
    if (!impl_.face.contains(p)) return false;
    std::optional<bool> in_w, in_umbra;
    std::optional<std::vector<std::size_t>> around;
    const auto inside = [&](const std::vector<ConvexRing>& rings, std::size_t except) {
      if (!around) around = near(p.at);
      return std::any_of(around->begin(), around->end(), [&](std::size_t k) {
        return k != except && rings[k].strictly_contains(p);
      });
    };
    for (const LineRole& role : line.roles) {
      if (role.kind == LineRole::kFace) return true;
      if (!role.ring->contains(p)) continue;
      if (!in_umbra) in_umbra = inside(umbrae_, prepared_.size());
      if (*in_umbra) return false;
      if (role.kind == LineRole::kUmbra) return true;
      if (role.kind == LineRole::kShadow && !inside(shadows_, role.owner)) return true;
      if (!in_w) in_w = shared(p);
      if (*in_w) return true;
    }
    return false;
  }

  // Where a line of a sector can matter: the closed range of s over the rings of its roles and
  // the box of those rings, enclosed in doubles (the whole plane for a role anywhere in the
  // face; all s for a ring not inside the sector's closed cone).
  struct Reach {
    static constexpr double kInfinity = std::numeric_limits<double>::infinity();
    double low = kInfinity, high = -kInfinity;  // s
    double box[2][2] = {{kInfinity, -kInfinity}, {kInfinity, -kInfinity}};
    // true when the boxes do not meet.
    bool apart(const Reach& other) const {
      for (int axis = 0; axis < 2; ++axis)
        if (box[axis][1] < other.box[axis][0] || other.box[axis][1] < box[axis][0]) return true;
      return false;
    }
    void add(const Reach& other) {
      low = std::min(low, other.low);
      high = std::max(high, other.high);
      for (int axis = 0; axis < 2; ++axis) {
        box[axis][0] = std::min(box[axis][0], other.box[axis][0]);
        box[axis][1] = std::max(box[axis][1], other.box[axis][1]);
      }
    }
  };

  // the reach of a ring: within the closed cone (or across the parallel lines), s over a
  // convex ring runs between its values at the vertices. rings keeps those made.
  Reach reach(const Pencil& pencil, const SweepLine& line,
              std::map<const ConvexRing*, Reach>& rings) const {
    Reach result;
    for (const LineRole& role : line.roles) {
      if (!role.ring) {
        Reach everywhere;
        everywhere.low = -Reach::kInfinity;
        everywhere.high = Reach::kInfinity;
        for (auto& axis : everywhere.box) axis[0] = -Reach::kInfinity, axis[1] = Reach::kInfinity;
        return everywhere;
      }
      auto found = rings.find(role.ring);
      if (found == rings.end()) {
        Reach ring;
        const auto box = role.ring->box();
        for (int axis = 0; axis < 2; ++axis)
          ring.box[axis][0] = box[axis].inf(), ring.box[axis][1] = box[axis].sup();
        for (const RationalPoint2& v : role.ring->points()) {
          const auto c = pencil.coordinates(v);
          if (!c) {
            ring.low = -Reach::kInfinity;
            ring.high = Reach::kInfinity;
            break;
          }
          const Interval s = detail::enclosure(c->first);
          ring.low = std::min(ring.low, s.inf());
          ring.high = std::max(ring.high, s.sup());
        }
        found = rings.emplace(role.ring, ring).first;
      }
      result.add(found->second);
    }
    return result;
  }

  // true when the intervals show that the lines do not cross where both matter.
  bool surely_apart(const SweepLine& a, const SweepLine& b) const {
    CGAL::Protect_FPU_rounding<true> upward;
    const auto& [ad, ae, af] = a.approx;
    const auto& [bd, be, bf] = b.approx;
    const Interval det = ad * be - ae * bd;
    if (det.inf() <= 0 && det.sup() >= 0) return false;
    const std::array<Interval, 2> at{(ae * bf - af * be) / det, (af * bd - ad * bf) / det};
    return surely_irrelevant(a, at) || surely_irrelevant(b, at);
  }

  // true when the intervals show that the line (the curve enclosed) does not matter where it
  // meets the pencil's line s (enclosed): it misses the face or every ring of its roles
  // there, or meets it at r <= 0 around a finite centre.
  bool surely_irrelevant(const Pencil& pencil, const SweepLine& line,
                         const detail::IntervalCurve& curve, const Interval& s) const {
    CGAL::Protect_FPU_rounding<true> upward;
    const auto r = curve.r(s);
    if (!r) return false;
    if (pencil.finite() && r->sup() <= 0) return true;
    return surely_irrelevant(line, detail::interval_point(pencil, s, *r));
  }

  // the same at a point enclosed by at (upward rounding).
  bool surely_irrelevant(const SweepLine& line, const std::array<Interval, 2>& at) const {
    if (impl_.face.maybe_contains(at) == false) return true;
    return std::all_of(line.roles.begin(), line.roles.end(), [&](const LineRole& role) {
      return role.ring && role.ring->maybe_contains(at) == false;
    });
  }

  void add_line(const Affine2& line, const LineRole& role) {
    if (CGAL::is_zero(line.d) && CGAL::is_zero(line.e)) return;
    // normalise: the first nonzero of (d, e) is 1, so equal lines compare equal.
    const Rational k = CGAL::is_zero(line.d) ? line.e : line.d;
    const Affine2 unit{line.d / k, line.e / k, line.f / k};
    for (SweepLine& known : lines_)
      if (known.line.d == unit.d && known.line.e == unit.e && known.line.f == unit.f) {
        known.roles.push_back(role);
        return;
      }
    lines_.push_back({unit, {role}, enclosures(unit)});
  }

  // the point shadows of the source's ends on the face, kept when the occluders may hide
  // it together there (W may have interior), else left empty.
  void find_w() {
    // W needs two occluders and interior on the face (joint_region.h); without it the
    // lines that only matter in W are left out and no point is shared.
    if (prepared_.size() < 2) return;
    // Each plane's function on the face, (n . u) x + (n . v) y + n . o + h, enclosed from
    // the enclosures of the plane and the frame; the rationals only when a sign needs them.
    CGAL::Protect_FPU_rounding<true> upward;
    const auto& [o, u, v] = frame_;
    for (const auto& prepared : prepared_)
      for (int end = 0; end < 2; ++end) {
        detail::EndShadow volume;
        volume.reserve(prepared->ends[end].size());
        for (std::size_t k = 0; k < prepared->ends[end].size(); ++k) {
          const auto& [a, b, c, h] = prepared->end_enclosures[end][k];
          const RationalPlane3* plane = &prepared->ends[end][k];
          volume.emplace_back(std::array<Interval, 3>{a * u[0] + b * u[1] + c * u[2],
                                                      a * v[0] + b * v[1] + c * v[2],
                                                      a * o[0] + b * o[1] + c * o[2] + h},
                              [frame = &face_.frame, plane] { return on_face(*frame, *plane); });
        }
        end_shadows_[end].push_back(std::move(volume));
      }
    w_parts_ = detail::joint_parts(impl_.face, end_shadows_, umbrae_);
    if (w_parts_.empty()) end_shadows_ = {};
    if (!w_parts_.empty() && certify_whole_umbra()) {
      // Every point of the face is umbra: the sweep needs only the face's edges.
      prepared_.clear();
      shadows_.clear();
      umbrae_.clear();
      end_shadows_ = {};
      w_parts_.clear();
      shadow_index_ = detail::BoxGrid();
      return;
    }
    std::vector<std::array<Interval, 2>> boxes;
    for (const auto& part : w_parts_) boxes.push_back(detail::box_of(part));
    w_index_ = detail::BoxGrid(boxes);
  }

  // true when the intervals certify that every point of the face is umbra, and then
  // impl_.joint says whether that takes two or more occluders. A convex occluder hides the
  // point q of the source from every point of a convex piece when it hides it from the
  // piece's corners (the points hiding q from it, its point shadow, are convex: section
  // 4.2.2), so where the parts of the source that each occluder hides from all the corners
  // (the intersection of their blocked intervals, enclosed from within) cover the source,
  // the piece is umbra. The umbra is closed, so a corner that surely sees some of the
  // source ends the test at once. A sufficient test only: where it fails, the sweep decides.
  bool certify_whole_umbra() {
    CGAL::Protect_FPU_rounding<true> upward;
    bool joint = false;
    for (const ConvexRing& piece : impl_.face.pieces()) {
      if (piece.empty()) continue;
      std::vector<std::pair<double, double>> within(prepared_.size(), {0, 1});
      for (std::size_t c = 0; c < piece.size(); ++c) {
        std::vector<std::pair<double, double>> around;
        for (std::size_t k = 0; k < prepared_.size(); ++k) {
          const Hidden h = hidden_from(*prepared_[k], piece.enclosures()[c], piece.points()[c]);
          within[k] = {std::max(within[k].first, h.low), std::min(within[k].second, h.high)};
          around.emplace_back(h.outer_low, h.outer_high);
        }
        if (!cover(around)) return false;
      }
      if (!cover(within)) return false;
      joint = joint || std::none_of(within.begin(), within.end(),
                                    [](const auto& w) { return w.first <= 0 && w.second >= 1; });
    }
    impl_.joint = joint;
    covered_whole_ = true;
    return true;
  }

  // What an occluder hides of the source from a corner of the face (at encloses it): what
  // it surely hides (low, high; empty when low > high) and a superset of it (outer; [0, 1]
  // when unknown). From the interval filter (which needs the corner surely outside the
  // solid), else from the exact clipping (for a corner on
  // the solid's boundary that counts only the directions strictly into the solid, fewer than
  // the closed solid hides). Needs upward rounding.
  struct Hidden {
    double low = 1, high = 0;
    double outer_low = 0, outer_high = 1;
  };
  Hidden hidden_from(const UmbraSolid& prepared, const std::array<Interval, 2>& at,
                     const RationalPoint2& corner) {
    if (const auto b = detail::blocked_bounds(prepared.filter(), world(at), q1i_, q2i_)) {
      if (b->kind == BlockedInterval::Kind::none) return {1, 0, 1, 0};
      if (b->kind == BlockedInterval::Kind::full) return {0, 1, 0, 1};
      return {b->low.sup(), b->high.inf(), b->low.inf(), b->high.sup()};
    }
    const BlockedInterval b = detail::blocked_interval(prepared.solid, world(corner), q1_, q2_);
    if (b.kind == BlockedInterval::Kind::none) return {1, 0, 1, 0};
    const Interval low = detail::enclosure(b.low), high = detail::enclosure(b.high);
    return {low.sup(), high.inf(), low.inf(), high.sup()};
  }

  // true when the closed intervals (pairs low, high; empty ones skipped) cover [0, 1].
  static bool cover(std::vector<std::pair<double, double>> intervals) {
    std::sort(intervals.begin(), intervals.end());
    double reach = 0;
    for (const auto& [low, high] : intervals) {
      if (low > high) continue;
      if (low > reach) return false;
      reach = std::max(reach, high);
    }
    return reach >= 1;
  }

  // the lines of the sweep (made when it first runs: a face none of whose groups may hide
  // the source together is not swept).
  void collect_lines() {
    lines_collected_ = true;
    const FaceFrame& frame = face_.frame;
    for (const auto& ring : impl_.face.boundary())
      for (std::size_t k = 0; k < ring.size(); ++k)
        add_line(line_through(ring[k], ring[(k + 1) % ring.size()]), {nullptr, LineRole::kFace, 0});
    const bool in_w = !end_shadows_[0].empty();
    for (std::size_t o = 0; o < prepared_.size(); ++o) {
      const ConvexRing* region = &shadows_[o];
      const auto& outer = region->points();
      for (std::size_t k = 0; k < outer.size(); ++k)
        add_line(line_through(outer[k], outer[(k + 1) % outer.size()]),
                 {region, LineRole::kShadow, o});
      const ConvexRing* umbra = &umbrae_[o];
      const auto& inner = umbra->points();
      for (std::size_t k = 0; k < inner.size(); ++k)
        add_line(line_through(inner[k], inner[(k + 1) % inner.size()]),
                 {umbra, LineRole::kUmbra, o});
      // The rest only matters in W within the occluder's whole shadow: lines that miss every
      // part of W meeting the shadow's box are left out.
      if (!in_w) continue;
      std::vector<std::size_t> found;
      w_index_.query(region->box(), found);
      if (found.empty()) continue;
      std::vector<detail::EnclosedPolygon> parts;
      detail::EnclosedPolygon hull;  // all their corners: those parts lie in its hull
      for (std::size_t k : found) {
        parts.push_back(w_parts_[k]);
        hull.insert(hull.end(), w_parts_[k].begin(), w_parts_[k].end());
      }
      const UmbraSolid& prepared = *prepared_[o];
      for (int end = 0; end < 2; ++end)
        for (const detail::FilteredAffine& f : end_shadows_[end][o])
          if (detail::may_meet(f.enclosures(), parts))
            add_line(f.exact(), {region, LineRole::kJoint, o});
      for (const RationalPlane3& plane : prepared.solid.planes)
        if (Affine2 line = on_face(frame, plane); detail::may_meet(enclosures(line), parts))
          add_line(line, {region, LineRole::kJoint, o});
      // A ray is a line of the pencil where an edge of the occluder's blocked interval
      // changes: a slab holding those parts on both sides of it needs it as a seam, so it is
      // left out only when it misses their hull.
      for (const RationalPlane3& ray : prepared.rays)
        if (Affine2 line = on_face(frame, ray); detail::may_meet(enclosures(line), {hull}))
          rays_.push_back(std::move(line));
    }
  }

  const detail::RationalSolid& solid(std::size_t k) const { return prepared_[k]->solid; }

  RationalPoint3 world(const RationalPoint2& p) const { return face_.frame.to_world(p); }

  // the enclosure of the world point at a point of the face enclosed by at (upward rounding).
  IntervalPoint world(const std::array<Interval, 2>& at) const {
    IntervalPoint x;
    for (int i = 0; i < 3; ++i) x[i] = frame_[0][i] + at[0] * frame_[1][i] + at[1] * frame_[2][i];
    return x;
  }

  // returns the id of the curve r = -num / den of this sector, registering it when new: one
  // id per curve (num and den have no common factor, so dividing both by den's leading
  // coefficient makes the pair unique), so that a degenerate conic along a line of the sweep
  // is that line, and pieces of one curve chain and merge.
  int register_curve(const PencilCurve& f, const Quadratic2& q, bool joint) {
    const Rational lead = f.den.c.back();
    std::vector<Rational> key;
    for (const Rational& c : f.num.c) key.push_back(c / lead);
    key.push_back(Rational(f.num.c.size()));  // separates num's coefficients from den's
    for (const Rational& c : f.den.c) key.push_back(c / lead);
    const auto found = known_.find(key);
    if (found != known_.end()) return found->second;
    const int id = static_cast<int>(impl_.curves.size());
    impl_.curves.push_back({f, q, joint});
    known_.emplace(std::move(key), id);
    return id;
  }

  // label_of at the pencil's point (s, r) from intervals alone (upward rounding), without
  // making the point: nullopt when a sign or comparison is not certified.
  std::optional<Label> maybe_label(const Pencil& pencil, const Rational& s, const Rational& r) {
    CGAL::Protect_FPU_rounding<true> upward;
    const std::array<Interval, 2> at =
        detail::interval_point(pencil, detail::enclosure(s), detail::enclosure(r));
    const auto in_face = impl_.face.maybe_contains(at);
    if (!in_face) return std::nullopt;
    if (!*in_face) return kLit;
    if (covered_whole_) return kUmbra;
    const std::vector<std::size_t> candidates = near(at);
    std::vector<std::size_t> under;  // the occluders whose whole shadows hold the point
    for (std::size_t k : candidates) {
      const auto in = shadows_[k].maybe_contains(at);
      if (!in) return std::nullopt;
      if (*in) under.push_back(k);
    }
    if (under.empty()) return kLit;
    bool unsure = false;
    for (std::size_t k : candidates) {
      const auto in = umbrae_[k].maybe_contains(at);
      if (in && *in) return kUmbra;
      unsure = unsure || !in;
    }
    if (unsure) return std::nullopt;
    // shared(): both ends hidden, each by some occluder
    if (under.size() < 2 || end_shadows_[0].empty()) return kPenumbra;
    for (const auto& hidden : end_shadows_) {
      bool any = false;
      for (std::size_t k : under) {
        const detail::EndShadow& volume = hidden[k];
        if (volume.empty()) continue;
        std::optional<bool> all = true;
        for (const detail::FilteredAffine& f : volume) {
          const auto sign = f.maybe_sign(at);
          if (sign == CGAL::POSITIVE) {
            all = false;
            break;
          }
          if (!sign) all = std::nullopt;
        }
        if (!all) return std::nullopt;
        any = any || *all;
      }
      if (!any) return kPenumbra;
    }
    // covered(): the blocked intervals at the world point
    const IntervalPoint x = world(at);
    std::vector<detail::BlockedBounds> bounds;
    for (std::size_t k : under) {
      const auto b = detail::blocked_bounds(prepared_[k]->filter(), x, q1i_, q2i_);
      if (!b) return std::nullopt;
      bounds.push_back(*b);
    }
    const auto covers = detail::covers_source(bounds);
    if (!covers) return std::nullopt;
    if (!*covers) return kPenumbra;
    impl_.joint = true;
    return kUmbra;
  }

  // the label of a point inside a cell (off every curve of the sweep): outside the shadows,
  // in a single umbra (the straight rings), or, where occluders may hide the source
  // together, covered by the exact union of the blocked intervals.
  Label label_of(const RationalPoint2& point) {
    const Probe p(point);
    if (!impl_.face.contains(p)) return kLit;
    if (covered_whole_) return kUmbra;
    const std::vector<std::size_t> under = holding(p);
    if (under.empty()) return kLit;
    if (std::any_of(under.begin(), under.end(),
                    [&](std::size_t k) { return umbrae_[k].contains(p); }))
      return kUmbra;
    if (!shared(p) || !covered(p)) return kPenumbra;
    impl_.joint = true;
    return kUmbra;
  }

  // true when the occluders' blocked intervals at p cover the source: certified by the
  // interval filter when it can, else exact. Where the filter names an end's edge but cannot
  // order the ends (pieces of one wall hide abutting intervals: a gap of exactly zero), that
  // end is the edge's parameter at p (blocked_interval.h), a quotient of two affine values,
  // and only the occluders the filter cannot name are clipped in rationals.
  bool covered(const Probe& p) const {
    const RationalPoint3 x = world(p.point);
    const std::vector<std::size_t> under = holding(p);
    std::vector<std::optional<detail::BlockedBounds>> named(under.size());
    {
      CGAL::Protect_FPU_rounding<true> upward;
      const IntervalPoint at = detail::interval_point(x);
      std::vector<detail::BlockedBounds> bounds;
      for (std::size_t i = 0; i < under.size(); ++i) {
        named[i] = detail::blocked_bounds(prepared_[under[i]]->filter(), at, q1i_, q2i_);
        if (named[i]) bounds.push_back(*named[i]);
      }
      if (bounds.size() == under.size())
        if (const auto covers = detail::covers_source(bounds)) return *covers;
    }
    std::vector<BlockedInterval> exact(under.size());
    for (std::size_t i = 0; i < under.size(); ++i)
      exact[i] = named[i] ? exactly(under[i], *named[i], x)
                          : detail::blocked_interval(solid(under[i]), x, q1_, q2_);
    return detail::covers_source(std::move(exact));
  }

  // the exact blocked interval of occluder k at x whose kind and ends' edges the filter
  // certified (bounds): a clamp is 0 or 1, another end its edge's parameter at x.
  BlockedInterval exactly(std::size_t k, const detail::BlockedBounds& bounds,
                          const RationalPoint3& x) const {
    BlockedInterval result;
    result.kind = bounds.kind;
    result.low_edge = bounds.low_edge;
    result.high_edge = bounds.high_edge;
    if (bounds.kind == BlockedInterval::Kind::none) return result;
    result.low = bounds.low_clamped ? Rational(0) : edge_value(k, bounds.low_edge, x);
    result.high = bounds.high_clamped ? Rational(1) : edge_value(k, bounds.high_edge, x);
    return result;
  }

  // t = (g_n . x + h_n) / (g_d . x + h_d) for edge e of occluder k.
  Rational edge_value(std::size_t k, int e, const RationalPoint3& x) const {
    const detail::EdgeParameter& t = prepared_[k]->edges()[e];
    const RationalVector3 o = x - CGAL::ORIGIN;
    return (t.gn * o + t.hn) / (t.gd * o + t.hd);
  }

  // What an occluder hides from a point, without the values: the kind of its blocked
  // interval and the edges that fix its ends.
  struct Ends {
    std::size_t occluder;
    BlockedInterval::Kind kind;
    int low_edge, high_edge;
  };

  // the ends of the blocked intervals of the occluders whose whole shadows hold p (the others
  // hide nothing): from the interval filter when it can, else exact.
  std::vector<Ends> ends(const Probe& p) const {
    const RationalPoint3 x = world(p.point);
    const IntervalPoint at = detail::interval_point(x);  // (enclosures are outward in any rounding)
    std::vector<Ends> result;
    for (std::size_t k : holding(p)) {
      std::optional<detail::BlockedBounds> b;
      {
        CGAL::Protect_FPU_rounding<true> upward;
        b = detail::blocked_bounds(prepared_[k]->filter(), at, q1i_, q2i_);
      }
      if (b) {
        result.push_back({k, b->kind, b->low_edge, b->high_edge});
      } else {
        const BlockedInterval exact = detail::blocked_interval(solid(k), x, q1_, q2_);
        result.push_back({k, exact.kind, exact.low_edge, exact.high_edge});
      }
    }
    return result;
  }

  // A conic of the sweep in this sector's pencil: its curve's id (-1: none) and the roots of
  // the pencil lines it holds.
  struct GapConic {
    int id = -1;
    std::vector<Algebraic> rays;
  };

  // the conic t_high(j) = t_low(k) of the edges f of occluder j and e of occluder k in the
  // pencil, made once per sector.
  const GapConic& gap_conic(const Pencil& pencil, std::size_t j, int f, std::size_t k, int e) {
    const std::array<std::size_t, 4> key{j, static_cast<std::size_t>(f), k,
                                         static_cast<std::size_t>(e)};
    const auto found = conics_.find(key);
    if (found != conics_.end()) return found->second;
    GapConic& conic = conics_[key];
    const Quadratic2 q = gap_quadratic(j, f, k, e);
    const detail::PencilTrace trace = pencil.trace(q);
    if (!trace.rays.zero()) conic.rays = all_roots(trace.rays);
    if (trace.curve) conic.id = register_curve(*trace.curve, q, true);
    return conic;
  }

  // Where the curve a meets the curve b (an id), a pole (den = 0, b = kPole) or the centre
  // (r = 0, b = kCentre): the real roots of the crossing polynomial, isolated once per sector
  // when first needed; nullptr when intervals show that it has no root in the closed range
  // of s (most pairs of a slab never meet in it, and isolating roots is the costly part).
  static constexpr int kPole = -1, kCentre = -2;
  const std::vector<Algebraic>* crossing_roots(int a, int b, const Interval& range) {
    CGAL::Protect_FPU_rounding<true> upward;
    auto found = crossings_.find({a, b});
    if (found == crossings_.end()) {
      std::vector<Interval> enclosure;
      const detail::IntervalCurve& c = enclosed(a);
      if (b == kPole) {
        enclosure = c.den;
      } else if (b == kCentre) {
        enclosure = c.num;
      } else {
        const detail::IntervalCurve& o = enclosed(b);
        enclosure =
            detail::difference(detail::product(c.num, o.den), detail::product(o.num, c.den));
      }
      found = crossings_.emplace(std::pair{a, b}, Crossing{std::move(enclosure), {}}).first;
    }
    Crossing& crossing = found->second;
    if (detail::surely_no_root(crossing.enclosure, range)) return nullptr;
    if (!crossing.roots) {
      const PencilCurve& c = impl_.curves[a].f;
      if (b == kPole) {
        crossing.roots = all_roots(c.den);
      } else if (b == kCentre) {
        crossing.roots = all_roots(c.num);
      } else {
        const PencilCurve& o = impl_.curves[b].f;
        crossing.roots = all_roots(c.num * o.den - o.num * c.den);
      }
    }
    return &*crossing.roots;
  }

  // the conic t_high(j) = t_low(k) of the edges f of occluder j and e of occluder k.
  Quadratic2 gap_quadratic(std::size_t j, int f, std::size_t k, int e) const {
    auto parameter = [&](std::size_t o, int edge) {
      const detail::EdgeParameter& t = prepared_[o]->edges()[edge];
      return std::make_pair(on_face(face_.frame, t.gn, t.hn), on_face(face_.frame, t.gd, t.hd));
    };
    const auto [nf, df] = parameter(j, f);
    const auto [ne, de] = parameter(k, e);
    const Quadratic2 left = nf * de, right = ne * df;
    return {left.a - right.a, left.b - right.b, left.c - right.c,
            left.d - right.d, left.e - right.e, left.f - right.f};
  }

  struct Portion {
    int bottom = -1, top = -1;  // curve ids (-1: r = 0 at a finite centre)
    std::vector<int> conics;
  };

  // sweeps the slab between the seams seam and seam + 1 of the sector.
  // middle: the slab's sample s; active: the lines (positions in line_curves, increasing) that
  // may matter there.
  void slab(Sector& sector, std::size_t seam, const Rational& middle,
            const std::vector<std::size_t>& active, const std::vector<std::size_t>& line_curves,
            const std::vector<int>& line_ids,
            const std::vector<detail::IntervalCurve>& line_enclosures, Carried& carried) {
    const Pencil& pencil = sector.pencil;
    const Rational &sa = sector.seams[seam], &sb = sector.seams[seam + 1];
    // The lines that matter on this slab, in increasing r.
    std::vector<int> straight;
    std::vector<Rational> below;  // a point r below each line and above the one before
    if (!lines_by_intervals(pencil, middle, active, line_curves, line_ids, line_enclosures,
                            straight, below))
      lines_exactly(pencil, middle, active, line_curves, line_ids, line_enclosures, straight,
                    below);

    // The conics of each piece between consecutive lines.
    std::vector<Portion> portions;
    std::vector<const std::vector<Algebraic>*> crossings;  // the roots of each
    std::vector<const std::vector<Algebraic>*> along;      // pencil lines in a conic (cuts)
    // (none above the last line: outside the face; none below the first around no centre)
    for (std::size_t k = pencil.finite() ? 0 : 1; k < straight.size(); ++k) {
      const RationalPoint2 point = pencil.point(middle, below[k]);
      const Probe p(point);
      if (!impl_.face.contains(p) || !shared(p)) continue;
      Portion portion;
      portion.bottom = k == 0 ? -1 : straight[k - 1];
      portion.top = straight[k];
      std::vector<Ends> hiding = ends(p);  // the occluders that hide an interval from there
      hiding.erase(
          std::remove_if(hiding.begin(), hiding.end(),
                         [](const Ends& e) { return e.kind != BlockedInterval::Kind::interval; }),
          hiding.end());
      for (const Ends& j : hiding)
        for (const Ends& i : hiding) {
          if (i.occluder == j.occluder) continue;
          if (j.high_edge < 0 || i.low_edge < 0) continue;
          const GapConic& conic =
              gap_conic(pencil, j.occluder, j.high_edge, i.occluder, i.low_edge);
          if (!conic.rays.empty()) {
            crossings.push_back(&conic.rays);
            along.push_back(&conic.rays);
          }
          if (conic.id >= 0) portion.conics.push_back(conic.id);
        }
      portions.push_back(std::move(portion));
    }
    const Interval range(detail::enclosure(sa).inf(), detail::enclosure(sb).sup());
    // A conic beyond its piece's bounds all over the slab is no curve of it: its crossings
    // would only cut columns where nothing changes.
    {
      CGAL::Protect_FPU_rounding<true> upward;
      for (Portion& portion : portions) {
        const auto bottom =
            portion.bottom < 0 ? std::optional<Interval>(0) : enclosed(portion.bottom).r(range);
        const auto top = enclosed(portion.top).r(range);
        if (!bottom || !top) continue;
        portion.conics.erase(
            std::remove_if(portion.conics.begin(), portion.conics.end(),
                           [&](int id) {
                             const auto r = enclosed(id).r(range);
                             return r && (r->sup() <= bottom->inf() || r->inf() >= top->sup());
                           }),
            portion.conics.end());
      }
    }
    // Where the conics cross each other, their piece's bounds, or leave through r = 0 or
    // infinity.
    const auto cross = [&](int c, int with) {
      if (const auto* roots = crossing_roots(c, with, range)) crossings.push_back(roots);
    };
    for (const Portion& portion : portions)
      for (std::size_t a = 0; a < portion.conics.size(); ++a) {
        const int c = portion.conics[a];
        cross(c, kPole);
        if (pencil.finite()) cross(c, kCentre);
        for (int bound : {portion.bottom, portion.top})
          if (bound >= 0) cross(c, bound);
        for (std::size_t b = a + 1; b < portion.conics.size(); ++b) cross(c, portion.conics[b]);
      }
    const Algebraic &low = sector.seam_values[seam], &high = sector.seam_values[seam + 1];
    std::vector<Algebraic> cuts{low, high};
    for (const std::vector<Algebraic>* roots : crossings)
      for (const Algebraic& root : *roots)
        if (root > low && root < high) cuts.push_back(root);
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());

    // A cell between the same two curves in the next column is the same cell unless the two
    // meet at the cut between the columns: its label is carried over, not made again. So is
    // the last column's of the slab before, across the seam, unless a line of the sweep runs
    // along the seam (run) or a conic of either slab does: then the cells on both sides are
    // not joined (a vertical boundary at the seam).
    const auto on = [](const std::vector<const std::vector<Algebraic>*>& lines,
                       const Algebraic& s) {
      return std::any_of(lines.begin(), lines.end(), [&](const auto* roots) {
        return std::find(roots->begin(), roots->end(), s) != roots->end();
      });
    };
    if (on(along, low)) carried.clear();
    const std::set<int> lines(straight.begin(), straight.end());
    Carried before = std::move(carried);  // the last column's cells by their curves
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      Column column;
      column.low = cuts[k];
      column.high = cuts[k + 1];
      column.sample = (cuts.size() == 2) ? middle : rational_between(cuts[k], cuts[k + 1]);
      const Rational& s = column.sample;
      std::vector<Rational> samples;  // a point r of each cell, from below
      order(pencil, s, straight, portions, column.curves, samples);
      Carried here;
      for (std::size_t c = 0; c < samples.size(); ++c) {
        const bool between = c > 0 && c < column.curves.size();
        const std::pair<int, int> bounds =
            between ? std::pair{column.curves[c - 1], column.curves[c]} : std::pair{0, 0};
        std::optional<Label> label;
        if (between) {
          const auto found = before.find(bounds);
          if (found != before.end() &&
              !(k == 0 ? meet_at(bounds, sa) : meet(bounds, lines, cuts[k], range)))
            label = found->second;
        }
        if (!label) label = maybe_label(pencil, s, samples[c]);
        if (!label) label = label_of(pencil.point(s, samples[c]));
        column.labels.push_back(*label);
        if (between) here.emplace(bounds, *label);
      }
      before = std::move(here);
      impl_.cells += column.labels.size();
      sector.columns.push_back(std::move(column));
    }
    carried.clear();
    if (!on(along, high)) carried = std::move(before);
  }

  // true when the curves (ids) meet at s, or either has a pole there: exactly, unless their
  // enclosures there are apart.
  bool meet_at(const std::pair<int, int>& curves, const Rational& s) {
    {
      CGAL::Protect_FPU_rounding<true> upward;
      const Interval at = detail::enclosure(s);
      const auto a = enclosed(curves.first).r(at), b = enclosed(curves.second).r(at);
      if (a && b && (a->sup() < b->inf() || b->sup() < a->inf())) return false;
    }
    const auto a = r_at(impl_.curves[curves.first], s), b = r_at(impl_.curves[curves.second], s);
    return !a || !b || *a == *b;
  }

  // true when the curves (ids) may meet at the cut: two lines of the slab never do (they
  // cross only at seams); a conic, at the roots of its crossing with the other curve.
  bool meet(const std::pair<int, int>& curves, const std::set<int>& lines, const Algebraic& cut,
            const Interval& range) {
    if (lines.count(curves.first) && lines.count(curves.second)) return false;
    const auto* roots = crossing_roots(curves.first, curves.second, range);
    return roots && std::find(roots->begin(), roots->end(), cut) != roots->end();
  }

  // The lines of the slab that matter at its middle s, by increasing distinct r, and a point
  // r below each and above the one before (below the first: above the centre, if finite).
  void lines_exactly(const Pencil& pencil, const Rational& middle,
                     const std::vector<std::size_t>& active,
                     const std::vector<std::size_t>& line_curves, const std::vector<int>& line_ids,
                     const std::vector<detail::IntervalCurve>& line_enclosures,
                     std::vector<int>& straight, std::vector<Rational>& below) const {
    std::vector<std::pair<Rational, int>> ordered;
    const Interval enclosed_middle = detail::enclosure(middle);
    for (std::size_t k : active) {
      if (surely_irrelevant(pencil, lines_[line_curves[k]], line_enclosures[k], enclosed_middle))
        continue;
      const auto r = r_at(impl_.curves[line_ids[k]], middle);
      if (!r || (pencil.finite() && !CGAL::is_positive(*r))) continue;
      if (!relevant(lines_[line_curves[k]], pencil.point(middle, *r))) continue;
      ordered.emplace_back(*r, line_ids[k]);
    }
    std::sort(ordered.begin(), ordered.end());
    ordered.erase(std::unique(ordered.begin(), ordered.end(),
                              [](const auto& a, const auto& b) { return a.first == b.first; }),
                  ordered.end());
    for (std::size_t k = 0; k < ordered.size(); ++k) {
      straight.push_back(ordered[k].second);
      if (k > 0)
        below.push_back(detail::simplest_between(ordered[k - 1].first, ordered[k].first));
      else
        below.push_back(pencil.finite() ? detail::simplest_between(0, ordered[0].first) : 0);
    }
  }

  // lines_exactly from intervals (upward rounding; whether a line matters exactly where they
  // cannot tell), the points r doubles with few bits: false, with nothing made, when the
  // enclosures of two values overlap, one holds a pole, or one around a finite centre holds 0.
  bool lines_by_intervals(const Pencil& pencil, const Rational& middle,
                          const std::vector<std::size_t>& active,
                          const std::vector<std::size_t>& line_curves,
                          const std::vector<int>& line_ids,
                          const std::vector<detail::IntervalCurve>& line_enclosures,
                          std::vector<int>& straight, std::vector<Rational>& below) const {
    CGAL::Protect_FPU_rounding<true> upward;
    const Interval at_s = detail::enclosure(middle);
    std::vector<std::pair<Interval, int>> ordered;
    for (std::size_t k : active) {
      const SweepLine& line = lines_[line_curves[k]];
      const auto r = line_enclosures[k].r(at_s);
      if (!r) return false;
      if (pencil.finite() && r->sup() <= 0) continue;
      const std::array<Interval, 2> at = detail::interval_point(pencil, at_s, *r);
      if (surely_irrelevant(line, at)) continue;
      if (pencil.finite() && !(r->inf() > 0)) return false;
      if (!surely_relevant(line, at) &&
          !relevant(line, pencil.point(middle, *r_at(impl_.curves[line_ids[k]], middle))))
        continue;
      ordered.emplace_back(*r, line_ids[k]);
    }
    std::sort(ordered.begin(), ordered.end(),
              [](const auto& a, const auto& b) { return a.first.inf() < b.first.inf(); });
    std::vector<double> points;
    for (std::size_t k = 0; k < ordered.size(); ++k) {
      std::optional<double> r = 0;
      if (k > 0)
        r = detail::short_between(ordered[k - 1].first.sup(), ordered[k].first.inf());
      else if (pencil.finite())
        r = detail::short_between(0, ordered[0].first.inf());
      if (!r) return false;  // (overlapping enclosures among them)
      points.push_back(*r);
    }
    for (const auto& entry : ordered) straight.push_back(entry.second);
    for (double r : points) below.emplace_back(r);
    return true;
  }

  // true when the intervals show that the line matters at the point enclosed by at: in the
  // face and in the ring of a role that matters outside W too (or anywhere).
  bool surely_relevant(const SweepLine& line, const std::array<Interval, 2>& at) const {
    if (impl_.face.maybe_contains(at) != true) return false;
    std::optional<std::vector<std::size_t>> around;
    // true when the intervals show the point outside every ring but except's (closed)
    const auto outside = [&](const std::vector<ConvexRing>& rings, std::size_t except) {
      if (!around) around = near(at);
      return std::all_of(around->begin(), around->end(), [&](std::size_t k) {
        return k == except || rings[k].maybe_contains(at) == false;
      });
    };
    return std::any_of(line.roles.begin(), line.roles.end(), [&](const LineRole& role) {
      if (role.kind == LineRole::kFace) return true;
      if (role.kind == LineRole::kJoint || role.ring->maybe_contains(at) != true) return false;
      return outside(umbrae_, prepared_.size()) &&
             (role.kind == LineRole::kUmbra || outside(shadows_, role.owner));
    });
  }

  // The curves of the column at s by increasing distinct r (the slab's lines, and each
  // portion's conics strictly inside it) and a point r of each cell, from below. The values
  // are enclosed in intervals (upward rounding); only the curves whose enclosures overlap
  // another's (or hold a pole) are evaluated in rationals and ordered exactly, and a cell's
  // point is a double with few bits where the enclosures around it are apart, else the
  // simplest rational between the exact values. Of curves with equal values at s the
  // smallest id is kept.
  void order(const Pencil& pencil, const Rational& s, const std::vector<int>& straight,
             const std::vector<Portion>& portions, std::vector<int>& curves,
             std::vector<Rational>& samples) {
    struct Value {
      Interval r;
      std::optional<Rational> exact;
      int id;
    };
    std::vector<Value> at;
    const auto exact = [&](Value& v) -> const Rational& {
      if (!v.exact) v.exact = *r_at(impl_.curves[v.id], s);
      return *v.exact;
    };
    CGAL::Protect_FPU_rounding<true> upward;
    const Interval at_s = detail::enclosure(s);
    const auto value = [&](int id) { return enclosed(id).r(at_s); };
    const auto add = [&](int id, const std::optional<Interval>& r) {
      if (r) return at.push_back({*r, std::nullopt, id});
      if (const auto e = r_at(impl_.curves[id], s)) at.push_back({detail::enclosure(*e), *e, id});
    };
    for (int id : straight) add(id, value(id));
    for (const Portion& portion : portions) {
      const auto bottom = portion.bottom < 0 ? std::optional<Interval>(0) : value(portion.bottom);
      const auto top = value(portion.top);
      for (int id : portion.conics) {
        const auto r = value(id);
        if (r && bottom && top) {
          if (r->inf() > bottom->sup() && r->sup() < top->inf()) {
            add(id, r);
            continue;
          }
          if (r->sup() <= bottom->inf() || r->inf() >= top->sup()) continue;
        }
        // (a conic on a bound there is left out)
        if (strictly_inside(portion, id, s)) add(id, r);
      }
    }
    std::sort(at.begin(), at.end(),
              [](const Value& a, const Value& b) { return a.r.inf() < b.r.inf(); });
    // each run of overlapping enclosures ordered exactly, equal values made one
    std::vector<Value> ordered;
    for (std::size_t first = 0; first < at.size();) {
      std::size_t last = first + 1;
      double reach = at[first].r.sup();
      for (; last < at.size() && !(reach < at[last].r.inf()); ++last)
        reach = std::max(reach, at[last].r.sup());
      if (last - first > 1) {
        for (std::size_t k = first; k < last; ++k) exact(at[k]);
        std::sort(at.begin() + first, at.begin() + last, [](const Value& a, const Value& b) {
          return *a.exact < *b.exact || (*a.exact == *b.exact && a.id < b.id);
        });
      }
      for (std::size_t k = first; k < last; ++k)
        if (k == first || *at[k].exact != *ordered.back().exact)
          ordered.push_back(std::move(at[k]));
      first = last;
    }
    for (const Value& v : ordered) curves.push_back(v.id);
    for (std::size_t cell = 0; cell <= ordered.size(); ++cell) {
      std::optional<double> r;
      if (ordered.empty()) {
        r = 1;
      } else if (cell == 0) {
        const double first = ordered[0].r.inf();
        if (pencil.finite())
          r = detail::short_between(0, first);
        else if (const double below = std::floor(first) - 1; below < first)
          r = below;
        if (!r) {
          const Rational& e = exact(ordered[0]);
          samples.push_back(pencil.finite() ? detail::simplest_between(0, e) : Rational(e - 1));
          continue;
        }
      } else if (cell == ordered.size()) {
        const double last = ordered.back().r.sup();
        if (const double above = std::ceil(last) + 1; above > last) r = above;
        if (!r) {
          samples.push_back(exact(ordered.back()) + 1);
          continue;
        }
      } else {
        Value &low = ordered[cell - 1], &high = ordered[cell];
        if (low.r.sup() < high.r.inf()) r = detail::short_between(low.r.sup(), high.r.inf());
        if (!r) {
          samples.push_back(detail::simplest_between(exact(low), exact(high)));
          continue;
        }
      }
      samples.emplace_back(*r);
    }
  }

  // true when the conic id lies strictly between the portion's bounds at s (exact).
  bool strictly_inside(const Portion& portion, int id, const Rational& s) const {
    const auto r = r_at(impl_.curves[id], s);
    if (!r) return false;
    const Rational bottom =
        portion.bottom < 0 ? Rational(0) : *r_at(impl_.curves[portion.bottom], s);
    return *r > bottom && *r < *r_at(impl_.curves[portion.top], s);
  }

  // the enclosure of curve id, made once per sweep (a reference that growing keeps valid).
  const detail::IntervalCurve& enclosed(int id) {
    if (static_cast<std::size_t>(id) >= enclosed_.size()) enclosed_.resize(impl_.curves.size());
    auto& curve = enclosed_[id];
    if (!curve) curve.emplace(impl_.curves[id].f);
    return *curve;
  }

  SweptPart& impl_;
  const Face& face_;
  RationalPoint3 q1_, q2_;
  std::vector<std::shared_ptr<const UmbraSolid>> prepared_;
  IntervalPoint q1i_ = detail::interval_point(q1_);
  IntervalPoint q2i_ = detail::interval_point(q2_);
  // the enclosures of the face frame's origin, u and v
  std::array<IntervalPoint, 3> frame_{penumbra::interval_point(face_.frame.origin()),
                                      penumbra::interval_point(face_.frame.u()),
                                      penumbra::interval_point(face_.frame.v())};
  std::vector<ConvexRing> shadows_;
  detail::BoxGrid shadow_index_;                // the shadows' boxes (near)
  std::map<std::vector<Rational>, int> known_;  // this sector's curves (register_curve)
  struct KeyHash {
    std::size_t operator()(const std::array<std::size_t, 4>& key) const {
      std::size_t h = 0;
      for (std::size_t k : key) h = h * 1000003u ^ std::hash<std::size_t>()(k);
      return h;
    }
    std::size_t operator()(const std::pair<int, int>& key) const {
      return std::hash<std::uint64_t>()(std::uint64_t(std::uint32_t(key.first)) << 32 |
                                        std::uint32_t(key.second));
    }
  };
  std::unordered_map<std::array<std::size_t, 4>, GapConic, KeyHash> conics_;  // (gap_conic)
  std::deque<std::optional<detail::IntervalCurve>> enclosed_;  // by curve id (enclosed)
  // a crossing polynomial of two curves (crossing_roots), its roots isolated when needed
  struct Crossing {
    std::vector<Interval> enclosure;  // of its coefficients
    std::optional<std::vector<Algebraic>> roots;
  };
  std::unordered_map<std::pair<int, int>, Crossing, KeyHash> crossings_;
  std::vector<ConvexRing> umbrae_;  // empty: no single umbra
  bool lines_collected_ = false;
  std::vector<SweepLine> lines_;
  std::vector<Affine2> rays_;
  // per end of the source, per occluder: its point shadow volume's planes on the face (the
  // points hiding that end are those where every one is <= 0; none: it hides nothing).
  std::array<std::vector<detail::EndShadow>, 2> end_shadows_;
  std::vector<detail::EnclosedPolygon> w_parts_;  // W lies in their union (joint_parts)
  bool covered_whole_ = false;  // every point of the face is umbra (certify_whole_umbra)
  detail::BoxGrid w_index_;     // of their boxes
};

// Appends the points of a curve of the sweep within tolerance (world units) of it: each
// chord's midpoint lies within tolerance of the curve's point at the middle s. Doubles
// throughout, the curve's and the pencil's coefficients converted once.
class Densify {
 public:
  Densify(const Pencil& pencil, const Curve& curve, const FaceFrame& frame, double tolerance)
      : pencil_(pencil),
        curve_(curve.f),
        straight_(curve.q.straight()),
        uu_(CGAL::to_double(frame.squared_u())),
        vv_(CGAL::to_double(frame.squared_v())),
        tolerance_(tolerance) {}

  // appends the points over [s0, s1] (either order; the first point only when points is
  // empty).
  void operator()(double s0, double s1, std::vector<std::array<double, 2>>& points) const {
    const std::array<double, 2> a = at(s0), b = at(s1);
    if (points.empty()) points.push_back(a);
    split(s0, s1, a, b, points, 0);
  }

 private:
  std::array<double, 2> at(double s) const { return pencil_.point(s, curve_.r(s)); }
  // the world length of a frame displacement (the frame's axes are orthogonal).
  double world_length(double du, double dv) const {
    return std::sqrt(du * du * uu_ + dv * dv * vv_);
  }

  // appends the points over (s0, s1], a and b those at s0 and s1, halving s until each
  // chord's midpoint lies within tolerance.
  void split(double s0, double s1, const std::array<double, 2>& a, const std::array<double, 2>& b,
             std::vector<std::array<double, 2>>& points, int depth) const {
    const double s = (s0 + s1) / 2;
    const std::array<double, 2> m = at(s);
    const double deviation = world_length(m[0] - (a[0] + b[0]) / 2, m[1] - (a[1] + b[1]) / 2);
    if (straight_ || deviation <= tolerance_ || depth > 40) {
      if (!straight_ && depth == 0) {
        // a single chord may miss a bulge between the samples: split once at least.
        split(s0, s, a, m, points, depth + 1);
        split(s, s1, m, b, points, depth + 1);
        return;
      }
      points.push_back(b);
      return;
    }
    split(s0, s, a, m, points, depth + 1);
    split(s, s1, m, b, points, depth + 1);
  }

  const Pencil& pencil_;
  DoubleCurve curve_;
  bool straight_;
  double uu_, vv_, tolerance_;
};

UmbraArc arc_of(const Curve& curve) {
  UmbraArc arc;
  const Quadratic2& q = curve.q;
  arc.curve = {exact_number(q.a), exact_number(q.b), exact_number(q.c),
               exact_number(q.d), exact_number(q.e), exact_number(q.f)};
  arc.straight = q.straight();
  arc.joint = curve.joint;
  return arc;
}

// The boundary pieces of one sector: curve pieces inside columns, merged along a curve
// across columns, and pieces of pencil lines at the seams between slabs. Each piece keeps
// its exact ends for chaining.
void trace_boundary(const SweptPart& impl, int sector_index, double tolerance, const Sector* next,
                    char kind, std::vector<BoundaryPiece>& pieces) {
  const Sector& sector = impl.sectors[sector_index];
  const Pencil& pencil = sector.pencil;
  struct Open {
    std::size_t first, last;  // columns
    bool above;
  };
  const auto& columns = sector.columns;
  std::map<int, Open> open;  // curve id -> piece being extended
  auto close = [&](int id) {
    const Open& piece = open.at(id);
    BoundaryPiece result;
    result.arc = arc_of(impl.curves[id]);
    // Larger r lies on the side r_side() of increasing s; keep the umbra on the left.
    const bool forward = piece.above == (pencil.r_side() > 0);
    const Algebraic& low = columns[piece.first].low;
    const Algebraic& high = columns[piece.last].high;
    Densify(pencil, impl.curves[id], impl.frame, tolerance)(
        approximate(forward ? low : high), approximate(forward ? high : low), result.arc.points);
    result.start = {sector_index, forward ? low : high, id, {}, {}};
    result.end = {sector_index, forward ? high : low, id, {}, {}};
    pieces.push_back(std::move(result));
    open.erase(id);
  };
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const Column& column = columns[c];
    std::map<int, bool> here;
    for (std::size_t k = 0; k < column.curves.size(); ++k)
      if ((column.labels[k] == kind) != (column.labels[k + 1] == kind))
        here[column.curves[k]] = column.labels[k + 1] == kind;
    for (auto it = open.begin(); it != open.end();) {
      const auto found = here.find(it->first);
      const bool continues =
          found != here.end() && found->second == it->second.above && it->second.last + 1 == c;
      ++it;
      if (!continues) close(std::prev(it)->first);
    }
    for (const auto& [id, above] : here) {
      auto found = open.find(id);
      if (found != open.end())
        found->second.last = c;
      else
        open[id] = {c, c, above};
    }
  }
  while (!open.empty()) close(open.begin()->first);

  // Pencil lines: at each seam, where the cells on its two sides differ.
  // s_after: the seam's parameter in the sector of after (the next quadrant starts at 0).
  auto seam = [&](const Column* before, const Column* after, const Rational& s,
                  const Rational& s_after) {
    std::vector<Rational> breaks;
    std::vector<std::optional<Rational>> values[2];
    for (int side = 0; side < 2; ++side) {
      const Column* column = side == 0 ? before : after;
      if (!column) continue;
      values[side] = impl.values_at(*column, side == 0 ? s : s_after);
      for (const auto& r : values[side])
        if (r) breaks.push_back(*r);
    }
    if (pencil.finite()) breaks.push_back(0);
    std::sort(breaks.begin(), breaks.end());
    breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
    std::vector<char> labels[2];
    std::optional<Algebraic> s_value;  // s as the pieces' ends name it, made once
    if (before) labels[0] = impl.labels_between(*before, values[0], breaks);
    if (after) labels[1] = impl.labels_between(*after, values[1], breaks);
    for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
      const bool left = before && labels[0][k] == kind;
      const bool right = after && labels[1][k] == kind;
      if (left == right) continue;
      BoundaryPiece piece;
      // the pencil line through pencil.point(s, r): two of its points make the line.
      const RationalPoint2 a = pencil.point(s, breaks[k]), b = pencil.point(s, breaks[k + 1]);
      const Affine2 line = line_through(a, b);
      piece.arc.curve = {Exact(0),
                         Exact(0),
                         Exact(0),
                         exact_number(line.d),
                         exact_number(line.e),
                         exact_number(line.f)};
      // The larger-s side is left of increasing r when r_side() < 0.
      const bool forward = right == (pencil.r_side() < 0);
      const std::array<double, 2> pa = {CGAL::to_double(a.x()), CGAL::to_double(a.y())};
      const std::array<double, 2> pb = {CGAL::to_double(b.x()), CGAL::to_double(b.y())};
      piece.arc.points = forward ? std::vector<std::array<double, 2>>{pa, pb}
                                 : std::vector<std::array<double, 2>>{pb, pa};
      if (!s_value) s_value = algebraic(s);
      const PieceEnd low{sector_index, *s_value, -1, breaks[k], s};
      const PieceEnd high{sector_index, *s_value, -1, breaks[k + 1], s};
      piece.start = forward ? low : high;
      piece.end = forward ? high : low;
      pieces.push_back(std::move(piece));
    }
  };
  const Column* first = columns.empty() ? nullptr : &columns.front();
  const Column* last = columns.empty() ? nullptr : &columns.back();
  if (!next) seam(nullptr, first, pencil.s_low(), pencil.s_low());
  std::size_t c = 0;
  for (std::size_t k = 1; k + 1 < sector.seams.size(); ++k) {
    const Algebraic& at = sector.seam_values[k];
    while (c + 1 < columns.size() && columns[c].high < at) ++c;
    seam(&columns[c], &columns[c + 1], sector.seams[k], sector.seams[k]);
  }
  if (next) {
    const Column* following = next->columns.empty() ? nullptr : &next->columns.front();
    seam(last, following, pencil.s_high(), next->pencil.s_low());
  } else {
    seam(last, nullptr, pencil.s_high(), pencil.s_high());
  }
}

// the exact r of a piece's end, when its s is the rational s: the ray's own r, or the
// curve's value there.
std::optional<Rational> r_of(const SweptPart& impl, const PieceEnd& end, const Rational& s) {
  if (end.curve < 0) return end.r;
  return r_at(impl.curves[end.curve], s);
}

// true when two ends of pieces are the same point, decided exactly: on the same line of the
// pencil (the same sector and s, or the seam between two quadrants) at the same r, or both
// at the centre.
bool same_point(const SweptPart& impl, const PieceEnd& a, const PieceEnd& b) {
  const bool finite = impl.sectors[a.sector].pencil.finite();
  if (finite && a.curve < 0 && b.curve < 0 && CGAL::is_zero(*a.r) && CGAL::is_zero(*b.r))
    return true;                   // the centre
  std::optional<Rational> sa, sb;  // rational s of each end on a shared ray, if any
  if (a.sector == b.sector) {
    if (a.s != b.s) return false;
    if (a.curve >= 0 && b.curve >= 0) {
      if (a.curve == b.curve) return true;
      // r_a(s) = r_b(s) at an algebraic s: the crossing polynomial vanishes there (it is
      // zero for two copies of one curve, a nonzero constant for curves that never meet).
      const PencilCurve& f = impl.curves[a.curve].f;
      const PencilCurve& g = impl.curves[b.curve].f;
      const Poly crossing = f.num * g.den - g.num * f.den;
      if (crossing.zero()) return true;
      if (crossing.degree() == 0) return false;
      return algebraic_kernel().sign_at_1_object()(integer_polynomial(crossing), a.s) == CGAL::ZERO;
    }
    const PieceEnd& ray = a.curve < 0 ? a : b;
    sa = sb = *ray.ray_s;
  } else {
    // quadrants k and k + 1 (mod 4) share the ray s = 1 of k, s = 0 of k + 1
    const auto seam_s = [&](const PieceEnd& x, const PieceEnd& y) -> std::optional<Rational> {
      if ((x.sector + 1) % 4 == y.sector && x.s == algebraic(1)) return Rational(1);
      if ((y.sector + 1) % 4 == x.sector && x.s == algebraic(0)) return Rational(0);
      return std::nullopt;
    };
    sa = seam_s(a, b);
    sb = seam_s(b, a);
    if (!sa || !sb) return false;
  }
  const auto ra = r_of(impl, a, *sa), rb = r_of(impl, b, *sb);
  return ra && rb && *ra == *rb;
}

// chains the pieces into rings (each piece's end to the piece starting there, decided by
// same_point among the starts near it in doubles), outer rings counter-clockwise and holes
// clockwise, each hole in the smallest outer ring around it.
std::pair<std::vector<CurvedPolygon>, std::vector<PolygonPieces>> chain(
    const SweptPart& impl, std::vector<BoundaryPiece> pieces, double scale) {
  std::vector<CurvedRing> rings;
  std::vector<std::vector<RingPiece>> ring_pieces;
  std::vector<bool> used(pieces.size(), false);
  const double near = 1e-6 * scale;
  // the pieces by the abscissa of their start, to find the candidates near a point
  std::vector<std::pair<double, std::size_t>> starts;
  for (std::size_t j = 0; j < pieces.size(); ++j)
    starts.emplace_back(pieces[j].arc.points.front()[0], j);
  std::sort(starts.begin(), starts.end());
  for (std::size_t first = 0; first < pieces.size(); ++first) {
    if (used[first]) continue;
    CurvedRing ring;
    std::vector<RingPiece> traced;
    std::size_t k = first;
    while (true) {
      used[k] = true;
      const UmbraArc& arc = pieces[k].arc;
      traced.push_back({pieces[k].start, arc.curve, arc.joint});
      const std::size_t from = ring.points.empty() ? 0 : ring.points.size() - 1;
      for (std::size_t i = ring.points.empty() ? 0 : 1; i < arc.points.size(); ++i)
        ring.points.push_back(arc.points[i]);
      if (!arc.straight) ring.arcs.push_back({from, ring.points.size() - 1, arc.curve, arc.joint});
      const std::array<double, 2>& tail = arc.points.back();
      std::optional<std::size_t> following;
      for (auto candidate = std::lower_bound(starts.begin(), starts.end(),
                                             std::make_pair(tail[0] - near, std::size_t(0)));
           candidate != starts.end() && candidate->first <= tail[0] + near; ++candidate) {
        const std::size_t j = candidate->second;  // (the first piece in order that fits)
        if ((used[j] && j != first) || (following && *following < j)) continue;
        const std::array<double, 2>& head = pieces[j].arc.points.front();
        if (std::abs(head[0] - tail[0]) > near || std::abs(head[1] - tail[1]) > near) continue;
        if (same_point(impl, pieces[k].end, pieces[j].start)) following = j;
      }
      if (!following) throw std::logic_error("exact_umbra: a boundary does not close");
      if (*following == first) break;
      k = *following;
    }
    ring.points.pop_back();  // the first point again
    rings.push_back(std::move(ring));
    ring_pieces.push_back(std::move(traced));
  }
  const auto signed_area = [](const CurvedRing& ring) {
    double sum = 0;
    for (std::size_t i = 0, n = ring.points.size(); i < n; ++i) {
      const auto& a = ring.points[i];
      const auto& b = ring.points[(i + 1) % n];
      sum += a[0] * b[1] - a[1] * b[0];
    }
    return sum / 2;
  };
  const auto inside = [](const CurvedRing& ring, const std::array<double, 2>& p) {
    bool in = false;
    for (std::size_t i = 0, n = ring.points.size(), j = n - 1; i < n; j = i++) {
      const auto& a = ring.points[i];
      const auto& b = ring.points[j];
      if ((a[1] > p[1]) != (b[1] > p[1]) &&
          p[0] < (b[0] - a[0]) * (p[1] - a[1]) / (b[1] - a[1]) + a[0])
        in = !in;
    }
    return in;
  };
  std::vector<CurvedPolygon> polygons;
  std::vector<PolygonPieces> polygon_pieces;
  std::vector<double> areas;
  std::vector<bool> outer(rings.size());
  for (std::size_t r = 0; r < rings.size(); ++r)
    if ((outer[r] = signed_area(rings[r]) > 0)) {
      areas.push_back(signed_area(rings[r]));
      polygons.push_back({std::move(rings[r]), {}});
      polygon_pieces.push_back({std::move(ring_pieces[r])});
    }
  for (std::size_t r = 0; r < rings.size(); ++r) {
    if (outer[r] || rings[r].points.empty()) continue;
    std::optional<std::size_t> best;
    for (std::size_t k = 0; k < polygons.size(); ++k)
      if (inside(polygons[k].outer, rings[r].points.front()) && (!best || areas[k] < areas[*best]))
        best = k;
    if (!best) continue;
    polygons[*best].holes.push_back(std::move(rings[r]));
    polygon_pieces[*best].push_back(std::move(ring_pieces[r]));
  }
  return {std::move(polygons), std::move(polygon_pieces)};
}

// the umbra's area in one sector: per column, the integral over s of the cells' extent
// (adaptive Gauss-Legendre; scale: the face's area, for the absolute tolerance).
double sector_area(const SweptPart& impl, const Sector& sector, double scale, char kind) {
  const Pencil& pencil = sector.pencil;
  const QuadratureRule rule = gauss_legendre(12);
  double total = 0;
  for (const Column& column : sector.columns) {
    if (std::none_of(column.labels.begin(), column.labels.end(), [&](char l) { return l == kind; }))
      continue;
    // Consecutive cells of the kind make one run between the curves below and above it
    // (-1: r = 0).
    std::vector<std::pair<int, int>> runs;
    for (std::size_t k = 0; k < column.labels.size(); ++k) {
      if (column.labels[k] != kind) continue;
      const int top = column.curves[k];
      if (k > 0 && column.labels[k - 1] == kind)
        runs.back().second = top;
      else
        runs.emplace_back(k == 0 ? -1 : column.curves[k - 1], top);
    }
    // The curves in t = s - c around the column's sample c, expanded exactly: far from s = 0
    // their values in s lose the digits the quadrature needs.
    const Rational& c = column.sample;
    std::vector<std::pair<std::optional<DoubleCurve>, DoubleCurve>> shifted;
    for (const auto& [bottom, top] : runs)
      shifted.emplace_back(
          bottom < 0 ? std::nullopt : std::optional(DoubleCurve::around(impl.curves[bottom].f, c)),
          DoubleCurve::around(impl.curves[top].f, c));
    const auto extent = [&](double t) {
      double sum = 0;
      auto f = [&](double r) { return pencil.finite() ? r * r / 2 : r; };
      for (const auto& [bottom, top] : shifted) sum += f(top.r(t)) - (bottom ? f(bottom->r(t)) : 0);
      return sum;
    };
    const auto integrate = [&](double a, double b) {
      double sum = 0;
      const QuadratureRule on = mapped(rule, a, b);
      for (std::size_t i = 0; i < on.nodes.size(); ++i) sum += on.weights[i] * extent(on.nodes[i]);
      return sum;
    };
    // Adaptive: halve until the two halves agree with the whole.
    std::function<double(double, double, double, int)> adapt = [&](double a, double b, double whole,
                                                                   int depth) {
      const double m = (a + b) / 2, left = integrate(a, m), right = integrate(m, b);
      const double sum = left + right;
      if (depth >= 24 || std::abs(sum - whole) <= 1e-13 * std::abs(sum) + 1e-16 * scale) return sum;
      return adapt(a, m, left, depth + 1) + adapt(m, b, right, depth + 1);
    };
    const double a = approximate(column.low) - CGAL::to_double(c),
                 b = approximate(column.high) - CGAL::to_double(c);
    total += adapt(a, b, integrate(a, b), 0);
  }
  return total * pencil.jacobian();
}

}  // namespace

namespace {

// true when p lies in the closure of the cells of the kind.
bool in_cells(const SweptPart& impl, const RationalPoint2& p, char kind) {
  if (!impl.face.contains(p)) return false;
  if (impl.whole) return kind == kUmbra;
  if (impl.centre && p == *impl.centre) return kind == kUmbra && impl.centre_label;
  for (const Sector& sector : impl.sectors) {
    const auto c = sector.pencil.coordinates(p);
    if (!c || c->first < sector.pencil.s_low() || c->first > sector.pencil.s_high()) continue;
    const Algebraic s = algebraic(c->first);
    for (const Column& column : sector.columns)
      if (column.low <= s && s <= column.high && impl.label_at(column, c->first, c->second, kind))
        return true;
  }
  return false;
}

// The sweep of one touching group of occluders on face (region: its pieces and rings) under
// the visible source ab, set up (its lines, and whether W may have interior) before it runs:
// a face none of whose groups may hide the source together need not be swept (joint_umbra).
class GroupSweep {
 public:
  GroupSweep(const Face& face, const detail::FaceRegion& region, const RationalPoint3& a,
             const RationalPoint3& b, const std::vector<UmbraOccluder>& occluders)
      : face_(face), a_(a), b_(b), impl_(std::make_shared<SweptPart>()) {
    impl_->face = region;
    impl_->frame = face.frame;
    sweep_ = std::make_unique<Sweep>(*impl_, face, a, b, occluders);
  }

  bool may_be_joint() const { return sweep_->may_be_joint(); }

  // sweeps the group: its cells, boundary, areas and polygons.
  std::shared_ptr<const SweptPart> run(double tolerance) {
    const Face& face = face_;
    const RationalPoint3 &a = a_, &b = b_;
    const auto& impl = impl_;
    const RationalPlane3 plane = exact_value(face.plane);
    const Rational f1 = plane_value(plane, a), f2 = plane_value(plane, b);
    const RationalVector2 axes[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    if (f1 != f2) {
      // The source's line meets the face's plane at x0: four quadrants of directions.
      impl->centre = face.frame.to_frame(a + (f1 / (f1 - f2)) * (b - a));
      for (int k = 0; k < 4; ++k)
        impl->sectors.push_back(
            {Pencil::cone(*impl->centre, axes[k], axes[(k + 1) % 4]), {}, {}, {}});
    } else {
      // Parallel to the face: lines along the source's direction, across the face.
      const RationalVector3 d = b - a;
      const RationalVector3 u = exact_value(face.frame.u()), v = exact_value(face.frame.v());
      const RationalVector2 delta((d * u) / (u * u), (d * v) / (v * v));
      const Pencil probe = Pencil::parallel(delta, 0, 0);
      std::optional<Rational> low, high;
      for (const RationalPoint2& p : impl->face.points()) {
        const Rational s = probe.coordinates(p)->first;
        if (!low || s < *low) low = s;
        if (!high || s > *high) high = s;
      }
      impl->sectors.push_back({Pencil::parallel(delta, *low, *high), {}, {}, {}});
    }
    // A quadrant beyond the face's extent along either of its axes holds none of the face:
    // it is not swept (no columns: no cell and no boundary there).
    std::vector<bool> meets(impl->sectors.size(), true);
    if (impl->centre) {
      std::array<std::optional<Rational>, 4> extent;  // the largest (p - x0) . axis
      for (const RationalPoint2& p : impl->face.points())
        for (int k = 0; k < 4; ++k) {
          const Rational along = (p - *impl->centre) * axes[k];
          if (!extent[k] || along > *extent[k]) extent[k] = along;
        }
      for (int k = 0; k < 4; ++k)
        meets[k] = extent[k] && !CGAL::is_negative(*extent[k]) && extent[(k + 1) % 4] &&
                   !CGAL::is_negative(*extent[(k + 1) % 4]);
    }
    for (std::size_t k = 0; k < impl->sectors.size(); ++k)
      if (meets[k]) sweep_->run(impl->sectors[k]);
    if (impl->centre && impl->face.contains(*impl->centre)) {
      for (const Sector& sector : impl->sectors)
        for (const Column& column : sector.columns)
          impl->centre_label |= column.labels.front() == kUmbra;
    }
    const std::size_t n = impl->sectors.size();
    std::vector<BoundaryPiece> umbra_pieces, penumbra_pieces;
    for (std::size_t k = 0; k < n; ++k) {
      const Sector* next = n == 4 ? &impl->sectors[(k + 1) % n] : nullptr;
      const double scale = CGAL::to_double(face.area);
      trace_boundary(*impl, static_cast<int>(k), tolerance, next, kUmbra, umbra_pieces);
      trace_boundary(*impl, static_cast<int>(k), tolerance, next, kPenumbra, penumbra_pieces);
      impl->area += sector_area(*impl, impl->sectors[k], scale, kUmbra);
      impl->penumbra_area += sector_area(*impl, impl->sectors[k], scale, kPenumbra);
    }
    for (const BoundaryPiece& piece : umbra_pieces) impl->boundary.push_back(piece.arc);
    for (const BoundaryPiece& piece : penumbra_pieces) impl->penumbra_boundary.push_back(piece.arc);
    double size = 0;  // the face's extent in frame units, for the chaining's candidates
    for (const RationalPoint2& p : impl->face.points())
      size = std::max({size, std::abs(CGAL::to_double(p.x())), std::abs(CGAL::to_double(p.y()))});
    std::tie(impl->umbra_polygons, impl->umbra_pieces) =
        chain(*impl, std::move(umbra_pieces), size);
    std::tie(impl->penumbra_polygons, impl->penumbra_pieces) =
        chain(*impl, std::move(penumbra_pieces), size);
    return impl;
  }

 private:
  const Face& face_;
  RationalPoint3 a_, b_;
  std::shared_ptr<SweptPart> impl_;
  std::unique_ptr<Sweep> sweep_;
};

}  // namespace

// The sets of a face: the parts of its touching groups of occluders, whose shadows are
// strictly apart, so the sets are the disjoint unions of the parts' sets.
struct ExactUmbra::Impl {
  std::vector<std::shared_ptr<const SweptPart>> parts;
  double area = 0, penumbra_area = 0;
  std::vector<UmbraArc> boundary, penumbra_boundary;
  std::vector<CurvedPolygon> umbra_polygons, penumbra_polygons;
  bool joint = false;
  std::size_t cells = 0;

  explicit Impl(std::vector<std::shared_ptr<const SweptPart>> swept) : parts(std::move(swept)) {
    const auto append = [](auto& to, const auto& from) {
      to.insert(to.end(), from.begin(), from.end());
    };
    for (const auto& part : parts) {
      area += part->area;
      penumbra_area += part->penumbra_area;
      append(boundary, part->boundary);
      append(penumbra_boundary, part->penumbra_boundary);
      append(umbra_polygons, part->umbra_polygons);
      append(penumbra_polygons, part->penumbra_polygons);
      joint = joint || part->joint;
      cells += part->cells;
    }
  }

  bool in_cells(const Point2& point, char kind) const {
    const RationalPoint2 p = rational_point(point);
    return std::any_of(parts.begin(), parts.end(),
                       [&](const auto& part) { return penumbra::in_cells(*part, p, kind); });
  }

  std::vector<ExactCurvedPolygon> exact_polygons(
      std::vector<PolygonPieces> SweptPart::*pieces) const {
    std::vector<ExactCurvedPolygon> result;
    for (const auto& part : parts) {
      std::vector<ExactCurvedPolygon> polygons = part->exact_polygons((*part).*pieces);
      std::move(polygons.begin(), polygons.end(), std::back_inserter(result));
    }
    detail::canonical_order(result);
    return result;
  }
};

bool ExactUmbra::contains(const Point2& point) const {
  return impl_->in_cells(point, kUmbra);
}

bool ExactUmbra::in_penumbra(const Point2& point) const {
  return impl_->in_cells(point, kPenumbra);
}

double ExactUmbra::area() const {
  return impl_->area;
}

const std::vector<UmbraArc>& ExactUmbra::boundary() const {
  return impl_->boundary;
}

const std::vector<CurvedPolygon>& ExactUmbra::umbra_polygons() const {
  return impl_->umbra_polygons;
}

const std::vector<CurvedPolygon>& ExactUmbra::penumbra_polygons() const {
  return impl_->penumbra_polygons;
}

std::vector<ExactCurvedPolygon> ExactUmbra::exact_umbra_polygons() const {
  return impl_->exact_polygons(&SweptPart::umbra_pieces);
}

std::vector<ExactCurvedPolygon> ExactUmbra::exact_penumbra_polygons() const {
  return impl_->exact_polygons(&SweptPart::penumbra_pieces);
}

double ExactUmbra::penumbra_area() const {
  return impl_->penumbra_area;
}

const std::vector<UmbraArc>& ExactUmbra::penumbra_boundary() const {
  return impl_->penumbra_boundary;
}

bool ExactUmbra::joint() const {
  return impl_->joint;
}

std::size_t ExactUmbra::cells() const {
  return impl_->cells;
}

ExactUmbra exact_umbra(const Face& face, const Point3& q1, const Point3& q2,
                       const std::vector<UmbraOccluder>& occluders, double tolerance) {
  return exact_umbra(face, {face.ring}, {face.ring}, q1, q2, occluders, tolerance);
}

namespace {

// exact_umbra, or when only_joint, nullopt where no group of occluders may hide the source
// together (no sweep is run then).
std::optional<ExactUmbra> umbra_of(const Face& face, const std::vector<Ring2>& pieces,
                                   const std::vector<Ring2>& boundary, const Point3& q1,
                                   const Point3& q2, const std::vector<UmbraOccluder>& occluders,
                                   double tolerance, bool only_joint) {
  const auto rational_ring = [](const Ring2& ring) {
    std::vector<RationalPoint2> points;
    for (const Point2& p : ring) points.push_back(rational_point(p));
    return points;
  };
  std::vector<ConvexRing> convex;
  for (const Ring2& piece : pieces) convex.emplace_back(rational_ring(piece));
  std::vector<std::vector<RationalPoint2>> rings;
  for (const Ring2& ring : boundary) rings.push_back(rational_ring(ring));
  const detail::FaceRegion region(std::move(convex), std::move(rings));
  const auto source = visible_source(face, q1, q2);
  if (!source) {
    if (only_joint) return std::nullopt;  // the whole face, no joint part
    auto whole = std::make_shared<SweptPart>();
    whole->whole = true;
    whole->face = region;
    whole->frame = face.frame;
    whole->area = CGAL::to_double(face.area);
    return ExactUmbra(std::make_shared<const ExactUmbra::Impl>(
        std::vector<std::shared_ptr<const SweptPart>>{std::move(whole)}));
  }
  const RationalPoint3 a = exact_value(source->q1), b = exact_value(source->q2);
  // Occluders whose whole shadows are strictly apart never hide the source together: each
  // touching group is swept on its own (in parallel), and none sweeps the others' lines.
  std::vector<Ring2> shadows;
  for (const UmbraOccluder& occluder : occluders) shadows.push_back(occluder.shadow);
  auto groups = detail::touching_groups(shadows);
  if (groups.empty()) groups.emplace_back();  // no occluder: the face alone
  std::vector<std::unique_ptr<GroupSweep>> sweeps(groups.size());
  for_each_index(groups.size(), true, [&](std::size_t g) {
    std::vector<UmbraOccluder> group;
    for (std::size_t k : groups[g]) group.push_back(occluders[k]);
    sweeps[g] = std::make_unique<GroupSweep>(face, region, a, b, group);
  });
  if (only_joint && std::none_of(sweeps.begin(), sweeps.end(),
                                 [](const auto& sweep) { return sweep->may_be_joint(); }))
    return std::nullopt;
  std::vector<std::shared_ptr<const SweptPart>> parts(groups.size());
  for_each_index(groups.size(), true, [&](std::size_t g) { parts[g] = sweeps[g]->run(tolerance); });
  return ExactUmbra(std::make_shared<const ExactUmbra::Impl>(std::move(parts)));
}

}  // namespace

ExactUmbra exact_umbra(const Face& face, const std::vector<Ring2>& pieces,
                       const std::vector<Ring2>& boundary, const Point3& q1, const Point3& q2,
                       const std::vector<UmbraOccluder>& occluders, double tolerance) {
  return *umbra_of(face, pieces, boundary, q1, q2, occluders, tolerance, false);
}

std::optional<ExactUmbra> joint_umbra(const Face& face, const Point3& q1, const Point3& q2,
                                      const std::vector<UmbraOccluder>& occluders,
                                      double tolerance) {
  return umbra_of(face, {face.ring}, {face.ring}, q1, q2, occluders, tolerance, true);
}

}  // namespace penumbra
