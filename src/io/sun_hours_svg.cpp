// The heat maps of a sun-hours document: every part of a face filled with the colour of
// its duration on the one colour scale (base/colour_scale.h), 0 h blue to the longest
// duration red.

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "penumbra/base/colour_scale.h"
#include "penumbra/base/input_error.h"
#include "penumbra/base/png.h"
#include "penumbra/io/sun_hours_document.h"
#include "svg_drawing.h"
#include "svg_text.h"

namespace penumbra::io {
namespace {

using nlohmann::json;

// the colour of minutes of sun out of longest.
Rgb8 duration_colour(double minutes, double longest) {
  return scale_colour(longest > 0 ? minutes / longest : 0);
}

// A face's parts as filled shapes (no stroke, so that the exact boundaries between parts
// are where the colours meet), under the face's outline.
FaceDrawing draw_face(const json& face, const Projection& project, double depth, double longest,
                      std::vector<Rgb8>* fills = nullptr) {
  FaceDrawing drawing{depth, {}};
  for (const json& part : face.at("hours")) {
    const Rgb8 colour = duration_colour(part.at("minutes").get<double>(), longest);
    const std::size_t before = drawing.shapes.size();
    add_region(drawing, part,
               "fill=\"" + hex_colour(colour) + "\" fill-rule=\"evenodd\" stroke=\"" +
                   hex_colour(colour) + "\" stroke-width=\"0.3\"",
               project);
    if (fills) fills->insert(fills->end(), drawing.shapes.size() - before, colour);
  }
  Shape outline{{}, "fill=\"none\" stroke=\"#333\" stroke-width=\"0.6\""};
  for (const json* ring : boundary_rings(face))
    if (auto flat = project_ring(*ring, project)) outline.rings.push_back(*flat);
  drawing.shapes.push_back(std::move(outline));
  return drawing;
}

// The legend: one swatch per whole hour from 0 to the longest duration.
void emit_legend(std::ostream& out, double longest, const std::string& title) {
  out << "<g font-family=\"sans-serif\" font-size=\"13\">\n<text x=\"20\" y=\"20\">"
      << escape_xml(title) << "</text>\n";
  const int hours = static_cast<int>(std::floor(longest / 60));
  for (int h = 0; h <= hours; ++h) {
    const double x = 20 + 34.0 * h;
    out << "<rect x=\"" << x << "\" y=\"30\" width=\"32\" height=\"14\" fill=\""
        << hex_colour(duration_colour(60.0 * h, longest)) << "\"/><text x=\"" << x << "\" y=\"58\">"
        << h << " h</text>\n";
  }
  out << "</g>\n";
}

constexpr double kSheetWidth = 900, kLegendHeight = 70;

}  // namespace

void write_sun_hours_svg(std::ostream& out, const json& document, SvgView view) {
  const double longest = document.at("longest_minutes").get<double>();
  std::ostringstream body;
  body << std::setprecision(6);
  double height = 700;
  if (view == SvgView::top) {
    std::vector<FaceDrawing> drawings;
    const Projection project = plan_projection();
    for (const json& face : document.at("faces"))
      if (const auto depth = plan_depth(face))
        drawings.push_back(draw_face(face, project, *depth, longest));
    emit(body, std::move(drawings), 20, kLegendHeight, kSheetWidth - 40,
         height - kLegendHeight - 20, true);
  } else {
    // One panel per face that gets any sun, in the face's own frame (façades included).
    const int columns = 4;
    const double panel = kSheetWidth / columns;
    int panels = 0;
    for (const json& face : document.at("faces")) {
      const json& parts = face.at("hours");
      if (parts.empty() || parts.back().at("minutes").get<double>() <= 0) continue;
      const double x0 = (panels % columns) * panel, y0 = kLegendHeight + (panels / columns) * panel;
      body << "<g>\n<text x=\"" << x0 + 10 << "\" y=\"" << y0 + 16
           << "\" font-family=\"sans-serif\" font-size=\"12\">"
           << escape_xml(face.at("object").get<std::string>()) << " face "
           << face.at("face").get<int>() << "</text>\n";
      emit(body, {draw_face(face, frame_projection(face), 0, longest)}, x0 + 10, y0 + 24,
           panel - 20, panel - 34, true);
      body << "</g>\n";
      ++panels;
    }
    height = kLegendHeight + std::ceil(panels / 4.0) * panel + 10;
  }
  const json& steps = document.at("steps");
  out << std::setprecision(6);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kSheetWidth << "\" height=\""
      << height << "\" viewBox=\"0 0 " << kSheetWidth << " " << height << "\">\n"
      << "<title>penumbra sun-hours</title>\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  emit_legend(out, longest,
              "hours of direct sun, " + steps.at("from").get<std::string>() + " to " +
                  steps.at("to").get<std::string>() + " (" +
                  (view == SvgView::top ? "plan view" : "per face") + ")");
  out << body.str() << "</svg>\n";
}

void write_sun_hours_png(const std::string& path, const json& document, int width) {
  const double longest = document.at("longest_minutes").get<double>();
  std::vector<FaceDrawing> drawings;
  std::vector<std::vector<Rgb8>> fills;
  const Projection project = plan_projection();
  for (const json& face : document.at("faces"))
    if (const auto depth = plan_depth(face)) {
      fills.emplace_back();
      drawings.push_back(draw_face(face, project, *depth, longest, &fills.back()));
      drawings.back().shapes.pop_back();  // no outline in the raster
    }
  const auto [min_x, min_y, max_x, max_y] = bounds_of(drawings);
  if (!(max_x > min_x && max_y > min_y))
    throw InputError(path, "", "no face turned up to draw in plan view");
  const double scale = width / (max_x - min_x);
  const int height = std::clamp(static_cast<int>(std::ceil((max_y - min_y) * scale)), 1, 16384);
  std::vector<std::uint8_t> rgb(3 * static_cast<std::size_t>(width) * height, 255);
  // Painter's order (lowest faces first), each shape filled even-odd at pixel centres.
  std::vector<std::size_t> order(drawings.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return drawings[a].depth > drawings[b].depth;
  });
  std::vector<double> crossings;
  for (const std::size_t d : order)
    for (std::size_t s = 0; s < drawings[d].shapes.size(); ++s) {
      const Shape& shape = drawings[d].shapes[s];
      const Rgb8 colour = fills[d][s];
      for (int row = 0; row < height; ++row) {
        const double y = max_y - (row + 0.5) / scale;
        crossings.clear();
        for (const auto& ring : shape.rings)
          for (std::size_t k = 0; k < ring.size(); ++k) {
            const Flat& a = ring[k];
            const Flat& b = ring[(k + 1) % ring.size()];
            if ((a[1] <= y) != (b[1] <= y))
              crossings.push_back(a[0] + (y - a[1]) / (b[1] - a[1]) * (b[0] - a[0]));
          }
        std::sort(crossings.begin(), crossings.end());
        for (std::size_t k = 0; k + 1 < crossings.size(); k += 2) {
          const int first =
              std::max(0, static_cast<int>(std::ceil((crossings[k] - min_x) * scale - 0.5)));
          const int last = std::min(
              width - 1, static_cast<int>(std::floor((crossings[k + 1] - min_x) * scale - 0.5)));
          for (int column = first; column <= last; ++column)
            std::copy(colour.begin(), colour.end(),
                      rgb.begin() + 3 * (static_cast<std::ptrdiff_t>(row) * width + column));
        }
      }
    }
  write_png(path, width, height, rgb);
}

}  // namespace penumbra::io
