// Runs the checks of a clause on an implementation's table and judges them against the
// reference with the clause's tolerance class (TOL-1): the in-process core of certification.
// (Running an implementation in an isolated child process is the certify tool's business.)
#pragma once

#include <string>
#include <vector>

#include <rotorcert/engine/cases.hpp>
#include <rotorcert/impl_abi.h>
#include <rotorcert/spec/spec.hpp>

namespace rotorcert::engine {

/// RESULT-1 codes that an in-process run can produce (CRASH and TIMEOUT need isolation).
enum class Outcome { pass, quality_warning, fail, not_supported };
const char* to_string(Outcome o);

struct ClauseResult {
  std::string clause;
  std::string level;
  std::string tolerance;
  Outcome outcome = Outcome::not_supported;
  std::size_t cases = 0;     // inputs evaluated
  std::size_t failures = 0;  // inputs beyond the loose bar or with a wrong status
  /// The worst input: its error (in eps units for eps classes, else in the class's unit; NaN for
  /// a wrong status or a NaN output), the op, what the case probes, the inputs in hexfloat and
  /// what was expected versus what came back.
  double worst_error = 0;
  std::string worst_op, worst_label, worst_input, worst_detail;
  /// Every finite error measured, for percentiles and histograms.
  std::vector<double> errors;
};

/// The ref::Format of a table.
ref::Format format_of(const rc_impl& table);

/// Runs and judges one clause. A clause without any check the table supports is NOT_SUPPORTED.
ClauseResult run_clause(const rc_impl& table, const spec::Spec& spec, const std::string& clause,
                        const CaseOptions& options);

/// The clause IDs a table claims.
std::vector<std::string> claimed_clauses(const rc_impl& table);

}  // namespace rotorcert::engine
