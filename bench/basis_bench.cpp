// Basis lighting (issue 9) on the paper's case (Dobashi 1995 section 5, Fig. 6): a room of
// about 16,000 patches (fixtures/scenes/basis-room.json at 0.16 m patches) with a degree-5
// (36-term) lamp at the centre of the ceiling and a degree-8 (81-term) lamp in a corner.
// BM_BasisPreprocess: mesh, form factors (1024 rays per patch), direct light and the
// solve with 117 right-hand sides. BM_Relight*: eq. (18) for a changed lighting, per patch
// (direct and total) or per vertex only (what a display needs). The counters give the
// memory of the basis values and the error of relighting against a direct solve with the
// exact distributions (max and RMS over the patches, relative to the largest E).

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <string>

#include "penumbra/basis/relight.h"
#include "penumbra/basis/scene_radiosity.h"
#include "penumbra/scene/load_scene.h"

namespace {

using namespace penumbra;

const Scene& room() {
  static std::unique_ptr<Scene> scene;
  if (!scene) {
    // Run from the repository's top directory, or point PENUMBRA_SOURCE_DIR at it.
    const char* top = std::getenv("PENUMBRA_SOURCE_DIR");
    scene = std::make_unique<Scene>(
        load_scene(std::string(top ? top : ".") + "/fixtures/scenes/basis-room.json"));
  }
  return *scene;
}

basis::BasisOptions room_options() {
  basis::BasisOptions options;
  options.patch_size = 0.16;
  options.degree = 5;
  options.light_degrees = {{"corner", 8}};
  options.form_factors.rays = 1024;
  options.radiosity.tolerance = 1e-6;
  return options;
}

const basis::BasisLuminances& room_basis() {
  static std::unique_ptr<basis::BasisLuminances> basis;
  if (!basis)
    basis = std::make_unique<basis::BasisLuminances>(basis::compute_basis(room(), room_options()));
  return *basis;
}

std::size_t block_bytes(const basis::BasisBlock& block) {
  return 4 * static_cast<std::size_t>(block.is_compressed()
                                          ? (block.rows() + block.cols()) * block.rank()
                                          : block.rows() * block.cols());
}

void BM_BasisPreprocess(benchmark::State& state) {
  for (auto _ : state) {
    const basis::BasisLuminances basis = basis::compute_basis(room(), room_options());
    state.counters["patches"] = static_cast<double>(basis.mesh.size());
    state.counters["vertices"] = static_cast<double>(basis.mesh.vertices().size());
    state.counters["ff_entries"] = static_cast<double>(basis.form_factor_entries);
    state.counters["sweeps"] = basis.iterations;
    state.counters["t_form_factors_s"] = basis.timings.form_factors_s;
    state.counters["t_direct_s"] = basis.timings.direct_s;
    state.counters["t_solve_s"] = basis.timings.solve_s;
    std::size_t bytes = 0;
    for (const basis::BasisLight& light : basis.lights) {
      bytes += block_bytes(light.direct);
      for (const auto& block : light.total) bytes += block_bytes(block);
      for (const auto& block : light.vertex_luminance) bytes += block_bytes(block);
    }
    state.counters["basis_MB"] = static_cast<double>(bytes) / 1e6;
  }
}

// a changed lighting: the centre lamp dimmed and warm, the corner lamp re-aimed
basis::Lighting changed_lighting(const basis::BasisLuminances& basis) {
  basis::Lighting lighting = basis::default_lighting(basis);
  lighting[0].scale = 0.7;
  lighting[0].colour = {1, 0.85, 0.7};
  const Vec3d axis{-0.6, 0.2, -0.77};
  const auto lid = photometry::make_distribution(
      nlohmann::json::parse(R"({"cos_power": 20, "spread_deg": 60, "candela": 4000})"),
      {"bench", "lid", "."});
  lighting[1].coefficients =
      basis::world_coefficients(*lid, 8, axis, basis::reaimed_c0(axis, basis.lights[1].c0), false);
  return lighting;
}

void BM_Relight(benchmark::State& state) {
  const basis::BasisLuminances& basis = room_basis();
  const basis::Lighting lighting = changed_lighting(basis);
  const bool vertices_only = state.range(0) == 1;
  for (auto _ : state) benchmark::DoNotOptimize(basis::relight(basis, lighting, vertices_only));
}

// the relit scene lighting against the solve with the exact distributions: max and RMS
// over the patches of |E_relit - E_exact| / max E_exact, and the 99th percentile
void record_error(benchmark::State& state, const std::string& name, const basis::Relit& relit,
                  const basis::SceneRadiosity& exact) {
  const Eigen::VectorXd difference =
      (relit.total.col(0).cast<double>() - exact.total.col(0)).cwiseAbs();
  const double scale = exact.total.col(0).cwiseAbs().maxCoeff();
  std::vector<double> sorted(difference.data(), difference.data() + difference.size());
  std::sort(sorted.begin(), sorted.end());
  state.counters[name + "_max"] = difference.maxCoeff() / scale;
  state.counters[name + "_p99"] = sorted[sorted.size() * 99 / 100] / scale;
  state.counters[name + "_rms"] =
      std::sqrt(difference.squaredNorm() / static_cast<double>(difference.size())) / scale;
}

void BM_RelightError(benchmark::State& state) {
  const basis::BasisLuminances& basis = room_basis();
  for (auto _ : state) {
    const basis::SceneRadiosity exact = basis::solve_scene_radiosity(room(), room_options());
    record_error(state, "sigma", basis::relight(basis, basis::default_lighting(basis)), exact);
    basis::Lighting plain = basis::default_lighting(basis);
    for (std::size_t k = 0; k < plain.size(); ++k) {
      const PointLight& lamp = std::get<PointLight>(room().lights[k].source);
      plain[k].coefficients = basis::world_coefficients(
          *lamp.distribution, basis.lights[k].columns.degree, lamp.axis, lamp.c0, false);
    }
    record_error(state, "plain", basis::relight(basis, plain), exact);
    state.counters["t_exact_solve_s"] =
        exact.timings.form_factors_s + exact.timings.direct_s + exact.timings.solve_s;
  }
}

}  // namespace

BENCHMARK(BM_BasisPreprocess)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_Relight)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RelightError)->Unit(benchmark::kSecond)->Iterations(1);
