// rotorcert: the command-line tool of the conformance suite. Each subcommand lives in its own
// cmd_<name>.cpp and is registered here (commands.hpp).
#include <exception>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include <rotorcert/reference/scalar.hpp>

#include "commands.hpp"

#ifndef ROTORCERT_VERSION
#error "ROTORCERT_VERSION must be defined by the build"
#endif

int main(int argc, char** argv) {
  using namespace rotorcert::cli;
  rotorcert::ref::use_reference_precision();  // NUM-2, before any MPFR number is created

  CLI::App app{"rotorcert: conformance suite for quaternion and geometric-algebra rotation libraries"};
  app.name("rotorcert");
  app.set_version_flag("--version", std::string("rotorcert ") + ROTORCERT_VERSION);
  app.require_subcommand(1);

  // One line per subcommand.
  const std::vector<Command> commands = {
      add_report(app), add_certify(app), add_vectors(app), add_list(app), add_selfcheck(app), add_render(app),
      add_bench(app), add_thirdparty(app), add_diff(app),
  };

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help, version, or the usage error
    return code == 0 ? kExitOk : kExitUsage;
  }

  try {
    for (const Command& c : commands)
      if (c.app->parsed()) return c.run();
  } catch (const std::exception& e) {
    std::cerr << "rotorcert: internal error: " << e.what() << '\n';
    return kExitUsage;
  }
  return kExitUsage;
}
