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

// An arc of an ellipse along a ring, in drawing coordinates: the ring's points first..last
// lie on (p - centre)^T Q (p - centre) = 1, Q = {{form[0], form[1]}, {form[1], form[2]}}
// positive definite (last may be the ring's size: the arc ends at its first point).
struct EllipseArc {
  std::size_t first, last;
  Flat centre;
  std::array<double, 3> form;
};

struct Shape {
  std::vector<std::vector<Flat>> rings;
  std::string style;
  std::vector<std::vector<EllipseArc>> arcs{};  // per ring (or none): drawn as SVG arcs
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

// appends the filled polygons of a region ({"polygons": [...]}) in the given style. For a
// curved region (shadows --joint-umbrae: "axes", "arcs") under an affine projection, the
// arcs of ellipses are kept as such (EllipseArc), the other conics stay densified.
void add_region(FaceDrawing& drawing, const nlohmann::json& region, const std::string& style,
                const Projection& project, bool affine = false);

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
// writes them as paths, farthest first: each EllipseArc as an SVG elliptical arc ("A") when
// every point of the ring along it lies within 0.01 px of that ellipse, otherwise as lines.
void emit(std::ostream& out, std::vector<FaceDrawing> drawings, double x0, double y0, double width,
          double height, bool flip_y);

}  // namespace penumbra::io
