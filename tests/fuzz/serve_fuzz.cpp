// Fuzz target "serve": the lighting-design server's HTTP API (docs/serve.md, "API") on
// arbitrary request bytes: the request line, headers, paths, query strings and bodies as
// cpp-httplib reads them from a connection, through the routes penumbra registers. Each
// input gets a fresh session over one basis (fixtures/scenes/serve-room.json, computed once
// per process, as the serve tests do), so inputs do not depend on one another, and the same
// body limit as `penumbra serve` (64 KiB here).

#include <cstring>
#include <mutex>

// Eigen first: httplib pulls in <resolv.h>, whose `_res` macro breaks Eigen's headers.
#include "penumbra/basis/basis_luminances.h"
#include "penumbra/scene/load_scene.h"
#include "penumbra/serve/lighting_session.h"

#include "../../src/serve/http_api.h"
#include "fuzz_target.h"

namespace {

// One connection's bytes: reading returns the input, then end of stream; writing keeps
// nothing.
class InputStream final : public httplib::Stream {
 public:
  InputStream(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  bool is_readable() const override { return true; }
  bool is_writable() const override { return true; }
  ssize_t read(char* ptr, std::size_t size) override {
    const std::size_t count = std::min(size, size_ - position_);
    std::memcpy(ptr, data_ + position_, count);
    position_ += count;
    return static_cast<ssize_t>(count);
  }
  ssize_t write(const char*, std::size_t size) override { return static_cast<ssize_t>(size); }
  void get_remote_ip_and_port(std::string& ip, int& port) const override {
    ip = "127.0.0.1";
    port = 50000;
  }
  void get_local_ip_and_port(std::string& ip, int& port) const override {
    ip = "127.0.0.1";
    port = 8080;
  }
  socket_t socket() const override { return INVALID_SOCKET; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t position_ = 0;
};

// A server whose request handling is reachable without a socket.
class InputServer final : public httplib::Server {
 public:
  void handle(httplib::Stream& stream) {
    bool closed = false;
    process_request(stream, true, closed, nullptr);
  }
};

const penumbra::Scene& room_scene() {
  static const penumbra::Scene scene = penumbra::load_scene(
      std::filesystem::path(PENUMBRA_SOURCE_DIR) / "fixtures" / "scenes" / "serve-room.json");
  return scene;
}

const penumbra::basis::BasisLuminances& room_basis() {
  static const penumbra::basis::BasisLuminances basis = [] {
    penumbra::basis::BasisOptions options;
    options.degree = 4;
    options.patch_size = 0.5;
    return penumbra::basis::compute_basis(room_scene(), options);
  }();
  return basis;
}

}  // namespace

PENUMBRA_FUZZ_TARGET(serve) {
  penumbra::serve::LightingSession session(room_basis(), room_scene());
  std::mutex mutex;
  InputServer server;
  server.set_payload_max_length(1 << 16);
  penumbra::serve::register_routes(server, session, mutex);
  InputStream stream(data, size);
  server.handle(stream);
}
