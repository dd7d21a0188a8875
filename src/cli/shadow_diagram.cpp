#include "shadow_diagram.h"

#include <iostream>

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

}  // namespace

int run_shadow_diagram(const Scene& scene, const DiagramArguments& arguments) {
  const SunPlacement& sun = studies::choose_sun(scene, arguments.scene, arguments.light);
  const std::vector<sun::ZonedInstant> times =
      diagram_times(arguments.times, sun.time.offset_minutes);
  std::vector<sun::UtcInstant> instants;
  for (const sun::ZonedInstant& t : times) instants.push_back(t.utc);
  const std::vector<studies::SunStep> steps = studies::sun_steps(sun, scene.north_deg, instants);

  // The scene lit by the sun alone, where it stands at each time.
  Scene stepped = scene;
  io::ShadowJsonOptions json_options;
  json_options.exact = arguments.exact;
  json_options.range_fraction = arguments.options.range_fraction;
  json_options.full_scale_lux = arguments.options.full_scale_lux;
  json_options.range_lux = arguments.options.range_lux;
  std::vector<io::DiagramTime> drawn;
  std::vector<std::string> skipped;
  Progress progress("shadow diagram", steps.size());
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const std::string when = sun::format_date_time(times[k].utc, times[k].offset_minutes);
    if (!steps[k].up()) {
      std::cerr << "penumbra: the sun is below the horizon at " << when << ": skipped\n";
      skipped.push_back(when);
      progress.advance();
      continue;
    }
    stepped.lights = {
        Light{sun.name, DirectionalLight{steps[k].direction, sun.illuminance}, sun.json_path}};
    const ShadowResult result = compute_shadows(stepped, arguments.options);
    drawn.push_back({when, steps[k].position.azimuth_deg, steps[k].position.elevation_deg,
                     io::shadow_json(stepped, result, json_options)});
    progress.advance();
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
