#pragma once
// The verbs of `penumbra` (DESIGN.md, "Command line"). Each verb file registers
// its subcommand and the callback that runs it; the callback returns the exit
// status (0 success, 1 a check found differences, 2 bad input or usage).

#include <functional>

#include <CLI/CLI.hpp>

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

// returns the --exposure value given on the command line: 0 for "auto", the value
// when it is a positive number, -1 otherwise (shared by render and raytrace).
double parse_exposure(const std::string& text);

}  // namespace penumbra::cli
