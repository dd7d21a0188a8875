#include "penumbra/io/shadow_json.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <vector>

#include "json_emitter.h"
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
  // An interval that is a point is the exact value (most areas and frame lengths of CAD
  // models are doubles): no exact evaluation needed.
  const auto& approx = x.approx();
  if (approx.is_point()) return approx.inf() + 0.0;
  return rounded(x.exact());
}

void emit_point(JsonEmitter& out, const RationalPoint3& p) {
  out.begin_array();
  for (int i = 0; i < 3; ++i) out.number(rounded(p[i]));
  out.end_array();
}
void emit_point(JsonEmitter& out, const Point3& p) {
  // A point given as doubles is its own rounding (most vertices of a scene are).
  const auto& approx = p.approx();
  if (!approx.x().is_point() || !approx.y().is_point() || !approx.z().is_point())
    return emit_point(out, CGAL::exact(p));
  out.begin_array();
  for (int i = 0; i < 3; ++i) out.number(approx[i].inf() + 0.0);
  out.end_array();
}
void emit_exact_point(JsonEmitter& out, const RationalPoint3& p) {
  out.begin_array();
  for (int i = 0; i < 3; ++i) out.string(rational_string(p[i]));
  out.end_array();
}

// the unit vector along v, rounded from v's exact coordinates.
void emit_unit(JsonEmitter& out, const Vector3& v) {
  const RationalVector3& exact = CGAL::exact(v);
  const double x = rounded(exact.x()), y = rounded(exact.y()), z = rounded(exact.z());
  const double length = std::sqrt(x * x + y * y + z * z);
  out.begin_array();
  for (double c : {x, y, z}) out.number(c / length + 0.0);
  out.end_array();
}

// A receiving face while it is written. Its shadow, umbra, lit holes and occluder polygons
// repeat the same points (the same lazy handles), each converted from frame to world
// coordinates in rationals: rounded holds each point's world doubles, computed once and
// across threads (a ground under a city has 10^5 of them), world maps a point's identity
// to its slot.
struct FaceOutput {
  const ReceivingFace& face;
  const Ring2& ring;  // the outer ring's points in the frame
  std::unordered_map<std::size_t, std::size_t> world;
  std::vector<std::array<double, 3>> rounded;
  std::unordered_map<const OccluderShadow*, double> occluder_area;  // m^2, computed alike
};

// the ring's points in the world: a face vertex as it is, any other point computed in
// rationals from its frame coordinates (no lazy construction made for output).
void emit_ring(JsonEmitter& out, const Ring2& ring, const FaceOutput& output, bool exact) {
  const ReceivingFace& face = output.face;
  out.begin_array();
  for (const Point2& p : ring) {
    const auto vertex = std::find_if(output.ring.begin(), output.ring.end(), [&](const Point2& q) {
      return CGAL::identical(p, q) || p == q;
    });
    if (vertex != output.ring.end()) {
      const Point3& world = face.outer[static_cast<std::size_t>(vertex - output.ring.begin())];
      if (exact)
        emit_exact_point(out, CGAL::exact(world));
      else
        emit_point(out, world);
      continue;
    }
    if (!exact) {
      if (const auto known = output.world.find(p.id()); known != output.world.end()) {
        out.begin_array();
        for (double x : output.rounded[known->second]) out.number(x);
        out.end_array();
        continue;
      }
    }
    const RationalPoint3 world = face.frame.to_world(CGAL::exact(p));
    if (exact)
      emit_exact_point(out, world);
    else
      emit_point(out, world);
  }
  out.end_array();
}

// a polygon's rings: {"holes": [...], "outer": [...]}.
void emit_rings(JsonEmitter& out, const Polygon2& polygon, const FaceOutput& face, bool exact) {
  out.key("holes");
  out.begin_array();
  for (const Ring2& hole : polygon.holes) emit_ring(out, hole, face, exact);
  out.end_array();
  out.key("outer");
  emit_ring(out, polygon.outer, face, exact);
}

void emit_region(JsonEmitter& out, const Region2& region, const FaceOutput& face, bool exact) {
  out.begin_object();
  out.key("area");
  out.number(world_area(region, face.face.frame));
  out.key("polygons");
  out.begin_array();
  for (const Polygon2& polygon : region.polygons) {
    out.begin_object();
    if (exact) {
      out.key("exact");
      out.begin_object();
      emit_rings(out, polygon, face, true);
      out.end_object();
    }
    emit_rings(out, polygon, face, false);
    out.end_object();
  }
  out.end_array();
  out.end_object();
}

// the plane scaled to a unit normal, in doubles; exactly, scaled so that its largest
// normal component has magnitude 1 (a canonical exact form).
void emit_plane(JsonEmitter& out, const Plane3& plane, bool exact) {
  out.begin_array();
  if (exact) {
    for (const Rational& k : canonical_plane(plane)) out.string(rational_string(k));
  } else {
    const RationalPlane3& rational = CGAL::exact(plane);
    const double a = rounded(rational.a()), b = rounded(rational.b()), c = rounded(rational.c()),
                 d = rounded(rational.d());
    const double length = std::sqrt(a * a + b * b + c * c);
    for (double k : {a, b, c, d}) out.number(k / length + 0.0);
  }
  out.end_array();
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

std::vector<const json*> boundary_rings(const json& face) {
  const json& boundary = face.at("boundary");
  if (boundary.is_array()) return {&boundary};
  std::vector<const json*> rings{&boundary.at("outer")};
  for (const json& hole : boundary.at("holes")) rings.push_back(&hole);
  return rings;
}

std::string format_json(const json& document) {
  std::string out;
  format(out, document, 0);
  return out + "\n";
}

double world_area(const Exact& area, const FaceFrame& frame) {
  const double uu = rounded(frame.squared_u());
  const double vv = rounded(frame.squared_v());
  return rounded(area) * std::sqrt(uu * vv);
}

double world_area(const Region2& region, const FaceFrame& frame) {
  return world_area(region.area, frame);
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

namespace {

// An occluder's entry; members in key order.
void emit_occluder(JsonEmitter& out, const Scene& scene, const OccluderShadow& occluder,
                   const FaceOutput& face, bool exact) {
  out.begin_object();
  out.key("area");
  const auto area = face.occluder_area.find(&occluder);
  out.number(area != face.occluder_area.end()
                 ? area->second
                 : world_area(convex_region(occluder.polygon), face.face.frame));
  const bool linear = occluder.linear_case.has_value();
  if (linear) {
    out.key("case");
    out.string(*occluder.linear_case == LinearCase::A ? "A" : "B");
  }
  // Linear sources: the occluder's umbra, its App. A2 case, and the raw loops of section
  // 4.1.2 (absent in the object-space case).
  const auto emit_umbra = [&](bool rationals) {
    if (occluder.umbra) {
      emit_ring(out, *occluder.umbra, face, rationals);
    } else {
      out.begin_array();
      out.end_array();
    }
  };
  if (exact) {
    out.key("exact");
    out.begin_object();
    if (linear) {
      out.key("penumbra_loop");
      emit_ring(out, occluder.penumbra_loop, face, true);
    }
    out.key("polygon");
    emit_ring(out, occluder.polygon, face, true);
    if (linear) {
      out.key("umbra");
      emit_umbra(true);
      out.key("umbra_loop");
      emit_ring(out, occluder.umbra_loop, face, true);
    }
    out.end_object();
  }
  out.key("object");
  out.string(scene.objects[occluder.occluder].name);
  if (linear) {
    out.key("object_space");
    out.boolean(occluder.object_space);
    out.key("penumbra_loop");
    emit_ring(out, occluder.penumbra_loop, face, false);
  }
  out.key("polygon");
  emit_ring(out, occluder.polygon, face, false);
  if (linear) {
    out.key("umbra");
    emit_umbra(false);
    out.key("umbra_loop");
    emit_ring(out, occluder.umbra_loop, face, false);
  }
  out.end_object();
}

// A light's entry for one face; members in key order.
void emit_light(JsonEmitter& out, const std::string& name, const FaceShadow& shadow,
                const Scene& scene, const FaceOutput& face, bool exact) {
  out.begin_object();
  if (shadow.beyond_range) {
    out.key("beyond_range");
    out.boolean(true);
  }
  out.key("faces_away");
  out.boolean(shadow.faces_away);
  out.key("joint_occlusion");
  out.boolean(shadow.joint_occlusion);
  out.key("light");
  out.string(name);
  if (shadow.beyond_range) {
    out.end_object();
    return;
  }
  out.key("lit");
  emit_region(out, shadow.lit, face, exact);
  out.key("occluders");
  out.begin_array();
  for (const OccluderShadow& occluder : shadow.occluders)
    emit_occluder(out, scene, occluder, face, exact);
  out.end_array();
  out.key("penumbra");
  if (shadow.linear) {
    emit_region(out, shadow.penumbra, face, exact);
  } else {  // point and directional sources: no penumbra
    emit_region(out, Region2{}, face, false);
  }
  out.key("shadow");
  emit_region(out, shadow.shadow, face, exact);
  if (shadow.linear) {
    out.key("source_clipped");
    out.boolean(shadow.source_clipped);
  }
  out.key("umbra");
  emit_region(out, shadow.linear ? shadow.umbra : shadow.shadow, face, exact);
  out.end_object();
}

// a world ring of exact points.
void emit_world_ring(JsonEmitter& out, const std::vector<Point3>& ring, bool exact) {
  out.begin_array();
  for (const Point3& p : ring)
    if (exact)
      emit_exact_point(out, CGAL::exact(p));
    else
      emit_point(out, p);
  out.end_array();
}

// the face's boundary: its ring, or for a face of a mesh part {"holes": [...], "outer": [...]}.
void emit_boundary(JsonEmitter& out, const ReceivingFace& face, bool exact) {
  if (!face.holes) {
    emit_world_ring(out, face.outer, exact);
    return;
  }
  out.begin_object();
  out.key("holes");
  out.begin_array();
  for (const auto& hole : *face.holes) emit_world_ring(out, hole, exact);
  out.end_array();
  out.key("outer");
  emit_world_ring(out, face.outer, exact);
  out.end_object();
}

// the fewest occluders for which a face's world points and areas are computed ahead.
constexpr std::size_t kCachedOccluders = 32;

// returns the face ready to be written: the world doubles of every point of its shadows.
FaceOutput prepare_output(const ReceivingFace& face, const ShadowResult& result, std::size_t r) {
  FaceOutput output{face, face.ring, {}, {}, {}};
  // Worth it only for a face under many shadows; a small face writes its points directly.
  std::size_t occluder_count = 0;
  for (const LightShadows& light : result.lights) occluder_count += light.faces[r].occluders.size();
  if (occluder_count < kCachedOccluders) return output;
  std::vector<const Point2*> points;
  std::vector<const OccluderShadow*> occluders;
  const auto add_ring = [&](const Ring2& ring) {
    for (const Point2& p : ring)
      if (output.world.emplace(p.id(), points.size()).second) points.push_back(&p);
  };
  const auto add_region = [&](const Region2& region) {
    for (const Polygon2& polygon : region.polygons) {
      add_ring(polygon.outer);
      for (const Ring2& hole : polygon.holes) add_ring(hole);
    }
  };
  for (const LightShadows& light : result.lights) {
    const FaceShadow& shadow = light.faces[r];
    for (const Region2* region : {&shadow.shadow, &shadow.umbra, &shadow.penumbra, &shadow.lit})
      add_region(*region);
    for (const OccluderShadow& occluder : shadow.occluders) {
      add_ring(occluder.polygon);
      occluders.push_back(&occluder);
    }
  }
  std::vector<double> areas(occluders.size());
  for_each_index(
      occluders.size(), occluders.size() > 64,
      [&](std::size_t k) {
        areas[k] = world_area(convex_region(occluders[k]->polygon), face.frame);
      },
      16);
  for (std::size_t k = 0; k < occluders.size(); ++k) output.occluder_area[occluders[k]] = areas[k];
  output.rounded.resize(points.size());
  for_each_index(
      points.size(), points.size() > 256,
      [&](std::size_t k) {
        const RationalPoint3 world = face.frame.to_world(CGAL::exact(*points[k]));
        for (int i = 0; i < 3; ++i) output.rounded[k][i] = rounded(world[i]);
      },
      64);
  return output;
}

// The entry of "faces" for receiver r; members in key order.
void emit_face(JsonEmitter& out, const Scene& scene, const ShadowResult& result, std::size_t r,
               const ShadowJsonOptions& options) {
  const ReceivingFace face = receiving_face(scene, result, r);
  const FaceOutput output = prepare_output(face, result, r);
  out.begin_object();
  out.key("area");
  out.number(world_area(face.area, face.frame));
  out.key("boundary");
  emit_boundary(out, face, false);
  if (options.exact) {
    out.key("exact");
    out.begin_object();
    out.key("boundary");
    emit_boundary(out, face, true);
    out.key("plane");
    emit_plane(out, face.plane, true);
    out.end_object();
  }
  out.key("face");
  out.integer(face.face);
  out.key("frame");
  out.begin_object();
  out.key("origin");
  emit_point(out, face.frame.origin());
  out.key("u");
  emit_unit(out, face.frame.u());
  out.key("v");
  emit_unit(out, face.frame.v());
  out.end_object();
  out.key("lights");
  out.begin_array();
  for (const LightShadows& shadows : result.lights)
    emit_light(out, scene.lights[shadows.light].name, shadows.faces[r], scene, output,
               options.exact);
  out.end_array();
  out.key("object");
  out.string(face.object);
  out.key("plane");
  emit_plane(out, face.plane, false);
  out.end_object();
}

}  // namespace

json shadow_face_json(const Scene& scene, const ShadowResult& result, std::size_t r,
                      const ShadowJsonOptions& options) {
  TreeEmitter tree;
  emit_face(tree, scene, result, r, options);
  return std::move(tree.result());
}

std::string shadow_face_text(const Scene& scene, const ShadowResult& result, std::size_t r,
                             const ShadowJsonOptions& options, int depth) {
  std::string text;
  TextEmitter emitter(text, depth);
  emit_face(emitter, scene, result, r, options);
  return text;
}

json shadow_json(const Scene& scene, const ShadowResult& result, const ShadowJsonOptions& options) {
  json document = shadow_header_json(scene, result, options);
  json faces = json::array();
  for (std::size_t r = 0; r < result.receivers.size(); ++r)
    faces.push_back(shadow_face_json(scene, result, r, options));
  document["faces"] = std::move(faces);
  return document;
}

const std::vector<json>& ShadowFaceBlock::entries() const {
  if (!entries_) {
    entries_.emplace(size_);
    for_each_index(size_, true, [&](std::size_t k) {
      (*entries_)[k] = shadow_face_json(scene_, result_, first_ + k, options_);
    });
  }
  return *entries_;
}

const std::vector<std::string>& ShadowFaceBlock::texts() const {
  if (!texts_) {
    texts_.emplace(size_);
    for_each_index(size_, true, [&](std::size_t k) {
      (*texts_)[k] = shadow_face_text(scene_, result_, first_ + k, options_, 2);
    });
  }
  return *texts_;
}

void stream_shadow_document(const Scene& scene, const ShadowResult& result,
                            const ShadowJsonOptions& options,
                            const std::vector<ShadowDocumentSink*>& sinks) {
  const json header = shadow_header_json(scene, result, options);
  const std::size_t count = result.receivers.size();
  for (ShadowDocumentSink* sink : sinks) sink->begin(header, count);
  constexpr std::size_t block = 2048;
  for (std::size_t first = 0; first < count; first += block) {
    const ShadowFaceBlock faces(scene, result, options, first, std::min(block, count - first));
    for (ShadowDocumentSink* sink : sinks) sink->faces(faces);
  }
  for (ShadowDocumentSink* sink : sinks) sink->end();
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

void ShadowJsonWriter::faces(const ShadowFaceBlock& block) {
  for (const std::string& text : block.texts())
    out_ << "  " << text << (++written_ < faces_ ? ",\n" : "\n ]");
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
