#pragma once
// The parts of a linear source (tube) that light a shading point of the ray tracer, each with
// the fraction of its light that arrives: Nishita 1985 section 4.2.3 (the source minus the
// sub-segments occluders hide, exact intervals from illuminance/occlusion.h) extended to
// Whitted 1980 section 2's transparent shadows. See docs/raytrace.md, "Tubes".
//
// Rule for transparent occluders, the one the point-light shadow rays follow: light crossing
// a surface with `transmit` k_t passes k_t of itself, so a tube element seen through a convex
// solid (two surfaces) passes k_t^2, through a flat polygon (one surface) k_t, through several
// occluders the product of their factors; an opaque occluder passes 0. A piece whose factor
// falls below the tracer's branch-weight threshold passes 0, as a shadow ray does.
//
// Every visibility decision is exact (Epeck); only the pieces' parameter ends are rounded
// to doubles, to integrate the closed form of illuminance/linear_source.h.

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "penumbra/base/vec3d.h"

namespace penumbra {

struct Scene;
struct LinearLight;

namespace raytrace {

// A piece of a tube: parameters [low, high] along start -> end, Q(u) = start + u (end -
// start), whose light arrives scaled by `passed` in (0, 1].
struct TubePiece {
  double low;
  double high;
  double passed;
};

// The surface a shading point lies on.
struct ShadedSurface {
  std::size_t object;  // index into Scene::objects
  bool inside;         // shaded from inside the object (the facing normal points inward)
};

class TubeVisibility {
 public:
  // prepares repeated queries on scene: each object's bounding box and transmission factor,
  // each linear light's exact end points. The scene must outlive this object.
  //   @param[in] min_passed  pieces passing less than this pass nothing (the tracer's
  //                          TraceOptions::min_weight)
  TubeVisibility(const Scene& scene, double min_passed);
  ~TubeVisibility();

  // === Queries (const and thread-safe)

  // computes the pieces of linear light `light` (index into Scene::lights) that light
  // `point`: the part strictly on the outer side of the plane through point with normal
  // `normal` (Nishita Fig. 7, S3), cut at the end of every sub-segment an occluder hides,
  // each piece weighted by the product of the factors of the occluders hiding it; pieces
  // passing nothing are left out. In increasing order, disjoint.
  //   @param[in] point    the shading point P (m)
  //   @param[in] normal   the facing normal N at P (any length > 0)
  //   @param[in] surface  the surface P lies on, if any. That object is not tested
  //                       exactly (P is rounded from its surface, so an exact test could
  //                       put P inside it): a convex object hides nothing on the outer side
  //                       of its tangent plane, and seen from inside a solid the light
  //                       crosses its one surface (k_t).
  // Occluders whose bounding box misses the box of the triangle (P, start, end), or lies
  // strictly on one side of its plane, are skipped before the exact work. Precondition: the
  // light is linear.
  std::vector<TubePiece> pieces(std::size_t light, const Vec3d& point, const Vec3d& normal,
                                const std::optional<ShadedSurface>& surface = {}) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// computes the illuminance (lux) at `point` (unit `normal`) from the tube over `pieces`: the
// sum of passed times the closed form of illuminance/linear_source.h over each piece.
double tube_illuminance(const LinearLight& tube, const Vec3d& point, const Vec3d& normal,
                        const std::vector<TubePiece>& pieces);

}  // namespace raytrace
}  // namespace penumbra
