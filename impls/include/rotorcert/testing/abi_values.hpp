// Test support for implementation tests (in impls/, the layer it belongs to: it reads impl.hpp
// types): values in the ABI's array layouts (impl_abi.h, LAYOUT-1)
// read exactly into the reference's types, and errors against the reference in eps units.
#pragma once

#include <algorithm>
#include <type_traits>

#include <rotorcert/impl.hpp>
#include <rotorcert/reference/metrics.hpp>
#include <rotorcert/reference/rotation_ops.hpp>

namespace rotorcert::testing::abi {

using ref::Real;
template <class S> using Q = impl::Quat<S>;
template <class S> using V = impl::Vec3<S>;
template <class S> using D = impl::DualQuat<S>;

/// eps of S's format (NUM-1), exact.
template <class S> Real eps() {
  return ref::format_epsilon<Real>(std::is_same_v<S, float> ? ref::Format::binary32 : ref::Format::binary64);
}

// ABI arrays -> reference types (exact: Real holds every float and double).
template <class S> ref::Quaternion<Real> rq(const Q<S>& q) { return {Real(q[3]), Real(q[0]), Real(q[1]), Real(q[2])}; }
template <class S> ref::Vec3<Real> rv(const V<S>& v) { return {Real(v[0]), Real(v[1]), Real(v[2])}; }
template <class S> ref::DualQuaternion<Real> rd(const D<S>& d) {
  return {{Real(d[3]), Real(d[0]), Real(d[1]), Real(d[2])}, {Real(d[7]), Real(d[4]), Real(d[5]), Real(d[6])}};
}

inline Real norm3(const ref::Vec3<Real>& v) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
inline ref::Vec3<Real> sub3(const ref::Vec3<Real>& a, const ref::Vec3<Real>& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

/// METRIC-7 (rotation and translation, the larger) in eps units of S.
template <class S> double rigid_err(const D<S>& got, const ref::DualQuaternion<Real>& want) {
  const auto e = ref::clause::METRIC_7_rigid_error(rd(got), want);
  return (std::max(e.rotation, e.translation) / eps<S>()).toDouble();
}
/// |got - want| / scale (METRIC-3 with a clause's own scale) in eps units of S.
template <class S> double vec_err(const V<S>& got, const ref::Vec3<Real>& want, const Real& scale) {
  return (norm3(sub3(rv(got), want)) / scale / eps<S>()).toDouble();
}

/// AXIS-1 by its definition, R(p - c) + c with R the rotation by `angle` about u/|u| (APPLY-1 of
/// the reference): an independent route to AXIS-1's answer, not the reference's AXIS_1 function.
inline ref::Vec3<Real> axis_expected(const ref::Vec3<Real>& c, const ref::Vec3<Real>& u, const Real& angle,
                                     const ref::Vec3<Real>& p) {
  const Real n = norm3(u), h = angle / 2;
  const ref::Quaternion<Real> q{cos(h), sin(h) * u[0] / n, sin(h) * u[1] / n, sin(h) * u[2] / n};
  const ref::Vec3<Real> r = ref::clause::APPLY_1_apply_vector(q, sub3(p, c)).value;
  return {r[0] + c[0], r[1] + c[1], r[2] + c[2]};
}

}  // namespace rotorcert::testing::abi
