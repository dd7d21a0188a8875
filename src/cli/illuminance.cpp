// penumbra illuminance SCENE: illuminance (lux) at given points or on a work plane grid
// (Nishita 1985 sections 3.3 and 4.2), with statistics and an isolux plot.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "dask_driver.h"
#include "numeric_csv.h"
#include "penumbra/base/atomic_file.h"
#include "penumbra/base/csv.h"
#include "penumbra/base/input_error.h"
#include "penumbra/base/progress.h"
#include "penumbra/illuminance/isolux.h"
#include "penumbra/illuminance/scene_illuminance.h"
#include "penumbra/illuminance/workplane.h"
#include "penumbra/io/isolux_svg.h"
#include "penumbra/scene/load_scene.h"
#include "verbs.h"

namespace penumbra::cli {
namespace {

namespace il = illuminance;

struct IlluminanceArguments {
  std::string scene;
  std::string points;
  std::string output;
  std::optional<double> workplane;
  double spacing = 0;
  std::string region;
  std::string svg;
  std::string levels;
  std::string dask;
};

// === Reading the points file (header x,y,z,nx,ny,nz; columns found by name)

std::vector<il::ReceivingPoint> read_points(const std::string& file) {
  std::vector<il::ReceivingPoint> receivers;
  for (const NumericRow& row :
       read_numeric_csv(file, {"x", "y", "z", "nx", "ny", "nz"}, "points file")) {
    const std::vector<double>& v = row.values;
    receivers.push_back(il::receiving_point({v[0], v[1], v[2], v[3], v[4], v[5]}, file,
                                            "line " + std::to_string(row.line)));
  }
  return receivers;
}

// === Writing CSV

// writes the values: x,y,z,nx,ny,nz,E,E[<light>]...,inside (the object containing the
// point, empty when none).
void write_values(std::ostream& out, const Scene& scene,
                  const std::vector<il::ReceivingPoint>& receivers,
                  const std::vector<il::PointIlluminance>& values) {
  std::vector<std::string> columns{"x", "y", "z", "nx", "ny", "nz", "E"};
  for (const Light& light : scene.lights) columns.push_back("E[" + light.name + "]");
  columns.push_back("inside");
  CsvWriter csv(out, columns);
  for (std::size_t k = 0; k < receivers.size(); ++k) {
    for (double coordinate : receivers[k].point) csv.number(coordinate);
    for (double component : receivers[k].normal) csv.number(component);
    csv.number(values[k].total);
    for (double value : values[k].per_light) csv.number(value);
    csv.text(values[k].inside ? scene.objects[*values[k].inside].name : "");
    csv.end_row();
  }
}

// computes the illuminance at the receivers in this process, or with --dask in chunks of
// points on the cluster (dask_driver.h): the same values either way.
std::vector<il::PointIlluminance> illuminance_at(const IlluminanceArguments& arguments,
                                                 const Scene& scene,
                                                 const std::vector<il::ReceivingPoint>& receivers,
                                                 const char* what) {
  if (arguments.dask.empty()) {
    const il::IlluminanceSolver solver(scene);
    Progress progress(what, receivers.size());
    return il::illuminance_at_points(solver, receivers,
                                     [&](std::size_t done) { progress.advance(done); });
  }
  const std::string points = dask_scratch_file("points.f64");
  {
    std::ofstream out(points, std::ios::binary);
    for (const il::ReceivingPoint& receiver : receivers) {
      out.write(reinterpret_cast<const char*>(receiver.point.data()), 3 * sizeof(double));
      out.write(reinterpret_cast<const char*>(receiver.normal.data()), 3 * sizeof(double));
    }
  }
  const std::string file =
      run_on_dask(arguments.dask, {{"job", "illuminance"},
                                   {"scene", std::filesystem::absolute(arguments.scene).string()},
                                   {"points", points}});
  // E (n doubles), E per light (n x lights doubles, row by row), the holding object (n int64)
  const std::size_t n = receivers.size(), lights = scene.lights.size();
  std::vector<double> total(n), per_light(n * lights);
  std::vector<std::int64_t> inside(n);
  std::ifstream in(file, std::ios::binary);
  in.read(reinterpret_cast<char*>(total.data()), static_cast<std::streamsize>(n * sizeof(double)));
  in.read(reinterpret_cast<char*>(per_light.data()),
          static_cast<std::streamsize>(n * lights * sizeof(double)));
  in.read(reinterpret_cast<char*>(inside.data()),
          static_cast<std::streamsize>(n * sizeof(std::int64_t)));
  if (!in || in.peek() != std::char_traits<char>::eof())
    throw InputError(file, "",
                     "the driver's result does not hold " + std::to_string(n) + " points");
  std::vector<il::PointIlluminance> values(n);
  for (std::size_t k = 0; k < n; ++k) {
    values[k].total = total[k];
    values[k].per_light.assign(per_light.begin() + static_cast<std::ptrdiff_t>(k * lights),
                               per_light.begin() + static_cast<std::ptrdiff_t>((k + 1) * lights));
    if (inside[k] >= 0) values[k].inside = static_cast<std::size_t>(inside[k]);
  }
  return values;
}

int run_points(const IlluminanceArguments& arguments, const Scene& scene) {
  const std::vector<il::ReceivingPoint> receivers = read_points(arguments.points);
  const std::vector<il::PointIlluminance> values =
      illuminance_at(arguments, scene, receivers, "illuminance");
  if (arguments.output.empty() || arguments.output == "-")
    write_values(std::cout, scene, receivers, values);
  else
    write_atomically(arguments.output,
                     [&](std::ostream& out) { write_values(out, scene, receivers, values); });
  return 0;
}

int run_workplane(const IlluminanceArguments& arguments, const Scene& scene) {
  il::PlanRegion region{};
  if (!arguments.region.empty()) {
    const std::vector<double> corners = parse_number_list(arguments.region, "--region");
    if (corners.size() != 4) throw InputError("", "--region", "expected x0,y0,x1,y1");
    region = {corners[0], corners[1], corners[2], corners[3]};
    if (!(region.x1 > region.x0) || !(region.y1 > region.y0))
      throw InputError("", "--region", "expected x0 < x1 and y0 < y1");
  } else if (const auto bounds = il::plan_bounds(scene)) {
    region = *bounds;
  } else {
    throw InputError(arguments.scene, "objects", "the scene has no objects: give --region");
  }
  if (!std::isfinite(*arguments.workplane))
    throw InputError("", "--workplane", "not a finite height");
  if (!(arguments.spacing > 0) || !std::isfinite(arguments.spacing))
    throw InputError("", "--spacing", "expected a positive spacing");
  const double cells = std::ceil((region.x1 - region.x0) / arguments.spacing) *
                       std::ceil((region.y1 - region.y0) / arguments.spacing);
  if (cells > 1e8)
    throw InputError("", "--spacing", "more than 10^8 grid points: use a larger spacing");
  std::vector<double> levels;
  if (!arguments.levels.empty()) {
    levels = parse_number_list(arguments.levels, "--levels");
    std::sort(levels.begin(), levels.end());
    levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
  }

  const il::WorkplaneGrid grid =
      il::make_workplane_grid(*arguments.workplane, arguments.spacing, region);
  const il::WorkplaneValues values{
      grid, illuminance_at(arguments, scene, il::workplane_points(grid), "work plane")};
  const il::WorkplaneStatistics statistics = il::workplane_statistics(values);

  if (!arguments.output.empty()) {
    write_atomically(arguments.output, [&](std::ostream& out) {
      write_values(out, scene, il::workplane_points(grid), values.values);
    });
  }
  std::string boundary_report;
  if (!arguments.svg.empty()) {
    if (levels.empty()) levels = il::isolux_levels(statistics.minimum, statistics.maximum);
    // docs/illuminance.md, "Exact isolux lines"
    io::IsoluxBoundaries boundaries;
    il::WorkplaneEdges edges = il::workplane_shadow_edges(scene, *arguments.workplane, region);
    for (const std::string& warning : edges.warnings)
      std::cerr << "penumbra: warning: no shadow boundaries on the work plane for " << warning
                << "\n";
    boundaries.edges = std::move(edges.edges);
    boundaries.refinement =
        il::refine_workplane(il::IlluminanceSolver(scene), values, boundaries.edges);
    write_atomically(arguments.svg, [&](std::ostream& out) {
      io::write_isolux_svg(out, scene, values, levels, boundaries);
    });
    boundary_report = "isolux plot: " + std::to_string(boundaries.edges.size()) +
                      " exact boundary edges, " +
                      std::to_string(boundaries.refinement.squares.size()) + " squares refined, " +
                      std::to_string(boundaries.refinement.evaluations) + " more evaluations\n";
  }

  std::ostringstream report;
  report << "work plane z = " << *arguments.workplane << " m, region " << region.x0 << ','
         << region.y0 << " to " << region.x1 << ',' << region.y1 << ", " << grid.columns << " x "
         << grid.rows << " cells of " << grid.cell_width << " x " << grid.cell_depth
         << " m: " << statistics.points << " points";
  if (statistics.excluded) report << " (" << statistics.excluded << " inside objects, not counted)";
  report << "\nE min " << statistics.minimum << " lx, average " << statistics.average << " lx, max "
         << statistics.maximum << " lx, uniformity U0 = Emin/Eavg = " << statistics.uniformity
         << "\n";
  for (std::size_t light = 0; light < scene.lights.size(); ++light) {
    const auto& [low, average, high] = statistics.per_light[light];
    report << "  " << scene.lights[light].name << ": min " << low << " lx, average " << average
           << " lx, max " << high << " lx\n";
  }
  std::cout << report.str() << boundary_report;
  return 0;
}

int run_illuminance(const IlluminanceArguments& arguments) {
  if (arguments.points.empty() == !arguments.workplane.has_value())
    throw InputError("", "", "give either --points FILE or --workplane HEIGHT --spacing S");
  if (arguments.workplane && !(arguments.spacing > 0))
    throw InputError("", "--spacing", "--workplane needs a positive --spacing");
  if (!arguments.workplane && (!arguments.svg.empty() || !arguments.region.empty()))
    throw InputError("", "", "--svg and --region apply to --workplane only");
  const Scene& scene = load_scene_until_exit(arguments.scene);
  for (const std::string& warning : scene.warnings)
    std::cerr << "penumbra: warning: " << warning << "\n";
  return arguments.workplane ? run_workplane(arguments, scene) : run_points(arguments, scene);
}

}  // namespace

void register_illuminance(CLI::App& app) {
  CLI::App* verb = app.add_subcommand(
      "illuminance", "illuminance (lux) at points or on a work plane, with an isolux plot");
  auto arguments = std::make_shared<IlluminanceArguments>();
  verb->add_option("SCENE", arguments->scene, "scene file (JSON)")->required();
  verb->add_option("--points", arguments->points,
                   "CSV with header x,y,z,nx,ny,nz (unit normals; other columns ignored)");
  verb->add_option(
      "-o,--output", arguments->output,
      "CSV of x,y,z,nx,ny,nz,E,E[<light>]...,inside (--points: default standard output)");
  verb->add_option("--workplane", arguments->workplane,
                   "height z of a horizontal work plane (normal +z)");
  verb->add_option("--spacing", arguments->spacing, "largest grid cell size on the work plane (m)");
  verb->add_option("--region", arguments->region,
                   "x0,y0,x1,y1: the work plane's extent (default: the scene's bounding box)");
  verb->add_option("--svg", arguments->svg, "isolux plot of the work plane (SVG)");
  verb->add_option("--levels", arguments->levels,
                   "isolux levels in lux, e.g. 100,200,500 (default: chosen)");
  verb->add_option("--dask", arguments->dask,
                   "compute on the Dask cluster of this scheduler (tcp://host:8786), in chunks "
                   "of points; the outputs are those of one process (docs/python.md)");
  verb->callback([arguments] { exit_status() = run_illuminance(*arguments); });
}

}  // namespace penumbra::cli
