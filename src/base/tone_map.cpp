#include "penumbra/base/tone_map.h"

#include <algorithm>
#include <cmath>

namespace penumbra {

double srgb_encode(double linear) {
  const double x = std::clamp(linear, 0.0, 1.0);
  if (x <= 0.0031308) return 12.92 * x;
  return 1.055 * std::pow(x, 1 / 2.4) - 0.055;
}

namespace {

// returns the luminances Y of the non-black values.
std::vector<double> positive_luminances(const std::vector<Colour>& values) {
  std::vector<double> luminance;
  luminance.reserve(values.size());
  for (const Colour& v : values) {
    const double y = photometric_value(v);
    if (y > 0) luminance.push_back(y);
  }
  return luminance;
}

// returns the value of rank fraction (0: least, 1: greatest) of values (reordered).
// Precondition: values is not empty.
double percentile(std::vector<double>& values, double fraction) {
  const auto rank = static_cast<std::size_t>(fraction * static_cast<double>(values.size() - 1));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(rank),
                   values.end());
  return values[rank];
}

}  // namespace

double auto_exposure(const std::vector<Colour>& values) {
  std::vector<double> luminance = positive_luminances(values);
  if (luminance.empty()) return 1;
  return 1 / percentile(luminance, 0.99);
}

double log_average_exposure(const std::vector<Colour>& values, double key) {
  const std::vector<double> luminance = positive_luminances(values);
  if (luminance.empty()) return 1;
  double sum = 0;
  for (double y : luminance) sum += std::log(y);
  return key / std::exp(sum / static_cast<double>(luminance.size()));
}

double filmic_white(const std::vector<Colour>& values, double exposure) {
  std::vector<double> luminance = positive_luminances(values);
  if (luminance.empty()) return 1;
  return std::max(1.0, exposure * percentile(luminance, 0.99));
}

std::vector<std::uint8_t> to_srgb8(const std::vector<Colour>& values, double exposure,
                                   ToneCurve curve, double white) {
  std::vector<std::uint8_t> bytes;
  bytes.reserve(3 * values.size());
  for (const Colour& v : values) {
    double scale = exposure;
    if (curve == ToneCurve::filmic) {
      const double y = exposure * photometric_value(v);
      if (y > 0) scale = exposure * (1 + y / (white * white)) / (1 + y);
    }
    for (double channel : v)
      bytes.push_back(static_cast<std::uint8_t>(std::lround(255 * srgb_encode(scale * channel))));
  }
  return bytes;
}

}  // namespace penumbra
