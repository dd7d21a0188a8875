#pragma once
// Generated city blocks shared by the benchmarks (the shadow benchmark of issue 3, the
// scanline renderer's of issue 7): N convex polyhedra on 10 m lots, N/2 lots each a
// ground tile and a building of random height (every fourth a gabled house), under a
// street lamp, the sun and two tubes.

#include <cmath>
#include <random>
#include <sstream>
#include <string>

namespace penumbra::bench {

// returns the scene file (JSON) of the city of `count` polyhedra; the lots cover
// [0, 10 side]^2 with side = ceil(sqrt(count / 2)), the buildings 6 to 30 m high.
inline std::string city_scene_json(int count) {
  std::mt19937 random(2024);  // fixed: the same city on every run
  std::uniform_int_distribution<int> storeys(2, 10);
  const int lots = count / 2;
  const int side = static_cast<int>(std::ceil(std::sqrt(lots)));
  std::ostringstream text;
  text << "{\"penumbra\": 1, \"objects\": [";
  for (int k = 0; k < lots; ++k) {
    const double x = 10.0 * (k % side), y = 10.0 * (k / side);
    const double height = 3.0 * storeys(random);
    text << (k ? "," : "") << "{\"name\": \"tile" << k << "\", \"box\": {\"min\": [" << x << ", "
         << y << ", -0.25], \"max\": [" << x + 10 << ", " << y + 10 << ", 0]}},";
    if (k % 4 == 3) {
      // A gabled house: a box with a ridge along y.
      text << "{\"name\": \"building" << k << "\", \"convex\": [";
      for (double px : {x + 2, x + 8})
        for (double py : {y + 2, y + 8})
          for (double pz : {0.0, height}) text << "[" << px << ", " << py << ", " << pz << "],";
      text << "[" << x + 5 << ", " << y + 2 << ", " << height + 3 << "], [" << x + 5 << ", "
           << y + 8 << ", " << height + 3 << "]]}";
    } else {
      text << "{\"name\": \"building" << k << "\", \"box\": {\"min\": [" << x + 2 << ", " << y + 2
           << ", 0], \"max\": [" << x + 8 << ", " << y + 8 << ", " << height << "]}}";
    }
  }
  const double centre = 5.0 * side;
  // Two tubes at 6 m over the gaps between lots (lot boundaries: no building there),
  // one along x and one along y, 10 m long.
  const double street = 10.0 * (side / 2);
  text << "], \"lights\": [{\"name\": \"lamp\", \"point\": [" << centre + 0.5 << ", "
       << centre + 0.5
       << ", 6], \"candela\": 2000}, {\"name\": \"sun\", \"directional\": [-0.3, -0.2, -0.93], "
          "\"illuminance\": 80000}, {\"name\": \"tube_x\", \"linear\": [["
       << street - 5 << ", " << street << ", 6], [" << street + 5 << ", " << street
       << ", 6]], \"candela_per_metre\": 300}, {\"name\": \"tube_y\", \"linear\": [[" << street
       << ", " << street - 5 << ", 6], [" << street << ", " << street + 5
       << ", 6]], \"candela_per_metre\": 300}]}";
  return text.str();
}

}  // namespace penumbra::bench
