#pragma once
// The one colour scale of illuminance drawings (Nishita 1985 section 5: "the color of the
// isolux belt varies in proportion to the illuminance value ... the maximum value is
// assigned to red"): hue from 240 degrees (blue) at 0 to 0 (red) at the maximum, full
// saturation. The render verb's isolux belts and the work-plane isolux plot use it.

#include <string>

#include "penumbra/base/colour.h"

namespace penumbra {

// returns the colour of fraction in [0, 1] (clamped) of the full scale.
Rgb8 scale_colour(double fraction);

// returns colour as "#rrggbb", each channel multiplied by darken (in [0, 1]) first.
std::string hex_colour(const Rgb8& colour, double darken = 1);

}  // namespace penumbra
