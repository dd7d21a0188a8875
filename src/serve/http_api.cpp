// The routes of the lighting-design server (http_api.h; docs/serve.md, "API"). Errors
// answer {"error": "..."} with a 4xx status: 400 malformed or invalid, 403 a path that
// climbs out of the page, 404 unknown path or light, 405 a known path asked with another
// method (with Allow), 413 a body over the limit (httplib).

#include "http_api.h"

#include <filesystem>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <regex>

#include "mesh_payload.h"
#include "penumbra/base/input_error.h"
#include "penumbra/base/input_file.h"
#include "static_files.h"

namespace penumbra::serve {
namespace {

constexpr const char* json_type = "application/json";
constexpr const char* binary_type = "application/octet-stream";

// returns body as JSON text. Strings from the request (a path in an error message) may not
// be UTF-8: they are written with U+FFFD in place of bad bytes, where dump() would throw and,
// thrown from the error handler, end the server (found by fuzzing).
std::string json_text(const nlohmann::json& body) {
  return body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

void send_json(httplib::Response& response, const nlohmann::json& body, int status = 200) {
  response.status = status;
  response.set_content(json_text(body), json_type);
}

void send_error(httplib::Response& response, int status, const std::string& message) {
  send_json(response, {{"error", message}}, status);
}

// parses the request's body as JSON (nested at most max_json_depth deep), or answers 400
// and returns {}.
std::optional<nlohmann::json> parse_body(const httplib::Request& request,
                                         httplib::Response& response) {
  try {
    return parse_input_json(request.body, "request body");
  } catch (const InputError& error) {
    send_error(response, 400, std::string("the request body is not valid JSON: ") + error.what());
    return {};
  }
}

// runs action, mapping the session's exceptions to status codes.
template <typename Action>
void guarded(httplib::Response& response, std::mutex& mutex, Action&& action) {
  try {
    std::lock_guard<std::mutex> lock(mutex);
    action();
  } catch (const UnknownLight& error) {
    send_error(response, 404, error.what());
  } catch (const std::invalid_argument& error) {
    send_error(response, 400, error.what());
  } catch (const nlohmann::json::exception& error) {
    send_error(response, 400, std::string("bad JSON value: ") + error.what());
  }
}

// returns the number in query parameter name, or {} when absent or not a finite number.
std::optional<double> query_number(const httplib::Request& request, const char* name) {
  if (!request.has_param(name)) return {};
  const std::string text = request.get_param_value(name);
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value)) return {};
  return value;
}

nlohmann::json vector_json(const Vec3d& v) {
  return {v[0], v[1], v[2]};
}

nlohmann::json scene_json(const LightingSession& session) {
  const basis::BasisLuminances& basis = session.basis();
  Vec3d low{0, 0, 0}, high{0, 0, 0};
  for (std::size_t i = 0; i < basis.mesh.vertices().size(); ++i)
    for (int axis = 0; axis < 3; ++axis) {
      const double value = basis.mesh.vertices()[i][axis];
      low[axis] = i == 0 ? value : std::min(low[axis], value);
      high[axis] = i == 0 ? value : std::max(high[axis], value);
    }
  nlohmann::json camera = nullptr;
  if (basis.camera)
    camera = {
        {"eye", vector_json(basis.camera->eye)}, {"target", vector_json(basis.camera->target)},
        {"up", vector_json(basis.camera->up)},   {"fov_deg", basis.camera->fov_deg},
        {"width", basis.camera->width},          {"height", basis.camera->height}};
  nlohmann::json lights = nlohmann::json::array();
  for (const LampState& lamp : session.lamps()) lights.push_back(describe(lamp));
  // The file's name only: the page must not show a path of the machine serving it.
  return {{"scene_file", std::filesystem::path(basis.scene_file).filename().string()},
          {"patches", basis.mesh.size()},
          {"vertices", basis.mesh.vertices().size()},
          {"channels", basis.channels},
          {"patch_size", basis.options.patch_size},
          {"bounds", {{"min", vector_json(low)}, {"max", vector_json(high)}}},
          {"camera", camera},
          {"objects", session.object_names()},
          {"lights", lights}};
}

nlohmann::json lux_json(const PatchLux& lux, const LightingSession& session) {
  const basis::Patch& patch = session.basis().mesh.patches()[lux.patch];
  const auto& names = session.object_names();
  return {{"patch", lux.patch},
          {"object", patch.object < names.size() ? names[patch.object] : std::string()},
          {"face", patch.face},
          {"centre", vector_json(patch.centre)},
          {"lux", lux.lux},
          {"total", lux.total},
          {"direct", lux.direct}};
}

// answers an edit with the lamp's state; with ?relight=1, in one round trip, the lamp and
// the relit values (mesh_payload.h, edited_payload).
void send_edited(const httplib::Request& request, httplib::Response& response,
                 LightingSession& session, const std::string& name) {
  const nlohmann::json lamp = describe(session.lamp(name));
  if (request.get_param_value("relight") != "1") return send_json(response, lamp);
  const RelitScene& relit = session.relit();
  response.set_content(edited_payload(json_text(lamp), relit), binary_type);
  response.set_header("X-Relight-Ms", std::to_string(relit.seconds * 1e3));
}

void register_api(httplib::Server& server, LightingSession& session, std::mutex& mutex) {
  server.Get("/api/scene", [&](const httplib::Request&, httplib::Response& response) {
    guarded(response, mutex, [&] { send_json(response, scene_json(session)); });
  });

  // The mesh never changes during a session: encoded once.
  auto mesh = std::make_shared<const std::string>(mesh_payload(session.basis().mesh));
  server.Get("/api/mesh", [mesh](const httplib::Request&, httplib::Response& response) {
    response.set_content(*mesh, binary_type);
  });

  server.Get("/api/lights", [&](const httplib::Request&, httplib::Response& response) {
    guarded(response, mutex, [&] {
      nlohmann::json lights = nlohmann::json::array();
      for (const LampState& lamp : session.lamps()) lights.push_back(describe(lamp));
      send_json(response, {{"lights", lights}});
    });
  });

  server.Get(R"(/api/lights/([^/]+))",
             [&](const httplib::Request& request, httplib::Response& response) {
               guarded(response, mutex,
                       [&] { send_json(response, describe(session.lamp(request.matches[1]))); });
             });

  const auto update_light = [&](const httplib::Request& request, httplib::Response& response) {
    const auto body = parse_body(request, response);
    if (!body) return;
    guarded(response, mutex, [&] {
      session.update(request.matches[1], *body);
      send_edited(request, response, session, request.matches[1]);
    });
  };
  server.Post(R"(/api/lights/([^/]+))", update_light);
  server.Patch(R"(/api/lights/([^/]+))", update_light);

  // Section 4.1: one control point moved, the weights updated by eq. (21).
  server.Post(R"(/api/lights/([^/]+)/control)", [&](const httplib::Request& request,
                                                    httplib::Response& response) {
    const auto body = parse_body(request, response);
    if (!body) return;
    guarded(response, mutex, [&] {
      if (!body->is_object() || !body->contains("index") || !(*body)["index"].is_number_integer() ||
          !body->contains("candela") || !(*body)["candela"].is_number())
        throw std::invalid_argument("expected {\"index\": integer, \"candela\": number}");
      session.move_control_point(request.matches[1], (*body)["index"].get<int>(),
                                 (*body)["candela"].get<double>());
      send_edited(request, response, session, request.matches[1]);
    });
  });

  // Section 3.5, step 3: the weighted sums, here on the server (eq. 18).
  server.Get("/api/relight", [&](const httplib::Request&, httplib::Response& response) {
    guarded(response, mutex, [&] {
      const auto start = std::chrono::steady_clock::now();
      const RelitScene& relit = session.relit();
      response.set_content(relit_payload(relit), binary_type);
      const double total =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      response.set_header("X-Relight-Ms", std::to_string(relit.seconds * 1e3));
      response.set_header("X-Response-Ms", std::to_string(total * 1e3));
    });
  });

  server.Get("/api/lux", [&](const httplib::Request& request, httplib::Response& response) {
    guarded(response, mutex, [&] {
      std::optional<PatchLux> lux;
      if (request.has_param("patch")) {
        const auto patch = query_number(request, "patch");
        if (!patch || *patch != std::floor(*patch))
          throw std::invalid_argument("patch: expected an integer");
        lux = session.lux_of_patch(static_cast<std::int64_t>(*patch));
      } else {
        const auto x = query_number(request, "x"), y = query_number(request, "y"),
                   z = query_number(request, "z");
        if (!x || !y || !z) throw std::invalid_argument("expected ?patch=i or ?x=&y=&z= (numbers)");
        lux = session.lux_at(Vec3d{*x, *y, *z});
      }
      if (!lux) return send_error(response, 404, "no patch there");
      send_json(response, lux_json(*lux, session));
    });
  });

  server.Get("/api/lighting", [&](const httplib::Request&, httplib::Response& response) {
    guarded(response, mutex, [&] { send_json(response, session.lighting_json()); });
  });
  const auto load_lighting = [&](const httplib::Request& request, httplib::Response& response) {
    const auto body = parse_body(request, response);
    if (!body) return;
    guarded(response, mutex, [&] {
      session.load_lighting_json(*body);
      send_json(response, session.lighting_json());
    });
  };
  server.Post("/api/lighting", load_lighting);
  server.Put("/api/lighting", load_lighting);
}

// returns the methods a path answers, as an Allow header: the routes of register_api
// (their paths as registered) and the page (GET). Empty for an /api/ path none has.
std::string allowed_methods(const std::string& path) {
  static const std::vector<std::pair<std::regex, const char*>> routes = {
      {std::regex("/api/(scene|mesh|lights|relight|lux)"), "GET"},
      {std::regex("/api/lights/[^/]+"), "GET, POST"},
      {std::regex("/api/lights/[^/]+/control"), "POST"},
      {std::regex("/api/lighting"), "GET, POST, PUT"}};
  for (const auto& [pattern, allow] : routes)
    if (std::regex_match(path, pattern)) return allow;
  return path.rfind("/api/", 0) == 0 ? "" : "GET";
}

void register_page(httplib::Server& server) {
  server.Get(R"(/.*)", [](const httplib::Request& request, httplib::Response& response) {
    const StaticFile file = find_static_file(request.path);
    if (file.check == PathCheck::forbidden) return send_error(response, 403, "forbidden path");
    if (file.check == PathCheck::not_found || request.path.rfind("/api/", 0) == 0)
      return send_error(response, 404, "not found: " + request.path);
    response.set_header("Cache-Control", "no-cache");
    response.set_content(file.asset->data, file.asset->size, file.mime_type.c_str());
  });
}

}  // namespace

void register_routes(httplib::Server& server, LightingSession& session, std::mutex& mutex) {
  register_api(server, session, mutex);
  register_page(server);
  // Anything no route answered (e.g. a POST to a page), and statuses set without a body.
  server.set_error_handler([](const httplib::Request& request, httplib::Response& response) {
    if (!response.body.empty()) return;
    // no route for this method: a path that exists under other methods is 405
    const std::string allow = response.status == 404 ? allowed_methods(request.path) : "";
    if (!allow.empty()) {
      response.set_header("Allow", allow);
      return send_error(
          response, 405,
          request.method + " not allowed on " + request.path + " (allowed: " + allow + ")");
    }
    const int status = response.status;
    const std::string message = status == 413 ? "request body too large"
                                : status == 404
                                    ? "not found: " + request.method + " " + request.path
                                    : "bad request";
    send_error(response, status, message);
  });
  server.set_exception_handler(
      [](const httplib::Request&, httplib::Response& response, std::exception_ptr error) {
        std::string message = "internal error";
        try {
          if (error) std::rethrow_exception(error);
        } catch (const std::exception& exception) {
          message += std::string(": ") + exception.what();
        } catch (...) {
        }
        send_error(response, 500, message);
      });
}

}  // namespace penumbra::serve
