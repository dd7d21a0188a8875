#include "penumbra/illuminance/isolux.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <unordered_map>
#include <variant>

namespace penumbra::illuminance {
namespace {

// === Marching squares

struct Segment {
  long from_edge, to_edge;
  PlanPoint from, to;
};

// joins segments sharing grid edges into polylines; each grid edge carries at most two
// segment ends at one level, so the walk is unambiguous.
std::vector<IsoluxLine> join(double level, const std::vector<Segment>& segments) {
  std::unordered_map<long, std::vector<std::size_t>> at_edge;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    at_edge[segments[s].from_edge].push_back(s);
    at_edge[segments[s].to_edge].push_back(s);
  }
  std::vector<bool> used(segments.size(), false);
  // returns the unused segment at edge, or -1.
  auto next_at = [&](long edge) -> long {
    for (std::size_t s : at_edge[edge])
      if (!used[s]) return static_cast<long>(s);
    return -1;
  };
  std::vector<IsoluxLine> lines;
  for (std::size_t start = 0; start < segments.size(); ++start) {
    if (used[start]) continue;
    used[start] = true;
    std::vector<PlanPoint> forward{segments[start].from, segments[start].to};
    std::vector<PlanPoint> backward;
    const long start_edge = segments[start].from_edge;
    long edge = segments[start].to_edge;
    bool closed = false;
    for (long s; (s = next_at(edge)) >= 0;) {
      used[s] = true;
      const Segment& segment = segments[s];
      const bool forwards = segment.from_edge == edge;
      edge = forwards ? segment.to_edge : segment.from_edge;
      if (edge == start_edge) {
        closed = true;
        break;
      }
      forward.push_back(forwards ? segment.to : segment.from);
    }
    for (edge = start_edge; !closed;) {
      const long s = next_at(edge);
      if (s < 0) break;
      used[s] = true;
      const Segment& segment = segments[s];
      const bool forwards = segment.from_edge == edge;
      edge = forwards ? segment.to_edge : segment.from_edge;
      backward.push_back(forwards ? segment.to : segment.from);
    }
    IsoluxLine line{level, {backward.rbegin(), backward.rend()}, closed};
    line.points.insert(line.points.end(), forward.begin(), forward.end());
    lines.push_back(std::move(line));
  }
  return lines;
}

// === Drawing helpers

struct Rgb {
  double r, g, b;
};

// a colour scale from dark blue (dim) to red (bright), fraction in [0, 1].
Rgb scale_colour(double fraction) {
  static const Rgb anchors[] = {{0.19, 0.21, 0.58}, {0.16, 0.48, 0.85}, {0.20, 0.75, 0.80},
                                {0.45, 0.82, 0.36}, {0.98, 0.85, 0.22}, {0.97, 0.52, 0.15},
                                {0.84, 0.16, 0.12}};
  const int last = static_cast<int>(std::size(anchors)) - 1;
  const double x = std::clamp(fraction, 0.0, 1.0) * last;
  const int i = std::min(static_cast<int>(x), last - 1);
  const double t = x - i;
  return {anchors[i].r + t * (anchors[i + 1].r - anchors[i].r),
          anchors[i].g + t * (anchors[i + 1].g - anchors[i].g),
          anchors[i].b + t * (anchors[i + 1].b - anchors[i].b)};
}

std::string hex(const Rgb& colour, double darken = 1) {
  char text[8];
  auto channel = [&](double c) {
    return static_cast<int>(std::lround(255 * std::clamp(c * darken, 0.0, 1.0)));
  };
  std::snprintf(text, sizeof text, "#%02x%02x%02x", channel(colour.r), channel(colour.g),
                channel(colour.b));
  return text;
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

std::string escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

// the outline of a convex object seen from above: the convex hull of its vertices'
// (x, y), by Andrew's monotone chain (drawing only).
std::vector<PlanPoint> plan_outline(const ConvexPolyhedron& solid) {
  std::vector<PlanPoint> points;
  for (const Point3& vertex : solid.vertices()) {
    const Vec3d p = to_double(vertex);
    points.push_back({p[0], p[1]});
  }
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  auto cross = [](const PlanPoint& o, const PlanPoint& a, const PlanPoint& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  };
  std::vector<PlanPoint> hull(2 * points.size());
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

std::vector<double> isolux_levels(double minimum, double maximum) {
  std::vector<double> levels;
  if (!(maximum > minimum) || !std::isfinite(minimum) || !std::isfinite(maximum)) return levels;
  const double floor_value = std::max(minimum, maximum * 1e-3);
  if (floor_value > 0 && maximum / floor_value > 20) {
    // 1-2-5 series: one decade per three lines suits a range of several decades.
    for (double decade = std::pow(10.0, std::floor(std::log10(floor_value))); decade <= maximum;
         decade *= 10)
      for (double mantissa : {1.0, 2.0, 5.0}) {
        const double level = mantissa * decade;
        if (level > floor_value && level < maximum) levels.push_back(level);
      }
    return levels;
  }
  const double raw = (maximum - minimum) / 8;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  double step = decade;
  for (double mantissa : {1.0, 2.0, 5.0, 10.0})
    if (mantissa * decade >= raw) {
      step = mantissa * decade;
      break;
    }
  for (double level = std::floor(minimum / step + 1) * step; level < maximum; level += step)
    if (level > minimum) levels.push_back(level);
  return levels;
}

std::vector<IsoluxLine> isolux_lines(const WorkplaneValues& values,
                                     const std::vector<double>& levels) {
  const WorkplaneGrid& grid = values.grid;
  std::vector<IsoluxLine> lines;
  if (grid.columns < 2 || grid.rows < 2) return lines;
  const auto index = [&](std::size_t i, std::size_t j) { return j * grid.columns + i; };
  const auto horizontal = [&](std::size_t i, std::size_t j) {
    return 2 * static_cast<long>(index(i, j));
  };
  const auto vertical = [&](std::size_t i, std::size_t j) {
    return 2 * static_cast<long>(index(i, j)) + 1;
  };
  for (double level : levels) {
    std::vector<Segment> segments;
    for (std::size_t j = 0; j + 1 < grid.rows; ++j)
      for (std::size_t i = 0; i + 1 < grid.columns; ++i) {
        // Corners counter-clockwise from the lower left; edge k runs from corner k to k + 1.
        const std::size_t corner[4] = {index(i, j), index(i + 1, j), index(i + 1, j + 1),
                                       index(i, j + 1)};
        const long edge_id[4] = {horizontal(i, j), vertical(i + 1, j), horizontal(i, j + 1),
                                 vertical(i, j)};
        double value[4];
        int mask = 0;
        bool skip = false;
        for (int k = 0; k < 4; ++k) {
          const PointIlluminance& at = values.values[corner[k]];
          skip = skip || at.inside.has_value();
          value[k] = at.total;
          if (value[k] >= level) mask |= 1 << k;
        }
        if (skip || mask == 0 || mask == 15) continue;
        const auto crossing = [&](int k) {
          const int a = k, b = (k + 1) % 4;
          const Vec3d pa = grid.point(corner[a]), pb = grid.point(corner[b]);
          const double t = (level - value[a]) / (value[b] - value[a]);
          return PlanPoint{pa[0] + t * (pb[0] - pa[0]), pa[1] + t * (pb[1] - pa[1])};
        };
        const auto add = [&](int e, int f) {
          segments.push_back({edge_id[e], edge_id[f], crossing(e), crossing(f)});
        };
        // An edge is crossed when its two corners differ; a square has two or four.
        std::vector<int> crossed;
        for (int k = 0; k < 4; ++k)
          if (((mask >> k) & 1) != ((mask >> ((k + 1) % 4)) & 1)) crossed.push_back(k);
        if (crossed.size() == 2) {
          add(crossed[0], crossed[1]);
          continue;
        }
        // Saddle (corners 0 and 2 against 1 and 3): the mean decides which diagonal pair
        // is joined. Edges 3 and 0 meet at corner 0, edges 1 and 2 at corner 2.
        const bool centre_above = (value[0] + value[1] + value[2] + value[3]) / 4 >= level;
        const bool corner0_above = (mask & 1) != 0;
        if (centre_above == corner0_above) {
          add(0, 1);  // cut off corner 1
          add(2, 3);  // and corner 3
        } else {
          add(3, 0);  // cut off corner 0
          add(1, 2);  // and corner 2
        }
      }
    for (IsoluxLine& line : join(level, segments)) lines.push_back(std::move(line));
  }
  return lines;
}

void write_isolux_svg(std::ostream& out, const Scene& scene, const WorkplaneValues& values,
                      const std::vector<double>& levels) {
  const WorkplaneGrid& grid = values.grid;
  const PlanRegion& region = grid.region;
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
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << number(total_width)
      << "\" height=\"" << number(total_height) << "\" viewBox=\"0 0 " << number(total_width) << ' '
      << number(total_height) << "\" font-family=\"sans-serif\">\n"
      << "<title>isolux plot, work plane z = " << number(grid.height) << " m</title>\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";

  // Isolux colour belts: each cell in the colour of the band of its centre's value.
  out << "<g id=\"belts\" shape-rendering=\"crispEdges\" opacity=\"0.55\">\n";
  for (std::size_t k = 0; k < grid.size(); ++k) {
    const Vec3d p = grid.point(k);
    const PointIlluminance& value = values.values[k];
    const std::string fill = value.inside ? "#c8c8c8" : hex(colour_of_band(band_of(value.total)));
    out << "<rect x=\"" << number(sx(p[0] - grid.cell_width / 2)) << "\" y=\""
        << number(sy(p[1] + grid.cell_depth / 2)) << "\" width=\""
        << number(grid.cell_width * scale + 0.3) << "\" height=\""
        << number(grid.cell_depth * scale + 0.3) << "\" fill=\"" << fill << "\"/>\n";
  }
  out << "</g>\n";

  // The plan: every object's outline seen from above, lower objects first.
  std::vector<std::size_t> order(scene.objects.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return scene.objects[a].solid.bbox().zmax() < scene.objects[b].solid.bbox().zmax();
  });
  out << "<g id=\"plan\" fill=\"none\" stroke=\"#303030\" stroke-width=\"1.2\">\n";
  std::map<std::string, std::pair<PlanPoint, double>> names;  // base name -> label spot, area
  for (std::size_t k : order) {
    const Object& object = scene.objects[k];
    const std::vector<PlanPoint> outline = plan_outline(object.solid);
    if (outline.empty()) continue;
    out << "<polygon points=\"";
    double area = 0, cx = 0, cy = 0;
    for (std::size_t i = 0; i < outline.size(); ++i) {
      const PlanPoint& a = outline[i];
      const PlanPoint& b = outline[(i + 1) % outline.size()];
      out << (i ? " " : "") << number(sx(a[0])) << ',' << number(sy(a[1]));
      const double w = a[0] * b[1] - b[0] * a[1];
      area += w;
      cx += (a[0] + b[0]) * w;
      cy += (a[1] + b[1]) * w;
    }
    out << "\"><title>" << escape(object.name) << "</title></polygon>\n";
    PlanPoint centre = outline.front();
    if (std::abs(area) > 0) centre = {cx / (3 * area), cy / (3 * area)};
    const std::string base = object.name.substr(0, object.name.find('#'));
    auto [place, inserted] = names.try_emplace(base, centre, std::abs(area));
    if (!inserted && std::abs(area) > place->second.second)
      place->second = {centre, std::abs(area)};
  }
  out << "</g>\n<g id=\"object-names\" font-size=\"10\" fill=\"#303030\" text-anchor=\"middle\">\n";
  std::vector<PlanPoint> name_spots;
  for (const auto& [name, spot] : names) {
    if (spot.second * scale * scale >= 0.8 * plot_width * plot_depth) continue;  // the floor
    PlanPoint at{sx(spot.first[0]), sy(spot.first[1]) + 3};
    // Move a name down until it clears the names already placed.
    while (std::any_of(name_spots.begin(), name_spots.end(), [&](const PlanPoint& other) {
      return std::abs(other[0] - at[0]) < 50 && std::abs(other[1] - at[1]) < 11;
    }))
      at[1] += 11;
    name_spots.push_back(at);
    out << "<text x=\"" << number(at[0]) << "\" y=\"" << number(at[1]) << "\">" << escape(name)
        << "</text>\n";
  }
  out << "</g>\n";

  // Isolux lines, a label on each line long enough to carry one (labels kept apart).
  const std::vector<IsoluxLine> lines = isolux_lines(values, levels);
  out << "<g id=\"isolux\" fill=\"none\" stroke-width=\"1.6\" stroke-linejoin=\"round\">\n";
  for (const IsoluxLine& line : lines) {
    const std::size_t band = band_of(line.level);
    out << "<polyline stroke=\"" << hex(colour_of_band(band), 0.65) << "\" points=\"";
    for (std::size_t i = 0; i < line.points.size(); ++i)
      out << (i ? " " : "") << number(sx(line.points[i][0])) << ','
          << number(sy(line.points[i][1]));
    if (line.closed && !line.points.empty())
      out << ' ' << number(sx(line.points[0][0])) << ',' << number(sy(line.points[0][1]));
    out << "\"/>\n";
  }
  out << "</g>\n<g id=\"isolux-labels\" font-size=\"10\" text-anchor=\"middle\" fill=\"black\" "
         "stroke=\"white\" stroke-width=\"3\" paint-order=\"stroke\">\n";
  std::vector<PlanPoint> placed;
  for (const IsoluxLine& line : lines) {
    double length = 0;
    for (std::size_t i = 1; i < line.points.size(); ++i)
      length += std::hypot(line.points[i][0] - line.points[i - 1][0],
                           line.points[i][1] - line.points[i - 1][1]);
    if (length * scale < 60) continue;
    const PlanPoint& at = line.points[line.points.size() / 2];
    const PlanPoint spot{sx(at[0]), sy(at[1])};
    if (std::any_of(placed.begin(), placed.end(), [&](const PlanPoint& other) {
          return std::hypot(other[0] - spot[0], other[1] - spot[1]) < 45;
        }))
      continue;
    placed.push_back(spot);
    out << "<text x=\"" << number(spot[0]) << "\" y=\"" << number(spot[1] + 3.5) << "\">"
        << number(line.level) << "</text>\n";
  }
  out << "</g>\n";

  // Lights in plan: point lights as circles, tubes as bars, the sun as an arrow.
  out << "<g id=\"lights\" font-size=\"10\">\n";
  for (const Light& light : scene.lights) {
    if (const auto* point = std::get_if<PointLight>(&light.source)) {
      const double x = sx(point->position[0]), y = sy(point->position[1]);
      out << "<circle cx=\"" << number(x) << "\" cy=\"" << number(y)
          << "\" r=\"5\" fill=\"#fff6a0\" stroke=\"black\"/>\n<text x=\"" << number(x + 7)
          << "\" y=\"" << number(y - 6) << "\">" << escape(light.name) << "</text>\n";
    } else if (const auto* tube = std::get_if<LinearLight>(&light.source)) {
      out << "<line x1=\"" << number(sx(tube->start[0])) << "\" y1=\"" << number(sy(tube->start[1]))
          << "\" x2=\"" << number(sx(tube->end[0])) << "\" y2=\"" << number(sy(tube->end[1]))
          << "\" stroke=\"black\" stroke-width=\"6\" stroke-linecap=\"round\"/>\n<line x1=\""
          << number(sx(tube->start[0])) << "\" y1=\"" << number(sy(tube->start[1])) << "\" x2=\""
          << number(sx(tube->end[0])) << "\" y2=\"" << number(sy(tube->end[1]))
          << "\" stroke=\"#fff6a0\" stroke-width=\"3\" stroke-linecap=\"round\"/>\n<text x=\""
          << number(sx((tube->start[0] + tube->end[0]) / 2)) << "\" y=\""
          << number(sy((tube->start[1] + tube->end[1]) / 2) - 8) << "\" text-anchor=\"middle\">"
          << escape(light.name) << "</text>\n";
    }
  }
  out << "</g>\n";

  // Legend: bands from bright to dim, the sun's direction in plan, the frame.
  const double lx = 2 * margin + plot_width;
  double ly = margin;
  out << "<g id=\"legend\" font-size=\"12\">\n<text x=\"" << number(lx) << "\" y=\"" << number(ly)
      << "\" font-weight=\"bold\">Illuminance E (lx)</text>\n<text x=\"" << number(lx) << "\" y=\""
      << number(ly + 16) << "\" font-size=\"10\">work plane z = " << number(grid.height)
      << " m, cells " << number(grid.cell_width) << " x " << number(grid.cell_depth)
      << " m</text>\n";
  ly += 32;
  for (std::size_t band = levels.size() + 1; band-- > 0;) {
    std::string label;
    if (levels.empty())
      label = "all values";
    else if (band == levels.size())
      label = ">= " + number(levels.back());
    else if (band == 0)
      label = "< " + number(levels.front());
    else
      label = number(levels[band - 1]) + " - " + number(levels[band]);
    out << "<rect x=\"" << number(lx) << "\" y=\"" << number(ly)
        << "\" width=\"24\" height=\"16\" fill=\"" << hex(colour_of_band(band))
        << "\" fill-opacity=\"0.55\" stroke=\"" << hex(colour_of_band(band), 0.65)
        << "\"/>\n<text x=\"" << number(lx + 32) << "\" y=\"" << number(ly + 12) << "\">"
        << escape(label) << "</text>\n";
    ly += 22;
  }
  out << "<rect x=\"" << number(lx) << "\" y=\"" << number(ly) << "\" width=\"24\" height=\"16\" "
      << "fill=\"#c8c8c8\"/>\n<text x=\"" << number(lx + 32) << "\" y=\"" << number(ly + 12)
      << "\">inside an object</text>\n";
  ly += 40;
  for (const Light& light : scene.lights)
    if (const auto* sun = std::get_if<DirectionalLight>(&light.source)) {
      const double dx = sun->direction[0], dy = sun->direction[1], length = std::hypot(dx, dy);
      if (length == 0) continue;
      const double cx = lx + 30, cy = ly + 20, ux = dx / length * 22, uy = -dy / length * 22;
      out << "<line x1=\"" << number(cx - ux) << "\" y1=\"" << number(cy - uy) << "\" x2=\""
          << number(cx + ux) << "\" y2=\"" << number(cy + uy)
          << "\" stroke=\"#d08000\" stroke-width=\"2\"/>\n<circle cx=\"" << number(cx + ux)
          << "\" cy=\"" << number(cy + uy) << "\" r=\"3\" fill=\"#d08000\"/>\n<text x=\""
          << number(lx + 62) << "\" y=\"" << number(cy + 4) << "\">" << escape(light.name)
          << ": light travels this way</text>\n";
      ly += 48;
    }
  out << "</g>\n<rect x=\"" << number(margin) << "\" y=\"" << number(margin) << "\" width=\""
      << number(plot_width) << "\" height=\"" << number(plot_depth)
      << "\" fill=\"none\" stroke=\"black\"/>\n</svg>\n";
}

}  // namespace penumbra::illuminance
