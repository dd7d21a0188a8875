#include "shadow_diagram.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>

#include "dask_driver.h"
#include "penumbra/base/atomic_file.h"
#include "penumbra/base/input_error.h"
#include "penumbra/base/progress.h"
#include "penumbra/io/shadow_diagram.h"
#include "penumbra/io/shadow_json.h"
#include "penumbra/studies/sun_hours.h"
#include "penumbra/studies/sun_hours_request.h"
#include "verbs.h"

namespace penumbra::cli {
namespace {

// the most times one diagram draws.
constexpr std::size_t kMaxTimes = 1000;

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    fields.push_back(text.substr(start, comma - start));
    if (comma == std::string::npos) return fields;
    start = comma + 1;
  }
}

// returns the instants of --times: FROM,TO,STEP (steps from local midnight of FROM's date,
// as `penumbra sun` lists them) or a list of times; times without an offset are on the clock
// of the scene's sun time.
std::vector<sun::ZonedInstant> diagram_times(const std::string& text, int offset) {
  const std::vector<std::string> fields = split(text);
  const sun::TextOrigin origin{"", "--times"};
  std::vector<sun::ZonedInstant> times;
  const bool range = fields.size() == 3 && fields[2].find('T') == std::string::npos &&
                     fields[2].find('-') == std::string::npos;
  if (range) {
    const sun::ZonedInstant from = sun::parse_date_time(fields[0], offset, origin);
    const sun::UtcInstant to = sun::parse_date_time(fields[1], offset, origin).utc;
    const sun::Duration step = sun::parse_step(fields[2], origin);
    if (to < from.utc) throw InputError("", "--times", "the last time is before the first");
    if ((to - from.utc) / step >= static_cast<long long>(kMaxTimes))
      throw InputError("", "--times", "more than 1000 times: use a longer step");
    for (const sun::UtcInstant t : sun::step_instants(from, to, step))
      times.push_back({t, from.offset_minutes});
  } else {
    if (fields.size() > kMaxTimes) throw InputError("", "--times", "more than 1000 times");
    for (const std::string& field : fields)
      times.push_back(sun::parse_date_time(field, offset, origin));
  }
  if (times.empty()) throw InputError("", "--times", "no time falls in the range");
  return times;
}

// computes the times drawn on the Dask cluster of arguments.dask (dask_driver.h), a few
// times a task: the documents one process makes.
std::vector<io::DiagramTime> diagram_on_dask(const Scene& scene, const DiagramArguments& arguments,
                                             const SunPlacement& sun,
                                             const std::vector<studies::SunStep>& steps,
                                             const std::vector<std::size_t>& up,
                                             const std::vector<std::string>& when) {
  nlohmann::json request = {
      {"job", "shadow_times"},
      {"scene", std::filesystem::absolute(arguments.scene).string()},
      {"light", sun.name},
      {"exact", arguments.exact},
      {"range_fraction", arguments.options.range_fraction},
      {"full_scale_lux", arguments.options.full_scale_lux},
      {"range_lux", arguments.options.range_lux ? nlohmann::json(*arguments.options.range_lux)
                                                : nlohmann::json()},
      {"receivers", nullptr},
      {"steps", nlohmann::json::array()}};
  if (arguments.options.receivers) {
    std::set<std::string> owners;
    for (const Receiver& receiver : *arguments.options.receivers)
      owners.insert(scene.objects[receiver.object].face_owner());
    request["receivers"] = owners;
  }
  for (std::size_t k : up)
    request["steps"].push_back({when[k], steps[k].position.azimuth_deg,
                                steps[k].position.elevation_deg, steps[k].direction[0],
                                steps[k].direction[1], steps[k].direction[2]});
  const std::string file = run_on_dask(arguments.dask, request);
  nlohmann::json documents;
  try {
    documents = nlohmann::json::parse(std::ifstream(file)).at("documents");
  } catch (const nlohmann::json::exception& error) {
    throw InputError(file, "", std::string("the driver's result is not its JSON: ") + error.what());
  }
  if (!documents.is_array() || documents.size() != up.size())
    throw InputError(file, "documents", "expected " + std::to_string(up.size()) + " documents");
  std::vector<io::DiagramTime> drawn;
  for (std::size_t k = 0; k < up.size(); ++k)
    drawn.push_back({when[up[k]], steps[up[k]].position.azimuth_deg,
                     steps[up[k]].position.elevation_deg, std::move(documents[k])});
  return drawn;
}

}  // namespace

int run_shadow_diagram(const Scene& scene, const DiagramArguments& arguments) {
  const SunPlacement& sun = studies::choose_sun(scene, arguments.scene, arguments.light);
  const std::vector<sun::ZonedInstant> times =
      diagram_times(arguments.times, sun.time.offset_minutes);
  std::vector<sun::UtcInstant> instants;
  for (const sun::ZonedInstant& t : times) instants.push_back(t.utc);
  const std::vector<studies::SunStep> steps = studies::sun_steps(sun, scene.north_deg, instants);

  const io::ShadowJsonOptions json_options =
      io::json_options_of(arguments.options, arguments.exact);
  std::vector<std::size_t> up;  // the steps drawn
  std::vector<std::string> when(steps.size()), skipped;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    when[k] = sun::format_date_time(times[k].utc, times[k].offset_minutes);
    if (steps[k].up()) {
      up.push_back(k);
    } else {
      std::cerr << "penumbra: the sun is below the horizon at " << when[k] << ": skipped\n";
      skipped.push_back(when[k]);
    }
  }
  std::vector<io::DiagramTime> drawn;
  if (!arguments.dask.empty()) {
    drawn = diagram_on_dask(scene, arguments, sun, steps, up, when);
  } else {
    io::SunShadows shadows(scene, sun, arguments.options, json_options);
    Progress progress("shadow diagram", up.size());
    for (std::size_t k : up) {
      drawn.push_back(shadows.at(steps[k], when[k]));
      progress.advance();
    }
  }
  const nlohmann::json diagram = io::shadow_diagram_json(sun.name, drawn, skipped);
  if (arguments.output.empty() || arguments.output == "-")
    std::cout << io::format_json(diagram);
  else
    write_atomically(arguments.output, [&](std::ostream& out) { out << io::format_json(diagram); });
  if (!arguments.svg.empty())
    write_atomically(arguments.svg,
                     [&](std::ostream& out) { io::write_shadow_diagram_svg(out, diagram); });
  return 0;
}

}  // namespace penumbra::cli
