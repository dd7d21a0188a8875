#pragma once
// Sun-hours (issue 19, docs/sun-hours.md): how long each part of every face is in direct
// sun over a range of time steps. Each step where the sun's centre is above the horizon
// lights the scene from the sun's direction then; the exact shadows on every face at every
// such step (shadow_map.h) are overlaid (region_overlay.h), so every part of a face carries
// the number of steps that light it (those the face faces less those whose shadow holds
// it), and the duration is that number times the step length (DESIGN.md: "each sun-up step
// counting one step length").

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "penumbra/base/vec3d.h"
#include "penumbra/scene/scene.h"
#include "penumbra/shadow/region_overlay.h"
#include "penumbra/shadow/shadow_map.h"
#include "penumbra/sun/civil_time.h"
#include "penumbra/sun/solar_position.h"

namespace penumbra::studies {

// One time step of a study: when, where the sun stands, and where its light goes.
struct SunStep {
  sun::UtcInstant time;
  sun::SolarPosition position;
  Vec3d direction;  // the direction sunlight travels in the model frame (as "directional")
  // the step counts when the sun's centre is above the horizon (refraction included when
  // the scene's sun gives the air), the rule by which a scene leaves a sun out of its lights.
  bool up() const { return position.elevation_deg > 0; }
};

// returns the steps of sun at the instants, in their order (sun::SolarPositionSolver,
// sun::light_direction with the scene's north_deg).
std::vector<SunStep> sun_steps(const SunPlacement& sun, double north_deg,
                               const std::vector<sun::UtcInstant>& instants);

struct SunHoursOptions {
  // only these receiving faces, as ShadowOptions::receivers; every face when empty.
  std::optional<std::vector<Receiver>> receivers;
  bool parallel = true;  // TBB across steps and faces (the shadows), and faces (the overlays)
  // progress (each may be empty): step_done after each sun-up step's shadows;
  // overlays_begin before the overlays with the number of faces, then face_done after each
  // face's overlay, from any thread.
  std::function<void()> step_done;
  std::function<void(std::size_t)> overlays_begin;
  std::function<void()> face_done;
};

// The sunlit parts of one receiving face.
struct FaceSunHours {
  // the face cut by the number of sun-up steps that light each part (Coverage::count),
  // increasing, together tiling the face; one part when the face is lit alike throughout.
  std::vector<Coverage> parts;
};

struct SunHoursResult {
  std::vector<SunStep> steps;  // every instant asked for, the sun up or not
  sun::Duration step{0};       // what each sun-up step counts
  // the receiving faces (receivers, mesh_faces, warnings; no lights), as receiving_face
  // names and draws them.
  ShadowResult faces;
  std::vector<FaceSunHours> hours;  // parallel to faces.receivers
  double shadow_seconds = 0;        // wall time of the steps' shadows
  double overlay_seconds = 0;       // wall time of the overlays

  std::size_t steps_up() const;
  // returns the duration that count sun-up steps make, in minutes.
  double minutes(std::size_t count) const;
  // returns the most sun-up steps that light any part of any face.
  std::size_t longest_count() const;
  // returns the area of face r (in its frame's units, exactly) that at least threshold of
  // sun reaches.
  Exact area_at_least(std::size_t r, sun::Duration threshold) const;
};

// computes the sun-hours of every face of scene (or of options.receivers) under sun (one
// of scene.suns) at the instants, each sun-up step counting step. The scene's other
// lights play no part. Throws InputError as compute_shadows does.
SunHoursResult sun_hours(const Scene& scene, const SunPlacement& sun,
                         const std::vector<sun::UtcInstant>& instants, sun::Duration step,
                         const SunHoursOptions& options = {});

// A receiving face's share of a region: the area of the face the region holds, and the
// part of it with at least a threshold of sun. For a plan region (a simple polygon of x, y
// seen from above: a garden, a playground drawn on the site plan) the region is the
// vertical prism over the polygon, met by the faces that face up (normal z > 0; vertical
// and downward faces have no plan area).
struct RegionShare {
  std::size_t receiver;  // index into SunHoursResult::faces.receivers
  Exact area;            // of the face inside the region, in the face's frame units
  Exact reached;         // of that, the area with at least the threshold of sun
};

// returns the shares of the faces of result that meet the prism over plan (counter-clockwise
// or clockwise, at least 3 points, not crossing itself), exactly: each face's window and
// its sun-hours parts intersected with the polygon carried onto the face's plane along z.
std::vector<RegionShare> plan_region_shares(const Scene& scene, const SunHoursResult& result,
                                            const std::vector<Point2>& plan,
                                            sun::Duration threshold);

}  // namespace penumbra::studies
