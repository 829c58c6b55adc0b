// A third-party adapter as rotorcert sees it: its manifest (conformance/adapters/NAME/adapter.json,
// format "rotorcert-adapter" version 1, documented in conformance/adapters/README.md) and, for an
// out-of-process adapter, the environment scripts/setup-adapters installed for it
// (ENV/NAME/status.json).
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace rotorcert::thirdparty {

/// adapter.json. Route "abi": the library is a C-ABI table, built in (`builtin`, a table name of
/// `rotorcert list`) or a plugin (`plugin`, the file stem): a C or C++ plugin is built by the
/// project's build (under its adapter_plugins/), a Rust one ("language": "rust", a Cargo crate in
/// the adapter's directory) by scripts/setup-adapters into the adapter's environment, which names
/// the file in its status.json. Route "vectors": a program in another language that reads exported
/// vectors and writes a results file.
struct Manifest {
  std::filesystem::path dir;  // conformance/adapters/NAME
  std::string name;           // certificate name; the directory's name
  std::string library, route, language;
  std::string builtin, plugin;       // route abi: exactly one set
  std::vector<std::string> scalars;  // "float", "double"
  nlohmann::json raw;                // the whole manifest, shown in the report
  /// Another version of the library than the manifest's pin (`rotorcert thirdparty --version
  /// NAME=VER`), empty for the pin. Its environment is ENV/NAME@VER, its known defects are still
  /// the pin's (what changed is the point).
  std::string version;
  /// NAME, or NAME@VER for another version: the environment's and the output's directory name.
  std::string run_name() const { return version.empty() ? name : name + "@" + version; }
  /// Whether scripts/setup-adapters makes what runs it (ENV/NAME/status.json): a vectors adapter's
  /// interpreter and packages, a Rust plugin's build.
  bool uses_environment() const { return route == "vectors" || language == "rust"; }
};

/// Every manifest under `adapters_dir`, sorted by name. Throws std::runtime_error naming the file
/// and the field for a malformed manifest (a usage error of the tool: exit 2).
std::vector<Manifest> load_manifests(const std::filesystem::path& adapters_dir);

/// ENV/NAME/status.json of an adapter that scripts/setup-adapters installs (Manifest::uses_environment),
/// as it wrote it.
struct Environment {
  bool installed = false;
  std::string reason;                        // why not installed
  std::vector<std::string> command;          // vectors: interpreter and script; the tool appends --vectors, --out
  std::vector<std::pair<std::string, std::string>> env;  // extra environment variables (NODE_PATH)
  std::filesystem::path plugin;              // route abi (Rust): the plugin it built
};

/// The environment of `name` under `env_dir`; not installed, with the reason, when setup-adapters
/// has not run or could not install it.
Environment read_environment(const std::filesystem::path& env_dir, const std::string& name);

/// The known defects of an adapter's library: NAME/expected_failures.json entries of `scalar`
/// (clause -> why), the same format as impls/*/expected_failures.json.
std::map<std::string, std::string> adapter_expected_failures(const Manifest& m, const std::string& scalar);

/// What running a program gave: its exit status, or that it was killed at the time limit.
struct ProgramRun {
  bool started = false, timed_out = false;
  int exit_code = -1;  // -1 when it ended by a signal
  std::string error;   // why it could not start
  double seconds = 0;
};

/// Runs argv with `extra_env` added to this process's environment, stdout and stderr into `log`,
/// killed (the whole process group) after timeout_s seconds.
ProgramRun run_program(const std::vector<std::string>& argv, const std::vector<std::pair<std::string, std::string>>& extra_env,
                       const std::filesystem::path& log, double timeout_s);

}  // namespace rotorcert::thirdparty
