#include "penumbra/shadow/shadow_map.h"

#include <algorithm>
#include <chrono>
#include <numeric>

#include "penumbra/input_error.h"
#include "penumbra/parallel.h"
#include "penumbra/shadow/linear_face_shadow.h"
#include "penumbra/shadow/shadow_polygon.h"
#include "penumbra/visibility/lighting_sphere.h"
#include "receiver_clip.h"

namespace penumbra {
namespace {

std::optional<LightPosition> position_of(const Light& light) {
  if (const auto* point = std::get_if<PointLight>(&light.source))
    return LightPosition::at(to_exact(point->position));
  if (const auto* sun = std::get_if<DirectionalLight>(&light.source))
    return LightPosition::toward(to_exact_vector(sun->direction));
  return std::nullopt;
}

std::optional<LightingSphere> sphere_of(const Light& light, const ShadowOptions& options) {
  const auto* point = std::get_if<PointLight>(&light.source);
  if (!point) return std::nullopt;
  const Point3 centre = to_exact(point->position);
  if (options.range_lux)
    return LightingSphere::absolute(centre, point->distribution->max_intensity(),
                                    *options.range_lux);
  // The partial sphere of lighting of photometry/figures.h (Nishita section 3.1):
  // light below range_fraction of the display's full scale is insignificant.
  if (options.range_fraction > 0)
    return LightingSphere::absolute(centre, point->distribution->max_intensity(),
                                    options.range_fraction * options.full_scale_lux);
  return std::nullopt;
}

// returns every other object for each receiver (no broad phase).
std::vector<std::vector<std::size_t>> all_pairs(const Scene& scene,
                                                const std::vector<Receiver>& receivers) {
  std::vector<std::vector<std::size_t>> candidates(receivers.size());
  for (std::size_t a = 0; a < receivers.size(); ++a)
    for (std::size_t o = 0; o < scene.objects.size(); ++o)
      if (o != receivers[a].object) candidates[a].push_back(o);
  return candidates;
}

// puts each receiver's occluders in canonical order (by object name: rank),
// whatever the input order, and counts the pairs tested.
void rank_candidates(std::vector<std::vector<std::size_t>>& candidates,
                     const std::vector<std::size_t>& rank, ShadowStats& stats) {
  for (auto& list : candidates) {
    std::sort(list.begin(), list.end(),
              [&](std::size_t a, std::size_t b) { return rank[a] < rank[b]; });
    stats.pairs_tested += list.size();
  }
}

// returns the shadows of light light_index before any face is computed: one empty entry
// per receiver and the pair counts.
LightShadows empty_result(const Scene& scene, const std::vector<Receiver>& receivers,
                          std::size_t light_index) {
  LightShadows result;
  result.light = light_index;
  result.faces.resize(receivers.size());
  result.stats.faces = receivers.size();
  result.stats.pairs_possible = receivers.size() * (scene.objects.size() - 1);
  return result;
}

LightShadows shade_scene(const Scene& scene, const std::vector<Receiver>& receivers,
                         const std::vector<std::size_t>& rank, std::size_t light_index,
                         const ShadowOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const Light& light = scene.lights[light_index];
  const LightPosition position = *position_of(light);
  const auto sphere = sphere_of(light, options);

  LightShadows result = empty_result(scene, receivers, light_index);
  ShadowStats& stats = result.stats;
  if (sphere) stats.radius = sphere->radius();

  // Culling: faces turned away are wholly unlit; faces outside the sphere of
  // lighting are not computed (Nishita 1985 section 3.1).
  std::vector<Receiver> active;
  std::vector<std::size_t> active_index;
  for (std::size_t r = 0; r < receivers.size(); ++r) {
    const Face& face = scene.objects[receivers[r].object].solid.faces()[receivers[r].face];
    if (faces_away(face, position)) {
      result.faces[r] = unlit_face(face);
      ++stats.faces_away;
    } else if (sphere && sphere->beyond(face)) {
      result.faces[r].beyond_range = true;
      ++stats.beyond_range;
    } else {
      active.push_back(receivers[r]);
      active_index.push_back(r);
    }
  }

  std::vector<std::vector<std::size_t>> candidates;
  if (options.broad_phase) {
    std::vector<const ConvexPolyhedron*> solids;
    for (const Object& object : scene.objects) solids.push_back(&object.solid);
    candidates = candidate_occluders(solids, active, position);
  } else {
    candidates = all_pairs(scene, active);
  }
  rank_candidates(candidates, rank, stats);

  // The shadow volume of each occluder depends only on the light: build it once.
  std::vector<char> needed(scene.objects.size(), 0);
  for (const auto& list : candidates)
    for (std::size_t occluder : list) needed[occluder] = 1;
  std::vector<std::vector<Plane3>> volumes(scene.objects.size());
  for_each_index(scene.objects.size(), options.parallel, [&](std::size_t o) {
    if (needed[o]) volumes[o] = shadow_volume(scene.objects[o].solid, position);
  });

  auto shade = [&](std::size_t a) {
    const Face& face = scene.objects[active[a].object].solid.faces()[active[a].face];
    if (candidates[a].empty()) {
      result.faces[active_index[a]] = unite_shadows(face, {});
      return;
    }
    // The face's ring and frame, exact and in intervals, once for all its occluders.
    const detail::ReceiverClip receiver(face);
    std::vector<OccluderShadow> shadows;
    for (std::size_t occluder : candidates[a])
      if (auto polygon =
              detail::shadow_polygon(scene.objects[occluder].solid, volumes[occluder], receiver))
        shadows.push_back({occluder, std::move(*polygon)});
    result.faces[active_index[a]] = unite_shadows(receiver.ring(), std::move(shadows));
  };
  for_each_index(active.size(), options.parallel, shade);

  for (const FaceShadow& face : result.faces) stats.pairs_shadowing += face.occluders.size();
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

// The same for a linear source (Nishita 1985 section 4.1, docs/linear-shadows.md),
// culled by a sphere around the tube's capsule of lighting.
LightShadows shade_linear(const Scene& scene, const std::vector<Receiver>& receivers,
                          const std::vector<std::size_t>& rank, std::size_t light_index,
                          const ShadowOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const Light& light = scene.lights[light_index];
  const auto& tube = std::get<LinearLight>(light.source);
  // End points in lexicographic order: the loops (which start at C1) must not
  // depend on the order the file lists them in.
  Point3 q1 = to_exact(tube.start), q2 = to_exact(tube.end);
  if (CGAL::compare_xyz(q2, q1) == CGAL::SMALLER) std::swap(q1, q2);

  LightShadows result = empty_result(scene, receivers, light_index);
  ShadowStats& stats = result.stats;

  std::optional<LightingSphere> sphere;
  const double threshold =
      options.range_lux ? *options.range_lux : options.range_fraction * options.full_scale_lux;
  if (threshold > 0)
    sphere = LightingSphere::around_segment(q1, q2, tube.candela_per_metre, threshold);
  if (sphere) stats.radius = sphere->radius();
  std::vector<Receiver> active;
  std::vector<std::size_t> active_index;
  for (std::size_t r = 0; r < receivers.size(); ++r) {
    const Face& face = scene.objects[receivers[r].object].solid.faces()[receivers[r].face];
    if (sphere && sphere->beyond(face)) {
      result.faces[r].beyond_range = true;
      result.faces[r].linear = true;
      ++stats.beyond_range;
    } else {
      active.push_back(receivers[r]);
      active_index.push_back(r);
    }
  }

  std::vector<const ConvexPolyhedron*> solids;
  for (const Object& object : scene.objects) solids.push_back(&object.solid);
  std::vector<std::vector<std::size_t>> candidates;
  if (options.broad_phase) {
    candidates = candidate_occluders(solids, active, q1, q2);
  } else {
    candidates = all_pairs(scene, active);
  }
  rank_candidates(candidates, rank, stats);

  auto shade = [&](std::size_t a) {
    const Object& object = scene.objects[active[a].object];
    const Face& face = object.solid.faces()[active[a].face];
    std::vector<Occluder> occluders;
    for (std::size_t o : candidates[a]) occluders.push_back({o, &scene.objects[o].solid});
    try {
      result.faces[active_index[a]] = linear_face_shadow(face, q1, q2, std::move(occluders));
    } catch (const std::domain_error&) {
      throw InputError(scene.file.string(), light.json_path,
                       "the linear source '" + light.name +
                           "' touches or passes through an "
                           "object that shadows face " +
                           std::to_string(active[a].face) + " of '" + object.name +
                           "': not supported (docs/linear-shadows.md)");
    }
  };
  for_each_index(active.size(), options.parallel, shade);

  for (const FaceShadow& face : result.faces) {
    stats.faces_away += face.faces_away;
    stats.pairs_shadowing += face.occluders.size();
  }
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace

ShadowResult compute_shadows(const Scene& scene, const ShadowOptions& options) {
  ShadowResult result;
  // Canonical order: objects by name (names are unique), faces by canonical index.
  std::vector<std::size_t> by_name(scene.objects.size());
  std::iota(by_name.begin(), by_name.end(), 0);
  std::sort(by_name.begin(), by_name.end(), [&](std::size_t a, std::size_t b) {
    return scene.objects[a].name < scene.objects[b].name;
  });
  std::vector<std::size_t> rank(scene.objects.size());
  for (std::size_t k = 0; k < by_name.size(); ++k) rank[by_name[k]] = k;
  for (std::size_t object : by_name)
    for (std::size_t f = 0; f < scene.objects[object].solid.faces().size(); ++f)
      result.receivers.push_back({object, f});

  std::vector<std::size_t> lights;
  if (options.light) {
    const Light* light = scene.find_light(*options.light);
    if (!light)
      throw InputError(scene.file.string(), "lights",
                       "there is no light named '" + *options.light + "'");
    lights.push_back(static_cast<std::size_t>(light - scene.lights.data()));
  } else {
    for (std::size_t k = 0; k < scene.lights.size(); ++k) lights.push_back(k);
  }
  // Lights in name order, for the same reason as objects.
  std::sort(lights.begin(), lights.end(), [&](std::size_t a, std::size_t b) {
    return scene.lights[a].name < scene.lights[b].name;
  });
  for (std::size_t light : lights)
    result.lights.push_back(position_of(scene.lights[light])
                                ? shade_scene(scene, result.receivers, rank, light, options)
                                : shade_linear(scene, result.receivers, rank, light, options));
  return result;
}

}  // namespace penumbra
