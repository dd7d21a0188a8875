#include "penumbra/io/shadow_diagram.h"

#include <algorithm>
#include <cctype>
#include <iomanip>
#include <sstream>

#include "penumbra/base/colour_scale.h"
#include "penumbra/io/shadow_json.h"
#include "svg_drawing.h"
#include "svg_text.h"

namespace penumbra::io {

SunShadows::SunShadows(const Scene& scene, const SunPlacement& sun, ShadowOptions options,
                       ShadowJsonOptions json_options)
    : stepped_(scene),
      sun_(sun),
      options_(std::move(options)),
      json_options_(std::move(json_options)) {}

DiagramTime SunShadows::at(const studies::SunStep& step, const std::string& when) {
  stepped_.lights = {
      Light{sun_.name, DirectionalLight{step.direction, sun_.illuminance}, sun_.json_path}};
  const ShadowResult result = compute_shadows(stepped_, options_);
  for (const std::string& warning : result.warnings)
    if (std::find(warnings_.begin(), warnings_.end(), warning) == warnings_.end())
      warnings_.push_back(warning);
  return {when, step.position.azimuth_deg, step.position.elevation_deg,
          shadow_json(stepped_, result, json_options_)};
}
namespace {

using nlohmann::json;

// the colour of time k of count, early blue to late red (the one colour scale).
std::string time_colour(std::size_t k, std::size_t count) {
  return hex_colour(
      scale_colour(count > 1 ? static_cast<double>(k) / static_cast<double>(count - 1) : 0));
}

// an SVG class for a time: "time-" and the text with every character that an XML name
// cannot hold turned into '-'.
std::string layer_id(const std::string& time) {
  std::string id = "time-";
  for (char c : time) id += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
  return id;
}

constexpr double kSheetWidth = 900, kSheetHeight = 760;

}  // namespace

json shadow_diagram_json(const std::string& sun, const std::vector<DiagramTime>& times,
                         const std::vector<std::string>& skipped) {
  json entries = json::array();
  for (const DiagramTime& time : times)
    entries.push_back({{"time", time.time},
                       {"azimuth_deg", time.azimuth_deg},
                       {"elevation_deg", time.elevation_deg},
                       {"shadows", time.shadows}});
  return {{"penumbra_shadow_diagram", 1},
          {"sun", sun},
          {"times", std::move(entries)},
          {"skipped", skipped}};
}

void write_shadow_diagram_svg(std::ostream& out, const json& diagram) {
  const json& times = diagram.at("times");
  const double legend_height = 40 + 18.0 * static_cast<double>(times.size() + 1);
  std::vector<FaceDrawing> drawings;
  const Projection project = plan_projection();
  // Each face turned up (the same faces at every time), lowest first: its outline, then its
  // shadow at each time in that time's colour and layer, so that a roof hides the ground's
  // shadows under it.
  const json* faces = times.empty() ? nullptr : &times.front().at("shadows").at("faces");
  for (std::size_t f = 0; faces && f < faces->size(); ++f) {
    const auto depth = plan_depth((*faces)[f]);
    if (!depth) continue;
    FaceDrawing drawing{*depth, {}};
    Shape outline{{},
                  "fill=\"#f4f4f4\" fill-rule=\"evenodd\" stroke=\"#333\" stroke-width=\"0.6\""};
    for (const json* ring : boundary_rings((*faces)[f]))
      if (auto flat = project_ring(*ring, project)) outline.rings.push_back(*flat);
    drawing.shapes.push_back(std::move(outline));
    drawings.push_back(std::move(drawing));
    for (std::size_t k = 0; k < times.size(); ++k) {
      const std::string colour = time_colour(k, times.size());
      const std::string style = "fill=\"" + colour +
                                "\" fill-opacity=\"0.25\" fill-rule=\"evenodd\" stroke=\"" +
                                colour + "\" stroke-width=\"0.8\"";
      FaceDrawing shadows{*depth, {}, layer_id(times[k].at("time").get<std::string>())};
      for (const json& light : times[k].at("shadows").at("faces")[f].at("lights"))
        if (!light.at("faces_away").get<bool>())
          add_region(shadows, light.at("shadow"), style, project);
      drawings.push_back(std::move(shadows));
    }
  }
  std::ostringstream body;
  body << std::setprecision(6);
  emit(body, std::move(drawings), 20, legend_height, kSheetWidth - 40,
       kSheetHeight - legend_height - 20, true);

  out << std::setprecision(6);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kSheetWidth << "\" height=\""
      << kSheetHeight << "\" viewBox=\"0 0 " << kSheetWidth << " " << kSheetHeight << "\">\n"
      << "<title>penumbra shadow diagram</title>\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<g font-family=\"sans-serif\" font-size=\"13\">\n<text x=\"20\" y=\"20\">shadows of "
      << escape_xml(diagram.at("sun").get<std::string>()) << " (plan view)</text>\n";
  double y = 30;
  for (std::size_t k = 0; k < times.size(); ++k, y += 18) {
    const json& time = times[k];
    out << "<rect x=\"20\" y=\"" << y << "\" width=\"14\" height=\"12\" fill=\""
        << time_colour(k, times.size()) << "\" fill-opacity=\"0.5\"/><text x=\"40\" y=\"" << y + 11
        << "\">" << escape_xml(time.at("time").get<std::string>()) << ", azimuth " << std::fixed
        << std::setprecision(1) << time.at("azimuth_deg").get<double>() << ", elevation "
        << time.at("elevation_deg").get<double>() << std::defaultfloat << std::setprecision(6)
        << "</text>\n";
  }
  if (!diagram.at("skipped").empty())
    out << "<text x=\"20\" y=\"" << y + 11 << "\">" << diagram.at("skipped").size()
        << " times with the sun below the horizon left out</text>\n";
  out << "</g>\n" << body.str() << "</svg>\n";
}

}  // namespace penumbra::io
