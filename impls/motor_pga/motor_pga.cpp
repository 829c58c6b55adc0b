// motor_pga: PGA Cl(3,0,1) motors as a drop-in for dual quaternions (the future work of
// Papagiannakis 2013). The runtime math is motor.hpp (layout and MOTOR-1 map documented there);
// this file is the ABI face.
//
// The ABI speaks dual quaternions [real xyzw, dual xyzw]; every operation converts with MOTOR-1
// at the boundary (exact: coefficients are only moved and negated), works on motors, and
// converts back. The conversion is part of what is measured.
//
// Defined outcomes (EDGE-5 .. EDGE-9): a non-finite component anywhere, a zero rotor part or a
// zero rotation, a zero axis, or bad weights give DOMAIN_ERROR (the adaptor writes the NaNs).
// A non-unit input motor stands for its normalisation M (M ~M)^(-1/2) (= DQ-4).
//
// Batches: the ordinary elements of dq_from_rotation_translation, dq_compose, dq_normalize,
// dq_apply_point, dq_blend, skin_dual_quaternion and rotate_about_axis run in SIMD lanes with the
// element function's bits (motor_lanes.hpp); every other element takes the checked element
// function (dq_blend's first tries the inline blend_ordinary()).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <type_traits>

#include <rotorcert/runtime/exact_sign.hpp>
#include <rotorcert/runtime/lane_batch.hpp>
#include <rotorcert/runtime/lane_blocks.hpp>
#include <rotorcert/runtime/scalar_real_part_log.hpp>
#include <rotorcert/runtime/target_clones.hpp>
#include <rotorcert/impl_table.hpp>

#include "motor.hpp"
#include "motor_lanes.hpp"

namespace {

namespace rci = rotorcert::impl;
namespace runtime = rotorcert::runtime;
namespace pga = rotorcert::motor_pga;
using rci::largest_weight;
using rci::Status;
using pga::Motor;
using pga::V3;

template <class S> bool finite(S x) { return std::isfinite(x); }
template <class S, std::size_t N> bool finite(const std::array<S, N>& a) {
  return std::all_of(a.begin(), a.end(), [](S x) { return finite(x); });
}
template <class S> bool valid_rotation(const rci::Quat<S>& q) {
  return finite(q) && (q[0] != 0 || q[1] != 0 || q[2] != 0 || q[3] != 0);
}
/// A usable dual quaternion: finite, real part (the rotor part of the motor) nonzero.
template <class S> bool valid_dq(const rci::DualQuat<S>& d) {
  return finite(d) && (d[0] != 0 || d[1] != 0 || d[2] != 0 || d[3] != 0);
}

/// <A ~B>_0 of the rotor parts for the hemisphere rules (EDGE-3), from the inputs as given, each
/// scaled by an exact power of two: normalised copies would turn an exact 0 (no flip) into
/// +-tiny, and raw products could overflow.
template <class S> int hemisphere_dot(const Motor<S>& a, const Motor<S>& b) {
  return runtime::hemisphere_sign<S>({a.s, a.e23, a.e31, a.e12}, {b.s, b.e23, b.e31, b.e12});
}

/// The unit motor of a dual quaternion (MOTOR-1, then normalisation).
template <class S> Motor<S> unit_motor(const rci::DualQuat<S>& d) {
  return pga::normalized(pga::from_dual_quaternion(d));
}

/// The rotor of the rotation q/|q|: q divided by the largest |component| (exact power of two)
/// and by its norm, then Q2R-1.
template <class S> Motor<S> unit_rotor(const rci::Quat<S>& q) {
  using std::abs;
  if (const S n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]; runtime::is_ordinary_square(n2)) {
    const S n = std::sqrt(n2);  // no scaling needed (runtime/ordinary_range.hpp)
    return pga::rotor(q[0] / n, q[1] / n, q[2] / n, q[3] / n);
  }
  const int e = -std::ilogb(std::max({abs(q[0]), abs(q[1]), abs(q[2]), abs(q[3])}));
  const S x = std::scalbn(q[0], e), y = std::scalbn(q[1], e), z = std::scalbn(q[2], e), w = std::scalbn(q[3], e);
  const S n = std::sqrt(x * x + y * y + z * z + w * w);
  return pga::rotor(x / n, y / n, z / n, w / n);
}

/// DQ-1 as a motor: M = T(t) R (rotate, then translate).
template <class S> Motor<S> rigid(const rci::Quat<S>& q, const rci::Vec3<S>& t) {
  return pga::translator(V3<S>{t[0], t[1], t[2]}) * unit_rotor(q);
}

template <class S> rci::Vec3<S> move_point(const Motor<S>& unit, const rci::Vec3<S>& p) {
  const pga::Point<S> moved = pga::sandwich(unit, pga::Point<S>{p[0], p[1], p[2], S(1)});
  return {moved.e032, moved.e013, moved.e021};
}

/// MOTOR-5 on validated input: normalise(sum (w_i / w_max) s_i M_i) over the unit influences,
/// s_i = -1 iff <M_i ~M_p>_0 < 0 against the pivot p (first weight > 0), decided on the motors
/// as given (`raw(i)`). Equals DLB (DQ-6) under MOTOR-1.
template <class S, class Raw, class Unit>
Motor<S> blend(std::size_t k, Raw raw, Unit unit_influence, std::span<const S> w, S w_max) {
  std::size_t p = 0;
  while (!(w[p] > 0)) ++p;
  const Motor<S> pivot = raw(p);
  Motor<S> sum{0, 0, 0, 0, 0, 0, 0, 0};
  for (std::size_t i = 0; i < k; ++i) {
    const Motor<S> m = unit_influence(i);
    const S f = hemisphere_dot(raw(i), pivot) < 0 ? -(w[i] / w_max) : w[i] / w_max;
    sum = {sum.s + f * m.s,     sum.e23 + f * m.e23, sum.e31 + f * m.e31, sum.e12 + f * m.e12,
           sum.e01 + f * m.e01, sum.e02 + f * m.e02, sum.e03 + f * m.e03, sum.e0123 + f * m.e0123};
  }
  return pga::normalized(sum);
}

/// MOTOR-5 on an element of the batch (k influences of 8 ABI scalars at d, k weights at w) whose
/// input passes the cheap tests: every weight in [0, max], some > 0; every influence with its
/// rotor part's n^2 ordinary and its ideal part's squares ordinary or 0 (then every coefficient is
/// finite and the rotor part nonzero); no normalisation whose subtraction cancels; every
/// hemisphere sign decided by the filter of runtime/exact_sign.hpp. There it is blend() above with
/// the same operations in the same order, so the same bits, without the checks, copies and calls.
/// Returns false, having written nothing, where a test fails: the caller takes the checked path.
template <class S>
bool blend_ordinary(std::size_t k, const S* d, const S* w, Motor<S>& out) {
  S w_max;
  std::size_t p;
  if (!rci::ordinary_weights(std::span<const S>(w, k), w_max, p)) return false;
  const std::array<S, 4> pivot{d[8 * p + 3], -d[8 * p], -d[8 * p + 1], -d[8 * p + 2]};  // (s, e23, e31, e12)
  Motor<S> sum{0, 0, 0, 0, 0, 0, 0, 0};
  for (std::size_t i = 0; i < k; ++i) {
    const S* x = d + 8 * i;
    const Motor<S> raw{x[3], -x[0], -x[1], -x[2], -x[4], -x[5], -x[6], -x[7]};  // MOTOR-1
    Motor<S> m;
    if (!pga::normalized_ordinary(raw, pga::rotor_norm2(raw), pga::ideal_norm2(raw), m)) return false;
    const int side = runtime::filtered_dot_sign<S, 4>({raw.s, raw.e23, raw.e31, raw.e12}, pivot);
    if (side == 2) return false;  // only the exact sum can tell (EDGE-3)
    const S f = side < 0 ? -(w[i] / w_max) : w[i] / w_max;
    sum = {sum.s + f * m.s,     sum.e23 + f * m.e23, sum.e31 + f * m.e31, sum.e12 + f * m.e12,
           sum.e01 + f * m.e01, sum.e02 + f * m.e02, sum.e03 + f * m.e03, sum.e0123 + f * m.e0123};
  }
  if (!pga::normalized_ordinary(sum, pga::rotor_norm2(sum), pga::ideal_norm2(sum), out)) out = pga::normalized(sum);
  return true;
}

template <class S>
struct MotorPga {
  using Scalar = S;
  /// The most influences a batched binary32 blend runs in SIMD lanes (the suite uses n <= 8: 8.3).
  static constexpr std::size_t kLaneInfluences = 8;
  static constexpr const char* name = "motor_pga";
  static constexpr const char* version = "0.1.0";
  static constexpr const char* description =
      "PGA Cl(3,0,1) motors (hand-expanded products, closed-form exp/log) behind the dual-quaternion ABI";
  static constexpr std::uint32_t levels = RC_LEVEL_RIGID | RC_LEVEL_SKINNING | RC_LEVEL_ROBUST;
  static constexpr const char* const clauses[] = {
      "DQ-1",   "DQ-2",   "DQ-3",   "DQ-4",   "DQ-5",   "DQ-6",   "AXIS-1",                      // Rigid
      "SKIN-2", "SKIN-3",                                                                        // Skinning
      "DQ-7",   "DQ-8",   "DQ-9",   "RIGID-1", "RIGID-2", "RIGID-3",                             // Extended
      "EDGE-1", "EDGE-2", "EDGE-3", "EDGE-4", "EDGE-5", "EDGE-6", "EDGE-7", "EDGE-9",  // Robust (EDGE-8: no quaternion ops)
      nullptr};

  static Status dq_from_rotation_translation(const rci::Quat<S>& q, const rci::Vec3<S>& t, rci::DualQuat<S>& out) {
    if (!valid_rotation(q) || !finite(t)) return Status::domain_error;
    out = pga::to_dual_quaternion(rigid(q, t));
    return Status::ok;
  }

  /// The batch of dq_from_rotation_translation, as dq's (dq.cpp): SIMD lanes (motor_lanes.hpp: the
  /// same bits) in blocks of 16, then of 4; a lane that is not ok, and the last n mod 4 elements,
  /// by the checked function above. dq_compose_batch and dq_normalize_batch below run the same way.
  ROTORCERT_TARGET_CLONES_FLAT static int dq_from_rotation_translation_batch(std::size_t n, const S* q, const S* t,
                                                                            S* out, std::uint8_t* status) {
    return runtime::lanes_or_element<rotorcert::motor_lanes::FromRotationTranslationLanes,
                                     &MotorPga::dq_from_rotation_translation, 4, 3, 8>(n, q, t, out, status);
  }

  /// DQ-7 (ABI version 3) in the algebra: the unit motor M = T R of the input; R is its Euclidean
  /// (real) part read back by MOTOR-1, t the image M O ~M of the origin O = e123 (R O ~R = O).
  static Status dq_to_rotation_translation(const rci::DualQuat<S>& d, rci::Quat<S>& q, rci::Vec3<S>& t) {
    if (!valid_dq(d)) return Status::domain_error;
    const Motor<S> m = unit_motor(d);
    const std::array<S, 8> u = pga::to_dual_quaternion(m);
    q = {u[0], u[1], u[2], u[3]};
    t = move_point(m, rci::Vec3<S>{S(0), S(0), S(0)});
    return Status::ok;
  }

  /// DQ-8 (ABI version 4): the motor log of the unit motor, xi = -(its bivector coefficients)
  /// (MOTOR-1 negates them). The closed-form log needs <M>_0 > -1; at the branch cut (rotor part
  /// -1, then M = -T(t)) the axis is taken along the translation t: xi = (pi t/|t|, t/2), +z for
  /// t = 0.
  static Status dq_log(const rci::DualQuat<S>& d, std::array<S, 6>& out) {
    if (!valid_dq(d)) return Status::domain_error;
    if (d[0] == 0 && d[1] == 0 && d[2] == 0 && d[3] < 0) {
      // The branch cut, read off the input (normalising first can underflow its parts).
      out = runtime::log_of_scalar_real_part<S>(d[3], {d[4], d[5], d[6]});
      return Status::ok;
    }
    const Motor<S> m = unit_motor(d);
    // The rotor and ideal parts as given: normalising can leave them subnormal (EDGE-1).
    const pga::Bivector<S> b = pga::log(m, std::array<S, 4>{d[3], -d[0], -d[1], -d[2]}, pga::V3<S>{-d[4], -d[5], -d[6]});
    out = {-b.e23, -b.e31, -b.e12, -b.e01, -b.e02, -b.e03};
    return Status::ok;
  }

  /// DQ-9 (ABI version 4): exp of the bivector -(xi_r, xi_d) (MOTOR-1), in closed form.
  static Status dq_exp(const std::array<S, 6>& xi, rci::DualQuat<S>& out) {
    if (!finite(xi)) return Status::domain_error;
    out = pga::to_dual_quaternion(pga::exp(pga::Bivector<S>{-xi[0], -xi[1], -xi[2], -xi[3], -xi[4], -xi[5]}));
    return Status::ok;
  }

  // -- rigid transforms as rotation + translation (ABI version 4): motors T(t) R ----------------

  /// The rotation and translation of a unit motor M = T R: R read back by MOTOR-1, t = M O ~M.
  static void split(const Motor<S>& m, rci::Quat<S>& q, rci::Vec3<S>& t) {
    const std::array<S, 8> u = pga::to_dual_quaternion(m);
    q = {u[0], u[1], u[2], u[3]};
    t = move_point(m, rci::Vec3<S>{S(0), S(0), S(0)});
  }

  /// RIGID-1: the product T(t_a) R_a T(t_b) R_b of the two motors.
  static Status rigid_compose(const rci::Quat<S>& qa, const rci::Vec3<S>& ta, const rci::Quat<S>& qb,
                              const rci::Vec3<S>& tb, rci::Quat<S>& q, rci::Vec3<S>& t) {
    if (!valid_rotation(qa) || !valid_rotation(qb) || !finite(ta) || !finite(tb)) return Status::domain_error;
    split(rigid(qa, ta) * rigid(qb, tb), q, t);
    return Status::ok;
  }

  /// RIGID-2: the sandwich of the point by T(t) R.
  static Status rigid_apply(const rci::Quat<S>& q, const rci::Vec3<S>& t, const rci::Vec3<S>& p, rci::Vec3<S>& out) {
    if (!valid_rotation(q) || !finite(t) || !finite(p)) return Status::domain_error;
    out = move_point(rigid(q, t), p);
    return Status::ok;
  }

  /// RIGID-3: the reverse ~M = ~R T(-t) of the unit motor.
  static Status rigid_inverse(const rci::Quat<S>& q_in, const rci::Vec3<S>& t_in, rci::Quat<S>& q, rci::Vec3<S>& t) {
    if (!valid_rotation(q_in) || !finite(t_in)) return Status::domain_error;
    split(pga::reverse(rigid(q_in, t_in)), q, t);
    return Status::ok;
  }

  /// MOTOR-3: the geometric product of the unit motors (apply b first): DQ-4 of DQ-2's product of
  /// the inputs as given (the motor norm is multiplicative), the rigid motion METRIC-7 compares.
  static Status dq_compose(const rci::DualQuat<S>& a, const rci::DualQuat<S>& b, rci::DualQuat<S>& out) {
    if (!valid_dq(a) || !valid_dq(b)) return Status::domain_error;
    out = pga::to_dual_quaternion(unit_motor(a) * unit_motor(b));
    return Status::ok;
  }

  /// The batch of dq_compose (motor_lanes.hpp DqComposeLanes), as dq_from_rotation_translation_batch.
  ROTORCERT_TARGET_CLONES_FLAT static int dq_compose_batch(std::size_t n, const S* a, const S* b, S* out,
                                                          std::uint8_t* status) {
    return runtime::lanes_or_element<rotorcert::motor_lanes::DqComposeLanes, &MotorPga::dq_compose, 8, 8, 8>(
        n, a, b, out, status);
  }

  /// MOTOR-2: the sandwich M P ~M of the unit motor.
  static Status dq_apply_point(const rci::DualQuat<S>& d, const rci::Vec3<S>& p, rci::Vec3<S>& out) {
    if (!valid_dq(d) || !finite(p)) return Status::domain_error;
    out = move_point(unit_motor(d), p);
    return Status::ok;
  }

  /// The batch of dq_apply_point, as dq's (dq.cpp): SIMD lanes (motor_lanes.hpp: the same bits) in
  /// blocks of 16, then of 4; a lane that is not ok, and the last n mod 4 elements, by the checked
  /// function above.
  ROTORCERT_TARGET_CLONES_FLAT static int dq_apply_point_batch(std::size_t n, const S* d, const S* p, S* out,
                                                              std::uint8_t* status) {
    return runtime::lanes_or_element<rotorcert::motor_lanes::ApplyPointLanes, &MotorPga::dq_apply_point, 8, 3, 3>(
        n, d, p, out, status);
  }

  static Status dq_normalize(const rci::DualQuat<S>& d, rci::DualQuat<S>& out) {
    if (!valid_dq(d)) return Status::domain_error;
    out = pga::to_dual_quaternion(unit_motor(d));
    return Status::ok;
  }

  /// The batch of dq_normalize (motor_lanes.hpp DqNormalizeLanes), as dq_from_rotation_translation_batch.
  ROTORCERT_TARGET_CLONES_FLAT static int dq_normalize_batch(std::size_t n, const S* d, S* out, std::uint8_t* status) {
    return runtime::lanes_or_element<rotorcert::motor_lanes::DqNormalizeLanes, &MotorPga::dq_normalize, 8, 8>(
        n, d, out, status);
  }

  /// DQ-5 through MOTOR-4: exp(t log(M_B ~M_A)) M_A on the shorter arc.
  static Status dq_sclerp(const rci::DualQuat<S>& a, const rci::DualQuat<S>& b, const S& t, rci::DualQuat<S>& out) {
    if (!valid_dq(a) || !valid_dq(b) || !finite(t)) return Status::domain_error;
    const Motor<S> ma = unit_motor(a), mb = unit_motor(b);
    const bool flip = hemisphere_dot(pga::from_dual_quaternion(b), pga::from_dual_quaternion(a)) < 0;
    out = pga::to_dual_quaternion(pga::interpolate_aligned(ma, flip ? -mb : mb, t));
    return Status::ok;
  }

  static Status dq_blend(std::span<const rci::DualQuat<S>> d, std::span<const S> w, rci::DualQuat<S>& out) {
    if (d.empty() || d.size() != w.size()) return Status::domain_error;
    for (const auto& x : d)
      if (!valid_dq(x)) return Status::domain_error;
    const S w_max = largest_weight(w);
    if (!(w_max > 0)) return Status::domain_error;
    out = pga::to_dual_quaternion(blend<S>(
        d.size(), [&](std::size_t i) { return pga::from_dual_quaternion(d[i]); },
        [&](std::size_t i) { return unit_motor(d[i]); }, w, w_max));
    return Status::ok;
  }

  /// The batch of dq_blend, as dq's (dq.cpp): k <= kLaneInfluences in SIMD lanes
  /// (motor_lanes.hpp: the same bits as the checked path), blocks of 16, then of 4; the last
  /// n mod 4 elements and more influences by blend_ordinary() per element; a lane or element that
  /// fails its cheap tests by the checked element function.
  ROTORCERT_TARGET_CLONES_FLAT static int dq_blend_batch(std::size_t n, std::size_t k, const S* d, const S* w, S* out,
                                                        std::uint8_t* status) {
    const auto checked = [&](std::size_t e) {
      rci::detail::blend<&MotorPga::dq_blend, S, 8, 8>(1, k, d + 8 * k * e, w + k * e, out + 8 * e, status + e);
    };
    const auto store = [&](std::size_t e, const Motor<S>& m) {
      const rci::DualQuat<S> o = pga::to_dual_quaternion(m);
      std::copy(o.begin(), o.end(), out + 8 * e);
      status[e] = RC_OK;
    };
    const auto single = [&](std::size_t i) {
      Motor<S> m;
      if (k > 0 && blend_ordinary(k, d + 8 * k * i, w + k * i, m)) [[likely]] store(i, m);
      else checked(i);
    };
    if (k > 0 && k <= kLaneInfluences) {
      runtime::in_lanes_or_checked<rotorcert::motor_lanes::BlendLanes>(
          n, d, 8 * k, w, k, [&](auto& lanes, const S* dd, const S* ww) { lanes.run(k, dd, ww); },
          [&](std::size_t e, const auto& lanes, std::size_t l) {
            store(e, Motor<S>{lanes.out[0][l], lanes.out[1][l], lanes.out[2][l], lanes.out[3][l], lanes.out[4][l],
                              lanes.out[5][l], lanes.out[6][l], lanes.out[7][l]});
          },
          checked, single);
      return 0;
    }
    for (std::size_t i = 0; i < n; ++i) single(i);
    return 0;
  }

  /// AXIS-1: the motor T_c R ~T_c, R = cos(angle/2) - sin(angle/2) (u1 e23 + u2 e31 + u3 e12)
  /// for the unit direction u, applied to the point.
  static Status rotate_about_axis(const rci::Vec3<S>& c, const rci::Vec3<S>& u, const S& angle, const rci::Vec3<S>& p,
                                  rci::Vec3<S>& out) {
    if (!finite(c) || !finite(u) || !finite(angle) || !finite(p)) return Status::domain_error;
    if (u[0] == 0 && u[1] == 0 && u[2] == 0) return Status::domain_error;
    const S sn = std::sin(angle / 2), cs = std::cos(angle / 2);
    // The rotor of the quaternion (cos, sin u/|u|): unit_rotor normalises the direction safely.
    const Motor<S> axis = unit_rotor(rci::Quat<S>{u[0], u[1], u[2], S(0)});  // (0, -u/|u|)
    const Motor<S> r{cs, sn * axis.e23, sn * axis.e31, sn * axis.e12, 0, 0, 0, 0};
    const Motor<S> tc = pga::translator(V3<S>{c[0], c[1], c[2]});
    out = move_point(tc * r * pga::reverse(tc), p);
    return Status::ok;
  }

  /// The batch of rotate_about_axis: SIMD lanes (motor_lanes.hpp RotateAboutAxisLanes: the same
  /// bits) in blocks of 16, then of 4; a lane that is not ok, and the last n mod 4 elements, by
  /// the checked function above.
  ROTORCERT_TARGET_CLONES_FLAT static int rotate_about_axis_batch(std::size_t n, const S* c, const S* u, const S* angle,
                                                                 const S* p, S* out, std::uint8_t* status) {
    return runtime::lanes_or_element<rotorcert::motor_lanes::RotateAboutAxisLanes, &MotorPga::rotate_about_axis, 3, 3,
                                     3, 3>(n, c, u, angle, p, out, status);
  }

  /// SKIN-2: M_i = T(t_i) R_i (unit by construction), blended (MOTOR-5), sandwich of v.
  static Status skin_dual_quaternion(std::span<const rci::Quat<S>> q, std::span<const rci::Vec3<S>> t,
                                     std::span<const S> w, const rci::Vec3<S>& v, rci::Vec3<S>& out) {
    if (q.empty() || q.size() != t.size() || q.size() != w.size() || !finite(v)) return Status::domain_error;
    for (std::size_t i = 0; i < q.size(); ++i)
      if (!valid_rotation(q[i]) || !finite(t[i])) return Status::domain_error;
    const S w_max = largest_weight(w);
    if (!(w_max > 0)) return Status::domain_error;
    // The hemisphere test on the rotations as given: rotor_dot of rotors = dot of quaternions.
    const auto raw = [&](std::size_t i) { return pga::rotor(q[i][0], q[i][1], q[i][2], q[i][3]); };
    out = move_point(blend<S>(q.size(), raw, [&](std::size_t i) { return rigid(q[i], t[i]); }, w, w_max), v);
    return Status::ok;
  }

  /// The batch of skin_dual_quaternion. k <= kLaneInfluences: SIMD lanes (motor_lanes.hpp
  /// SkinDualQuaternionLanes: the same bits) in blocks of 16, then of 4; a lane that is not ok
  /// (an undecided hemisphere sign, EDGE-3, among its tests), the last n mod 4 elements and every
  /// element of more influences by the checked function above.
  ROTORCERT_TARGET_CLONES_FLAT static int skin_dual_quaternion_batch(std::size_t n, std::size_t k, const S* q,
                                                                    const S* t, const S* w, const S* v, S* out,
                                                                    std::uint8_t* status) {
    return runtime::skin_lanes_or_element<rotorcert::motor_lanes::SkinDualQuaternionLanes,
                                          &MotorPga::skin_dual_quaternion, kLaneInfluences>(n, k, q, t, w, v, out,
                                                                                            status);
  }
};

}  // namespace

ROTORCERT_DEFINE_ENTRY(motor_pga, MotorPga<float>, MotorPga<double>)
