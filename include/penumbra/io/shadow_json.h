#pragma once
// The shadow loops output of DESIGN.md ("Shadow loops output (JSON)"): per face its
// plane, frame, boundary and area, and per light its shadow, umbra, penumbra and
// lit polygon sets in 3D world coordinates, with each occluder's shadow polygon.
// For point and directional sources umbra = shadow and the penumbra is empty.
// With exact, every coordinate also appears as "p/q" rationals under "exact" keys.

#include <string>

#include <nlohmann/json.hpp>

#include "penumbra/shadow/shadow_map.h"

namespace penumbra::io {

struct ShadowJsonOptions {
  bool exact = false;
  double range_fraction = 1.0 / 256;  // recorded so that `check` recomputes alike
  double full_scale_lux = 500;
  std::optional<double> range_lux;
};

// builds the document for result, computed from scene.
nlohmann::json shadow_json(const Scene& scene, const ShadowResult& result,
                           const ShadowJsonOptions& options);

// formats a document for files: objects indented one level per depth, arrays that
// hold no objects (points, rings) on one line, so that golden files stay small and
// diff by line.
std::string format_json(const nlohmann::json& document);

// returns the world area of a region of face (frame area times |u| |v|), in m^2.
double world_area(const Region2& region, const Face& face);

}  // namespace penumbra::io
