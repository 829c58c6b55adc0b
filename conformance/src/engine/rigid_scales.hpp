// The length scales of the rigid ops' point measures (AbiOp::scale) whose formulas are more than
// a max of input lengths, as templates: the judge evaluates them on mpfr::mpreal, the fast oracle
// on ref::Bounded (fast_oracle.cpp), one formula at both levels.
#pragma once

#include <algorithm>
#include <type_traits>

#include <rotorcert/reference/bounded.hpp>
#include <rotorcert/reference/rigid_ops.hpp>

namespace rotorcert::engine::rigid_scales {

/// max(a, b). On Bounded, the 1-Lipschitz max of the intervals (no comparison to decide).
template <class T>
T largest(const T& a, const T& b) {
  if constexpr (std::is_same_v<T, ref::Bounded>) return ref::max(a, b);
  else return std::max(a, b);
}

template <class T>
T length(const ref::Vec3<T>& v) {
  using std::sqrt;
  return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

/// DQ-7: max(1, |t|) of the translation that sigma stands for (1 for a non-finite or zero-real
/// sigma, which is a DOMAIN_ERROR).
template <class T>
T dq_translation_scale(const ref::DualQuaternion<T>& sigma) {
  if (!ref::finite(sigma) || ref::is_zero(sigma.real)) return T(1);
  return largest(T(1), length(ref::clause::dual_quaternion_translation(sigma)));
}

/// DQ-8's error scale: max(1, |xi_ref|, kappa |d_v|) with kappa = b / sin b, (r, d) = DQ-4(sigma),
/// b = atan2(|r_v|, r_w). xi_d holds (b / sin b) d_perp, so an error of eps |d_v| in the dual part
/// (the rounding of the input itself) becomes kappa eps |d_v|: the log's own condition near the
/// branch cut b = pi, where no implementation in the format can do better. kappa = 1 at the cut
/// itself (sin b = 0: the spec's choice of axis, no amplification).
template <class T>
T dq_log_scale(const ref::DualQuaternion<T>& sigma) {
  using std::atan2;
  if (!ref::finite(sigma) || ref::is_zero(sigma.real)) return T(1);
  const ref::DualQuaternion<T> u = ref::clause::DQ_4_normalize(sigma).value;
  const auto xi = ref::clause::DQ_8_log(sigma).value;
  const T s = length(ref::Vec3<T>{u.real.x, u.real.y, u.real.z});
  const T kappa = s == 0 ? T(1) : largest(T(1), T(atan2(s, u.real.w) / s));
  return largest(largest(T(1), T(length(xi.real) + length(xi.dual))),
                 T(kappa * length(ref::Vec3<T>{u.dual.x, u.dual.y, u.dual.z})));
}

}  // namespace rotorcert::engine::rigid_scales
