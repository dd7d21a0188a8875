#pragma once
// The shadow loops output of DESIGN.md ("Shadow loops output (JSON)"): per face its
// plane, frame, boundary and area, and per light its shadow, umbra, penumbra and
// lit polygon sets in 3D world coordinates, with each occluder's shadow polygon.
// For point and directional sources umbra = shadow and the penumbra is empty.
// With exact, every coordinate also appears as "p/q" rationals under "exact" keys.

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "penumbra/shadow/shadow_map.h"

namespace penumbra::io {

struct ShadowJsonOptions {
  bool exact = false;
  double range_fraction = 1.0 / 256;  // recorded so that `check` recomputes alike
  double full_scale_lux = 500;
  std::optional<double> range_lux;
};

// builds the document for result, computed from scene.
nlohmann::json shadow_json(const Scene& scene, const ShadowResult& result,
                           const ShadowJsonOptions& options);

// the document without its "faces" (culling and per-light statistics).
nlohmann::json shadow_header_json(const Scene& scene, const ShadowResult& result,
                                  const ShadowJsonOptions& options);

// the entry of "faces" for receiver r of result.
nlohmann::json shadow_face_json(const Scene& scene, const ShadowResult& result, std::size_t r,
                                const ShadowJsonOptions& options);

// Receives the document piece by piece, in order: begin() with the document without its
// faces and the number of faces to come, face() for each entry of "faces", end().
class ShadowDocumentSink {
 public:
  virtual ~ShadowDocumentSink() = default;
  virtual void begin(const nlohmann::json& header, std::size_t faces) = 0;
  virtual void face(const nlohmann::json& entry) = 0;
  virtual void end() = 0;
};

// gives the document of result to every sink: the streamed form of shadow_json for
// outputs too large to hold whole. The face entries are built a block at a time across
// threads (options decide what they hold) and handed over in order, so the sinks see the
// same sequence whatever the threads.
void stream_shadow_document(const Scene& scene, const ShadowResult& result,
                            const ShadowJsonOptions& options,
                            const std::vector<ShadowDocumentSink*>& sinks);

// gives a whole document (as shadow_json builds it) to sink.
void feed_shadow_document(ShadowDocumentSink& sink, const nlohmann::json& document);

// Writes the document as format_json would, face by face.
class ShadowJsonWriter : public ShadowDocumentSink {
 public:
  explicit ShadowJsonWriter(std::ostream& out) : out_(out) {}
  void begin(const nlohmann::json& header, std::size_t faces) override;
  void face(const nlohmann::json& entry) override;
  void end() override;

 private:
  std::ostream& out_;
  nlohmann::json after_faces_;  // the header's keys that sort after "faces"
  std::size_t written_ = 0, faces_ = 0;
};

// formats a document for files: objects indented one level per depth, arrays that
// hold no objects (points, rings) on one line, so that golden files stay small and
// diff by line.
std::string format_json(const nlohmann::json& document);

// returns the world area of a region of face (frame area times |u| |v|), in m^2.
double world_area(const Region2& region, const Face& face);

}  // namespace penumbra::io
