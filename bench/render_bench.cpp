// The scanline renderer (issue 7) at 1920 x 1080, intervals 1, 3 and 5 (Nishita 1985
// section 3.3), on two scenes: the default scene (fixtures/scenes/office.json) and the
// 1,000-polyhedron city of city_scene.h (a street lamp, the sun and two tubes) seen from
// above one corner. BM_RenderPrepare times the preparation (visibility pass, exact
// shadows of every light on every face the camera sees, occluder lists, solver); BM_RenderShade/K
// the shading at interval K (TBB over scan lines) with its interpolation error against interval 1
// (max and mean, relative to the largest E in the image). Counters: process CPU seconds (all
// threads) per iteration beside the wall time. At interval 1, E at every 97th visible pixel is
// compared with the plain solver (every object an occluder).

#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>

#include "city_scene.h"
#include "penumbra/illuminance/scene_illuminance.h"
#include "penumbra/render/scanline_renderer.h"
#include "penumbra/scene/load_scene.h"

namespace {

using namespace penumbra;

enum class Which { office, city };

Scene load(Which which) {
  Scene scene;
  if (which == Which::office) {
    // Run from the repository's top directory, or point PENUMBRA_SOURCE_DIR at it.
    const char* top = std::getenv("PENUMBRA_SOURCE_DIR");
    scene = load_scene(std::string(top ? top : ".") + "/fixtures/scenes/office.json");
  } else {
    scene = parse_scene(bench::city_scene_json(1000), "city.json");
    // 500 lots on a 23 x 23 grid (230 m square); the eye 90 m above a point off the
    // south-west corner, looking at the middle (where the lamp and tubes are).
    scene.camera = Camera{{-40, -40, 90}, {115, 115, 0}, {0, 0, 1}, 50, 0, 0};
  }
  scene.camera->width = 1920;
  scene.camera->height = 1080;
  return scene;
}

struct Prepared {
  Scene scene;
  std::unique_ptr<render::ScanlineRenderer> renderer;
  std::unique_ptr<render::RenderedImage> exact;  // interval 1
};

Prepared& prepared(Which which) {
  static std::map<Which, Prepared> cache;
  auto it = cache.find(which);
  if (it == cache.end()) {
    it = cache.emplace(which, Prepared{load(which), nullptr, nullptr}).first;
    it->second.renderer =
        std::make_unique<render::ScanlineRenderer>(it->second.scene, *it->second.scene.camera);
  }
  return it->second;
}

const render::RenderedImage& exact_image(Which which) {
  Prepared& scene = prepared(which);
  if (!scene.exact)
    scene.exact = std::make_unique<render::RenderedImage>(scene.renderer->render({1, true, {}}));
  return *scene.exact;
}

double process_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6;
  };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

void BM_RenderPrepare(benchmark::State& state, Which which) {
  const Scene& scene = prepared(which).scene;
  const double cpu_before = process_cpu_seconds();
  for (auto _ : state) {
    const render::ScanlineRenderer renderer(scene, *scene.camera);
    benchmark::DoNotOptimize(&renderer);
  }
  state.counters["objects"] = static_cast<double>(scene.objects.size());
  state.counters["process_cpu_s"] =
      (process_cpu_seconds() - cpu_before) / static_cast<double>(state.iterations());
}

void BM_RenderShade(benchmark::State& state, Which which) {
  const int interval = static_cast<int>(state.range(0));
  const render::ScanlineRenderer& renderer = *prepared(which).renderer;
  const render::RenderedImage& exact = exact_image(which);
  render::RenderedImage image;
  const double cpu_before = process_cpu_seconds();
  for (auto _ : state) image = renderer.render({interval, true, {}});
  state.counters["process_cpu_s"] =
      (process_cpu_seconds() - cpu_before) / static_cast<double>(state.iterations());
  const double top = *std::max_element(exact.illuminance.begin(), exact.illuminance.end());
  double max_error = 0, sum = 0;
  std::size_t seen = 0;
  for (std::size_t pixel = 0; pixel < exact.illuminance.size(); ++pixel) {
    if (exact.visibility.objects[pixel] < 0) continue;
    const double error = std::abs(image.illuminance[pixel] - exact.illuminance[pixel]) / top;
    max_error = std::max(max_error, error);
    sum += error;
    ++seen;
  }
  if (interval == 1) {
    // Independent check of the occluder lists (shadow maps near each light, the broad
    // phase beyond the tubes' sphere of lighting): the plain solver, every object an
    // occluder, at every 97th visible pixel, relative to the largest E.
    const Prepared& scene = prepared(which);
    const illuminance::IlluminanceSolver plain(scene.scene);
    double deviation = 0;
    for (std::size_t pixel = 0; pixel < exact.illuminance.size(); pixel += 97) {
      const int i = static_cast<int>(pixel % exact.width),
                j = static_cast<int>(pixel / exact.width);
      const auto point = renderer.visible_point(i, j);
      if (!point) continue;
      const double value = plain.at((*point)[0], (*point)[1]).total;
      deviation = std::max(deviation, std::abs(value - exact.illuminance[pixel]) / top);
    }
    state.counters["plain_solver_deviation"] = deviation;
  }
  state.counters["evaluations"] = static_cast<double>(image.evaluations);
  state.counters["crossings"] = static_cast<double>(image.boundary_crossings);
  state.counters["max_error"] = max_error;
  state.counters["mean_error"] = sum / static_cast<double>(seen);
  state.counters["max_E_lux"] = top;
}

}  // namespace

BENCHMARK_CAPTURE(BM_RenderPrepare, office, Which::office)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_RenderShade, office, Which::office)
    ->Arg(1)
    ->Arg(3)
    ->Arg(5)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);
BENCHMARK_CAPTURE(BM_RenderPrepare, city, Which::city)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_RenderShade, city, Which::city)
    ->Arg(1)
    ->Arg(3)
    ->Arg(5)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);
