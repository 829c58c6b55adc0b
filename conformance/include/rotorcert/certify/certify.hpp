// Certification: every clause of the chosen levels, for every table given, each clause in its
// own child process (isolate.hpp), results gathered into certificates (certificate.hpp).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <rotorcert/certify/certificate.hpp>
#include <rotorcert/certify/isolate.hpp>
#include <rotorcert/certify/journal.hpp>
#include <rotorcert/engine/cases.hpp>
#include <rotorcert/spec/spec.hpp>

namespace rotorcert::certify {

/// The defaults of --cases (LEVEL-1: at least 512 per family) and --search (implementation calls
/// per check for the worst-case search); reproduce commands leave defaults out.
inline constexpr int kDefaultCasesPerFamily = 512;
inline constexpr int kDefaultSearchBudget = 64;

/// A table to certify: built in (linked into the tool), or the index-th table of a plugin, which
/// only ever gets loaded inside child processes.
struct Target {
  TableInfo info;
  std::string plugin_path;  // empty: built in
  std::uint32_t plugin_index = 0;
  /// Only these clauses, run whether claimed or not (a mutant is judged on the clauses it
  /// breaks). Empty: the options decide.
  std::vector<std::string> clauses;
};

struct CertifyOptions {
  engine::CaseOptions cases;                   // seed, cases per family
  std::vector<std::string> levels;             // levels certified (non-Meta)
  std::vector<std::string> clauses;            // only these clauses (empty: all of the levels)
  bool run_unclaimed = false;                  // run clauses the table does not claim (mutants)
  ChildLimits limits;
  int jobs = 1;
  bool detect_conventions = true;
  bool progress = false;                       // a progress line on stderr (a terminal)
  std::string reproduce_prefix = "rotorcert";  // how the reproduce commands call the tool
  Journal* journal = nullptr;                  // RESULT-4: finished clauses recorded, resumed ones not run
};

/// Every built-in table.
std::vector<Target> builtin_targets();

/// The tables of a plugin, read in a child process (a plugin that crashes while loading does not
/// take the tool with it). Throws std::runtime_error with the reason if it cannot be read.
std::vector<Target> probe_plugin(const std::string& path, const ChildLimits& limits);

/// The non-Meta clauses of the given levels (in spec order), restricted to `only` if not empty.
std::vector<std::string> clauses_to_certify(const spec::Spec& spec, const std::vector<std::string>& levels,
                                            const std::vector<std::string>& only);

/// Certifies every target. Clauses a table does not claim are NOT_SUPPORTED without running.
std::vector<Certificate> certify_targets(const spec::Spec& spec, const std::vector<Target>& targets,
                                         const CertifyOptions& options);

/// The options object of report.json for these options.
json options_json(const CertifyOptions& options);

/// What identifies a certification for --resume (journal.hpp): versions, the options that decide
/// results, and the tables.
json run_identity(const spec::Spec& spec, const std::vector<Target>& targets, const CertifyOptions& options);

/// The journal's name of a target: "name/scalar", with the plugin path and table index for a plugin.
std::string table_key(const Target& t);

}  // namespace rotorcert::certify
