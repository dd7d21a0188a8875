#pragma once
// Colours: linear RGB triples for tints and radiance (cd/m^2 per channel, or relative
// in [0, 1] for a material's tint), and 8-bit sRGB triples for what is drawn.

#include <array>
#include <cstdint>

namespace penumbra {

using Colour = std::array<double, 3>;
using Rgb8 = std::array<std::uint8_t, 3>;

// The photometric value of a linear RGB triple: Y = 0.2126 R + 0.7152 G + 0.0722 B (Rec. 709
// luminance weights; equal channels give that value).
inline constexpr double kLuminanceWeights[3] = {0.2126, 0.7152, 0.0722};
inline double photometric_value(const Colour& rgb) {
  return kLuminanceWeights[0] * rgb[0] + kLuminanceWeights[1] * rgb[1] +
         kLuminanceWeights[2] * rgb[2];
}

}  // namespace penumbra
