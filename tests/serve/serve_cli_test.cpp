// `penumbra serve` on bad input: exit status 2 and a message naming the file, before any
// socket is opened (docs/serve.md, "Running it").

#include <boost/test/unit_test.hpp>
#include <fstream>

#include "support/fixtures.h"

namespace penumbra::test {

BOOST_AUTO_TEST_SUITE(serve_cli)

BOOST_AUTO_TEST_CASE(a_missing_scene_exits_2) {
  const CommandResult result = run_penumbra("serve no-such-scene.json --port 0");
  BOOST_TEST(result.status == 2);
  BOOST_TEST(result.err.find("no-such-scene.json") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_bad_basis_file_exits_2) {
  const auto dir = scratch_dir("serve-cli");
  const auto basis = dir / "garbage.pbl";
  std::ofstream(basis) << "not a basis file";
  const CommandResult result = run_penumbra("serve '" + fixture("scenes/serve-room.json").string() +
                                            "' --port 0 --basis '" + basis.string() + "'");
  BOOST_TEST(result.status == 2);
  BOOST_TEST(result.err.find("garbage.pbl") != std::string::npos);
  BOOST_TEST(result.out.find("http://") == std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_bad_port_exits_2) {
  const CommandResult result =
      run_penumbra("serve '" + fixture("scenes/serve-room.json").string() + "' --port 70000");
  BOOST_TEST(result.status == 2);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace penumbra::test
