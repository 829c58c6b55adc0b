// rotor_m2: the paper's Method 2 with the signs corrected (ERRATUM-2): quaternion -> rotor by
// the coefficient map Phi(q) = w - x e23 - y e31 - z e12 (Q2R-1), no trigonometry on the way in;
// every operation in Cl(3,0) (impls/rotor/rotor3.hpp) and the quaternion read back by Phi^-1.
// The same code as rotor_m1 except this conversion.
//
// Every batch but sqrt and blend_log runs its ordinary elements in SIMD lanes
// (rotor/rotor_lanes.hpp: RotorOps' operations in RotorOps' order, so the same bits; the libm
// calls of the angle, log, exp and slerp lanes are RotorOps' own, made one lane at a time) and
// every other element, and the last n mod 4, through RotorOps, which scales only where it must.
#include <cstddef>
#include <cstdint>

#include <rotorcert/impl_table.hpp>
#include <rotorcert/runtime/lane_batch.hpp>
#include <rotorcert/runtime/target_clones.hpp>

#include "../rotor/rotor3.hpp"
#include "../rotor/rotor_lanes.hpp"

namespace {

namespace runtime = rotorcert::runtime;
namespace lanes = rotorcert::rotor::lanes;

template <class S>
struct RotorM2 : rotorcert::rotor::RotorOps<S, rotorcert::rotor::Method2> {
  using Base = rotorcert::rotor::RotorOps<S, rotorcert::rotor::Method2>;
  static constexpr const char* name = "rotor_m2";
  static constexpr const char* version = "1";
  static constexpr const char* description =
      "GA rotors, corrected Method 2: rotor = Phi(q) = w - x e23 - y e31 - z e12, ops in Cl(3,0)";
  static constexpr std::uint32_t levels = rotorcert::rotor::kRotorLevels;
  static constexpr const char* const* clauses = rotorcert::rotor::kRotorClauses;
  /// The most influences a blend_qlb batch runs in SIMD lanes (the suite's blends have at most 8).
  static constexpr std::size_t kLaneInfluences = 8;

  /// NORM-1, COMPOSE-1, APPLY-1 batches: lanes for ordinary |q|^2 (and finite v), RotorOps
  /// otherwise (runtime/lane_batch.hpp).
  ROTORCERT_TARGET_CLONES_FLAT static int normalize_batch(std::size_t n, const S* q, S* out, std::uint8_t* status) {
    return runtime::lanes_or_element<lanes::NormalizeLanes, &Base::normalize, 4, 4>(n, q, out, status);
  }
  ROTORCERT_TARGET_CLONES_FLAT static int compose_batch(std::size_t n, const S* a, const S* b, S* out,
                                                       std::uint8_t* status) {
    return runtime::lanes_or_element<lanes::ComposeLanes, &Base::compose, 4, 4, 4>(n, a, b, out, status);
  }
  ROTORCERT_TARGET_CLONES_FLAT static int apply_vector_batch(std::size_t n, const S* q, const S* v, S* out,
                                                            std::uint8_t* status) {
    return runtime::lanes_or_element<lanes::ApplyVectorLanes, &Base::apply_vector, 4, 3, 3>(n, q, v, out, status);
  }
  /// APPLY-2 batches: a bivector's coefficients rotate as a vector's (sandwich_bivector is
  /// sandwich_vector), so the APPLY-1 lanes compute them.
  ROTORCERT_TARGET_CLONES_FLAT static int apply_bivector_batch(std::size_t n, const S* q, const S* b, S* out,
                                                              std::uint8_t* status) {
    return runtime::lanes_or_element<lanes::ApplyVectorLanes, &Base::apply_bivector, 4, 3, 3>(n, q, b, out, status);
  }
  /// APPLY-3 batches: the checks in lanes, the output the input.
  ROTORCERT_TARGET_CLONES_FLAT static int apply_trivector_batch(std::size_t n, const S* q, const S* a, S* out,
                                                               std::uint8_t* status) {
    return runtime::lanes_or_element<lanes::ApplyTrivectorLanes, &Base::apply_trivector, 4, 1, 1>(n, q, a, out, status);
  }
  /// INV-1 batches.
  ROTORCERT_TARGET_CLONES_FLAT static int inverse_batch(std::size_t n, const S* q, S* out, std::uint8_t* status) {
    return runtime::lanes_or_element<lanes::InverseLanes, &Base::inverse, 4, 4>(n, q, out, status);
  }
  /// MAT-1 batches.
  ROTORCERT_TARGET_CLONES_FLAT static int to_matrix_batch(std::size_t n, const S* q, S* out, std::uint8_t* status) {
    return runtime::lanes_or_element<lanes::ToMatrixLanes, &Base::to_matrix, 4, 9>(n, q, out, status);
  }
  /// MAT-2 batches: lanes where MAT-3's fast path applies (a rotation rounded to the format).
  ROTORCERT_TARGET_CLONES_FLAT static int from_matrix_batch(std::size_t n, const S* m, S* out, std::uint8_t* status) {
    return runtime::lanes_or_element<lanes::FromMatrixLanes, &Base::from_matrix, 9, 4>(n, m, out, status);
  }
  /// AXANG-4 batches (ABI version 3).
  ROTORCERT_TARGET_CLONES_FLAT static int to_axis_batch(std::size_t n, const S* q, S* out, std::uint8_t* status) {
    return runtime::lanes_or_element<lanes::ToAxisLanes, &Base::to_axis, 4, 3>(n, q, out, status);
  }
  /// NLERP-1 batches: lanes where the inputs are ordinary and the hemisphere filter decides.
  ROTORCERT_TARGET_CLONES_FLAT static int nlerp_batch(std::size_t n, const S* a, const S* b, const S* t, S* out,
                                                     std::uint8_t* status) {
    return runtime::lanes_or_element<lanes::NlerpLanes, &Base::nlerp, 4, 4>(n, a, b, t, out, status);
  }
  /// AXANG-2 batches: lanes for a finite angle and an axis of ordinary |axis|^2.
  ROTORCERT_TARGET_CLONES_FLAT static int from_axis_angle_batch(std::size_t n, const S* angle, const S* axis, S* out,
                                                               std::uint8_t* status) {
    return runtime::lanes_or_element<lanes::FromAxisAngleLanes, &Base::from_axis_angle, 1, 3, 4>(n, angle, axis, out,
                                                                                                  status);
  }
  /// AXANG-1 batches: lanes as for to_angle and to_axis, the angle and the axis stored apart.
  ROTORCERT_TARGET_CLONES_FLAT static int to_axis_angle_batch(std::size_t n, const S* q, S* angle, S* axis,
                                                             std::uint8_t* status) {
    const auto checked = [&](std::size_t e) {
      rotorcert::impl::detail::Elementwise<&Base::to_axis_angle, decltype(&Base::to_axis_angle)>::run(
          1, q + 4 * e, angle + e, axis + 3 * e, status + e);
    };
    const auto store = [&](std::size_t e, const auto& lanes, std::size_t l) {
      angle[e] = lanes.out[0][l];
      for (std::size_t c = 0; c < 3; ++c) axis[3 * e + c] = lanes.out[1 + c][l];
      status[e] = RC_OK;
    };
    runtime::in_lanes_or_checked<lanes::ToAxisAngleLanes>(
        n, q, 4, q, 0, [](auto& l, const S* x, const S* y) { l.run(x, y); }, store, checked, checked);
    return 0;
  }
  /// AXANG-3 batches (ABI version 3).
  ROTORCERT_TARGET_CLONES_FLAT static int to_angle_batch(std::size_t n, const S* q, S* out, std::uint8_t* status) {
    return runtime::lanes_or_element<lanes::ToAngleLanes, &Base::to_angle, 4, 1>(n, q, out, status);
  }
  /// LOG-1 batches: lanes where |q|^2 and the rotor's |B|^2 (and, past a half turn, |v|^2) are
  /// ordinary.
  ROTORCERT_TARGET_CLONES_FLAT static int log_batch(std::size_t n, const S* q, S* out, std::uint8_t* status) {
    return runtime::lanes_or_element<lanes::LogLanes, &Base::log, 4, 3>(n, q, out, status);
  }
  /// EXP-1 batches: lanes where |v|^2 is ordinary.
  ROTORCERT_TARGET_CLONES_FLAT static int exp_batch(std::size_t n, const S* v, S* out, std::uint8_t* status) {
    return runtime::lanes_or_element<lanes::ExpLanes, &Base::exp, 3, 4>(n, v, out, status);
  }
  /// SKIN-1 batches of at most kLaneInfluences influences: lanes where the weights and every
  /// influence are ordinary and the vertex and translations finite.
  ROTORCERT_TARGET_CLONES_FLAT static int skin_linear_batch(std::size_t n, std::size_t k, const S* q, const S* t,
                                                           const S* w, const S* v, S* out, std::uint8_t* status) {
    return runtime::skin_lanes_or_element<lanes::SkinLinearLanes, &Base::skin_linear, kLaneInfluences>(n, k, q, t, w, v,
                                                                                                      out, status);
  }
  /// SLERP-2 batches: lanes where the inputs, log's bivector and exp's argument are ordinary.
  ROTORCERT_TARGET_CLONES_FLAT static int slerp_batch(std::size_t n, const S* a, const S* b, const S* t, S* out,
                                                     std::uint8_t* status) {
    return runtime::lanes_or_element<lanes::SlerpLanes, &Base::slerp, 4, 4>(n, a, b, t, out, status);
  }
  /// QLB-1 batches of at most kLaneInfluences influences: lanes where the weights, every influence
  /// and the sum are ordinary and the filter decides every hemisphere sign; every other element,
  /// the last n mod 4 and any batch of more influences through RotorOps.
  ROTORCERT_TARGET_CLONES_FLAT static int blend_qlb_batch(std::size_t n, std::size_t k, const S* q, const S* w, S* out,
                                                         std::uint8_t* status) {
    const auto checked = [&](std::size_t e) {
      rotorcert::impl::detail::blend<&Base::blend_qlb, S, 4, 4>(1, k, q + 4 * k * e, w + k * e, out + 4 * e, status + e);
    };
    if (k == 0 || k > kLaneInfluences) return rotorcert::impl::detail::blend<&Base::blend_qlb, S, 4, 4>(n, k, q, w, out, status);
    runtime::in_lanes_or_checked<lanes::BlendQlbLanes>(
        n, q, 4 * k, w, k, [k](auto& l, const S* qq, const S* ww) { l.run(k, qq, ww); },
        runtime::copy_lane_outputs<4>(out, status), checked, checked);
    return 0;
  }
};

}  // namespace

ROTORCERT_DEFINE_ENTRY(rotor_m2, RotorM2<float>, RotorM2<double>)
