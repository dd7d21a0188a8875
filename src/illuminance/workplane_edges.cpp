#include "penumbra/illuminance/workplane_edges.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "penumbra/base/input_error.h"
#include "penumbra/base/parallel.h"
#include "penumbra/shadow/shadow_map.h"

namespace penumbra::illuminance {

namespace {

// appends the edges of every ring of region, carried from the face frame to the plan.
void append_edges(const Region2& region, const FaceFrame& frame, std::size_t light, bool umbra,
                  std::vector<PlanEdge>& out) {
  const auto append_ring = [&](const Ring2& ring) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Vec3d a = to_double(frame.to_world(ring[k]));
      const Vec3d b = to_double(frame.to_world(ring[(k + 1) % ring.size()]));
      out.push_back({{a[0], a[1]}, {b[0], b[1]}, light, umbra});
    }
  };
  for (const Polygon2& polygon : region.polygons) {
    append_ring(polygon.outer);
    for (const Ring2& hole : polygon.holes) append_ring(hole);
  }
}

// whether segment ab meets the closed rectangle [x0, x1] x [y0, y1] (Liang and Barsky's
// clipping of the segment's parameter interval by the four slabs).
bool meets(const PlanEdge& edge, double x0, double y0, double x1, double y1) {
  double low = 0, high = 1;
  const double d[2] = {edge.b[0] - edge.a[0], edge.b[1] - edge.a[1]};
  const double from[2] = {edge.a[0], edge.a[1]};
  const double lo[2] = {x0, y0}, hi[2] = {x1, y1};
  for (int axis = 0; axis < 2; ++axis) {
    if (d[axis] == 0) {
      if (from[axis] < lo[axis] || from[axis] > hi[axis]) return false;
      continue;
    }
    double t0 = (lo[axis] - from[axis]) / d[axis], t1 = (hi[axis] - from[axis]) / d[axis];
    if (t0 > t1) std::swap(t0, t1);
    low = std::max(low, t0);
    high = std::min(high, t1);
    if (low > high) return false;
  }
  return true;
}

}  // namespace

WorkplaneEdges workplane_shadow_edges(const Scene& scene, double height, const PlanRegion& region) {
  Scene copy = scene;
  if (copy.materials.empty()) copy.materials.emplace_back();
  Object plane;
  plane.name = "work plane";
  plane.kind = "polygon";
  plane.material = 0;
  plane.solid = ConvexPolyhedron::flat_polygon(
      {Point3(region.x0, region.y0, height), Point3(region.x1, region.y0, height),
       Point3(region.x1, region.y1, height), Point3(region.x0, region.y1, height)});
  const std::size_t object = copy.objects.size();
  std::size_t upper = 0;
  for (std::size_t f = 0; f < plane.solid.faces().size(); ++f)
    if (CGAL::sign(plane.solid.faces()[f].normal().z()) > 0) upper = f;
  copy.objects.push_back(std::move(plane));

  WorkplaneEdges result;
  for (std::size_t light = 0; light < copy.lights.size(); ++light) {
    ShadowOptions options;
    options.light = copy.lights[light].name;
    options.receivers = std::vector<Receiver>{{object, upper}};
    ShadowResult shadows;
    try {
      shadows = compute_shadows(copy, options);
    } catch (const InputError& error) {
      result.warnings.push_back(copy.lights[light].name + ": " + error.what());
      continue;
    }
    const Face& face = copy.objects[object].solid.faces()[upper];
    for (const LightShadows& lit : shadows.lights)
      for (const FaceShadow& map : lit.faces) {
        if (map.faces_away || map.beyond_range) continue;
        append_edges(map.shadow, face.frame, light, false, result.edges);
        if (map.extended) append_edges(map.umbra, face.frame, light, true, result.edges);
      }
  }
  return result;
}

PlanPoint WorkplaneRefinement::corner(const WorkplaneGrid& grid, const RefinedSquare& square,
                                      int refine, int a, int b) {
  const Vec3d origin = grid.point(square.i, square.j);
  return {origin[0] + grid.cell_width * a / refine, origin[1] + grid.cell_depth * b / refine};
}

WorkplaneRefinement refine_workplane(const IlluminanceSolver& solver, const WorkplaneValues& values,
                                     const std::vector<PlanEdge>& edges, int refine) {
  const WorkplaneGrid& grid = values.grid;
  WorkplaneRefinement result;
  result.refine = refine;
  if (grid.columns < 2 || grid.rows < 2) return result;
  const std::size_t squares_x = grid.columns - 1, squares_y = grid.rows - 1;
  const double grow = 1e-9 * std::max(grid.cell_width, grid.cell_depth);
  const Vec3d first = grid.point(0, 0);
  // the squares each edge's bounding box covers, tested one by one
  std::vector<char> marked(squares_x * squares_y, 0);
  const auto index_range = [](double low, double high, double origin, double step,
                              std::size_t count) {
    const double a = std::floor((low - origin) / step) - 1,
                 b = std::floor((high - origin) / step) + 1;
    const auto clamp = [&](double v) {
      return static_cast<std::size_t>(std::clamp(v, 0.0, static_cast<double>(count - 1)));
    };
    return std::array<std::size_t, 2>{clamp(a), clamp(b)};
  };
  for (const PlanEdge& edge : edges) {
    const auto is = index_range(std::min(edge.a[0], edge.b[0]), std::max(edge.a[0], edge.b[0]),
                                first[0], grid.cell_width, squares_x);
    const auto js = index_range(std::min(edge.a[1], edge.b[1]), std::max(edge.a[1], edge.b[1]),
                                first[1], grid.cell_depth, squares_y);
    for (std::size_t j = js[0]; j <= js[1]; ++j)
      for (std::size_t i = is[0]; i <= is[1]; ++i) {
        if (marked[j * squares_x + i]) continue;
        const Vec3d p = grid.point(i, j), q = grid.point(i + 1, j + 1);
        if (meets(edge, p[0] - grow, p[1] - grow, q[0] + grow, q[1] + grow))
          marked[j * squares_x + i] = 1;
      }
  }
  for (std::size_t j = 0; j < squares_y; ++j)
    for (std::size_t i = 0; i < squares_x; ++i)
      if (marked[j * squares_x + i]) result.squares.push_back({i, j, {}, {}});

  // the corners' illuminance (the square's own corners are the grid's values) and which
  // sub-squares an edge meets
  const int side = refine + 1;
  for_each_range(result.squares.size(), true, [&](std::size_t from, std::size_t to) {
    for (std::size_t s = from; s < to; ++s) {
      RefinedSquare& square = result.squares[s];
      std::vector<ReceivingPoint> points;
      for (int b = 0; b < side; ++b)
        for (int a = 0; a < side; ++a) {
          const PlanPoint at = WorkplaneRefinement::corner(grid, square, refine, a, b);
          points.push_back({{at[0], at[1], grid.height}, {0, 0, 1}});
        }
      const std::vector<PointIlluminance> found = illuminance_at_points(solver, points);
      square.values.resize(found.size());
      for (std::size_t k = 0; k < found.size(); ++k)
        square.values[k] =
            found[k].inside ? std::numeric_limits<double>::quiet_NaN() : found[k].total;
      square.cut.assign(static_cast<std::size_t>(refine) * refine, 0);
      const Vec3d low = grid.point(square.i, square.j);
      const Vec3d high = grid.point(square.i + 1, square.j + 1);
      std::vector<PlanEdge> near;
      for (const PlanEdge& edge : edges)
        if (meets(edge, low[0] - grow, low[1] - grow, high[0] + grow, high[1] + grow))
          near.push_back(edge);
      for (int b = 0; b < refine; ++b)
        for (int a = 0; a < refine; ++a) {
          const PlanPoint p = WorkplaneRefinement::corner(grid, square, refine, a, b);
          const PlanPoint q = WorkplaneRefinement::corner(grid, square, refine, a + 1, b + 1);
          for (const PlanEdge& edge : near)
            if (meets(edge, p[0] - grow, p[1] - grow, q[0] + grow, q[1] + grow)) {
              square.cut[static_cast<std::size_t>(b * refine + a)] = 1;
              break;
            }
        }
    }
  });
  result.evaluations = result.squares.size() * static_cast<std::size_t>(side * side);
  return result;
}

}  // namespace penumbra::illuminance
