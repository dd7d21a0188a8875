// Shadows of generated city blocks (issue 3, city_scene.h): N convex polyhedra (N/2
// lots, each a ground tile and a building of random height, every fourth with a gabled
// roof), under one street lamp, the sun and two tubes, all faces, TBB across faces. Counters:
// faces, pairs possible and tested, pairs with a shadow, peak resident memory.

#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <map>

#include "city_scene.h"
#include "penumbra/scene/load_scene.h"
#include "penumbra/shadow/exact_umbra.h"
#include "penumbra/shadow/shadow_map.h"

namespace {

using namespace penumbra;

const Scene& scene_of(int count) {
  static std::map<int, Scene> scenes;
  auto it = scenes.find(count);
  if (it == scenes.end())
    it = scenes.emplace(count, parse_scene(bench::city_scene_json(count), "city.json")).first;
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

// The exact joint umbrae of a tube (issue #17): the single-occluder shadows of every face,
// then exact_umbra on each face whose occluders' shadows overlap. The time against
// BM_ShadowsTube*'s is the cost of the joint umbrae; counters: faces with overlapping
// shadows, faces with a joint part, cells of the sweeps.
void joint_umbrae_of_city(benchmark::State& state, const std::string& light) {
  const Scene& scene = scene_of(static_cast<int>(state.range(0)));
  ShadowOptions options;
  options.light = light;
  std::size_t overlapping = 0, joint = 0, cells = 0;
  for (auto _ : state) {
    const ShadowResult result = compute_shadows(scene, options);
    const auto& tube = std::get<LinearLight>(scene.lights[result.lights.front().light].source);
    const Point3 start = to_exact(tube.start), end = to_exact(tube.end);
    overlapping = joint = cells = 0;
    for (std::size_t r = 0; r < result.receivers.size(); ++r) {
      const FaceShadow& shadow = result.lights.front().faces[r];
      if (!shadow.joint_occlusion) continue;
      ++overlapping;
      std::vector<UmbraOccluder> occluders;
      for (const OccluderShadow& o : shadow.occluders)
        occluders.push_back({&scene.objects[o.occluder].solid, o.polygon, o.umbra});
      const Receiver& receiver = result.receivers[r];
      const Face& face = scene.objects[receiver.object].solid.faces()[receiver.face];
      const ExactUmbra umbra = exact_umbra(face, start, end, occluders);
      joint += umbra.joint();
      cells += umbra.cells();
    }
  }
  state.counters["overlapping_faces"] = static_cast<double>(overlapping);
  state.counters["joint_faces"] = static_cast<double>(joint);
  state.counters["cells"] = static_cast<double>(cells);
}

// The same as the pipeline computes it (`shadows --joint-umbrae`): compute_shadows with
// ShadowOptions::joint_umbrae, the exact umbrae inside the per-face work, TBB across faces,
// as the single-occluder path is. Counter: faces with a joint part.
void joint_umbrae_pipeline(benchmark::State& state, const std::string& light) {
  const Scene& scene = scene_of(static_cast<int>(state.range(0)));
  ShadowOptions options;
  options.light = light;
  options.joint_umbrae = true;
  std::size_t joint = 0;
  for (auto _ : state) {
    const ShadowResult result = compute_shadows(scene, options);
    joint = 0;
    for (const FaceShadow& shadow : result.lights.front().faces) joint += bool(shadow.curved);
  }
  state.counters["joint_faces"] = static_cast<double>(joint);
}

void BM_JointUmbraePipelineTubeX(benchmark::State& state) {
  joint_umbrae_pipeline(state, "tube_x");
}
void BM_JointUmbraePipelineTubeY(benchmark::State& state) {
  joint_umbrae_pipeline(state, "tube_y");
}

void BM_JointUmbraeTubeX(benchmark::State& state) {
  joint_umbrae_of_city(state, "tube_x");
}
void BM_JointUmbraeTubeY(benchmark::State& state) {
  joint_umbrae_of_city(state, "tube_y");
}

}  // namespace

// the city sizes of the issue, one timed run each
static void city_sizes(benchmark::internal::Benchmark* benchmark) {
  benchmark->Arg(100)
      ->Arg(1000)
      ->Arg(10000)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->Iterations(1);
}

BENCHMARK(BM_ShadowsLamp)->Apply(city_sizes);
BENCHMARK(BM_ShadowsSun)->Apply(city_sizes);
BENCHMARK(BM_ShadowsTubeX)->Apply(city_sizes);
BENCHMARK(BM_ShadowsTubeY)->Apply(city_sizes);
BENCHMARK(BM_JointUmbraeTubeX)->Apply(city_sizes);
BENCHMARK(BM_JointUmbraeTubeY)->Apply(city_sizes);
BENCHMARK(BM_JointUmbraePipelineTubeX)->Apply(city_sizes);
BENCHMARK(BM_JointUmbraePipelineTubeY)->Apply(city_sizes);
