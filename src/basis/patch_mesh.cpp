#include "penumbra/basis/patch_mesh.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>

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

// returns the number of cells of size at most size across extent (at least one).
int cell_count(double extent, double size) {
  const double cells = std::ceil(extent / size * (1 - 1e-12));
  return std::max(1, static_cast<int>(std::min(cells, 1e6)));
}

}  // namespace

PatchMesh PatchMesh::subdivide(const Scene& scene, double patch_size) {
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
      // vertices of this face, shared between its cells: keyed on their frame coordinates
      // rounded to a billionth of a cell (clipping the same edge twice gives equal doubles;
      // the rounding only merges the rare corner computed in two orders).
      std::map<std::pair<long long, long long>, std::uint32_t> shared;
      const double quantum = 1e-9 * std::max(grid.du, grid.dv);
      const auto vertex_of = [&](const Point2d& p) {
        const std::pair<long long, long long> key{std::llround(p[0] / quantum),
                                                  std::llround(p[1] / quantum)};
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
          const double area = signed_area(cell);
          if (!(area > 0)) continue;
          Patch patch;
          patch.object = grid.object;
          patch.face = grid.face;
          const Point2d c = centroid(cell, area);
          patch.centre = grid.origin + c[0] * grid.u + c[1] * grid.v;
          patch.normal = normal;
          patch.area = area;
          patch.reflectance = reflectance;
          for (const Point2d& p : cell) {
            const std::uint32_t id = vertex_of(p);
            if (patch.vertices.empty() ||
                (patch.vertices.back() != id && patch.vertices.front() != id))
              patch.vertices.push_back(id);
          }
          if (patch.vertices.size() < 3) continue;
          grid.cells[static_cast<std::size_t>(a) + static_cast<std::size_t>(grid.nu) * b] =
              static_cast<std::int64_t>(mesh.patches_.size());
          mesh.patches_.push_back(std::move(patch));
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
  const std::int64_t direct =
      grid.cells[static_cast<std::size_t>(a) + grid.nu * static_cast<std::size_t>(b)];
  if (direct >= 0) return static_cast<std::uint32_t>(direct);
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
