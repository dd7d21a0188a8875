// Area sources (issue #21): the illuminance of a work plane under six 0.6 m x 0.6 m panels
// among 50 occluders, at 10 cm spacing, exact (Lambert's closed form over the exactly visible
// part of each panel) against Monte Carlo with Embree shadow rays (stratified samples of each
// panel, sample_area_stratified) in the same run. Each Monte Carlo row reports its RMS error
// against the exact values, relative to their mean (counter rms_percent): the row at or
// under 0.5 % is the one the exact time is compared with (docs/performance.md, "Area
// sources"). Single thread for both.

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <sstream>
#include <vector>

#include "penumbra/illuminance/scene_illuminance.h"
#include "penumbra/raytrace/area_sampling.h"
#include "penumbra/raytrace/embree_scene.h"
#include "penumbra/scene/load_scene.h"

namespace {

using penumbra::Vec3d;

// A 7.2 m x 4.8 m office: panels in a 3 x 2 grid at z = 2.8; 50 occluders between the work
// plane (z = 0.8) and the ceiling: 20 ducts and baffles hanging at 2.2-2.6 m, 30 shelves and
// screens at 1.0-1.9 m (fixed seed).
struct Office {
  penumbra::Scene scene;
  std::vector<Vec3d> points;  // the work plane grid, 10 cm apart
  std::vector<double> exact;  // the exact total illuminance at each point

  Office() {
    std::mt19937_64 engine{21};
    std::uniform_real_distribution<double> x(0.3, 6.6), y(0.3, 4.2), size(0.15, 0.8);
    std::ostringstream text;
    text << R"({"penumbra": 1, "objects": [)";
    for (int k = 0; k < 50; ++k) {
      const double x0 = x(engine), y0 = y(engine);
      const double z0 = k < 20 ? 2.2 + 0.3 * size(engine) : 1.0 + size(engine);
      text << (k ? "," : "") << R"({"name": "o)" << k << R"(", "box": {"min": [)" << x0 << "," << y0
           << "," << z0 << R"(], "max": [)" << x0 + size(engine) << "," << y0 + size(engine) << ","
           << z0 + 0.05 + 0.2 * size(engine) << "]}}";
    }
    text << R"(], "lights": [)";
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 2; ++j) {
        const double cx = 1.2 + 2.4 * i, cy = 1.2 + 2.4 * j;
        text << (i + j ? "," : "") << R"({"name": "p)" << i << j << R"(", "area": [[)" << cx - 0.3
             << "," << cy - 0.3 << ",2.8],[" << cx - 0.3 << "," << cy + 0.3 << ",2.8],[" << cx + 0.3
             << "," << cy + 0.3 << ",2.8],[" << cx + 0.3 << "," << cy - 0.3
             << R"(,2.8]], "luminance": 4000})";
      }
    text << "]}";
    scene = penumbra::parse_scene(text.str(), "area-office.json");
    for (int i = 0; i < 72; ++i)
      for (int j = 0; j < 48; ++j) points.push_back({0.05 + 0.1 * i, 0.05 + 0.1 * j, 0.8});
    const penumbra::illuminance::IlluminanceSolver solver(scene);
    for (const Vec3d& p : points) exact.push_back(solver.at(p, {0, 0, 1}).total);
  }
};

const Office& office() {
  static const Office shared;
  return shared;
}

void area_exact_work_plane(benchmark::State& state) {
  const Office& room = office();
  for (auto _ : state) {
    const penumbra::illuminance::IlluminanceSolver solver(room.scene);
    for (const Vec3d& p : room.points) benchmark::DoNotOptimize(solver.at(p, {0, 0, 1}).total);
  }
  state.counters["points"] = static_cast<double>(room.points.size());
}
BENCHMARK(area_exact_work_plane)->Unit(benchmark::kSecond)->Iterations(1);

void area_monte_carlo_work_plane(benchmark::State& state) {
  const Office& room = office();
  const int samples = static_cast<int>(state.range(0));
  double rms = 0;
  for (auto _ : state) {
    const penumbra::raytrace::EmbreeScene embree(room.scene);
    double squares = 0, mean = 0;
    for (std::size_t k = 0; k < room.points.size(); ++k) {
      const Vec3d& p = room.points[k];
      const auto shadow_ray = [&](const Vec3d& q) {
        const Vec3d d{q[0] - p[0], q[1] - p[1], q[2] - p[2]};
        const double r = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        penumbra::raytrace::Ray ray{p, {d[0] / r, d[1] / r, d[2] / r}, 1e-6, r * (1 - 1e-6)};
        return embree.occluded(ray) ? 0.0 : 1.0;
      };
      double e = 0;
      for (const penumbra::Light& light : room.scene.lights)
        for (const auto& element : penumbra::raytrace::sample_area_stratified(
                 std::get<penumbra::AreaLight>(light.source), p, samples, 1000 + k, shadow_ray)) {
          const Vec3d d{element.position[0] - p[0], element.position[1] - p[1],
                        element.position[2] - p[2]};
          const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
          e += element.candela * (d[2] / std::sqrt(r2)) / r2;
        }
      squares += (e - room.exact[k]) * (e - room.exact[k]);
      mean += room.exact[k];
    }
    const double n = static_cast<double>(room.points.size());
    rms = std::sqrt(squares / n) / (mean / n);
  }
  state.counters["rms_percent"] = 100 * rms;
  state.counters["rays_per_point"] = 6.0 * samples;
}
BENCHMARK(area_monte_carlo_work_plane)
    ->Arg(16)
    ->Arg(64)
    ->Arg(256)
    ->Arg(512)
    ->Arg(576)
    ->Arg(1024)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

}  // namespace
