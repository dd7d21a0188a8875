#include "penumbra/photometry/analytic_distribution.h"

#include <cmath>
#include <stdexcept>
#include "penumbra/base/numbers.h"

namespace penumbra::photometry {

CosPowerDistribution::CosPowerDistribution(double candela, double power, double spread_deg)
    : candela_(candela), power_(power), spread_(radians(spread_deg)) {
  if (!(candela >= 0) || !(power >= 0) || !(spread_deg > 0 && spread_deg <= 90))
    throw std::invalid_argument("CosPowerDistribution: candela, power >= 0, spread in (0, 90]");
}

double CosPowerDistribution::intensity(double gamma, double) const {
  // Eq. (11) leaves gamma = spread open; the spot is taken closed there, so a spread
  // of 90 degrees ends at cos = 0 continuously.
  if (gamma > spread_) return 0;
  return candela_ * std::pow(std::cos(gamma), power_);
}

double CosPowerDistribution::flux() const {
  return 2 * pi * candela_ * (1 - std::pow(std::cos(spread_), power_ + 1)) / (power_ + 1);
}

double CardioidDistribution::intensity(double gamma, double) const {
  return candela_ * 0.5 * (1 + std::cos(gamma));
}

}  // namespace penumbra::photometry
