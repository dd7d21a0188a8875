#pragma once
// Scenes for the radiosity tests, written out in the tests' own terms.

#include <sstream>
#include <string>

#include "penumbra/scene/load_scene.h"

namespace penumbra::test {

// A closed room [0, size]^3 of six slabs 0.1 m thick, all of reflectance rho, lit by the
// point light `lamp_json` (a scene `lights` entry), with `extra` (e.g. `, "camera": {...}`)
// added to the scene's top level. Each slab's inner face is exactly one face of the room.
inline Scene closed_room(double size, double rho, const std::string& lamp_json,
                         const std::string& extra = "") {
  std::ostringstream json;
  json.precision(17);
  const double t = 0.1, s = size;
  const auto box = [&](const char* name, double x0, double y0, double z0, double x1, double y1,
                       double z1) {
    json << "{\"name\": \"" << name << "\", \"material\": \"grey\", \"box\": {\"min\": [" << x0
         << ',' << y0 << ',' << z0 << "], \"max\": [" << x1 << ',' << y1 << ',' << z1 << "]}}";
  };
  json << "{\"penumbra\": 1, \"materials\": {\"grey\": {\"reflectance\": " << rho
       << "}}, \"objects\": [";
  box("floor", 0, 0, -t, s, s, 0);
  json << ',';
  box("ceiling", 0, 0, s, s, s, s + t);
  json << ',';
  box("west", -t, 0, 0, 0, s, s);
  json << ',';
  box("east", s, 0, 0, s + t, s, s);
  json << ',';
  box("south", 0, -t, 0, s, 0, s);
  json << ',';
  box("north", 0, s, 0, s, s + t, s);
  json << "], \"lights\": [" << lamp_json << "]" << extra << "}";
  return parse_scene(json.str(), "closed-room.json");
}

}  // namespace penumbra::test
