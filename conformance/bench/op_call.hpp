// Calling one op of an rc_ops table (impl_abi.h) on prepared arrays: a switch over the slots,
// so the timed loop pays one jump and the implementation's own call.
#pragma once

#include <cstddef>
#include <cstdint>

#include <rotorcert/impl_abi.h>

#include "op_layout.hpp"

namespace rotorcert::bench {

/// One call's arrays, in the order of the op's OpSpec (inputs, outputs), of scalar S.
template <class S>
struct CallArgs {
  std::size_t n = 0, k = 0;
  const S* in[kMaxInputs] = {};
  S* out[kMaxOutputs] = {};
  std::uint8_t* status = nullptr;
};

/// Whether the table has op `id` (a NULL slot is NOT_SUPPORTED).
template <class Ops>
bool has(const Ops& o, OpId id) {
  switch (id) {
#define RC_BENCH_SLOT(name) \
  case OpId::name: return o.name != nullptr;
    RC_BENCH_SLOT(normalize) RC_BENCH_SLOT(compose) RC_BENCH_SLOT(inverse) RC_BENCH_SLOT(apply_vector)
    RC_BENCH_SLOT(apply_bivector) RC_BENCH_SLOT(apply_trivector) RC_BENCH_SLOT(to_matrix)
    RC_BENCH_SLOT(from_matrix) RC_BENCH_SLOT(to_axis_angle) RC_BENCH_SLOT(from_axis_angle) RC_BENCH_SLOT(log)
    RC_BENCH_SLOT(exp) RC_BENCH_SLOT(slerp) RC_BENCH_SLOT(nlerp) RC_BENCH_SLOT(blend_qlb) RC_BENCH_SLOT(blend_log)
    RC_BENCH_SLOT(dq_from_rotation_translation) RC_BENCH_SLOT(dq_compose) RC_BENCH_SLOT(dq_apply_point)
    RC_BENCH_SLOT(dq_normalize) RC_BENCH_SLOT(dq_sclerp) RC_BENCH_SLOT(dq_blend) RC_BENCH_SLOT(rotate_about_axis)
    RC_BENCH_SLOT(skin_linear) RC_BENCH_SLOT(skin_dual_quaternion)
#undef RC_BENCH_SLOT
    case OpId::count_: break;
  }
  return false;
}

/// Calls op `id` of the table (which must have it) and returns the function's return value.
template <class S, class Ops>
int call(const Ops& o, OpId id, const CallArgs<S>& a) {
  const std::size_t n = a.n, k = a.k;
  const S* const* I = a.in;
  S* const* O = a.out;
  std::uint8_t* st = a.status;
  switch (id) {
    case OpId::normalize: return o.normalize(n, I[0], O[0], st);
    case OpId::compose: return o.compose(n, I[0], I[1], O[0], st);
    case OpId::inverse: return o.inverse(n, I[0], O[0], st);
    case OpId::apply_vector: return o.apply_vector(n, I[0], I[1], O[0], st);
    case OpId::apply_bivector: return o.apply_bivector(n, I[0], I[1], O[0], st);
    case OpId::apply_trivector: return o.apply_trivector(n, I[0], I[1], O[0], st);
    case OpId::to_matrix: return o.to_matrix(n, I[0], O[0], st);
    case OpId::from_matrix: return o.from_matrix(n, I[0], O[0], st);
    case OpId::to_axis_angle: return o.to_axis_angle(n, I[0], O[0], O[1], st);
    case OpId::from_axis_angle: return o.from_axis_angle(n, I[0], I[1], O[0], st);
    case OpId::log: return o.log(n, I[0], O[0], st);
    case OpId::exp: return o.exp(n, I[0], O[0], st);
    case OpId::slerp: return o.slerp(n, I[0], I[1], I[2], O[0], st);
    case OpId::nlerp: return o.nlerp(n, I[0], I[1], I[2], O[0], st);
    case OpId::blend_qlb: return o.blend_qlb(n, k, I[0], I[1], O[0], st);
    case OpId::blend_log: return o.blend_log(n, k, I[0], I[1], O[0], st);
    case OpId::dq_from_rotation_translation: return o.dq_from_rotation_translation(n, I[0], I[1], O[0], st);
    case OpId::dq_compose: return o.dq_compose(n, I[0], I[1], O[0], st);
    case OpId::dq_apply_point: return o.dq_apply_point(n, I[0], I[1], O[0], st);
    case OpId::dq_normalize: return o.dq_normalize(n, I[0], O[0], st);
    case OpId::dq_sclerp: return o.dq_sclerp(n, I[0], I[1], I[2], O[0], st);
    case OpId::dq_blend: return o.dq_blend(n, k, I[0], I[1], O[0], st);
    case OpId::rotate_about_axis: return o.rotate_about_axis(n, I[0], I[1], I[2], I[3], O[0], st);
    case OpId::skin_linear: return o.skin_linear(n, k, I[0], I[1], I[2], I[3], O[0], st);
    case OpId::skin_dual_quaternion: return o.skin_dual_quaternion(n, k, I[0], I[1], I[2], I[3], O[0], st);
    case OpId::count_: break;
  }
  return -1;
}

}  // namespace rotorcert::bench
