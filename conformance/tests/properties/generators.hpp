// rapidcheck generators of engine::Case values: the rapidcheck-native counterpart of the seeded
// families of conformance/src/engine/cases.cpp, with shrinking.
//
// rapidcheck's own floating-point generators never produce NaN, +-Inf, -0 or subnormals, and
// rarely anything near a rotation's special points. These generators reach them on purpose:
// near-identity and near-antipodal inputs, exact half turns and exact ties of the hemisphere rule,
// angles from 1e-9 to 1e-3, non-unit scales from 1e-3 to 1e3 (and the format's extremes),
// subnormal and -0 components, NaN and +-Inf, t outside [0, 1], degenerate weight sets and rigid
// transforms with translations up to 1e6.
//
// Every value is built from integer draws (inRange, shrinking toward 0 / the first choice) mapped
// to an exact number, computed in the reference precision and rounded once to the format: a
// Case holds exactly what the implementation receives, so the reference is evaluated on exactly
// the implementation's input, and a shrunk counterexample moves toward simple values (identity,
// axis-aligned vectors, t = 0, short lists).
#pragma once

#include <stdexcept>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include <rapidcheck.h>

#include <rotorcert/engine/cases.hpp>
#include <rotorcert/engine/runner.hpp>
#include <rotorcert/reference/rigid_ops.hpp>
#include <rotorcert/reference/rotation_ops.hpp>

namespace rotorcert::properties {

using engine::Case;
using ref::Real;
using Quat = ref::Quaternion<Real>;
using V3 = ref::Vec3<Real>;
using DQ = ref::DualQuaternion<Real>;

/// The input families. Which clause draws from which: families_for().
enum class Family {
  random,             // ordinary inputs: unit quaternions, t in [0, 1], positive weights
  large_translation,  // rigid inputs with translations of length 1e3 .. 1e6
  non_unit,           // quaternion inputs scaled by 10^U(-3, 3)
  extreme_scale,      // quaternion inputs scaled near the format's overflow / underflow thresholds
  subnormal,          // quaternion components subnormal in the format, or -0
  near_identity,      // rotation angles (or differences) 10^U(-9, -3)
  near_antipodal,     // angle near 2 pi / pairs near b = -a
  half_turn,          // w = 0 exactly (matrices of half turns for from_matrix)
  dot_zero,           // pairs with a.b = 0 exactly: the tie of the hemisphere rule (EDGE-3)
  antipode,           // pairs with b = -a exactly
  negated,            // some quaternion arrays negated (EDGE-4)
  identity,           // identity inputs (EDGE-1)
  zero,               // a zero quaternion / zero real part, components +-0 (EDGE-6)
  nonfinite,          // one component NaN, +Inf or -Inf, in any input array (EDGE-7)
  t_outside,          // t in [-1, 0) or (1, 2]
  t_endpoint,         // t = 0 or t = 1
  t_grid,             // t = j/8 on [0, 1]
  bad_weights,        // negative, NaN, Inf weights, zero sum, k = 0; and -0 weights that are fine
  first_weight_zero,  // first weight 0: the pivot is the second influence, and the third
                      // influence's hemisphere differs between the two candidate pivots
  negative_real,      // (+-0, +-0, +-0, w < 0): LOG-2's cut, AXANG-1's theta = 2 pi
  angle_near_2pi,     // rotation angle in (2 pi - 1, 2 pi): w < -cos(1/2)
  perturbed_matrix,   // a rotation plus noise 1e-6 .. 1e-2, or scaled anisotropically (det > 0)
  reflection,         // det < 0 or the zero matrix: DOMAIN_ERROR (MAT-3)
  bad_axis,           // zero axis (+-0 components): DOMAIN_ERROR (AXANG-2)
  same_influences,    // a single influence or all influences equal (SKIN-3)
};

inline const char* to_string(Family f) {
  switch (f) {
    case Family::random: return "random";
    case Family::large_translation: return "large translation";
    case Family::non_unit: return "non-unit scale 1e-3..1e3";
    case Family::extreme_scale: return "extreme scale";
    case Family::subnormal: return "subnormal and -0 components";
    case Family::near_identity: return "angle 1e-9..1e-3";
    case Family::near_antipodal: return "near-antipodal";
    case Family::half_turn: return "half turn (w = 0)";
    case Family::dot_zero: return "dot exactly 0";
    case Family::antipode: return "exact antipode";
    case Family::negated: return "negated quaternions";
    case Family::identity: return "identity";
    case Family::zero: return "zero quaternion";
    case Family::nonfinite: return "NaN or Inf";
    case Family::t_outside: return "t outside [0, 1]";
    case Family::t_endpoint: return "t = 0 or 1";
    case Family::t_grid: return "t = j/8";
    case Family::bad_weights: return "degenerate weights";
    case Family::first_weight_zero: return "first weight 0";
    case Family::negative_real: return "negative real quaternion";
    case Family::angle_near_2pi: return "angle in (2pi - 1, 2pi)";
    case Family::perturbed_matrix: return "non-orthonormal matrix, det > 0";
    case Family::reflection: return "det <= 0";
    case Family::bad_axis: return "zero axis";
    case Family::same_influences: return "single or equal influences";
  }
  return "?";
}

/// The families that probe `clause` through `op`. An operation's own clause draws ordinary
/// inputs plus what its text singles out (NORM-1: every scale of the format; MAT-2: half turns;
/// QLB-1: the pivot rule, ...); the edge behaviours the spec assigns to EDGE-1..9 ("Edges:" of
/// each operation) are drawn by those clauses, so that each defect is charged to the clause
/// that defines it.
inline std::vector<Family> families_for(const std::string& clause, const std::string& op) {
  using F = Family;
  const bool rigid = op.rfind("dq_", 0) == 0 || op == "rotate_about_axis" || op.rfind("skin_", 0) == 0;
  if (clause == "NORM-1") return {F::random, F::non_unit, F::extreme_scale, F::subnormal};
  if (clause == "INV-1") return {F::random, F::non_unit};  // defined unnormalised
  if (clause == "MAT-2") return {F::random, F::half_turn, F::near_antipodal, F::near_identity};
  // LEVEL-1's ordinary families: small angles and angles near a full turn for single rotations,
  // near-identical and near-antipodal pairs (exact antipodes included) for interpolations.
  if (clause == "COMPOSE-1") return {F::random, F::non_unit, F::near_identity, F::near_antipodal};
  if (clause == "MAT-1" || clause == "APPLY-1" || clause == "LOG-1" || clause == "EXP-1")
    return {F::random, F::near_identity, F::near_antipodal};
  if (clause == "SLERP-1") return {F::random, F::near_identity, F::near_antipodal, F::antipode};
  // The domain errors a clause's own text and worked examples define (MAT-3: EX-MAT-3-e..g;
  // AXANG-2: "zero or non-finite axis"; DQ-1: EX-DQ-1-g, a zero rotation) are drawn under it as
  // well as under EDGE-6 / EDGE-7: without them a defect that lives only on that set (glm's
  // dualquat(0, t) = 0 with status OK) is found by no property of the clause it is charged to.
  if (clause == "MAT-3") return {F::perturbed_matrix, F::reflection, F::nonfinite};
  if (clause == "AXANG-1" || clause == "AXANG-3" || clause == "AXANG-4" || clause == "SQRT-1")
    return {F::random, F::angle_near_2pi, F::negative_real, F::near_identity};
  if (clause == "AXANG-2") return {F::random, F::bad_axis, F::nonfinite, F::near_identity};
  if (clause == "DQ-1") return {F::random, F::large_translation, F::zero};
  if (clause == "LOG-2") return {F::negative_real};
  if (clause == "EXP-2") return {F::random, F::angle_near_2pi, F::negative_real, F::near_identity};
  if (clause == "SLERP-2" || clause == "NLERP-1") return {F::random, F::t_outside, F::near_antipodal, F::antipode};
  if (clause == "SLERP-3") return {F::t_endpoint};
  if (clause == "SLERP-4") return {F::t_outside};
  if (clause == "SLERP-5") return {F::t_grid};
  if (clause == "QLB-1" || clause == "LOGBLEND-1") return {F::random, F::first_weight_zero};
  if (clause == "DQ-6") return {F::random, F::first_weight_zero, F::large_translation};
  if (clause == "SKIN-3") return {F::same_influences};
  if (clause == "EDGE-1") return {F::identity};
  if (clause == "EDGE-2") return {F::near_identity};
  if (clause == "EDGE-3") return {F::dot_zero, F::antipode};
  if (clause == "EDGE-4") return {F::negated};
  if (clause == "EDGE-5") return {F::non_unit, F::extreme_scale};
  if (clause == "EDGE-6") return {F::zero};
  if (clause == "EDGE-7") return {F::nonfinite};
  if (clause == "EDGE-8") return {F::subnormal};
  if (clause == "EDGE-9") return {F::bad_weights};
  if (rigid) return {F::random, F::large_translation};
  return {F::random};
}

namespace gen {

// ---- integer draws ----------------------------------------------------------------------
// rapidcheck scales inRange by the test's size (size 0: always the minimum). The draws below use
// the full range at every size, so that the first tests of a property are as varied as the last;
// shrinking still moves toward the minimum.

/// An integer in [0, n], shrinking toward 0.
inline rc::Gen<int> upto(int n) { return rc::gen::resize(100, rc::gen::inRange(0, n + 1)); }

/// An integer in [-n, n], shrinking toward 0 through small magnitudes (0, 1, -1, 2, -2, ...).
inline rc::Gen<int> symmetric(int n) {
  return rc::gen::map(upto(2 * n), [](int k) { return k % 2 ? (k + 1) / 2 : -(k / 2); });
}

// ---- exact values (call inside rc::gen::exec or a property: they use operator*) ----------

inline Real round(ref::Format f, const Real& x) { return engine::round_to(f, x); }
inline Real pi() { return ref::ScalarTraits<Real>::pi(); }
inline Real pow10(const Real& e) { return pow(Real(10), e); }

/// 10^e with e uniform on a grid of 1000 steps in [lo, hi].
inline Real decades(double lo, double hi) {
  const int j = *upto(1000);
  return pow10(Real(lo) + Real(hi - lo) * Real(j) / Real(1000));
}

/// A rotation from four integers in [-1000, 1000] (all zero: the identity), normalised exactly.
/// Every rotation is within ~1e-3 of one; shrinks toward axis-aligned quaternions and 1.
inline Quat unit_quaternion() {
  Quat q{Real(*symmetric(1000)), Real(*symmetric(1000)), Real(*symmetric(1000)), Real(*symmetric(1000))};
  if (ref::dot(q, q) == 0) q.w = Real(1);
  return ref::normalized(q);
}

/// A unit vector from three integers (all zero: +z), exact.
inline V3 direction() {
  V3 v{Real(*symmetric(1000)), Real(*symmetric(1000)), Real(*symmetric(1000))};
  const Real n2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  if (n2 == 0) return {Real(0), Real(0), Real(1)};
  const Real n = sqrt(n2);
  return {v[0] / n, v[1] / n, v[2] / n};
}

inline V3 scaled(const V3& v, const Real& s) { return {v[0] * s, v[1] * s, v[2] * s}; }

/// The exact rotation by `angle` about the unit `axis`.
inline Quat rotation(const Real& angle, const V3& axis) {
  const Real h = angle / Real(2);
  return {cos(h), sin(h) * axis[0], sin(h) * axis[1], sin(h) * axis[2]};
}

/// An angle 10^U(-9, -3) (EDGE-2's range).
inline Real small_angle() { return decades(-9, -3); }

/// t = j/1024 in [lo, hi] (exact in both formats).
inline Real t_in(int lo, int hi) { return Real(lo) + Real(*upto((hi - lo) * 1024)) / Real(1024); }

/// Weights of k influences: w_i = j/64, j in 1..64 for the first (the pivot), 0..64 for the others.
inline std::vector<Real> weights(std::size_t k) {
  std::vector<Real> w;
  for (std::size_t i = 0; i < k; ++i) w.push_back(Real(i == 0 ? 1 + *upto(63) : *upto(64)) / Real(64));
  return w;
}

/// A rigid motion (unit dual quaternion, exact) with a translation of length 10^U(lo, hi).
inline DQ rigid(double lo, double hi) {
  const Quat q = unit_quaternion();
  const V3 t = scaled(direction(), decades(lo, hi));
  return ref::clause::DQ_1_from_rotation_translation(q, t).value;
}

inline std::vector<Real> flat(const Quat& q) { return {q.x, q.y, q.z, q.w}; }
inline std::vector<Real> flat(const V3& v) { return {v[0], v[1], v[2]}; }
inline std::vector<Real> flat(const DQ& d) {
  return {d.real.x, d.real.y, d.real.z, d.real.w, d.dual.x, d.dual.y, d.dual.z, d.dual.w};
}
inline Quat quat_at(const std::vector<Real>& a, std::size_t i) {
  return {a[i * 4 + 3], a[i * 4], a[i * 4 + 1], a[i * 4 + 2]};
}
inline void put(std::vector<Real>& a, std::size_t i, const std::vector<Real>& v) {
  std::copy(v.begin(), v.end(), a.begin() + std::ptrdiff_t(i * v.size()));
}
inline void append(std::vector<Real>& a, const std::vector<Real>& b) { a.insert(a.end(), b.begin(), b.end()); }

/// Indices of the op's input arrays with this stride (4: quaternions, 8: dual quaternions).
inline std::vector<std::size_t> arrays_with_stride(const engine::AbiOp& op, int stride) {
  std::vector<std::size_t> r;
  for (std::size_t i = 0; i < op.inputs.size(); ++i)
    if (op.inputs[i].stride == stride) r.push_back(i);
  return r;
}
inline std::size_t array_named(const engine::AbiOp& op, const std::string& name) {
  for (std::size_t i = 0; i < op.inputs.size(); ++i)
    if (op.inputs[i].name == name) return i;
  return op.inputs.size();
}

/// Ordinary inputs of `op` in exact values (rounded by the caller): unit quaternions, vectors of
/// length 10^U(-3, 3), t in [0, 1], positive weights, k influences (n-way ops; 0: drawn).
inline Case ordinary(const engine::AbiOp& op, std::size_t k = 0) {
  const std::string& n = op.name;
  Case c;
  auto q = [] { return flat(unit_quaternion()); };
  auto vec = [](double lo, double hi) { return flat(scaled(direction(), decades(lo, hi))); };
  if (n == "normalize" || n == "inverse" || n == "to_matrix" || n == "to_axis_angle" || n == "log" ||
      n == "to_angle" || n == "to_axis" || n == "sqrt") {
    c.inputs = {q()};
  } else if (n == "dq_to_rotation_translation" || n == "dq_log") {
    c.inputs = {flat(rigid(-1, 3))};
  } else if (n == "dq_exp") {
    std::vector<Real> xi = vec(-2, 1);  // any |xi_r| up to 10 (DQ-9, as EXP-1)
    append(xi, vec(-1, 3));
    c.inputs = {xi};
  } else if (n == "rigid_compose") {
    c.inputs = {q(), vec(-1, 3), q(), vec(-1, 3)};
  } else if (n == "rigid_apply") {
    c.inputs = {q(), vec(-1, 3), vec(-1, 3)};
  } else if (n == "rigid_inverse") {
    c.inputs = {q(), vec(-1, 3)};
  } else if (n == "compose") {
    c.inputs = {q(), q()};
  } else if (n == "apply_vector" || n == "apply_bivector") {
    c.inputs = {q(), vec(-3, 3)};
  } else if (n == "apply_trivector") {
    c.inputs = {q(), {Real(*symmetric(1 << 12)) / Real(256)}};
  } else if (n == "from_matrix") {
    const auto m = ref::clause::MAT_1_to_matrix(unit_quaternion()).value;
    c.inputs = {{m.begin(), m.end()}};
  } else if (n == "from_axis_angle") {
    // A unit axis: a non-unit one is an EDGE-5 input (drawn there, bad_axis).
    c.inputs = {{Real(*symmetric(7 * 1024)) / Real(1024)}, flat(direction())};
  } else if (n == "exp") {
    c.inputs = {vec(-2, 1)};  // |v| up to 10: exp has no restriction on |v| (EXP-1)
  } else if (n == "slerp" || n == "nlerp") {
    c.inputs = {q(), q(), {t_in(0, 1)}};
  } else if (n == "blend_qlb" || n == "blend_log") {
    c.k = k ? k : std::size_t(1 + *upto(4));
    std::vector<Real> qs;
    for (std::size_t i = 0; i < c.k; ++i) append(qs, q());
    c.inputs = {qs, weights(c.k)};
  } else if (n == "dq_from_rotation_translation") {
    c.inputs = {q(), vec(-1, 3)};
  } else if (n == "dq_compose") {
    c.inputs = {flat(rigid(-1, 3)), flat(rigid(-1, 3))};
  } else if (n == "dq_apply_point") {
    c.inputs = {flat(rigid(-1, 3)), vec(-1, 3)};
  } else if (n == "dq_normalize") {
    // Non-unit and with a dual part not orthogonal to the real part: what DQ-4 must repair.
    std::vector<Real> v = flat(rigid(-1, 2));
    const Real s(std::ldexp(1.0, *symmetric(3)));
    const Real along = Real(*symmetric(32)) / Real(64);
    for (int i = 0; i < 8; ++i) v[i] *= s;
    for (int i = 4; i < 8; ++i) v[i] += v[i - 4] * along;
    c.inputs = {v};
  } else if (n == "dq_sclerp") {
    c.inputs = {flat(rigid(-1, 2)), flat(rigid(-1, 2)), {t_in(0, 1)}};
  } else if (n == "dq_blend") {
    c.k = k ? k : std::size_t(1 + *upto(3));
    std::vector<Real> ds;
    for (std::size_t i = 0; i < c.k; ++i) append(ds, flat(rigid(-1, 2)));
    c.inputs = {ds, weights(c.k)};
  } else if (n == "rotate_about_axis") {
    c.inputs = {vec(-1, 2), vec(-1, 1), {Real(*symmetric(7 * 1024)) / Real(1024)}, vec(-1, 2)};
  } else if (n == "skin_linear" || n == "skin_dual_quaternion") {
    c.k = k ? k : std::size_t(1 + *upto(3));
    std::vector<Real> qs, ts;
    for (std::size_t i = 0; i < c.k; ++i) {
      append(qs, q());
      append(ts, vec(-1, 1));
    }
    c.inputs = {qs, ts, weights(c.k), vec(-1, 1)};
  } else {
    throw std::logic_error("properties/generators.hpp: no ordinary inputs for op " + n + " (add them)");
  }
  return c;
}

/// Replaces the translations of a rigid case by ones of length 10^U(3, 6), keeping rotations.
inline void large_translations(const engine::AbiOp& op, Case& c) {
  auto big = [] { return scaled(direction(), decades(3, 6)); };
  for (std::size_t a : arrays_with_stride(op, 8))
    for (std::size_t j = 0; j < c.inputs[a].size() / 8; ++j) {
      const Quat r = quat_at(c.inputs[a], 2 * j);
      put(c.inputs[a], j, flat(ref::clause::DQ_1_from_rotation_translation(r, big()).value));
    }
  if (op.name == "dq_from_rotation_translation") c.inputs[1] = flat(big());
  if (op.name == "dq_apply_point" || op.name == "rotate_about_axis") c.inputs.back() = flat(big());
  if (op.name == "rotate_about_axis") c.inputs[0] = flat(big());
  if (op.name == "skin_linear" || op.name == "skin_dual_quaternion")
    for (std::size_t j = 0; j < c.k; ++j) put(c.inputs[1], j, flat(big()));
}

/// Sets every quaternion of the op (and real part of every dual quaternion, with its translation
/// kept) from `make(i)`, i counting the quaternions in order.
template <class Make>
void set_rotations(const engine::AbiOp& op, Case& c, Make make) {
  std::size_t i = 0;
  for (std::size_t a : arrays_with_stride(op, 4))
    for (std::size_t j = 0; j < c.inputs[a].size() / 4; ++j) put(c.inputs[a], j, flat(make(i++)));
  for (std::size_t a : arrays_with_stride(op, 8))
    for (std::size_t j = 0; j < c.inputs[a].size() / 8; ++j) {
      const auto& v = c.inputs[a];
      const Quat old{v[j * 8 + 3], v[j * 8], v[j * 8 + 1], v[j * 8 + 2]};
      const Quat dual{v[j * 8 + 7], v[j * 8 + 4], v[j * 8 + 5], v[j * 8 + 6]};
      const V3 t = ref::clause::dual_quaternion_translation(DQ{old, dual});
      put(c.inputs[a], j, flat(ref::clause::DQ_1_from_rotation_translation(make(i++), t).value));
    }
}

/// Rotation-shaped inputs of ops that take no quaternion (exp: a log; from_axis_angle and
/// rotate_about_axis: an angle; from_matrix: a matrix): set from the rotation angle and axis.
inline void set_angle(const engine::AbiOp& op, Case& c, const Real& angle, const V3& axis) {
  if (op.name == "exp") c.inputs[0] = flat(scaled(axis, angle / Real(2)));
  if (op.name == "dq_exp") put(c.inputs[0], 0, flat(scaled(axis, angle / Real(2))));  // xi_r; xi_d kept
  if (op.name == "from_axis_angle") c.inputs = {{angle}, flat(axis)};
  if (op.name == "rotate_about_axis") c.inputs[2] = {angle};
  if (op.name == "from_matrix") {
    const auto m = ref::clause::MAT_1_to_matrix(rotation(angle, axis)).value;
    c.inputs[0] = {m.begin(), m.end()};
  }
}

/// The op's t array (slerp, nlerp, dq_sclerp), or inputs.size().
inline std::size_t t_array(const engine::AbiOp& op) {
  return op.name == "slerp" || op.name == "nlerp" || op.name == "dq_sclerp" ? 2 : op.inputs.size();
}

/// Ops whose rotations relate to each other (interpolation, composition, blends): the near-
/// identity and near-antipodal families set the second and later rotations from the first.
inline bool is_pair_op(const std::string& n) {
  return n == "slerp" || n == "nlerp" || n == "compose" || n == "dq_sclerp" || n == "blend_qlb" ||
         n == "blend_log" || n == "dq_blend" || n == "dq_compose" || n == "skin_linear" ||
         n == "skin_dual_quaternion";
}

/// Draws a case of `op` in `family`, exact values of the format `f`. Call inside rc::gen::exec.
inline Case draw(const engine::AbiOp& op, Family family, ref::Format f) {
  using F = Family;
  const std::string& n = op.name;
  const bool f32 = f == ref::Format::binary32;
  Case c = ordinary(op, family == F::dot_zero || family == F::antipode || family == F::first_weight_zero ? 3 : 0);
  const bool pair = is_pair_op(n);
  switch (family) {
    case F::random: break;
    case F::large_translation: large_translations(op, c); break;
    case F::non_unit:
    case F::extreme_scale: {
      // COMPOSE-1 is defined on the unnormalised inputs: its exact product must stay representable,
      // so each factor gets half the extreme exponent.
      const int extreme = (f32 ? 100 : 900) / (n == "compose" ? 2 : 1);
      for (int stride : {4, 8})
        for (std::size_t a : arrays_with_stride(op, stride))
          for (std::size_t j = 0; j < c.inputs[a].size() / std::size_t(stride); ++j) {
            Real s;
            if (family == F::non_unit) s = decades(-3, 3);
            else s = Real(std::ldexp(1.0 + *upto(255) / 256.0, *upto(1) ? extreme : -extreme));
            for (int i = 0; i < stride; ++i) c.inputs[a][j * stride + i] *= s;
          }
      break;
    }
    case F::subnormal: {
      // Components subnormal in the format, or -0: a naive |q|^2 underflows to 0.
      const int lowest = f32 ? -149 : -1074;
      for (std::size_t a : arrays_with_stride(op, 4))
        for (std::size_t j = 0; j < c.inputs[a].size(); ++j) {
          const int m = *upto(8);  // 0: -0
          c.inputs[a][j] = m == 0 ? Real(-0.0) : Real(std::ldexp(double(m), lowest + *upto(12)));
          if (*upto(1)) c.inputs[a][j] = -c.inputs[a][j];
        }
      // One in four: a subnormal vector part beside w = +-1, a rotation within a few ulp of +-1
      // whose axis B/|B| must still be accurate (the engine's EDGE-8 family has it too).
      if (*upto(3) == 3)
        for (std::size_t a : arrays_with_stride(op, 4))
          for (std::size_t j = 3; j < c.inputs[a].size(); j += 4) c.inputs[a][j] = Real(*upto(1) ? 1.0 : -1.0);
      break;
    }
    case F::near_identity: {
      // Small angles (and small differences between the two inputs of a pair).
      const Quat a = unit_quaternion();
      if (n == "compose") {
        set_rotations(op, c, [&](std::size_t) { return rotation(small_angle(), direction()); });
      } else if (pair) {
        set_rotations(op, c, [&](std::size_t i) { return i == 0 ? a : a * rotation(small_angle(), direction()); });
      } else {
        set_rotations(op, c, [&](std::size_t) { return rotation(small_angle(), direction()); });
        set_angle(op, c, small_angle(), direction());
      }
      break;
    }
    case F::near_antipodal: {
      const Quat a = unit_quaternion();
      if (pair) {
        set_rotations(op, c, [&](std::size_t i) { return i == 0 ? a : -(a * rotation(small_angle(), direction())); });
      } else {
        const Real angle = Real(2) * pi() - small_angle();  // w near -1
        set_rotations(op, c, [&](std::size_t) { return rotation(angle, direction()); });
        set_angle(op, c, n == "from_matrix" ? pi() - small_angle() : angle, direction());
      }
      break;
    }
    case F::half_turn: {
      set_rotations(op, c, [&](std::size_t) { return rotation(pi(), direction()); });
      set_angle(op, c, pi(), direction());
      // w = 0 exactly (cos(pi/2) in the reference is ~1e-77, not 0).
      for (std::size_t a : arrays_with_stride(op, 4))
        for (std::size_t j = 3; j < c.inputs[a].size(); j += 4) c.inputs[a][j] = Real(0);
      break;
    }
    case F::dot_zero:
    case F::antipode: {
      // (x, y, z, w) and (z, -y, x, -w) have a dot product of exactly 0 in any arithmetic (the
      // products pair up and cancel): a half turn between them, the tie of the hemisphere rule.
      const Quat a = unit_quaternion();
      const Quat b = family == F::antipode ? -a : Quat{a.z, -a.y, a.x, -a.w};
      set_rotations(op, c, [&](std::size_t i) { return i % 2 ? b : a; });
      break;
    }
    case F::negated: {
      bool any = false;
      for (int stride : {4, 8})
        for (std::size_t a : arrays_with_stride(op, stride))
          if (*upto(1) || !any) {
            any = true;
            for (Real& x : c.inputs[a]) x = -x;
          }
      break;
    }
    case F::identity: {
      set_rotations(op, c, [](std::size_t) { return Quat::identity(); });
      for (std::size_t a : arrays_with_stride(op, 8))  // the identity motion: no translation either
        for (std::size_t j = 0; j < c.inputs[a].size() / 8; ++j)
          put(c.inputs[a], j, {Real(0), Real(0), Real(0), Real(1), Real(0), Real(0), Real(0), Real(0)});
      set_angle(op, c, Real(0), direction());
      if (n == "exp") c.inputs[0] = {Real(0), Real(0), Real(0)};
      if (n == "dq_exp") c.inputs[0] = std::vector<Real>(6, Real(0));  // the identity motion's log
      if (t_array(op) < c.inputs.size()) c.inputs[t_array(op)] = {t_in(-1, 2)};  // "for every finite t"
      break;
    }
    case F::zero: {
      // One quaternion (or real part) of +-0 components, in any array and at any influence,
      // with weight 0 or not: DOMAIN_ERROR either way (SPEC 8.3).
      std::vector<std::pair<std::size_t, int>> slots;  // (array, stride)
      for (int stride : {4, 8})
        for (std::size_t a : arrays_with_stride(op, stride)) slots.push_back({a, stride});
      if (slots.empty()) break;
      const auto [a, stride] = *rc::gen::elementOf(slots);
      const std::size_t count = c.inputs[a].size() / std::size_t(stride);
      const std::size_t j = std::size_t(*upto(int(count) - 1));
      for (int i = 0; i < 4; ++i) c.inputs[a][j * stride + i] = *upto(1) ? Real(-0.0) : Real(0);
      const std::size_t w = array_named(op, "w");
      if (w < c.inputs.size() && *upto(1)) c.inputs[w][j] = Real(0);
      break;
    }
    case F::nonfinite: {
      std::vector<std::size_t> arrays;
      for (std::size_t a = 0; a < c.inputs.size(); ++a)
        if (!c.inputs[a].empty()) arrays.push_back(a);
      const std::size_t a = *rc::gen::elementOf(arrays);
      const std::size_t at = std::size_t(*upto(int(c.inputs[a].size()) - 1));
      const Real specials[3] = {ref::ScalarTraits<Real>::nan(), Real("inf"), -Real("inf")};
      c.inputs[a][at] = specials[*upto(2)];
      break;
    }
    case F::t_outside:
      if (t_array(op) < c.inputs.size()) c.inputs[t_array(op)] = {*upto(1) ? Real(1) + t_in(0, 1) : -t_in(0, 1)};
      if (t_array(op) < c.inputs.size() && c.inputs[t_array(op)][0] == 0) c.inputs[t_array(op)][0] = Real(-1);
      if (t_array(op) < c.inputs.size() && c.inputs[t_array(op)][0] == 1) c.inputs[t_array(op)][0] = Real(2);
      break;
    case F::t_endpoint:
      if (t_array(op) < c.inputs.size()) c.inputs[t_array(op)] = {Real(*upto(1))};
      break;
    case F::t_grid:
      if (t_array(op) < c.inputs.size()) c.inputs[t_array(op)] = {Real(*upto(8)) / Real(8)};
      break;
    case F::bad_weights: {
      const std::size_t w = array_named(op, "w");
      if (w >= c.inputs.size()) break;
      const int kind = *upto(6);
      auto& ws = c.inputs[w];
      const std::size_t at = std::size_t(*upto(int(ws.size()) - 1));
      switch (kind) {
        case 0: ws[at] = -Real(1 + *upto(63)) / Real(64); break;  // negative
        case 1: ws[at] = -Real(std::ldexp(1.0, f32 ? -149 : -1074)); break;  // the smallest negative
        case 2: ws[at] = ref::ScalarTraits<Real>::nan(); break;
        case 3: ws[at] = *upto(1) ? Real("inf") : -Real("inf"); break;
        case 4:  // all zero, some -0: the sum is 0
          for (Real& x : ws) x = *upto(1) ? Real(-0.0) : Real(0);
          break;
        case 5:  // no influences
          c.k = 0;
          for (std::size_t a = 0; a < op.inputs.size(); ++a)
            if (op.inputs[a].per_influence) c.inputs[a].clear();
          break;
        case 6:  // -0 weights count as 0 and are fine: still OK (the pivot moves past them)
          for (std::size_t i = 0; i + 1 < ws.size(); ++i)
            if (*upto(1)) ws[i] = Real(-0.0);
          break;
      }
      break;
    }
    case F::first_weight_zero: {
      // Pivot = the second influence q1 (w0 = 0 or -0). With c = q0.q1 != 0, s = sign(c),
      // q2 = q1 - s q0 has q2.q1 = 1 - |c| > 0 and q2.q0 = s(|c| - 1): its sign relative to q0 is
      // -s, so a blend that flips against the first influence instead of the pivot gets it wrong.
      const std::size_t w = array_named(op, "w");
      const auto qs = *rc::gen::suchThat(rc::gen::exec([] { return std::make_pair(unit_quaternion(), unit_quaternion()); }),
                                        [](const std::pair<Quat, Quat>& p) {
                                          const Real d = abs(ref::dot(p.first, p.second));
                                          return d > Real(1) / Real(8) && d < Real(7) / Real(8);
                                        });
      const Real s = ref::dot(qs.first, qs.second) < 0 ? Real(-1) : Real(1);
      const Quat q2 = ref::normalized(qs.second - s * qs.first);
      set_rotations(op, c, [&](std::size_t i) { return i == 0 ? qs.first : i == 1 ? qs.second : q2; });
      c.inputs[w][0] = *upto(1) ? Real(-0.0) : Real(0);
      break;
    }
    case F::negative_real: {
      const Real w = -decades(-3, 3);
      std::vector<Real> q = {Real(0), Real(0), Real(0), w};
      for (int i = 0; i < 3; ++i)
        if (*upto(1)) q[i] = Real(-0.0);
      c.inputs[0] = q;
      break;
    }
    case F::angle_near_2pi: {
      const Real angle = Real(2) * pi() - Real(1 + *upto(1023)) / Real(1024);
      c.inputs[0] = flat(rotation(angle, direction()));
      break;
    }
    case F::perturbed_matrix: {
      auto& m = c.inputs[0];
      if (*upto(1)) {
        const Real size = decades(-6, -2);
        for (Real& x : m) x += size * Real(*symmetric(1000)) / Real(1000);
      } else {
        // M = R diag(s): column c scaled by s_c in [1/16, 4] (smallest singular value >= 1/16).
        for (int col = 0; col < 3; ++col) {
          const Real s = Real(16 + *upto(48)) / Real(64) * Real(*upto(1) ? 1 : 4) / Real(*upto(1) ? 4 : 1);
          for (int r = 0; r < 3; ++r) m[col * 3 + r] *= s;
        }
      }
      break;
    }
    case F::reflection: {
      auto& m = c.inputs[0];
      const int kind = *upto(2);
      if (kind == 0) {
        for (int r = 0; r < 3; ++r) m[r] = -m[r];  // det -1
      } else if (kind == 1) {
        std::fill(m.begin(), m.end(), Real(0));  // det 0
      } else {
        for (int r = 0; r < 3; ++r) m[3 + r] = m[r];  // two equal columns: det 0
      }
      break;
    }
    case F::bad_axis: {
      for (std::size_t i = 0; i < 3; ++i) c.inputs[1][i] = *upto(1) ? Real(-0.0) : Real(0);
      break;
    }
    case F::same_influences: {
      if (*upto(1)) {
        c = ordinary(op, 1);
        break;
      }
      c = ordinary(op, std::size_t(2 + *upto(2)));
      // Copy influence 0 (rotation, possibly negated, and translation) over the others.
      for (std::size_t j = 1; j < c.k; ++j) {
        const Real sign = *upto(1) ? Real(-1) : Real(1);
        for (int s = 0; s < 4; ++s) c.inputs[0][j * 4 + s] = sign * c.inputs[0][s];
        for (int s = 0; s < 3; ++s) c.inputs[1][j * 3 + s] = c.inputs[1][s];
      }
      break;
    }
  }
  for (auto& arr : c.inputs)
    for (Real& x : arr) x = round(f, x);
  c.label = to_string(family);
  return c;
}

}  // namespace gen

/// One drawn input: the op, the family it came from, the case, and the format it is exact in.
struct Drawn {
  std::string op;
  Family family = Family::random;
  Case c;
  ref::Format format = ref::Format::binary64;
};

/// The counterexample as rapidcheck prints it: op, family, every input in hexfloat.
inline void showValue(const Drawn& d, std::ostream& os) {
  os << d.op << " [" << to_string(d.family) << "] " << engine::describe_inputs(*engine::find_abi_op(d.op), d.c, d.format);
}

/// A case of one of `ops` (drawn first, shrinking toward the first op), from one of the families
/// of `clause` for that op.
inline rc::Gen<Drawn> drawn(const std::string& clause, const std::vector<std::string>& ops, ref::Format f) {
  return rc::gen::exec([=] {
    Drawn d;
    d.op = *rc::gen::elementOf(ops);
    d.family = *rc::gen::elementOf(families_for(clause, d.op));
    d.c = gen::draw(*engine::find_abi_op(d.op), d.family, f);
    d.format = f;
    return d;
  });
}

}  // namespace rotorcert::properties
