// The paper's printed forms (ERRATUM-1 ... ERRATUM-5), implemented exactly as printed so that
// the tests can show, as executable facts, what each one computes and which clause it breaks.
//
// Source: /work/shared/paper/ga-rotors-skinning-2013.txt (Section 4.1 Step 1, Table 1,
// Appendix A MATLAB, Appendix B C++). Nothing here is a reference for a clause: these are the
// counterexamples. Blades are built from the printed outer products (e2^e3, -e1^e3, e1^e2),
// not from the spec's named blades, so that a sign slip in the transcription cannot hide
// behind cl3.hpp's e31 = -e13 bookkeeping.
#pragma once

#include "cl3.hpp"
#include "metrics.hpp"
#include "multivector.hpp"
#include "quaternion.hpp"
#include "result.hpp"
#include "rotation_ops.hpp"
#include "scalar.hpp"

namespace rotorcert::ref::paper {

namespace detail {

template <class T> cl3::MV<T> e(int k) { return cl3::MV<T>::vector(k - 1); }  // e(1) = e1, ...

template <class T>
cl3::MV<T> all_nan() {
  cl3::MV<T> m;
  for (T& c : m.c) c = ScalarTraits<T>::nan();
  return m;
}

/// libgasandbox's unit_e: X / sqrt(X * ~X) with * the scalar product (Euclidean norm).
template <class T>
cl3::MV<T> unit_e(const cl3::MV<T>& x) {
  using std::sqrt;
  return x / sqrt(scp(x, reverse(x)));
}

}  // namespace detail

/// ERRATUM-1 (Section 4.1, Step 1): i = e2^e3, j = -e1^e3, k = e1^e2 as printed. Their
/// product i j k is +1 (and i j = -k): not Hamilton's ijk = -1. The fix is Q2R-1.
template <class T>
cl3::MV<T> ERRATUM_1_ijk_product() {
  using detail::e;
  const cl3::MV<T> i = op(e<T>(2), e<T>(3));
  const cl3::MV<T> j = -op(e<T>(1), e<T>(3));
  const cl3::MV<T> k = op(e<T>(1), e<T>(2));
  return gp(gp(i, j), k);
}

/// ERRATUM-2 (Table 1, Appendix A): Method 2 as printed,
///   Rsrc = srcQ.e(1) + srcQ.e(2)*(e2^e3) - srcQ.e(3)*(e1^e3) + srcQ.e(4)*(e1^e2)
/// with MATLAB's e(1..4) = w, x, y, z: R = w + x e23 + y e31 + z e12 = ~Phi(q), the reverse
/// rotor. Applied to q as given (the paper normalises srcQ on the line before).
template <class T>
cl3::MV<T> ERRATUM_2_method2_as_printed(const Quaternion<T>& q) {
  using detail::e;
  return cl3::MV<T>(q.w) + q.x * op(e<T>(2), e<T>(3)) - q.y * op(e<T>(1), e<T>(3)) + q.z * op(e<T>(1), e<T>(2));
}

/// ERRATUM-4 (Appendix B, commented alternative):
///   e3ga::rotor(rotor_scalar_e1e2_e2e3_e3e1, w, z, x, -y) = w + z e12 + x e23 - y e31.
/// Applied to q as given (the paper normalises srcQ first).
template <class T>
cl3::MV<T> ERRATUM_4_alternative_rotor_as_printed(const Quaternion<T>& q) {
  using detail::e;
  const cl3::MV<T> e12 = op(e<T>(1), e<T>(2)), e23 = op(e<T>(2), e<T>(3)), e31 = op(e<T>(3), e<T>(1));
  return cl3::MV<T>(q.w) + q.z * e12 + q.x * e23 + (-q.y) * e31;
}

/// ERRATUM-5 (Appendix B): srcQ = normalize(q); angle = glm::angle(srcQ) (radians since GLM
/// 0.9.6: AXANG-1's angle), axis = glm::axis(srcQ) (AXANG-1's axis), u = unit_e(axis), then
///   exp(bivector(glm::radians(angle)/2 * (-I3 * u)))
/// which multiplies the angle by pi/180 a second time: the rotor rotates by theta*pi/180.
/// Zero or non-finite q: all-NaN.
template <class T>
cl3::MV<T> ERRATUM_5_method1_as_printed(const Quaternion<T>& q) {
  const auto aa = clause::AXANG_1_to_axis_angle(q);
  if (aa.status != Status::ok) return detail::all_nan<T>();
  const T radians_of_angle = aa.value.angle * ScalarTraits<T>::pi() / T(180);  // glm::radians
  const cl3::MV<T> u = detail::unit_e(cl3::vector(aa.value.axis));
  const cl3::MV<T> b = grade((radians_of_angle / T(2)) * gp(-cl3::I<T>(), u), 2);  // bivector(...)
  return cl3::exp_bivector(cl3::bivector_part(b));
}

/// ERRATUM-3 (Appendix B interpolateGA, Appendix A Table 2), with the angle-unit slip of
/// ERRATUM-5 corrected so that this shows only the interpolation's own error:
///   srcMV = unit_e(w + x e1 + y e2 + z e3)             (scalar + VECTOR, not a rotor)
///   Rsrc  = exp(-I3 u_src theta_src/2), Rdest likewise  (Method 1, correct radians: AXANG-1)
///   Rtot  = Rdest * inverse(Rsrc)
///   Ri    = exp(Factor/2 * log(Rtot))                  (principal rotor log)
///   RintQ = Ri * srcMV * inverse(Ri)
///   Out   = (scalar, e1, e2, e3) of RintQ.
/// The sandwich leaves the scalar part alone: Out.w = w_src for every Factor. Non-finite or
/// zero input, non-finite factor: all-NaN.
template <class T>
Quaternion<T> ERRATUM_3_interpolation_as_printed(const Quaternion<T>& src, const Quaternion<T>& dst, const T& factor) {
  if (!finite(src) || !finite(dst) || is_zero(src) || is_zero(dst) || !finite(factor)) {
    Quaternion<T> bad;
    poison(bad);
    return bad;
  }
  using detail::e;
  const Quaternion<T> s = normalized(src), d = normalized(dst);
  const cl3::MV<T> src_mv = detail::unit_e(cl3::MV<T>(s.w) + s.x * e<T>(1) + s.y * e<T>(2) + s.z * e<T>(3));
  const auto as = clause::AXANG_1_to_axis_angle(s), ad = clause::AXANG_1_to_axis_angle(d);
  const cl3::MV<T> r_src = clause::Q2R_4_method1(as.value.angle, as.value.axis).value;
  const cl3::MV<T> r_dest = clause::Q2R_4_method1(ad.value.angle, ad.value.axis).value;
  const cl3::MV<T> r_tot = gp(r_dest, clause::detail::versor_inverse(r_src));
  const cl3::MV<T> r_i = clause::detail::exp((factor / T(2)) * clause::detail::log(r_tot));
  const cl3::MV<T> r_int = gp(gp(r_i, src_mv), clause::detail::versor_inverse(r_i));
  return {r_int.c[0], r_int.c[cl3::kE1], r_int.c[cl3::kE2], r_int.c[cl3::kE3]};
}

}  // namespace rotorcert::ref::paper
