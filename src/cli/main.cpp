// penumbra: a thin command line over the library (DESIGN.md, "Command line").

#include <iostream>

#include "penumbra/base/input_error.h"
#include "verbs.h"

int main(int argc, char** argv) {
  using namespace penumbra::cli;
  CLI::App app{"penumbra: exact shadows and illuminance for scenes of convex polyhedra"};
  app.name("penumbra");
  app.require_subcommand(1);
  app.footer(
      "Exit status: 0 success, 1 a check found differences, 2 bad input or usage.\n"
      "Run 'penumbra VERB --help' for the options of a verb.");

  register_info(app);
  register_shadows(app);
  register_check(app);
  register_illuminance(app);
  register_render(app);
  register_raytrace(app);
  register_lid(app);
  register_radiosity(app);
  register_basis(app);
  register_relight(app);
  register_serve(app);
  register_sun(app);
  register_sun_hours(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  } catch (const penumbra::InputError& e) {
    std::cerr << "penumbra: error: " << e.what() << "\n";
    return 2;
  }
  return exit_status();
}
