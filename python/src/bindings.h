#pragma once
// The parts of the native module _penumbra (docs/python.md): the scene and what is
// computed on it (scene_binding.cpp), the studies over time and the documents' writers
// (studies_binding.cpp). The Python package penumbra wraps them (python/penumbra/).

#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "penumbra/illuminance/scene_illuminance.h"
#include "penumbra/scene/scene.h"
#include "penumbra/shadow/shadow_map.h"

namespace penumbra::python {

// A loaded scene, shared by the Python objects that refer to it, with the illuminance
// solver built on first use and kept (a Dask worker answers many point chunks with one).
class SceneHandle {
 public:
  explicit SceneHandle(Scene scene) : scene_(std::make_shared<const Scene>(std::move(scene))) {}
  const Scene& scene() const { return *scene_; }
  const illuminance::IlluminanceSolver& solver() const;

 private:
  std::shared_ptr<const Scene> scene_;
  mutable std::once_flag solver_once_;
  mutable std::optional<illuminance::IlluminanceSolver> solver_;
};

// returns the receiving faces that the receivers argument names: shell patterns of object
// names as `--receivers` (a str), or the exact owners' names (a list of str, as the faces'
// "object" in documents); every face when none.
std::optional<std::vector<Receiver>> chosen_receivers(const Scene& scene,
                                                      const pybind11::object& receivers);

// returns the options of compute_shadows: the faces receivers names (chosen_receivers) and the
// culling of `penumbra shadows` (--range-fraction, --full-scale-lux, --range-lux).
ShadowOptions shadow_options(const Scene& scene, const pybind11::object& receivers,
                             double range_fraction, double full_scale_lux,
                             std::optional<double> range_lux);

void bind_scene(pybind11::module_& module);
void bind_studies(pybind11::module_& module);

}  // namespace penumbra::python
