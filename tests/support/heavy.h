#pragma once
// What the sanitizer suite (scripts/sanitize, docs/reliability.md "Sanitizers") leaves out
// or draws less of. AddressSanitizer makes the exact code about ten times slower, and the
// sanitizers look for memory errors and undefined behaviour, which the same code paths show
// on fewer samples; the Release suite runs everything in full.
//
// The label of the cases left out: oracles over a large real model that take a minute in the
// Release build and ten under AddressSanitizer, on code paths that smaller cases of the same
// suite already run. `--run_test='!@heavy'` skips them.
//   BOOST_AUTO_TEST_CASE(name, PENUMBRA_HEAVY_TEST) { ... }

#include <boost/test/unit_test.hpp>

#define PENUMBRA_HEAVY_TEST *boost::unit_test::label("heavy")

// Heavy cases of several minutes (a joint umbra over a whole real model): the Release suite
// runs them as a CTest test of their own, `<layer>_long`, started first beside the others
// (tests/CMakeLists.txt), instead of at the end of their layer's test.
#define PENUMBRA_LONG_TEST *boost::unit_test::label("heavy") * boost::unit_test::label("long")

namespace penumbra::test {

// true in the sanitizer build (PENUMBRA_SANITIZED, tests/CMakeLists.txt).
constexpr bool sanitized() {
#ifdef PENUMBRA_SANITIZED
  return true;
#else
  return false;
#endif
}

// the number of random samples (scenes, points, iterations) to draw, or a count that a
// test requires of them: all of them in the Release suite, a quarter (at least one) in the
// sanitizer suite.
constexpr int samples(int count) {
  if (!sanitized()) return count;
  return count / 4 > 0 ? count / 4 : 1;
}

}  // namespace penumbra::test
