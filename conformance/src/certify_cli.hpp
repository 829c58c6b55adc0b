// Options shared by `rotorcert certify` and `rotorcert report`, and the steps both take after
// certifying: print, write the report atomically, choose the exit code.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include <rotorcert/certify/certify.hpp>

namespace rotorcert::cli {

struct CertifyCli {
  std::uint64_t seed = 1;
  int cases = certify::kDefaultCasesPerFamily;    // LEVEL-1: at least 512 cases per family by default
  int search = certify::kDefaultSearchBudget;  // worst-case search: implementation calls per check
  std::vector<std::string> levels;  // empty: every implementation level
  std::vector<std::string> clauses;
  double timeout_s = 30;
  std::size_t memory_mb = 2048;
  int jobs = 0;  // 0: one per core
  std::string out;
  std::optional<std::string> spec_dir;
  bool verbose = false, quiet = false;
  bool resume = false;  // RESULT-4: continue the interrupted run whose journal is in --out
};

/// Adds the shared options to a subcommand.
void add_certify_options(CLI::App& app, CertifyCli& o);

/// Builds CertifyOptions from the parsed options; throws CLI-style usage errors as
/// std::invalid_argument (unknown level or clause).
certify::CertifyOptions make_options(const spec::Spec& spec, const CertifyCli& o);

/// Loads the spec and builds the options; on a bad spec or option prints "rotorcert CMD: why" and
/// returns false (the caller exits with kExitUsage).
bool load_spec_and_options(const char* command, const CertifyCli& o, spec::Spec& spec,
                           certify::CertifyOptions& options);

/// Certifies `targets` with the journal of --out (RESULT-4, journal.hpp): each finished clause is
/// recorded as it comes, --resume keeps what an interrupted run finished, and Ctrl-C or SIGTERM
/// ends every child and returns nothing, leaving the previous report as it was. On nothing,
/// `code` is the exit code (128 + the signal; kExitUsage when the journal cannot be used) and the
/// reason has been printed. The journal stays open in `journal` until the report is written.
std::optional<std::vector<certify::Certificate>> certify_resumably(const char* command, const CertifyCli& o,
                                                                   const spec::Spec& spec,
                                                                   const std::vector<certify::Target>& targets,
                                                                   certify::CertifyOptions& options,
                                                                   std::unique_ptr<certify::Journal>& journal, int& code);

/// The report's run object: date, host, duration, command line.
certify::json run_json(double seconds, const std::string& command, int jobs);

/// The command line as typed, for the report.
std::string command_line();

}  // namespace rotorcert::cli
