#include "svg_drawing.h"

#include <algorithm>
#include <cmath>

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

void add_region(FaceDrawing& drawing, const json& region, const std::string& style,
                const Projection& project) {
  for (const auto& polygon : region.at("polygons")) {
    Shape shape{{}, style};
    const auto outer = project_ring(polygon.at("outer"), project);
    if (!outer) continue;
    shape.rings.push_back(*outer);
    for (const auto& hole : polygon.at("holes"))
      if (auto ring = project_ring(hole, project)) shape.rings.push_back(*ring);
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
      for (const auto& ring : shape.rings) {
        for (std::size_t k = 0; k < ring.size(); ++k) {
          const double x = x0 + (ring[k][0] - min_x) * scale;
          const double y =
              flip_y ? y0 + (max_y - ring[k][1]) * scale : y0 + (ring[k][1] - min_y) * scale;
          out << (k ? " L" : "M") << x << " " << y;
        }
        out << " Z ";
      }
      out << "\"/>\n";
    }
  }
  if (!layer.empty()) out << "</g>\n";
}

}  // namespace penumbra::io
