#include "penumbra/base/tone_map.h"

#include <algorithm>
#include <cmath>

namespace penumbra {

double srgb_encode(double linear) {
  const double x = std::clamp(linear, 0.0, 1.0);
  if (x <= 0.0031308) return 12.92 * x;
  return 1.055 * std::pow(x, 1 / 2.4) - 0.055;
}

double auto_exposure(const std::vector<Colour>& values) {
  std::vector<double> luminance;
  luminance.reserve(values.size());
  for (const Colour& v : values) {
    const double y = 0.2126 * v[0] + 0.7152 * v[1] + 0.0722 * v[2];
    if (y > 0) luminance.push_back(y);
  }
  if (luminance.empty()) return 1;
  const auto rank = static_cast<std::size_t>(0.99 * static_cast<double>(luminance.size() - 1));
  std::nth_element(luminance.begin(), luminance.begin() + static_cast<std::ptrdiff_t>(rank),
                   luminance.end());
  return 1 / luminance[rank];
}

std::vector<std::uint8_t> to_srgb8(const std::vector<Colour>& values, double exposure) {
  std::vector<std::uint8_t> bytes;
  bytes.reserve(3 * values.size());
  for (const Colour& v : values)
    for (double channel : v)
      bytes.push_back(
          static_cast<std::uint8_t>(std::lround(255 * srgb_encode(exposure * channel))));
  return bytes;
}

}  // namespace penumbra
