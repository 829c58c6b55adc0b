// What a correct library may choose, and what it may require (spec section 4a):
//
//   - preconditions (DECL-1): documented requirements on the input of a call ("the axis must be
//     normalized", "t in [0, 1]", "a pure rotation matrix"). A table declares the ones its
//     library documents; an input outside a declared precondition is not held against it at
//     Core..Skinning, and makes a Robust clause NOT_SUPPORTED unless something else FAILs.
//   - acceptable conventions (ACC-1): outputs that differ from the spec's answer yet describe the
//     same rotation in a way a correct library may choose (the sign of from_matrix's q, the angle
//     range of to_axis_angle, the axis of the identity, the branch of log at w < 0, either side of
//     a hemisphere tie). Such an output is graded ACCEPTABLE (the certificate names the
//     convention); declared by the table, it simply passes.
//
// Both are data: an id, a description, the ops it concerns, and a predicate on one case. The
// judge (runner.hpp) consults them per input; nothing here calls an implementation.
#pragma once

#include <functional>
#include <optional>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

#include <rotorcert/engine/abi_op.hpp>
#include <rotorcert/engine/cases.hpp>
#include <rotorcert/impl_abi.h>
#include <rotorcert/reference/bounded.hpp>
#include <rotorcert/reference/metrics.hpp>
#include <rotorcert/reference/rotation_ops.hpp>
#include <rotorcert/reference/tolerance.hpp>

namespace rotorcert::engine {

/// The declarations of one table (ABI version 2 fields, or an adapter manifest): "op:id" strings.
struct Declarations {
  std::set<std::string> preconditions;
  std::set<std::string> conventions;
  bool has_precondition(const std::string& op, const std::string& id) const {
    return preconditions.count(op + ":" + id) > 0 || preconditions.count("*:" + id) > 0;
  }
  bool has_convention(const std::string& op, const std::string& id) const {
    return conventions.count(op + ":" + id) > 0 || conventions.count("*:" + id) > 0;
  }
  bool empty() const { return preconditions.empty() && conventions.empty(); }
};

/// A table's declarations (empty for an ABI version 1 table).
Declarations declarations_of(const rc_impl& table);

/// Why a table's declarations cannot be honoured, or "" if they can: an id DECL-1 or ACC-1 does
/// not define, an op the ABI lacks or the id does not apply to, or an output_of_to_axis_angle
/// declaration of a table without to_axis_angle (`supported`: whether the table has an op).
std::string declaration_problem(const Declarations& d, const std::function<bool(const std::string& op)>& supported);

/// DECL-1: one kind of documented precondition.
struct Precondition {
  std::string id;           // stable: "unit_axis", "t_in_unit_interval", ...
  std::string description;  // one line
  std::function<bool(const AbiOp& op)> applies;
  /// Whether the case satisfies it (exact inputs; `f` gives eps for the near-unit bands).
  std::function<bool(const AbiOp& op, const Case& c, ref::Format f)> holds;
};
const std::vector<Precondition>& preconditions();
const Precondition* find_precondition(const std::string& id);

/// The first precondition declared for this op that the case violates, or nullptr.
const Precondition* violated_precondition(const Declarations& d, const AbiOp& op, const Case& c, ref::Format f);

/// Whether an acceptable convention can make a difference on a case: a predicate on the input
/// alone, or on the input and the spec's answer `want`. Which of the two is part of the type, so
/// a fast judge that has no exact answer yet knows when the input alone decides (of_input).
class Relevance {
 public:
  using OfInput = std::function<bool(const AbiOp& op, const Case& c, ref::Format f)>;
  using OfResult = std::function<bool(const AbiOp& op, const Case& c, const Values& want, ref::Format f)>;

  Relevance() = default;
  template <class F>
    requires std::is_invocable_r_v<bool, F, const AbiOp&, const Case&, ref::Format>
  Relevance(F f) : of_input_(std::move(f)) {}  // NOLINT: a lambda reads as its relevance
  template <class F>
    requires std::is_invocable_r_v<bool, F, const AbiOp&, const Case&, const Values&, ref::Format>
  Relevance(F f) : of_result_(std::move(f)) {}  // NOLINT

  bool operator()(const AbiOp& op, const Case& c, const Values& want, ref::Format f) const {
    return of_input_ ? of_input_(op, c, f) : of_result_(op, c, want, f);
  }
  /// The answer from the input alone; nullopt where it needs the spec's answer.
  std::optional<bool> of_input(const AbiOp& op, const Case& c, ref::Format f) const {
    if (!of_input_) return std::nullopt;
    return of_input_(op, c, f);
  }

 private:
  OfInput of_input_;
  OfResult of_result_;
};

/// ACC-1: one acceptable convention. `error` measures the implementation's output against the
/// answer under the convention, in the unit of the op's own measure (radians, relative), or
/// returns nullopt when the convention has nothing to say about this case.
struct AcceptableConvention {
  std::string id;
  std::string description;
  /// Accepted only where the table declares it: a choice that is a defect when unintended
  /// (an interpolation that takes the long arc), correct when documented.
  bool declared_only = false;
  std::function<bool(const AbiOp& op)> applies;
  /// Whether the convention can make a difference on this input: the judge consults it only
  /// where it is relevant.
  Relevance relevant;
  std::function<std::optional<Real>(const AbiOp& op, const Case& c, const Values& got, const Values& want,
                                    ref::Format f)>
      error;
  /// Judged where the spec answers DOMAIN_ERROR (EDGE-6's zero input) and the output is OK: an
  /// answer the spec does not give, but a correct library may (a sentinel, the algebra's value).
  bool outside_domain = false;
  /// The fast oracle's form of `relevant` (where it reads the spec's answer) and of `error`, where
  /// the convention has one: the same formulas on ref::Bounded values (the answer and the output
  /// as intervals); a decision their bounds do not settle is undecided (ref::BoundedScope). Unset:
  /// MPFR judges the convention. A relevance read from the input alone needs no fast form.
  using BoundedArrays = std::vector<std::vector<ref::Bounded>>;
  std::function<bool(const AbiOp& op, const Case& c, const BoundedArrays& want, ref::Format f)> fast_relevant{};
  /// `in`: c's inputs as Bounded values (formed once per element by the caller).
  std::function<std::optional<ref::Bounded>(const AbiOp& op, const Case& c, const BoundedArrays& in,
                                            const BoundedArrays& got, const BoundedArrays& want, ref::Format f)>
      fast_error{};
  /// Outside the domain the judge holds an acceptable answer to the bars of the clause's class,
  /// which for EDGE-6 and EDGE-7 (class outcome) accept no numeric error: exact sentinels. A
  /// convention whose answer is a rounded number gives the bars of the class ACC-1 names for it.
  std::optional<ref::Bars> bars{};
};
const std::vector<AcceptableConvention>& acceptable_conventions();

/// nlerp's chord (1 - t) a + t b, before normalising (NLERP-1 on an aligned pair; ACC-1 oriented
/// and hemisphere_tie on the pair as given).
template <class T>
ref::Quaternion<T> lerp_chord(const ref::Quaternion<T>& a, const ref::Quaternion<T>& b, const T& t) {
  return {(T(1) - t) * a.w + t * b.w, (T(1) - t) * a.x + t * b.x, (T(1) - t) * a.y + t * b.y,
          (T(1) - t) * a.z + t * b.z};
}

/// ACC-1 hemisphere_tie on a blend or ScLERP: the case's inputs with every influence (ScLERP: b)
/// whose real part's dot with the pivot's (with a's) is exactly 0 negated, the reference on which
/// is the other branch of the tie. nullopt where none is (and for slerp and nlerp, whose other
/// branch is the interpolation with the flip forced the other way).
std::optional<Values> hemisphere_tie_flipped_inputs(const AbiOp& op, const Case& c, ref::Format f);
/// ACC-1 hemisphere_tie's other branch of slerp (else nlerp): the interpolation of qa/|qa| and
/// qb/|qb| with the spec's flip of b (`spec_flip`, decided on the exact inputs) reversed. One
/// formula for the convention's MPFR error and its fast form (T = ref::Bounded).
template <class T>
ref::Quaternion<T> hemisphere_tie_other_branch(bool slerp, const ref::Quaternion<T>& qa, const ref::Quaternion<T>& qb,
                                               const T& t, bool spec_flip) {
  namespace detail = ref::clause::detail;
  const ref::Quaternion<T> a = ref::normalized(qa), b = ref::normalized(qb);
  if (slerp) return detail::quaternion(detail::rotor_interpolation(detail::rotor(a), detail::rotor(b), t, !spec_flip));
  return ref::normalized(lerp_chord(a, spec_flip ? b : -b, t));
}

/// Whether slerp's and nlerp's hemisphere rule (SLERP-1, EDGE-3) negates b: a.b < 0 strictly, on
/// the exact inputs c.inputs[0] and [1].
bool hemisphere_rule_flips_b(const Case& c);

/// The ops ACC-1 hemisphere_tie applies to: those with a hemisphere rule.
bool hemisphere_tie_applies(const AbiOp& op);
/// ACC-1 hemisphere_tie's relevance: an op it applies to, with a dot of the real parts within the
/// tie band (8 eps).
bool hemisphere_tie_at_stake(const AbiOp& op, const Case& c, ref::Format f);

/// The ids of the acceptable conventions that can apply to this case at all (for the vectors'
/// `result` field: a case with any is "acceptable", else "valid").
std::vector<std::string> acceptable_for_case(const AbiOp& op, const Case& c, ref::Format f);

}  // namespace rotorcert::engine
