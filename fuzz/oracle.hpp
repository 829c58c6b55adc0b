// The oracle of the operation harnesses: runs every eligible built-in implementation table on a
// decoded batch and judges each element against the 256-bit reference with the engine's own
// judge (engine::judge_case / judge_round_trip: one comparison code for every route). A finding
// prints the table, scalar type, op, clauses and class, the inputs (hexfloat and raw bits) and
// the judge's detail to stderr, then aborts: libFuzzer keeps the input as a crash artifact.
//
// Eligibility (which table is checked on which op): a table is checked on op X only if it claims
// every clause whose checks run X (engine::ops_for_clause) and none of those clauses is a known
// defect of that table (impls/*/expected_failures.json). Otherwise the fuzzer would only find
// the documented defects again (GLM, Eigen and the paper as printed are thereby skipped on most
// operations; fuzz/README.md lists the result).
//
// Verdicts, per element:
//   - reference DOMAIN_ERROR (EDGE-6, EDGE-7, EDGE-9, MAT-3): judge_case must PASS, i.e. status
//     DOMAIN_ERROR and every output NaN;
//   - reference OK and the problem well-conditioned at this input: judge_case with the op's
//     tolerance class must not FAIL (QUALITY_WARNING is allowed, as in certification);
//   - reference OK but ill-conditioned, or values without headroom: status OK is required (no
//     spurious DOMAIN_ERROR); the numbers are not judged;
//   - the reference's own status changes under the perturbation below (an input on the domain
//     boundary within rounding, e.g. det M = 0): nothing is judged beyond not crashing.
// Well-conditioned means: the reference evaluated on the inputs perturbed by one unit roundoff
// u of the format, componentwise (three sign patterns) and normwise (one input element at a
// time: u times its norm added to each of its components), rounded to the format and judged by
// the same judge_case, PASSes the strict bar. A backward-stable implementation (backward error up to
// 16 roundoffs) then stays within the loose bar (loose = 16 x strict in every eps class), so a
// FAIL is a defect of the implementation, not of the bits it was handed (slerp at t = 1e30, the
// exp of a vector of length 1e20, blends whose weighted sum cancels, nearly singular matrices).
// Headroom: inputs other than quaternions and dual quaternions (which EDGE-5 requires at every
// scale), the translation 2|d|/|r| of a dual quaternion, and the exact outputs at most
// 2^(emax - 8); matrix entries within 2^(+-(emax/3 - 4)).
// How much is judged is decided only for a result that is not surely within the loose bar with
// status OK (no finding under any of the three): most elements never need their perturbations
// (fuzz/README.md, "Judged on demand").
// Ties of the hemisphere rules (a dot product of exactly 0, or one below the format's
// resolution once the inputs are normalised) are discontinuities and so count as ill-conditioned here; the
// engine's EDGE-3 cases judge exact ties.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <rotorcert/engine/runner.hpp>
#include <rotorcert/impl_abi.h>
#include <rotorcert/spec/spec.hpp>

#include "decode.hpp"

namespace rotorcert::fuzz {

/// The spec compiled into the fuzzers (clauses and worked examples).
const spec::Spec& embedded_spec();

/// Known defects: "table/scalar/clause" entries of every impls/*/expected_failures.json.
bool is_expected_failure(const std::string& table, const std::string& scalar, const std::string& clause);

/// The clauses (non-Meta) whose checks run `op`.
std::vector<std::string> clauses_judging(const std::string& op);

/// The tolerance class the fuzzers judge `op` with: the loosest numeric class that
/// engine::tolerance_for() gives the op under any clause judging it (for from_matrix that is
/// MAT-3's inherited-mat, whose bars reduce to MAT-2's for rotations).
std::string fuzz_tolerance(const std::string& op);

/// Whether `table` is checked on `op` (see above); `why` says why not.
bool eligible(const rc_impl& table, const std::string& op, std::string* why = nullptr);

/// What a finding reports: the table, the element, what is wrong and the judge's verdict.
struct Finding {
  const rc_impl* table = nullptr;
  std::size_t element = 0;
  std::string what;
  std::string tolerance;
  engine::CaseVerdict verdict;
};
/// Called once per finding. The default (check(d)) prints the finding and aborts, which is how
/// libFuzzer sees it; a handler that returns lets check() go on with the next result.
using FindingHandler = std::function<void(const Decoded&, const Finding&)>;

/// Runs and judges a decoded batch on every eligible table of its scalar type; aborts on a finding.
/// Returns the number of tables run.
int check(const Decoded& d);
/// The same on `tables` (each run where it is eligible), each finding passed to `on_finding`.
/// The oracle's memo is shared with check(d): a test uses this to show what the memo keeps.
int check(const Decoded& d, const std::vector<const rc_impl*>& tables, const FindingHandler& on_finding);

/// Sets the reference precision and loads the embedded spec (idempotent; every harness calls it).
void init();

}  // namespace rotorcert::fuzz
