// Runs the checks of a clause on an implementation's table and judges them against the
// reference with the clause's tolerance class (TOL-1): the in-process core of certification.
//
// Two halves, so that every route to a verdict shares one comparison:
//   observe()    calls the implementation on a batch of cases and reads back what it wrote;
//   judge_case() compares one case's observation with the 256-bit reference.
// run_clause() is both halves over the checks of a clause. `rotorcert vectors check` judges
// observations read from a results file, the property tests judge one generated case at a time,
// and the fuzzers judge decoded bytes: all through judge_case().
// (Running an implementation in an isolated child process is the certify tool's business.)
#pragma once

#include <cfenv>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <rotorcert/engine/cases.hpp>
#include <rotorcert/engine/convention.hpp>
#include <rotorcert/engine/declarations.hpp>
#include <rotorcert/impl_abi.h>
#include <rotorcert/reference/bounded.hpp>
#include <rotorcert/reference/tolerance.hpp>
#include <rotorcert/spec/spec.hpp>

namespace rotorcert::engine {

/// RESULT-1 codes. An in-process run produces the first four; CRASH and TIMEOUT come from the
/// isolating runner of the certify tool.
enum class Outcome { pass, quality_warning, fail, not_supported, crash, timeout };
const char* to_string(Outcome o);
/// The Outcome named by a RESULT-1 code ("PASS", ...); false if there is none.
bool parse_outcome(const std::string& code, Outcome& out);

/// What an implementation gave back for one case.
/// One batch call as raw bytes (HYG-1 .. HYG-3): every input array before and after the call and
/// every output array and the status bytes after it, in the table's scalar type.
struct RawCall {
  int call_rc = 0;
  std::string fault;                                 // the batch wrote past the end of an array
  std::size_t scalar_size = 8;                       // sizeof(float) or sizeof(double)
  std::vector<std::vector<unsigned char>> in_before, in_after, out;
  std::vector<std::uint8_t> status;                  // one per element
  /// Output array a of element i as exact values.
  std::vector<Real> output(const AbiOp& op, std::size_t a, std::size_t i) const;
  /// Input array a of element i (k influences per element for n-way inputs) as exact values,
  /// before (after = false) or after the call.
  std::vector<Real> input(const AbiOp& op, std::size_t a, std::size_t i, std::size_t k, bool after) const;
  /// Whether element i's outputs and status are bit for bit those of element j of `other`.
  bool same_element(const AbiOp& op, std::size_t i, const RawCall& other, std::size_t j) const;
};
RawCall call_raw(const rc_impl& table, const AbiOp& op, const std::vector<const Case*>& cases, std::size_t k);

struct Observed {
  int call_rc = 0;              // the batch call's return value; nonzero: the call as a whole failed
  std::uint8_t status = RC_OK;  // the element's status byte (RESULT-2)
  Values outputs;               // one vector per output array of the op, as exact values
  std::string fault;            // the batch wrote past the end of an output or the status array
};

/// How a case was graded (ACC-1, DECL-1): by the spec's answer, under an acceptable convention,
/// or not at all because it lies outside a precondition the table declares.
enum class Grade { valid, acceptable, excluded };

/// The judgement of one case.
struct CaseVerdict {
  CaseVerdict() = default;
  CaseVerdict(ref::Verdict v, double e, std::string d) : verdict(v), error(e), detail(std::move(d)) {}
  ref::Verdict verdict = ref::Verdict::pass;
  double error = 0;  // in eps units for eps classes; NaN for a wrong status or a NaN output
  std::string detail;  // expected versus got, in decimal
  Grade grade = Grade::valid;
  bool status_mismatch = false;  // the verdict is about the status (RESULT-2), not a number
  std::string convention;        // acceptable: the convention (ACC-1) under which the output passes
  bool declared = false;         // acceptable: the table declares that convention
  std::string precondition;      // excluded: the declared precondition (DECL-1) the input violates
};

/// The worst case of one op within a clause (finite errors only): for the accuracy tables.
struct WorstCase {
  double error = 0;  // eps units
  std::string label, input, detail;
};

struct ClauseResult {
  std::string clause;
  std::string level;
  std::string tolerance;
  Outcome outcome = Outcome::not_supported;
  std::string note;          // why NOT_SUPPORTED, CRASH or TIMEOUT, or what else the reader must know
  std::size_t cases = 0;     // inputs evaluated
  std::size_t failures = 0;  // inputs beyond the loose bar or with a wrong status
  /// The worst input: its error (in eps units for eps classes, else in the class's unit; NaN for
  /// a wrong status or a NaN output), the op, what the case probes, the inputs in hexfloat and
  /// what was expected versus what came back.
  double worst_error = 0;
  std::string worst_op, worst_label, worst_input, worst_detail;
  /// Whether a worst input was recorded (a clause that ran no case, or only passed, has none).
  bool has_worst() const { return !(worst_op.empty() && worst_input.empty()); }
  /// Every finite error measured (eps units), per ABI op, in case order: percentiles, histograms.
  std::map<std::string, std::vector<double>> errors;
  /// The largest finite error per ABI op, with its input.
  std::map<std::string, WorstCase> worst_by_op;
  /// Conventions (convention.hpp) under which a failing clause passes: a consistent but different
  /// convention rather than a numerical defect. Filled by detect_conventions().
  std::vector<std::string> conventions;

  /// CONV-1 per input: a convention that explains some of the failing inputs (at least half),
  /// with the failing inputs it does not explain.
  struct Diagnosis {
    std::string convention;
    std::size_t explained = 0, failing = 0;
    std::vector<std::string> unexplained;  // inputs (hexfloat), at most 3
  };
  std::vector<Diagnosis> diagnoses;

  /// Inputs whose status was wrong (RESULT-2), listed apart from the numeric headline: their
  /// count and the first of them.
  std::size_t status_failures = 0;
  std::string status_op, status_label, status_input, status_detail;

  /// ACC-1: outputs that pass only under an acceptable convention, per convention id.
  struct Acceptable {
    std::string convention;
    bool declared = false;
    std::size_t count = 0;
    std::string op, label, input, detail;  // the first such input
  };
  std::vector<Acceptable> acceptable;

  /// DECL-1: inputs not judged because they violate a declared precondition, per precondition.
  std::map<std::string, std::size_t> excluded;

  /// Evaluations spent by the worst-case search (CaseOptions::search_budget).
  std::size_t searched = 0;
};

/// The ref::Format of a table.
ref::Format format_of(const rc_impl& table);

/// Element values as text: hexfloat of the format ("0x1.8p+0") and decimal (12 digits).
std::string hexfloat(const Real& x, ref::Format f);
/// "[v0, v1, ...]" in hexfloat of the format, or in decimal (12 digits).
std::string join_values(const std::vector<Real>& v, bool hexfloat, ref::Format f);
std::string describe_inputs(const AbiOp& op, const Case& c, ref::Format f);

/// The floating-point environment implementation calls run in (NUM-1: an implementation is tested
/// as it is, FTZ/DAZ included), while the judging around them runs in the default environment.
/// The certify tool's child sets it to what it found after loading the implementation, then resets
/// its own environment to the default. Unset: calls run in whatever environment is current.
void set_call_environment(const std::fenv_t& env);

/// Calls `op` once on all `cases` (they share one k) and reads back status bytes and outputs.
std::vector<Observed> observe(const rc_impl& table, const AbiOp& op, const std::vector<const Case*>& cases,
                              std::size_t k);

/// The error of an implementation's outputs against reference outputs, in the unit of the op's
/// measures (radians, relative; the largest over the output arrays; NaN if any is NaN).
Real output_error(const AbiOp& op, const Values& got, const Values& want, const Case& c, ref::Format f);

/// output_error by the same measures in the fast oracle's Bounded arithmetic (fast_oracle.hpp),
/// with the case's scale and the format's smallest normal given.
ref::Bounded output_error_bounded(const AbiOp& op, const std::vector<std::vector<ref::Bounded>>& got,
                                  const std::vector<std::vector<ref::Bounded>>& want, const ref::Bounded& scale,
                                  const ref::Bounded& tiny);

/// Strict and loose bars of class `tc` for one case, in the unit errors are compared in.
ref::Bars bars_for(const spec::ToleranceClass& tc, const AbiOp& op, const Case& c, const Real& eps);

/// Judges one case: the reference on c.inputs (mapped by `convention` if given) against `got`.
/// With `declared`: an input outside a declared precondition is Grade::excluded (not judged);
/// without a convention, a numeric FAIL that passes under an acceptable convention (ACC-1) is
/// Grade::acceptable.
CaseVerdict judge_case(const AbiOp& op, const spec::ToleranceClass& tc, const Case& c, const Observed& got,
                       ref::Format f, const Convention* convention = nullptr, const Declarations* declared = nullptr);

/// judge_case without a convention, against the reference result `want` of c.inputs computed by
/// the caller (the fuzz oracle evaluates it once per element and judges every table and every
/// perturbation against it). With `detail` false a PASS leaves CaseVerdict::detail empty (its
/// decimal text costs more than the judging).
CaseVerdict judge_case_against(const AbiOp& op, const spec::ToleranceClass& tc, const Case& c, const Observed& got,
                               ref::Format f, const ReferenceResult& want, bool detail = true);

/// EXP-2: judges exp(log q) = q, given what log returned (`log_got`) and what exp returned when
/// fed that (`exp_got`). c is the log case.
CaseVerdict judge_round_trip(const spec::ToleranceClass& tc, const Case& c, const Observed& log_got,
                             const Observed& exp_got, ref::Format f);

/// Accumulates case verdicts into a ClauseResult: counts, the headline (the largest numeric error
/// among validly graded inputs), the status failures, the acceptable and excluded inputs, and
/// the error lists.
struct ClauseJudge {
  explicit ClauseJudge(ClauseResult& r) : result(r) {}
  ClauseResult& result;
  ref::Verdict worst_verdict = ref::Verdict::pass;
  ref::Verdict numeric_verdict = ref::Verdict::pass;
  struct Numeric : WorstCase {
    std::string op;
  } numeric;  // the numeric headline so far (finish() moves it into result)
  void record(const CaseVerdict& v, const AbiOp& op, const Case& c, ref::Format f);
  /// Sets result.outcome from the worst verdict (PASS, QUALITY_WARNING or FAIL); a Robust clause
  /// with inputs outside a declared precondition and no FAIL is NOT_SUPPORTED, and so is a clause
  /// none of whose inputs were judged (DECL-1).
  void finish();
};

/// Hooks of a run, for the isolating runner and convention detection.
struct RunHooks {
  /// Called before each call into the implementation with the cases it is about to receive, so a
  /// crash can be pinned on them.
  std::function<void(const AbiOp& op, const std::vector<const Case*>& cases)> before_call;
  /// Calls each case on its own (n = 1) instead of one batch per op: slower, but pins a crash on
  /// one input.
  bool one_at_a_time = false;
  /// Judges under this convention instead of the spec's (detect_conventions()).
  const Convention* convention = nullptr;
};

/// Runs and judges one clause. A clause without any check the table supports is NOT_SUPPORTED.
ClauseResult run_clause(const rc_impl& table, const spec::Spec& spec, const std::string& clause,
                        const CaseOptions& options, const RunHooks& hooks = {});

/// For a FAILed clause: the ids of the conventions under which the same cases all pass (PASS or
/// QUALITY_WARNING). Runs the implementation again on the same cases.
std::vector<std::string> detect_conventions(const rc_impl& table, const spec::Spec& spec,
                                            const std::string& clause, const CaseOptions& options);
/// The same, per input (CONV-1): fills result.conventions (conventions that explain every failing
/// input and contradict none) and result.diagnoses (conventions that explain at least half of the
/// failing inputs, with the inputs they do not explain).
void detect_conventions(const rc_impl& table, const spec::Spec& spec, const std::string& clause,
                        const CaseOptions& options, ClauseResult& result);

/// The clause IDs a table claims: its rc_impl.clauses, and the hygiene clauses (HYG-*) always.
std::vector<std::string> claimed_clauses(const rc_impl& table);

}  // namespace rotorcert::engine
