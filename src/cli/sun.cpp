// penumbra sun SCENE: the sun of the scene (a light given by place and time, docs/sun.md)
// through a day or a range of times: its azimuth, elevation and the direction its light
// travels in the model frame, as CSV.

#include <iostream>
#include <memory>
#include <string>

#include "penumbra/base/atomic_file.h"
#include "penumbra/base/csv.h"
#include "penumbra/base/input_error.h"
#include "penumbra/studies/sun_hours_request.h"
#include "penumbra/sun/solar_position.h"
#include "verbs.h"

namespace penumbra::cli {
namespace {

struct SunArguments {
  std::string scene;
  std::string light;
  std::string from, to;
  std::string step = "10min";
  std::string output;
};

// the most rows one command writes (a year at one-minute steps is 525,600).
constexpr std::size_t kMaxSteps = 1'000'000;

void write_rows(std::ostream& out, const SunPlacement& sun, double north_deg,
                const std::vector<sun::UtcInstant>& instants, int offset_minutes) {
  CsvWriter csv(out, {"time", "azimuth_deg", "elevation_deg", "dx", "dy", "dz"});
  sun::SolarPositionSolver solver(sun.site, sun.atmosphere);
  for (const sun::UtcInstant instant : instants) {
    const sun::SolarPosition seen = solver.at(instant);
    const Vec3d direction = sun::light_direction(seen, north_deg);
    csv.text(sun::format_date_time(instant, offset_minutes));
    csv.number(seen.azimuth_deg).number(seen.elevation_deg);
    for (double component : direction) csv.number(component);
    csv.end_row();
  }
}

int run_sun(const SunArguments& arguments) {
  const Scene& scene = load_scene_until_exit(arguments.scene);
  for (const std::string& warning : scene.warnings)
    std::cerr << "penumbra: warning: " << warning << "\n";
  const SunPlacement* sun = &studies::choose_sun(scene, arguments.scene, arguments.light);
  // Times without an offset are on the clock of the scene's sun time (issue 19).
  const int offset = sun->time.offset_minutes;
  const sun::CivilDate day = sun::civil_date_time(sun->time.utc, offset).date;
  const sun::ZonedInstant from = arguments.from.empty()
                                     ? sun::ZonedInstant{sun::local_midnight(day, offset), offset}
                                     : sun::parse_date_time(arguments.from, offset, {"", "--from"});
  const sun::UtcInstant to = arguments.to.empty()
                                 ? sun::local_midnight(day, offset) + std::chrono::hours(24)
                                 : sun::parse_date_time(arguments.to, offset, {"", "--to"}).utc;
  const sun::Duration step = sun::parse_step(arguments.step, {"", "--step"});
  if (to < from.utc) throw InputError("", "--to", "is before --from");
  if ((to - from.utc) / step >= static_cast<long long>(kMaxSteps))
    throw InputError("", "--step", "more than 10^6 times: use a longer step or a shorter range");
  const std::vector<sun::UtcInstant> instants = sun::step_instants(from, to, step);

  if (arguments.output.empty() || arguments.output == "-")
    write_rows(std::cout, *sun, scene.north_deg, instants, from.offset_minutes);
  else
    write_atomically(arguments.output, [&](std::ostream& out) {
      write_rows(out, *sun, scene.north_deg, instants, from.offset_minutes);
    });
  return 0;
}

}  // namespace

void register_sun(CLI::App& app) {
  CLI::App* verb = app.add_subcommand(
      "sun", "the scene's sun through time: azimuth, elevation and light direction (CSV)");
  auto arguments = std::make_shared<SunArguments>();
  verb->add_option("SCENE", arguments->scene, "scene file (JSON) with a \"sun\" light")->required();
  verb->add_option("--light", arguments->light, "the sun to follow (when the scene has several)");
  verb->add_option("--from", arguments->from,
                   "first time, ISO 8601 (default: local midnight of the scene's date; "
                   "without an offset, the scene's)");
  verb->add_option("--to", arguments->to, "last time (default: the next midnight)");
  verb->add_option("--step", arguments->step,
                   "step length, e.g. 10min, 1h, 1h30min; times fall on whole steps from "
                   "local midnight of --from's date (default 10min)");
  verb->add_option("-o,--output", arguments->output,
                   "CSV of time,azimuth_deg,elevation_deg,dx,dy,dz (default: standard output)");
  verb->callback([arguments] { exit_status() = run_sun(*arguments); });
}

}  // namespace penumbra::cli
