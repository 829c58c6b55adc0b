// Certifying third-party libraries (spec REPORT-3): every adapter of conformance/adapters/ is
// certified by the route it declares, and the results become the report's third-party section.
//   route abi, built in:   certify::certify_targets on the table (GLM, Eigen);
//   route abi, plugin:     the same on the plugin the build made (cqrlib);
//   route vectors:         vectors exported with the run's seed and cases, the adapter run on them
//                          in its own environment (scripts/setup-adapters), its results file graded
//                          by vectors::grade (clifford, kingdon, ganja.js).
// A library whose adapter cannot run here (not built, package not installable) is "not run" with
// the reason; a library that runs is "certified", as expected or not: its known defects are its
// expected_failures.json, which must FAIL, and every other claimed clause must pass.
#pragma once

#include <filesystem>
#include <map>
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
  std::filesystem::path plugin_dir;    // the build's adapter_plugins/
  std::filesystem::path out;           // vectors/, NAME/results.json, NAME/adapter.log go here
  std::vector<std::string> names;      // only these adapters (empty: all)
  certify::CertifyOptions certify;     // seed, cases, clauses, limits, jobs (both routes)
  double adapter_timeout_s = 900;      // one run of a vectors adapter
  bool quiet = false;
};

/// Certificates already made in this run (rotorcert report certifies GLM and Eigen anyway), keyed
/// by "table/scalar": reused instead of certifying the table again.
using KnownCertificates = std::map<std::string, certify::json>;

struct Outcome {
  certify::json section;                     // sections.third_party
  std::vector<certify::json> certificates;   // every certificate made, in section order
};

/// Certifies the adapters chosen by `o`. Throws std::runtime_error for a malformed manifest or an
/// unknown adapter name (usage errors).
Outcome certify_third_party(const spec::Spec& spec, const Options& o, const KnownCertificates& known = {});

/// The one command that reproduces a library's certificate.
std::string reproduce_command(const std::string& adapter, const std::vector<std::string>& clauses = {});

}  // namespace rotorcert::thirdparty
