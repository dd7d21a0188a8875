#pragma once
// The verbs of `penumbra` (DESIGN.md, "Command line"). Each verb file registers
// its subcommand and the callback that runs it; the callback returns the exit
// status (0 success, 1 a check found differences, 2 bad input or usage).

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "penumbra/scene/scene.h"

namespace penumbra::cli {

using VerbResult = std::function<int()>;

// The status a verb's callback sets for main() to return.
int& exit_status();

void register_info(CLI::App& app);
void register_shadows(CLI::App& app);
void register_check(CLI::App& app);
void register_raytrace(CLI::App& app);
void register_render(CLI::App& app);
void register_lid(CLI::App& app);
void register_illuminance(CLI::App& app);
void register_radiosity(CLI::App& app);
void register_basis(CLI::App& app);
void register_relight(CLI::App& app);
void register_serve(CLI::App& app);
void register_sun(CLI::App& app);
void register_sun_hours(CLI::App& app);

// returns the --exposure value given on the command line: 0 for "auto", the value
// when it is a positive number, -1 otherwise (shared by render and raytrace).
double parse_exposure(const std::string& text);

// The heap that lives as long as the process. A verb runs once per process, and freeing a
// large exact model (10^6 GMP numbers, each its own allocation) one by one takes longer
// than the exit that follows: 0.5 s of the 10,000-building city. Objects kept here are
// never destroyed, yet stay reachable from a static, so leak checkers do not report them.
std::vector<std::shared_ptr<void>>& kept_until_exit();

// moves value onto that heap and returns it.
template <class T>
T& keep_until_exit(T&& value) {
  auto kept = std::make_shared<std::decay_t<T>>(std::forward<T>(value));
  kept_until_exit().push_back(kept);
  return *kept;
}

// returns the scene of path (load_scene), kept until the process exits.
const Scene& load_scene_until_exit(const std::string& path);

}  // namespace penumbra::cli
