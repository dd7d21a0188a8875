#pragma once
// The shadow diagram of a sun study (issue 19, docs/sun-hours.md, "Shadow diagrams"): the
// shadows of the scene's sun at several times in one document, and the classic plan-view
// drawing of a planning application, every time's shadows over the faces turned up, a
// layer and a colour per time.

#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "penumbra/io/shadow_json.h"
#include "penumbra/studies/sun_hours.h"

namespace penumbra::io {

// One time of the diagram: when (ISO 8601), where the sun stood, and the shadow loops
// document of the scene lit by the sun alone at that time (io/shadow_json.h).
struct DiagramTime {
  std::string time;
  double azimuth_deg = 0, elevation_deg = 0;
  nlohmann::json shadows;
};

// The shadows of a scene lit by one of its suns alone, where the sun stands at given steps:
// the times of a diagram, computed one by one (by `shadows --times`, or by tasks of a Dask
// job, each a few times, penumbra.dask).
class SunShadows {
 public:
  SunShadows(const Scene& scene, const SunPlacement& sun, ShadowOptions options,
             ShadowJsonOptions json_options);
  // returns the diagram's time when (ISO 8601): the shadow document of the scene lit from
  // step.direction.
  DiagramTime at(const studies::SunStep& step, const std::string& when);
  // the warnings of the times computed so far, each once.
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  Scene stepped_;  // the scene with the sun as its only light, moved at each step
  SunPlacement sun_;
  ShadowOptions options_;
  ShadowJsonOptions json_options_;
  std::vector<std::string> warnings_;
};

// returns {"penumbra_shadow_diagram": 1, "sun": sun, "times": [{"azimuth_deg",
// "elevation_deg", "shadows", "time"}], "skipped": [times with the sun below the horizon]}.
nlohmann::json shadow_diagram_json(const std::string& sun, const std::vector<DiagramTime>& times,
                                   const std::vector<std::string>& skipped);

// writes the plan view: the faces turned up, lowest first, each outlined and then with its
// shadow at each time in the time's colour, in groups <g class="time-..."> (a layer per time
// for stylesheets and drawing programs), and a legend of the times (and of the skipped ones).
void write_shadow_diagram_svg(std::ostream& out, const nlohmann::json& diagram);

}  // namespace penumbra::io
