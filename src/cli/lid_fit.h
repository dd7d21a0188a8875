#pragma once
// penumbra lid fit: the Legendre series of a distribution (Dobashi 1995 section 3),
// called from the `lid` verb (lid.cpp), which loads FILE|SPEC.

#include <memory>

#include "penumbra/photometry/distribution.h"

namespace penumbra::cli {

struct LidFitOptions {
  std::shared_ptr<const photometry::Distribution> distribution;
  int degree = 8;      // highest Legendre degree N, 0..kMaxLidFitDegree
  bool sigma = false;  // apply the sigma factors of eq. (13) to the series and its error
  bool json = false;
};

inline constexpr int kMaxLidFitDegree = 60;

// prints the weights w_0..w_N (eq. 3), the sigma factors when asked, and the error of
// the series over the sphere; returns the exit status. Throws InputError for a degree
// out of range.
int run_lid_fit(const LidFitOptions& options);

}  // namespace penumbra::cli
