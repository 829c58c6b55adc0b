// Certifying third-party libraries (spec REPORT-3): every adapter of conformance/adapters/ is
// certified by the route it declares, and the results become the report's third-party section.
//   route abi, built in:   certify::certify_targets on the table (GLM, Eigen);
//   route abi, plugin:     the same on the plugin the build made (cqrlib), or, for a Rust adapter,
//                          the one scripts/setup-adapters built with cargo in its environment
//                          (glam, nalgebra);
//   route vectors:         vectors exported with the run's seed and cases, the adapter run on them
//                          in its own environment (scripts/setup-adapters), its results file graded
//                          by vectors::grade (clifford, kingdon, ganja.js).
// A library whose adapter cannot run here (not built, package not installable) is "not run" with
// the reason; a library that runs is "certified", as expected or not: its known defects are its
// expected_failures.json, which must FAIL, and every other claimed clause must pass.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <rotorcert/certify/certify.hpp>
#include <rotorcert/spec/spec.hpp>
#include <rotorcert/thirdparty/adapter.hpp>

namespace rotorcert::thirdparty {

/// The cases per family every adapter's expected_failures.json was established with (certify's
/// default). With fewer, a listed defect whose input is not reached is "not reproduced" instead of
/// making the library not as expected.
inline constexpr int kListedAtCases = 64;

struct Options {
  std::filesystem::path adapters_dir;  // conformance/adapters
  std::filesystem::path env_dir;       // where scripts/setup-adapters installed the environments
  std::filesystem::path plugin_dir;    // the build's adapter_plugins/ (C and C++ plugins; Rust ones are in env_dir)
  std::filesystem::path out;           // vectors/, NAME/results.json, NAME/adapter.log go here
  std::vector<std::string> names;      // only these adapters (empty: all)
  /// Other versions to certify as well, (adapter, version): each a library of its own, NAME@VER,
  /// in the environment scripts/setup-adapters --version NAME=VER installed.
  std::vector<std::pair<std::string, std::string>> versions;
  certify::CertifyOptions certify;     // seed, cases, clauses, limits, jobs (both routes)
  double adapter_timeout_s = 900;      // one run of a vectors adapter
  bool quiet = false;
};

/// Certificates already made in this run (rotorcert report certifies GLM and Eigen anyway), keyed
/// by "table/scalar": reused instead of certifying the table again.
using KnownCertificates = std::map<std::string, certify::Certificate>;

/// The reproducer of a defect in the library's own language (REPORT-3):
/// conformance/adapters/NAME/reproducers/FILE, the command that runs it and its ctest.
struct Reproducer {
  std::string file;      // relative to the checkout
  std::string language;  // "C++", "Python", "JavaScript", "Rust"
  std::string run, ctest;
};

/// What the library's own issue tracker says of a listed defect (the "upstream" field of an
/// expected_failures.json entry, REPORT-3): whether a thread describes it, and where.
struct Upstream {
  enum class Status { reported, not_found, declined };
  Status status = Status::not_found;
  std::vector<std::string> refs;  // issue / pull request URLs
  std::string note;               // what the threads say, or what was searched
  std::string searched;           // the date of the search, YYYY-MM-DD
};
const char* to_string(Upstream::Status s);  // "reported", "not found", "declined"
/// The "upstream" object of an expected_failures.json entry; std::invalid_argument saying what is
/// wrong when it is malformed (the adapter test reads every entry through this).
Upstream parse_upstream(const nlohmann::json& j);

/// A claimed clause of a library that FAILed, crashed or hung: known when its expected_failures.json
/// lists it (why), a surprise otherwise.
struct Defect {
  std::string scalar;
  engine::ClauseResult result;
  std::optional<std::string> why;  // the listed reason; empty optional: not listed
  std::string reproduce;           // the rotorcert command
  std::optional<Reproducer> reproducer;
  std::optional<Upstream> upstream;  // listed and searched for in the library's tracker
};

/// A listed defect whose clause did not FAIL in this run.
struct NotReproduced {
  std::string scalar, clause;
  engine::Outcome outcome;
};

enum class LibraryStatus { not_run, certified, error };
const char* to_string(LibraryStatus s);  // "not run", "certified", "error"

/// One adapter's library in the run.
struct Library {
  Manifest manifest;
  std::string reproduce;  // the command that certifies it again
  LibraryStatus status = LibraryStatus::not_run;
  std::string reason;     // why not run, or the error
  std::vector<certify::Certificate> certificates;  // in the manifest's scalar order
  std::vector<Defect> defects;
  std::vector<NotReproduced> not_reproduced;
  bool as_expected = false;  // certified only: no surprise (thirdparty.cpp: finish)
  std::optional<double> adapter_seconds;  // vectors route, once the adapter ran
  std::string adapter_log;
};

struct Outcome {
  std::vector<Library> libraries;  // sorted by name
  /// Every library that ran is as expected and none gave an error.
  bool as_expected() const;
  /// Every certificate made, in library order.
  std::vector<certify::Certificate> certificates() const;
};

/// sections.third_party of report.json: where the typed outcome leaves the tool.
nlohmann::json section_json(const Outcome& outcome, const Options& o);

/// Certifies the adapters chosen by `o`. Throws std::runtime_error for a malformed manifest or an
/// unknown adapter name (usage errors).
Outcome certify_third_party(const spec::Spec& spec, const Options& o, const KnownCertificates& known = {});

/// The one command that reproduces a library's certificate.
std::string reproduce_command(const std::string& adapter, const std::vector<std::string>& clauses = {});

}  // namespace rotorcert::thirdparty
