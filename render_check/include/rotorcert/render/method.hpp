// A skinning method: one implementation table (float or double ABI table, impl_abi.h) used with
// one skinning technique. What a table can do is read from its ABI functions (non-NULL pointers)
// and its claims, never from its name:
//
//   LBS (linear blend skinning, SKIN-1): keyframe rotations by `slerp`, hierarchy by `compose`
//        and `apply_vector`, skinning matrices by `to_matrix`; the suite blends the 3x4 matrices
//        and applies them in the table's scalar type, as a vertex shader does.
//   DQS (dual-quaternion skinning, SKIN-2): keyframe rotations by `slerp`, or by `dq_sclerp` of
//        rotation-only dual quaternions when there is no slerp; hierarchy by
//        `dq_from_rotation_translation` and `dq_compose`; vertices by `dq_blend` followed by
//        `dq_apply_point` (the dual quaternions stay the method's own), else by
//        `skin_dual_quaternion` fed with (real part, translation) of each skinning transform.
//
// Optional ops, needed only by some inputs: `normalize` (CUBICSPLINE rotation channels; DQS:
// `normalize` or `dq_normalize`) and the pose blend of two samples (LBS: `blend_qlb`, else
// `nlerp`; DQS: `dq_blend`, else `dq_sclerp`).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <rotorcert/impl_abi.h>

namespace rotorcert::render {

enum class Technique { lbs, dqs };

/// "LBS", "DQS".
const char* to_string(Technique t);

/// How LINEAR rotation channels are interpolated.
enum class KeyInterpolation { slerp, sclerp };

/// How a pose blend of two samples combines the local transforms (and which reference rule
/// defines its expected result).
enum class PoseBlend {
  none,    // the table has no op for it: blending is refused
  qlb,     // blend_qlb with weights (1 - alpha, alpha); rotations only, translations lerped
  nlerp,   // nlerp(a, b, alpha): the same rotation as QLB of two (QLB-1, NLERP-1)
  dlb,     // dq_blend of the two local rigid motions (DQ-6): translation follows the blend
  sclerp,  // dq_sclerp(a, b, alpha) of the two local rigid motions (DQ-5)
};
const char* to_string(PoseBlend b);

/// How DQS vertices are computed.
enum class DqsRoute { skin_dual_quaternion, blend_and_apply };

/// A table and a technique it supports (make_method checks that).
struct SkinningMethod {
  const rc_impl* table = nullptr;
  Technique technique = Technique::lbs;

  /// "<table name> <float|double> <LBS|DQS>", e.g. "rotor_m2 double LBS".
  std::string name() const;
  bool is_float() const { return table->scalar == RC_SCALAR_FLOAT32; }
  /// Machine epsilon of the table's format (NUM-1): 2^-23 or 2^-52.
  double epsilon() const;

  KeyInterpolation key_interpolation() const;
  PoseBlend pose_blend() const;
  DqsRoute dqs_route() const;  // DQS only
  /// The spec clauses of the ops the method calls for LINEAR clips without a pose blend, with
  /// EDGE-5 (the ops receive quaternions that are unit only to rounding) (LBS:
  /// the matrix blend is the suite's, so SKIN-1 is not among them; DQS: SKIN-2 when the table's
  /// skin_dual_quaternion does the vertices).
  std::vector<std::string> clauses() const;
  /// clauses() that the table does not claim.
  std::vector<std::string> unclaimed() const;
};

/// Empty when `table` offers every op `technique` needs; otherwise the missing ops, e.g.
/// "compose, to_matrix".
std::string missing_ops(const rc_impl& table, Technique technique);

/// The method, or std::invalid_argument naming the missing ops.
SkinningMethod make_method(const rc_impl& table, Technique technique);

/// Every (table, technique) pair the tables support, tables in the given order, LBS first.
std::vector<SkinningMethod> skinning_methods(std::span<const rc_impl* const> tables);

/// An ABI call that could not run, or an element it answered with DOMAIN_ERROR on input the
/// pose or skin job considers valid.
class MethodError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

namespace detail {

/// Calls one batched op of n elements (the trailing arguments are the op's arrays, status last)
/// and throws MethodError naming the method, the op and the first element whose status is not
/// RC_OK. A NULL op is a programming error here: jobs validate before they call.
template <class Fn, class... Args>
void call(const SkinningMethod& m, const char* op, Fn fn, std::size_t n, std::vector<std::uint8_t>& status,
          Args... args) {
  if (fn == nullptr) throw MethodError(m.name() + ": " + op + " is not offered");
  status.assign(n, RC_OK);
  if (fn(n, args..., status.data()) != 0) throw MethodError(m.name() + ": " + op + " could not run");
  for (std::size_t i = 0; i < n; ++i)
    if (status[i] != RC_OK)
      throw MethodError(m.name() + ": " + op + " answered DOMAIN_ERROR for element " + std::to_string(i));
}

}  // namespace detail
}  // namespace rotorcert::render
