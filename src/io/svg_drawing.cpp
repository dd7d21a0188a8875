#include "svg_drawing.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <gmpxx.h>

#include "penumbra/io/shadow_json.h"
#include "svg_text.h"

namespace penumbra::io {

using nlohmann::json;
using namespace vector_ops;

std::optional<std::vector<Flat>> project_ring(const json& ring, const Projection& project) {
  std::vector<Flat> out;
  for (const auto& point : ring) {
    const auto p = project(point.get<Vec3d>());
    if (!p) return std::nullopt;
    out.push_back(*p);
  }
  return out;
}

namespace {

// a "p/q" string as a double, truncated (GMP: p and q of any size).
double rational_value(const json& x) {
  return mpq_class(x.get<std::string>()).get_d();
}

// The map from a curved region's frame (s, t) to drawing coordinates under an affine
// projection: f(s, t) = origin + s m[0] + t m[1].
struct FrameMap {
  Flat origin;
  std::array<Flat, 2> m;
};

std::optional<FrameMap> frame_map(const json& axes, const Projection& project) {
  Vec3d origin, u, v;
  for (int k = 0; k < 3; ++k) {
    origin[k] = rational_value(axes.at("origin")[k]);
    u[k] = rational_value(axes.at("u")[k]);
    v[k] = rational_value(axes.at("v")[k]);
  }
  const auto o = project(origin), a = project(origin + u), b = project(origin + v);
  if (!o || !a || !b) return std::nullopt;
  return FrameMap{
      *o, {Flat{(*a)[0] - (*o)[0], (*a)[1] - (*o)[1]}, Flat{(*b)[0] - (*o)[0], (*b)[1] - (*o)[1]}}};
}

// the arc's conic a s^2 + b s t + c t^2 + d s + e t + f = 0 as an ellipse in drawing
// coordinates; nullopt for the other conics (and lines).
std::optional<EllipseArc> ellipse_of(const json& arc, const FrameMap& map) {
  std::array<double, 6> k;
  for (int i = 0; i < 6; ++i) k[i] = rational_value(arc.at("conic")[i]);
  const auto [a, b, c, d, e, f] = k;
  const double det = 4 * a * c - b * b;
  if (!(det > 0)) return std::nullopt;  // not an ellipse (or a line)
  // centre: grad = 0; then (p - centre)^T K (p - centre) = -F(centre), K = [[a, b/2], [b/2, c]]
  const double cs = (b * e - 2 * c * d) / det, ct = (b * d - 2 * a * e) / det;
  const double value = a * cs * cs + b * cs * ct + c * ct * ct + d * cs + e * ct + f;
  if (!(a * value < 0)) return std::nullopt;  // K / -value not positive definite: no curve
  // in drawing coordinates q = origin + M p: Q = M^-T (K / -value) M^-1
  const auto& [m0, m1] = map.m;
  const double jac = m0[0] * m1[1] - m1[0] * m0[1];
  if (jac == 0) return std::nullopt;
  // M^-1 = [[m1y, -m1x], [-m0y, m0x]] / jac
  const double i00 = m1[1] / jac, i01 = -m1[0] / jac, i10 = -m0[1] / jac, i11 = m0[0] / jac;
  const double k00 = a / -value, k01 = b / 2 / -value, k11 = c / -value;
  const auto form = [&](double x0, double x1, double y0, double y1) {  // x^T K y, columns of M^-1
    return x0 * (k00 * y0 + k01 * y1) + x1 * (k01 * y0 + k11 * y1);
  };
  EllipseArc ellipse{
      arc.at("first").get<std::size_t>(),
      arc.at("last").get<std::size_t>(),
      Flat{map.origin[0] + m0[0] * cs + m1[0] * ct, map.origin[1] + m0[1] * cs + m1[1] * ct},
      {form(i00, i10, i00, i10), form(i00, i10, i01, i11), form(i01, i11, i01, i11)}};
  return ellipse;
}

std::vector<EllipseArc> ellipses_of(const json& arcs, const FrameMap& map) {
  std::vector<EllipseArc> result;
  for (const auto& arc : arcs)
    if (auto ellipse = ellipse_of(arc, map)) result.push_back(*ellipse);
  return result;
}

}  // namespace

void add_region(FaceDrawing& drawing, const json& region, const std::string& style,
                const Projection& project, bool affine) {
  std::optional<FrameMap> map;
  if (affine && region.contains("axes")) map = frame_map(region.at("axes"), project);
  for (const auto& polygon : region.at("polygons")) {
    Shape shape{{}, style};
    const auto outer = project_ring(polygon.at("outer"), project);
    if (!outer) continue;
    shape.rings.push_back(*outer);
    if (map) shape.arcs.push_back(ellipses_of(polygon.at("arcs"), *map));
    const auto& holes = polygon.at("holes");
    for (std::size_t h = 0; h < holes.size(); ++h)
      if (auto ring = project_ring(holes[h], project)) {
        shape.rings.push_back(*ring);
        if (map) shape.arcs.push_back(ellipses_of(polygon.at("hole_arcs")[h], *map));
      }
    drawing.shapes.push_back(std::move(shape));
  }
}

Projection plan_projection() {
  return [](const Vec3d& p) -> std::optional<Flat> { return Flat{p[0], p[1]}; };
}

std::optional<double> plan_depth(const json& face) {
  if (face.at("plane")[2].get<double>() <= 0) return std::nullopt;
  double top = -INFINITY;
  for (const auto& p : *boundary_rings(face).front()) top = std::max(top, p[2].get<double>());
  return -top;
}

Projection frame_projection(const json& face) {
  const Vec3d origin = face.at("frame").at("origin").get<Vec3d>();
  const Vec3d u = face.at("frame").at("u").get<Vec3d>(), v = face.at("frame").at("v").get<Vec3d>();
  return [=](const Vec3d& p) -> std::optional<Flat> {
    return Flat{dot(p - origin, u), dot(p - origin, v)};
  };
}

Bounds bounds_of(const std::vector<FaceDrawing>& drawings) {
  Bounds b;
  for (const auto& drawing : drawings)
    for (const auto& shape : drawing.shapes)
      for (const auto& ring : shape.rings)
        for (const Flat& p : ring) {
          b.min_x = std::min(b.min_x, p[0]), b.max_x = std::max(b.max_x, p[0]);
          b.min_y = std::min(b.min_y, p[1]), b.max_y = std::max(b.max_y, p[1]);
        }
  return b;
}

namespace {

// the SVG arc command from ring[arc.first] to ring[arc.last] along the ellipse, or nullopt
// when a point of the ring on the way lies farther than 0.01 px from it (doubles lost the
// conic: draw lines).
std::optional<std::string> svg_arc(const std::vector<Flat>& ring, const EllipseArc& arc) {
  const auto [p, r, q] = arc.form;
  double turned = 0;  // the angle swept around the centre, positive from +x toward +y
  for (std::size_t k = arc.first; k <= arc.last; ++k) {
    const Flat& a = ring[k % ring.size()];
    const double x = a[0] - arc.centre[0], y = a[1] - arc.centre[1];
    // distance to the ellipse, to first order: |g| / |grad g|, g = x^T Q x - 1
    const double g = p * x * x + 2 * r * x * y + q * y * y - 1;
    const double gx = 2 * (p * x + r * y), gy = 2 * (r * x + q * y);
    if (!(std::abs(g) <= 0.01 * std::hypot(gx, gy))) return std::nullopt;
    if (k == arc.first) continue;
    const Flat& b = ring[(k - 1) % ring.size()];
    const double bx = b[0] - arc.centre[0], by = b[1] - arc.centre[1];
    turned += std::atan2(bx * y - by * x, bx * x + by * y);
  }
  // the axes: eigenvalues of Q; the larger one's eigenvector at half atan2(2r, p - q)
  const double mean = (p + q) / 2, spread = std::hypot((p - q) / 2, r);
  const double large = mean + spread, small = mean - spread;
  if (!(small > 0)) return std::nullopt;
  const double angle = 0.5 * std::atan2(2 * r, p - q) * 180 / M_PI;
  const Flat& end = ring[arc.last % ring.size()];
  std::ostringstream text;
  text << std::setprecision(9) << " A" << 1 / std::sqrt(large) << " " << 1 / std::sqrt(small) << " "
       << angle << " " << (std::abs(turned) > M_PI ? 1 : 0) << " " << (turned > 0 ? 1 : 0) << " "
       << end[0] << " " << end[1];
  return text.str();
}

// writes a ring as a closed path: lines, and the arcs of ellipses that svg_arc can draw.
void write_ring(std::ostream& out, const std::vector<Flat>& ring,
                const std::vector<EllipseArc>& arcs) {
  if (ring.empty()) return;
  std::vector<const EllipseArc*> starting(ring.size(), nullptr);
  for (const EllipseArc& arc : arcs)
    if (arc.last > arc.first && arc.last <= ring.size()) starting[arc.first] = &arc;
  out << "M" << ring[0][0] << " " << ring[0][1];
  for (std::size_t k = 0; k < ring.size();) {
    if (starting[k])
      if (const auto drawn = svg_arc(ring, *starting[k])) {
        out << *drawn;
        k = starting[k]->last;
        continue;
      }
    if (++k < ring.size()) out << " L" << ring[k][0] << " " << ring[k][1];
  }
  out << " Z ";
}

}  // namespace

void emit(std::ostream& out, std::vector<FaceDrawing> drawings, double x0, double y0, double width,
          double height, bool flip_y) {
  const auto [min_x, min_y, max_x, max_y] = bounds_of(drawings);
  if (!(max_x >= min_x)) return;
  const double scale =
      std::min(width / std::max(max_x - min_x, 1e-9), height / std::max(max_y - min_y, 1e-9));
  std::stable_sort(drawings.begin(), drawings.end(),
                   [](const FaceDrawing& a, const FaceDrawing& b) { return a.depth > b.depth; });
  std::string layer;
  for (const auto& drawing : drawings) {
    if (drawing.layer != layer) {
      if (!layer.empty()) out << "</g>\n";
      layer = drawing.layer;
      if (!layer.empty()) out << "<g class=\"" << escape_xml(layer) << "\">\n";
    }
    for (const auto& shape : drawing.shapes) {
      out << "<path " << shape.style << " d=\"";
      for (std::size_t r = 0; r < shape.rings.size(); ++r) {
        std::vector<Flat> ring;
        for (const Flat& p : shape.rings[r])
          ring.push_back({x0 + (p[0] - min_x) * scale,
                          flip_y ? y0 + (max_y - p[1]) * scale : y0 + (p[1] - min_y) * scale});
        std::vector<EllipseArc> arcs;
        if (r < shape.arcs.size())
          for (EllipseArc arc : shape.arcs[r]) {
            // the sheet's map: q = (x0, y0) + scale (p - corner), y mirrored when flip_y
            const double sign = flip_y ? -1 : 1;
            arc.centre = {x0 + (arc.centre[0] - min_x) * scale,
                          flip_y ? y0 + (max_y - arc.centre[1]) * scale
                                 : y0 + (arc.centre[1] - min_y) * scale};
            arc.form = {arc.form[0] / (scale * scale), sign * arc.form[1] / (scale * scale),
                        arc.form[2] / (scale * scale)};
            arcs.push_back(arc);
          }
        write_ring(out, ring, arcs);
      }
      out << "\"/>\n";
    }
  }
  if (!layer.empty()) out << "</g>\n";
}

}  // namespace penumbra::io
