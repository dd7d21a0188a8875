#include "penumbra/render/isolux_belts.h"

#include "penumbra/base/colour_scale.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

namespace penumbra::render {

Rgb8 belt_colour(double e, double maximum) {
  // Nishita 1985 section 5: the colour varies in proportion to the illuminance.
  return scale_colour(e / maximum);
}

LevelScale level_scale(const std::vector<double>& levels, double maximum) {
  LevelScale scale;
  scale.maximum = maximum;
  if (!levels.empty() && levels.front() > 0 && levels.back() / levels.front() > 20) {
    scale.logarithmic = true;
    scale.low = levels.front();
  }
  return scale;
}

Rgb8 LevelScale::colour(double value) const {
  if (!logarithmic) return belt_colour(value, maximum);
  if (!(value > low)) return scale_colour(0);
  return scale_colour(std::log(value / low) / std::log(maximum / low));
}

int isolux_band(double e, const std::vector<double>& levels) {
  return static_cast<int>(std::upper_bound(levels.begin(), levels.end(), e) - levels.begin());
}

void paint_isolux_belts(std::vector<std::uint8_t>& rgb, const RenderedImage& image,
                        const std::vector<double>& levels) {
  const double maximum =
      std::max(levels.empty() ? 0.0 : levels.back(),
               *std::max_element(image.illuminance.begin(), image.illuminance.end()));
  if (!(maximum > 0)) return;
  const LevelScale scale = level_scale(levels, maximum);
  for (std::size_t pixel = 0; pixel < image.illuminance.size(); ++pixel) {
    if (image.visibility.objects[pixel] < 0) continue;
    const double e = image.illuminance[pixel];
    // above the highest level there is no closing line: the shaded image shows through
    const int band = isolux_band(e, levels);
    if (band % 2 == 0 || band == static_cast<int>(levels.size())) continue;
    const Rgb8 colour = scale.colour(e);
    for (int c = 0; c < 3; ++c) rgb[3 * pixel + c] = colour[c];
  }
}

void paint_false_colour(std::vector<std::uint8_t>& rgb, const RenderedImage& image,
                        const std::vector<double>& values, const LevelScale& scale) {
  for (std::size_t pixel = 0; pixel < values.size(); ++pixel) {
    if (image.visibility.objects[pixel] < 0) continue;
    const Rgb8 colour = scale.colour(values[pixel]);
    for (int c = 0; c < 3; ++c) rgb[3 * pixel + c] = colour[c];
  }
}

std::string level_text(double level) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", level);
  return text;
}

namespace {

// A 3 x 5 bitmap font: each glyph is five rows of three bits, the top row first.
const std::map<char, std::array<int, 5>>& font() {
  static const std::map<char, std::array<int, 5>> glyphs = {
      {'0', {7, 5, 5, 5, 7}}, {'1', {2, 6, 2, 2, 7}}, {'2', {7, 1, 7, 4, 7}},
      {'3', {7, 1, 7, 1, 7}}, {'4', {5, 5, 7, 1, 1}}, {'5', {7, 4, 7, 1, 7}},
      {'6', {7, 4, 7, 5, 7}}, {'7', {7, 1, 1, 1, 1}}, {'8', {7, 5, 7, 5, 7}},
      {'9', {7, 5, 7, 1, 7}}, {'.', {0, 0, 0, 0, 2}}, {'-', {0, 0, 7, 0, 0}},
      {'e', {0, 7, 7, 4, 7}}, {'+', {0, 2, 7, 2, 0}}, {'l', {4, 4, 4, 4, 6}},
      {'x', {0, 5, 2, 5, 5}}, {' ', {0, 0, 0, 0, 0}}, {'c', {0, 7, 4, 4, 7}},
      {'d', {1, 1, 7, 5, 7}}, {'m', {0, 7, 7, 5, 5}}, {'/', {1, 1, 2, 4, 4}}};
  return glyphs;
}

}  // namespace

void draw_isolux_legend(std::vector<std::uint8_t>& rgb, int width, int height,
                        const std::vector<double>& levels, double maximum,
                        const std::string& unit) {
  if (levels.empty() || !(maximum > 0)) return;
  const LevelScale colours = level_scale(levels, maximum);
  const int scale = std::max(1, std::min(width, height) / 160);
  const int line = 7 * scale;
  const auto set = [&](int x, int y, const Rgb8& colour) {
    if (x < 0 || y < 0 || x >= width || y >= height) return;
    const std::size_t pixel = static_cast<std::size_t>(y) * width + x;
    for (int c = 0; c < 3; ++c) rgb[3 * pixel + c] = colour[c];
  };
  std::size_t longest = 0;
  for (double level : levels)
    longest = std::max(longest, level_text(level).size() + 1 + unit.size());
  const int box_width = (6 + 4 * static_cast<int>(longest)) * scale + 2 * scale;
  const int box_height = line * static_cast<int>(levels.size()) + 2 * scale;
  for (int y = 0; y < box_height; ++y)
    for (int x = 0; x < box_width; ++x) set(x, y, {0, 0, 0});
  // the highest level on top, as on a colour scale
  for (std::size_t k = 0; k < levels.size(); ++k) {
    const double level = levels[levels.size() - 1 - k];
    const int top = scale + line * static_cast<int>(k);
    const Rgb8 colour = colours.colour(level);
    for (int y = 0; y < 5 * scale; ++y)
      for (int x = 0; x < 4 * scale; ++x) set(scale + x, top + y, colour);
    int left = 6 * scale;
    for (char ch : level_text(level) + " " + unit) {
      const auto glyph = font().find(ch);
      if (glyph != font().end())
        for (int row = 0; row < 5; ++row)
          for (int column = 0; column < 3; ++column)
            if (glyph->second[row] & (4 >> column))
              for (int y = 0; y < scale; ++y)
                for (int x = 0; x < scale; ++x)
                  set(left + column * scale + x, top + row * scale + y, {255, 255, 255});
      left += 4 * scale;
    }
  }
}

}  // namespace penumbra::render
