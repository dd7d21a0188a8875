#pragma once
// Drawings and tables of a shadow loops document (io/shadow_json.h) for CAD users:
// an SVG sheet (plan view, camera view, or one panel per face), a DXF file of closed
// LWPOLYLINEs on layers per light and kind, and a CSV of shaded area and percentage
// per face and light. They read the document's double coordinates: output only. Each is a
// ShadowDocumentSink, so that it can be written while the document streams; the functions
// write a whole document.

#include <memory>
#include <optional>
#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

#include "penumbra/base/csv.h"
#include "penumbra/io/shadow_json.h"
#include "penumbra/scene/scene.h"

namespace penumbra::io {

enum class SvgView { top, camera, faces };

// parses "top", "camera" or "faces"; nullopt otherwise.
std::optional<SvgView> parse_svg_view(const std::string& name);

// The SVG drawing: faces outlined, umbra (dark) and penumbra (light) filled per light, a
// legend; with loops, the raw penumbra and umbra loops of linear sources as polylines with
// arrows along their direction. Laid out when the faces are all in.
class ShadowSvgWriter : public ShadowDocumentSink {
 public:
  // camera is needed by the camera view (precondition).
  ShadowSvgWriter(std::ostream& out, SvgView view, const std::optional<Camera>& camera,
                  bool loops = false);
  ~ShadowSvgWriter() override;
  void begin(const nlohmann::json& header, std::size_t faces) override;
  void faces(const ShadowFaceBlock& block) override;
  void end() override;

 private:
  void face(const nlohmann::json& entry);
  struct Drawing;
  std::ostream& out_;
  SvgView view_;
  std::optional<Camera> camera_;
  bool loops_;
  std::unique_ptr<Drawing> drawing_;
};

// The DXF file (R2000), entity by entity: each face boundary on layer "faces" and every
// shadow, umbra, penumbra and lit polygon ring as a closed LWPOLYLINE on layer
// "<light>-shadow" / "-umbra" / "-penumbra" / "-lit", in the face's plane (object
// coordinate system by the arbitrary axis algorithm).
class ShadowDxfWriter : public ShadowDocumentSink {
 public:
  explicit ShadowDxfWriter(std::ostream& out);
  ~ShadowDxfWriter() override;
  void begin(const nlohmann::json& header, std::size_t faces) override;
  void faces(const ShadowFaceBlock& block) override;
  void end() override;

 private:
  class Writer;
  std::unique_ptr<Writer> writer_;
};

// The CSV table, row by row from the shadow maps: object,face,light,face_area,shadow_area,
// lit_area,shadow_percent,faces_away,beyond_range,occluders,umbra_area,penumbra_area,
// joint_occlusion, one row per face and light.
class ShadowCsvWriter : public ShadowDocumentSink {
 public:
  explicit ShadowCsvWriter(std::ostream& out) : out_(out) {}
  void begin(const nlohmann::json& header, std::size_t faces) override;
  void faces(const ShadowFaceBlock& block) override;
  void end() override {}

 private:
  std::ostream& out_;
  std::unique_ptr<CsvWriter> csv_;
};

}  // namespace penumbra::io
