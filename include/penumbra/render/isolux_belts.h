#pragma once
// Isolux colour belts over a shaded image (Nishita 1985 section 5): the illuminance
// levels cut the image into bands; every other band is painted with a colour that varies
// with the illuminance (blue at 0, red at the image's maximum), and the bands between
// show the shaded image, so both remain visible. A legend gives the lux of each level in
// the colour of that level. Drawing only: doubles and 8-bit sRGB.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "penumbra/base/colour.h"
#include "penumbra/render/scanline_renderer.h"

namespace penumbra::render {

// returns the belt colour of illuminance e on a scale whose maximum is maximum: hue from
// 240 degrees (blue) at 0 to 0 (red) at maximum, full saturation. Precondition: maximum > 0.
Rgb8 belt_colour(double e, double maximum);

// The colour scale of belts, false colour and their legend over a set of levels: linear in
// the value from 0 (blue) to maximum (red) when the levels span at most a factor 20 (the
// evenly spaced levels of isolux_levels), otherwise logarithmic from the lowest level
// (blue) to maximum (red), so that every decade of a 1-2-5 series gets its share of hues.
struct LevelScale {
  double low = 0;      // the value drawn blue (0 on a linear scale)
  double maximum = 1;  // the value drawn red
  bool logarithmic = false;

  Rgb8 colour(double value) const;
};

// returns the scale of levels (increasing, positive) up to maximum (>= the last level).
LevelScale level_scale(const std::vector<double>& levels, double maximum);

// returns the band of e: the number of levels at or below e (levels increasing). Pixels
// in odd bands below the last (between two levels) are painted.
int isolux_band(double e, const std::vector<double>& levels);

// paints the belts of image's illuminance into rgb (3 bytes per pixel, rows from the top,
// the shaded picture of image) in the colours of level_scale(levels, max(last level, max
// E)). Pixels that see nothing are left alone. Precondition: levels increasing and positive.
void paint_isolux_belts(std::vector<std::uint8_t>& rgb, const RenderedImage& image,
                        const std::vector<double>& levels);

// paints every pixel that sees something in the colour of its value (values: one per
// pixel, lux or cd/m^2) on scale: the false-colour view of lighting design.
void paint_false_colour(std::vector<std::uint8_t>& rgb, const RenderedImage& image,
                        const std::vector<double>& values, const LevelScale& scale);

// draws the legend in the top-left corner: one line per level, a swatch of its colour on
// level_scale(levels, maximum) and its value followed by unit ("lx" or "cd/m2"), in a
// 3 x 5 bitmap font scaled by the image size.
void draw_isolux_legend(std::vector<std::uint8_t>& rgb, int width, int height,
                        const std::vector<double>& levels, double maximum,
                        const std::string& unit = "lx");

// returns the text of a level as the legend prints it ("%g" with up to 4 digits).
std::string level_text(double level);

}  // namespace penumbra::render
