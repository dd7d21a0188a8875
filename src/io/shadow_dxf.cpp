#include <cmath>
#include <iomanip>
#include <set>
#include <sstream>

#include "penumbra/base/vec3d.h"
#include "penumbra/io/shadow_drawing.h"

namespace penumbra::io {
namespace {

using namespace vector_ops;

// returns v with each component divided by its length: correctly rounded, unlike
// normalized()'s product with the reciprocal, so the drawing's numbers stay as they were.
Vec3d unit(const Vec3d& v) {
  const double l = length(v);
  return {v[0] / l, v[1] / l, v[2] / l};
}

// The object coordinate system of an entity with extrusion direction n (DXF
// reference, "Arbitrary Axis Algorithm").
struct Ocs {
  Vec3d x, y, z;
  explicit Ocs(const Vec3d& normal) : z(unit(normal)) {
    const double limit = 1.0 / 64;
    x = unit(std::abs(z[0]) < limit && std::abs(z[1]) < limit ? cross({0, 1, 0}, z)
                                                              : cross({0, 0, 1}, z));
    y = unit(cross(z, x));
  }
};

}  // namespace

class ShadowDxfWriter::Writer {
 public:
  explicit Writer(std::ostream& out) : out_(out) { out_ << std::setprecision(17); }

  void tag(int code, const std::string& value) { out_ << code << "\n" << value << "\n"; }
  void tag(int code, double value) { out_ << code << "\n" << value << "\n"; }
  std::string handle() {
    std::ostringstream text;
    text << std::hex << std::uppercase << next_handle_++;
    return text.str();
  }

  // writes a closed LWPOLYLINE through world points, all in the plane of normal.
  void polyline(const std::string& layer, const nlohmann::json& ring, const Vec3d& normal) {
    const Ocs ocs(normal);
    tag(0, "LWPOLYLINE");
    tag(5, handle());
    tag(100, "AcDbEntity");
    tag(8, layer);
    tag(100, "AcDbPolyline");
    tag(90, std::to_string(ring.size()));
    tag(70, "1");
    const Vec3d first = ring.at(0).get<Vec3d>();
    tag(38, dot(first, ocs.z));
    for (const auto& point : ring) {
      const Vec3d p = point.get<Vec3d>();
      tag(10, dot(p, ocs.x));
      tag(20, dot(p, ocs.y));
    }
    tag(210, ocs.z[0]);
    tag(220, ocs.z[1]);
    tag(230, ocs.z[2]);
  }

 private:
  std::ostream& out_;
  unsigned next_handle_ = 0x100;
};

ShadowDxfWriter::ShadowDxfWriter(std::ostream& out) : writer_(new Writer(out)) {}

ShadowDxfWriter::~ShadowDxfWriter() = default;

void ShadowDxfWriter::begin(const nlohmann::json& header, std::size_t faces) {
  // Layers: the faces, and four per light when there are faces to draw on.
  std::set<std::string> layers{"faces"};
  if (faces > 0)
    for (const auto& light : header.at("lights"))
      for (const char* kind : {"-shadow", "-umbra", "-penumbra", "-lit"})
        layers.insert(light.at("name").get<std::string>() + kind);
  Writer& dxf = *writer_;
  dxf.tag(0, "SECTION");
  dxf.tag(2, "HEADER");
  dxf.tag(9, "$ACADVER");
  dxf.tag(1, "AC1015");
  dxf.tag(9, "$INSUNITS");
  dxf.tag(70, "6");  // metres
  dxf.tag(0, "ENDSEC");
  dxf.tag(0, "SECTION");
  dxf.tag(2, "TABLES");
  dxf.tag(0, "TABLE");
  dxf.tag(2, "LAYER");
  dxf.tag(5, dxf.handle());
  dxf.tag(100, "AcDbSymbolTable");
  dxf.tag(70, std::to_string(layers.size()));
  int colour = 1;
  for (const std::string& layer : layers) {
    dxf.tag(0, "LAYER");
    dxf.tag(5, dxf.handle());
    dxf.tag(100, "AcDbSymbolTableRecord");
    dxf.tag(100, "AcDbLayerTableRecord");
    dxf.tag(2, layer);
    dxf.tag(70, "0");
    dxf.tag(62, std::to_string(layer == "faces" ? 7 : colour++ % 6 + 1));
    dxf.tag(6, "CONTINUOUS");
  }
  dxf.tag(0, "ENDTAB");
  dxf.tag(0, "ENDSEC");
  dxf.tag(0, "SECTION");
  dxf.tag(2, "ENTITIES");
}

void ShadowDxfWriter::faces(const ShadowFaceBlock& block) {
  Writer& dxf = *writer_;
  for (const nlohmann::json& face : block.entries()) {
    const auto& plane = face.at("plane");
    const Vec3d normal{plane[0].get<double>(), plane[1].get<double>(), plane[2].get<double>()};
    for (const nlohmann::json* ring : boundary_rings(face)) dxf.polyline("faces", *ring, normal);
    for (const auto& light : face.at("lights")) {
      if (light.value("beyond_range", false)) continue;
      const std::string name = light.at("light");
      for (const char* kind : {"shadow", "umbra", "penumbra", "lit"})
        for (const auto& polygon : light.at(kind).at("polygons")) {
          dxf.polyline(name + "-" + kind, polygon.at("outer"), normal);
          for (const auto& hole : polygon.at("holes"))
            dxf.polyline(name + "-" + kind, hole, normal);
        }
    }
  }
}

void ShadowDxfWriter::end() {
  writer_->tag(0, "ENDSEC");
  writer_->tag(0, "EOF");
}

}  // namespace penumbra::io
