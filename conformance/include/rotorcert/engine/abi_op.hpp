// The operations of the implementation ABI (impl_abi.h), described as data: their arrays, how
// each output is measured, which reference function defines them, and how to call an
// implementation's table. Everything the engine does per operation goes through this table.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <rotorcert/impl_abi.h>
#include <rotorcert/op_id.hpp>
#include <rotorcert/reference/result.hpp>
#include <rotorcert/reference/scalar.hpp>

namespace rotorcert::engine {

using ref::Real;
using rotorcert::OpId;

/// How an output array is compared with the reference (SPEC section 3).
enum class Measure {
  rotation,       // quaternion: METRIC-1 radians (sign-free)
  quaternion,     // quaternion defined on unnormalised input (COMPOSE-1, INV-1): METRIC-1 and the
                  // componentwise relative error max_i |q_i - r_i| / |r| (scale and sign count)
  unit_rotation,  // quaternion that must be unit: METRIC-1 and METRIC-6
  signed_unit_rotation,  // unit_rotation where the sign is specified too (SLERP-3's endpoints a and
                         // b'): and max_i |q_i - r_i|, so -r costs 2
  canonical_rotation,  // from_matrix (MAT-2): unit_rotation, and the canonical sign (w > 0) once
                       // the reference |w| is above the bar: a wrong sign costs |w_ref|
  vector,         // METRIC-3, relative to |reference|
  point,          // |p - p_ref| / AbiOp::scale (max(1, |inputs|)): rigid operations (DQ-3, AXIS-1,
                  // SKIN-*, RIGID-*), over every component (DQ-8's 6-scalar dual vector)
  bivector,       // METRIC-5, radians (logs)
  matrix,         // METRIC-4
  angle,          // absolute radians
  scalar,         // relative, absolute at 0
  rigid,          // dual quaternion: METRIC-7, rotation and translation
  unit_rigid,     // dual quaternion that must be unit (DQ-4): METRIC-7, METRIC-6 of the real part,
                  // and the orthogonality defect |r.d| / max(1, |t_ref|)
  dual_parts,     // dual quaternion with a definite sign, part by part (DQ-9): max_i |r_i - r_ref_i|
                  // (absolute: r is unit), |d - d_ref| / AbiOp::scale (the size of the input's dual
                  // part, whose rounding the output carries) and METRIC-6 of r
};

struct Array {
  std::string name;
  int stride = 1;              // scalars per element (per influence for n-way inputs)
  bool per_influence = false;  // n-way input: k elements of `stride` per case
  Measure measure = Measure::scalar;  // outputs only
};

/// One case's values: one vector of exact values per array (inputs or outputs), in ABI layout.
using Values = std::vector<std::vector<Real>>;

struct ReferenceResult {
  ref::Status status = ref::Status::ok;
  Values outputs;
};

struct AbiOp {
  std::string name;  // the rc_ops slot, e.g. "slerp"
  std::vector<Array> inputs, outputs;
  bool nway = false;  // takes k influences per element
  /// The reference on one case's exact inputs (256-bit MPFR).
  std::function<ReferenceResult(const Values& inputs, std::size_t k)> reference;
  /// The length scale of a case for Measure::point (max(1, |p|, |t|, ...)).
  std::function<Real(const Values& inputs, std::size_t k)> scale;
  /// Its row of the op list (abi_op_list.h); abi_ops()[i].id == OpId(i).
  OpId id = OpId::count_;
};

/// Every op of the ABI, entry i describing OpId i (the rows of abi_op_list.h in order; a table of
/// abi_version < 3 never supports the version-3 ops, one of abi_version < 4 the version-4 ops).
const std::vector<AbiOp>& abi_ops();
/// The op of that name, or nullptr.
const AbiOp* find_abi_op(const std::string& name);
/// The op as `clause` judges it: find_abi_op(op) with the clause's own output measures where a
/// clause specifies more than the op's measure says (SLERP-3: the sign of the endpoints). Throws
/// std::logic_error for an unknown op.
const AbiOp& judged_op(const std::string& clause, const std::string& op);

/// The Euclidean norm of v[from .. from + n) (the elements past v's end count as absent): one
/// quaternion, axis or real part of a dual quaternion of an input array.
Real block_norm(const std::vector<Real>& v, std::size_t from, std::size_t n);

/// Whether input array `a` of `op` is a rotation axis (AXANG-2's axis, AXIS-1's u): normalised by
/// its clause like a quaternion, so it has the quaternions' scale classes and unit band.
bool is_axis_input(const AbiOp& op, const Array& a);

/// ||M^T M - I||_F of a column-major 3x3 matrix: how far it is from orthogonal (MAT-3's delta).
Real orthogonality_defect(const std::vector<Real>& m);

/// Whether the table has that op (non-NULL pointer).
bool supports(const rc_impl& table, const std::string& op);

/// Calls op on n elements through the table. `in`/`out` hold one pointer per input/output
/// array of the op, of the table's scalar type; status has n bytes. Returns the function's
/// return value (0 = ran), or -1 if the table lacks the op.
int call(const rc_impl& table, const std::string& op, std::size_t n, std::size_t k,
         const std::vector<const void*>& in, const std::vector<void*>& out, std::uint8_t* status);

}  // namespace rotorcert::engine
