#pragma once
// SplitMix64 (Steele, Lea & Flood 2014): a small, fast, seedable generator for the random
// choices of the ray tracer (roughness perturbations, tube strata) and of the form factors
// (ray origins and directions). Callers seed one stream per independent piece of work (an
// image position, a patch), so results do not depend on the order in which threads run.

#include <cmath>
#include <cstdint>
#include <cstring>

#include "penumbra/base/numbers.h"

namespace penumbra {

// mixes 64 bits (SplitMix64's finaliser).
inline std::uint64_t mix_bits(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// returns a key for a pair of doubles (an image position) combined with a seed.
inline std::uint64_t position_key(std::uint64_t seed, double x, double y) {
  std::uint64_t bx = 0, by = 0;
  std::memcpy(&bx, &x, sizeof bx);
  std::memcpy(&by, &y, sizeof by);
  return mix_bits(seed ^ mix_bits(bx ^ mix_bits(by)));
}

class SplitMix64 {
 public:
  static constexpr std::uint64_t golden_gamma = 0x9e3779b97f4a7c15ULL;

  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  // returns the next 64 random bits.
  std::uint64_t next() { return mix_bits(state_ += golden_gamma); }
  // returns a uniform number in [0, 1).
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  // returns a standard normal number (Box-Muller).
  double normal() {
    const double u = 1 - uniform();
    return std::sqrt(-2 * std::log(u)) * std::cos(2 * pi * uniform());
  }

 private:
  std::uint64_t state_;
};

}  // namespace penumbra
