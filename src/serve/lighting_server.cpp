// The loopback HTTP server (include/penumbra/serve/lighting_server.h) over cpp-httplib.

#include "penumbra/serve/lighting_server.h"

#include <atomic>
#include <chrono>
#include <mutex>
#include <stdexcept>
#include <thread>

#include <httplib.h>

#include "http_api.h"

namespace penumbra::serve {

namespace {
constexpr std::size_t kConnectionThreads = 64;  // connections served at once
}  // namespace

bool is_loopback(const std::string& host) {
  return host == "localhost" || host == "::1" || host.rfind("127.", 0) == 0;
}

struct LightingServer::Impl {
  LightingSession& session;
  ServerOptions options;
  httplib::Server server;
  std::mutex mutex;
  bool bound = false;
  // stop() may come before run() has started listening: these two flags close the race.
  std::atomic<bool> in_run{false}, stop_requested{false};
};

LightingServer::LightingServer(LightingSession& session, ServerOptions options)
    : impl_(new Impl{session, std::move(options), {}, {}, false, {false}, {false}}) {
  impl_->server.set_payload_max_length(impl_->options.max_body);
  impl_->server.set_keep_alive_max_count(1000);
  // cpp-httplib gives each connection a thread for its whole life, keep-alive included, so
  // its default of 8 threads let six browser connections and two slow clients hold every
  // thread while new connections waited seconds (the load test, docs/reliability.md).
  impl_->server.new_task_queue = [] { return new httplib::ThreadPool(kConnectionThreads); };
  // Small answers at once: Nagle's algorithm against delayed ACKs costs 40 ms a request.
  impl_->server.set_tcp_nodelay(true);
  register_routes(impl_->server, impl_->session, impl_->mutex);
}

LightingServer::~LightingServer() {
  stop();
}

int LightingServer::bind() {
  const ServerOptions& options = impl_->options;
  int port = options.port;
  if (options.port == 0) {
    port = impl_->server.bind_to_any_port(options.host);
    if (port < 0) port = -1;
  } else if (!impl_->server.bind_to_port(options.host, options.port)) {
    port = -1;
  }
  if (port < 0)
    throw std::runtime_error("cannot listen on " + options.host + ":" +
                             std::to_string(options.port) + " (in use, or not an address here)");
  impl_->bound = true;
  return port;
}

void LightingServer::run() {
  if (!impl_->bound) throw std::logic_error("LightingServer::run before bind");
  impl_->in_run = true;
  if (!impl_->stop_requested) impl_->server.listen_after_bind();
  impl_->in_run = false;
}

void LightingServer::stop() {
  impl_->stop_requested = true;
  // run() has begun: wait until it listens (or returns), then shut the socket.
  while (impl_->in_run && !impl_->server.is_running())
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  impl_->server.stop();
}

}  // namespace penumbra::serve
