#pragma once
// Exact numbers as text: "p/q" strings (or "p" for integers) for outputs with --exact.

#include <string>

#include "penumbra/geometry/kernel.h"

namespace penumbra::io {

// returns the exact rational value of x as "p/q" in lowest terms, or "p".
std::string rational_string(const Exact& x);

}  // namespace penumbra::io
