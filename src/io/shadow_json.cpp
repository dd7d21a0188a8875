#include "penumbra/io/shadow_json.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <vector>

#include "face_json.h"
#include "json_emitter.h"
#include "penumbra/base/parallel.h"
#include "penumbra/geometry/exact.h"
#include "penumbra/io/rational.h"

namespace penumbra::io {
namespace {

using nlohmann::json;

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

double world_area(double frame_area, const FaceFrame& frame) {
  const double uu = rounded(frame.squared_u());
  const double vv = rounded(frame.squared_v());
  return frame_area * std::sqrt(uu * vv);
}

double world_area(const Exact& area, const FaceFrame& frame) {
  return world_area(rounded(area), frame);
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
  if (options.joint_umbrae) document["joint_umbrae"] = true;

  json lights = json::array();
  for (const LightShadows& shadows : result.lights) {
    const ShadowStats& stats = shadows.stats;
    json entry = {{"name", scene.lights[shadows.light].name},
                  {"kind", kind_name(scene.lights[shadows.light])},
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
  // Bézier patch objects are seen through their tessellation (docs/bezier-patches.md): the
  // boundaries on and of them are the tessellation's.
  if (!scene.tessellated.empty()) {
    json tessellated = json::array();
    for (const TessellatedPatches& record : scene.tessellated)
      tessellated.push_back({{"object", record.name},
                             {"patches", record.patches},
                             {"triangles", record.triangles},
                             {"tolerance", record.tolerance}});
    document["tessellated"] = std::move(tessellated);
  }
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
  if (shadow.curved) {
    const auto polygons =
        exact ? shadow.curved->exact_penumbra_polygons() : std::vector<ExactCurvedPolygon>{};
    emit_curved_region(out, shadow.curved->penumbra_polygons(), shadow.curved->penumbra_area(),
                       face, exact ? &polygons : nullptr);
  } else if (shadow.extended) {
    emit_region(out, shadow.penumbra, face, exact);
  } else {  // point and directional sources: no penumbra
    emit_region(out, Region2{}, face, false);
  }
  out.key("shadow");
  emit_region(out, shadow.shadow, face, exact);
  if (shadow.extended) {
    out.key("source_clipped");
    out.boolean(shadow.source_clipped);
  }
  out.key("umbra");
  if (shadow.curved) {
    const auto polygons =
        exact ? shadow.curved->exact_umbra_polygons() : std::vector<ExactCurvedPolygon>{};
    emit_curved_region(out, shadow.curved->umbra_polygons(), shadow.curved->area(), face,
                       exact ? &polygons : nullptr);
  } else
    emit_region(out, shadow.extended ? shadow.umbra : shadow.shadow, face, exact);
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
  for (const LightShadows& light : result.lights) {
    const FaceShadow& shadow = light.faces[r];
    for (const Region2* region : {&shadow.shadow, &shadow.umbra, &shadow.penumbra, &shadow.lit})
      add_points(output, points, *region);
    for (const OccluderShadow& occluder : shadow.occluders) {
      add_points(output, points, occluder.polygon);
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
  round_points(output, points);
  return output;
}

// The entry of "faces" for receiver r; members in key order.
void emit_face(JsonEmitter& out, const Scene& scene, const ShadowResult& result, std::size_t r,
               const ShadowJsonOptions& options) {
  const ReceivingFace face = receiving_face(scene, result, r);
  const FaceOutput output = prepare_output(face, result, r);
  emit_face_entry(out, output, options.exact, [&] {
    out.key("lights");
    out.begin_array();
    for (const LightShadows& shadows : result.lights)
      emit_light(out, scene.lights[shadows.light].name, shadows.faces[r], scene, output,
                 options.exact);
    out.end_array();
  });
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

ShadowJsonOptions json_options_of(const ShadowOptions& options, bool exact) {
  ShadowJsonOptions json_options;
  json_options.exact = exact;
  json_options.range_fraction = options.range_fraction;
  json_options.full_scale_lux = options.full_scale_lux;
  json_options.range_lux = options.range_lux;
  json_options.joint_umbrae = options.joint_umbrae;
  return json_options;
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

ShadowJsonWriter::ShadowJsonWriter(std::ostream& out)
    : writer_(std::make_unique<FacesDocumentWriter>(out)) {}
ShadowJsonWriter::~ShadowJsonWriter() = default;

void ShadowJsonWriter::begin(const json& header, std::size_t faces) {
  writer_->begin(header, faces);
}

void ShadowJsonWriter::faces(const ShadowFaceBlock& block) {
  for (const std::string& text : block.texts()) writer_->face(text);
}

void ShadowJsonWriter::end() {
  writer_->end();
}

}  // namespace penumbra::io
