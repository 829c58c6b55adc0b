// Subcommands of the `rotorcert` tool: one file per subcommand (cmd_<name>.cpp), each adding its
// CLI11 subcommand and returning the function that runs it. Exit codes, for every subcommand:
//   0  success (everything checked passed),
//   1  the check ran and something failed,
//   2  usage error, or a spec / input file that cannot be read or is malformed.
#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <rotorcert/thirdparty/thirdparty.hpp>

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

/// `rotorcert diff OLD/report.json NEW/report.json [--json]` (cmd_diff.cpp).
Command add_diff(CLI::App& parent);

/// `rotorcert vectors export --out DIR` and `rotorcert vectors check FILE` (cmd_vectors.cpp).
Command add_vectors(CLI::App& parent);

/// `rotorcert render [FILE] --out DIR ...` (cmd_render.cpp; its library and build lines are in
/// render_check/render_check.cmake).
Command add_render(CLI::App& parent);

/// What `rotorcert render` is asked to do; `rotorcert report` asks the same for its render section.
struct RenderRequest {
  std::string file;                 // a .gltf/.glb; empty: the built-in characters (CHAR-1)
  std::string out;                  // render.json, render.html and the PNGs go here
  std::vector<std::string> clips;   // empty: every clip
  int frames = 4;
  int width = 512;
  int height = 512;
  std::vector<std::string> impls;   // empty: every built-in implementation
  double metres_per_unit = 1.0;
  bool print = true;                // the per-method table on stdout
  bool require_methods = true;      // false: implementations without LBS or DQS are no error (exit 0, no files)
};
/// Runs the render check and writes its files; the exit code of `rotorcert render` (0 as
/// expected, 1 not, 2 usage or malformed file, messages prefixed with `who`). `result`, when
/// given, receives the check's result (render.json's content; null when nothing was checked).
int run_render(const RenderRequest& request, const char* who, nlohmann::json* result = nullptr);

/// `rotorcert bench [--quick] --out DIR` (cmd_bench.cpp).
Command add_bench(CLI::App& parent);

/// What `rotorcert bench` is asked to run; `rotorcert report` asks the quick run for its speed section.
struct BenchRequest {
  std::string out;     // bench.json (Google Benchmark's format) and bench.log go here
  bool quick = false;  // rotorcert_bench --quick
  std::string filter;  // --benchmark_filter; empty: all
  std::string binary;  // empty: the rotorcert_bench of this build
  std::vector<std::string> plugins;  // --plugin=PATH: third-party tables timed in the same run
};
/// Runs rotorcert_bench; on success `bench` holds its JSON, DIR/bench.json is written (renamed
/// into place when whole). Exit code as `rotorcert bench`, messages prefixed with `who`.
int run_bench(const BenchRequest& request, const char* who, nlohmann::json& bench);
/// The targets and the paper's claim from a speed section, a line each.
void print_speed_summary(std::ostream& out, const nlohmann::json& speed);

/// `rotorcert thirdparty --out DIR [--adapter NAME]...` (cmd_thirdparty.cpp).
Command add_thirdparty(CLI::App& parent);

/// What `rotorcert thirdparty` is asked to certify; `rotorcert report` asks the same for its
/// third-party section (into OUT/third_party).
struct ThirdPartyRequest {
  ThirdPartyRequest();                  // the build's defaults
  std::string adapters_dir;             // conformance/adapters
  std::string env_dir;                  // scripts/setup-adapters' environments
  std::string plugin_dir;               // the build's adapter_plugins/
  std::string out;                      // vectors, results files and adapter logs go here
  std::vector<std::string> names;       // empty: every adapter
  double adapter_timeout_s = 900;
  bool quiet = false;
  std::vector<std::string> versions;    // --version NAME=VER: another version of NAME, certified as well
  bool speed = false;                   // time the native (C-ABI) libraries against glm_quat, same run
  std::string bench_binary;             // empty: the rotorcert_bench of this build
};
/// --adapters, --adapters-env, --plugins, --adapter-timeout, --version.
void add_third_party_options(CLI::App& app, ThirdPartyRequest& request);
/// Times the ops of every certified C-ABI library of `outcome` and glm_quat in one rotorcert_bench
/// run (--plugin for the plugins, 4096 elements) and adds them to `section`: section.speed says
/// how, each native library gets `speed`, per table the ns per element, the ratio to glm_quat's
/// same op and their median. A failed run is a note, never an error.
void add_third_party_speed(const ThirdPartyRequest& request, const thirdparty::Outcome& outcome, const char* who,
                           nlohmann::json& section);
/// Certifies the libraries; exit code as `rotorcert thirdparty` (0 every library that ran as
/// expected, 1 not, 2 usage), messages prefixed with `who`. `section` is sections.third_party.
int run_third_party(const ThirdPartyRequest& request, const spec::Spec& spec, const certify::CertifyOptions& options,
                    const thirdparty::KnownCertificates& known, const char* who, thirdparty::Outcome& outcome,
                    nlohmann::json& section);
/// One line per library: status, defects, claims, or why it did not run.
void print_third_party_summary(std::ostream& out, const thirdparty::Outcome& outcome);

}  // namespace rotorcert::cli
