#include "penumbra/raytrace/bezier_intersection.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace penumbra::raytrace {

using namespace vector_ops;
namespace {

constexpr double kEdgeSlack = 1e-12;  // parameter slack at a piece's edges
constexpr int kMaxDepth = 8;          // subdivision levels of flat_pieces
constexpr int kRetryDepth = 3;        // further levels where Newton's method finds no hit

void cut(const BezierPatch& hull, double u0, double u1, double v0, double v1, int depth,
         std::size_t patch, double relative_flatness, std::vector<PatchPiece>& out) {
  const auto [low, high] = hull.bounds();
  if (depth == kMaxDepth || hull.flatness() <= relative_flatness * length(high - low)) {
    out.push_back({hull, u0, u1, v0, v1, patch, low, high});
    return;
  }
  // Halve the direction in which the control net is longer.
  const double along_u =
      length(hull.at(3, 0) - hull.at(0, 0)) + length(hull.at(3, 3) - hull.at(0, 3));
  const double along_v =
      length(hull.at(0, 3) - hull.at(0, 0)) + length(hull.at(3, 3) - hull.at(3, 0));
  const bool split_u = along_u >= along_v;
  const auto [first, second] = hull.split(split_u);
  if (split_u) {
    const double mid = 0.5 * (u0 + u1);
    cut(first, u0, mid, v0, v1, depth + 1, patch, relative_flatness, out);
    cut(second, mid, u1, v0, v1, depth + 1, patch, relative_flatness, out);
  } else {
    const double mid = 0.5 * (v0 + v1);
    cut(first, u0, u1, v0, mid, depth + 1, patch, relative_flatness, out);
    cut(second, u0, u1, mid, v1, depth + 1, patch, relative_flatness, out);
  }
}

// returns the part [near, far] of the ray's segment inside the box grown by a relative
// margin, or {}.
std::optional<std::pair<double, double>> box_span(const Vec3d& low, const Vec3d& high,
                                                  const Ray& ray) {
  const double margin =
      1e-9 * (length(high - low) + std::abs(low[0]) + std::abs(low[1]) + std::abs(low[2]));
  double near = ray.t_near, far = ray.t_far;
  for (int k = 0; k < 3; ++k) {
    const double lo = low[k] - margin, hi = high[k] + margin;
    if (ray.direction[k] == 0) {
      if (ray.origin[k] < lo || ray.origin[k] > hi) return std::nullopt;
      continue;
    }
    double a = (lo - ray.origin[k]) / ray.direction[k];
    double b = (hi - ray.origin[k]) / ray.direction[k];
    if (a > b) std::swap(a, b);
    near = std::max(near, a);
    far = std::min(far, b);
    if (near > far) return std::nullopt;
  }
  return std::pair{near, far};
}

// returns whether the ray's span [near, far] meets the slab of the control points across
// the corners' mean normal (the hull lies in it): a flat piece's slab is much thinner than
// its box, so most rays that only cross the box are turned away here.
bool crosses_slab(const BezierPatch& h, const Ray& ray, std::pair<double, double> span) {
  const Vec3d n = cross(h.at(3, 3) - h.at(0, 0), h.at(0, 3) - h.at(3, 0));
  const double size = length(n);
  if (!(size > 0)) return true;
  const Vec3d unit = (1 / size) * n;
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const Vec3d& p : h.points) {
    const double s = dot(unit, p - h.at(0, 0));
    low = std::min(low, s);
    high = std::max(high, s);
  }
  const double margin = 1e-9 * (high - low + length(h.at(3, 3) - h.at(0, 0)));
  low -= margin;
  high += margin;
  const double start = dot(unit, ray.origin - h.at(0, 0)), rate = dot(unit, ray.direction);
  if (rate == 0) return start >= low && start <= high;
  double a = (low - start) / rate, b = (high - start) / rate;
  if (a > b) std::swap(a, b);
  return std::max(a, span.first) <= std::min(b, span.second);
}

// The ray's hit on triangle a, b, c as (t, s, w) with p = a + s (b - a) + w (c - a)
// (Moller and Trumbore), accepting s and w a quarter beyond the triangle: a guess, not a hit.
std::optional<std::array<double, 3>> triangle_guess(const Vec3d& a, const Vec3d& b, const Vec3d& c,
                                                    const Ray& ray) {
  const Vec3d e1 = b - a, e2 = c - a;
  const Vec3d p = cross(ray.direction, e2);
  const double det = dot(e1, p);
  if (det == 0 || !std::isfinite(det)) return std::nullopt;
  const Vec3d s = ray.origin - a;
  const double x = dot(s, p) / det;
  const Vec3d q = cross(s, e1);
  const double y = dot(ray.direction, q) / det;
  if (x < -0.25 || y < -0.25 || x + y > 1.5) return std::nullopt;
  return std::array<double, 3>{dot(e2, q) / det, x, y};
}

// Newton's method on S(u, v) - (o + t d) = 0 from x; gives up when the iterate leaves the
// parameter box [u0, u1] x [v0, v1] grown by its own size, or does not converge.
std::optional<PatchHit> newton(const BezierPatch& patch, const Ray& ray, PatchHit x, double u0,
                               double u1, double v0, double v1) {
  const double grow_u = u1 - u0, grow_v = v1 - v0;
  int settled = 0;
  for (int iteration = 0; iteration < 32 && settled < 2; ++iteration) {
    const BezierPatch::Jet jet = patch.jet(x.u, x.v);
    const Vec3d residual = ray.origin + x.t * ray.direction - jet.point;  // = -F
    // [S_u S_v -d] (du, dv, dt) = -F by Cramer's rule.
    const Vec3d c2 = -ray.direction;
    const Vec3d c12 = cross(jet.dv, c2);
    const double det = dot(jet.du, c12);
    if (det == 0 || !std::isfinite(det)) return std::nullopt;
    const double du = dot(residual, c12) / det;
    const double dv = dot(jet.du, cross(residual, c2)) / det;
    const double dt = dot(jet.du, cross(jet.dv, residual)) / det;
    x.u += du;
    x.v += dv;
    x.t += dt;
    if (!std::isfinite(x.u) || !std::isfinite(x.v) || !std::isfinite(x.t)) return std::nullopt;
    if (x.u < u0 - grow_u || x.u > u1 + grow_u || x.v < v0 - grow_v || x.v > v1 + grow_v)
      return std::nullopt;
    if (std::abs(du) + std::abs(dv) <= 1e-14) ++settled;
  }
  if (settled == 0) return std::nullopt;
  return x;
}

bool within(double value, double low, double high) {
  return value >= std::max(low, 0.0) - kEdgeSlack && value <= std::min(high, 1.0) + kEdgeSlack;
}

// returns true when det(d, a, b) has one strict sign for every a among the differences of
// the control points along u and b among those along v (see hit_on).
bool seen_from_one_side(const BezierPatch& h, const Vec3d& d) {
  bool positive = false, negative = false;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) {
      const Vec3d along = cross(d, h.at(i + 1, j) - h.at(i, j));
      for (int k = 0; k < 4; ++k)
        for (int l = 0; l < 3; ++l) {
          const double value = dot(along, h.at(k, l + 1) - h.at(k, l));
          positive = positive || value >= 0;
          negative = negative || value <= 0;
          if (positive && negative) return false;
        }
    }
  return true;
}

// The hit on the part of patch that hull (the sub-patch over [u0, u1] x [v0, v1]) covers:
// Newton's method from the hits on the two triangles of the corner quadrilateral and from
// the middle; where none converges inside while the ray crosses the box, the four quarters
// in turn (Whitted's subdivision), at most `depth` more levels.
std::optional<PatchHit> hit_on(const BezierPatch& patch, const BezierPatch& h, double u0, double u1,
                               double v0, double v1, const Ray& ray, int depth,
                               const std::pair<Vec3d, Vec3d>& box) {
  const auto span = box_span(box.first, box.second, ray);
  if (!span || !crosses_slab(h, ray, *span)) return std::nullopt;
  const auto local = [&](double a, double b, double t) {
    return PatchHit{t, u0 + a * (u1 - u0), v0 + b * (v1 - v0)};
  };
  std::array<std::optional<PatchHit>, 3> starts;
  if (const auto g = triangle_guess(h.at(0, 0), h.at(3, 0), h.at(3, 3), ray))
    starts[0] = local((*g)[1] + (*g)[2], (*g)[2], (*g)[0]);
  if (const auto g = triangle_guess(h.at(0, 0), h.at(3, 3), h.at(0, 3), ray))
    starts[1] = local((*g)[1], (*g)[1] + (*g)[2], (*g)[0]);
  const Vec3d middle = h.point(0.5, 0.5);
  starts[2] = local(0.5, 0.5, dot(middle - ray.origin, ray.direction));
  std::optional<PatchHit> found;
  for (const auto& start : starts) {
    if (!start) continue;
    const auto hit = newton(patch, ray, *start, u0, u1, v0, v1);
    if (!hit || !within(hit->u, u0, u1) || !within(hit->v, v0, v1) || hit->t < ray.t_near ||
        hit->t > ray.t_far)
      continue;
    found = PatchHit{hit->t, std::clamp(hit->u, 0.0, 1.0), std::clamp(hit->v, 0.0, 1.0)};
    break;
  }
  // The first root found is the only one when the ray's direction d sees the whole piece
  // from one side: det(d, S_u, S_v) of one sign. S_u lies in the hull of the vectors
  // 3 (P_(i+1)j - P_ij) and S_v in that of 3 (P_i(j+1) - P_ij), and the determinant is
  // bilinear in the two, so its signs at the pairs of those vectors bound it.
  if (found && (depth == 0 || seen_from_one_side(h, ray.direction))) return found;
  if (depth == 0) return std::nullopt;
  std::optional<PatchHit> nearest = found;
  Ray segment = ray;
  if (found) segment.t_far = std::nextafter(found->t, ray.t_near);
  const double um = 0.5 * (u0 + u1), vm = 0.5 * (v0 + v1);
  const auto [low_u, high_u] = h.split(true);
  const std::array<std::pair<const BezierPatch*, std::array<double, 2>>, 2> halves{
      {{&low_u, {u0, um}}, {&high_u, {um, u1}}}};
  for (const auto& [half, us] : halves) {
    const auto [low_v, high_v] = half->split(false);
    for (const auto& [quarter, vs] : {std::pair{&low_v, std::array<double, 2>{v0, vm}},
                                      std::pair{&high_v, std::array<double, 2>{vm, v1}}})
      if (const auto hit = hit_on(patch, *quarter, us[0], us[1], vs[0], vs[1], segment, depth - 1,
                                  quarter->bounds())) {
        nearest = hit;
        segment.t_far = hit->t;
      }
  }
  return nearest;
}

}  // namespace

std::vector<PatchPiece> flat_pieces(const BezierPatch& patch, std::size_t patch_index,
                                    double relative_flatness) {
  std::vector<PatchPiece> pieces;
  cut(patch, 0, 1, 0, 1, 0, patch_index, relative_flatness, pieces);
  return pieces;
}

std::optional<PatchHit> intersect_piece(const BezierPatch& patch, const PatchPiece& piece,
                                        const Ray& ray) {
  return hit_on(patch, piece.hull, piece.u0, piece.u1, piece.v0, piece.v1, ray, kRetryDepth,
                {piece.low, piece.high});
}

std::optional<PatchHit> intersect_patch(const BezierPatch& patch,
                                        const std::vector<PatchPiece>& pieces, const Ray& ray) {
  std::optional<PatchHit> nearest;
  Ray segment = ray;
  for (const PatchPiece& piece : pieces)
    if (const auto hit = intersect_piece(patch, piece, segment)) {
      nearest = hit;
      segment.t_far = hit->t;
    }
  return nearest;
}

}  // namespace penumbra::raytrace
