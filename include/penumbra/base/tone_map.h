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

// returns the exposure (1 / (cd/m^2)) that maps the log-average (geometric mean) luminance Y
// of the non-black values to key: Reinhard et al. 2002's automatic exposure, key 0.18 (a
// mid-grey); 1 when every value is black. Unlike auto_exposure, a bright minority (a sun
// patch) does not darken the rest: it saturates, or is rolled off by the filmic curve.
double log_average_exposure(const std::vector<Colour>& values, double key = 0.18);

// How scaled luminance becomes display values in [0, 1].
enum class ToneCurve {
  linear,  // clip at 1
  filmic   // Reinhard et al. 2002 eq. 4 on Y: Y (1 + Y / w^2) / (1 + Y), hue kept
};

// returns the white point w of the filmic curve for values at exposure: the 99th percentile
// of exposure * Y over the non-black values, at least 1 (so w maps to 1 and above it clips).
double filmic_white(const std::vector<Colour>& values, double exposure);

// returns 8-bit sRGB triples, row by row, of exposure * value (linear curve), or of the
// filmic curve of it with white point white: each channel is scaled by T(Y) / Y, T the
// curve, then clipped at 1.
std::vector<std::uint8_t> to_srgb8(const std::vector<Colour>& values, double exposure,
                                   ToneCurve curve = ToneCurve::linear, double white = 1);

}  // namespace penumbra
