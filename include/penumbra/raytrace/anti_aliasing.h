#pragma once
// Adaptive anti-aliasing, Whitted 1980 section 3 (Fig. 5): a pixel is the square whose
// corners are four sample points. Where the corner values are nearly equal their average
// stands for the square; where they differ, the square is cut into four and each quarter is
// treated the same way, down to a depth limit; quarters are weighted by their area.

#include <array>
#include <cstddef>
#include <functional>

#include "penumbra/base/colour.h"

namespace penumbra::raytrace {

struct AdaptiveOptions {
  int max_depth = 3;       // subdivision levels below the pixel (a square of 2^-depth pixels)
  double threshold = 0.1;  // corners differ when a channel differs by more than this ...
  double exposure = 1;     // ... after exposure and sRGB encoding (display units, 0..1)
};

// A sample of the image at continuous image coordinates (x, y).
using SampleFunction = std::function<Colour(double x, double y)>;

// The corners of a square in the order (x, y), (x + s, y), (x, y + s), (x + s, y + s).
using Corners = std::array<Colour, 4>;

struct SquareEstimate {
  Colour mean{0, 0, 0};     // the area-weighted mean over the square
  std::size_t samples = 0;  // samples taken beyond the four corners given
};

// returns true when two corner values are not "nearly equal" (section 3): some channel
// differs by more than options.threshold on the display.
bool values_differ(const Colour& a, const Colour& b, const AdaptiveOptions& options);

// estimates the mean of sample over the square [x, x + size] x [y, y + size] from its
// corners, subdividing recursively where they differ (depth counts levels already cut).
// force_below > 0 forces subdivision while the square is larger than force_below: Whitted's
// guard against small objects that fall between the sample points.
SquareEstimate adaptive_mean(const SampleFunction& sample, double x, double y, double size,
                             const Corners& corners, const AdaptiveOptions& options, int depth = 0,
                             double force_below = 0);

}  // namespace penumbra::raytrace
