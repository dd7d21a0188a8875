#pragma once
// The loopback HTTP server of the browser lighting-design tool (docs/serve.md): the page
// (web/, embedded) and a small JSON/binary API over a LightingSession. Requests are
// served one at a time against the session; bad requests get 4xx answers with a JSON
// {"error": ...} body and never stop the server.

#include <cstddef>
#include <memory>
#include <string>

#include "penumbra/serve/lighting_session.h"

namespace penumbra::serve {

struct ServerOptions {
  std::string host = "127.0.0.1";  // loopback only unless asked
  int port = 8080;                 // 0: any free port
  std::size_t max_body = 1 << 20;  // bytes; larger request bodies get 413
};

// returns whether host names only this machine (127.0.0.0/8, ::1, localhost).
bool is_loopback(const std::string& host);

class LightingServer {
 public:
  // serves session, which must outlive the server.
  LightingServer(LightingSession& session, ServerOptions options);
  ~LightingServer();
  LightingServer(const LightingServer&) = delete;
  LightingServer& operator=(const LightingServer&) = delete;

  // binds the socket and returns the port. Throws std::runtime_error when it cannot.
  int bind();
  // serves until stop(); bind() first.
  void run();
  // stops run() from another thread (or a signal handler's thread).
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace penumbra::serve
