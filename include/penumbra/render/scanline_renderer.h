#pragma once
// The scanline renderer (Nishita 1985 sections 3.3 and 4.2.2, Appendix A1): visibility
// by scan lines (scanline_visibility.h), then illuminance along each visible run of a
// face evaluated exactly (illuminance::IlluminanceSolver) at the run's ends, at the
// pixels on both sides of every crossing of a shadow boundary with the scan line, and
// every K pixels, and interpolated linearly in between. The shadow boundaries are the
// exact shadow and umbra regions of every light on the face (shadow_map.h), carried into
// the scan plane, so interpolation never bridges the edge of a shadow; that also covers
// section 4.2.2's object-space case, where the loops do not project onto the face. A face
// wholly beyond a point or linear light's sphere of lighting (section 3.1: below 1/256 of
// a 500 lx full scale) has no boundaries for that light: there interpolation may bridge
// the edge of a shadow worth less than that threshold.
//
// A diffuse face's luminance is L = rho E / pi (cd/m^2), tinted per channel by its
// material's colour. With an indirect light field (RenderOptions::indirect), E is the exact
// direct illuminance (interpolated along runs as above) plus the field's indirect
// illuminance evaluated at every pixel, per channel: radiance_c = rho color_c (E_direct +
// E_indirect,c) / pi, and L uses the photometric value of E_indirect (docs/render.md).

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "penumbra/render/scanline_visibility.h"
#include "penumbra/scene/scene.h"

namespace penumbra::render {

// The indirect (interreflected) illuminance per channel (lux) at a point of face `face` of
// object `object`, added to the exact direct light of every pixel (basis/indirect_light.h
// gives it from a radiosity solve; the render layer does not depend on how).
using IndirectLightField =
    std::function<Colour(std::size_t object, std::size_t face, const Vec3d& point)>;

struct RenderOptions {
  int interval = 3;             // K: evaluate every K pixels along a run (1: every pixel)
  bool parallel = true;         // TBB across scan lines
  IndirectLightField indirect;  // empty: direct light only
};

struct RenderedImage {
  int width = 0;
  int height = 0;
  VisibilityMap visibility;
  std::vector<double> illuminance;     // E, lux, per pixel; 0 where nothing is seen
  std::vector<double> indirect;        // the indirect part of E (photometric), lux, per pixel
  std::vector<double> luminance;       // L = rho E / pi, cd/m^2, per pixel
  std::vector<Colour> radiance;        // L tinted by the material colour, per channel
  std::size_t evaluations = 0;         // exact illuminance evaluations
  std::size_t boundary_crossings = 0;  // shadow boundaries met on scan lines

  std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * width + i; }
};

// Renders one camera's view of a scene, caching what does not depend on the interval:
// the visibility map, the shadow boundaries and occluder lists of every visible face and
// the illuminance solver.
class ScanlineRenderer {
 public:
  // computes the visibility of camera's image, the exact shadows of every light on every
  // face the camera sees (within the light's sphere of lighting; beyond it, the objects
  // that can shadow the face, without boundaries) and prepares the illuminance solver.
  // Throws what compute_shadows throws for a tube touching an object that shadows a seen
  // face. joint_umbrae: the exact umbrae of tubes hidden by several occluders together
  // (ShadowOptions::joint_umbrae), whose curved edges then bound the interpolation too.
  ScanlineRenderer(const Scene& scene, const Camera& camera, bool parallel = true,
                   bool joint_umbrae = false);
  ~ScanlineRenderer();

  // === Methods

  // shades the image: illuminance at span ends, shadow-boundary crossings and every
  // options.interval pixels, linear in between. Precondition: options.interval >= 1.
  RenderedImage render(const RenderOptions& options = {}) const;

  const VisibilityMap& visibility() const;
  const CameraFrame& view() const;

  // returns the point pixel (i, j) sees, lifted by surface_lift off its face so that it
  // is not inside its own solid after rounding, with the face's unit outward normal;
  // {} where nothing is seen.
  std::optional<std::array<Vec3d, 2>> visible_point(int i, int j) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// the distance (m, times 1 + the largest coordinate magnitude) a shading point is lifted
// off its face along the outward normal.
constexpr double surface_lift = 1e-9;

// renders camera's image of scene: the one-shot form of ScanlineRenderer.
RenderedImage render_scanline(const Scene& scene, const Camera& camera,
                              const RenderOptions& options = {});

}  // namespace penumbra::render
