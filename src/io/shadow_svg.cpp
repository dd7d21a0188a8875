#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <sstream>

#include "penumbra/io/shadow_drawing.h"
#include "penumbra/scene/camera_frame.h"
#include "svg_drawing.h"
#include "svg_text.h"

namespace penumbra::io {
namespace {

using nlohmann::json;
using namespace vector_ops;

const char* const palette[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};

std::optional<FaceDrawing> draw_face(const json& face, const std::vector<std::string>& lights,
                                     const Projection& project, double depth, bool loops,
                                     bool affine) {
  FaceDrawing drawing{depth, {}};
  const auto rings = boundary_rings(face);
  const auto outline = project_ring(*rings.front(), project);
  if (!outline) return std::nullopt;
  Shape boundary{{*outline},
                 "fill=\"#f4f4f4\" fill-rule=\"evenodd\" stroke=\"#333\" stroke-width=\"1\""};
  for (std::size_t k = 1; k < rings.size(); ++k)
    if (auto hole = project_ring(*rings[k], project)) boundary.rings.push_back(*hole);
  drawing.shapes.push_back(std::move(boundary));
  for (const auto& light : face.at("lights")) {
    if (light.value("beyond_range", false)) continue;
    const auto index = std::find(lights.begin(), lights.end(), light.at("light")) - lights.begin();
    const std::string colour = palette[index % 6];
    // Two tones: the penumbra light, the umbra dark (for point lights and the sun
    // the umbra is the whole shadow).
    const std::string fill = "fill=\"" + colour + "\" fill-rule=\"evenodd\" stroke=\"" + colour +
                             "\" stroke-width=\"0.5\" fill-opacity=";
    add_region(drawing, light.at("penumbra"), fill + "\"0.2\"", project, affine);
    add_region(drawing, light.at("umbra"), fill + "\"0.55\"", project, affine);
    if (!loops) continue;
    // The raw loops of a linear source (section 4.1.2), with arrows along their
    // direction, so that a twisted umbra loop and its clockwise part show.
    for (const auto& occluder : light.at("occluders"))
      for (const char* kind : {"penumbra_loop", "umbra_loop"}) {
        if (!occluder.contains(kind) || occluder.at(kind).empty()) continue;
        if (const auto ring = project_ring(occluder.at(kind), project))
          drawing.shapes.push_back(
              {{*ring},
               std::string("fill=\"none\" stroke=\"") + (kind[0] == 'u' ? "#000" : "#666") +
                   "\" stroke-width=\"1\" marker-mid=\"url(#arrow)\" marker-end=\"url(#arrow)\""});
      }
  }
  return drawing;
}

}  // namespace

std::optional<SvgView> parse_svg_view(const std::string& name) {
  if (name == "top") return SvgView::top;
  if (name == "camera") return SvgView::camera;
  if (name == "faces") return SvgView::faces;
  return std::nullopt;
}

struct ShadowSvgWriter::Drawing {
  std::vector<std::string> lights;
  double sheet_width = 900;
  double legend_height = 0;
  double sheet_height = 700;
  std::ostringstream body;  // the faces view's panels
  int panels = 0;
  Projection project;  // top and camera views
  std::function<std::optional<double>(const json&)> depth_of;
  std::vector<FaceDrawing> drawings;
};

ShadowSvgWriter::ShadowSvgWriter(std::ostream& out, SvgView view,
                                 const std::optional<Camera>& camera, bool loops)
    : out_(out), view_(view), camera_(camera), loops_(loops), drawing_(new Drawing) {}

ShadowSvgWriter::~ShadowSvgWriter() = default;

void ShadowSvgWriter::begin(const json& header, std::size_t) {
  Drawing& d = *drawing_;
  for (const auto& light : header.at("lights")) d.lights.push_back(light.at("name"));
  d.legend_height = 30 + 20.0 * static_cast<double>(d.lights.size() + 1);
  d.body << std::setprecision(6);
  if (view_ == SvgView::top) {
    // Plan view: faces turned up, lowest first.
    d.project = plan_projection();
    d.depth_of = plan_depth;
  } else if (view_ == SvgView::camera) {
    const CameraFrame frame(*camera_);
    const Vec3d eye = camera_->eye;
    const double focal = 0.5 * camera_->height / frame.half_height();
    d.project = [=](const Vec3d& p) -> std::optional<Flat> {
      const auto [x, y, z] = frame.to_camera(p);
      if (z <= 0) return std::nullopt;
      return Flat{focal * x / z, focal * y / z};
    };
    // Faces turned toward the eye, farthest first (painter's order).
    d.depth_of = [=](const json& face) -> std::optional<double> {
      const auto& plane = face.at("plane");
      const Vec3d normal{plane[0].get<double>(), plane[1].get<double>(), plane[2].get<double>()};
      const json& outer = *boundary_rings(face).front();
      const Vec3d first = outer[0].get<Vec3d>();
      if (dot(normal, eye - first) <= 0) return std::nullopt;
      Vec3d centre{0, 0, 0};
      for (const auto& p : outer)
        for (int i = 0; i < 3; ++i)
          centre[i] += p[i].get<double>() / static_cast<double>(outer.size());
      return length(centre - eye);
    };
  }
}

void ShadowSvgWriter::faces(const ShadowFaceBlock& block) {
  for (const json& entry : block.entries()) face(entry);
}

void ShadowSvgWriter::face(const json& face) {
  Drawing& d = *drawing_;
  if (view_ != SvgView::faces) {
    if (const auto depth = d.depth_of(face))
      if (auto drawing =
              draw_face(face, d.lights, d.project, *depth, loops_, view_ == SvgView::top))
        d.drawings.push_back(std::move(*drawing));
    return;
  }
  // One panel per face that some light reaches, drawn in the face's own frame.
  bool reached = false;
  for (const auto& light : face.at("lights"))
    reached =
        reached || (!light.at("faces_away").get<bool>() && !light.value("beyond_range", false));
  if (!reached) return;
  const int columns = 4;
  const double panel = d.sheet_width / columns;
  const Projection project = frame_projection(face);
  const double x0 = (d.panels % columns) * panel,
               y0 = d.legend_height + (d.panels / columns) * panel;
  d.body << "<g>\n<text x=\"" << x0 + 10 << "\" y=\"" << y0 + 16
         << "\" font-family=\"sans-serif\" font-size=\"12\">"
         << escape_xml(face.at("object").get<std::string>()) << " face "
         << face.at("face").get<int>() << "</text>\n";
  if (auto drawing = draw_face(face, d.lights, project, 0, loops_, true))
    emit(d.body, {*drawing}, x0 + 10, y0 + 24, panel - 20, panel - 34, true);
  d.body << "</g>\n";
  ++d.panels;
}

void ShadowSvgWriter::end() {
  Drawing& d = *drawing_;
  if (view_ == SvgView::faces)
    d.sheet_height = d.legend_height + std::ceil(d.panels / 4.0) * (d.sheet_width / 4) + 10;
  else
    emit(d.body, std::move(d.drawings), 20, d.legend_height, d.sheet_width - 40,
         d.sheet_height - d.legend_height - 20, true);

  out_ << std::setprecision(6);
  out_
      << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << d.sheet_width << "\" height=\""
      << d.sheet_height << "\" viewBox=\"0 0 " << d.sheet_width << " " << d.sheet_height << "\">\n"
      << "<title>penumbra shadows</title>\n"
      << "<defs><marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"5\" refY=\"5\" markerWidth=\"6\" "
         "markerHeight=\"6\" orient=\"auto\"><path d=\"M0 0 L10 5 L0 10 z\"/></marker></defs>\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  // Legend: one swatch per light, and the face fill.
  out_ << "<g font-family=\"sans-serif\" font-size=\"13\">\n<text x=\"20\" y=\"20\">shadows ("
       << (view_ == SvgView::top      ? "plan view"
           : view_ == SvgView::camera ? "camera view"
                                      : "per face")
       << ")</text>\n";
  double y = 30;
  out_ << "<rect x=\"20\" y=\"" << y
       << "\" width=\"14\" height=\"14\" fill=\"#f4f4f4\" stroke=\"#333\"/>"
       << "<text x=\"40\" y=\"" << y + 12 << "\">face</text>\n";
  for (std::size_t k = 0; k < d.lights.size(); ++k) {
    y += 20;
    out_ << "<rect x=\"20\" y=\"" << y << "\" width=\"14\" height=\"14\" fill=\"" << palette[k % 6]
         << "\" fill-opacity=\"0.55\"/><rect x=\"34\" y=\"" << y
         << "\" width=\"14\" height=\"14\" fill=\"" << palette[k % 6]
         << "\" fill-opacity=\"0.2\"/><text x=\"54\" y=\"" << y + 12 << "\">umbra and penumbra of "
         << escape_xml(d.lights[k]) << "</text>\n";
  }
  out_ << "</g>\n" << d.body.str() << "</svg>\n";
}

}  // namespace penumbra::io
