#include "penumbra/illuminance/isolux.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace penumbra::illuminance {
namespace {

// === Marching squares

struct Segment {
  long from_edge, to_edge;
  PlanPoint from, to;
};

// joins segments sharing grid edges into polylines; each grid edge carries at most two
// segment ends at one level, so the walk is unambiguous.
std::vector<IsoluxLine> join(double level, const std::vector<Segment>& segments) {
  std::unordered_map<long, std::vector<std::size_t>> at_edge;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    at_edge[segments[s].from_edge].push_back(s);
    at_edge[segments[s].to_edge].push_back(s);
  }
  std::vector<bool> used(segments.size(), false);
  // returns the unused segment at edge, or -1.
  auto next_at = [&](long edge) -> long {
    for (std::size_t s : at_edge[edge])
      if (!used[s]) return static_cast<long>(s);
    return -1;
  };
  std::vector<IsoluxLine> lines;
  for (std::size_t start = 0; start < segments.size(); ++start) {
    if (used[start]) continue;
    used[start] = true;
    std::vector<PlanPoint> forward{segments[start].from, segments[start].to};
    std::vector<PlanPoint> backward;
    const long start_edge = segments[start].from_edge;
    long edge = segments[start].to_edge;
    bool closed = false;
    for (long s; (s = next_at(edge)) >= 0;) {
      used[s] = true;
      const Segment& segment = segments[s];
      const bool forwards = segment.from_edge == edge;
      edge = forwards ? segment.to_edge : segment.from_edge;
      if (edge == start_edge) {
        closed = true;
        break;
      }
      forward.push_back(forwards ? segment.to : segment.from);
    }
    for (edge = start_edge; !closed;) {
      const long s = next_at(edge);
      if (s < 0) break;
      used[s] = true;
      const Segment& segment = segments[s];
      const bool forwards = segment.from_edge == edge;
      edge = forwards ? segment.to_edge : segment.from_edge;
      backward.push_back(forwards ? segment.to : segment.from);
    }
    IsoluxLine line{level, {backward.rbegin(), backward.rend()}, closed};
    line.points.insert(line.points.end(), forward.begin(), forward.end());
    lines.push_back(std::move(line));
  }
  return lines;
}

}  // namespace

std::vector<double> isolux_levels(double minimum, double maximum) {
  std::vector<double> levels;
  if (!(maximum > minimum) || !std::isfinite(minimum) || !std::isfinite(maximum)) return levels;
  const double floor_value = std::max(minimum, maximum * 1e-3);
  if (floor_value > 0 && maximum / floor_value > 20) {
    // 1-2-5 series: one decade per three lines suits a range of several decades.
    for (double decade = std::pow(10.0, std::floor(std::log10(floor_value))); decade <= maximum;
         decade *= 10)
      for (double mantissa : {1.0, 2.0, 5.0}) {
        const double level = mantissa * decade;
        if (level > floor_value && level < maximum) levels.push_back(level);
      }
    return levels;
  }
  const double raw = (maximum - minimum) / 8;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  double step = decade;
  for (double mantissa : {1.0, 2.0, 5.0, 10.0})
    if (mantissa * decade >= raw) {
      step = mantissa * decade;
      break;
    }
  for (double level = std::floor(minimum / step + 1) * step; level < maximum; level += step)
    if (level > minimum) levels.push_back(level);
  return levels;
}

namespace {

// Marching squares on one square: corners counter-clockwise from the lower left, edge k from
// corner k to k + 1 with the id edge_id[k] (shared with the neighbour across it, so that
// join() links the segments). Appends the square's segments at level.
void march(const PlanPoint (&at)[4], const double (&value)[4], const long (&edge_id)[4],
           double level, std::vector<Segment>& segments) {
  int mask = 0;
  for (int k = 0; k < 4; ++k)
    if (value[k] >= level) mask |= 1 << k;
  if (mask == 0 || mask == 15) return;
  const auto crossing = [&](int k) {
    const int a = k, b = (k + 1) % 4;
    const double t = (level - value[a]) / (value[b] - value[a]);
    return PlanPoint{at[a][0] + t * (at[b][0] - at[a][0]), at[a][1] + t * (at[b][1] - at[a][1])};
  };
  const auto add = [&](int e, int f) {
    segments.push_back({edge_id[e], edge_id[f], crossing(e), crossing(f)});
  };
  // An edge is crossed when its two corners differ; a square has two or four.
  std::vector<int> crossed;
  for (int k = 0; k < 4; ++k)
    if (((mask >> k) & 1) != ((mask >> ((k + 1) % 4)) & 1)) crossed.push_back(k);
  if (crossed.size() == 2) {
    add(crossed[0], crossed[1]);
    return;
  }
  // Saddle (corners 0 and 2 against 1 and 3): the mean decides which diagonal pair is
  // joined. Edges 3 and 0 meet at corner 0, edges 1 and 2 at corner 2.
  const bool centre_above = (value[0] + value[1] + value[2] + value[3]) / 4 >= level;
  const bool corner0_above = (mask & 1) != 0;
  if (centre_above == corner0_above) {
    add(0, 1);  // cut off corner 1
    add(2, 3);  // and corner 3
  } else {
    add(3, 0);  // cut off corner 0
    add(1, 2);  // and corner 2
  }
}

// The squares of an n_x x n_y lattice of nodes, with ids of their edges from first_id on:
// node (a, b)'s edge to (a + 1, b) is first_id + 2 (b n_x + a), to (a, b + 1) one more.
struct Lattice {
  std::size_t nx;
  long first_id;
  long horizontal(std::size_t a, std::size_t b) const {
    return first_id + 2 * static_cast<long>(b * nx + a);
  }
  long vertical(std::size_t a, std::size_t b) const { return horizontal(a, b) + 1; }
  void edges(std::size_t a, std::size_t b, long (&id)[4]) const {
    id[0] = horizontal(a, b);
    id[1] = vertical(a + 1, b);
    id[2] = horizontal(a, b + 1);
    id[3] = vertical(a, b);
  }
};

}  // namespace

std::vector<IsoluxLine> isolux_lines(const WorkplaneValues& values,
                                     const std::vector<double>& levels) {
  return isolux_lines(values, levels, WorkplaneRefinement{});
}

std::vector<IsoluxLine> isolux_lines(const WorkplaneValues& values,
                                     const std::vector<double>& levels,
                                     const WorkplaneRefinement& refinement) {
  const WorkplaneGrid& grid = values.grid;
  std::vector<IsoluxLine> lines;
  if (grid.columns < 2 || grid.rows < 2) return lines;
  const auto index = [&](std::size_t i, std::size_t j) { return j * grid.columns + i; };
  const Lattice coarse{grid.columns, 0};
  std::vector<char> refined((grid.columns - 1) * (grid.rows - 1), 0);
  for (const RefinedSquare& square : refinement.squares)
    refined[square.j * (grid.columns - 1) + square.i] = 1;
  const int n = refinement.refine, side = n + 1;
  for (double level : levels) {
    std::vector<Segment> segments;
    for (std::size_t j = 0; j + 1 < grid.rows; ++j)
      for (std::size_t i = 0; i + 1 < grid.columns; ++i) {
        if (refined[j * (grid.columns - 1) + i]) continue;
        const std::size_t corner[4] = {index(i, j), index(i + 1, j), index(i + 1, j + 1),
                                       index(i, j + 1)};
        long edge_id[4];
        coarse.edges(i, j, edge_id);
        double value[4];
        PlanPoint at[4];
        bool skip = false;
        for (int k = 0; k < 4; ++k) {
          const PointIlluminance& e = values.values[corner[k]];
          skip = skip || e.inside.has_value();
          value[k] = e.total;
          const Vec3d p = grid.point(corner[k]);
          at[k] = {p[0], p[1]};
        }
        if (!skip) march(at, value, edge_id, level, segments);
      }
    // docs/illuminance.md, "Exact isolux lines": inside a refined square, only the
    // sub-squares no boundary meets, so no line crosses a boundary
    for (std::size_t s = 0; s < refinement.squares.size(); ++s) {
      const RefinedSquare& square = refinement.squares[s];
      const Lattice fine{
          static_cast<std::size_t>(side),
          2 * static_cast<long>(grid.size()) + 2 * static_cast<long>(s) * side * side};
      for (int b = 0; b < n; ++b)
        for (int a = 0; a < n; ++a) {
          if (square.cut[static_cast<std::size_t>(b * n + a)]) continue;
          const int node[4][2] = {{a, b}, {a + 1, b}, {a + 1, b + 1}, {a, b + 1}};
          double value[4];
          PlanPoint at[4];
          bool skip = false;
          for (int k = 0; k < 4; ++k) {
            value[k] = square.values[static_cast<std::size_t>(node[k][1] * side + node[k][0])];
            skip = skip || std::isnan(value[k]);
            at[k] = WorkplaneRefinement::corner(grid, square, n, node[k][0], node[k][1]);
          }
          long edge_id[4];
          fine.edges(static_cast<std::size_t>(a), static_cast<std::size_t>(b), edge_id);
          if (!skip) march(at, value, edge_id, level, segments);
        }
    }
    for (IsoluxLine& line : join(level, segments)) lines.push_back(std::move(line));
  }
  return lines;
}

std::vector<double> picture_levels(std::vector<double> values) {
  values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return !(v > 0); }),
               values.end());
  if (values.empty()) return {};
  const auto at = [&](double fraction) {
    const auto rank =
        static_cast<std::ptrdiff_t>(fraction * static_cast<double>(values.size() - 1));
    std::nth_element(values.begin(), values.begin() + rank, values.end());
    return values[static_cast<std::size_t>(rank)];
  };
  const double low = at(0.02), high = at(0.98);
  return isolux_levels(low, high);
}

}  // namespace penumbra::illuminance
