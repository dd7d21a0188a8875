#pragma once
// One Embree 3 bounding volume hierarchy over a whole scene (issue 8, item 1): polygon faces
// as triangles, spheres exact. It supersedes Whitted's per-object bounding spheres (section
// 3): a ray visits only the boxes it crosses instead of testing every object's sphere.
// Embree traverses in single precision; each hit is refined in double precision against the
// exact face plane or the exact sphere, so hit points lie on the surface to double rounding.
// Bézier patches enter as user geometry, one primitive per flat piece, intersected in double
// precision (bezier_intersection.h); or, where the caller asks, as their tessellation.

#include <array>
#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <vector>
#include "penumbra/base/vec3d.h"

namespace penumbra {

struct Scene;

namespace raytrace {

// A ray segment: points origin + t direction with t_near <= t <= t_far.
struct Ray {
  Vec3d origin;
  Vec3d direction;  // unit length
  double t_near = 0;
  double t_far = std::numeric_limits<double>::infinity();
};

// The first surface a ray meets.
struct Hit {
  double distance;     // t along the (unit) direction
  Vec3d point;         // origin + distance * direction, on the surface
  std::size_t object;  // index into Scene::objects
  int face;            // index into the object's faces; -1 on an exact sphere or patch
  Vec3d normal;        // unit outward normal of the exact surface at point
};

// A sphere that encloses one object (used to find small objects, Whitted section 3).
struct BoundingSphere {
  Vec3d center;
  double radius;
};

// How objects made of Bézier patches enter: the patches themselves (the ray tracer), or
// the planar pieces of their tessellation like other objects (form factors, whose patches
// are faces of the tessellation).
enum class PatchSurfaces { exact, tessellated };

class EmbreeScene {
 public:
  // builds the hierarchy: every face of every object, fan-triangulated in single precision,
  // one exact sphere per sphere object, and the flat pieces of each Bézier patch (or its
  // tessellation). Two-sided polygons enter once.
  explicit EmbreeScene(const Scene& scene, PatchSurfaces patches = PatchSurfaces::exact);
  ~EmbreeScene();
  EmbreeScene(EmbreeScene&&) noexcept;
  EmbreeScene& operator=(EmbreeScene&&) noexcept;

  // returns the nearest hit on the ray, or {} when it hits nothing.
  std::optional<Hit> intersect(const Ray& ray) const;

  // returns true when something lies on the ray (between t_near and t_far).
  bool occluded(const Ray& ray) const;

  // intersects each ray with Embree only, without refinement or normals, and returns how
  // many hit: the bare traversal the benchmark compares shading against.
  std::size_t traverse(const std::vector<Ray>& rays) const;

  // the diagonal of the scene's bounding box (m): the scale of offsets and attenuation.
  double scale() const;

  // one enclosing sphere per object, in the order of Scene::objects.
  const std::vector<BoundingSphere>& bounding_spheres() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace raytrace
}  // namespace penumbra
