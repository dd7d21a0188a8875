#pragma once
// From linear luminance (cd/m^2 per channel) to 8-bit sRGB: an exposure scale, clipping at
// white, and the sRGB transfer function (IEC 61966-2-1). Shared by the image writers.

#include <cstdint>
#include <vector>

#include "penumbra/base/colour.h"

namespace penumbra {

// returns the sRGB-encoded value of a linear value, both in [0, 1] (inputs outside clip).
double srgb_encode(double linear);

// returns the exposure (1 / (cd/m^2)) that maps the 99th percentile of the luminance
// Y = 0.2126 R + 0.7152 G + 0.0722 B of the non-black values to white, so a few highlights
// may clip but the scene is not dimmed by them; 1 when every value is black.
double auto_exposure(const std::vector<Colour>& values);

// returns 8-bit sRGB triples, row by row, of exposure * value.
std::vector<std::uint8_t> to_srgb8(const std::vector<Colour>& values, double exposure);

}  // namespace penumbra
