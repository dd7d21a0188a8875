// The lighting-design server's API against a running server on loopback (docs/serve.md,
// "API"), good requests and bad ones: every bad request gets its 4xx and a JSON error,
// and the server keeps answering.

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <thread>

#include "penumbra/serve/lighting_server.h"
#include "serve_room.h"

// after Eigen (serve_room.h): httplib pulls in <resolv.h>, whose `_res` macro breaks Eigen
#include <httplib.h>

namespace penumbra::serve {
namespace {

// A server on an ephemeral loopback port, running on its own thread for one test case.
struct RunningServer {
  LightingSession session{test::serve_room_basis(), test::serve_room_scene()};
  LightingServer server{session, ServerOptions{"127.0.0.1", 0, 1 << 16}};
  int port = server.bind();
  std::thread thread{[this] { server.run(); }};
  httplib::Client client{"127.0.0.1", port};

  ~RunningServer() {
    server.stop();
    thread.join();
  }

  httplib::Result post(const std::string& path, const std::string& body) {
    return client.Post(path.c_str(), body, "application/json");
  }
};

// returns the error message of a JSON error body (fails the test if it is not one).
std::string error_of(const httplib::Result& result) {
  const auto body = nlohmann::json::parse(result->body, nullptr, false);
  BOOST_TEST_REQUIRE(body.is_object());
  BOOST_TEST_REQUIRE(body.contains("error"));
  return body["error"].get<std::string>();
}

}  // namespace

BOOST_FIXTURE_TEST_SUITE(http_api, RunningServer)

BOOST_AUTO_TEST_CASE(the_page_and_the_scene_are_served) {
  const auto page = client.Get("/");
  BOOST_TEST_REQUIRE(static_cast<bool>(page));
  BOOST_TEST(page->status == 200);
  BOOST_TEST(page->get_header_value("Content-Type").find("text/html") == 0u);
  BOOST_TEST(page->body.find("main.js") != std::string::npos);
  const auto script = client.Get("/viewer.js");
  BOOST_TEST(script->status == 200);
  BOOST_TEST(script->get_header_value("Content-Type").find("text/javascript") == 0u);

  const auto scene = client.Get("/api/scene");
  BOOST_TEST(scene->status == 200);
  const auto json = nlohmann::json::parse(scene->body);
  BOOST_TEST(json["patches"].get<std::size_t>() == session.basis().mesh.size());
  BOOST_TEST(json["lights"].size() == 2u);
  BOOST_TEST(json["lights"][0]["controls"]["angles_deg"].size() == 19u);
  BOOST_TEST(json["objects"][0] == "floor");
  // The scene was loaded from an absolute path; the page gets the file's name only.
  BOOST_TEST(std::filesystem::path(session.basis().scene_file).is_absolute());
  BOOST_TEST(json["scene_file"] == "serve-room.json");
}

// The binary sizes of docs/serve.md: the mesh's header counts and arrays, and the relit
// values per vertex (RGB + lux) and per patch (lux).
BOOST_AUTO_TEST_CASE(binary_bodies_have_the_documented_sizes) {
  const auto mesh = client.Get("/api/mesh");
  BOOST_TEST_REQUIRE(mesh->status == 200);
  std::uint32_t header[4];
  std::memcpy(header, mesh->body.data(), sizeof header);
  const std::size_t v = header[0], t = header[1], p = header[2];
  BOOST_TEST(v == session.basis().mesh.vertices().size());
  BOOST_TEST(p == session.basis().mesh.size());
  BOOST_TEST(mesh->body.size() == 4 * (4 + 3 * v + 3 * t + t + 6 * p + p));
  const auto relit = client.Get("/api/relight");
  BOOST_TEST_REQUIRE(relit->status == 200);
  BOOST_TEST(relit->body.size() == 4 * (4 * v));
  BOOST_TEST(std::stod(relit->get_header_value("X-Relight-Ms")) >= 0);
  // the last vertex's lux and the first vertex's red luminance are the session's
  float last_lux = 0, first_red = 0;
  std::memcpy(&last_lux, relit->body.data() + 16 * v - 4, 4);
  std::memcpy(&first_red, relit->body.data(), 4);
  BOOST_TEST(last_lux == session.relit().vertex_lux[static_cast<Eigen::Index>(v) - 1]);
  BOOST_TEST(first_red == session.relit().vertex_luminance(0, 0));
}

BOOST_AUTO_TEST_CASE(a_moved_control_point_changes_weights_and_relit_values) {
  const auto before = nlohmann::json::parse(client.Get("/api/lights/downlight")->body);
  const auto relit_before = client.Get("/api/relight")->body;
  const auto moved = post("/api/lights/downlight/control", R"({"index": 2, "candela": 900})");
  BOOST_TEST_REQUIRE(moved->status == 200);
  const auto after = nlohmann::json::parse(moved->body);
  BOOST_TEST(after["controls"]["candela"][2] == 900.0);
  // eq. (21): w_0 grows by 1/2 dI sin(gamma) dgamma (P_0 = 1, t = 1)
  const double d_gamma = 3.14159265358979323846 / 18, gamma = 2 * d_gamma;
  const double old_intensity = before["controls"]["candela"][2].get<double>();
  BOOST_TEST(after["weights"][0].get<double>() - before["weights"][0].get<double>() ==
                 0.5 * (900 - old_intensity) * std::sin(gamma) * d_gamma,
             boost::test_tools::tolerance(1e-9));
  BOOST_TEST(client.Get("/api/relight")->body != relit_before);
}

// ?relight=1: the edit's answer carries the lamp and the relit values (edited_payload).
BOOST_AUTO_TEST_CASE(an_edit_can_answer_with_the_relit_values) {
  const auto result =
      post("/api/lights/downlight/control?relight=1", R"({"index": 4, "candela": 50})");
  BOOST_TEST_REQUIRE(result->status == 200);
  const std::string& body = result->body;
  std::uint32_t length = 0;
  std::memcpy(&length, body.data(), 4);
  const auto lamp = nlohmann::json::parse(body.substr(4, length));
  BOOST_TEST(lamp["controls"]["candela"][4] == 50.0);
  const std::size_t offset = 4 + (length + 3) / 4 * 4;
  const std::size_t v = session.basis().mesh.vertices().size();
  BOOST_TEST(body.size() == offset + 16 * v);
  BOOST_TEST(body.substr(offset) == client.Get("/api/relight")->body);
}

BOOST_AUTO_TEST_CASE(lamps_are_aimed_coloured_and_dimmed) {
  const auto aimed =
      post("/api/lights/spot", R"({"aim": [1, 2, 0], "colour": [1, 0.5, 0.25], "scale": 0.5})");
  BOOST_TEST_REQUIRE(aimed->status == 200);
  const auto state = nlohmann::json::parse(aimed->body);
  const double length = std::sqrt(2.5 * 2.5 + 1.5 * 1.5 + 2.6 * 2.6);
  BOOST_TEST(state["axis"][0].get<double>() == -2.5 / length, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(state["scale"] == 0.5);
  const auto lux = client.Get("/api/lux?x=1&y=1&z=0");
  BOOST_TEST_REQUIRE(lux->status == 200);
  BOOST_TEST(nlohmann::json::parse(lux->body)["object"] == "floor");
  const auto by_patch = client.Get("/api/lux?patch=0");
  BOOST_TEST(by_patch->status == 200);
}

BOOST_AUTO_TEST_CASE(the_lighting_is_saved_and_loaded) {
  post("/api/lights/downlight", R"({"scale": 0.25, "sigma": false})");
  const auto saved = client.Get("/api/lighting");
  BOOST_TEST_REQUIRE(saved->status == 200);
  post("/api/lights/downlight", R"({"scale": 1, "sigma": true})");
  const auto loaded = client.Put("/api/lighting", saved->body, "application/json");
  BOOST_TEST_REQUIRE(loaded->status == 200);
  const auto state = nlohmann::json::parse(client.Get("/api/lights/downlight")->body);
  BOOST_TEST(state["scale"] == 0.25);
  BOOST_TEST(state["sigma"] == false);
}

BOOST_AUTO_TEST_CASE(path_traversal_is_forbidden) {
  for (const char* path : {"/../../etc/passwd", "/..%2f..%2fetc%2fpasswd", "/%2e%2e/etc/passwd",
                           "/web/..\\..\\secret", "//etc/passwd"}) {
    const auto result = client.Get(path);
    BOOST_TEST_REQUIRE(static_cast<bool>(result));
    BOOST_TEST(result->status == 403, path);
    BOOST_TEST(result->body.find("root:") == std::string::npos);
  }
  BOOST_TEST(client.Get("/package.json")->status == 404);
  BOOST_TEST(client.Get("/node_modules/playwright-core/package.json")->status == 404);
}

BOOST_AUTO_TEST_CASE(bad_requests_get_4xx_and_the_server_survives) {
  struct Case {
    const char* path;
    const char* body;
    int status;
  };
  const Case cases[] = {
      {"/api/lights/downlight", "{not json", 400},
      {"/api/lights/downlight", "", 400},
      {"/api/lights/downlight", "[1, 2]", 400},
      {"/api/lights/downlight", R"({"colour": "red"})", 400},
      {"/api/lights/downlight", R"({"scale": -2})", 400},
      {"/api/lights/downlight", R"({"aim": [2, 1.5, 2.7]})", 400},
      {"/api/lights/downlight", R"({"wattage": 60})", 400},
      {"/api/lights/nope", R"({"scale": 1})", 404},
      {"/api/lights/nope/control", R"({"index": 0, "candela": 1})", 404},
      {"/api/lights/downlight/control", R"({"index": 99, "candela": 1})", 400},
      {"/api/lights/downlight/control", R"({"index": 1.5, "candela": 1})", 400},
      {"/api/lights/downlight/control", R"({"index": 1, "candela": -5})", 400},
      {"/api/lights/downlight/control", R"({"index": 1})", 400},
      {"/api/lighting", R"({"lights": []})", 400},
      {"/api/lighting", R"({"penumbra_lighting": 1, "lights": [{"name": "nope"}]})", 404},
      {"/api/lighting", R"({"penumbra_lighting": 1, "lights": [{"scale": 1}]})", 400},
      {"/api/nothing", "{}", 404},
  };
  for (const Case& c : cases) {
    const auto result = post(c.path, c.body);
    BOOST_TEST_REQUIRE(static_cast<bool>(result), c.path);
    BOOST_TEST(result->status == c.status, c.path << " " << c.body);
    BOOST_TEST(!error_of(result).empty());
  }
  // a body over the limit (64 KiB here)
  const auto oversized = post("/api/lighting", std::string(100000, ' '));
  BOOST_TEST_REQUIRE(static_cast<bool>(oversized));
  BOOST_TEST(oversized->status == 413);
  for (const char* query :
       {"/api/lux", "/api/lux?patch=abc", "/api/lux?patch=1.5", "/api/lux?x=1&y=nan&z=0"})
    BOOST_TEST(client.Get(query)->status == 400, query);
  BOOST_TEST(client.Get("/api/lux?patch=999999")->status == 404);
  BOOST_TEST(client.Get("/api/lights/nope")->status == 404);
  // a known path with a method it does not answer: 405 with the methods it does
  const auto wrong_method = client.Delete("/api/lighting");
  BOOST_TEST(wrong_method->status == 405);
  BOOST_TEST(wrong_method->get_header_value("Allow") == "GET, POST, PUT");
  BOOST_TEST(client.Post("/api/scene", "{}", "application/json")->status == 405);
  BOOST_TEST(client.Post("/index.html", "{}", "application/json")->status == 405);
  BOOST_TEST(client.Delete("/api/nothing")->status == 404);
  // a path that is not UTF-8 (found by fuzzing: its 404 message could not be written as JSON,
  // and the exception ended the server), answered with U+FFFD in its place
  const auto not_utf8 = client.Post("/api/\xdf/x", "{}", "application/json");
  BOOST_TEST_REQUIRE(static_cast<bool>(not_utf8));
  BOOST_TEST(not_utf8->status == 404);
  BOOST_TEST(error_of(not_utf8).find("/api/\xEF\xBF\xBD/x") != std::string::npos);
  // a body nested deeper than the JSON limit of docs/reliability.md
  const auto deep = post("/api/lights/downlight", std::string(100, '[') + std::string(100, ']'));
  BOOST_TEST(deep->status == 400);
  BOOST_TEST(error_of(deep).find("nested more than 64 deep") != std::string::npos);
  // still serving, state untouched by the refused edits
  const auto state = client.Get("/api/lights/downlight");
  BOOST_TEST_REQUIRE(state->status == 200);
  BOOST_TEST(nlohmann::json::parse(state->body)["scale"] == 1.0);
}

BOOST_AUTO_TEST_CASE(only_loopback_counts_as_local) {
  BOOST_TEST(is_loopback("127.0.0.1"));
  BOOST_TEST(is_loopback("localhost"));
  BOOST_TEST(is_loopback("::1"));
  BOOST_TEST(!is_loopback("0.0.0.0"));
  BOOST_TEST(!is_loopback("192.168.1.10"));
}

BOOST_AUTO_TEST_SUITE_END()

// A scene with a real model (issue #14): the L-shaped courtyard building, closed and not
// convex, enters as convex pieces whose inner sides receive nothing. The server serves its
// patches (only the receiving sides: those of the basis) and relights them.
BOOST_AUTO_TEST_CASE(a_scene_with_a_real_model_is_served_and_relit) {
  const Scene scene = load_scene(test::fixture("scenes/mesh-courtyard.json"));
  basis::BasisOptions options;
  options.degree = 2;
  options.patch_size = 1;
  const basis::BasisLuminances basis = basis::compute_basis(scene, options);
  LightingSession session(basis, scene);
  LightingServer server(session, ServerOptions{"127.0.0.1", 0, 1 << 16});
  const int port = server.bind();
  std::thread thread([&] { server.run(); });
  httplib::Client client("127.0.0.1", port);
  const auto described = client.Get("/api/scene");
  const auto mesh = client.Get("/api/mesh");
  const auto relit = client.Get("/api/relight");
  server.stop();
  thread.join();
  BOOST_TEST_REQUIRE((described && mesh && relit));
  BOOST_TEST(described->status == 200);
  const auto json = nlohmann::json::parse(described->body);
  BOOST_TEST(json["patches"].get<std::size_t>() == basis.mesh.size());
  BOOST_TEST(json["scene_file"] == "mesh-courtyard.json");
  const std::size_t v = basis.mesh.vertices().size();
  BOOST_TEST(relit->body.size() == 4 * (4 * v));
  // The sun lights the ground beside the house: some vertex has tens of thousands of lux.
  float brightest = 0;
  for (std::size_t k = 0; k < v; ++k) {
    float lux = 0;
    std::memcpy(&lux, relit->body.data() + 12 * v + 4 * k, 4);
    brightest = std::max(brightest, lux);
  }
  BOOST_TEST(brightest > 10000.0f);
}

}  // namespace penumbra::serve
