// Nominal cost of each ABI op per element: flops of the plain formula and bytes moved in the ABI
// layout. The report divides the machine's roofs (roofline/*) by these to get each kernel's
// attainable bound min(peak_flops / flops, bandwidth / bytes) and the fraction reached.
//
// Counting rule (the same for float and double, whatever an implementation actually does):
//   - add, sub, mul, div, sqrt: 1 flop each; an FMA a*b+c counts 2 (it is a mul and an add),
//     which is also how roofline/peak_fma counts;
//   - negation, abs, comparisons, selects, sign flips, copies: 0;
//   - a transcendental (sin, cos, acos, atan2, ...) counts kTranscendentalFlops = 20, about a
//     range reduction plus a degree-7..9 polynomial in Horner form (the size of Eberly's 2011
//     slerp polynomial); sin and cos of one angle count as two;
//   - the formula is the spec's definition (spec/SPEC.md, clause named per op) for unit inputs:
//     the input normalisation every clause requires (EDGE-5) and domain checks are not counted,
//     output normalisation that is part of the definition is;
//   - n-way ops count k influences, every one in full (the pivot too).
// dq_sclerp is an estimate (screw parameters in the usual closed form); the rest are exact
// counts of the written formula.
//
// Bytes per element: every input and output array in ABI layout (k influences for the per-
// influence arrays) times the scalar size, plus the one status byte. Write-allocate traffic is
// not counted (the STREAM convention, as roofline/bandwidth/triad).
#pragma once

#include <cstddef>

#include "op_layout.hpp"

namespace rotorcert::bench {

inline constexpr double kTranscendentalFlops = 20;

namespace cost {
constexpr double T = kTranscendentalFlops;
constexpr double dot4 = 7;                     // 4 mul, 3 add
constexpr double dot3 = 5;                     // 3 mul, 2 add
constexpr double norm3 = dot3 + 1;             // |v|: + sqrt
constexpr double normalize4 = dot4 + 1 + 1 + 4;  // |q|^2, sqrt, 1/|q|, 4 mul
constexpr double hamilton = 28;                // quaternion product: 16 mul, 12 add
constexpr double rotate = 30;                  // v + w t + u x t with t = 2 u x v: 15 mul, 15 add
constexpr double to_matrix = 24;               // 3 doublings, 9 products, 12 entry sums
constexpr double dq_product = 3 * hamilton + 4;          // DQ-2: r = ar br, d = ar bd + ad br
constexpr double dq_normalize = dot4 + 1 + 1 + 4 + dot4 + 4 + 3 + 8;  // DQ-4 as written
constexpr double dq_translation = 21 + 3;      // vector part of 2 d r*: 3 x (4 mul, 3 add), 3 mul
constexpr double dq_from_rt = 20 + 4;          // 1/2 t q with t pure: 12 mul, 8 add; 4 mul
}  // namespace cost

/// Nominal flops of one element of op `id` with k influences (n-way ops).
constexpr double flops_per_element(OpId id, std::size_t k_influences) {
  using namespace cost;
  const double k = static_cast<double>(k_influences);
  switch (id) {
    case OpId::normalize: return normalize4;                                   // NORM-1
    case OpId::compose: return hamilton;                                       // COMPOSE-1
    case OpId::inverse: return dot4 + 1 + 4;                                   // INV-1: q* / |q|^2
    case OpId::apply_vector: return rotate;                                    // APPLY-1
    case OpId::apply_bivector: return rotate;                                  // APPLY-2
    case OpId::apply_trivector: return 0;                                      // APPLY-3: s I is invariant
    case OpId::to_matrix: return to_matrix;                                    // MAT-1
    case OpId::from_matrix: return 2 + 1 + 1 + 1 + 1 + 3 + 3;                  // MAT-2: Shepperd, one branch
    case OpId::to_axis_angle: return norm3 + T + 1 + 1 + 3;                    // AXANG-1: 2 atan2(|v|, w), v/|v|
    case OpId::from_axis_angle: return 1 + 2 * T + 3;                          // AXANG-2: sin, cos of angle/2
    case OpId::log: return norm3 + T + 1 + 3;                                  // LOG-1: atan2(|v|, w) v/|v|
    case OpId::exp: return norm3 + 2 * T + 1 + 3;                              // EXP-1: cos|v|, sin|v| v/|v|
    case OpId::slerp:                                                          // SLERP-1
      // dot, acos, sin(Omega), sin((1-t)Omega), sin(t Omega), 1/sin, 2 coefficients, 2 scaled sums
      return dot4 + 4 * T + 2 + 1 + 1 + 2 + 12;
    case OpId::nlerp: return dot4 + 1 + 4 + 4 + 4 + normalize4;               // NLERP-1: (1-t) a + t b'
    case OpId::blend_qlb:                                                      // QLB-1
      return dot4 * (k - 1) + 4 * k + 4 * (k - 1) + normalize4;
    case OpId::blend_log:                                                      // LOGBLEND-1
      // 1/W; per influence q_p* q_i, log, w_i/W and the scaled sum; exp; q_p times it
      return (k - 1) + 1 + k * (hamilton + norm3 + T + 1 + 3 + 1 + 3) + 3 * (k - 1) +
             (norm3 + 2 * T + 1 + 3) + hamilton;
    case OpId::dq_from_rotation_translation: return dq_from_rt;              // DQ-1
    case OpId::dq_compose: return dq_product;                                 // DQ-2
    case OpId::dq_apply_point: return dq_translation + rotate + 3;            // DQ-3: R p + t
    case OpId::dq_normalize: return dq_normalize;                             // DQ-4
    case OpId::dq_sclerp:                                                      // DQ-5 (estimate)
      // a* b', screw parameters (acos, sin, cos of the half angle; 16 flops), scaled by t and
      // rebuilt (sin, cos; 20 flops), a times the power
      return dq_product + (3 * T + 16) + (2 * T + 20) + dq_product;
    case OpId::dq_blend:                                                       // DQ-6
      return dot4 * (k - 1) + 8 * k + 8 * (k - 1) + dq_normalize;
    case OpId::rotate_about_axis:                                              // AXIS-1: Rodrigues about c
      // p - c; sin, cos; u x v, u . v, 1 - cos, (u . v)(1 - cos); three scaled terms; + c
      return 3 + 2 * T + 9 + dot3 + 1 + 1 + 15 + 3;
    case OpId::skin_linear:                                                    // SKIN-1
      // per influence R_i v + t_i and w_i times it, the sum, W and 1/W, the scaled result
      return k * (rotate + 3 + 3) + 3 * (k - 1) + (k - 1) + 1 + 3;
    case OpId::skin_dual_quaternion:                                           // SKIN-2
      // DQ-1 per influence, DLB (DQ-6), DQ-3 on the unit result
      return k * dq_from_rt + (dot4 * (k - 1) + 8 * k + 8 * (k - 1) + dq_normalize) +
             (dq_translation + rotate + 3);
    case OpId::to_angle: return norm3 + T + 1;                                 // AXANG-3: 2 atan2(|v|, w)
    case OpId::to_axis: return norm3 + 1 + 3;                                  // AXANG-4: v/|v|
    case OpId::sqrt: return 1 + normalize4;                                    // SQRT-1: (1 + w, v) normalised
    case OpId::dq_to_rotation_translation: return dq_translation;              // DQ-7 on a unit input
    case OpId::dq_log:                                                         // DQ-8 on a unit input
      // |r_v|, atan2, n = r_v/|r_v|, d_v . n, a, d_perp, b/|r_v|, b n and a n + k d_perp
      return norm3 + T + 3 + dot3 + 3 + 6 + 1 + 3 + 9;
    case OpId::dq_exp:                                                         // DQ-9
      // b = |xi_r|, n, a = xi_d . n, xi_perp, cos, sin, sin b / b, real (3), dual (1 + 3 x 4)
      return norm3 + 3 + dot3 + 6 + 2 * T + 1 + 3 + 13;
    case OpId::rigid_compose: return hamilton + rotate + 3;                    // RIGID-1
    case OpId::rigid_apply: return rotate + 3;                                 // RIGID-2
    case OpId::rigid_inverse: return rotate;                                   // RIGID-3: q*, -R^-1 t
    case OpId::count_: break;                                                  // the list's size, not an op
  }  // no default: -Wswitch (-Wall, errors) names an op of the list that has no cost here
  return 0;
}

/// Scalars one element reads and writes (inputs + outputs, k influences), status byte excluded.
constexpr std::size_t scalars_per_element(const OpSpec& op, std::size_t k) {
  std::size_t s = 0;
  for (std::size_t i = 0; i < op.n_in; ++i) s += array_scalars(op.in[i], 1, k);
  for (std::size_t i = 0; i < op.n_out; ++i) s += array_scalars(op.out[i], 1, k);
  return s;
}

/// Bytes one element reads and writes in the ABI layout: scalars plus the status byte.
constexpr std::size_t bytes_per_element(const OpSpec& op, std::size_t scalar_bytes, std::size_t k) {
  return scalars_per_element(op, k) * scalar_bytes + 1;
}

// The slerp inputs and output in float: a, b, out 4 each, t 1, status 1 = 53 bytes.
static_assert(bytes_per_element(op_spec(OpId::slerp), 4, 1) == 53);

}  // namespace rotorcert::bench
