// Placeholder until `rotorcert vectors` lands (helper V owns this file).
#include "commands.hpp"
namespace rotorcert::cli {
Command add_vectors(CLI::App& parent) {
  Command c;
  c.app = parent.add_subcommand("vectors", "test vectors for any language (export, check)");
  c.run = [] { return kExitUsage; };
  return c;
}
}  // namespace rotorcert::cli
