#include "penumbra/basis/sigma_factors.h"

#include <cmath>
#include <stdexcept>

namespace penumbra::basis {

double sigma_factor(int degree, int l) {
  if (degree < 0 || l < 0) throw std::invalid_argument("sigma_factor: negative degree");
  if (l == 0) return 1;
  // Dobashi eq. (13).
  const double t = 3.14159265358979323846 * l / (degree + 1);
  return std::sin(t) / t;
}

std::vector<double> sigma_factors(int degree) {
  std::vector<double> factors;
  for (int l = 0; l <= degree; ++l) factors.push_back(sigma_factor(degree, l));
  return factors;
}

}  // namespace penumbra::basis
