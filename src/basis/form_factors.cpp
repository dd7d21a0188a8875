#include "penumbra/basis/form_factors.h"

#include <algorithm>
#include <cmath>

#include "penumbra/base/numbers.h"
#include "penumbra/base/parallel.h"
#include "penumbra/base/random.h"
#include "penumbra/basis/patch_mesh.h"
#include "penumbra/raytrace/embree_scene.h"
#include "penumbra/scene/scene.h"

namespace penumbra::basis {

using namespace vector_ops;

namespace {

using Row = std::vector<std::pair<std::int64_t, double>>;

// An orthonormal frame (t, b, n) around unit n (Duff et al. 2017, branchless).
void tangent_frame(const Vec3d& n, Vec3d& t, Vec3d& b) {
  const double sign = std::copysign(1.0, n[2]);
  const double a = -1 / (sign + n[2]);
  const double c = n[0] * n[1] * a;
  t = {1 + sign * n[0] * n[0] * a, sign * c, -sign * n[0]};
  b = {c, sign + n[1] * n[1] * a, -n[1]};
}

// Maps the unit square onto a convex patch with constant Jacobian (area-preserving), so
// that stratified points of the square are stratified points of the patch: the first
// coordinate picks a triangle of the fan by area and, rescaled, the distance from its
// apex (sqrt for uniform area), the second the position across.
class PatchMap {
 public:
  PatchMap(const PatchMesh& mesh, const Patch& patch) {
    const auto& ring = patch.vertices;
    origin_ = mesh.vertices()[ring[0]];
    double total = 0;
    for (std::size_t k = 1; k + 1 < ring.size(); ++k) {
      const Vec3d e1 = mesh.vertices()[ring[k]] - origin_;
      const Vec3d e2 = mesh.vertices()[ring[k + 1]] - origin_;
      edges_.push_back({e1, e2});
      lower_.push_back(total);
      total += length(cross(e1, e2));
    }
    for (double& c : lower_) c /= total;
    lower_.push_back(1);
  }
  Vec3d operator()(double a, double b) const {
    std::size_t k = 0;
    while (k + 1 < edges_.size() && a >= lower_[k + 1]) ++k;
    const double share = lower_[k + 1] - lower_[k];
    const double along = std::sqrt(std::clamp(share > 0 ? (a - lower_[k]) / share : 0.0, 0.0, 1.0));
    return origin_ + along * (1 - b) * edges_[k][0] + along * b * edges_[k][1];
  }

 private:
  Vec3d origin_;
  std::vector<std::array<Vec3d, 2>> edges_;
  std::vector<double> lower_;  // cumulative area fraction before each triangle, then 1
};

// The unit normals of every face of every sphere object, in doubles: exact spheres
// report face -1, and are mapped to the facet of their tessellation with the nearest normal.
using SphereNormals = std::vector<std::vector<Vec3d>>;

SphereNormals sphere_normals(const Scene& scene) {
  SphereNormals normals(scene.objects.size());
  for (std::size_t k = 0; k < scene.objects.size(); ++k)
    if (scene.objects[k].sphere)
      for (const Face& face : scene.objects[k].solid.faces())
        normals[k].push_back(normalized(to_double(face.normal())));
  return normals;
}

// The patch a ray hit.
std::optional<std::uint32_t> hit_patch(const SphereNormals& spheres, const PatchMesh& mesh,
                                       const raytrace::Hit& hit) {
  int face = hit.face;
  if (face < 0) {
    double best = -2;
    const std::vector<Vec3d>& normals = spheres[hit.object];
    for (std::size_t f = 0; f < normals.size(); ++f) {
      const double c = dot(normals[f], hit.normal);
      if (c > best) best = c, face = static_cast<int>(f);
    }
    if (face < 0) return {};
  }
  return mesh.locate(static_cast<std::uint32_t>(hit.object), static_cast<std::uint32_t>(face),
                     hit.point);
}

// Stratified cosine-weighted rays from patch i (Malley's method).
Row ray_row(const SphereNormals& spheres, const PatchMesh& mesh,
            const raytrace::EmbreeScene& embree, std::size_t i, int strata, std::uint64_t seed,
            double offset) {
  const Patch& patch = mesh.patches()[i];
  const PatchMap on_patch(mesh, patch);
  // One stream per patch, so the rows do not depend on the order threads take them.
  SplitMix64 random(seed * SplitMix64::golden_gamma ^ (i + 1));
  Vec3d t, b;
  tangent_frame(patch.normal, t, b);
  std::vector<std::int64_t> hits;
  const int rays = strata * strata;
  hits.reserve(static_cast<std::size_t>(rays));
  // origins stratified over the patch too, their strata paired with the direction strata
  // by a random permutation (a Latin pairing), so that both integrals are stratified
  std::vector<int> origin_stratum(static_cast<std::size_t>(rays));
  for (int k = 0; k < rays; ++k) origin_stratum[static_cast<std::size_t>(k)] = k;
  for (int k = rays - 1; k > 0; --k)
    std::swap(origin_stratum[static_cast<std::size_t>(k)],
              origin_stratum[static_cast<std::size_t>(
                  std::min(k, static_cast<int>(random.uniform() * (k + 1))))]);
  for (int a = 0; a < strata; ++a)
    for (int c = 0; c < strata; ++c) {
      const double r2 = (a + random.uniform()) / strata;            // stratified in r^2 and phi:
      const double phi = 2 * pi * (c + random.uniform()) / strata;  // equal-area on the disk
      const double r = std::sqrt(r2);
      const Vec3d direction = r * std::cos(phi) * t + r * std::sin(phi) * b +
                              std::sqrt(std::max(0.0, 1 - r2)) * patch.normal;
      const int o = origin_stratum[static_cast<std::size_t>(a * strata + c)];
      const Vec3d origin = on_patch((o / strata + random.uniform()) / strata,
                                    (o % strata + random.uniform()) / strata);
      raytrace::Ray ray{origin, direction, offset, std::numeric_limits<double>::infinity()};
      // a ray leaving a face outward cannot meet that face again: a hit on it is single-
      // precision traversal finding the origin's own plane, and the ray goes on past it.
      for (int attempt = 0; attempt < 4; ++attempt) {
        const std::optional<raytrace::Hit> hit = embree.intersect(ray);
        if (!hit) break;
        if (hit->object == patch.object && hit->face == static_cast<int>(patch.face)) {
          ray.t_near = hit->distance + offset;
          continue;
        }
        const std::optional<std::uint32_t> j = hit_patch(spheres, mesh, *hit);
        if (j && *j != i) hits.push_back(*j);
        break;
      }
    }
  std::sort(hits.begin(), hits.end());
  Row row;
  const double share = 1.0 / (static_cast<double>(strata) * strata);
  for (std::size_t k = 0; k < hits.size();) {
    std::size_t end = k;
    while (end < hits.size() && hits[end] == hits[k]) ++end;
    row.emplace_back(hits[k], share * static_cast<double>(end - k));
    k = end;
  }
  return row;
}

// clips polygon to the closed half-space n . (x - p) >= 0.
std::vector<Vec3d> clip_to_front(const std::vector<Vec3d>& polygon, const Vec3d& p,
                                 const Vec3d& n) {
  std::vector<Vec3d> out;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const Vec3d& a = polygon[k];
    const Vec3d& c = polygon[(k + 1) % polygon.size()];
    const double fa = dot(n, a - p), fc = dot(n, c - p);
    if (fa >= 0) out.push_back(a);
    if ((fa >= 0) != (fc >= 0)) out.push_back(a + (fa / (fa - fc)) * (c - a));
  }
  return out;
}

// Point-to-polygon form factors from the centre of patch i, times the visibility of
// each patch centre.
Row analytic_row(const PatchMesh& mesh, const raytrace::EmbreeScene& embree, std::size_t i,
                 double offset) {
  const Patch& from = mesh.patches()[i];
  Row row;
  for (std::size_t j = 0; j < mesh.size(); ++j) {
    if (j == i) continue;
    const Patch& to = mesh.patches()[j];
    // the receiving patch must face the centre, and lie (partly) in front of it
    if (dot(to.normal, from.centre - to.centre) <= 0) continue;
    std::vector<Vec3d> polygon;
    for (std::uint32_t v : to.vertices) polygon.push_back(mesh.vertices()[v]);
    polygon = clip_to_front(polygon, from.centre, from.normal);
    if (polygon.size() < 3) continue;
    const double factor = point_polygon_form_factor(from.centre, from.normal, polygon);
    if (factor <= 0) continue;
    const Vec3d to_centre = to.centre - from.centre;
    const double distance = length(to_centre);
    const raytrace::Ray ray{from.centre, (1 / distance) * to_centre, offset, distance - offset};
    if (distance > 2 * offset && embree.occluded(ray)) continue;
    row.emplace_back(static_cast<std::int64_t>(j), factor);
  }
  return row;
}

}  // namespace

double point_polygon_form_factor(const Vec3d& point, const Vec3d& normal,
                                 const std::vector<Vec3d>& polygon) {
  double sum = 0;
  const std::size_t n = polygon.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3d a = normalized(polygon[k] - point);
    const Vec3d b = normalized(polygon[(k + 1) % n] - point);
    const Vec3d c = cross(a, b);
    const double s = length(c);
    if (s == 0) continue;
    const double gamma = std::atan2(s, dot(a, b));
    sum += gamma * dot(normal, c) / s;
  }
  return std::abs(sum) / (2 * pi);
}

FormFactorMatrix form_factors(const Scene& scene, const PatchMesh& mesh,
                              const FormFactorOptions& options,
                              const std::function<void(std::size_t)>& progress) {
  const raytrace::EmbreeScene embree(scene, raytrace::PatchSurfaces::tessellated);
  const SphereNormals spheres = sphere_normals(scene);
  // as the ray tracer: Embree traverses in single precision (raytrace/ray_tracer.cpp)
  const double offset = 1e-5 * embree.scale();
  const int strata = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(options.rays))));
  std::vector<Row> rows(mesh.size());
  const auto compute = [&](std::size_t i) {
    rows[i] = options.method == FormFactorMethod::rays
                  ? ray_row(spheres, mesh, embree, i, strata, options.seed, offset)
                  : analytic_row(mesh, embree, i, offset);
    if (progress) progress(1);
  };
  for_each_index(mesh.size(), options.parallel, compute);
  FormFactorMatrix matrix(static_cast<std::int64_t>(mesh.size()),
                          static_cast<std::int64_t>(mesh.size()));
  std::vector<std::int64_t> sizes;
  for (const Row& row : rows) sizes.push_back(static_cast<std::int64_t>(row.size()));
  matrix.reserve(sizes);
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (const auto& [j, value] : rows[i]) matrix.insert(static_cast<std::int64_t>(i), j) = value;
  matrix.makeCompressed();
  return matrix;
}

}  // namespace penumbra::basis
