#pragma once
// Illuminance at a point of a scene, per light and in total (Nishita 1985 sections 3.3
// and 4.2.3): the kernels of point_source.h and linear_source.h fed with exact
// visibility from occlusion.h. See docs/illuminance.md, "Illuminance in a scene".
//
// - point light:  E = I(theta) cos(alpha) / r^2, I from the light's distribution in its
//                 photometric frame; 0 when an occluder meets the open segment P -> Q.
// - directional:  E = E_n cos(alpha); 0 when an occluder meets the open ray toward the sun.
// - area:         Lambert's closed form (area_source.h) over the exact visible part of the
//                 source (shadow/source_view.h); 0 behind a one-sided source.
// - linear:       the closed form integrated over the visible parts of the source: the
//                 part on the outer side of the receiving plane minus the union of the
//                 sub-segments each occluder hides (exact intervals, section 4.2.3). In
//                 umbra, single or joint, E = 0.
// Visibility is decided exactly from the doubles given; doubles enter only as magnitudes.
// Every sign is first computed in interval arithmetic and left to the exact test only
// when the interval cannot certify it (a filter, as in CGAL's predicates: same answers).
// Tie-breaks: a light not strictly on the outer side of the receiving plane gives 0; a
// segment that only touches an occluder's boundary is not blocked; a point strictly
// inside an object gets 0 from every light.

#include <array>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "penumbra/illuminance/occlusion.h"
#include "penumbra/scene/scene.h"

namespace penumbra::illuminance {

// The illuminance at one receiving point.
struct PointIlluminance {
  double total = 0;               // lux, the sum over the lights
  std::vector<double> per_light;  // lux, in the order of Scene::lights
  // the object (index into Scene::objects) strictly containing the point, if any: then
  // every value is 0 (a convex solid hides everything from a point inside it).
  std::optional<std::size_t> inside;
};

class IlluminanceSolver {
 public:
  // prepares repeated queries on scene: the occluders with their bounding boxes, each
  // light's exact frame, and for every point light the region each occluder hides from
  // it (so a point-light query is one cull and a few exact sign tests per occluder).
  // Copies what it needs; scene may be destroyed afterwards.
  explicit IlluminanceSolver(const Scene& scene);

  // === Queries (const and thread-safe)

  // computes the illuminance at `point` on a surface with unit outward `normal`.
  //   @param[in] point   receiving point P (m)
  //   @param[in] normal  unit outward normal N at P (precondition: finite, non-zero)
  PointIlluminance at(const Vec3d& point, const Vec3d& normal) const;

  // computes the same illuminance testing, for each light k, only the objects
  // occluders[k] (indices into Scene::objects, tested in the order given; put the
  // likeliest blocker first) as occluders: the fast path of a caller that knows which
  // objects can block each light, e.g. from the exact shadow maps of the face holding
  // the point (FaceShadow::occluders, shadow_map.h). Everything else is as in at(): the
  // outer-side tie-break, the exact tests on the objects given, the containing object.
  // Precondition: occluders.size() == light_count(), and no object outside occluders[k]
  // hides any part of light k from point; then the result equals at(point, normal).
  // Throws std::invalid_argument for a wrong number of lists or an index out of range.
  //   @param[in] occluders  #lights lists of object indices
  PointIlluminance at(const Vec3d& point, const Vec3d& normal,
                      const std::vector<std::vector<std::size_t>>& occluders) const;

  // computes the illuminance (lux) from light `light` (index into Scene::lights) alone.
  double light_at(std::size_t light, const Vec3d& point, const Vec3d& normal) const;

  // returns the visible parts of linear light `light` seen from point: the outer-side
  // part of the source minus every hidden sub-segment, as exact closed intervals of the
  // parameter u along start -> end, increasing. Precondition: the light is linear.
  std::vector<ExactInterval> visible_parts(std::size_t light, const Vec3d& point,
                                           const Vec3d& normal) const;

  // returns the object strictly containing point, or {}.
  std::optional<std::size_t> containing_object(const Vec3d& point) const;

  std::size_t light_count() const;

 private:
  struct Impl;
  std::shared_ptr<const Impl> impl_;
};

// computes the illuminance at one point of scene: the one-shot form of IlluminanceSolver.
PointIlluminance illuminance_at(const Scene& scene, const Vec3d& point, const Vec3d& normal);

// A receiving point and the unit outward normal of the surface it lies on.
struct ReceivingPoint {
  Vec3d point;
  Vec3d normal;
};

// returns the receiving point of the values x, y, z, nx, ny, nz, its normal scaled to unit
// length. A normal further than 1e-3 from unit length (enough for four decimals: 0.7071,
// 0.7071 has length 0.99999) is more likely a mix-up of columns than a normal, so it is
// refused rather than silently rescaled: InputError naming file and where (e.g. "line 4"),
// as for a zero normal or a value that is not finite.
ReceivingPoint receiving_point(const std::array<double, 6>& values, const std::string& file,
                               const std::string& where);

// computes solver.at(point, normal) at every receiving point, across TBB's threads: the one
// loop of `illuminance --points` and the work plane. advance, when given, is called with
// the number of points finished (from several threads) for a progress display.
std::vector<PointIlluminance> illuminance_at_points(
    const IlluminanceSolver& solver, const std::vector<ReceivingPoint>& receivers,
    const std::function<void(std::size_t)>& advance = {});

}  // namespace penumbra::illuminance
