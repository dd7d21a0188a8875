// The Whitted ray tracer (issue 8) on the paper's rebuilt scenes (fixtures/scenes/
// whitted-fig6.json, whitted-fig7.json) at 1024 x 768:
//   - shading: every ray of one sample per pixel centre, the whole ray tree, one thread;
//   - bare traversal: the very same rays (recorded while shading) through Embree alone,
//     so the ratio of the two rates is the cost of shading and ray generation;
//   - the full parallel render (TBB over tiles);
//   - anti-aliasing at equal quality: adaptive (Whitted section 3) against fixed k x k
//     supersampling, each compared with a 8 x 8 supersampled reference (smaller image).
//   - Bézier patches (issue #23): the teapot scenes (bezier-teapot.json, bezier-glass.json)
//     at 640 x 480, adaptive, with the patches intersected against the same scene traced as
//     its tessellation (14,280 triangles).
// Counters: rays and rays per second; for anti-aliasing the camera rays per pixel and the
// RMS error of the 8-bit sRGB image against the reference.

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>

#include "penumbra/base/tone_map.h"
#include "penumbra/raytrace/render.h"
#include "penumbra/scene/camera_frame.h"
#include "penumbra/scene/load_scene.h"
#include "penumbra/scene/scene.h"

namespace {

using namespace penumbra;
using namespace penumbra::raytrace;

const char* const kFigures[] = {"whitted-fig6", "whitted-fig7", "bezier-teapot", "bezier-glass"};

// loads a fixture scene once and keeps it (the tracer holds a reference to it).
const Scene& figure(int index, int width, int height) {
  static std::map<std::string, std::unique_ptr<Scene>> scenes;
  const std::string key =
      std::string(kFigures[index]) + std::to_string(width) + "x" + std::to_string(height);
  auto& scene = scenes[key];
  if (!scene) {
    // Run from the repository's top directory, or point PENUMBRA_SOURCE_DIR at it.
    const char* top = std::getenv("PENUMBRA_SOURCE_DIR");
    scene = std::make_unique<Scene>(
        load_scene(std::string(top ? top : ".") + "/fixtures/scenes/" + kFigures[index] + ".json"));
    scene->camera->width = width;
    scene->camera->height = height;
  }
  return *scene;
}

// traces one ray tree through every pixel centre, serially.
RayCounts trace_centres(const RayTracer& tracer, const Camera& camera, std::vector<Ray>* log) {
  const CameraFrame pinhole(camera);
  RayCounts counts;
  counts.log = log;
  for (int j = 0; j < camera.height; ++j)
    for (int i = 0; i < camera.width; ++i)
      benchmark::DoNotOptimize(
          tracer.trace(pinhole.eye(), pinhole.unit_direction(i + 0.5, j + 0.5), 0, counts));
  return counts;
}

void shading(benchmark::State& state) {
  const Scene& scene = figure(static_cast<int>(state.range(0)), 1024, 768);
  const RayTracer tracer(scene);
  std::uint64_t rays = 0;
  for (auto _ : state) rays += trace_centres(tracer, *scene.camera, nullptr).total();
  state.SetLabel(kFigures[state.range(0)]);
  state.counters["rays"] = static_cast<double>(rays) / static_cast<double>(state.iterations());
  state.counters["rays_per_s"] =
      benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kIsRate);
}

void bare_traversal(benchmark::State& state) {
  const Scene& scene = figure(static_cast<int>(state.range(0)), 1024, 768);
  const RayTracer tracer(scene);
  std::vector<Ray> rays;
  trace_centres(tracer, *scene.camera, &rays);
  std::uint64_t cast = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(tracer.embree_scene().traverse(rays));
    cast += rays.size();
  }
  state.SetLabel(kFigures[state.range(0)]);
  state.counters["rays"] = static_cast<double>(rays.size());
  state.counters["rays_per_s"] =
      benchmark::Counter(static_cast<double>(cast), benchmark::Counter::kIsRate);
}

void parallel_render(benchmark::State& state) {
  const Scene& scene = figure(static_cast<int>(state.range(0)), 1024, 768);
  const RayTracer tracer(scene);
  RenderOptions options;
  options.anti_aliasing = state.range(1) ? AntiAliasing::adaptive : AntiAliasing::none;
  options.progress = false;
  std::uint64_t rays = 0;
  for (auto _ : state) rays += render(tracer, *scene.camera, options).counts.total();
  state.SetLabel(std::string(kFigures[state.range(0)]) +
                 (state.range(1) ? " adaptive" : " centres"));
  state.counters["rays_per_s"] =
      benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kIsRate);
}

// range(0): the teapot scene; range(1): 0 the patches, 1 their tessellation.
void bezier_patches(benchmark::State& state) {
  const Scene& scene = figure(static_cast<int>(state.range(0)), 640, 480);
  TraceOptions trace;
  trace.patches = state.range(1) ? PatchSurfaces::tessellated : PatchSurfaces::exact;
  const RayTracer tracer(scene, trace);
  RenderOptions options;
  options.progress = false;
  std::uint64_t rays = 0;
  for (auto _ : state) rays += render(tracer, *scene.camera, options).counts.total();
  state.SetLabel(std::string(kFigures[state.range(0)]) +
                 (state.range(1) ? " tessellated" : " patches"));
  state.counters["rays_per_s"] =
      benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kIsRate);
}

// the RMS difference of two images in 8-bit sRGB levels at a common exposure.
double rms_levels(const RenderedImage& image, const RenderedImage& reference) {
  const auto a = to_srgb8(image.pixels, reference.exposure);
  const auto b = to_srgb8(reference.pixels, reference.exposure);
  double sum = 0;
  for (std::size_t k = 0; k < a.size(); ++k) sum += (a[k] - b[k]) * (a[k] - b[k]);
  return std::sqrt(sum / static_cast<double>(a.size()));
}

// range(0): figure; range(1): 0 adaptive, k > 0 fixed k x k grid; range(2): adaptive depth.
void anti_aliasing_quality(benchmark::State& state) {
  const int width = 256, height = 192;
  const Scene& scene = figure(static_cast<int>(state.range(0)), width, height);
  const RayTracer tracer(scene);
  static std::map<long, RenderedImage> references;
  RenderedImage& reference = references[state.range(0)];
  if (reference.pixels.empty()) {
    RenderOptions options;
    options.anti_aliasing = AntiAliasing::fixed;
    options.fixed_grid = 8;
    options.progress = false;
    reference = render(tracer, *scene.camera, options);
  }
  RenderOptions options;
  options.progress = false;
  options.exposure = reference.exposure;
  if (state.range(1) > 0) {
    options.anti_aliasing = AntiAliasing::fixed;
    options.fixed_grid = static_cast<int>(state.range(1));
  } else {
    options.anti_aliasing = AntiAliasing::adaptive;
    options.aa_depth = static_cast<int>(state.range(2));
  }
  RenderedImage image;
  for (auto _ : state) image = render(tracer, *scene.camera, options);
  state.SetLabel(std::string(kFigures[state.range(0)]) +
                 (state.range(1) > 0 ? " fixed " + std::to_string(state.range(1)) + "x" +
                                           std::to_string(state.range(1))
                                     : " adaptive depth " + std::to_string(state.range(2))));
  state.counters["camera_rays_per_pixel"] =
      static_cast<double>(image.counts.camera) / (width * height);
  state.counters["rays"] = static_cast<double>(image.counts.total());
  state.counters["rms_8bit"] = rms_levels(image, reference);
}

}  // namespace

BENCHMARK(shading)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(bare_traversal)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(parallel_render)
    ->Args({0, 0})
    ->Args({1, 0})
    ->Args({0, 1})
    ->Args({1, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(bezier_patches)
    ->Args({2, 0})
    ->Args({2, 1})
    ->Args({3, 0})
    ->Args({3, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(anti_aliasing_quality)
    ->Args({0, 0, 2})
    ->Args({0, 0, 3})
    ->Args({0, 2, 0})
    ->Args({0, 3, 0})
    ->Args({0, 4, 0})
    ->Args({1, 0, 2})
    ->Args({1, 0, 3})
    ->Args({1, 2, 0})
    ->Args({1, 3, 0})
    ->Args({1, 4, 0})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
