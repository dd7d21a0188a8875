#pragma once
// Whitted's recursive illumination model (Whitted 1980, section 2, eq. (2)) in physical
// units, over an EmbreeScene:
//
//   L = sum_j [ rho color E_j / pi  +  (k_spec / pi) E_n,j cos^n(psi_j) ]  +  k_s S  +  k_t T
//
// E_j the illuminance from light j where its shadow ray is unblocked (Whitted's
// k_d sum (N . L_j) made photometric: rho E / pi is the luminance of a Lambertian face),
// the Phong term as in illuminance/specular.h (E_n = I / r^2, psi between the viewer and
// the light's mirror direction), S the radiance arriving along R, T along P. No ambient term
// (I_a = 0): every value is a luminance in cd/m^2 per colour channel. See docs/raytrace.md.

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "penumbra/base/colour.h"
#include "penumbra/raytrace/embree_scene.h"

namespace penumbra {

struct Scene;

namespace raytrace {

// Linear RGB luminance (cd/m^2) per channel.

enum class Attenuation {
  none,   // radiance is conserved along rays (physically right)
  linear  // Whitted section 2: each node's value falls linearly with its parent ray's length
};

struct TraceOptions {
  int max_depth = 8;         // deepest reflection/refraction generation (0: camera rays only)
  double min_weight = 1e-3;  // a branch whose product of k_s, k_t falls below stops
  bool fresnel = false;      // k_s, k_t from the dielectric Fresnel equations (docs)
  Attenuation attenuation = Attenuation::none;
  int tube_samples = 16;      // stratified elements per linear source and shading point for
                              // Phong's highlight (the diffuse term is exact, tube_visibility.h)
  int area_samples = 64;      // stratified shadow rays per area source and shading point
  std::uint64_t seed = 1980;  // the seed of every random choice (reproducible images)
  // Bézier patch objects: the patches (Newton on the bicubic) or their tessellation
  PatchSurfaces patches = PatchSurfaces::exact;
  // the indirect (interreflected) illuminance per channel (lux) at a point of face `face` of
  // object `object` (basis/indirect_light.h gives it from a radiosity solve), added to E of
  // eq. (2) at every diffuse hit on a face seen from outside; empty: none (Whitted's I_a = 0)
  std::function<Colour(std::size_t object, std::size_t face, const Vec3d& point)> indirect;
};

// Rays cast, by kind (Whitted's ray tree: camera, shadow, R and P rays).
struct RayCounts {
  std::uint64_t camera = 0;
  std::uint64_t shadow = 0;
  std::uint64_t reflected = 0;
  std::uint64_t refracted = 0;
  // when set, every ray cast is appended here (the benchmark replays them through bare
  // Embree traversal); not merged by +=.
  std::vector<Ray>* log = nullptr;

  std::uint64_t total() const { return camera + shadow + reflected + refracted; }
  RayCounts& operator+=(const RayCounts& other);
};

// What one ray brings back.
struct TraceResult {
  Colour radiance{0, 0, 0};
  std::optional<std::size_t> object;  // the first object hit (index into Scene::objects)
  double distance = 0;                // to that hit (infinite on a miss)
};

class RayTracer {
 public:
  // prepares the scene (builds its BVH). The scene must outlive the tracer.
  explicit RayTracer(const Scene& scene, TraceOptions options = {});
  ~RayTracer();

  // traces a camera ray and its whole ray tree; sample_key seeds the random choices of this
  // tree (roughness, tube strata), counts receives the rays cast.
  TraceResult trace(const Vec3d& origin, const Vec3d& direction, std::uint64_t sample_key,
                    RayCounts& counts) const;

  // returns the illuminance (lux) at point on a surface with unit normal, from every light:
  // the E of eq. (2), with shadow rays for point and directional lights and the exact visible
  // pieces of linear lights (tube_visibility.h; every object may occlude the point).
  double illuminance(const Vec3d& point, const Vec3d& normal, std::uint64_t sample_key,
                     RayCounts& counts) const;

  // returns the first object on a ray, without shading.
  std::optional<std::size_t> first_object(const Vec3d& origin, const Vec3d& direction) const;

  const Scene& scene() const;
  const EmbreeScene& embree_scene() const;
  const TraceOptions& options() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace raytrace
}  // namespace penumbra
