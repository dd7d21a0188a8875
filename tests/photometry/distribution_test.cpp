#include <boost/test/unit_test.hpp>

#include "penumbra/photometry/distribution.h"

BOOST_AUTO_TEST_SUITE(distribution)

BOOST_AUTO_TEST_CASE(isotropic_is_the_same_in_every_direction) {
  const auto lid = penumbra::photometry::make_isotropic(120);
  for (double gamma : {0.0, 0.5, 1.5, 3.0})
    for (double c : {0.0, 1.0, 4.0}) BOOST_TEST(lid->intensity(gamma, c) == 120.0);
  BOOST_TEST(lid->max_intensity() == 120.0);
}

BOOST_AUTO_TEST_SUITE_END()
