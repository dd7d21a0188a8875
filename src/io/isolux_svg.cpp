#include "penumbra/io/isolux_svg.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <variant>

#include "penumbra/base/colour_scale.h"
#include "svg_text.h"

namespace penumbra::io {
namespace {

// the outline of a convex object seen from above: the convex hull of its vertices'
// (x, y), by Andrew's monotone chain (drawing only).
std::vector<illuminance::PlanPoint> plan_outline(const ConvexPolyhedron& solid) {
  std::vector<illuminance::PlanPoint> points;
  for (const Point3& vertex : solid.vertices()) {
    const Vec3d p = to_double(vertex);
    points.push_back({p[0], p[1]});
  }
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  auto cross = [](const illuminance::PlanPoint& o, const illuminance::PlanPoint& a,
                  const illuminance::PlanPoint& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  };
  std::vector<illuminance::PlanPoint> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

}  // namespace

void write_isolux_svg(std::ostream& out, const Scene& scene,
                      const illuminance::WorkplaneValues& values, const std::vector<double>& levels,
                      const IsoluxBoundaries& boundaries) {
  const illuminance::WorkplaneGrid& grid = values.grid;
  const illuminance::PlanRegion& region = grid.region;
  const double width = region.x1 - region.x0, depth = region.y1 - region.y0;
  const double scale = std::min(800 / width, 640 / depth);
  const double margin = 40, legend_width = 230;
  const double plot_width = width * scale, plot_depth = depth * scale;
  const auto sx = [&](double x) { return margin + (x - region.x0) * scale; };
  const auto sy = [&](double y) { return margin + (region.y1 - y) * scale; };
  const double total_width = 2 * margin + plot_width + legend_width;
  const double total_height =
      std::max(2 * margin + plot_depth, 120 + 22.0 * static_cast<double>(levels.size() + 6));
  const auto colour_of_band = [&](std::size_t band) {
    return scale_colour(
        levels.empty() ? 0.5 : static_cast<double>(band) / static_cast<double>(levels.size()));
  };
  const auto band_of = [&](double value) {
    return static_cast<std::size_t>(std::upper_bound(levels.begin(), levels.end(), value) -
                                    levels.begin());
  };

  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << svg_number(total_width)
      << "\" height=\"" << svg_number(total_height) << "\" viewBox=\"0 0 "
      << svg_number(total_width) << ' ' << svg_number(total_height)
      << "\" font-family=\"sans-serif\">\n"
      << "<title>isolux plot, work plane z = " << svg_number(grid.height) << " m</title>\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";

  // Isolux colour belts: each cell in the colour of the band of its centre's value.
  out << "<g id=\"belts\" shape-rendering=\"crispEdges\" opacity=\"0.55\">\n";
  for (std::size_t k = 0; k < grid.size(); ++k) {
    const Vec3d p = grid.point(k);
    const illuminance::PointIlluminance& value = values.values[k];
    const std::string fill =
        value.inside ? "#c8c8c8" : hex_colour(colour_of_band(band_of(value.total)));
    out << "<rect x=\"" << svg_number(sx(p[0] - grid.cell_width / 2)) << "\" y=\""
        << svg_number(sy(p[1] + grid.cell_depth / 2)) << "\" width=\""
        << svg_number(grid.cell_width * scale + 0.3) << "\" height=\""
        << svg_number(grid.cell_depth * scale + 0.3) << "\" fill=\"" << fill << "\"/>\n";
  }
  // where a boundary crosses, the refined squares' sub-squares in the band of the mean of
  // their corners (each sub-square's corners lie on one side of every boundary but for the
  // sub-squares a boundary meets, whose colour the drawn boundary covers)
  const illuminance::WorkplaneRefinement& refinement = boundaries.refinement;
  const int n = refinement.refine;
  for (const illuminance::RefinedSquare& square : refinement.squares)
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < n; ++a) {
        double sum = 0;
        for (const auto& [da, db] : {std::pair{0, 0}, {1, 0}, {0, 1}, {1, 1}})
          sum += square.values[static_cast<std::size_t>((b + db) * (n + 1) + a + da)];
        const illuminance::PlanPoint p =
            illuminance::WorkplaneRefinement::corner(grid, square, n, a, b + 1);
        const std::string fill =
            std::isnan(sum) ? "#c8c8c8" : hex_colour(colour_of_band(band_of(sum / 4)));
        out << "<rect x=\"" << svg_number(sx(p[0])) << "\" y=\"" << svg_number(sy(p[1]))
            << "\" width=\"" << svg_number(grid.cell_width / n * scale + 0.1) << "\" height=\""
            << svg_number(grid.cell_depth / n * scale + 0.1) << "\" fill=\"" << fill << "\"/>\n";
      }
  out << "</g>\n";

  // The plan: every object's outline seen from above, lower objects first, then by name (the
  // drawing does not depend on the order of the scene file).
  std::vector<std::size_t> order(scene.objects.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const double za = scene.objects[a].solid.bbox().zmax(),
                 zb = scene.objects[b].solid.bbox().zmax();
    return za != zb ? za < zb : scene.objects[a].name < scene.objects[b].name;
  });
  out << "<g id=\"plan\" fill=\"none\" stroke=\"#303030\" stroke-width=\"1.2\">\n";
  std::map<std::string, std::pair<illuminance::PlanPoint, double>>
      names;  // base name -> label spot, area
  for (std::size_t k : order) {
    const Object& object = scene.objects[k];
    const std::vector<illuminance::PlanPoint> outline = plan_outline(object.solid);
    if (outline.empty()) continue;
    out << "<polygon points=\"";
    double area = 0, cx = 0, cy = 0;
    for (std::size_t i = 0; i < outline.size(); ++i) {
      const illuminance::PlanPoint& a = outline[i];
      const illuminance::PlanPoint& b = outline[(i + 1) % outline.size()];
      out << (i ? " " : "") << svg_number(sx(a[0])) << ',' << svg_number(sy(a[1]));
      const double w = a[0] * b[1] - b[0] * a[1];
      area += w;
      cx += (a[0] + b[0]) * w;
      cy += (a[1] + b[1]) * w;
    }
    out << "\"><title>" << escape_xml(object.name) << "</title></polygon>\n";
    illuminance::PlanPoint centre = outline.front();
    if (std::abs(area) > 0) centre = {cx / (3 * area), cy / (3 * area)};
    const std::string base = object.name.substr(0, object.name.find('#'));
    auto [place, inserted] = names.try_emplace(base, centre, std::abs(area));
    if (!inserted && std::abs(area) > place->second.second)
      place->second = {centre, std::abs(area)};
  }
  out << "</g>\n<g id=\"object-names\" font-size=\"10\" fill=\"#303030\" text-anchor=\"middle\">\n";
  std::vector<illuminance::PlanPoint> name_spots;
  for (const auto& [name, spot] : names) {
    if (spot.second * scale * scale >= 0.8 * plot_width * plot_depth) continue;  // the floor
    illuminance::PlanPoint at{sx(spot.first[0]), sy(spot.first[1]) + 3};
    // Move a name down until it clears the names already placed.
    while (
        std::any_of(name_spots.begin(), name_spots.end(), [&](const illuminance::PlanPoint& other) {
          return std::abs(other[0] - at[0]) < 50 && std::abs(other[1] - at[1]) < 11;
        }))
      at[1] += 11;
    name_spots.push_back(at);
    out << "<text x=\"" << svg_number(at[0]) << "\" y=\"" << svg_number(at[1]) << "\">"
        << escape_xml(name) << "</text>\n";
  }
  out << "</g>\n";

  // Isolux lines, a label on each line long enough to carry one (labels kept apart).
  const std::vector<illuminance::IsoluxLine> lines =
      illuminance::isolux_lines(values, levels, boundaries.refinement);
  out << "<g id=\"isolux\" fill=\"none\" stroke-width=\"1.6\" stroke-linejoin=\"round\">\n";
  for (const illuminance::IsoluxLine& line : lines) {
    const std::size_t band = band_of(line.level);
    out << "<polyline stroke=\"" << hex_colour(colour_of_band(band), 0.65) << "\" points=\"";
    for (std::size_t i = 0; i < line.points.size(); ++i)
      out << (i ? " " : "") << svg_number(sx(line.points[i][0])) << ','
          << svg_number(sy(line.points[i][1]));
    if (line.closed && !line.points.empty())
      out << ' ' << svg_number(sx(line.points[0][0])) << ',' << svg_number(sy(line.points[0][1]));
    out << "\"/>\n";
  }
  // the exact shadow (solid) and umbra (dashed) boundaries, across which E may jump
  out << "</g>\n<g id=\"shadow-boundaries\" stroke=\"#202020\" stroke-width=\"1\">\n";
  for (const illuminance::PlanEdge& edge : boundaries.edges)
    out << "<line x1=\"" << svg_number(sx(edge.a[0])) << "\" y1=\"" << svg_number(sy(edge.a[1]))
        << "\" x2=\"" << svg_number(sx(edge.b[0])) << "\" y2=\"" << svg_number(sy(edge.b[1]))
        << (edge.umbra ? "\" stroke-dasharray=\"4 2" : "") << "\"><title>"
        << escape_xml(scene.lights[edge.light].name) << (edge.umbra ? " umbra" : " shadow")
        << "</title></line>\n";
  out << "</g>\n<g id=\"isolux-labels\" font-size=\"10\" text-anchor=\"middle\" fill=\"black\" "
         "stroke=\"white\" stroke-width=\"3\" paint-order=\"stroke\">\n";
  std::vector<illuminance::PlanPoint> placed;
  for (const illuminance::IsoluxLine& line : lines) {
    double length = 0;
    for (std::size_t i = 1; i < line.points.size(); ++i)
      length += std::hypot(line.points[i][0] - line.points[i - 1][0],
                           line.points[i][1] - line.points[i - 1][1]);
    if (length * scale < 60) continue;
    const illuminance::PlanPoint& at = line.points[line.points.size() / 2];
    const illuminance::PlanPoint spot{sx(at[0]), sy(at[1])};
    if (std::any_of(placed.begin(), placed.end(), [&](const illuminance::PlanPoint& other) {
          return std::hypot(other[0] - spot[0], other[1] - spot[1]) < 45;
        }))
      continue;
    placed.push_back(spot);
    out << "<text x=\"" << svg_number(spot[0]) << "\" y=\"" << svg_number(spot[1] + 3.5) << "\">"
        << svg_number(line.level) << "</text>\n";
  }
  out << "</g>\n";

  // Lights in plan: point lights as circles, tubes as bars, area sources as their polygons
  // (a vertical panel is drawn as the line it projects to), the sun as an arrow.
  // Clipped to the plot: a light beyond the region (a panel wider than the objects' box) must
  // not run over the legend.
  out << "<clipPath id=\"plot\"><rect x=\"" << svg_number(margin) << "\" y=\"" << svg_number(margin)
      << "\" width=\"" << svg_number(plot_width) << "\" height=\"" << svg_number(plot_depth)
      << "\"/></clipPath>\n"
      << "<g id=\"lights\" font-size=\"10\" clip-path=\"url(#plot)\">\n";
  for (const Light& light : scene.lights) {
    if (const auto* point = std::get_if<PointLight>(&light.source)) {
      const double x = sx(point->position[0]), y = sy(point->position[1]);
      out << "<circle cx=\"" << svg_number(x) << "\" cy=\"" << svg_number(y)
          << "\" r=\"5\" fill=\"#fff6a0\" stroke=\"black\"/>\n<text x=\"" << svg_number(x + 7)
          << "\" y=\"" << svg_number(y - 6) << "\">" << escape_xml(light.name) << "</text>\n";
    } else if (const auto* tube = std::get_if<LinearLight>(&light.source)) {
      out << "<line x1=\"" << svg_number(sx(tube->start[0])) << "\" y1=\""
          << svg_number(sy(tube->start[1])) << "\" x2=\"" << svg_number(sx(tube->end[0]))
          << "\" y2=\"" << svg_number(sy(tube->end[1]))
          << "\" stroke=\"black\" stroke-width=\"6\" stroke-linecap=\"round\"/>\n<line x1=\""
          << svg_number(sx(tube->start[0])) << "\" y1=\"" << svg_number(sy(tube->start[1]))
          << "\" x2=\"" << svg_number(sx(tube->end[0])) << "\" y2=\""
          << svg_number(sy(tube->end[1]))
          << "\" stroke=\"#fff6a0\" stroke-width=\"3\" stroke-linecap=\"round\"/>\n<text x=\""
          << svg_number(sx((tube->start[0] + tube->end[0]) / 2)) << "\" y=\""
          << svg_number(sy((tube->start[1] + tube->end[1]) / 2) - 8) << "\" text-anchor=\"middle\">"
          << escape_xml(light.name) << "</text>\n";
    } else if (const auto* panel = std::get_if<AreaLight>(&light.source)) {
      out << "<polygon points=\"";
      double cx = 0, cy = 0;
      for (std::size_t k = 0; k < panel->vertices.size(); ++k) {
        const Vec3d& q = panel->vertices[k];
        out << (k ? " " : "") << svg_number(sx(q[0])) << "," << svg_number(sy(q[1]));
        cx += sx(q[0]) / panel->vertices.size();
        cy += sy(q[1]) / panel->vertices.size();
      }
      out << "\" fill=\"#fff6a0\" stroke=\"black\"/>\n<text x=\"" << svg_number(cx) << "\" y=\""
          << svg_number(cy + 3.5) << "\" text-anchor=\"middle\">" << escape_xml(light.name)
          << "</text>\n";
    }
  }
  out << "</g>\n";

  // Legend: bands from bright to dim, the sun's direction in plan, the frame.
  const double lx = 2 * margin + plot_width;
  double ly = margin;
  out << "<g id=\"legend\" font-size=\"12\">\n<text x=\"" << svg_number(lx) << "\" y=\""
      << svg_number(ly) << "\" font-weight=\"bold\">Illuminance E (lx)</text>\n<text x=\""
      << svg_number(lx) << "\" y=\"" << svg_number(ly + 16)
      << "\" font-size=\"10\">work plane z = " << svg_number(grid.height) << " m, cells "
      << svg_number(grid.cell_width) << " x " << svg_number(grid.cell_depth) << " m</text>\n";
  ly += 32;
  for (std::size_t band = levels.size() + 1; band-- > 0;) {
    std::string label;
    if (levels.empty())
      label = "all values";
    else if (band == levels.size())
      label = ">= " + svg_number(levels.back());
    else if (band == 0)
      label = "< " + svg_number(levels.front());
    else
      label = svg_number(levels[band - 1]) + " - " + svg_number(levels[band]);
    out << "<rect x=\"" << svg_number(lx) << "\" y=\"" << svg_number(ly)
        << "\" width=\"24\" height=\"16\" fill=\"" << hex_colour(colour_of_band(band))
        << "\" fill-opacity=\"0.55\" stroke=\"" << hex_colour(colour_of_band(band), 0.65)
        << "\"/>\n<text x=\"" << svg_number(lx + 32) << "\" y=\"" << svg_number(ly + 12) << "\">"
        << escape_xml(label) << "</text>\n";
    ly += 22;
  }
  out << "<rect x=\"" << svg_number(lx) << "\" y=\"" << svg_number(ly)
      << "\" width=\"24\" height=\"16\" "
      << "fill=\"#c8c8c8\"/>\n<text x=\"" << svg_number(lx + 32) << "\" y=\"" << svg_number(ly + 12)
      << "\">inside an object</text>\n";
  ly += 40;
  for (const Light& light : scene.lights)
    if (const auto* sun = std::get_if<DirectionalLight>(&light.source)) {
      const double dx = sun->direction[0], dy = sun->direction[1], length = std::hypot(dx, dy);
      if (length == 0) continue;
      const double cx = lx + 30, cy = ly + 20, ux = dx / length * 22, uy = -dy / length * 22;
      out << "<line x1=\"" << svg_number(cx - ux) << "\" y1=\"" << svg_number(cy - uy) << "\" x2=\""
          << svg_number(cx + ux) << "\" y2=\"" << svg_number(cy + uy)
          << "\" stroke=\"#d08000\" stroke-width=\"2\"/>\n<circle cx=\"" << svg_number(cx + ux)
          << "\" cy=\"" << svg_number(cy + uy) << "\" r=\"3\" fill=\"#d08000\"/>\n<text x=\""
          << svg_number(lx + 62) << "\" y=\"" << svg_number(cy + 4) << "\">"
          << escape_xml(light.name) << ": light travels this way</text>\n";
      ly += 48;
    }
  out << "</g>\n<rect x=\"" << svg_number(margin) << "\" y=\"" << svg_number(margin)
      << "\" width=\"" << svg_number(plot_width) << "\" height=\"" << svg_number(plot_depth)
      << "\" fill=\"none\" stroke=\"black\"/>\n</svg>\n";
}

}  // namespace penumbra::io
