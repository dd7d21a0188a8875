#include "penumbra/raytrace/ray_tracer.h"

#include <cmath>
#include <limits>

#include "penumbra/base/numbers.h"
#include "penumbra/base/random.h"
#include "penumbra/base/vec3d.h"
#include "penumbra/photometry/orientation.h"
#include "penumbra/raytrace/area_sampling.h"
#include "penumbra/raytrace/optics.h"
#include "penumbra/raytrace/tube_sampling.h"
#include "penumbra/raytrace/tube_visibility.h"
#include "penumbra/scene/scene.h"

namespace penumbra::raytrace {

using namespace vector_ops;

RayCounts& RayCounts::operator+=(const RayCounts& other) {
  camera += other.camera;
  shadow += other.shadow;
  reflected += other.reflected;
  refracted += other.refracted;
  return *this;
}

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// A shadow ray crosses at most this many transparent surfaces before it counts as blocked.
constexpr int kMaxShadowCrossings = 16;

}  // namespace

struct RayTracer::Impl {
  const Scene& scene;
  EmbreeScene embree;
  TraceOptions options;
  TubeVisibility tubes;
  bool any_transparent = false;
  // Secondary rays start at the exact hit point but ignore hits closer than this (m):
  // Embree traverses in single precision, so a ray leaving the surface could find the
  // surface again. Skipping along the ray, not off along the normal, keeps the ray's line
  // exact (no lateral shift through a slab); surfaces closer than this are not seen.
  double offset;

  Impl(const Scene& scene_in, TraceOptions options_in)
      : scene(scene_in),
        embree(scene_in, options_in.patches),
        options(options_in),
        tubes(scene_in, options_in.min_weight) {
    for (const Object& object : scene.objects)
      if (scene.materials[object.material].transmit > 0) any_transparent = true;
    offset = 1e-5 * embree.scale();
  }

  const Material& material_of(std::size_t object) const {
    return scene.materials[scene.objects[object].material];
  }

  // returns the fraction of light that passes along the segment from origin over distance
  // (Whitted section 2: a blocked shadow ray removes the light's contribution). Transparent
  // surfaces on the way pass k_t each; shadow rays are not refracted.
  double transmittance(const Vec3d& origin, const Vec3d& direction, double distance,
                       RayCounts& counts) const {
    Ray ray{origin, direction, offset, distance - offset};
    if (ray.t_far <= ray.t_near) return 1;
    if (!any_transparent) {
      ++counts.shadow;
      if (counts.log) counts.log->push_back(ray);
      return embree.occluded(ray) ? 0 : 1;
    }
    double passed = 1;
    for (int crossing = 0; crossing < kMaxShadowCrossings; ++crossing) {
      ++counts.shadow;
      if (counts.log) counts.log->push_back(ray);
      const std::optional<Hit> hit = embree.intersect(ray);
      if (!hit) return passed;
      passed *= material_of(hit->object).transmit;
      if (passed < options.min_weight) return 0;
      ray.origin = hit->point;
      ray.t_far -= hit->distance;
      if (ray.t_far <= ray.t_near) return passed;
    }
    return 0;
  }

  // Accumulates the light arriving at a shading point: the diffuse sum of eq. (2) and
  // Phong's specular term (Whitted section 2, last paragraph of the model: highlights of
  // the light sources themselves use Phong's model, not the perturbation scheme).
  struct DirectLight {
    const Vec3d& normal;     // facing normal
    const Vec3d& to_viewer;  // unit, from the point toward where the ray came from
    const Material* material;
    double illuminance = 0;  // lux
    double specular = 0;     // cd/m^2

    // adds a light of normal illuminance e_normal (lux) arriving from unit direction
    // to_light, with cos_alpha = N . to_light > 0.
    void add(double e_normal, double cos_alpha, const Vec3d& to_light) {
      illuminance += e_normal * cos_alpha;
      add_highlight(e_normal, cos_alpha, to_light);
    }

    bool has_highlights() const { return material && material->specular > 0; }

    // adds Phong's term only.
    void add_highlight(double e_normal, double cos_alpha, const Vec3d& to_light) {
      if (!has_highlights()) return;
      const Vec3d mirror = 2 * cos_alpha * normal - to_light;
      const double cos_psi = dot(mirror, to_viewer);
      if (cos_psi > 0)
        specular += material->specular / pi * e_normal * std::pow(cos_psi, material->shininess);
    }
  };

  // surface: the object the point lies on (its own tube occlusion is decided by convexity,
  // tube_visibility.h), {} for a free point.
  void gather(const Vec3d& point, const std::optional<ShadedSurface>& surface, DirectLight& light,
              SplitMix64& random, RayCounts& counts) const {
    const Vec3d& normal = light.normal;
    const Vec3d& origin = point;
    // shadow_passed < 0: cast the shadow ray here; otherwise the caller already did.
    // highlight_only: the diffuse part is counted elsewhere.
    const auto from_point_light = [&](const Vec3d& position, auto&& intensity_toward,
                                      double shadow_passed, bool highlight_only = false) {
      const Vec3d to_light = position - point;
      const double r2 = dot(to_light, to_light);
      const double distance = std::sqrt(r2);
      if (distance == 0) return;
      const Vec3d direction = (1 / distance) * to_light;
      const double cos_alpha = dot(normal, direction);
      if (cos_alpha <= 0) return;  // grazing or behind: unlit (DESIGN.md tie-break)
      const double candela = intensity_toward(-direction);
      if (candela <= 0) return;
      const double passed =
          shadow_passed >= 0 ? shadow_passed : transmittance(origin, direction, distance, counts);
      if (passed <= 0) return;
      if (highlight_only)
        light.add_highlight(candela * passed / r2, cos_alpha, direction);
      else
        light.add(candela * passed / r2, cos_alpha, direction);
    };
    for (std::size_t index = 0; index < scene.lights.size(); ++index) {
      const Light& source = scene.lights[index];
      if (const auto* lamp = std::get_if<PointLight>(&source.source)) {
        from_point_light(
            lamp->position,
            [&](const Vec3d& direction) {
              return photometry::intensity_toward(*lamp->distribution, lamp->axis, lamp->c0,
                                                  direction);
            },
            -1);
      } else if (const auto* sun = std::get_if<DirectionalLight>(&source.source)) {
        const Vec3d direction = -normalized(sun->direction);
        const double cos_alpha = dot(normal, direction);
        if (cos_alpha <= 0) continue;
        const double passed = transmittance(origin, direction, kInfinity, counts);
        if (passed > 0) light.add(sun->illuminance * passed, cos_alpha, direction);
      } else if (const auto* panel = std::get_if<AreaLight>(&source.source)) {
        // Stratified shadow rays over the polygon, each element a point source.
        const auto passed = [&](const Vec3d& position) {
          const Vec3d to = position - point;
          const double distance = length(to);
          return transmittance(origin, (1 / distance) * to, distance, counts);
        };
        for (const SourceElement& element :
             sample_area_stratified(*panel, point, options.area_samples, random.next(), passed))
          from_point_light(
              element.position, [&](const Vec3d&) { return element.candela; }, 1);
      } else if (const auto* tube = std::get_if<LinearLight>(&source.source)) {
        // Nishita 1985 section 4.2.3: the closed form over the exactly visible pieces, each
        // scaled by what transparent occluders pass (no shadow rays).
        const std::vector<TubePiece> pieces = tubes.pieces(index, point, normal, surface);
        light.illuminance += tube_illuminance(*tube, point, normal, pieces);
        // Phong's highlight has no closed form: stratified elements within the pieces.
        const std::uint64_t seed = random.next();
        if (!light.has_highlights()) continue;
        for (const SourceElement& element :
             sample_tube_stratified(*tube, point, pieces, options.tube_samples, seed))
          from_point_light(
              element.position, [&](const Vec3d&) { return element.candela; }, 1, true);
      }
    }
  }

  // Whitted section 2: a rough surface is modelled by a random perturbation of the normal
  // (microfacets); the perturbed normal must still face the ray.
  Vec3d perturbed_normal(const Vec3d& normal, const Vec3d& direction, double roughness,
                         SplitMix64& random) const {
    if (roughness <= 0) return normal;
    for (int attempt = 0; attempt < 8; ++attempt) {
      const Vec3d jitter{random.normal(), random.normal(), random.normal()};
      const Vec3d candidate = normalized(normal + roughness * jitter);
      if (dot(direction, candidate) < 0) return candidate;
    }
    return normal;
  }

  double attenuation(double distance) const {
    if (options.attenuation == Attenuation::none) return 1;
    // Whitted section 2: linear in the distance between the intersection points; the scene
    // diagonal, the longest segment inside the scene's box, brings it to zero.
    return std::max(0.0, 1 - distance / embree.scale());
  }

  TraceResult shade(const Ray& ray, int depth, double weight, SplitMix64& random,
                    RayCounts& counts) const {
    TraceResult result;
    result.distance = kInfinity;
    if (counts.log) counts.log->push_back(ray);
    const std::optional<Hit> hit = embree.intersect(ray);
    if (!hit) return result;  // the background is black
    result.object = hit->object;
    result.distance = hit->distance;
    const Object& object = scene.objects[hit->object];
    const Material& material = scene.materials[object.material];
    const Vec3d& direction = ray.direction;

    // Section 2 sign conventions: N toward the incoming ray, k_n inverted when leaving.
    const FacingSurface surface = face_the_ray(direction, hit->normal, material.ior);
    const Vec3d to_viewer = -direction;
    DirectLight light{surface.normal, to_viewer, &material};
    const bool inside = dot(surface.normal, hit->normal) < 0;
    gather(hit->point, ShadedSurface{hit->object, inside}, light, random, counts);
    Colour indirect{0, 0, 0};
    if (options.indirect && hit->face >= 0 && !inside)
      indirect = options.indirect(hit->object, static_cast<std::size_t>(hit->face), hit->point);
    for (int c = 0; c < 3; ++c)
      result.radiance[c] =
          material.reflectance * material.color[c] * (light.illuminance + indirect[c]) / pi +
          light.specular;

    if (depth >= options.max_depth) return result;
    double k_s = material.reflect;
    double k_t = material.transmit;
    if (k_s <= 0 && k_t <= 0) return result;
    const Vec3d normal = perturbed_normal(surface.normal, direction, material.roughness, random);
    if (options.fresnel && material.ior != 1) {
      // Section 2: "for the best accuracy they should be functions that incorporate ... the
      // Fresnel reflection law": k_s = F, and what is not reflected is transmitted.
      const double reflectance =
          fresnel_reflectance(-dot(direction, normal), surface.relative_index);
      k_s = reflectance;
      k_t = material.transmit * (1 - reflectance);
    }
    if (k_s > 0 && weight * k_s >= options.min_weight) {
      Vec3d reflected = reflected_direction(direction, normal);
      if (dot(reflected, surface.normal) <= 0)
        reflected = reflected_direction(direction, surface.normal);
      ++counts.reflected;
      const TraceResult s =
          shade({hit->point, reflected, offset}, depth + 1, weight * k_s, random, counts);
      const double factor = k_s * attenuation(s.distance);
      for (int c = 0; c < 3; ++c) result.radiance[c] += factor * s.radiance[c];
    }
    if (k_t > 0 && weight * k_t >= options.min_weight) {
      std::optional<Vec3d> transmitted;
      if (object.solid.is_flat()) {
        transmitted = direction;  // a sheet of no thickness: in and out at once, unbent
      } else {
        transmitted = refracted_direction(direction, normal, surface.relative_index);
        if (transmitted && dot(*transmitted, surface.normal) >= 0)
          transmitted = refracted_direction(direction, surface.normal, surface.relative_index);
      }
      // Section 2: under total internal reflection T is zero.
      if (transmitted) {
        ++counts.refracted;
        const TraceResult t =
            shade({hit->point, *transmitted, offset}, depth + 1, weight * k_t, random, counts);
        const double factor = k_t * attenuation(t.distance);
        for (int c = 0; c < 3; ++c) result.radiance[c] += factor * t.radiance[c];
      }
    }
    return result;
  }
};

RayTracer::RayTracer(const Scene& scene, TraceOptions options)
    : impl_(std::make_unique<Impl>(scene, options)) {}

RayTracer::~RayTracer() = default;

TraceResult RayTracer::trace(const Vec3d& origin, const Vec3d& direction, std::uint64_t sample_key,
                             RayCounts& counts) const {
  SplitMix64 random(mix_bits(impl_->options.seed ^ sample_key));
  ++counts.camera;
  return impl_->shade({origin, normalized(direction)}, 0, 1, random, counts);
}

double RayTracer::illuminance(const Vec3d& point, const Vec3d& normal, std::uint64_t sample_key,
                              RayCounts& counts) const {
  SplitMix64 random(mix_bits(impl_->options.seed ^ sample_key));
  const Vec3d unit = normalized(normal);
  Impl::DirectLight light{unit, unit, nullptr};
  impl_->gather(point, std::nullopt, light, random, counts);
  return light.illuminance;
}

std::optional<std::size_t> RayTracer::first_object(const Vec3d& origin,
                                                   const Vec3d& direction) const {
  const std::optional<Hit> hit = impl_->embree.intersect({origin, normalized(direction)});
  if (!hit) return std::nullopt;
  return hit->object;
}

const Scene& RayTracer::scene() const {
  return impl_->scene;
}
const EmbreeScene& RayTracer::embree_scene() const {
  return impl_->embree;
}
const TraceOptions& RayTracer::options() const {
  return impl_->options;
}

}  // namespace penumbra::raytrace
