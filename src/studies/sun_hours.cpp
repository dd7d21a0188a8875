#include "penumbra/studies/sun_hours.h"

#include <algorithm>
#include <chrono>
#include <string>
#include <utility>

#include "penumbra/base/parallel.h"
#include "penumbra/geometry/exact_sum.h"

namespace penumbra::studies {
namespace {

using Clock = std::chrono::steady_clock;

constexpr std::size_t kStepsAtOnce = 8;  // sun-up steps computed side by side

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// returns a receiving face as a polygon of its frame: its outer ring and its holes.
Polygon2 window_of(const ReceivingFace& face) {
  Polygon2 window{canonical_ring(face.ring), {}};
  if (face.holes)
    for (const std::vector<Point3>& hole : *face.holes) {
      Ring2 ring;
      for (const Point3& p : hole) ring.push_back(face.frame.to_frame(p));
      window.holes.push_back(canonical_ring(ring));
    }
  return window;
}

// What the steps did to one face: how many it faced (lit but for shadows), and the shadows
// of those that shadowed a part of it.
struct FaceSteps {
  std::size_t facing = 0;
  std::vector<Region2> shadows;
};

}  // namespace

std::vector<SunStep> sun_steps(const SunPlacement& sun, double north_deg,
                               const std::vector<sun::UtcInstant>& instants) {
  sun::SolarPositionSolver solver(sun.site, sun.atmosphere);
  std::vector<SunStep> steps;
  steps.reserve(instants.size());
  for (const sun::UtcInstant instant : instants) {
    const sun::SolarPosition position = solver.at(instant);
    steps.push_back({instant, position, sun::light_direction(position, north_deg)});
  }
  return steps;
}

std::size_t SunHoursResult::steps_up() const {
  return static_cast<std::size_t>(
      std::count_if(steps.begin(), steps.end(), [](const SunStep& s) { return s.up(); }));
}

double SunHoursResult::minutes(std::size_t count) const {
  return static_cast<double>(count) * std::chrono::duration<double, std::ratio<60>>(step).count();
}

std::size_t SunHoursResult::longest_count() const {
  std::size_t longest = 0;
  for (const FaceSunHours& face : hours)
    for (const Coverage& part : face.parts) longest = std::max(longest, part.count);
  return longest;
}

Exact SunHoursResult::area_at_least(std::size_t r, sun::Duration threshold) const {
  std::vector<Exact> areas;
  for (const Coverage& part : hours[r].parts)
    if (step * static_cast<long long>(part.count) >= threshold) areas.push_back(part.region.area);
  return exact_sum(areas);
}

SunHoursResult sun_hours(const Scene& scene, const SunPlacement& sun,
                         const std::vector<sun::UtcInstant>& instants, sun::Duration step,
                         const SunHoursOptions& options) {
  SunHoursResult result;
  result.steps = sun_steps(sun, scene.north_deg, instants);
  result.step = step;

  // The scene with no light but the sun where it stands at the step being computed.
  Scene stepped = scene;
  stepped.lights.clear();
  ShadowOptions shadow_options;
  shadow_options.receivers = options.receivers;
  shadow_options.parallel = options.parallel;
  // The overlay takes the shadows alone.
  shadow_options.lit_parts = false;
  result.faces = compute_shadows(stepped, shadow_options);  // the receivers, no lights
  const std::size_t count = result.faces.receivers.size();

  const Clock::time_point shading = Clock::now();
  std::vector<FaceSteps> faces(count);
  std::vector<std::size_t> up;
  for (std::size_t k = 0; k < result.steps.size(); ++k)
    if (result.steps[k].up()) up.push_back(k);
  // The steps in batches, each batch's suns the lights of one computation, so that steps
  // are computed side by side (compute_shadows runs its lights in parallel); the batch
  // bounds the shadows held at once beyond those kept for the overlay.
  for (std::size_t first = 0; first < up.size(); first += kStepsAtOnce) {
    const std::size_t last = std::min(up.size(), first + kStepsAtOnce);
    stepped.lights.clear();
    for (std::size_t k = first; k < last; ++k) {
      // Names in step order: the lights come back in name order.
      std::string number = std::to_string(k);
      number.insert(0, 8 - std::min<std::size_t>(8, number.size()), '0');
      stepped.lights.push_back(
          Light{sun.name + "@" + number,
                DirectionalLight{result.steps[up[k]].direction, sun.illuminance}, sun.json_path});
    }
    ShadowResult shadows = compute_shadows(stepped, shadow_options);
    for (std::string& warning : shadows.warnings)
      if (std::find(result.faces.warnings.begin(), result.faces.warnings.end(), warning) ==
          result.faces.warnings.end())
        result.faces.warnings.push_back(std::move(warning));
    for (LightShadows& at_step : shadows.lights) {
      std::vector<FaceShadow>& lit = at_step.faces;
      for (std::size_t r = 0; r < count; ++r) {
        if (lit[r].faces_away) continue;
        ++faces[r].facing;
        if (!lit[r].shadow.empty()) faces[r].shadows.push_back(std::move(lit[r].shadow));
      }
      if (options.step_done) options.step_done();
    }
  }
  result.shadow_seconds = seconds_since(shading);

  const Clock::time_point overlaying = Clock::now();
  result.hours.resize(count);
  if (options.overlays_begin) options.overlays_begin(count);
  for_each_index(count, options.parallel, [&](std::size_t r) {
    const Polygon2 window = window_of(receiving_face(scene, result.faces, r));
    // The steps that light a point are those the face faces less those whose shadow
    // holds it: the shadows are overlaid (they cluster around their occluders, while the
    // lit sets all reach across the face).
    FaceSteps& face = faces[r];
    std::vector<const Region2*> shadows;
    for (const Region2& shadow : face.shadows) shadows.push_back(&shadow);
    std::vector<Coverage> parts = coverage(window, shadows);
    std::reverse(parts.begin(), parts.end());
    for (Coverage& part : parts) part.count = face.facing - part.count;
    result.hours[r].parts = std::move(parts);
    face = FaceSteps{};
    if (options.face_done) options.face_done();
  });
  result.overlay_seconds = seconds_since(overlaying);
  return result;
}

std::vector<RegionShare> plan_region_shares(const Scene& scene, const SunHoursResult& result,
                                            const std::vector<Point2>& plan,
                                            sun::Duration threshold) {
  std::vector<RegionShare> shares;
  for (std::size_t r = 0; r < result.faces.receivers.size(); ++r) {
    const ReceivingFace face = receiving_face(scene, result.faces, r);
    const Plane3& plane = face.plane;
    if (!CGAL::is_positive(plane.c())) continue;
    // The plan point (x, y) on the plane a x + b y + c z + d = 0, in the face's frame.
    Ring2 ring;
    for (const Point2& p : plan)
      ring.push_back(face.frame.to_frame(
          Point3(p.x(), p.y(), -(plane.a() * p.x() + plane.b() * p.y() + plane.d()) / plane.c())));
    if (area_sign(ring) == CGAL::NEGATIVE) std::reverse(ring.begin(), ring.end());
    const Region2 prism = canonical_region({Polygon2{canonical_ring(ring), {}}});
    const Region2 inside = intersection(canonical_region({window_of(face)}), prism);
    if (inside.empty()) continue;
    std::vector<Exact> reached;
    for (const Coverage& part : result.hours[r].parts)
      if (result.step * static_cast<long long>(part.count) >= threshold)
        reached.push_back(intersection(part.region, prism).area);
    shares.push_back({r, inside.area, exact_sum(reached)});
  }
  return shares;
}

}  // namespace penumbra::studies
