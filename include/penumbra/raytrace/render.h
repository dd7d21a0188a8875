#pragma once
// A whole ray-traced image: camera rays through the scene camera (scene/camera_frame.h), Whitted's
// ray tree per sample (RayTracer), anti-aliasing per pixel, in parallel over tiles (TBB).

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "penumbra/raytrace/ray_tracer.h"

namespace penumbra {

struct Camera;

namespace raytrace {

enum class AntiAliasing {
  none,      // one sample through each pixel centre
  adaptive,  // Whitted section 3: corner samples, subdivided where they differ
  fixed      // a fixed grid of fixed_grid x fixed_grid samples per pixel (for comparison)
};

struct RenderOptions {
  AntiAliasing anti_aliasing = AntiAliasing::adaptive;
  int aa_depth = 3;                // adaptive: subdivision levels below the pixel
  int fixed_grid = 4;              // fixed: samples per pixel side
  double aa_threshold = 0.1;       // display units (sRGB, 0..1), see AdaptiveOptions
  std::optional<double> exposure;  // 1 / (cd/m^2); automatic when empty (auto_exposure)
  bool objects = false;            // record the object seen through each pixel centre
  bool progress = true;            // show progress on a terminal
};

struct RenderedImage {
  int width = 0;
  int height = 0;
  std::vector<Colour> pixels;         // linear luminance per channel, rows from the top
  std::vector<long> objects;          // object index per pixel, -1 for the background (if asked)
  double exposure = 1;                // the exposure used to judge corner differences and to save
  RayCounts counts;                   // every ray cast
  std::size_t subdivided_pixels = 0;  // adaptive: pixels cut at least once
};

// renders the camera's image of the tracer's scene.
RenderedImage render(const RayTracer& tracer, const Camera& camera, const RenderOptions& options);

}  // namespace raytrace
}  // namespace penumbra
