// Evaluations per second of the illuminance kernels (docs/performance.md, "Illuminance
// kernels"): point sources, the linear-source closed form and its adaptive quadrature.

#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "penumbra/illuminance/linear_source.h"
#include "penumbra/illuminance/point_source.h"
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

}  // namespace
