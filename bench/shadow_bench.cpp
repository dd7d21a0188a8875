// Shadows of generated city blocks (issue 3): N convex polyhedra (N/2 lots, each a
// ground tile and a building of random height, every fourth with a gabled roof),
// under one street lamp and under the sun, all faces, TBB across faces. Counters:
// faces, pairs possible and tested, pairs with a shadow, peak resident memory.

#include <benchmark/benchmark.h>

#include <sys/resource.h>
#include <cmath>
#include <map>
#include <random>
#include <sstream>

#include "penumbra/scene/load_scene.h"
#include "penumbra/shadow/shadow_map.h"

namespace {

using namespace penumbra;

// builds the city of `count` polyhedra on 10 m lots.
std::string city(int count) {
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
       << ", 6]], \"candela_per_metre\": 300}, {\"name\": \"tube_y\", \"linear\": [["
       << street << ", " << street - 5 << ", 6], [" << street << ", " << street + 5
       << ", 6]], \"candela_per_metre\": 300}]}";
  return text.str();
}

const Scene& scene_of(int count) {
  static std::map<int, Scene> scenes;
  auto it = scenes.find(count);
  if (it == scenes.end()) it = scenes.emplace(count, parse_scene(city(count), "city.json")).first;
  return it->second;
}

double peak_megabytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux: kilobytes
}

void shadows_of_city(benchmark::State& state, const std::string& light) {
  const Scene& scene = scene_of(static_cast<int>(state.range(0)));
  ShadowOptions options;
  options.light = light;
  ShadowStats stats;
  for (auto _ : state) {
    const ShadowResult result = compute_shadows(scene, options);
    stats = result.lights.front().stats;
    benchmark::DoNotOptimize(result.lights.front().faces.data());
  }
  state.counters["polyhedra"] = static_cast<double>(scene.objects.size());
  state.counters["faces"] = static_cast<double>(stats.faces);
  state.counters["pairs_possible"] = static_cast<double>(stats.pairs_possible);
  state.counters["pairs_tested"] = static_cast<double>(stats.pairs_tested);
  state.counters["pairs_shadowing"] = static_cast<double>(stats.pairs_shadowing);
  state.counters["beyond_range"] = static_cast<double>(stats.beyond_range);
  state.counters["peak_MB"] = peak_megabytes();
}

void BM_ShadowsLamp(benchmark::State& state) {
  shadows_of_city(state, "lamp");
}
void BM_ShadowsSun(benchmark::State& state) {
  shadows_of_city(state, "sun");
}
void BM_ShadowsTubeX(benchmark::State& state) {
  shadows_of_city(state, "tube_x");
}
void BM_ShadowsTubeY(benchmark::State& state) {
  shadows_of_city(state, "tube_y");
}

}  // namespace

BENCHMARK(BM_ShadowsLamp)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(10000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);
BENCHMARK(BM_ShadowsSun)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(10000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);
BENCHMARK(BM_ShadowsTubeX)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(10000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);
BENCHMARK(BM_ShadowsTubeY)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(10000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);
