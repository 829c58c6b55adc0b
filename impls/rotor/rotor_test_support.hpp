// Test support of the rotor group (not a harness): calls into an implementation's C table for
// one element, and errors against the reference in eps units (METRIC-1/3/5/6, METRIC-2).
#pragma once

#include <array>
#include <cstdint>
#include <limits>

#include <rotorcert/impl.hpp>
#include <rotorcert/reference/metrics.hpp>
#include <rotorcert/reference/rotation_ops.hpp>

namespace rotor_test {

using rotorcert::ref::Real;
using RQ = rotorcert::ref::Quaternion<Real>;
using RV = std::array<Real, 3>;
template <class S> using Q = rotorcert::impl::Quat<S>;
template <class S> using V = rotorcert::impl::Vec3<S>;
template <class S> using M = rotorcert::impl::Mat3<S>;
template <class S> using Ops = rotorcert::impl::Ops<S>;

/// The table of scalar S from an entry point.
template <class S>
const Ops<S>& ops_of(rc_impl_entry_fn entry) {
  for (std::uint32_t i = 0;; ++i) {
    const rc_impl* t = entry(RC_ABI_VERSION, i);
    if (!t) break;
    if constexpr (std::is_same_v<S, float>) {
      if (t->scalar == RC_SCALAR_FLOAT32) return *t->f32;
    } else {
      if (t->scalar == RC_SCALAR_FLOAT64) return *t->f64;
    }
  }
  throw std::runtime_error("no table of that scalar type");
}

template <class S> double eps() { return std::numeric_limits<S>::epsilon(); }

template <class S> RQ real(const Q<S>& q) { return {Real(q[3]), Real(q[0]), Real(q[1]), Real(q[2])}; }
template <class S> RV real(const V<S>& v) { return {Real(v[0]), Real(v[1]), Real(v[2])}; }
/// A reference value rounded to S (for inputs; the test then uses the rounded value exactly).
template <class S> S round_to(const Real& x) { return static_cast<S>(x.toDouble()); }
template <class S> Q<S> round_to(const RQ& q) { return {round_to<S>(q.x), round_to<S>(q.y), round_to<S>(q.z), round_to<S>(q.w)}; }
template <class S> V<S> round_to(const RV& v) { return {round_to<S>(v[0]), round_to<S>(v[1]), round_to<S>(v[2])}; }

/// METRIC-1 and METRIC-6 of a unit-valued quaternion output, the larger in eps units.
template <class S>
double rotation_error(const Q<S>& got, const RQ& ref) {
  namespace c = rotorcert::ref::clause;
  const Real d = c::METRIC_1_rotation_distance(real(got), ref);
  const Real n = c::METRIC_6_norm_defect(real(got));
  return std::max(d.toDouble(), n.toDouble()) / eps<S>();
}
/// METRIC-3 with scale s (absolute when s = 0), eps units.
template <class S>
double vector_error(const V<S>& got, const RV& ref, const Real& s) {
  Real d(0);
  for (int i = 0; i < 3; ++i) d += (Real(got[i]) - ref[i]) * (Real(got[i]) - ref[i]);
  const Real e = s == 0 ? sqrt(d) : sqrt(d) / s;
  return e.toDouble() / eps<S>();
}
/// METRIC-5, eps units.
template <class S>
double bivector_error(const V<S>& got, const RV& ref) {
  return rotorcert::ref::clause::METRIC_5_bivector_error(real(got), ref).toDouble() / eps<S>();
}
/// METRIC-4, eps units.
template <class S>
double matrix_error(const M<S>& got, const std::array<Real, 9>& ref) {
  Real e(0);
  for (int i = 0; i < 9; ++i) e = std::max(e, Real(abs(Real(got[i]) - ref[i])));
  return e.toDouble() / eps<S>();
}
inline Real length(const RV& v) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

}  // namespace rotor_test

// ---- a short smoke check of every op against the reference (rotor_m1, rotor_m2) ----------
#include <rapidcheck.h>

#include <rotorcert/reference/rigid_ops.hpp>
#include <rotorcert/testing/generators.hpp>
#include <rotorcert/testing/tolerance.hpp>

namespace rotor_test {

/// The FAIL threshold (loose bar) of a class: a random input must never FAIL. Whether the worst
/// case over many inputs stays under the strict bar (PASS rather than QUALITY_WARNING) is what the
/// certificate grades; rotor_m1 in binary32, for one, reaches 4.6 eps on NORM-1 (Method 1's
/// atan2/cos/sin on the way in), above eps4's strict bar, within its loose one.
inline double bar(const char* cls) { return rotorcert::testing::eps_class_bars(cls).loose; }

/// Componentwise relative error max_i |q_i - r_i| / |r| (Table 3, non-unit quaternions).
template <class S>
double relative_error(const Q<S>& got, const RQ& ref) {
  const RQ g = real(got);
  const Real d = std::max({Real(abs(g.w - ref.w)), Real(abs(g.x - ref.x)), Real(abs(g.y - ref.y)), Real(abs(g.z - ref.z))});
  return (d / norm(ref)).toDouble() / eps<S>();
}

/// One random input per op, judged by the op's clause class (strict bar). rapidcheck property body.
template <class S>
void smoke(const Ops<S>& o) {
  namespace c = rotorcert::ref::clause;
  using rotorcert::testing::quaternion;
  using rotorcert::testing::real_in;
  using rotorcert::testing::vector3;
  std::uint8_t st = 9;
  const Q<S> a = round_to<S>(*quaternion()), b = round_to<S>(*quaternion()), e = round_to<S>(*quaternion());
  const RQ A = real(a), B = real(b), E = real(e);
  const V<S> v = round_to<S>(*vector3());
  const RV x = real(v);
  const S t = round_to<S>(*real_in(2));
  Q<S> q;
  V<S> w;
  o.normalize(1, a.data(), q.data(), &st);
  RC_ASSERT(st == RC_OK);
  RC_ASSERT(rotation_error(q, c::NORM_1_normalize(A).value) <= bar("eps4"));
  o.compose(1, a.data(), b.data(), q.data(), &st);
  RC_ASSERT(relative_error(q, A * B) <= bar("eps8"));  // the plain product (COMPOSE-1, EX-COMPOSE-1-h)
  o.inverse(1, a.data(), q.data(), &st);
  RC_ASSERT(relative_error(q, c::INV_1_inverse(A).value) <= bar("eps4"));
  o.apply_vector(1, a.data(), v.data(), w.data(), &st);
  RC_ASSERT(vector_error(w, c::APPLY_1_apply_vector(A, x).value, length(x)) <= bar("eps8"));
  o.apply_bivector(1, a.data(), v.data(), w.data(), &st);
  RC_ASSERT(vector_error(w, c::APPLY_2_apply_bivector(A, x).value, length(x)) <= bar("eps8"));
  M<S> m;
  o.to_matrix(1, a.data(), m.data(), &st);
  const auto mref = c::MAT_1_to_matrix(A).value;
  RC_ASSERT(matrix_error(m, mref) <= bar("eps8"));
  M<S> mr;
  std::array<Real, 9> mr_real;
  for (int i = 0; i < 9; ++i) mr[i] = round_to<S>(mref[i]), mr_real[i] = Real(mr[i]);
  o.from_matrix(1, mr.data(), q.data(), &st);
  const RQ qm = c::MAT_2_from_matrix(mr_real).value;
  RC_ASSERT(rotation_error(q, qm) <= bar("eps16"));
  RC_ASSERT(abs(qm.w) <= Real(bar("eps16") * eps<S>()) || (Real(q[3]) > 0) == (qm.w > 0));  // MAT-2 sign rule
  S angle;
  o.to_axis_angle(1, a.data(), &angle, w.data(), &st);
  const auto aa = c::AXANG_1_to_axis_angle(A).value;
  RC_ASSERT(abs(Real(angle) - aa.angle).toDouble() / eps<S>() <= bar("eps16"));
  RC_ASSERT(vector_error(w, aa.axis, Real(1)) <= bar("eps16"));
  o.from_axis_angle(1, &t, v.data(), q.data(), &st);
  RC_ASSERT(length(x) == 0 || rotation_error(q, c::AXANG_2_from_axis_angle(Real(t), x).value) <= bar("eps16"));
  o.log(1, a.data(), w.data(), &st);
  RC_ASSERT(bivector_error(w, c::LOG_1_log(A).value) <= bar("eps16"));
  o.exp(1, v.data(), q.data(), &st);
  RC_ASSERT(rotation_error(q, c::EXP_1_exp(x).value) <= bar("eps16"));
  o.slerp(1, a.data(), b.data(), &t, q.data(), &st);
  RC_ASSERT(rotation_error(q, c::SLERP_1_slerp(A, B, Real(t)).value) <= bar("eps16"));
  o.nlerp(1, a.data(), b.data(), &t, q.data(), &st);
  RC_ASSERT(rotation_error(q, c::NLERP_1_nlerp(A, B, Real(t)).value) <= bar("eps16"));
  // Blends of three influences; the first weight may be 0 (the pivot is then the second).
  const std::array<Q<S>, 3> qs{a, b, e};
  const std::array<RQ, 3> rqs{A, B, E};
  const std::array<S, 3> ws{*rc::gen::element(S(0), S(0.25), S(1)), S(0.5), S(2)};
  const std::array<Real, 3> rws{Real(ws[0]), Real(ws[1]), Real(ws[2])};
  o.blend_qlb(1, 3, qs[0].data(), ws.data(), q.data(), &st);
  RC_ASSERT(rotation_error(q, c::QLB_1_blend(std::span<const RQ>(rqs), std::span<const Real>(rws)).value) <= bar("eps32"));
  o.blend_log(1, 3, qs[0].data(), ws.data(), q.data(), &st);
  RC_ASSERT(rotation_error(q, c::LOGBLEND_1_blend(std::span<const RQ>(rqs), std::span<const Real>(rws)).value) <= bar("eps32"));
  const std::array<V<S>, 3> ts{round_to<S>(*vector3(8)), round_to<S>(*vector3(8)), round_to<S>(*vector3(8))};
  const std::array<RV, 3> rts{real(ts[0]), real(ts[1]), real(ts[2])};
  o.skin_linear(1, 3, qs[0].data(), ts[0].data(), ws.data(), v.data(), w.data(), &st);
  RC_ASSERT(st == RC_OK);
  Real scale = std::max(Real(1), length(x));
  for (const RV& ti : rts) scale = std::max(scale, length(ti));
  const RV skin = c::SKIN_1_linear_blend(std::span<const RQ>(rqs), std::span<const RV>(rts), std::span<const Real>(rws), x).value;
  RC_ASSERT(vector_error(w, skin, scale) <= bar("eps64"));
}

}  // namespace rotor_test
