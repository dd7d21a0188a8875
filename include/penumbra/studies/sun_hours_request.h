#pragma once
// What a sun-hours study asks for, as `penumbra sun-hours` and the Python module take it
// (docs/sun-hours.md): the sun (one of the scene's, or one placed at a site), the days on
// a clock and the step; and the steps that follow from it. Errors name the command-line
// option (--date, --step, ...), which the Python module's keywords mirror.

#include <string>
#include <vector>

#include "penumbra/scene/scene.h"
#include "penumbra/sun/civil_time.h"

namespace penumbra::studies {

struct SunHoursRequest {
  std::string scene_path;  // the scene file, for messages
  std::string light;       // the sun to follow; the scene's only one when empty
  std::string site;        // "LATITUDE,LONGITUDE[,ELEVATION]": a sun at that place instead
  std::string date, to;    // the first and last days, YYYY-MM-DD (default: the sun's date)
  std::string step = "10min";
  std::string utc_offset;  // the clock of the days, e.g. +01:00 (default: the sun time's)
};

struct SunHoursPlan {
  SunPlacement sun;
  int offset_minutes = 0;     // the clock the days and times are on
  sun::UtcInstant from, end;  // the first midnight and the one after the last day
  sun::Duration step{0};
  std::vector<sun::UtcInstant> instants;  // whole steps from the first midnight, before end
};

// the most steps one study computes (a year at 10-minute steps is 52,560).
constexpr long long kMaxSunHoursSteps = 1'000'000;

// returns the sun (a light given by place and time) of scene, loaded from path, that name
// names, or its only one when name is empty. Throws InputError when there is none, when
// name names none, or when the scene has several and name is empty.
const SunPlacement& choose_sun(const Scene& scene, const std::string& path,
                               const std::string& name);

// returns the sun and steps of request on scene. Throws InputError for a bad date, step,
// offset or site, a missing sun, or more than kMaxSunHoursSteps steps.
SunHoursPlan plan_sun_hours(const Scene& scene, const SunHoursRequest& request);

}  // namespace penumbra::studies
