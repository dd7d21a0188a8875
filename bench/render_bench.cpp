// The scanline renderer (issue 7) on the default scene (fixtures/scenes/office.json) at
// 1920 x 1080, intervals 1, 3 and 5 (Nishita 1985 section 3.3): the time to shade (TBB
// over scan lines), with the visibility pass and the exact shadows prepared once, and the
// interpolation error of intervals 3 and 5 against interval 1 (max and mean, relative
// to the largest E in the image). BM_RenderPrepare times the preparation alone.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>

#include "penumbra/render/scanline_renderer.h"
#include "penumbra/scene/load_scene.h"

namespace {

using namespace penumbra;

const Scene& office() {
  static std::unique_ptr<Scene> scene;
  if (!scene) {
    // Run from the repository's top directory, or point PENUMBRA_SOURCE_DIR at it.
    const char* top = std::getenv("PENUMBRA_SOURCE_DIR");
    scene = std::make_unique<Scene>(
        load_scene(std::string(top ? top : ".") + "/fixtures/scenes/office.json"));
    scene->camera->width = 1920;
    scene->camera->height = 1080;
  }
  return *scene;
}

const render::ScanlineRenderer& renderer() {
  static const render::ScanlineRenderer prepared(office(), *office().camera);
  return prepared;
}

const render::RenderedImage& exact_image() {
  static const render::RenderedImage image = renderer().render({1, true});
  return image;
}

void BM_RenderPrepare(benchmark::State& state) {
  for (auto _ : state) {
    const render::ScanlineRenderer prepared(office(), *office().camera);
    benchmark::DoNotOptimize(&prepared);
  }
}

void BM_RenderShade(benchmark::State& state) {
  const int interval = static_cast<int>(state.range(0));
  render::RenderedImage image;
  for (auto _ : state) image = renderer().render({interval, true});
  const render::RenderedImage& exact = exact_image();
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
  state.counters["evaluations"] = static_cast<double>(image.evaluations);
  state.counters["max_error"] = max_error;
  state.counters["mean_error"] = sum / static_cast<double>(seen);
}

BENCHMARK(BM_RenderPrepare)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_RenderShade)->Arg(1)->Arg(3)->Arg(5)->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace
