#pragma once
// The shadow loops output of DESIGN.md ("Shadow loops output (JSON)"): per face its
// plane, frame, boundary and area, and per light its shadow, umbra, penumbra and
// lit polygon sets in 3D world coordinates, with each occluder's shadow polygon.
// For point and directional sources umbra = shadow and the penumbra is empty.
// With exact, every coordinate also appears as "p/q" rationals under "exact" keys.

#include <cstddef>
#include <memory>
#include <optional>
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
  bool joint_umbrae = false;  // recorded ("joint_umbrae": true) so that `check` recomputes alike
};

// returns the document options of a result computed with options: its culling recorded (so
// that `check` recomputes alike), with exact rationals on request.
ShadowJsonOptions json_options_of(const ShadowOptions& options, bool exact);

// builds the document for result, computed from scene.
nlohmann::json shadow_json(const Scene& scene, const ShadowResult& result,
                           const ShadowJsonOptions& options);

// the document without its "faces" (culling and per-light statistics).
nlohmann::json shadow_header_json(const Scene& scene, const ShadowResult& result,
                                  const ShadowJsonOptions& options);

// the entry of "faces" for receiver r of result.
nlohmann::json shadow_face_json(const Scene& scene, const ShadowResult& result, std::size_t r,
                                const ShadowJsonOptions& options);

// the same entry as text, laid out as format_json lays out a value at depth, written
// directly (no tree built).
std::string shadow_face_text(const Scene& scene, const ShadowResult& result, std::size_t r,
                             const ShadowJsonOptions& options, int depth);

// A run of consecutive faces of a shadow result as the writers see it: the shadow maps
// themselves, and, built on first request (across threads) and kept, their entries of
// "faces" as trees or as text.
class ShadowFaceBlock {
 public:
  ShadowFaceBlock(const Scene& scene, const ShadowResult& result, const ShadowJsonOptions& options,
                  std::size_t first, std::size_t size)
      : scene_(scene), result_(result), options_(options), first_(first), size_(size) {}

  const Scene& scene() const { return scene_; }
  const ShadowResult& result() const { return result_; }
  std::size_t first() const { return first_; }  // the receiver index of the block's first face
  std::size_t size() const { return size_; }

  // the entries as trees (shadow_face_json).
  const std::vector<nlohmann::json>& entries() const;
  // the entries as text at depth 2, their place in the document (shadow_face_text).
  const std::vector<std::string>& texts() const;

 private:
  const Scene& scene_;
  const ShadowResult& result_;
  const ShadowJsonOptions& options_;
  std::size_t first_, size_;
  mutable std::optional<std::vector<nlohmann::json>> entries_;
  mutable std::optional<std::vector<std::string>> texts_;
};

// Receives the document piece by piece, in order: begin() with the document without its
// faces and the number of faces to come, faces() for each block of faces, end().
class ShadowDocumentSink {
 public:
  virtual ~ShadowDocumentSink() = default;
  virtual void begin(const nlohmann::json& header, std::size_t faces) = 0;
  virtual void faces(const ShadowFaceBlock& block) = 0;
  virtual void end() = 0;
};

// gives the document of result to every sink: the streamed form of shadow_json for
// outputs too large to hold whole, a block of faces at a time, in order.
void stream_shadow_document(const Scene& scene, const ShadowResult& result,
                            const ShadowJsonOptions& options,
                            const std::vector<ShadowDocumentSink*>& sinks);

class FacesDocumentWriter;

// Writes the document as format_json would, block by block.
class ShadowJsonWriter : public ShadowDocumentSink {
 public:
  explicit ShadowJsonWriter(std::ostream& out);
  ~ShadowJsonWriter() override;
  void begin(const nlohmann::json& header, std::size_t faces) override;
  void faces(const ShadowFaceBlock& block) override;
  void end() override;

 private:
  std::unique_ptr<FacesDocumentWriter> writer_;
};

// returns the rings of a face entry's "boundary": the ring of an object's face, or the outer
// ring and then the holes of a face of a mesh part ({"outer": ..., "holes": [...]}).
std::vector<const nlohmann::json*> boundary_rings(const nlohmann::json& face);

// formats a document for files: objects indented one level per depth, arrays that
// hold no objects (points, rings) on one line, so that golden files stay small and
// diff by line.
std::string format_json(const nlohmann::json& document);

// returns the world area of a region of a face with the given frame (frame area times
// |u| |v|), in m^2; the other forms from the frame area itself.
double world_area(const Region2& region, const FaceFrame& frame);
double world_area(double frame_area, const FaceFrame& frame);
double world_area(const Exact& area, const FaceFrame& frame);

}  // namespace penumbra::io
