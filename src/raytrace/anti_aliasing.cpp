#include "penumbra/raytrace/anti_aliasing.h"

#include <cmath>

#include "penumbra/base/tone_map.h"

namespace penumbra::raytrace {

bool values_differ(const Colour& a, const Colour& b, const AdaptiveOptions& options) {
  for (int c = 0; c < 3; ++c) {
    const double difference =
        srgb_encode(options.exposure * a[c]) - srgb_encode(options.exposure * b[c]);
    if (std::abs(difference) > options.threshold) return true;
  }
  return false;
}

SquareEstimate adaptive_mean(const SampleFunction& sample, double x, double y, double size,
                             const Corners& corners, const AdaptiveOptions& options, int depth,
                             double force_below) {
  SquareEstimate estimate;
  bool subdivide = false;
  if (depth < options.max_depth) {
    subdivide = force_below > 0 && size > force_below;
    for (int i = 0; i < 4 && !subdivide; ++i)
      for (int k = i + 1; k < 4 && !subdivide; ++k)
        subdivide = values_differ(corners[i], corners[k], options);
  }
  if (!subdivide) {
    // Section 3: nearly equal corners; their average approximates the whole square.
    for (int c = 0; c < 3; ++c)
      estimate.mean[c] = (corners[0][c] + corners[1][c] + corners[2][c] + corners[3][c]) / 4;
    return estimate;
  }
  // Five new points make the corners of the four quarters: edge midpoints and the centre.
  const double half = size / 2;
  const Colour top = sample(x + half, y);
  const Colour left = sample(x, y + half);
  const Colour centre = sample(x + half, y + half);
  const Colour right = sample(x + size, y + half);
  const Colour bottom = sample(x + half, y + size);
  estimate.samples = 5;
  const Corners quarters[4] = {{corners[0], top, left, centre},
                               {top, corners[1], centre, right},
                               {left, centre, corners[2], bottom},
                               {centre, right, bottom, corners[3]}};
  const double origins[4][2] = {{x, y}, {x + half, y}, {x, y + half}, {x + half, y + half}};
  for (int q = 0; q < 4; ++q) {
    const SquareEstimate part = adaptive_mean(sample, origins[q][0], origins[q][1], half,
                                              quarters[q], options, depth + 1, force_below);
    // Each quarter carries a quarter of the area.
    for (int c = 0; c < 3; ++c) estimate.mean[c] += part.mean[c] / 4;
    estimate.samples += part.samples;
  }
  return estimate;
}

}  // namespace penumbra::raytrace
