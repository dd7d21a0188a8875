#include "penumbra/base/colour_scale.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace penumbra {

Rgb8 scale_colour(double fraction) {
  const double hue = 4 * (1 - std::clamp(fraction, 0.0, 1.0));  // in sextants: 4 blue, 0 red
  const int sextant = std::min(3, static_cast<int>(hue));
  const double f = hue - sextant;
  double r = 0, g = 0, b = 0;
  switch (sextant) {
    case 0:
      r = 1, g = f;
      break;  // red -> yellow
    case 1:
      r = 1 - f, g = 1;
      break;  // yellow -> green
    case 2:
      g = 1, b = f;
      break;  // green -> cyan
    default:
      g = 1 - f, b = 1;
      break;  // cyan -> blue
  }
  const auto byte = [](double v) { return static_cast<std::uint8_t>(std::lround(255 * v)); };
  return {byte(r), byte(g), byte(b)};
}

std::string hex_colour(const Rgb8& colour, double darken) {
  char text[8];
  const auto channel = [&](std::uint8_t c) {
    return static_cast<int>(std::lround(c * std::clamp(darken, 0.0, 1.0)));
  };
  std::snprintf(text, sizeof text, "#%02x%02x%02x", channel(colour[0]), channel(colour[1]),
                channel(colour[2]));
  return text;
}

}  // namespace penumbra
