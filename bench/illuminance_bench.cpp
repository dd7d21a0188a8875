// Evaluations per second of the illuminance kernels (docs/performance.md, "Illuminance
// kernels"): point sources, the linear-source closed form and its adaptive quadrature;
// and of whole scene queries with exact visibility (section "Illuminance in a scene").

#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "penumbra/illuminance/linear_source.h"
#include "penumbra/illuminance/point_source.h"
#include "penumbra/illuminance/scene_illuminance.h"
#include "penumbra/illuminance/specular.h"

namespace {

using penumbra::Vec3d;
namespace il = penumbra::illuminance;

// Receiving points on a 6 m x 4 m floor lit by the default scene's tube (2,1,2.8)-(2,3,2.8);
// a fixed seed keeps the workload identical between runs.
struct Workload {
  std::vector<Vec3d> points;
  Workload() {
    std::mt19937_64 engine{1985};
    std::uniform_real_distribution<double> x(0, 6), y(0, 4);
    for (int i = 0; i < 1024; ++i) points.push_back({x(engine), y(engine), 0});
  }
};
const Workload workload;
const Vec3d floor_normal{0, 0, 1};

void point_isotropic(benchmark::State& state) {
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        il::point_illuminance(workload.points[i++ & 1023], floor_normal, {1, 3, 2.5}, 120));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(point_isotropic);

void point_with_distribution(benchmark::State& state) {
  std::size_t i = 0;
  auto cosine_lamp = [](const Vec3d& direction) {
    return direction[2] < 0 ? -1000 * direction[2] : 0.0;
  };
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        il::point_illuminance(workload.points[i++ & 1023], floor_normal, {3, 2, 2.8}, cosine_lamp));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(point_with_distribution);

// Tube parallel to the floor (the paper's Case A) and an oblique one (Case C).
const Vec3d parallel_a{2, 1, 2.8}, parallel_b{2, 3, 2.8};
const Vec3d oblique_a{1, 0.5, 2.8}, oblique_b{3, 3, 1.9};

void linear_closed_form_parallel(benchmark::State& state) {
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(il::linear_illuminance(workload.points[i++ & 1023], floor_normal,
                                                    parallel_a, parallel_b, 150));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(linear_closed_form_parallel);

void linear_closed_form_oblique(benchmark::State& state) {
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(il::linear_illuminance(workload.points[i++ & 1023], floor_normal,
                                                    oblique_a, oblique_b, 150));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(linear_closed_form_oblique);

void linear_closed_form_three_visible_parts(benchmark::State& state) {
  const std::vector<il::SourceInterval> visible{{0, 0.2}, {0.35, 0.6}, {0.8, 1}};
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(il::linear_illuminance(workload.points[i++ & 1023], floor_normal,
                                                    oblique_a, oblique_b, 150, visible));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(linear_closed_form_three_visible_parts);

// The quadrature at the tolerance given by the argument (1e-6 and the default 1e-12).
void linear_quadrature_oblique(benchmark::State& state) {
  il::QuadratureOptions options;
  options.relative_tolerance = state.range(0) == 6 ? 1e-6 : 1e-12;
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(il::linear_illuminance_quadrature(
        workload.points[i++ & 1023], floor_normal, oblique_a, oblique_b, 150, options));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(linear_quadrature_oblique)->Arg(6)->Arg(12);

// Points 2 cm under the tube (h small: the quadrature must resolve a peak of width h).
void linear_close_to_the_tube(benchmark::State& state) {
  const bool closed = state.range(0) == 0;
  std::size_t i = 0;
  for (auto _ : state) {
    const Vec3d& q = workload.points[i++ & 1023];
    const Vec3d p{2 + 0.01 * (q[0] - 3), 1 + 0.5 * q[1], 2.78};
    benchmark::DoNotOptimize(
        closed ? il::linear_illuminance(p, floor_normal, parallel_a, parallel_b, 150)
               : il::linear_illuminance_quadrature(p, floor_normal, parallel_a, parallel_b, 150));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  state.SetLabel(closed ? "closed form" : "quadrature 1e-12");
}
BENCHMARK(linear_close_to_the_tube)->Arg(0)->Arg(1);

void linear_specular_oblique(benchmark::State& state) {
  const il::PhongSpecular glossy{0.3, 30};
  il::QuadratureOptions options;
  options.relative_tolerance = 1e-6;
  std::size_t i = 0;
  for (auto _ : state) {
    const Vec3d& p = workload.points[i++ & 1023];
    benchmark::DoNotOptimize(il::linear_specular(p, floor_normal, {0, 0.6, 0.8}, oblique_a,
                                                 oblique_b, 150, glossy, options));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(linear_specular_oblique);

// === Scene queries with exact visibility: a 4 m tube, a lamp and the sun over a 12 m x 12 m
// floor with 100 occluders: 30 tables (1 m x 0.6 m tops at 0.7 m, which make umbrae under
// them) and 70 boxes of 0.3 m floating between 1 m and 2.5 m (which make penumbrae).

penumbra::ConvexPolyhedron box_solid(const Vec3d& lo, const Vec3d& hi) {
  std::vector<penumbra::Point3> corners;
  for (int k = 0; k < 8; ++k)
    corners.push_back(penumbra::to_exact(
        {(k & 1) ? hi[0] : lo[0], (k & 2) ? hi[1] : lo[1], (k & 4) ? hi[2] : lo[2]}));
  return penumbra::ConvexPolyhedron::hull(corners);
}

enum class Visibility { unshadowed, penumbra, umbra };

struct SceneWorkload {
  penumbra::Scene scene;
  std::unique_ptr<il::IlluminanceSolver> solver;
  std::vector<Vec3d> points[3];  // receiving points on the floor, by visibility of the tube

  SceneWorkload() {
    std::mt19937_64 engine{171};  // fixed seed: the same scene and points every run
    std::uniform_real_distribution<double> coordinate(0, 12), height(1, 2.5);
    for (int k = 0; k < 100; ++k) {
      const double x = coordinate(engine), y = coordinate(engine);
      const bool table = k < 30;
      const Vec3d lo = table ? Vec3d{x, y, 0.7} : Vec3d{x, y, height(engine)};
      const Vec3d hi =
          table ? Vec3d{x + 1, y + 0.6, 0.74} : Vec3d{lo[0] + 0.3, lo[1] + 0.3, lo[2] + 0.3};
      scene.objects.push_back(
          {"occluder" + std::to_string(k), "box", 0, box_solid(lo, hi), {}, ""});
    }
    scene.lights.push_back({"tube", penumbra::LinearLight{{4, 6, 3}, {8, 6, 3}, 150}, ""});
    solver = std::make_unique<il::IlluminanceSolver>(scene);
    // Classify random floor points by the exact visible parts of the tube.
    const Vec3d up{0, 0, 1};
    while (points[0].size() < 256 || points[1].size() < 256 || points[2].size() < 256) {
      const Vec3d p{coordinate(engine), coordinate(engine), 0};
      const auto visible = solver->visible_parts(0, p, up);
      const bool whole = visible.size() == 1 && visible[0].low == 0 && visible[0].high == 1;
      auto& bucket = points[visible.empty() ? 2 : whole ? 0 : 1];
      if (bucket.size() < 256) bucket.push_back(p);
    }
  }
};
const SceneWorkload& scene_workload() {
  static const SceneWorkload shared;
  return shared;
}

void scene_linear_100_occluders(benchmark::State& state) {
  const SceneWorkload& scene = scene_workload();
  const auto& points = scene.points[state.range(0)];
  std::size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(scene.solver->light_at(0, points[i++ & 255], {0, 0, 1}));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  static const char* labels[] = {"unshadowed", "penumbra", "umbra"};
  state.SetLabel(labels[state.range(0)]);
}
BENCHMARK(scene_linear_100_occluders)->Arg(0)->Arg(1)->Arg(2);

// The same occluders with a point lamp over the tube's centre and with the sun, at the
// tube's unshadowed points (culled pairs) and at its umbra points (under tables: blocked).
void scene_point_and_sun_100_occluders(benchmark::State& state) {
  static const il::IlluminanceSolver solver = [] {
    penumbra::Scene scene = scene_workload().scene;
    scene.lights.clear();
    scene.lights.push_back(
        {"lamp",
         penumbra::PointLight{
             {6, 6, 3}, penumbra::photometry::make_isotropic(500), {0, 0, -1}, {1, 0, 0}, nullptr},
         ""});
    scene.lights.push_back({"sun", penumbra::DirectionalLight{{0.3, 0.4, -0.87}, 60000}, ""});
    return il::IlluminanceSolver(scene);
  }();
  const auto& points = scene_workload().points[state.range(1) == 0 ? 0 : 2];
  std::size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(
        solver.light_at(static_cast<std::size_t>(state.range(0)), points[i++ & 255], {0, 0, 1}));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  state.SetLabel(std::string(state.range(0) == 0 ? "point lamp" : "sun") +
                 (state.range(1) == 0 ? ", tube-unshadowed points" : ", tube-umbra points"));
}
BENCHMARK(scene_point_and_sun_100_occluders)
    ->Args({0, 0})
    ->Args({0, 1})
    ->Args({1, 0})
    ->Args({1, 1});

}  // namespace
