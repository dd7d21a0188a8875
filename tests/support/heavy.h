#pragma once
// The label of the test cases the sanitizer suite leaves out (scripts/sanitize,
// docs/reliability.md "Sanitizers"): oracles over a large real model that take a minute in
// the Release build and ten under AddressSanitizer, on code paths that smaller cases of the
// same suite already run. The Release suite runs them; `--run_test='!@heavy'` skips them.
//   BOOST_AUTO_TEST_CASE(name, PENUMBRA_HEAVY_TEST) { ... }

#include <boost/test/unit_test.hpp>

#define PENUMBRA_HEAVY_TEST *boost::unit_test::label("heavy")
