// in progress
#include "commands.hpp"
namespace rotorcert::cli {
Command add_report(CLI::App& parent) {
  Command c;
  c.app = parent.add_subcommand("report", "report");
  c.run = [] { return kExitUsage; };
  return c;
}
}  // namespace rotorcert::cli
