// penumbra sun-hours SCENE: how long every part of every face is in direct sun through a
// day or a range of days (docs/sun-hours.md): the exact parts by duration as JSON, the
// area with at least H hours per face as CSV, heat maps, and the area of a region that
// reaches a threshold.

#include <CGAL/Polygon_2.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "dask_driver.h"
#include "penumbra/base/atomic_file.h"
#include "penumbra/base/input_error.h"
#include "penumbra/base/progress.h"
#include "penumbra/io/shadow_json.h"
#include "penumbra/io/sun_hours_document.h"
#include "penumbra/scene/object_selection.h"
#include "penumbra/studies/sun_hours.h"
#include "penumbra/studies/sun_hours_request.h"
#include "verbs.h"

namespace penumbra::cli {
namespace {

struct SunHoursArguments {
  std::string scene;
  std::string light;
  std::string date, to;
  std::string step = "10min";
  std::string utc_offset;
  std::string output, report, svg, png;
  std::string view = "top";
  int png_width = 1200;
  bool exact = false;
  std::string receivers;
  std::string threshold, region;
  std::string site;
  bool stats = false;
  std::string dask;
};

// computes the study on the Dask cluster at arguments.dask (dask_driver.h): tiles of the
// receiving faces' owners, merged into the exact document that is read back here.
studies::SunHoursResult sun_hours_on_dask(const Scene& scene, const SunHoursArguments& arguments,
                                          const studies::SunHoursPlan& study,
                                          const std::optional<std::vector<Receiver>>& receivers) {
  const auto given = [](const std::string& text) {
    return text.empty() ? nlohmann::json() : nlohmann::json(text);
  };
  nlohmann::json request = {{"job", "sun_hours"},
                            {"scene", std::filesystem::absolute(arguments.scene).string()},
                            {"study",
                             {{"date", given(arguments.date)},
                              {"to", given(arguments.to)},
                              {"step", given(arguments.step)},
                              {"light", given(arguments.light)},
                              {"site", given(arguments.site)},
                              {"utc_offset", given(arguments.utc_offset)}}},
                            {"receivers", nullptr}};
  if (receivers) {
    std::set<std::string> owners;
    for (const Receiver& receiver : *receivers)
      owners.insert(scene.objects[receiver.object].face_owner());
    request["receivers"] = owners;
  }
  const std::string file = run_on_dask(arguments.dask, request);
  nlohmann::json merged;
  try {
    merged = nlohmann::json::parse(std::ifstream(file));
  } catch (const nlohmann::json::exception& error) {
    throw InputError(file, "", std::string("the driver's result is not JSON: ") + error.what());
  }
  studies::SunHoursResult result =
      io::sun_hours_from_json(scene, study, receivers, merged["document"], file);
  result.faces.warnings = merged.value("warnings", std::vector<std::string>());
  return result;
}

// returns "A m2 of T m2 (P %)".
std::string area_share(double reached, double total) {
  char text[128];
  std::snprintf(text, sizeof text, "%.6g m2 of %.6g m2 (%.2f %%)", reached, total,
                total > 0 ? 100 * reached / total : 0.0);
  return text;
}

// returns the plan polygon a --region "x,y x,y x,y ..." gives (points apart by spaces or
// semicolons), or {} when the text is not one (it names objects then).
std::optional<std::vector<Point2>> plan_polygon(const std::string& text) {
  std::string spaced = text;
  std::replace(spaced.begin(), spaced.end(), ';', ' ');
  std::istringstream in(spaced);
  std::vector<Point2> points;
  for (std::string token; in >> token;) {
    const std::size_t comma = token.find(',');
    if (comma == std::string::npos || token.find(',', comma + 1) != std::string::npos)
      return std::nullopt;
    double xy[2];
    const std::string parts[2] = {token.substr(0, comma), token.substr(comma + 1)};
    for (int k = 0; k < 2; ++k) {
      std::size_t used = 0;
      try {
        xy[k] = std::stod(parts[k], &used);
      } catch (const std::exception&) {
        return std::nullopt;
      }
      if (used != parts[k].size()) return std::nullopt;
      if (!std::isfinite(xy[k]))
        throw InputError("", "--region", "the plan polygon's coordinates must be finite");
    }
    points.emplace_back(xy[0], xy[1]);
  }
  if (points.size() < 2) return std::nullopt;
  const CGAL::Polygon_2<Kernel> polygon(points.begin(), points.end());
  if (points.size() < 3 || !polygon.is_simple() || CGAL::is_zero(polygon.area()))
    throw InputError("", "--region",
                     "a plan polygon is at least 3 points x,y that enclose an area without "
                     "crossing or repeating, found '" +
                         text + "'");
  return points;
}

// returns the shares of the faces of the named objects in a region: each face whole, and
// its area with at least threshold of sun (a garden modelled as a box is its top face).
std::vector<studies::RegionShare> object_shares(const Scene& scene,
                                                const studies::SunHoursResult& result,
                                                const std::vector<std::size_t>& objects,
                                                sun::Duration threshold) {
  std::vector<bool> chosen(scene.objects.size(), false);
  for (std::size_t object : objects) chosen[object] = true;
  std::vector<studies::RegionShare> shares;
  for (std::size_t r = 0; r < result.faces.receivers.size(); ++r)
    if (chosen[result.faces.receivers[r].object])
      shares.push_back(
          {r, receiving_face(scene, result.faces, r).area, result.area_at_least(r, threshold)});
  return shares;
}

// prints the area of a region that gets at least threshold of sun, then the same for each
// face it holds a share of.
void report_threshold(const Scene& scene, const studies::SunHoursResult& result,
                      const std::string& region, const std::vector<studies::RegionShare>& shares,
                      sun::Duration threshold) {
  double total = 0, reached = 0;
  std::ostringstream faces;
  for (const studies::RegionShare& share : shares) {
    const ReceivingFace face = receiving_face(scene, result.faces, share.receiver);
    const double area = io::world_area(share.area, face.frame);
    const double lit = io::world_area(share.reached, face.frame);
    total += area;
    reached += lit;
    faces << "  " << face.object << " face " << face.face << ": " << area_share(lit, area) << "\n";
  }
  const double minutes = std::chrono::duration<double, std::ratio<60>>(threshold).count();
  std::cout << "region " << region << ": " << area_share(reached, total) << " gets at least "
            << minutes / 60 << " h of direct sun\n"
            << faces.str();
}

int run_sun_hours(const SunHoursArguments& arguments) {
  using Clock = std::chrono::steady_clock;
  const auto started = Clock::now();
  const Scene& scene = load_scene_until_exit(arguments.scene);
  for (const std::string& warning : scene.warnings)
    std::cerr << "penumbra: warning: " << warning << "\n";
  studies::SunHoursRequest request;
  request.scene_path = arguments.scene;
  request.light = arguments.light;
  request.site = arguments.site;
  request.date = arguments.date;
  request.to = arguments.to;
  request.step = arguments.step;
  request.utc_offset = arguments.utc_offset;
  if (!arguments.threshold.empty() && arguments.region.empty())
    throw InputError("", "--threshold", "needs --region NAME[,NAME...] or --region 'x,y x,y x,y'");
  if (arguments.threshold.empty() && !arguments.region.empty())
    throw InputError("", "--region", "needs --threshold, e.g. 2h");
  const studies::SunHoursPlan study = studies::plan_sun_hours(scene, request);
  const SunPlacement& sun = study.sun;
  const std::vector<sun::UtcInstant>& instants = study.instants;
  std::optional<sun::Duration> threshold;
  if (!arguments.threshold.empty())
    threshold = sun::parse_step(arguments.threshold, {"", "--threshold"});
  std::vector<std::size_t> region_objects;
  const std::optional<std::vector<Point2>> plan = plan_polygon(arguments.region);
  if (threshold && !plan) region_objects = select_objects(scene, arguments.region, "--region");

  studies::SunHoursOptions options;
  if (!arguments.receivers.empty())
    options.receivers = faces_of_objects(scene, select_objects(scene, arguments.receivers));
  std::size_t up = 0;
  for (const studies::SunStep& s : studies::sun_steps(sun, scene.north_deg, instants)) up += s.up();
  std::unique_ptr<Progress> progress =
      std::make_unique<Progress>("sun-hours: shadows of the steps", up);
  options.step_done = [&] { progress->advance(); };
  options.overlays_begin = [&](std::size_t faces) {
    progress = std::make_unique<Progress>("sun-hours: overlays", faces);
  };
  options.face_done = [&] { progress->advance(); };
  if (!arguments.dask.empty()) progress.reset();  // the cluster's dashboard shows the tasks
  const studies::SunHoursResult& result = keep_until_exit(
      arguments.dask.empty() ? studies::sun_hours(scene, sun, instants, study.step, options)
                             : sun_hours_on_dask(scene, arguments, study, options.receivers));
  progress.reset();
  for (const std::string& warning : result.faces.warnings)
    std::cerr << "penumbra: warning: " << warning << "\n";
  if (up == 0)
    std::cerr << "penumbra: warning: the sun '" << sun.name
              << "' is below the horizon at every step: every face gets 0 h\n";
  const auto computed = Clock::now();

  const io::SunHoursHeader header = io::sun_hours_header(scene, study);
  // The JSON goes to standard output with "-o -", or when nothing else is asked for.
  const bool to_stdout =
      arguments.output == "-" || (arguments.output.empty() && arguments.report.empty() &&
                                  !threshold && arguments.svg.empty() && arguments.png.empty());
  // The heat maps are drawn from the document; the JSON alone is written without it.
  nlohmann::json document;
  const bool drawn = !arguments.svg.empty() || !arguments.png.empty();
  if (drawn) document = io::sun_hours_json(scene, result, header, arguments.exact);
  const auto write_json = [&](std::ostream& out) {
    if (drawn)
      out << io::format_json(document);
    else
      io::write_sun_hours_json(out, scene, result, header, arguments.exact);
  };
  // Every file is written whole or not at all; the first to fail stops the rest.
  if (to_stdout)
    write_json(std::cout);
  else if (!arguments.output.empty())
    write_atomically(arguments.output, write_json);
  if (!arguments.report.empty())
    write_atomically(arguments.report,
                     [&](std::ostream& out) { io::write_sun_hours_csv(out, scene, result); });
  if (!arguments.svg.empty()) {
    const auto view = io::parse_svg_view(arguments.view);
    write_atomically(arguments.svg,
                     [&](std::ostream& out) { io::write_sun_hours_svg(out, document, *view); });
  }
  if (!arguments.png.empty()) io::write_sun_hours_png(arguments.png, document, arguments.png_width);
  if (threshold && plan)
    report_threshold(scene, result, "plan polygon of " + std::to_string(plan->size()) + " points",
                     studies::plan_region_shares(scene, result, *plan, *threshold), *threshold);
  if (threshold && !plan)
    report_threshold(scene, result, arguments.region,
                     object_shares(scene, result, region_objects, *threshold), *threshold);
  if (arguments.stats)
    std::cerr << "steps " << result.steps.size() << " (" << up << " with the sun up), faces "
              << result.faces.receivers.size() << "; time: shadows " << result.shadow_seconds
              << " s, overlay " << result.overlay_seconds << " s, total (load to files) "
              << std::chrono::duration<double>(Clock::now() - started).count() << " s (outputs "
              << std::chrono::duration<double>(Clock::now() - computed).count() << " s)\n";
  return 0;
}

}  // namespace

void register_sun_hours(CLI::App& app) {
  CLI::App* verb = app.add_subcommand(
      "sun-hours",
      "exact sunlit duration on every face through a day or days (JSON, CSV, SVG, PNG)");
  auto arguments = std::make_shared<SunHoursArguments>();
  verb->add_option("SCENE", arguments->scene, "scene file (JSON) with a \"sun\" light")->required();
  verb->add_option("--light", arguments->light, "the sun to follow (when the scene has several)");
  verb->add_option("--site", arguments->site,
                   "LATITUDE,LONGITUDE[,ELEVATION]: the place, for a scene whose sun is not "
                   "given by place and time (with --date; days at --utc-offset, default UTC)");
  verb->add_option("--date", arguments->date,
                   "the (first) day, YYYY-MM-DD (default: the date of the scene's sun time)");
  verb->add_option("--to", arguments->to, "the last day, YYYY-MM-DD (default: --date)");
  verb->add_option("--step", arguments->step,
                   "step length, e.g. 10min, 1h; steps fall on whole steps from local midnight "
                   "and each with the sun up counts one step (default 10min)");
  verb->add_option("--utc-offset", arguments->utc_offset,
                   "the clock of the days, e.g. +01:00 (default: the offset of the scene's sun "
                   "time)");
  verb->add_option("-o,--output", arguments->output,
                   "JSON of every face cut into parts by duration (default: standard output "
                   "when no other output is asked for)");
  verb->add_option("--report", arguments->report,
                   "CSV: object,face,face_area,area_ge_0h,area_ge_1h,... per face");
  verb->add_option("--svg", arguments->svg, "heat map SVG");
  verb->add_option("--view", arguments->view, "SVG view: top (plan) or faces (one panel each)")
      ->check(CLI::IsMember({"top", "faces"}));
  verb->add_option("--png", arguments->png, "heat map PNG in plan view");
  verb->add_option("--png-width", arguments->png_width, "PNG width in pixels (default 1200)")
      ->check(CLI::Range(16, 16384));
  verb->add_flag("--exact", arguments->exact,
                 "JSON: add exact rational coordinates (\"p/q\") under \"exact\" keys");
  verb->add_option("--receivers", arguments->receivers,
                   "only the faces of these objects: NAME[,NAME...], shell patterns; the "
                   "others still cast shadows");
  verb->add_option("--threshold", arguments->threshold,
                   "with --region: print the area of the region with at least this much sun "
                   "(e.g. 2h, 90min)");
  verb->add_option("--region", arguments->region,
                   "the region: the objects whose faces make it (NAME[,NAME...], shell "
                   "patterns), or a polygon of the site plan 'x,y x,y x,y ...' on the faces "
                   "facing up");
  verb->add_flag("--stats", arguments->stats, "print steps, faces and time per stage on stderr");
  verb->add_option("--dask", arguments->dask,
                   "run the study on the Dask cluster of this scheduler (tcp://host:8786), in "
                   "tiles of faces; the outputs are those of one process (docs/python.md)");
  verb->callback([arguments] { exit_status() = run_sun_hours(*arguments); });
}

}  // namespace penumbra::cli
