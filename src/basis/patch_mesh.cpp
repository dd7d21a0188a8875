#include "penumbra/basis/patch_mesh.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <tuple>

#include "penumbra/base/input_error.h"
#include "penumbra/scene/scene.h"

namespace penumbra::basis {

using namespace vector_ops;

namespace {

using Point2d = std::array<double, 2>;
using Polygon2d = std::vector<Point2d>;

// clips a convex polygon to the half-plane sign * (p[axis] - bound) >= 0
// (Sutherland-Hodgman, one edge of a grid cell).
Polygon2d clip(const Polygon2d& polygon, int axis, double bound, double sign) {
  Polygon2d out;
  const std::size_t n = polygon.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Point2d& p = polygon[k];
    const Point2d& q = polygon[(k + 1) % n];
    const double fp = sign * (p[axis] - bound);
    const double fq = sign * (q[axis] - bound);
    if (fp >= 0) out.push_back(p);
    if ((fp >= 0) != (fq >= 0)) {
      Point2d x;
      x[axis] = bound;
      const int other = 1 - axis;
      x[other] = p[other] + (q[other] - p[other]) * ((bound - p[axis]) / (q[axis] - p[axis]));
      out.push_back(x);
    }
  }
  return out;
}

double signed_area(const Polygon2d& polygon) {
  double twice = 0;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const Point2d& p = polygon[k];
    const Point2d& q = polygon[(k + 1) % polygon.size()];
    twice += p[0] * q[1] - p[1] * q[0];
  }
  return twice / 2;
}

Point2d centroid(const Polygon2d& polygon, double area) {
  double cx = 0, cy = 0;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const Point2d& p = polygon[k];
    const Point2d& q = polygon[(k + 1) % polygon.size()];
    const double w = p[0] * q[1] - p[1] * q[0];
    cx += (p[0] + q[0]) * w;
    cy += (p[1] + q[1]) * w;
  }
  return {cx / (6 * area), cy / (6 * area)};
}

// clips a convex polygon to the side of the line through a and b where
// side * cross(b - a, p - a) >= 0.
Polygon2d clip_half(const Polygon2d& polygon, const Point2d& a, const Point2d& b, double side) {
  const auto f = [&](const Point2d& p) {
    return side * ((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]));
  };
  Polygon2d out;
  const std::size_t n = polygon.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Point2d& p = polygon[k];
    const Point2d& q = polygon[(k + 1) % n];
    const double fp = f(p), fq = f(q);
    if (fp >= 0) out.push_back(p);
    if ((fp >= 0) != (fq >= 0)) {
      const double t = fp / (fp - fq);
      out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
    }
  }
  return out;
}

// whether point lies inside the region of rings by the even-odd rule.
bool inside_rings(const std::vector<Polygon2d>& rings, const Point2d& point) {
  bool inside = false;
  for (const Polygon2d& ring : rings)
    for (std::size_t k = 0, j = ring.size() - 1; k < ring.size(); j = k++)
      if ((ring[k][1] > point[1]) != (ring[j][1] > point[1]) &&
          point[0] < ring[j][0] + (ring[k][0] - ring[j][0]) * (point[1] - ring[j][1]) /
                                      (ring[k][1] - ring[j][1]))
        inside = !inside;
  return inside;
}

// cuts a convex cell along the lines of every edge whose box overlaps the piece's (pieces
// thinner than a millionth of the cell's area are not made); the pieces stay convex.
std::vector<Polygon2d> split_cell(const Polygon2d& cell,
                                  const std::vector<std::array<Point2d, 2>>& edges) {
  std::vector<Polygon2d> pieces{cell};
  const double smallest = 1e-6 * signed_area(cell);
  for (const auto& [a, b] : edges) {
    std::vector<Polygon2d> next;
    for (const Polygon2d& piece : pieces) {
      double lo[2] = {piece[0][0], piece[0][1]}, hi[2] = {lo[0], lo[1]};
      for (const Point2d& p : piece)
        for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
      const bool overlaps = std::max(a[0], b[0]) >= lo[0] && std::min(a[0], b[0]) <= hi[0] &&
                            std::max(a[1], b[1]) >= lo[1] && std::min(a[1], b[1]) <= hi[1];
      const Polygon2d left = overlaps ? clip_half(piece, a, b, 1) : Polygon2d{};
      const Polygon2d right = overlaps ? clip_half(piece, a, b, -1) : Polygon2d{};
      if (left.size() >= 3 && right.size() >= 3 && signed_area(left) > smallest &&
          signed_area(right) > smallest) {
        next.push_back(left);
        next.push_back(right);
      } else {
        next.push_back(piece);
      }
    }
    pieces = std::move(next);
  }
  return pieces;
}

// returns the number of cells of size at most size across extent (at least one).
int cell_count(double extent, double size) {
  const double cells = std::ceil(extent / size * (1 - 1e-12));
  return std::max(1, static_cast<int>(std::min(cells, 1e6)));
}

}  // namespace

PatchMesh PatchMesh::subdivide(const Scene& scene, double patch_size, const MeshBreaks& breaks) {
  if (!(patch_size > 0) || !std::isfinite(patch_size))
    throw std::invalid_argument("patch size must be positive and finite");
  PatchMesh mesh;
  std::uint64_t cells = 0;
  // objects by name: the patches' order (and so the form factors' seeds, which follow it) does
  // not depend on the order of the scene file (docs/reliability.md)
  std::vector<std::size_t> by_name(scene.objects.size());
  std::iota(by_name.begin(), by_name.end(), 0);
  std::sort(by_name.begin(), by_name.end(), [&](std::size_t a, std::size_t b) {
    return scene.objects[a].name < scene.objects[b].name;
  });
  for (const std::size_t object : by_name) {
    const Object& body = scene.objects[object];
    const Material& material = scene.materials[body.material];
    std::array<double, 3> reflectance;
    for (int c = 0; c < 3; ++c) reflectance[c] = material.reflectance * material.color[c];
    const auto& faces = body.solid.faces();
    for (std::size_t f = 0; f < faces.size(); ++f) {
      if (!body.receives(f)) continue;  // inside a closed mesh
      const Face& face = faces[f];
      FaceGrid grid;
      grid.object = static_cast<std::uint32_t>(object);
      grid.face = static_cast<std::uint32_t>(f);
      grid.origin = to_double(face.frame.origin());
      grid.u = face.frame.unit_u();
      grid.v = face.frame.unit_v();
      const Vec3d normal = normalized(to_double(face.normal()));
      Polygon2d polygon;
      for (const Point3& p : face.vertices) {
        const Vec3d d = to_double(p) - grid.origin;
        polygon.push_back({dot(d, grid.u), dot(d, grid.v)});
      }
      double lo[2] = {polygon[0][0], polygon[0][1]}, hi[2] = {lo[0], lo[1]};
      for (const Point2d& p : polygon)
        for (int a = 0; a < 2; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
      grid.nu = cell_count(hi[0] - lo[0], patch_size);
      grid.nv = cell_count(hi[1] - lo[1], patch_size);
      grid.u0 = lo[0];
      grid.v0 = lo[1];
      grid.du = (hi[0] - lo[0]) / grid.nu;
      grid.dv = (hi[1] - lo[1]) / grid.nv;
      // the grid's cells bound the patches: refused over the limit before they are made
      cells += static_cast<std::uint64_t>(grid.nu) * static_cast<std::uint64_t>(grid.nv);
      if (cells > max_patches)
        throw InputError("<command line>", "--patch-size",
                         "a patch size of " + std::to_string(patch_size) + " m makes more than " +
                             std::to_string(max_patches) +
                             " patches: give a larger one (docs/reliability.md, \"Limits\")");
      grid.cells.assign(static_cast<std::size_t>(grid.nu) * grid.nv, -1);
      // the breaks of this face in its frame: each region's rings, and every ring edge
      std::vector<std::vector<Polygon2d>> regions;
      std::vector<std::array<Point2d, 2>> edges;
      if (const auto found = breaks.find({grid.object, grid.face}); found != breaks.end()) {
        for (const auto& rings : found->second.regions) {
          std::vector<Polygon2d>& region = regions.emplace_back();
          for (const auto& ring : rings) {
            Polygon2d& flat = region.emplace_back();
            for (const Vec3d& p : ring) {
              const Vec3d d = p - grid.origin;
              flat.push_back({dot(d, grid.u), dot(d, grid.v)});
            }
            for (std::size_t k = 0; k < flat.size(); ++k)
              edges.push_back({flat[k], flat[(k + 1) % flat.size()]});
          }
        }
        grid.pieces.assign(grid.cells.size(), 0);
      }
      // vertices of this face, shared between its cells: keyed on their frame coordinates
      // rounded to a billionth of a cell (clipping the same edge twice gives equal doubles;
      // the rounding only merges the rare corner computed in two orders) and on the side of
      // every break region the patch lies on (a vertex on a break is one per side)
      std::map<std::tuple<long long, long long, std::string>, std::uint32_t> shared;
      const double quantum = 1e-9 * std::max(grid.du, grid.dv);
      std::string side;
      const auto vertex_of = [&](const Point2d& p) {
        const std::tuple<long long, long long, std::string> key{std::llround(p[0] / quantum),
                                                                std::llround(p[1] / quantum), side};
        const auto found = shared.find(key);
        if (found != shared.end()) return found->second;
        const auto id = static_cast<std::uint32_t>(mesh.vertices_.size());
        mesh.vertices_.push_back(grid.origin + p[0] * grid.u + p[1] * grid.v);
        shared.emplace(key, id);
        return id;
      };
      const auto line = [](double origin, double step, int k, int count, double last) {
        return k == count ? last : origin + step * k;
      };
      for (int b = 0; b < grid.nv; ++b)
        for (int a = 0; a < grid.nu; ++a) {
          Polygon2d cell = polygon;
          cell = clip(cell, 0, line(grid.u0, grid.du, a, grid.nu, hi[0]), 1);
          cell = clip(cell, 0, line(grid.u0, grid.du, a + 1, grid.nu, hi[0]), -1);
          cell = clip(cell, 1, line(grid.v0, grid.dv, b, grid.nv, hi[1]), 1);
          cell = clip(cell, 1, line(grid.v0, grid.dv, b + 1, grid.nv, hi[1]), -1);
          if (cell.size() < 3) continue;
          if (!(signed_area(cell) > 0)) continue;
          const std::size_t k = static_cast<std::size_t>(a) + static_cast<std::size_t>(grid.nu) * b;
          for (const Polygon2d& piece :
               edges.empty() ? std::vector<Polygon2d>{cell} : split_cell(cell, edges)) {
            const double area = signed_area(piece);
            if (!(area > 0)) continue;
            Patch patch;
            patch.object = grid.object;
            patch.face = grid.face;
            const Point2d c = centroid(piece, area);
            patch.centre = grid.origin + c[0] * grid.u + c[1] * grid.v;
            patch.normal = normal;
            patch.area = area;
            patch.reflectance = reflectance;
            side.clear();
            for (const auto& region : regions) side += inside_rings(region, c) ? '1' : '0';
            for (const Point2d& p : piece) {
              const std::uint32_t id = vertex_of(p);
              if (patch.vertices.empty() ||
                  (patch.vertices.back() != id && patch.vertices.front() != id))
                patch.vertices.push_back(id);
            }
            if (patch.vertices.size() < 3) continue;
            if (grid.cells[k] < 0) grid.cells[k] = static_cast<std::int64_t>(mesh.patches_.size());
            if (!grid.pieces.empty()) ++grid.pieces[k];
            mesh.patches_.push_back(std::move(patch));
          }
        }
      mesh.grids_.push_back(std::move(grid));
    }
  }
  mesh.index();
  return mesh;
}

PatchMesh::PatchMesh(std::vector<Vec3d> vertices, std::vector<Patch> patches)
    : vertices_(std::move(vertices)), patches_(std::move(patches)) {
  index();
}

void PatchMesh::index() {
  vertex_weights_.assign(vertices_.size(), {});
  for (std::size_t p = 0; p < patches_.size(); ++p)
    for (std::uint32_t v : patches_[p].vertices)
      vertex_weights_.at(v).emplace_back(static_cast<std::uint32_t>(p), patches_[p].area);
  for (auto& weights : vertex_weights_) {
    double sum = 0;
    for (const auto& entry : weights) sum += entry.second;
    for (auto& entry : weights) entry.second /= sum;
  }
  first_grid_.clear();
  for (std::size_t g = 0; g < grids_.size(); ++g)
    if (grids_[g].face == 0) {
      if (first_grid_.size() <= grids_[g].object) first_grid_.resize(grids_[g].object + 1, 0);
      first_grid_[grids_[g].object] = g;
    }
}

std::vector<std::array<std::uint32_t, 3>> PatchMesh::triangles(
    std::vector<std::uint32_t>* triangle_patch) const {
  std::vector<std::array<std::uint32_t, 3>> out;
  if (triangle_patch) triangle_patch->clear();
  for (std::size_t p = 0; p < patches_.size(); ++p) {
    const auto& ring = patches_[p].vertices;
    for (std::size_t k = 1; k + 1 < ring.size(); ++k) {
      out.push_back({ring[0], ring[k], ring[k + 1]});
      if (triangle_patch) triangle_patch->push_back(static_cast<std::uint32_t>(p));
    }
  }
  return out;
}

std::optional<std::uint32_t> PatchMesh::locate(std::uint32_t object, std::uint32_t face,
                                               const Vec3d& point) const {
  if (object >= first_grid_.size()) return {};
  std::size_t g = first_grid_[object] + face;
  const auto is_it = [&](std::size_t k) {
    return k < grids_.size() && grids_[k].object == object && grids_[k].face == face;
  };
  // A face without patches (the inner side of a closed mesh's piece) shifts the object's
  // later grids down by one.
  if (!is_it(g) && face > 0 && is_it(g - 1)) --g;
  if (!is_it(g)) return {};
  const FaceGrid& grid = grids_[g];
  const Vec3d d = point - grid.origin;
  const auto cell_index = [](double s, double origin, double step, int count) {
    const double k = std::floor((s - origin) / step);
    return static_cast<int>(std::clamp(k, 0.0, static_cast<double>(count - 1)));
  };
  const int a = cell_index(dot(d, grid.u), grid.u0, grid.du, grid.nu);
  const int b = cell_index(dot(d, grid.v), grid.v0, grid.dv, grid.nv);
  const std::size_t cell = static_cast<std::size_t>(a) + grid.nu * static_cast<std::size_t>(b);
  const std::int64_t direct = grid.cells[cell];
  if (direct >= 0 && (grid.pieces.empty() || grid.pieces[cell] <= 1))
    return static_cast<std::uint32_t>(direct);
  if (direct >= 0) {
    // a cell cut along breaks: the piece holding the point, or the nearest piece centre
    const auto first = static_cast<std::uint32_t>(direct);
    std::uint32_t best = first;
    double best_distance = INFINITY;
    for (std::uint32_t p = first; p < first + grid.pieces[cell]; ++p) {
      const Patch& piece = patches_[p];
      bool holds = true;
      for (std::size_t k = 0; k < piece.vertices.size() && holds; ++k) {
        const Vec3d& from = vertices_[piece.vertices[k]];
        const Vec3d& to = vertices_[piece.vertices[(k + 1) % piece.vertices.size()]];
        holds = dot(piece.normal, cross(to - from, point - from)) >= 0;
      }
      if (holds) return p;
      const Vec3d away = piece.centre - point;
      if (dot(away, away) < best_distance) best = p, best_distance = dot(away, away);
    }
    return best;
  }
  // a point on the face whose cell kept no patch (a cell clipped to nothing by rounding):
  // the nearest patch centre among the neighbouring cells.
  std::optional<std::uint32_t> best;
  double best_distance = 0;
  for (int bb = std::max(0, b - 1); bb <= std::min(grid.nv - 1, b + 1); ++bb)
    for (int aa = std::max(0, a - 1); aa <= std::min(grid.nu - 1, a + 1); ++aa) {
      const std::int64_t p =
          grid.cells[static_cast<std::size_t>(aa) + grid.nu * static_cast<std::size_t>(bb)];
      if (p < 0) continue;
      const Vec3d to = patches_[static_cast<std::size_t>(p)].centre - point;
      const double distance = dot(to, to);
      if (!best || distance < best_distance)
        best = static_cast<std::uint32_t>(p), best_distance = distance;
    }
  return best;
}

std::optional<std::uint32_t> PatchMesh::nearest_patch(const Vec3d& point, double tolerance) const {
  std::optional<std::uint32_t> best;
  double best_distance = 0;
  for (std::size_t p = 0; p < patches_.size(); ++p) {
    const Patch& patch = patches_[p];
    if (std::abs(dot(point - patch.centre, patch.normal)) > tolerance) continue;
    const Vec3d to = patch.centre - point;
    const double distance = dot(to, to);
    if (!best || distance < best_distance)
      best = static_cast<std::uint32_t>(p), best_distance = distance;
  }
  return best;
}

}  // namespace penumbra::basis
