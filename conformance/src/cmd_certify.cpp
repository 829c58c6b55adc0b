// in progress
#include "commands.hpp"
namespace rotorcert::cli {
Command add_certify(CLI::App& parent) {
  Command c;
  c.app = parent.add_subcommand("certify", "certify");
  c.run = [] { return kExitUsage; };
  return c;
}
}  // namespace rotorcert::cli
