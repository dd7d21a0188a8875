// penumbra serve SCENE: the browser lighting-design tool (docs/serve.md; Dobashi 1995
// section 4). Computes or loads the basis luminances, then serves the page and its API
// on the loopback interface until interrupted.

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>

#include "penumbra/base/input_error.h"
#include "penumbra/basis/basis_file.h"
#include "penumbra/basis/basis_luminances.h"
#include "penumbra/scene/load_scene.h"
#include "penumbra/serve/lighting_server.h"
#include "verbs.h"

namespace penumbra::cli {
namespace {

struct ServeArguments {
  std::string scene;
  std::string basis;
  std::string host = "127.0.0.1";
  int port = 8080;
  int degree = 8;
  double patch_size = 0.25;
};

basis::BasisLuminances basis_for(const Scene& scene, const ServeArguments& args) {
  if (!args.basis.empty()) {
    std::cerr << "penumbra serve: reading " << args.basis << "\n";
    return basis::read_basis(args.basis);
  }
  basis::BasisOptions options;
  options.degree = args.degree;
  options.patch_size = args.patch_size;
  const auto start = std::chrono::steady_clock::now();
  std::cerr << "penumbra serve: computing basis luminances (degree " << args.degree
            << ", patches <= " << args.patch_size << " m)\n";
  basis::BasisLuminances basis = basis::compute_basis(scene, options);
  std::cerr << "penumbra serve: " << basis.mesh.size() << " patches, "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
            << " s\n";
  return basis;
}

int run_serve(const ServeArguments& args) {
  const Scene scene = load_scene(args.scene);
  for (const std::string& warning : scene.warnings)
    std::cerr << "penumbra: warning: " << warning << "\n";
  serve::LightingSession session(basis_for(scene, args), scene);

  serve::ServerOptions options;
  options.host = args.host;
  options.port = args.port;
  if (!serve::is_loopback(args.host))
    std::cerr << "penumbra serve: warning: listening on " << args.host
              << ": anyone who can reach this address can read the scene and change the "
                 "lighting; there is no authentication\n";
  serve::LightingServer server(session, options);
  int port = 0;
  try {
    port = server.bind();
  } catch (const std::runtime_error& error) {
    throw InputError("", "--port", error.what());
  }
  const std::string shown_host =
      args.host.find(':') != std::string::npos ? "[" + args.host + "]" : args.host;
  std::cout << "penumbra serve: http://" << shown_host << ":" << port << "/ (Ctrl-C to stop)"
            << std::endl;
  server.run();
  return 0;
}

}  // namespace

void register_serve(CLI::App& app) {
  CLI::App* verb = app.add_subcommand("serve", "interactive lighting design in a browser");
  auto args = std::make_shared<ServeArguments>();
  verb->add_option("SCENE", args->scene, "scene file (JSON)")->required();
  verb->add_option("--port", args->port, "TCP port (0: any free port, printed)")
      ->capture_default_str()
      ->check(CLI::Range(0, 65535));
  verb->add_option("--basis", args->basis,
                   "basis file from 'penumbra basis' (default: compute it now)");
  verb->add_option("--degree", args->degree, "SH degree of point lamps when computing")
      ->capture_default_str()
      ->check(CLI::Range(0, 20));
  verb->add_option("--patch-size", args->patch_size, "largest patch edge (m) when computing")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  verb->add_option("--host", args->host,
                   "address to listen on; anything but loopback exposes the tool (warned)")
      ->capture_default_str();
  verb->callback([args] { exit_status() = run_serve(*args); });
}

}  // namespace penumbra::cli
