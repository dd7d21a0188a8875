#include "segment_arrangement.h"

#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <unordered_map>

#include <tbb/parallel_sort.h>

#include "disjoint_sets.h"
#include "penumbra/base/parallel.h"
#include "penumbra/geometry/exact.h"

namespace penumbra::detail {
namespace {

// ---- exact values by hash --------------------------------------------------------------

std::size_t mix(std::size_t h, std::size_t x) {
  return (h ^ x) * 0x100000001B3ull + 0x9E3779B97F4A7C15ull;
}

std::size_t hash_of(const mpz_class& z, std::size_t h) {
  const mpz_srcptr p = z.get_mpz_t();
  h = mix(h, static_cast<std::size_t>(mpz_sgn(p) + 1));
  for (std::size_t i = 0, n = mpz_size(p); i < n; ++i) h = mix(h, mpz_getlimbn(p, i));
  return h;
}

std::size_t hash_of(const RationalPoint2& p) {
  std::size_t h = 1469598103934665603ull;
  h = hash_of(p.x().get_num(), h);
  h = hash_of(p.x().get_den(), h);
  h = hash_of(p.y().get_num(), h);
  return hash_of(p.y().get_den(), h);
}

// returns for each of the points at(0), ..., at(count - 1) the index of the first point
// equal to it (exactly).
template <typename At>
std::vector<std::size_t> first_equal(std::size_t count, const At& at) {
  std::vector<std::size_t> hashes(count);
  for_each_index(
      count, count > 4096, [&](std::size_t k) { hashes[k] = hash_of(at(k)); }, 256);
  std::vector<std::size_t> order(count);
  std::iota(order.begin(), order.end(), 0);
  tbb::parallel_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return hashes[a] != hashes[b] ? hashes[a] < hashes[b] : a < b;
  });
  std::vector<std::size_t> first(count);
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j < order.size() && hashes[order[j]] == hashes[order[i]]) ++j;
    for (std::size_t k = i; k < j; ++k) {
      first[order[k]] = order[k];
      for (std::size_t m = i; m < k; ++m)
        if (first[order[m]] == order[m] && at(order[m]) == at(order[k])) {
          first[order[k]] = order[m];
          break;
        }
    }
    i = j;
  }
  return first;
}

// ---- lines --------------------------------------------------------------------------------

// a x + b y + c = 0 in integers, divided by their gcd, (a, b) > 0 lexicographically: one
// line, one triple.
struct Line {
  mpz_class a, b, c;
  bool operator==(const Line& o) const { return a == o.a && b == o.b && c == o.c; }
};

Line line_through(const RationalPoint2& p, const RationalPoint2& q) {
  const Rational a = p.y() - q.y(), b = q.x() - p.x(), c = p.x() * q.y() - p.y() * q.x();
  mpz_class l;
  mpz_lcm(l.get_mpz_t(), a.get_den_mpz_t(), b.get_den_mpz_t());
  mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), c.get_den_mpz_t());
  Line line{a.get_num() * (l / a.get_den()), b.get_num() * (l / b.get_den()),
            c.get_num() * (l / c.get_den())};
  mpz_class g;
  mpz_gcd(g.get_mpz_t(), line.a.get_mpz_t(), line.b.get_mpz_t());
  mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), line.c.get_mpz_t());
  if (g > 1) {
    mpz_divexact(line.a.get_mpz_t(), line.a.get_mpz_t(), g.get_mpz_t());
    mpz_divexact(line.b.get_mpz_t(), line.b.get_mpz_t(), g.get_mpz_t());
    mpz_divexact(line.c.get_mpz_t(), line.c.get_mpz_t(), g.get_mpz_t());
  }
  if (sgn(line.a) < 0 || (sgn(line.a) == 0 && sgn(line.b) < 0)) {
    line.a = -line.a;
    line.b = -line.b;
    line.c = -line.c;
  }
  return line;
}

std::size_t hash_of(const Line& line) {
  return hash_of(line.c, hash_of(line.b, hash_of(line.a, 7)));
}

using Interval = CGAL::Interval_nt<false>;
struct IntervalPoint {
  Interval x, y;
};
struct IntervalLine {
  Interval a, b, c;
};

IntervalPoint interval_of(const RationalPoint2& p) {
  return {Interval(CGAL::to_interval(p.x())), Interval(CGAL::to_interval(p.y()))};
}
IntervalLine interval_of(const Line& l) {
  return {Interval(CGAL::to_interval(l.a)), Interval(CGAL::to_interval(l.b)),
          Interval(CGAL::to_interval(l.c))};
}

// returns the sign of a x + b y + c at p.
int side(const Line& line, const RationalPoint2& p);

// the same, decided in intervals where they can.
int side(const Line& line, const IntervalLine& li, const RationalPoint2& p,
         const IntervalPoint& pi) {
  {
    CGAL::Protect_FPU_rounding<true> upward;
    const CGAL::Uncertain<CGAL::Sign> sign = CGAL::sign(li.a * pi.x + li.b * pi.y + li.c);
    if (CGAL::is_certain(sign)) return static_cast<int>(sign.make_certain());
  }
  return side(line, p);
}

int side(const Line& line, const RationalPoint2& p) {
  // x = xn / xd, y = yn / yd, xd, yd > 0: the sign of a xn yd + b yn xd + c xd yd.
  const mpz_class& xn = p.x().get_num();
  const mpz_class& xd = p.x().get_den();
  const mpz_class& yn = p.y().get_num();
  const mpz_class& yd = p.y().get_den();
  const mpz_class value = line.a * xn * yd + line.b * yn * xd + line.c * xd * yd;
  return sgn(value);
}

// returns -1, 0, 1 as p <, ==, > q lexicographically.
int compare_xy(const RationalPoint2& p, const RationalPoint2& q);

// the same, decided in intervals where they can.
int compare_xy(const RationalPoint2& p, const IntervalPoint& pi, const RationalPoint2& q,
               const IntervalPoint& qi) {
  if (pi.x.sup() < qi.x.inf()) return -1;
  if (pi.x.inf() > qi.x.sup()) return 1;
  if (pi.x.is_point() && qi.x.is_point() && pi.x.inf() == qi.x.inf()) {
    if (pi.y.sup() < qi.y.inf()) return -1;
    if (pi.y.inf() > qi.y.sup()) return 1;
  }
  return compare_xy(p, q);
}

int compare_xy(const RationalPoint2& p, const RationalPoint2& q) {
  if (const int x = cmp(p.x(), q.x())) return x < 0 ? -1 : 1;
  const int y = cmp(p.y(), q.y());
  return y < 0 ? -1 : (y > 0 ? 1 : 0);
}

// The direction of a halfedge: sign * (b, -a) of its line.
struct Direction {
  const Line* line;
  int sign;
  int dx() const { return sign * sgn(line->b); }
  int dy() const { return -sign * sgn(line->a); }
};

// returns the sign of the cross product u x v.
int cross_sign(const Direction& u, const Direction& v) {
  // (s b1, -s a1) x (t b2, -t a2) = s t (a1 b2 - a2 b1)
  const mpz_class value = u.line->a * v.line->b - v.line->a * u.line->b;
  return u.sign * v.sign * sgn(value);
}

// returns true when u comes before v counter-clockwise from the direction (1, 0) included.
bool before(const Direction& u, const Direction& v) {
  const auto half = [](const Direction& d) {
    return (d.dy() > 0 || (d.dy() == 0 && d.dx() > 0)) ? 0 : 1;
  };
  if (half(u) != half(v)) return half(u) < half(v);
  return cross_sign(u, v) > 0;
}

// Items grouped by a key, each group's items in increasing order, in one array (a vector of
// vectors would allocate for each of millions of vertices and faces).
struct Groups {
  std::vector<std::size_t> start, items;  // group k: items[start[k]] to items[start[k + 1]]
  std::size_t* begin(std::size_t k) { return items.data() + start[k]; }
  std::size_t* end(std::size_t k) { return items.data() + start[k + 1]; }
  std::size_t size(std::size_t k) const { return start[k + 1] - start[k]; }
};

// returns the items 0 to count - 1 grouped by key(item), a key below keys.
template <typename Key>
Groups group_by(std::size_t count, std::size_t keys, const Key& key) {
  Groups groups;
  groups.start.assign(keys + 1, 0);
  for (std::size_t i = 0; i < count; ++i) ++groups.start[key(i) + 1];
  for (std::size_t k = 0; k < keys; ++k) groups.start[k + 1] += groups.start[k];
  groups.items.resize(count);
  std::vector<std::size_t> at(groups.start.begin(), groups.start.end() - 1);
  for (std::size_t i = 0; i < count; ++i) groups.items[at[key(i)]++] = i;
  return groups;
}

}  // namespace

SegmentArrangement arrange(const std::vector<LayerSegment>& input) {
  SegmentArrangement result;
  const std::size_t n = input.size();

  // Corners numbered by their exact values; each segment from its smaller corner to its larger.
  std::vector<RationalPoint2> raw;
  raw.reserve(2 * n);
  for (const LayerSegment& s : input) {
    raw.push_back(exact_value(s.a));
    raw.push_back(exact_value(s.b));
  }
  std::vector<std::size_t> first =
      first_equal(raw.size(), [&](std::size_t k) -> const RationalPoint2& { return raw[k]; });
  std::vector<std::size_t> vertex_of(raw.size());
  std::vector<RationalPoint2>& points = result.points;
  points.reserve(raw.size());
  for (std::size_t k = 0; k < raw.size(); ++k) {
    if (first[k] == k) {
      vertex_of[k] = points.size();
      points.push_back(raw[k]);
    } else {
      vertex_of[k] = vertex_of[first[k]];
    }
  }
  struct Seg {
    std::size_t a, b;  // vertices, a < b lexicographically
    long left;         // added on the left of a -> b
    std::size_t line;
  };
  std::vector<Seg> segs(n);
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t a = vertex_of[2 * k], b = vertex_of[2 * k + 1];
    long left = input[k].left;
    if (compare_xy(points[a], points[b]) > 0) {
      std::swap(a, b);
      left = -left;
    }
    segs[k] = {a, b, left, 0};
  }
  // Lines numbered by their exact triples.
  std::vector<Line> lines;
  {
    std::vector<Line> of(n);
    for_each_index(
        n, n > 1024,
        [&](std::size_t k) { of[k] = line_through(points[segs[k].a], points[segs[k].b]); }, 64);
    std::unordered_multimap<std::size_t, std::size_t> by_hash;
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t h = hash_of(of[k]);
      std::optional<std::size_t> found;
      for (auto [it, end] = by_hash.equal_range(h); it != end; ++it)
        if (lines[it->second] == of[k]) found = it->second;
      if (!found) {
        found = lines.size();
        lines.push_back(of[k]);
        by_hash.emplace(h, *found);
      }
      segs[k].line = *found;
    }
  }

  // Intervals of the corners and of the lines, for the filters.
  std::vector<IntervalPoint> approx(points.size());
  for_each_index(
      points.size(), points.size() > 4096,
      [&](std::size_t v) { approx[v] = interval_of(points[v]); }, 256);
  std::vector<IntervalLine> line_approx(lines.size());
  for (std::size_t l = 0; l < lines.size(); ++l) line_approx[l] = interval_of(lines[l]);
  const auto less = [&](std::size_t u, std::size_t v) {
    return compare_xy(points[u], approx[u], points[v], approx[v]) < 0;
  };

  // Pairs of segments whose boxes meet, each classified exactly.
  using Box = CGAL::Box_intersection_d::Box_with_handle_d<double, 2, std::size_t,
                                                          CGAL::Box_intersection_d::ID_EXPLICIT>;
  std::vector<Box> boxes;
  for (std::size_t k = 0; k < n; ++k) boxes.emplace_back(input[k].a.bbox() + input[k].b.bbox(), k);
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& p, const Box& q) {
    pairs.emplace_back(p.handle(), q.handle());
  });
  // What the pairs give: corners of one segment inside the other (by vertex), and crossings
  // (new points, with their pairs). The pairs run in chunks across threads, each chunk's
  // findings in pair order, so that the numbering below does not depend on the threads.
  struct Split {
    std::size_t segment;
    std::size_t vertex;
  };
  struct Crossing {
    std::size_t pair;
    RationalPoint2 point;
  };
  struct Findings {
    std::vector<Split> splits;
    std::vector<Crossing> crossings;
  };
  constexpr std::size_t kPairsPerChunk = 4096;
  std::vector<Findings> found((pairs.size() + kPairsPerChunk - 1) / kPairsPerChunk);
  const auto inside = [&](std::size_t v, const Seg& s) {  // v on s's line: strictly inside s?
    return v != s.a && v != s.b && less(s.a, v) && less(v, s.b);
  };
  const auto classify = [&](std::size_t k, Findings& out) {
    const std::size_t i = pairs[k].first, j = pairs[k].second;
    const Seg &s = segs[i], &t = segs[j];
    if (s.line == t.line) {  // collinear: the corners of each strictly inside the other
      for (std::size_t v : {t.a, t.b})
        if (inside(v, s)) out.splits.push_back({i, v});
      for (std::size_t v : {s.a, s.b})
        if (inside(v, t)) out.splits.push_back({j, v});
      return;
    }
    const auto on = [&](std::size_t v, const Seg& r) {
      return (v == r.a || v == r.b)
                 ? 0
                 : side(lines[r.line], line_approx[r.line], points[v], approx[v]);
    };
    const int o1 = on(t.a, s), o2 = on(t.b, s);
    if (o1 == o2 && o1 != 0) return;
    const int o3 = on(s.a, t), o4 = on(s.b, t);
    if (o3 == o4 && o3 != 0) return;
    if (o1 != 0 && o2 != 0 && o3 != 0 && o4 != 0) {
      // A proper crossing: Cramer's rule on the two integer lines.
      const Line &l = lines[s.line], &m = lines[t.line];
      const mpz_class d = l.a * m.b - m.a * l.b;
      Rational x(l.b * m.c - m.b * l.c, d), y(m.a * l.c - l.a * m.c, d);
      x.canonicalize();
      y.canonicalize();
      out.crossings.push_back({k, RationalPoint2(x, y)});
      return;
    }
    // Lines apart: the one common point of the lines, if it is a corner of one lying
    // inside the other.
    if (o1 == 0 && inside(t.a, s)) out.splits.push_back({i, t.a});
    if (o2 == 0 && inside(t.b, s)) out.splits.push_back({i, t.b});
    if (o3 == 0 && inside(s.a, t)) out.splits.push_back({j, s.a});
    if (o4 == 0 && inside(s.b, t)) out.splits.push_back({j, s.b});
  };
  for_each_index(
      found.size(), found.size() > 1,
      [&](std::size_t c) {
        const std::size_t end = std::min(pairs.size(), (c + 1) * kPairsPerChunk);
        for (std::size_t k = c * kPairsPerChunk; k < end; ++k) classify(k, found[c]);
      },
      1);

  // Crossings numbered with the corners by their exact values (corners are distinct
  // already); the points vector grows once, since moving a rational may copy it.
  const std::size_t corners = points.size();
  std::vector<Crossing*> crossings;
  for (Findings& f : found)
    for (Crossing& crossing : f.crossings) crossings.push_back(&crossing);
  const std::vector<std::size_t> same =
      first_equal(corners + crossings.size(), [&](std::size_t k) -> const RationalPoint2& {
        return k < corners ? points[k] : crossings[k - corners]->point;
      });
  std::vector<std::size_t> crossing_vertex(crossings.size());
  std::size_t distinct = 0;
  for (std::size_t k = 0; k < crossings.size(); ++k) distinct += same[corners + k] == corners + k;
  points.reserve(corners + distinct);
  for (std::size_t k = 0; k < crossings.size(); ++k) {
    const std::size_t earliest = same[corners + k];
    if (earliest < corners) {
      crossing_vertex[k] = earliest;
    } else if (earliest == corners + k) {
      crossing_vertex[k] = points.size();
      points.push_back(std::move(crossings[k]->point));
    } else {
      crossing_vertex[k] = crossing_vertex[earliest - corners];
    }
  }

  approx.resize(points.size());
  for_each_index(
      points.size() - corners, points.size() - corners > 4096,
      [&](std::size_t k) { approx[corners + k] = interval_of(points[corners + k]); }, 256);
  // Each segment's vertices in order, consecutive ones the edges.
  std::vector<std::vector<std::size_t>> on_segment(n);
  for (std::size_t k = 0; k < n; ++k) on_segment[k] = {segs[k].a, segs[k].b};
  for (const Findings& f : found)
    for (const Split& split : f.splits) on_segment[split.segment].push_back(split.vertex);
  for (std::size_t k = 0; k < crossings.size(); ++k) {
    const std::pair<std::size_t, std::size_t>& pair = pairs[crossings[k]->pair];
    on_segment[pair.first].push_back(crossing_vertex[k]);
    on_segment[pair.second].push_back(crossing_vertex[k]);
  }
  found.clear();
  found.shrink_to_fit();
  for_each_index(
      n, n > 1024,
      [&](std::size_t k) {
        std::vector<std::size_t>& list = on_segment[k];
        std::sort(list.begin(), list.end(),
                  [&](std::size_t u, std::size_t v) { return u != v && less(u, v); });
        list.erase(std::unique(list.begin(), list.end()), list.end());
      },
      64);
  // Every piece (u, v, segment) sorted by (u, v) across threads: equal pieces are one edge.
  // A piece's key holds both vertices in 32 bits each.
  if (points.size() > 0xFFFFFFFFu) throw std::length_error("an overlay of more than 2^32 vertices");
  std::vector<std::size_t> start(n + 1, 0);
  for (std::size_t k = 0; k < n; ++k) start[k + 1] = start[k] + on_segment[k].size() - 1;
  struct Piece {
    std::uint64_t key;
    std::size_t segment;
  };
  std::vector<Piece> pieces(start[n]);
  for_each_index(
      n, n > 1024,
      [&](std::size_t k) {
        const std::vector<std::size_t>& list = on_segment[k];
        for (std::size_t i = 0; i + 1 < list.size(); ++i)
          pieces[start[k] + i] = {(static_cast<std::uint64_t>(list[i]) << 32) | list[i + 1], k};
      },
      64);
  tbb::parallel_sort(pieces.begin(), pieces.end(), [](const Piece& a, const Piece& b) {
    return a.key != b.key ? a.key < b.key : a.segment < b.segment;
  });
  std::vector<std::size_t> edge_line;
  std::vector<std::size_t>& origin = result.origin;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    if (i == 0 || pieces[i].key != pieces[i - 1].key) {
      edge_line.push_back(segs[pieces[i].segment].line);
      result.left.push_back(0);
      origin.push_back(static_cast<std::size_t>(pieces[i].key >> 32));
      origin.push_back(static_cast<std::size_t>(pieces[i].key & 0xFFFFFFFFu));
    }
    result.left.back() += segs[pieces[i].segment].left;
  }
  const std::size_t edges = edge_line.size();

  // Around each vertex, its outgoing halfedges counter-clockwise; next[h] for the halfedge
  // h entering a vertex is the outgoing one clockwise after its twin.
  const auto direction = [&](std::size_t h) {
    const Line& line = lines[edge_line[h / 2]];
    // 2e goes from the smaller vertex to the larger: rightward (dx > 0, or dx = 0 and dy > 0).
    const int dx = sgn(line.b), dy = -sgn(line.a);
    const int rightward = (dx > 0 || (dx == 0 && dy > 0)) ? 1 : -1;
    return Direction{&line, (h % 2 == 0) ? rightward : -rightward};
  };
  Groups around = group_by(2 * edges, points.size(), [&](std::size_t h) { return origin[h]; });
  result.next.assign(2 * edges, 0);
  for_each_index(
      points.size(), points.size() > 1024,
      [&](std::size_t v) {
        std::size_t* list = around.begin(v);
        std::sort(list, around.end(v), [&](std::size_t g, std::size_t h) {
          return g != h && before(direction(g), direction(h));
        });
        const std::size_t m = around.size(v);
        for (std::size_t i = 0; i < m; ++i) result.next[list[i] ^ 1] = list[(i + m - 1) % m];
      },
      64);

  // Cycles of next; components of the edges; each component's outer cycle leaves its
  // lexicographically smallest vertex along its most counter-clockwise edge.
  std::vector<std::size_t> cycle(2 * edges, SIZE_MAX);
  std::size_t cycles = 0;
  for (std::size_t h = 0; h < 2 * edges; ++h) {
    if (cycle[h] != SIZE_MAX) continue;
    for (std::size_t at = h; cycle[at] == SIZE_MAX; at = result.next[at]) cycle[at] = cycles;
    ++cycles;
  }
  DisjointSets component(points.size());
  for (std::size_t e = 0; e < edges; ++e) component.join(origin[2 * e], origin[2 * e + 1]);
  std::map<std::size_t, std::size_t> lowest;  // component root -> its smallest vertex
  for (std::size_t v = 0; v < points.size(); ++v) {
    if (around.size(v) == 0) continue;
    auto [it, added] = lowest.emplace(component.root(v), v);
    if (!added && less(v, it->second)) it->second = v;
  }

  // Faces: the cycles, each component's outer cycle joined to the face that holds it (found
  // by a ray from its smallest vertex to the left), and the unbounded face (index cycles).
  DisjointSets faces(cycles + 1);
  // Edges by horizontal bands of their vertical extents (intervals rounded outward), for the
  // rays; only needed when there are components to locate beside the first.
  double y_low = 0, y_high = 0;
  std::size_t bands = 1;
  std::vector<std::vector<std::size_t>> in_band(1);
  if (lowest.size() > 1 && edges > 0) {
    y_low = approx[0].y.inf();
    y_high = approx[0].y.sup();
    for (const IntervalPoint& p : approx) {
      y_low = std::min(y_low, p.y.inf());
      y_high = std::max(y_high, p.y.sup());
    }
    bands = std::max<std::size_t>(1, std::min<std::size_t>(1 << 12, edges / 16));
    in_band.assign(bands, {});
  }
  const auto band = [&](double y) {
    if (!(y_high > y_low)) return std::size_t(0);
    const double t = (y - y_low) / (y_high - y_low) * static_cast<double>(bands);
    return std::min(bands - 1, static_cast<std::size_t>(std::max(0.0, t)));
  };
  if (lowest.size() > 1)
    for (std::size_t e = 0; e < edges; ++e) {
      const IntervalPoint &a = approx[origin[2 * e]], &b = approx[origin[2 * e + 1]];
      const std::size_t bottom = band(std::min(a.y.inf(), b.y.inf()));
      const std::size_t top = band(std::max(a.y.sup(), b.y.sup()));
      for (std::size_t k = bottom; k <= top; ++k) in_band[k].push_back(e);
    }
  for (const auto& [root, v] : lowest) {
    std::size_t outer = *around.begin(v);
    for (const std::size_t* at = around.begin(v); at != around.end(v); ++at) {
      const std::size_t h = *at;
      const Direction d = direction(h), best = direction(outer);
      const bool vertical = d.dx() == 0;
      if (best.dx() != 0 && (vertical || cross_sign(best, d) > 0)) outer = h;
    }
    const RationalPoint2& p = points[v];
    // The nearest edge of another component crossing the ray leftward from p (just above
    // it: an edge counts when its lower end is at or below p.y and its upper end above).
    std::optional<std::size_t> hit;
    Rational hit_x;
    std::vector<std::size_t> candidates;
    if (lowest.size() > 1)
      for (std::size_t k = band(approx[v].y.inf()); k <= band(approx[v].y.sup()); ++k)
        candidates.insert(candidates.end(), in_band[k].begin(), in_band[k].end());
    const IntervalPoint& pi = approx[v];
    double hit_low = -std::numeric_limits<double>::infinity();  // below the nearest x so far
    for (const std::size_t e : candidates) {
      {
        // Interval filters: an edge wholly above, below, right of p or left of the nearest
        // so far is not the nearest.
        const IntervalPoint &ai = approx[origin[2 * e]], &bi = approx[origin[2 * e + 1]];
        if (std::max(ai.y.sup(), bi.y.sup()) < pi.y.inf() ||
            std::min(ai.y.inf(), bi.y.inf()) > pi.y.sup() ||
            std::min(ai.x.inf(), bi.x.inf()) > pi.x.sup() ||
            std::max(ai.x.sup(), bi.x.sup()) < hit_low)
          continue;
      }
      if (component.root(origin[2 * e]) == root) continue;
      std::size_t lo = origin[2 * e], hi = origin[2 * e + 1];
      int c = cmp(points[lo].y(), points[hi].y());
      if (c == 0) continue;
      if (c > 0) std::swap(lo, hi);
      if (cmp(points[lo].y(), p.y()) > 0 || cmp(p.y(), points[hi].y()) >= 0) continue;
      const RationalPoint2 &a = points[lo], &b = points[hi];
      const Rational x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (cmp(x, p.x()) >= 0) continue;  // not on the left (never equal: components apart)
      bool nearer = !hit || cmp(x, hit_x) > 0;
      if (hit && cmp(x, hit_x) == 0) {
        // Both cross at one point: the one further right just above it is nearer.
        std::size_t hlo = origin[2 * *hit], hhi = origin[2 * *hit + 1];
        if (cmp(points[hlo].y(), points[hhi].y()) > 0) std::swap(hlo, hhi);
        const Rational mine = (b.x() - a.x()) / (b.y() - a.y());
        const Rational theirs =
            (points[hhi].x() - points[hlo].x()) / (points[hhi].y() - points[hlo].y());
        nearer = cmp(mine, theirs) > 0;
      }
      if (nearer) {
        hit = e;
        hit_x = x;
        hit_low = CGAL::to_interval(x).first;
      }
    }
    if (!hit) {
      faces.join(cycle[outer], cycles);
      continue;
    }
    // p lies on the right of the edge directed upward: the face on the left of the
    // downward halfedge.
    const std::size_t e = *hit;
    const bool even_up = cmp(points[origin[2 * e]].y(), points[origin[2 * e + 1]].y()) < 0;
    const std::size_t down = even_up ? 2 * e + 1 : 2 * e;
    faces.join(cycle[outer], cycle[down]);
  }

  // Face numbers (the unbounded face 0) and counts spread from it across the edges.
  std::vector<std::size_t> number(cycles + 1, SIZE_MAX);
  number[faces.root(cycles)] = 0;
  result.faces = 1;
  for (std::size_t c = 0; c < cycles; ++c)
    if (number[faces.root(c)] == SIZE_MAX) number[faces.root(c)] = result.faces++;
  result.face.resize(2 * edges);
  for (std::size_t h = 0; h < 2 * edges; ++h) result.face[h] = number[faces.root(cycle[h])];
  Groups halfedges_of =
      group_by(2 * edges, result.faces, [&](std::size_t h) { return result.face[h]; });
  result.count.assign(result.faces, 0);
  std::vector<bool> reached(result.faces, false);
  reached[0] = true;
  std::vector<std::size_t> queue{0};
  while (!queue.empty()) {
    const std::size_t f = queue.back();
    queue.pop_back();
    for (const std::size_t* at = halfedges_of.begin(f); at != halfedges_of.end(f); ++at) {
      const std::size_t h = *at;
      const std::size_t g = result.face[h ^ 1];
      if (reached[g]) continue;
      reached[g] = true;
      const long left = result.left[h / 2];
      result.count[g] = result.count[f] + (h % 2 == 0 ? -left : left);
      queue.push_back(g);
    }
  }
  return result;
}

std::vector<KeyPolygons> polygons_by_count(const SegmentArrangement& arrangement,
                                           const std::function<long(long)>& key_of,
                                           TraceSide side) {
  const std::size_t halfedges = arrangement.origin.size();
  std::vector<long> keys(arrangement.faces);
  for (std::size_t f = 0; f < arrangement.faces; ++f) keys[f] = key_of(arrangement.count[f]);
  DisjointSets sets(arrangement.faces);
  for (std::size_t h = 0; h < halfedges; h += 2) {
    const std::size_t a = arrangement.face[h], b = arrangement.face[h + 1];
    if (a != b && keys[a] >= 0 && keys[a] == keys[b]) sets.join(a, b);
  }
  const bool outside = side == TraceSide::outside;
  // A boundary halfedge has on its left the side its rings are traced on.
  const auto boundary = [&](std::size_t h) {
    const long k = keys[arrangement.face[h]], across = keys[arrangement.face[h ^ 1]];
    return outside ? (k < 0 && across >= 0) : (k >= 0 && k != across);
  };
  // The rings traced (vertex numbers only), one after another, each with the faces it
  // bounds on the inside side; traced outside, each ring's faces are one polygon, and its
  // vertices are reversed so that the inside lies on its left.
  std::vector<std::size_t> ring_vertices, ring_start{0}, ring_face;
  std::vector<bool> traced(halfedges, false);
  for (std::size_t h = 0; h < halfedges; ++h) {
    if (!boundary(h) || traced[h]) continue;
    const std::size_t first = ring_vertices.size();
    const std::size_t face = sets.root(arrangement.face[outside ? h ^ 1 : h]);
    std::size_t at = h;
    do {
      traced[at] = true;
      ring_vertices.push_back(arrangement.origin[at]);
      if (outside) sets.join(arrangement.face[at ^ 1], face);
      std::size_t next = arrangement.next[at];
      while (!boundary(next)) next = arrangement.next[next ^ 1];
      at = next;
    } while (at != h);
    if (outside)
      std::reverse(ring_vertices.begin() + static_cast<std::ptrdiff_t>(first), ring_vertices.end());
    ring_start.push_back(ring_vertices.size());
    ring_face.push_back(face);
  }
  for (std::size_t& face : ring_face) face = sets.root(face);
  // Twice each ring's area enclosed from its vertices' coordinates on the grid, added by
  // key in blocks of rings across threads (a ground's overlay has 3 10^6 rings: their
  // integers are not kept), with the ring's sign where the enclosure decides it.
  const std::size_t rings = ring_face.size();
  const auto ring_twice = [&](std::size_t r) {
    const std::size_t* first = ring_vertices.data() + ring_start[r];
    const std::size_t n = ring_start[r + 1] - ring_start[r];
    ShoelaceEnclosure twice;
    twice.add_path(n + 1, [&](std::size_t i) -> const RationalPoint2& {
      return arrangement.points[first[i % n]];
    });
    return twice;
  };
  constexpr std::size_t kRingsPerBlock = 1024;
  constexpr int kUndecided = 2;
  std::vector<std::map<long, ShoelaceEnclosure>> block_twice((rings + kRingsPerBlock - 1) /
                                                             kRingsPerBlock);
  std::vector<int> sign(rings, kUndecided);
  for_each_index(block_twice.size(), block_twice.size() > 1, [&](std::size_t b) {
    for (std::size_t r = b * kRingsPerBlock; r < std::min(rings, (b + 1) * kRingsPerBlock); ++r) {
      const ShoelaceEnclosure twice = ring_twice(r);
      if (const std::optional<int> known = twice.sign()) sign[r] = *known;
      block_twice[b][keys[ring_face[r]]].add(twice);
    }
  });
  // The points of the vertices on the rings, made once each, across threads.
  std::vector<char> used(arrangement.points.size(), 0);
  for (const std::size_t v : ring_vertices) used[v] = 1;
  std::vector<Point2> points(arrangement.points.size());
  for_each_index(
      points.size(), points.size() > 4096,
      [&](std::size_t v) {
        if (used[v]) points[v] = point_from<Point2>(RationalPoint2(arrangement.points[v]));
      },
      256);
  // Each ring made canonical and told outer boundary or hole, across threads: by the sign of
  // its area (the traced ring's is the canonical ring's: it drops only corners on a line),
  // since an orientation test at one corner (CGAL::orientation_2) is wrong at a corner where
  // the ring touches itself.
  std::vector<Ring2> canonical(rings);
  for_each_index(
      rings, rings > 64,
      [&](std::size_t r) {
        const std::size_t* first = ring_vertices.data() + ring_start[r];
        const std::size_t* last = ring_vertices.data() + ring_start[r + 1];
        Ring2 ring;
        ring.reserve(static_cast<std::size_t>(last - first));
        for (const std::size_t* v = first; v != last; ++v) ring.push_back(points[*v]);
        canonical[r] = canonical_ring(ring);
        if (!canonical[r].empty() && sign[r] == kUndecided) sign[r] = area_sign(canonical[r]);
      },
      16);
  // The polygons by face (the root of the faces a ring bounds).
  std::vector<std::size_t> polygon_of(arrangement.faces, rings);
  std::vector<Polygon2> polygons;
  for (std::size_t r = 0; r < rings; ++r) {
    if (canonical[r].empty()) continue;
    std::size_t& slot = polygon_of[ring_face[r]];
    if (slot == rings) {
      slot = polygons.size();
      polygons.emplace_back();
    }
    if (sign[r] > 0)
      polygons[slot].outer = std::move(canonical[r]);
    else
      polygons[slot].holes.push_back(std::move(canonical[r]));
  }
  std::map<long, std::pair<std::vector<Polygon2>, ShoelaceEnclosure>> by_key;
  for (const std::map<long, ShoelaceEnclosure>& block : block_twice)
    for (const auto& [key, twice] : block) by_key[key].second.add(twice);
  // The holes of faces without an outer boundary (the unbounded face's, when its key is one
  // to keep) are not kept: their areas are taken off again.
  for (std::size_t r = 0; r < rings; ++r)
    if (const std::size_t slot = polygon_of[ring_face[r]];
        slot != rings && polygons[slot].outer.empty())
      by_key[keys[ring_face[r]]].second.remove(ring_twice(r));
  for (std::size_t f = 0; f < arrangement.faces; ++f)
    if (polygon_of[f] != rings && !polygons[polygon_of[f]].outer.empty())
      by_key[keys[f]].first.push_back(std::move(polygons[polygon_of[f]]));
  std::vector<KeyPolygons> result;
  for (auto& [key, entry] : by_key)
    if (!entry.first.empty()) result.push_back({key, std::move(entry.first), entry.second.area()});
  return result;
}

}  // namespace penumbra::detail
