#include "penumbra/studies/sun_hours_request.h"

#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <variant>

#include "penumbra/base/input_error.h"

namespace penumbra::studies {
namespace {

// returns the UTC offset in minutes of text such as +01:00, -0530, Z.
int parse_offset(const std::string& text) {
  return sun::parse_date_time("2000-01-01T00:00" + text, std::nullopt, {"", "--utc-offset"})
      .offset_minutes;
}

// returns LATITUDE,LONGITUDE[,ELEVATION] of text.
sun::Site parse_site(const std::string& text) {
  std::vector<double> values;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    const std::string field = text.substr(start, comma - start);
    try {
      std::size_t used = 0;
      values.push_back(std::stod(field, &used));
      if (used != field.size()) throw std::invalid_argument(field);
    } catch (const std::exception&) {
      throw InputError("", "--site",
                       "expected LATITUDE,LONGITUDE[,ELEVATION], found '" + text + "'");
    }
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (values.size() < 2 || values.size() > 3 || !(std::abs(values[0]) <= 90) ||
      !(std::abs(values[1]) <= 180) || (values.size() == 3 && !std::isfinite(values[2])))
    throw InputError(
        "", "--site",
        "expected LATITUDE (-90..90),LONGITUDE (-180..180)[,ELEVATION m], found '" + text + "'");
  return {values[0], values[1], values.size() == 3 ? values[2] : 0.0};
}

// returns the sun of the study: the scene's, or with a site one at that place, with the
// illuminance of the scene's sun or directional light of that name (100,000 lx otherwise).
SunPlacement study_sun(const Scene& scene, const SunHoursRequest& request) {
  if (request.site.empty()) return choose_sun(scene, request.scene_path, request.light);
  SunPlacement sun;
  sun.name = request.light.empty() ? "sun" : request.light;
  sun.json_path = "--site";
  sun.illuminance = 100000;
  for (const SunPlacement& candidate : scene.suns)
    if (candidate.name == sun.name) sun = candidate;
  if (const Light* light = scene.find_light(sun.name))
    if (const auto* directional = std::get_if<DirectionalLight>(&light->source))
      sun.illuminance = directional->illuminance;
  sun.site = parse_site(request.site);
  return sun;
}

}  // namespace

const SunPlacement& choose_sun(const Scene& scene, const std::string& path,
                               const std::string& name) {
  if (scene.suns.empty())
    throw InputError(path, "lights",
                     "no light is a sun given by place and time (\"sun\": {\"latitude\", ...})");
  if (name.empty()) {
    if (scene.suns.size() > 1)
      throw InputError("", "--light", "the scene has several suns: name one");
    return scene.suns.front();
  }
  for (const SunPlacement& candidate : scene.suns)
    if (candidate.name == name) return candidate;
  throw InputError("", "--light", "no sun named '" + name + "'");
}

SunHoursPlan plan_sun_hours(const Scene& scene, const SunHoursRequest& request) {
  SunHoursPlan plan;
  plan.sun = study_sun(scene, request);
  // Dates are days on the clock of the scene's sun time unless the offset says otherwise.
  plan.offset_minutes =
      request.utc_offset.empty() ? plan.sun.time.offset_minutes : parse_offset(request.utc_offset);
  if (request.date.empty() && plan.sun.json_path == "--site")
    throw InputError("", "--date", "is needed with --site (the scene gives no date)");
  const sun::CivilDate first =
      request.date.empty()
          ? sun::civil_date_time(plan.sun.time.utc, plan.sun.time.offset_minutes).date
          : sun::parse_date(request.date, {"", "--date"});
  const sun::CivilDate last =
      request.to.empty() ? first : sun::parse_date(request.to, {"", "--to"});
  plan.from = sun::local_midnight(first, plan.offset_minutes);
  plan.end = sun::local_midnight(last, plan.offset_minutes) + std::chrono::hours(24);
  if (plan.end <= plan.from) throw InputError("", "--to", "is before --date");
  plan.step = sun::parse_step(request.step, {"", "--step"});
  if ((plan.end - plan.from) / plan.step >= kMaxSunHoursSteps)
    throw InputError("", "--step", "more than 10^6 steps: use a longer step or fewer days");
  // The steps of the days: from the first midnight up to, not including, the last one.
  plan.instants =
      sun::step_instants({plan.from, plan.offset_minutes}, plan.end - sun::Duration(1), plan.step);
  return plan;
}

}  // namespace penumbra::studies
