// The operations of the implementation ABI as the benchmarks see them: for each op (every ABI
// version's), how each input array is filled (Gen, see inputs.hpp).
// The op's identity and array counts come from the op list (abi_op_list.h, rotorcert/op_id.hpp);
// op_cost.hpp adds the cost model, op_call.hpp the call.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>

#include <rotorcert/op_id.hpp>

namespace rotorcert::bench {

using rotorcert::OpId;

/// How an input array is filled: values typical of animation data (inputs.cpp documents the
/// distributions). "Anchor" = the element's first quaternion or dual-quaternion input.
enum class Gen {
  unit_quat,     // uniformly random rotation (becomes the element's anchor)
  near_quat,     // the anchor rotated by at most kNeighbourAngle (the next keyframe)
  scaled_quat,   // a random rotation times a scale in [0.5, 1.5] (an unnormalised blend result)
  param_t,       // interpolation parameter in [0, 1]
  angle,         // radians in [-pi, pi]
  unit_axis,     // random unit vector
  point,         // point or translation in [-1, 1]^3 (metres)
  trivector,     // scalar in [-1, 1]
  log_vec,       // rotation log (angle/2) axis, rotation angle in [0, pi]
  rot_matrix,    // 3x3 column-major matrix of a random rotation
  unit_dq,       // unit dual quaternion: random rotation, translation in [-1, 1]^3 (anchor)
  near_dq,       // the anchor dual quaternion moved by at most kNeighbourAngle and 0.1 m
  scaled_dq,     // unit_dq times a scale in [0.5, 1.5] (both parts)
  cluster_quat,  // k influences: rotations within kNeighbourAngle of one random rotation
  cluster_dq,    // k influences: cluster_quat rotations with translations in [-1, 1]^3
  weights,       // k weights in [0.05, 1], scaled to sum to 1
  dual_vec,      // a motor log [xi_r, xi_d]: xi_r as log_vec, xi_d in [-1, 1]^3 (half a translation)
};

struct ArraySpec {
  std::string_view name;
  int stride = 0;              // scalars per element, or per influence when per_influence
  bool per_influence = false;  // k of them per element (n-way ops)
  Gen gen = Gen::point;        // inputs only
};

inline constexpr std::size_t kMaxInputs = 4;
inline constexpr std::size_t kMaxOutputs = 2;

struct OpSpec {
  OpId id;
  std::string_view name;  // the rc_ops slot (op_name(id))
  bool nway = false;      // takes k influences per element
  std::size_t n_in = 0, n_out = 0;
  std::array<ArraySpec, kMaxInputs> in{};
  std::array<ArraySpec, kMaxOutputs> out{};
};

namespace detail {
constexpr ArraySpec I(std::string_view name, int stride, Gen gen) { return {name, stride, false, gen}; }
constexpr ArraySpec K(std::string_view name, int stride, Gen gen) { return {name, stride, true, gen}; }
constexpr ArraySpec O(std::string_view name, int stride) { return {name, stride, false, Gen::point}; }
/// An op's entry: its arrays as given, its name, kind and array counts from the op list.
constexpr OpSpec spec(OpId id, std::array<ArraySpec, kMaxInputs> in, std::array<ArraySpec, kMaxOutputs> out) {
  const OpInfo& row = op_info(id);
  return {id, row.name, row.kind != OpKind::ELEM, static_cast<std::size_t>(row.inputs),
          static_cast<std::size_t>(row.outputs), in, out};
}
}  // namespace detail

/// Every op of the op list, in its order: entry i is OpId i.
inline constexpr std::size_t kTimedOpCount = rotorcert::kOpCount;
inline constexpr std::array<OpSpec, kTimedOpCount> kTimedOps = [] {
  using namespace detail;
  using G = Gen;
  const ArraySpec q = I("q", 4, G::unit_quat), v = I("v", 3, G::point), t = I("t", 1, G::param_t);
  const ArraySpec out_q = O("out_q", 4), out_v = O("out_v", 3), out_d = O("out_d", 8), out_p = O("out_p", 3);
  const ArraySpec skin_q = K("q", 4, G::cluster_quat), skin_t = K("t", 3, G::point), skin_w = K("w", 1, G::weights);
  return std::array<OpSpec, kTimedOpCount>{{
      spec(OpId::normalize, {I("q", 4, G::scaled_quat)}, {out_q}),
      spec(OpId::compose, {I("a", 4, G::unit_quat), I("b", 4, G::unit_quat)}, {out_q}),
      spec(OpId::inverse, {q}, {out_q}),
      spec(OpId::apply_vector, {q, v}, {out_v}),
      spec(OpId::apply_bivector, {q, I("b", 3, G::point)}, {O("out_b", 3)}),
      spec(OpId::apply_trivector, {q, I("s", 1, G::trivector)}, {O("out_s", 1)}),
      spec(OpId::to_matrix, {q}, {O("out_m", 9)}),
      spec(OpId::from_matrix, {I("m", 9, G::rot_matrix)}, {out_q}),
      spec(OpId::to_axis_angle, {q}, {O("out_angle", 1), O("out_axis", 3)}),
      spec(OpId::from_axis_angle, {I("angle", 1, G::angle), I("axis", 3, G::unit_axis)}, {out_q}),
      spec(OpId::log, {q}, {out_v}),
      spec(OpId::exp, {I("v", 3, G::log_vec)}, {out_q}),
      spec(OpId::slerp, {I("a", 4, G::unit_quat), I("b", 4, G::near_quat), t}, {out_q}),
      spec(OpId::nlerp, {I("a", 4, G::unit_quat), I("b", 4, G::near_quat), t}, {out_q}),
      spec(OpId::blend_qlb, {K("q", 4, G::cluster_quat), K("w", 1, G::weights)}, {out_q}),
      spec(OpId::blend_log, {K("q", 4, G::cluster_quat), K("w", 1, G::weights)}, {out_q}),
      spec(OpId::dq_from_rotation_translation, {q, I("t", 3, G::point)}, {out_d}),
      spec(OpId::dq_compose, {I("a", 8, G::unit_dq), I("b", 8, G::unit_dq)}, {out_d}),
      spec(OpId::dq_apply_point, {I("d", 8, G::unit_dq), I("p", 3, G::point)}, {out_p}),
      spec(OpId::dq_normalize, {I("d", 8, G::scaled_dq)}, {out_d}),
      spec(OpId::dq_sclerp, {I("a", 8, G::unit_dq), I("b", 8, G::near_dq), t}, {out_d}),
      spec(OpId::dq_blend, {K("d", 8, G::cluster_dq), K("w", 1, G::weights)}, {out_d}),
      spec(OpId::rotate_about_axis,
           {I("c", 3, G::point), I("u", 3, G::unit_axis), I("angle", 1, G::angle), I("p", 3, G::point)}, {out_p}),
      spec(OpId::skin_linear, {skin_q, skin_t, skin_w, I("v", 3, G::point)}, {out_v}),
      spec(OpId::skin_dual_quaternion, {skin_q, skin_t, skin_w, I("v", 3, G::point)}, {out_v}),
      // ABI version 3
      spec(OpId::to_angle, {q}, {O("out_angle", 1)}),
      spec(OpId::to_axis, {q}, {O("out_axis", 3)}),
      spec(OpId::sqrt, {q}, {out_q}),
      spec(OpId::dq_to_rotation_translation, {I("d", 8, G::unit_dq)}, {out_q, O("out_t", 3)}),
      // ABI version 4
      spec(OpId::dq_log, {I("d", 8, G::unit_dq)}, {O("out_xi", 6)}),
      spec(OpId::dq_exp, {I("xi", 6, G::dual_vec)}, {out_d}),
      spec(OpId::rigid_compose,
           {I("qa", 4, G::unit_quat), I("ta", 3, G::point), I("qb", 4, G::unit_quat), I("tb", 3, G::point)},
           {out_q, O("out_t", 3)}),
      spec(OpId::rigid_apply, {q, I("t", 3, G::point), I("p", 3, G::point)}, {out_p}),
      spec(OpId::rigid_inverse, {q, I("t", 3, G::point)}, {out_q, O("out_t", 3)}),
  }};
}();

// Every op of the op list has its entry, in order, and every array the list gives has a spec.
static_assert([] {
  for (std::size_t i = 0; i < kTimedOpCount; ++i) {
    const OpSpec& o = kTimedOps[i];
    if (op_index(o.id) != i || o.n_in > kMaxInputs || o.n_out > kMaxOutputs) return false;
    for (std::size_t j = 0; j < o.n_in; ++j)
      if (o.in[j].stride == 0) return false;
    for (std::size_t j = 0; j < o.n_out; ++j)
      if (o.out[j].stride == 0) return false;
  }
  return true;
}(), "kTimedOps must hold every op in the op list's order, every array specified");

constexpr const OpSpec& op_spec(OpId id) { return kTimedOps[op_index(id)]; }

/// Scalars of one array for n elements with k influences.
constexpr std::size_t array_scalars(const ArraySpec& a, std::size_t n, std::size_t k) {
  return n * static_cast<std::size_t>(a.stride) * (a.per_influence ? k : 1);
}

}  // namespace rotorcert::bench
