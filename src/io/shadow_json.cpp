#include "penumbra/io/shadow_json.h"

#include <cmath>

#include "penumbra/base/parallel.h"
#include "penumbra/io/rational.h"

namespace penumbra::io {
namespace {

using nlohmann::json;

// rounds from the exact value, never from the lazy kernel's interval, whose width
// depends on what was evaluated before (and so on threads); adding +0.0 turns -0.0
// into 0.0, so that equal points print alike.
double rounded(const Rational& x) {
  return CGAL::to_double(x) + 0.0;
}
double rounded(const Exact& x) {
  return rounded(x.exact());
}

json point_json(const RationalPoint3& p) {
  return json::array({rounded(p.x()), rounded(p.y()), rounded(p.z())});
}
json point_json(const Point3& p) {
  return point_json(CGAL::exact(p));
}

// the unit vector along v, rounded from v's exact coordinates.
json unit_json(const Vector3& v) {
  const RationalVector3& exact = CGAL::exact(v);
  const double x = rounded(exact.x()), y = rounded(exact.y()), z = rounded(exact.z());
  const double length = std::sqrt(x * x + y * y + z * z);
  return json::array({x / length + 0.0, y / length + 0.0, z / length + 0.0});
}

json exact_point_json(const RationalPoint3& p) {
  return json::array({rational_string(p.x()), rational_string(p.y()), rational_string(p.z())});
}

// the ring's points in the world, computed in rationals from the frame coordinates (no
// lazy construction made for output).
json ring_json(const Ring2& ring, const Face& face, bool exact) {
  json points = json::array();
  for (const Point2& p : ring) {
    const RationalPoint3 world = face.frame.to_world(CGAL::exact(p));
    points.push_back(exact ? exact_point_json(world) : point_json(world));
  }
  return points;
}

json region_json(const Region2& region, const Face& face, bool exact) {
  json polygons = json::array();
  for (const Polygon2& polygon : region.polygons) {
    json entry = {{"outer", ring_json(polygon.outer, face, false)}, {"holes", json::array()}};
    for (const Ring2& hole : polygon.holes) entry["holes"].push_back(ring_json(hole, face, false));
    if (exact) {
      json rationals = {{"outer", ring_json(polygon.outer, face, true)}, {"holes", json::array()}};
      for (const Ring2& hole : polygon.holes)
        rationals["holes"].push_back(ring_json(hole, face, true));
      entry["exact"] = std::move(rationals);
    }
    polygons.push_back(std::move(entry));
  }
  return {{"area", world_area(region, face)}, {"polygons", std::move(polygons)}};
}

// the plane scaled to a unit normal, in doubles; exactly, scaled so that its largest
// normal component has magnitude 1 (a canonical exact form).
json plane_json(const Plane3& plane, bool exact) {
  if (exact) {
    json coefficients = json::array();
    for (const Rational& k : canonical_plane(plane)) coefficients.push_back(rational_string(k));
    return coefficients;
  }
  const RationalPlane3& rational = CGAL::exact(plane);
  const double a = rounded(rational.a()), b = rounded(rational.b()), c = rounded(rational.c()),
               d = rounded(rational.d());
  const double length = std::sqrt(a * a + b * b + c * c);
  return json::array({a / length + 0.0, b / length + 0.0, c / length + 0.0, d / length + 0.0});
}

const char* kind_of(const Light& light) {
  if (std::holds_alternative<PointLight>(light.source)) return "point";
  if (std::holds_alternative<LinearLight>(light.source)) return "linear";
  return "directional";
}

bool holds_objects(const json& node) {
  if (node.is_object()) return true;
  if (node.is_array())
    for (const json& item : node)
      if (holds_objects(item)) return true;
  return false;
}

void format(std::string& out, const json& node, int depth) {
  const std::string indent(static_cast<std::size_t>(depth) + 1, ' ');
  const std::string closing(static_cast<std::size_t>(depth), ' ');
  if (node.is_object() && !node.empty()) {
    out += "{\n";
    std::size_t k = 0;
    for (const auto& [key, value] : node.items()) {
      out += indent + json(key).dump() + ": ";
      format(out, value, depth + 1);
      out += ++k < node.size() ? ",\n" : "\n";
    }
    out += closing + "}";
  } else if (node.is_array() && holds_objects(node)) {
    out += "[\n";
    for (std::size_t k = 0; k < node.size(); ++k) {
      out += indent;
      format(out, node[k], depth + 1);
      out += k + 1 < node.size() ? ",\n" : "\n";
    }
    out += closing + "]";
  } else {
    out += node.dump();
  }
}

}  // namespace

// writes one member "key": value of an object at depth, as format() does.
void format_member(std::string& out, const std::string& key, const json& value, int depth) {
  out += std::string(static_cast<std::size_t>(depth) + 1, ' ') + json(key).dump() + ": ";
  format(out, value, depth + 1);
}

std::string format_json(const json& document) {
  std::string out;
  format(out, document, 0);
  return out + "\n";
}

double world_area(const Region2& region, const Face& face) {
  const double uu = CGAL::to_double(face.frame.squared_u());
  const double vv = CGAL::to_double(face.frame.squared_v());
  return rounded(region.area) * std::sqrt(uu * vv);
}

json shadow_header_json(const Scene& scene, const ShadowResult& result,
                        const ShadowJsonOptions& options) {
  json document = {{"penumbra_shadows", 1}};
  json culling = {{"range_fraction", options.range_fraction},
                  {"full_scale_lux", options.full_scale_lux}};
  if (options.range_lux) culling = {{"range_lux", *options.range_lux}};
  document["culling"] = culling;

  json lights = json::array();
  for (const LightShadows& shadows : result.lights) {
    const ShadowStats& stats = shadows.stats;
    json entry = {{"name", scene.lights[shadows.light].name},
                  {"kind", kind_of(scene.lights[shadows.light])},
                  {"faces", stats.faces},
                  {"faces_away", stats.faces_away},
                  {"beyond_range", stats.beyond_range},
                  {"pairs_possible", stats.pairs_possible},
                  {"pairs_tested", stats.pairs_tested},
                  {"pairs_shadowing", stats.pairs_shadowing}};
    if (stats.radius) entry["sphere_of_lighting_radius"] = *stats.radius;
    lights.push_back(std::move(entry));
  }
  document["lights"] = std::move(lights);

  return document;
}

json shadow_face_json(const Scene& scene, const ShadowResult& result, std::size_t r,
                      const ShadowJsonOptions& options) {
  const Object& object = scene.objects[result.receivers[r].object];
  const Face& face = object.solid.faces()[result.receivers[r].face];
  const Ring2 ring = face_ring(face);
  json entry = {{"object", object.name},
                {"face", result.receivers[r].face},
                {"plane", plane_json(face.plane, false)},
                {"frame",
                 {{"origin", point_json(face.frame.origin())},
                  {"u", unit_json(face.frame.u())},
                  {"v", unit_json(face.frame.v())}}},
                {"boundary", ring_json(ring, face, false)},
                {"area", world_area(convex_region(ring), face)}};
  if (options.exact)
    entry["exact"] = {{"plane", plane_json(face.plane, true)},
                      {"boundary", ring_json(ring, face, true)}};
  json per_light = json::array();
  for (const LightShadows& shadows : result.lights) {
    const FaceShadow& shadow = shadows.faces[r];
    json item = {{"light", scene.lights[shadows.light].name},
                 {"faces_away", shadow.faces_away},
                 {"joint_occlusion", shadow.joint_occlusion}};
    if (shadow.beyond_range) {
      item["beyond_range"] = true;
      per_light.push_back(std::move(item));
      continue;
    }
    item["shadow"] = region_json(shadow.shadow, face, options.exact);
    if (shadow.linear) {
      item["source_clipped"] = shadow.source_clipped;
      item["umbra"] = region_json(shadow.umbra, face, options.exact);
      item["penumbra"] = region_json(shadow.penumbra, face, options.exact);
    } else {
      item["umbra"] = item["shadow"];
      item["penumbra"] = {{"area", 0.0}, {"polygons", json::array()}};
    }
    item["lit"] = region_json(shadow.lit, face, options.exact);
    json occluders = json::array();
    for (const OccluderShadow& occluder : shadow.occluders) {
      json o = {{"object", scene.objects[occluder.occluder].name},
                {"polygon", ring_json(occluder.polygon, face, false)},
                {"area", world_area(convex_region(occluder.polygon), face)}};
      json exact;
      if (options.exact) exact["polygon"] = ring_json(occluder.polygon, face, true);
      if (occluder.linear_case) {
        // Linear sources: the occluder's umbra, its App. A2 case, and the raw loops
        // of section 4.1.2 (absent in the object-space case).
        o["case"] = *occluder.linear_case == LinearCase::A ? "A" : "B";
        o["object_space"] = occluder.object_space;
        o["umbra"] = occluder.umbra ? ring_json(*occluder.umbra, face, false) : json::array();
        o["penumbra_loop"] = ring_json(occluder.penumbra_loop, face, false);
        o["umbra_loop"] = ring_json(occluder.umbra_loop, face, false);
        if (options.exact) {
          exact["umbra"] = occluder.umbra ? ring_json(*occluder.umbra, face, true) : json::array();
          exact["penumbra_loop"] = ring_json(occluder.penumbra_loop, face, true);
          exact["umbra_loop"] = ring_json(occluder.umbra_loop, face, true);
        }
      }
      if (options.exact) o["exact"] = std::move(exact);
      occluders.push_back(std::move(o));
    }
    item["occluders"] = std::move(occluders);
    per_light.push_back(std::move(item));
  }
  entry["lights"] = std::move(per_light);
  return entry;
}

json shadow_json(const Scene& scene, const ShadowResult& result, const ShadowJsonOptions& options) {
  json document = shadow_header_json(scene, result, options);
  json faces = json::array();
  for (std::size_t r = 0; r < result.receivers.size(); ++r)
    faces.push_back(shadow_face_json(scene, result, r, options));
  document["faces"] = std::move(faces);
  return document;
}

void stream_shadow_document(const Scene& scene, const ShadowResult& result,
                            const ShadowJsonOptions& options,
                            const std::vector<ShadowDocumentSink*>& sinks) {
  const json header = shadow_header_json(scene, result, options);
  const std::size_t count = result.receivers.size();
  for (ShadowDocumentSink* sink : sinks) sink->begin(header, count);
  // A block of faces at a time: built across threads, handed over in order.
  constexpr std::size_t block = 2048;
  std::vector<json> entries;
  for (std::size_t first = 0; first < count; first += block) {
    const std::size_t size = std::min(block, count - first);
    entries.assign(size, json());
    for_each_index(size, true, [&](std::size_t k) {
      entries[k] = shadow_face_json(scene, result, first + k, options);
    });
    for (const json& entry : entries)
      for (ShadowDocumentSink* sink : sinks) sink->face(entry);
  }
  for (ShadowDocumentSink* sink : sinks) sink->end();
}

void feed_shadow_document(ShadowDocumentSink& sink, const json& document) {
  json header = document;
  header.erase("faces");
  const json& faces = document.at("faces");
  sink.begin(header, faces.size());
  for (const json& face : faces) sink.face(face);
  sink.end();
}

// The document is an object whose keys sort as "culling" < "faces" < "lights" <
// "penumbra_shadows" (nlohmann::json keeps them sorted): the members before "faces" are
// written at begin(), the faces as they come, the rest at end().
void ShadowJsonWriter::begin(const json& header, std::size_t faces) {
  faces_ = faces;
  std::string text = "{\n";
  for (const auto& [key, value] : header.items()) {
    if (key > "faces") {
      after_faces_[key] = value;
      continue;
    }
    format_member(text, key, value, 0);
    text += ",\n";
  }
  text += " \"faces\": ";
  text += faces == 0 ? "[]" : "[\n";
  out_ << text;
}

void ShadowJsonWriter::face(const json& entry) {
  std::string text = "  ";
  format(text, entry, 2);
  text += ++written_ < faces_ ? ",\n" : "\n ]";
  out_ << text;
}

void ShadowJsonWriter::end() {
  std::string text;
  for (const auto& [key, value] : after_faces_.items()) {
    text += ",\n";
    format_member(text, key, value, 0);
  }
  out_ << text << "\n}\n";
}

}  // namespace penumbra::io
