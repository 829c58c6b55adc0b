// Test cases of the differential engine: for each clause, which ABI operation(s) judge it and on
// which inputs. Inputs are exact values already representable in the implementation's format,
// so the reference is evaluated on exactly what the implementation was given.
//
// Sources, per clause: the inputs of the clause's worked examples (spec/examples.json, rounded
// to the format), and families of fixed reference vectors drawn from a seeded generator (same
// seed, same cases): random rotations, near-identity and near-antipodal pairs, exact ties,
// t outside [0, 1], non-unit scales, subnormals, NaN and infinities, bad weight sets.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <rotorcert/engine/abi_op.hpp>
#include <rotorcert/reference/metrics.hpp>
#include <rotorcert/spec/spec.hpp>

namespace rotorcert::engine {

struct Case {
  Values inputs;       // one vector per input array of the op, element values in ABI layout
  std::size_t k = 0;   // influences per element (n-way ops), else 0
  std::string label;   // what it probes, in prose: "random", "near-antipodal", "example EX-SLERP-1-a", ...
  /// The same as data: the test-vector flags (vocabulary: conformance/src/vectors/flags.cpp), set
  /// where the case is made, never recovered from the label.
  std::vector<std::string> flags;
};

struct Check {
  std::string clause;  // the clause it judges
  std::string op;      // ABI op
  std::vector<Case> cases;
  /// How the worst case is judged. Empty: by the clause's tolerance class. Otherwise the name of
  /// the class to use instead (an edge clause applied to an op with a looser class).
  std::string tolerance;
  /// exp(log q) = q through the implementation (EXP-2), instead of a reference comparison.
  bool log_exp_round_trip = false;
};

struct CaseOptions {
  std::uint64_t seed = 1;
  int cases_per_family = 32;
  bool worked_examples = true;
  /// Worst-case search (run_clause): implementation calls spent per check on walking the
  /// neighbourhood of the worst inputs found (ulp steps). 0: none. Deterministic in the seed.
  int search_budget = 0;
};

/// Where an input belongs by its magnitudes (LEVEL-1): "" for the ordinary inputs of Core ..
/// Skinning, else the Robust clause that judges it: "EDGE-5" (a quaternion or vector far from
/// unit scale), "EDGE-6" (a zero quaternion, dual real part or axis), "EDGE-7" (NaN or Inf),
/// "EDGE-8" (subnormal components), "EDGE-9" (degenerate weights).
std::string robust_clause_of(const AbiOp& op, const Case& c, ref::Format f);

/// The checks that judge `clause` for an implementation of `format` that supports the ABI ops
/// for which `supported(op)` is true. Empty when the clause has no implementation-visible check
/// (Meta clauses) or the implementation supports none of its ops.
template <class Supported>
std::vector<Check> checks_for_clause(const spec::Spec& spec, const std::string& clause, ref::Format format,
                                     const CaseOptions& options, Supported supported);

/// Non-template core of checks_for_clause.
std::vector<Check> checks_for_clause_impl(const spec::Spec& spec, const std::string& clause, ref::Format format,
                                          const CaseOptions& options, const std::vector<std::string>& supported_ops);

/// The operation clause an ABI op belongs to (the first clause judged by that op alone, e.g.
/// "SLERP-1" for slerp), or "" for none.
std::string main_clause_of(const std::string& op);

/// The ABI ops that can judge `clause` at all (whether or not an implementation supports them).
std::vector<std::string> ops_for_clause(const std::string& clause);

/// The tolerance class that judges `op` under `clause`: the clause's own class, or for an edge
/// clause applied to an op the op's class when that is looser (see checks_for_clause).
std::string tolerance_for(const spec::Spec& spec, const std::string& clause, const std::string& op);

/// x rounded to the nearest value of the format (binary32 or binary64), as an exact Real.
Real round_to(ref::Format format, const Real& x);

/// MAT-3's band: |det M| <= 8u per(|M|) for the 3x3 column-major M (u the format's unit
/// roundoff), where the format cannot decide the sign of det M (Shewchuk's bound on a
/// floating-point 3x3 determinant) and either outcome conforms. False for non-finite entries
/// (EDGE-7, judged as such) and for anything but 9 entries.
bool numerically_singular(const std::vector<Real>& m, ref::Format format);

template <class Supported>
std::vector<Check> checks_for_clause(const spec::Spec& spec, const std::string& clause, ref::Format format,
                                     const CaseOptions& options, Supported supported) {
  std::vector<std::string> ops;
  for (const std::string& op : ops_for_clause(clause))
    if (supported(op)) ops.push_back(op);
  return checks_for_clause_impl(spec, clause, format, options, ops);
}

}  // namespace rotorcert::engine
