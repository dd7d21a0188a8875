#pragma once
// Colours: linear RGB triples for tints and radiance (cd/m^2 per channel, or relative
// in [0, 1] for a material's tint), and 8-bit sRGB triples for what is drawn.

#include <array>
#include <cstdint>

namespace penumbra {

using Colour = std::array<double, 3>;
using Rgb8 = std::array<std::uint8_t, 3>;

}  // namespace penumbra
