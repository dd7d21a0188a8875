#include "penumbra/io/rational.h"

#include <sstream>

#include "penumbra/geometry/exact.h"

namespace penumbra::io {

std::string rational_string(const Rational& x) {
  // The rational type streams as "p/q" in lowest terms ("p" when q = 1).
  std::ostringstream out;
  out << x;
  return out.str();
}

std::string rational_string(const Exact& x) {
  return rational_string(exact_value(x));
}

std::array<Rational, 4> canonical_plane(const Plane3& plane) {
  const RationalPlane3& exact = exact_value(plane);
  Rational scale = abs(exact.a());
  for (const Rational& c : {exact.b(), exact.c()})
    if (abs(c) > scale) scale = abs(c);
  return {exact.a() / scale, exact.b() / scale, exact.c() / scale, exact.d() / scale};
}

}  // namespace penumbra::io
