#include "penumbra/raytrace/render.h"

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "penumbra/base/parallel.h"
#include "penumbra/base/progress.h"
#include "penumbra/base/random.h"
#include "penumbra/base/tone_map.h"
#include "penumbra/raytrace/anti_aliasing.h"
#include "penumbra/scene/camera_frame.h"
#include "penumbra/scene/scene.h"

namespace penumbra::raytrace {
namespace {

constexpr int kTile = 16;  // tile edge in pixels: the unit of parallel work

struct Tiles {
  int columns, rows;
  int count() const { return columns * rows; }
};

// returns, per pixel, the size below which Whitted's small-object guard keeps subdividing
// (0: no small object). Section 3 gives each small object's bounding sphere a minimum radius
// so some ray always meets it; here each bounding sphere that projects to less than a pixel
// marks the pixels around its image, which are then cut until their squares are no larger
// than the projected radius.
std::vector<double> small_object_guard(const EmbreeScene& embree, const CameraFrame& camera) {
  const int width = camera.width(), height = camera.height();
  std::vector<double> guard(static_cast<std::size_t>(width) * static_cast<std::size_t>(height),
                            0.0);
  for (const BoundingSphere& sphere : embree.bounding_spheres()) {
    const auto projected = camera.project(sphere.center);
    if (!projected || (*projected)[2] <= sphere.radius) continue;
    const double radius = sphere.radius / (*projected)[2] / camera.pixel_angle();
    if (radius >= 1) continue;  // large enough for the corner samples to find it
    const double floor_radius = std::max(radius, 1.0 / 64);
    const int i0 = static_cast<int>(std::floor((*projected)[0] - 1));
    const int j0 = static_cast<int>(std::floor((*projected)[1] - 1));
    for (int j = std::max(0, j0); j <= std::min(height - 1, j0 + 2); ++j)
      for (int i = std::max(0, i0); i <= std::min(width - 1, i0 + 2); ++i) {
        double& size = guard[static_cast<std::size_t>(j) * width + i];
        size = size == 0 ? floor_radius : std::min(size, floor_radius);
      }
  }
  return guard;
}

}  // namespace

RenderedImage render(const RayTracer& tracer, const Camera& scene_camera,
                     const RenderOptions& options) {
  const CameraFrame camera(scene_camera);
  const int width = camera.width(), height = camera.height();
  const std::uint64_t seed = tracer.options().seed;
  RenderedImage image;
  image.width = width;
  image.height = height;
  const std::size_t pixel_count = static_cast<std::size_t>(width) * height;
  image.pixels.assign(pixel_count, Colour{0, 0, 0});
  const Tiles tiles{(width + kTile - 1) / kTile, (height + kTile - 1) / kTile};
  tbb::enumerable_thread_specific<RayCounts> thread_counts;

  const auto sample_at = [&](double x, double y, RayCounts& counts) {
    // Each sample seeds its own random stream from its position: shared corners agree and
    // the image does not depend on the order in which tiles run.
    return tracer.trace(camera.eye(), camera.unit_direction(x, y), position_key(seed, x, y), counts)
        .radiance;
  };
  const bool adaptive = options.anti_aliasing == AntiAliasing::adaptive;
  Progress progress("raytrace", static_cast<std::size_t>(tiles.count()) +
                                    (adaptive ? static_cast<std::size_t>(height + 1) : 0));

  std::vector<Colour> corners;
  if (adaptive) {
    // Section 3, Fig. 5a: every pixel corner is a sample point shared by up to four pixels.
    const auto corner_width = static_cast<std::size_t>(width) + 1;
    corners.assign(corner_width * static_cast<std::size_t>(height + 1), Colour{0, 0, 0});
    for_each_index(static_cast<std::size_t>(height + 1), true, [&](std::size_t row) {
      const int j = static_cast<int>(row);
      RayCounts& counts = thread_counts.local();
      for (int i = 0; i <= width; ++i)
        corners[static_cast<std::size_t>(j) * corner_width + i] = sample_at(i, j, counts);
      if (options.progress) progress.advance();
    });
    image.exposure = options.exposure ? *options.exposure : auto_exposure(corners);
  }

  const std::vector<double> guard =
      adaptive ? small_object_guard(tracer.embree_scene(), camera) : std::vector<double>{};
  std::atomic<std::size_t> subdivided{0};
  const AdaptiveOptions adaptive_options{options.aa_depth, options.aa_threshold, image.exposure};
  const int grid =
      options.anti_aliasing == AntiAliasing::fixed ? std::max(1, options.fixed_grid) : 1;

  for_each_index(static_cast<std::size_t>(tiles.count()), true, [&](std::size_t tile_index) {
    const int tile = static_cast<int>(tile_index);
    RayCounts& counts = thread_counts.local();
    const int i_begin = (tile % tiles.columns) * kTile, j_begin = (tile / tiles.columns) * kTile;
    const SampleFunction sample = [&](double x, double y) { return sample_at(x, y, counts); };
    for (int j = j_begin; j < std::min(height, j_begin + kTile); ++j)
      for (int i = i_begin; i < std::min(width, i_begin + kTile); ++i) {
        const std::size_t index = static_cast<std::size_t>(j) * width + i;
        Colour& pixel = image.pixels[index];
        if (adaptive) {
          const auto corner_width = static_cast<std::size_t>(width) + 1;
          const auto at = [&](int ci, int cj) {
            return corners[static_cast<std::size_t>(cj) * corner_width + ci];
          };
          const SquareEstimate estimate = adaptive_mean(
              sample, i, j, 1, {at(i, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)},
              adaptive_options, 0, guard[index]);
          pixel = estimate.mean;
          if (estimate.samples > 0) ++subdivided;
        } else {
          // Pixel centres, or the centres of a fixed grid of sub-squares.
          for (int b = 0; b < grid; ++b)
            for (int a = 0; a < grid; ++a) {
              const Colour value = sample(i + (a + 0.5) / grid, j + (b + 0.5) / grid);
              for (int c = 0; c < 3; ++c) pixel[c] += value[c] / (grid * grid);
            }
        }
      }
    if (options.progress) progress.advance();
  });

  if (!adaptive)
    image.exposure = options.exposure ? *options.exposure : auto_exposure(image.pixels);
  if (options.objects) {
    image.objects.assign(pixel_count, -1);
    for_each_index(static_cast<std::size_t>(height), true, [&](std::size_t row) {
      const int j = static_cast<int>(row);
      thread_counts.local().camera += static_cast<std::uint64_t>(width);
      for (int i = 0; i < width; ++i) {
        const auto object =
            tracer.first_object(camera.eye(), camera.unit_direction(i + 0.5, j + 0.5));
        if (object)
          image.objects[static_cast<std::size_t>(j) * width + i] = static_cast<long>(*object);
      }
    });
  }
  for (const RayCounts& counts : thread_counts) image.counts += counts;
  image.subdivided_pixels = subdivided;
  return image;
}

}  // namespace penumbra::raytrace
