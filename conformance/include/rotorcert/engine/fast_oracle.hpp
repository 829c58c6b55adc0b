// The fast level of the two-level oracle (fuzz/README.md, "The fast oracle").
//
// The reference's clause templates are evaluated in ref::Bounded (reference/bounded.hpp): an x87
// extended value with a rigorous bound on its distance from the exact result. A judgement is
// taken from it only where the bound decides it; everything else (a bound too wide, a branch the
// bound cannot settle, a verdict other than PASS) goes to the 256-bit MPFR reference, so the
// verdicts are MPFR's by construction. conformance/tests/test_fast_oracle.cpp checks every bound
// against MPFR on the suite's own cases, and the fuzz harnesses can run both levels side by side
// (ROTORCERT_FUZZ_ORACLE=both) and stop on any difference.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <rotorcert/engine/abi_op.hpp>
#include <rotorcert/engine/cases.hpp>
#include <rotorcert/engine/runner.hpp>
#include <rotorcert/reference/bounded.hpp>

namespace rotorcert::engine {

using BoundedValues = std::vector<std::vector<ref::Bounded>>;

/// A reference result in Bounded arithmetic: the exact result lies within each component's bound.
struct FastReference {
  ref::Status status = ref::Status::ok;
  BoundedValues outputs;
};

/// Whether `op` has a fast reference: the closed-form ops, and from_matrix, whose iterative
/// eigenvector is verified after the fact (reference/bounded_from_matrix.hpp).
bool has_fast_reference(const std::string& op);

/// The reference of `op` on exact inputs in Bounded arithmetic. nullopt when op has no fast
/// reference or the evaluation met an undecided event (BoundedScope).
std::optional<FastReference> fast_reference(const AbiOp& op, const Values& inputs, std::size_t k);
/// The same on inputs already in Bounded form (each exact value within its component's bound).
std::optional<FastReference> fast_reference(const AbiOp& op, const BoundedValues& inputs, std::size_t k);

/// Exact values as Bounded ones: exact where long double holds them, else the nearest long
/// double with its rounding as the bound.
ref::Bounded bounded_value(const Real& x);
BoundedValues bounded_values(const Values& v);

/// An MPFR reference result held as a FastReference, for an element whose fast reference is
/// undecided: each output's interval holds both MPFR's value and the exact one (within 2^-240 of
/// its magnitude), so what is decided against it is decided against either.
FastReference fast_reference_from(const AbiOp& op, const ReferenceResult& r);

/// The exact value nearest to each fast output (for the checks that read magnitudes).
Values fast_values(const FastReference& r);

/// Every way the exact outputs may round to the format: each component's interval rounds to one
/// value of the format, or, where it holds a rounding point, to one of two; the candidates are
/// every combination. nullopt where more than `max_candidates` combinations would be needed.
std::optional<std::vector<Values>> fast_roundings(const FastReference& r, ref::Format f,
                                                  std::size_t max_candidates = 256);

/// What judging one case needs that does not depend on the observation: the bars, the case's
/// length scale and the format's smallest normal as Bounded values, eps. Computed once per case
/// and shared by every table and every rounding candidate. nullopt for a class that is not a
/// plain numeric one (exact, outcome): MPFR's to judge.
struct FastCase {
  ref::Bars bars;
  ref::Bounded scale, tiny;
  long double eps;
};
std::optional<FastCase> fast_case(const AbiOp& op, const spec::ToleranceClass& tc, const Case& c, ref::Format f);

/// The TOL-1 verdicts at the two ends of an interval that holds the exact error of `got`: the
/// numeric verdict judge_case_against(op, tc, c, got, f, exact reference) starts from lies between
/// `best` and `worst`. nullopt where the fast level cannot bound the error, or where the judgement
/// is not a plain numeric one (a wrong status, a domain error): MPFR's to judge.
struct FastVerdicts {
  ref::Verdict best, worst;
};
std::optional<FastVerdicts> fast_verdicts(const AbiOp& op, const FastCase& fc, const Observed& got,
                                          const FastReference& want);
/// The same for an observation with status OK whose outputs are given as exact Bounded values
/// (every value of the format is a long double): the fuzzers read a table's words into these
/// directly, without MPFR numbers. nullopt where a value is not finite or `want` is not OK.
std::optional<FastVerdicts> fast_verdicts_of_values(const AbiOp& op, const FastCase& fc, const BoundedValues& got,
                                                    const FastReference& want);

/// The verdicts of `r` rounded to the format against `want`, whichever way each component rounds:
/// each component is replaced by the interval between the roundings of its two ends (rounding is
/// monotone), and the error is bounded over all of them at once. For results whose bound spans
/// more rounding points than fast_roundings enumerates. nullopt where r is not OK, a rounding is
/// not finite, or the error is not bounded.
std::optional<FastVerdicts> fast_verdicts_of_rounding(const AbiOp& op, const FastCase& fc, const FastReference& r,
                                                      ref::Format f, const FastReference& want);

/// The verdicts of judge_round_trip (EXP-2: exp(log q) = q through the implementation) at the two
/// ends of an interval that holds the exact distance METRIC-1(exp_got, q): `fc` is
/// fast_case(log, EXP-2's class, c, f), whose bars are the round trip's. nullopt where a call
/// failed, a status is not OK or a value is not finite (MPFR's to judge), or the bound is undecided.
std::optional<FastVerdicts> fast_round_trip_verdicts(const FastCase& fc, const Case& c, const Observed& log_got,
                                                     const Observed& exp_got);

/// Whether an acceptable convention (ACC-1) that needs no declaration may be relevant to case `c`
/// of `op` inside its domain: judge_case_against may then turn a numeric QUALITY_WARNING or FAIL
/// into an ACCEPTABLE PASS, which only MPFR decides. A convention whose relevance the input alone
/// settles (Relevance::of_input) counts only where it is relevant; one that reads the spec's
/// answer counts always.
bool may_be_acceptable(const AbiOp& op, const Case& c, ref::Format f);

/// `r` rounded to the format, each component as the interval between the roundings of its two ends
/// (rounding is monotone): an interval that holds every way r may round. nullopt where r is not OK
/// or a rounding is not finite.
std::optional<BoundedValues> rounded_intervals(const FastReference& r, ref::Format f);

/// TOL-1's verdicts at the two ends of an interval that holds an exact error (in absolute terms).
FastVerdicts fast_verdicts_of_error(const FastCase& fc, const ref::Bounded& e);

/// The acceptable conventions (ACC-1) relevant to case `c` of `op`, in the order in which
/// judge_case_against consults them, each with its fast form:
///   - `answer`: hemisphere_tie's other branch of a tie (slerp and nlerp with the flip forced the
///     other way, a blend or ScLERP on the exactly tied influences negated), in Bounded arithmetic
///     on `in` (c's inputs as exact Bounded values); an observation's error against it
///     (fast_verdicts_of_rounding with the answer as `want`) is the convention's error;
///   - else `error`: the convention's own error of an output (AcceptableConvention::fast_error,
///     against the spec's answer `want`), nullopt where the convention says nothing about it; an
///     undecided bound shows in ref::BoundedScope. Valid while op, c, in and want are.
/// A convention whose error is undefined on c gives none. nullopt where a relevant convention has
/// no fast form, or where a relevance or an answer is undecided.
struct AcceptableAnswer {
  std::string convention;  // the AcceptableConvention's id
  std::optional<FastReference> answer;
  std::function<std::optional<ref::Bounded>(const BoundedValues& got)> error;
};
std::optional<std::vector<AcceptableAnswer>> fast_acceptable_answers(const AbiOp& op, const Case& c,
                                                                     const BoundedValues& in,
                                                                     const FastReference& want, ref::Format f);

/// For the agreement test only: a deliberately broken fast level, which the test must catch.
enum class FastOracleMutation { none, bound_too_small, wrong_term };
void set_fast_oracle_mutation(FastOracleMutation m);

}  // namespace rotorcert::engine
