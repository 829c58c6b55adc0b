// Subcommands of the `rotorcert` tool: one file per subcommand (cmd_<name>.cpp), each adding its
// CLI11 subcommand and returning the function that runs it. Exit codes, for every subcommand:
//   0  success (everything checked passed),
//   1  the check ran and something failed,
//   2  usage error, or a spec / input file that cannot be read or is malformed.
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

namespace rotorcert::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailed = 1;
inline constexpr int kExitUsage = 2;

struct Command {
  CLI::App* app = nullptr;    // the subcommand, owned by the parent app
  std::function<int()> run;  // called after parsing when this subcommand was given
};

/// `rotorcert selfcheck [--spec DIR] [--json FILE] [--verbose]` (cmd_selfcheck.cpp).
Command add_selfcheck(CLI::App& parent);

/// `rotorcert list [--plugin PATH]...` (cmd_list.cpp).
Command add_list(CLI::App& parent);

/// `rotorcert certify --impl NAME | --plugin PATH ... --out DIR` (cmd_certify.cpp).
Command add_certify(CLI::App& parent);

/// `rotorcert report --out DIR ...` (cmd_report.cpp).
Command add_report(CLI::App& parent);

/// `rotorcert vectors export --out DIR` and `rotorcert vectors check FILE` (cmd_vectors.cpp).
Command add_vectors(CLI::App& parent);

}  // namespace rotorcert::cli
