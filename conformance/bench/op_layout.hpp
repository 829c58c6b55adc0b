// The operations of the implementation ABI (impl_abi.h) as the benchmarks see them: for each op,
// its input and output arrays in ABI layout (LAYOUT-1) and how each input is filled (Gen, see
// inputs.hpp). Data only; op_cost.hpp adds the cost model, op_call.hpp the calls.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>

namespace rotorcert::bench {

/// The ABI ops, in the order of the rc_ops struct.
enum class OpId {
  normalize, compose, inverse, apply_vector, apply_bivector, apply_trivector, to_matrix, from_matrix,
  to_axis_angle, from_axis_angle, log, exp, slerp, nlerp, blend_qlb, blend_log,
  dq_from_rotation_translation, dq_compose, dq_apply_point, dq_normalize, dq_sclerp, dq_blend,
  rotate_about_axis, skin_linear, skin_dual_quaternion,
  count_
};
inline constexpr std::size_t kOpCount = static_cast<std::size_t>(OpId::count_);

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
  std::string_view name;  // the rc_ops slot
  bool nway = false;      // takes k influences per element
  std::size_t n_in = 0, n_out = 0;
  std::array<ArraySpec, kMaxInputs> in{};
  std::array<ArraySpec, kMaxOutputs> out{};
};

namespace detail {
constexpr ArraySpec I(std::string_view name, int stride, Gen gen) { return {name, stride, false, gen}; }
constexpr ArraySpec K(std::string_view name, int stride, Gen gen) { return {name, stride, true, gen}; }
constexpr ArraySpec O(std::string_view name, int stride) { return {name, stride, false, Gen::point}; }
}  // namespace detail

/// Every op, indexed by OpId.
inline constexpr std::array<OpSpec, kOpCount> kOps = [] {
  using namespace detail;
  using G = Gen;
  const ArraySpec q = I("q", 4, G::unit_quat), v = I("v", 3, G::point), t = I("t", 1, G::param_t);
  const ArraySpec out_q = O("out_q", 4), out_v = O("out_v", 3), out_d = O("out_d", 8), out_p = O("out_p", 3);
  return std::array<OpSpec, kOpCount>{{
      {OpId::normalize, "normalize", false, 1, 1, {I("q", 4, G::scaled_quat)}, {out_q}},
      {OpId::compose, "compose", false, 2, 1, {I("a", 4, G::unit_quat), I("b", 4, G::unit_quat)}, {out_q}},
      {OpId::inverse, "inverse", false, 1, 1, {q}, {out_q}},
      {OpId::apply_vector, "apply_vector", false, 2, 1, {q, v}, {out_v}},
      {OpId::apply_bivector, "apply_bivector", false, 2, 1, {q, I("b", 3, G::point)}, {O("out_b", 3)}},
      {OpId::apply_trivector, "apply_trivector", false, 2, 1, {q, I("s", 1, G::trivector)}, {O("out_s", 1)}},
      {OpId::to_matrix, "to_matrix", false, 1, 1, {q}, {O("out_m", 9)}},
      {OpId::from_matrix, "from_matrix", false, 1, 1, {I("m", 9, G::rot_matrix)}, {out_q}},
      {OpId::to_axis_angle, "to_axis_angle", false, 1, 2, {q}, {O("out_angle", 1), O("out_axis", 3)}},
      {OpId::from_axis_angle, "from_axis_angle", false, 2, 1, {I("angle", 1, G::angle), I("axis", 3, G::unit_axis)},
       {out_q}},
      {OpId::log, "log", false, 1, 1, {q}, {out_v}},
      {OpId::exp, "exp", false, 1, 1, {I("v", 3, G::log_vec)}, {out_q}},
      {OpId::slerp, "slerp", false, 3, 1, {I("a", 4, G::unit_quat), I("b", 4, G::near_quat), t}, {out_q}},
      {OpId::nlerp, "nlerp", false, 3, 1, {I("a", 4, G::unit_quat), I("b", 4, G::near_quat), t}, {out_q}},
      {OpId::blend_qlb, "blend_qlb", true, 2, 1, {K("q", 4, G::cluster_quat), K("w", 1, G::weights)}, {out_q}},
      {OpId::blend_log, "blend_log", true, 2, 1, {K("q", 4, G::cluster_quat), K("w", 1, G::weights)}, {out_q}},
      {OpId::dq_from_rotation_translation, "dq_from_rotation_translation", false, 2, 1, {q, I("t", 3, G::point)},
       {out_d}},
      {OpId::dq_compose, "dq_compose", false, 2, 1, {I("a", 8, G::unit_dq), I("b", 8, G::unit_dq)}, {out_d}},
      {OpId::dq_apply_point, "dq_apply_point", false, 2, 1, {I("d", 8, G::unit_dq), I("p", 3, G::point)}, {out_p}},
      {OpId::dq_normalize, "dq_normalize", false, 1, 1, {I("d", 8, G::scaled_dq)}, {out_d}},
      {OpId::dq_sclerp, "dq_sclerp", false, 3, 1, {I("a", 8, G::unit_dq), I("b", 8, G::near_dq), t}, {out_d}},
      {OpId::dq_blend, "dq_blend", true, 2, 1, {K("d", 8, G::cluster_dq), K("w", 1, G::weights)}, {out_d}},
      {OpId::rotate_about_axis, "rotate_about_axis", false, 4, 1,
       {I("c", 3, G::point), I("u", 3, G::unit_axis), I("angle", 1, G::angle), I("p", 3, G::point)}, {out_p}},
      {OpId::skin_linear, "skin_linear", true, 4, 1,
       {K("q", 4, G::cluster_quat), K("t", 3, G::point), K("w", 1, G::weights), I("v", 3, G::point)}, {out_v}},
      {OpId::skin_dual_quaternion, "skin_dual_quaternion", true, 4, 1,
       {K("q", 4, G::cluster_quat), K("t", 3, G::point), K("w", 1, G::weights), I("v", 3, G::point)}, {out_v}},
  }};
}();

static_assert([] {
  for (std::size_t i = 0; i < kOpCount; ++i)
    if (static_cast<std::size_t>(kOps[i].id) != i) return false;
  return true;
}(), "kOps must be indexed by OpId");

constexpr const OpSpec& op_spec(OpId id) { return kOps[static_cast<std::size_t>(id)]; }

/// Scalars of one array for n elements with k influences.
constexpr std::size_t array_scalars(const ArraySpec& a, std::size_t n, std::size_t k) {
  return n * static_cast<std::size_t>(a.stride) * (a.per_influence ? k : 1);
}

}  // namespace rotorcert::bench
