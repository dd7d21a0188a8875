#define BOOST_TEST_MODULE penumbra
#include <boost/test/unit_test.hpp>
