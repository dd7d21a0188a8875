#pragma once
// Closed-form luminous intensity distributions of the papers: the spotlight of
// Dobashi 1995 eq. (11) and the (1 + cos)/2 curve of Nishita 1985 section 3.1.

#include <memory>

#include "penumbra/base/numbers.h"
#include "penumbra/photometry/distribution.h"

namespace penumbra::photometry {

// Dobashi 1995 eq. (11): I(g) = I0 cos^k g for g < spread, 0 beyond.
class CosPowerDistribution final : public Distribution {
 public:
  // builds the spot of on-axis intensity candela (>= 0), sharpness power (>= 0) and
  // spread angle spread_deg in (0, 90]. Beyond 90 degrees cos^k would be negative
  // (odd k) or a mirrored back lobe (even k), neither a spotlight, so it is refused.
  CosPowerDistribution(double candela, double power, double spread_deg);

  double intensity(double gamma, double c) const override;
  double max_intensity() const override { return candela_; }
  PhotometricDirection max_direction() const override { return {0, 0}; }
  // 2 pi I0 (1 - cos^(k+1) s) / (k + 1), the integral of I0 cos^k g sin g over g < s.
  double flux() const override;
  Symmetry symmetry() const override { return Symmetry::axial; }

  double power() const { return power_; }
  double spread() const { return spread_; }

 private:
  double candela_;
  double power_;
  double spread_;  // radians
};

// Nishita 1985 section 3.1: I(g) = I0 (1 + cos g) / 2, a cardioid in the polar plot.
class CardioidDistribution final : public Distribution {
 public:
  explicit CardioidDistribution(double candela) : candela_(candela) {}

  double intensity(double gamma, double c) const override;
  double max_intensity() const override { return candela_; }
  PhotometricDirection max_direction() const override { return {0, 0}; }
  // 2 pi I0: int_0^pi (1 + cos g)/2 sin g dg = 1.
  double flux() const override { return 2 * pi * candela_; }
  Symmetry symmetry() const override { return Symmetry::axial; }

 private:
  double candela_;
};

}  // namespace penumbra::photometry
