#pragma once
// Drawing faces of a document in SVG (private to io/): projections of world points, filled
// shapes per face, painter's order and fitting to the sheet. The shadow sheet
// (shadow_svg.cpp) and the sun-hours heat map (sun_hours_svg.cpp) draw with it.

#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "penumbra/base/vec3d.h"

namespace penumbra::io {

using Flat = std::array<double, 2>;

// A projection of world points to drawing coordinates (before fitting to the sheet);
// nullopt when a point cannot be drawn (behind the camera).
using Projection = std::function<std::optional<Flat>(const Vec3d&)>;

struct Shape {
  std::vector<std::vector<Flat>> rings;
  std::string style;
};

// a face's drawing: its outline and what is drawn on it.
struct FaceDrawing {
  double depth;  // drawn from largest to smallest
  std::vector<Shape> shapes;
  std::string layer{};  // drawn inside <g class="layer"> with the drawings next to it of that layer
};

// returns a ring of world points (JSON) projected, or nullopt when a point cannot be.
std::optional<std::vector<Flat>> project_ring(const nlohmann::json& ring,
                                              const Projection& project);

// appends the filled polygons of a region ({"polygons": [...]}) in the given style.
void add_region(FaceDrawing& drawing, const nlohmann::json& region, const std::string& style,
                const Projection& project);

// the plan view: (x, y).
Projection plan_projection();
// the depth of a face entry in the plan view: faces turned up, lowest first; nullopt for
// the others.
std::optional<double> plan_depth(const nlohmann::json& face);
// the projection onto a face entry's own frame (u, v).
Projection frame_projection(const nlohmann::json& face);

// The box around drawings (empty: min > max).
struct Bounds {
  double min_x = INFINITY, min_y = INFINITY, max_x = -INFINITY, max_y = -INFINITY;
};
Bounds bounds_of(const std::vector<FaceDrawing>& drawings);

// fits the drawings into a box of the given size (y up in the drawings, down in SVG) and
// writes them as paths, farthest first.
void emit(std::ostream& out, std::vector<FaceDrawing> drawings, double x0, double y0, double width,
          double height, bool flip_y);

}  // namespace penumbra::io
