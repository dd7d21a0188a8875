#pragma once
// Exact numbers as text: "p/q" strings (or "p" for integers) for outputs with --exact.

#include <array>
#include <string>

#include "penumbra/geometry/exact.h"

namespace penumbra::io {

// returns the exact rational value of x as "p/q" in lowest terms, or "p".
std::string rational_string(const Exact& x);
std::string rational_string(const Rational& x);

// returns the plane's coefficients (a, b, c, d) scaled so that the largest of |a|, |b|, |c|
// is 1: a canonical exact form, the same for every representation of the plane with the
// same orientation.
std::array<Rational, 4> canonical_plane(const Plane3& plane);

}  // namespace penumbra::io
