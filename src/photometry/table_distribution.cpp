#include "penumbra/photometry/table_distribution.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include "penumbra/base/numbers.h"

namespace penumbra::photometry {
namespace {

// Integrals over [x0, x1] of the weight w and of (x - x0) w, for w = sin or cos.
struct WeightIntegrals {
  double plain;
  double moment;
};

WeightIntegrals sin_integrals(double x0, double x1) {
  // int sin = -cos;  int (x - x0) sin x dx = -(x - x0) cos x + sin x.
  return {std::cos(x0) - std::cos(x1), -(x1 - x0) * std::cos(x1) + std::sin(x1) - std::sin(x0)};
}

WeightIntegrals cos_integrals(double x0, double x1) {
  // int cos = sin;  int (x - x0) cos x dx = (x - x0) sin x + cos x.
  return {std::sin(x1) - std::sin(x0), (x1 - x0) * std::sin(x1) + std::cos(x1) - std::cos(x0)};
}

// returns the integral over [x0, x1] of the linear function from a (at x0) to b (at x1)
// times the weight whose integrals are w.
double linear_times_weight(double x0, double x1, double a, double b, const WeightIntegrals& w) {
  return a * w.plain + (b - a) / (x1 - x0) * w.moment;
}

// returns the index i with angles[i] <= x < angles[i+1] (the last interval includes
// its end). Precondition: angles.front() <= x <= angles.back(), size >= 2.
std::size_t interval(const std::vector<double>& angles, double x) {
  const auto above = std::upper_bound(angles.begin(), angles.end(), x);
  const std::size_t i = static_cast<std::size_t>(above - angles.begin());
  return std::min(i == 0 ? 0 : i - 1, angles.size() - 2);
}

bool strictly_increasing(const std::vector<double>& values) {
  for (std::size_t i = 1; i < values.size(); ++i)
    if (!(values[i - 1] < values[i])) return false;
  return true;
}

}  // namespace

std::optional<Symmetry> horizontal_symmetry(const std::vector<double>& h, PhotometricType type) {
  if (h.empty()) return std::nullopt;
  const double first = h.front(), last = h.back();
  if (type != PhotometricType::c) {
    // LM-63 types A and B: lateral angles -90..90, or 0..90 for a laterally
    // symmetric luminaire (mirror H -> -H, which is C -> -C in the C-gamma frame). One
    // lateral angle is no range: nothing to interpolate across (found by fuzzing).
    if (h.size() < 2) return std::nullopt;
    if (first == 0 && last <= 90) return Symmetry::bilateral_c0_c180;
    if (first >= -90 && first < 0 && last <= 90) return Symmetry::none;
    return std::nullopt;
  }
  if (h.size() == 1 && first == 0) return Symmetry::axial;
  if (first == 0 && last == 90) return Symmetry::quadrant;
  if (first == 0 && last == 180) return Symmetry::bilateral_c0_c180;
  if (first == 90 && last == 270) return Symmetry::bilateral_c90_c270;
  // A full circle, with or without the closing 360 degree plane.
  if (first == 0 && last > 180 && last <= 360) return Symmetry::none;
  return std::nullopt;
}

TableDistribution::TableDistribution(PhotometricGrid grid, Interpolation interpolation)
    : grid_(std::move(grid)), interpolation_(interpolation) {
  const auto& h = grid_.horizontal_deg;
  const auto& v = grid_.vertical_deg;
  if (h.empty() || v.size() < 2 || grid_.candela.size() != h.size())
    throw std::invalid_argument("TableDistribution: grid sizes do not match");
  for (const auto& block : grid_.candela)
    if (block.size() != v.size()) throw std::invalid_argument("TableDistribution: ragged grid");
  if (!strictly_increasing(h) || !strictly_increasing(v))
    throw std::invalid_argument("TableDistribution: angles must strictly increase");
  if (interpolation_ == Interpolation::cosine && grid_.type != PhotometricType::c)
    throw std::invalid_argument("TableDistribution: cosine interpolation needs a type C grid");
  const auto symmetry = horizontal_symmetry(h, grid_.type);
  if (!symmetry) throw std::invalid_argument("TableDistribution: unsupported horizontal range");
  symmetry_ = *symmetry;

  // Unfold the stored blocks by the symmetry so that interpolation and integration
  // see the whole range: type C covers 0..360 degrees, types A and B -90..90 (or the
  // measured part of it).
  std::vector<std::pair<double, std::size_t>> unfolded;
  for (std::size_t k = 0; k < h.size(); ++k) {
    unfolded.emplace_back(h[k], k);
    if (grid_.type != PhotometricType::c) {
      if (symmetry_ == Symmetry::bilateral_c0_c180) unfolded.emplace_back(-h[k], k);
      continue;
    }
    switch (symmetry_) {
      case Symmetry::quadrant:
        unfolded.emplace_back(180 - h[k], k);
        unfolded.emplace_back(180 + h[k], k);
        unfolded.emplace_back(360 - h[k], k);
        break;
      case Symmetry::bilateral_c0_c180:
        unfolded.emplace_back(360 - h[k], k);
        break;
      case Symmetry::bilateral_c90_c270: {
        const double mirror = 180 - h[k];  // I(C) = I(180 - C)
        unfolded.emplace_back(mirror < 0 ? mirror + 360 : mirror, k);
        break;
      }
      default:
        break;
    }
  }
  std::stable_sort(unfolded.begin(), unfolded.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  unfolded.erase(std::unique(unfolded.begin(), unfolded.end(),
                             [](const auto& a, const auto& b) { return a.first == b.first; }),
                 unfolded.end());
  // Close the circle: C = 360 is C = 0 (the "360 degrees gives zero" bug of other parsers).
  if (grid_.type == PhotometricType::c && symmetry_ != Symmetry::axial &&
      unfolded.back().first < 360)
    unfolded.emplace_back(360.0, unfolded.front().second);
  for (const auto& [angle, block] : unfolded) {
    horizontal_.push_back(radians(angle));
    block_of_.push_back(block);
  }
  for (double angle : v) vertical_.push_back(radians(angle));
  // The physical ends: gamma 0 and 180 (type C), the poles H = +-90 of type B's
  // lateral angle and V = +-90 of type A's elevation (both from asin). Type B's plane
  // angle V and type A's H (from atan2) continue beyond 90 into the back hemisphere,
  // where a -90..90 table has no data.
  switch (grid_.type) {
    case PhotometricType::c:
      vertical_open_low_ = v.front() == 0;
      vertical_open_high_ = v.back() == 180;
      horizontal_open_low_ = horizontal_open_high_ = true;  // periodic
      break;
    case PhotometricType::b:
      horizontal_open_low_ = unfolded.front().first == -90;
      horizontal_open_high_ = unfolded.back().first == 90;
      break;
    case PhotometricType::a:
      vertical_open_low_ = v.front() == -90;
      vertical_open_high_ = v.back() == 90;
      break;
  }
  for (std::size_t i = 0; i < vertical_.size(); ++i)
    cos_vertical_.push_back(std::cos(vertical_[i]));
  for (std::size_t i = 0; i + 1 < vertical_.size(); ++i)
    inverse_cos_step_.push_back(1.0 / (cos_vertical_[i + 1] - cos_vertical_[i]));

  // The interpolant is bilinear (or monotone in t) on every cell, so its maximum is
  // at a node.
  max_candela_ = -1;
  for (std::size_t k = 0; k < h.size(); ++k)
    for (std::size_t i = 0; i < v.size(); ++i)
      if (grid_.candela[k][i] > max_candela_) {
        max_candela_ = grid_.candela[k][i];
        const double hk = radians(h[k]), vi = radians(v[i]);
        switch (grid_.type) {
          case PhotometricType::c:
            max_direction_ = {vi, hk};
            break;
          case PhotometricType::b:  // d = (cos H sin V, sin H, cos H cos V) in (e0, e90, axis)
            max_direction_ = {std::acos(std::clamp(std::cos(hk) * std::cos(vi), -1.0, 1.0)),
                              std::atan2(std::sin(hk), std::cos(hk) * std::sin(vi))};
            break;
          case PhotometricType::a:  // d = (sin V, cos V sin H, cos V cos H)
            max_direction_ = {std::acos(std::clamp(std::cos(vi) * std::cos(hk), -1.0, 1.0)),
                              std::atan2(std::cos(vi) * std::sin(hk), std::sin(vi))};
            break;
        }
        if (max_direction_.c < 0) max_direction_.c += 2 * pi;
      }
}

double TableDistribution::along_vertical(std::size_t block, std::size_t i, double vertical,
                                         double cos_vertical) const {
  const auto& values = grid_.candela[block];
  // Nishita eq. (1): I = I_i + (I_i+1 - I_i) t, t from the angle or from its cosine.
  const double t = interpolation_ == Interpolation::linear
                       ? (vertical - vertical_[i]) / (vertical_[i + 1] - vertical_[i])
                       : (cos_vertical - cos_vertical_[i]) * inverse_cos_step_[i];
  return values[i] + (values[i + 1] - values[i]) * t;
}

double TableDistribution::native(double horizontal, double vertical) const {
  // A table that reaches the end of the physical range (gamma 0 or 180 degrees; A and
  // B angles of +-90) covers every query up to it, so that pi and radians(180), which
  // may differ in the last bit, both hit the last node.
  if (vertical < vertical_.front()) {
    if (!vertical_open_low_) return 0;
    vertical = vertical_.front();
  }
  if (vertical > vertical_.back()) {
    if (!vertical_open_high_) return 0;
    vertical = vertical_.back();
  }
  const std::size_t i = interval(vertical_, vertical);
  const double cos_vertical = interpolation_ == Interpolation::cosine ? std::cos(vertical) : 0.0;
  if (symmetry_ == Symmetry::axial) return along_vertical(0, i, vertical, cos_vertical);
  if (horizontal < horizontal_.front()) {
    if (!horizontal_open_low_) return 0;
    horizontal = horizontal_.front();
  }
  if (horizontal > horizontal_.back()) {
    if (!horizontal_open_high_) return 0;
    horizontal = horizontal_.back();
  }
  const std::size_t j = interval(horizontal_, horizontal);
  const double s = (horizontal - horizontal_[j]) / (horizontal_[j + 1] - horizontal_[j]);
  const double low = along_vertical(block_of_[j], i, vertical, cos_vertical);
  const double high = along_vertical(block_of_[j + 1], i, vertical, cos_vertical);
  return low + (high - low) * s;
}

double TableDistribution::intensity(double gamma, double c) const {
  switch (grid_.type) {
    case PhotometricType::c: {
      double azimuth = std::fmod(c, 2 * pi);
      if (azimuth < 0) azimuth += 2 * pi;
      return native(azimuth, gamma);
    }
    case PhotometricType::b: {
      // Type B: polar axis e90 (lateral), beam along the axis, planes tilted toward e0.
      const double along = std::sin(gamma) * std::sin(c);
      return native(std::asin(std::clamp(along, -1.0, 1.0)),
                    std::atan2(std::sin(gamma) * std::cos(c), std::cos(gamma)));
    }
    case PhotometricType::a: {
      // Type A: polar axis e0 (vertical), elevation toward e0, lateral toward e90.
      const double up = std::sin(gamma) * std::cos(c);
      return native(std::atan2(std::sin(gamma) * std::sin(c), std::cos(gamma)),
                    std::asin(std::clamp(up, -1.0, 1.0)));
    }
  }
  return 0;
}

double TableDistribution::flux() const {
  const auto& values = grid_.candela;
  const std::size_t nv = vertical_.size();
  // The integral over one block's vertical profile, with the type's weight.
  auto profile = [&](std::size_t block, std::size_t i) {
    const double v0 = vertical_[i], v1 = vertical_[i + 1];
    const double a = values[block][i], b = values[block][i + 1];
    if (grid_.type == PhotometricType::c) {
      // Linear in cos(gamma): the trapezoid rule in u = cos(gamma) is exact.
      if (interpolation_ == Interpolation::cosine)
        return 0.5 * (a + b) * (cos_vertical_[i] - cos_vertical_[i + 1]);
      return linear_times_weight(v0, v1, a, b, sin_integrals(v0, v1));
    }
    return linear_times_weight(v0, v1, a, b, cos_integrals(v0, v1));  // type A: cos V
  };
  double total = 0;
  if (symmetry_ == Symmetry::axial) {
    for (std::size_t i = 0; i + 1 < nv; ++i) total += profile(0, i);
    return 2 * pi * total;
  }
  for (std::size_t j = 0; j + 1 < horizontal_.size(); ++j) {
    const double h0 = horizontal_[j], h1 = horizontal_[j + 1];
    const std::size_t k0 = block_of_[j], k1 = block_of_[j + 1];
    for (std::size_t i = 0; i + 1 < nv; ++i) {
      if (grid_.type == PhotometricType::b) {
        // Type B: dOmega = cos H dH dV, the weight lies along the horizontal angle.
        const WeightIntegrals w = cos_integrals(h0, h1);
        total += 0.5 * (vertical_[i + 1] - vertical_[i]) *
                 (linear_times_weight(h0, h1, values[k0][i], values[k1][i], w) +
                  linear_times_weight(h0, h1, values[k0][i + 1], values[k1][i + 1], w));
      } else {
        // Linear in the horizontal angle: the trapezoid rule across the cell is exact.
        total += 0.5 * (h1 - h0) * (profile(k0, i) + profile(k1, i));
      }
    }
  }
  return total;
}

std::shared_ptr<const TableDistribution> make_axial_table(const std::vector<double>& gamma_deg,
                                                          const std::vector<double>& candela,
                                                          Interpolation interpolation) {
  PhotometricGrid grid;
  grid.horizontal_deg = {0};
  grid.vertical_deg = gamma_deg;
  grid.candela = {candela};
  return std::make_shared<TableDistribution>(std::move(grid), interpolation);
}

}  // namespace penumbra::photometry
