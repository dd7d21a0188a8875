#include "penumbra/io/rational.h"

#include <sstream>

namespace penumbra::io {

std::string rational_string(const Exact& x) {
  // The exact type streams as "p/q" in lowest terms ("p" when q = 1).
  std::ostringstream out;
  out << CGAL::exact(x);
  return out.str();
}

}  // namespace penumbra::io
