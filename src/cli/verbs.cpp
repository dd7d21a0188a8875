#include "verbs.h"

#include <iostream>

namespace penumbra::cli {

int& exit_status() {
  static int status = 0;
  return status;
}

void register_pending(CLI::App& app, const std::string& name, const std::string& description,
                      const std::string& issue) {
  CLI::App* verb = app.add_subcommand(name, description + " [not built yet]");
  verb->allow_extras();
  verb->callback([name, issue] {
    std::cerr << "penumbra " << name << ": not built yet (tracked in issue " << issue << ")\n";
    exit_status() = 2;
  });
}

}  // namespace penumbra::cli
