#pragma once
// Reads back the exact parts of a shadow JSON document written with exact = true
// (docs/shadows.md; io::shadow_json): per face entry its object, face number, plane and
// boundary, and per light its faces_away flag and its shadow and lit polygon sets, every
// coordinate from its "p/q" string. A face of a mesh part has the boundary
// {"outer": ring, "holes": [ring, ...]}; a face of a convex object (or of a convex closed
// part) the ring alone: both are read as a polygon with holes.

#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "penumbra/geometry/exact.h"

namespace penumbra::test {

// returns the exact value of "p/q" or "p". Both are read as integers and divided, so the
// quotient is in lowest terms whatever the text (the rational type's own parser keeps
// "3/6" as written, which its comparisons do not expect).
inline Exact parse_rational(const std::string& text) {
  const auto slash = text.find('/');
  if (slash == std::string::npos) return exact_number(Rational(text.c_str()));
  const std::string numerator = text.substr(0, slash), denominator = text.substr(slash + 1);
  return exact_number(Rational(numerator.c_str()) / Rational(denominator.c_str()));
}

inline Point3 parse_point(const nlohmann::json& xyz) {
  return Point3(parse_rational(xyz.at(0).get<std::string>()),
                parse_rational(xyz.at(1).get<std::string>()),
                parse_rational(xyz.at(2).get<std::string>()));
}

inline std::vector<Point3> parse_ring(const nlohmann::json& ring) {
  std::vector<Point3> points;
  for (const nlohmann::json& xyz : ring) points.push_back(parse_point(xyz));
  return points;
}

struct ExactPolygon {
  std::vector<Point3> outer;
  std::vector<std::vector<Point3>> holes;
};

// reads {"outer": ring, "holes": [ring, ...]}, or a bare ring.
inline ExactPolygon parse_polygon(const nlohmann::json& value) {
  if (value.is_array()) return {parse_ring(value), {}};
  ExactPolygon polygon{parse_ring(value.at("outer")), {}};
  for (const nlohmann::json& hole : value.at("holes")) polygon.holes.push_back(parse_ring(hole));
  return polygon;
}

struct LightEntry {
  std::string light;
  bool faces_away = false;
  std::vector<ExactPolygon> shadow, lit;
};

struct FaceEntry {
  std::string object;
  long face = -1;
  Plane3 plane;
  ExactPolygon boundary;
  const nlohmann::json* lights = nullptr;  // the entry's "lights", read by parse_lights
};

inline std::vector<ExactPolygon> parse_polygon_set(const nlohmann::json& set) {
  std::vector<ExactPolygon> polygons;
  for (const nlohmann::json& polygon : set.at("polygons"))
    polygons.push_back(parse_polygon(polygon.at("exact")));
  return polygons;
}

// reads an entry's face: its object, number, plane and boundary (its lights are read on
// demand: a large model has tens of thousands of entries, few of them sampled).
inline FaceEntry parse_face_entry(const nlohmann::json& entry) {
  FaceEntry face;
  face.object = entry.at("object").get<std::string>();
  face.face = entry.at("face").get<long>();
  const nlohmann::json& exact = entry.at("exact");
  std::array<Exact, 4> plane;
  for (std::size_t k = 0; k < 4; ++k)
    plane[k] = parse_rational(exact.at("plane").at(k).get<std::string>());
  face.plane = Plane3(plane[0], plane[1], plane[2], plane[3]);
  face.boundary = parse_polygon(exact.at("boundary"));
  face.lights = &entry.at("lights");
  return face;
}

// reads the entry's lights, leaving out those for which the face is beyond the sphere of
// lighting (no polygons).
inline std::vector<LightEntry> parse_lights(const FaceEntry& face) {
  std::vector<LightEntry> lights;
  for (const nlohmann::json& light : *face.lights) {
    if (light.value("beyond_range", false)) continue;
    LightEntry parsed;
    parsed.light = light.at("light").get<std::string>();
    parsed.faces_away = light.value("faces_away", false);
    parsed.shadow = parse_polygon_set(light.at("shadow"));
    parsed.lit = parse_polygon_set(light.at("lit"));
    lights.push_back(std::move(parsed));
  }
  return lights;
}

}  // namespace penumbra::test
