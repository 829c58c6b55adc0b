// rotor_simd, per target: the SoA math kernels, lane-wise and with no knowledge of the ABI
// layout (scaling, normalisation, products, atan2, log, exp, the exact hemisphere decision).
#if defined(ROTORCERT_ROTOR_SIMD_KERNELS_INL_H_) == defined(HWY_TARGET_TOGGLE)  // per-target include guard
#ifdef ROTORCERT_ROTOR_SIMD_KERNELS_INL_H_
#undef ROTORCERT_ROTOR_SIMD_KERNELS_INL_H_
#else
#define ROTORCERT_ROTOR_SIMD_KERNELS_INL_H_
#endif

#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "rotor_simd/layout-inl.h"

HWY_BEFORE_NAMESPACE();
namespace rotorcert::rotor_simd::HWY_NAMESPACE {

// ---- 2b. SoA math kernels (lane-wise; no knowledge of the ABI layout) ---------------------

HWY_INLINE Quat scale(const Quat& q, V s) { return {hn::Mul(q.x, s), hn::Mul(q.y, s), hn::Mul(q.z, s), hn::Mul(q.w, s)}; }
HWY_INLINE Vec3 scale(const Vec3& v, V s) { return {hn::Mul(v.x, s), hn::Mul(v.y, s), hn::Mul(v.z, s)}; }
HWY_INLINE Quat negate_if(M m, const Quat& q) {
  return {hn::IfThenElse(m, hn::Neg(q.x), q.x), hn::IfThenElse(m, hn::Neg(q.y), q.y),
          hn::IfThenElse(m, hn::Neg(q.z), q.z), hn::IfThenElse(m, hn::Neg(q.w), q.w)};
}
HWY_INLINE Quat select(M m, const Quat& a, const Quat& b) {
  return {hn::IfThenElse(m, a.x, b.x), hn::IfThenElse(m, a.y, b.y), hn::IfThenElse(m, a.z, b.z),
          hn::IfThenElse(m, a.w, b.w)};
}
HWY_INLINE V dot(const Quat& a, const Quat& b) {
  return hn::MulAdd(a.w, b.w, hn::MulAdd(a.z, b.z, hn::MulAdd(a.y, b.y, hn::Mul(a.x, b.x))));
}
HWY_INLINE V dot(const Vec3& a, const Vec3& b) { return hn::MulAdd(a.z, b.z, hn::MulAdd(a.y, b.y, hn::Mul(a.x, b.x))); }
HWY_INLINE Vec3 cross(const Vec3& a, const Vec3& b) {
  return {hn::MulSub(a.y, b.z, hn::Mul(a.z, b.y)), hn::MulSub(a.z, b.x, hn::Mul(a.x, b.z)),
          hn::MulSub(a.x, b.y, hn::Mul(a.y, b.x))};
}

/// Hamilton product a b (QUAT-1), the quaternion view of Phi(a) Phi(b).
HWY_INLINE Quat hamilton(const Quat& a, const Quat& b) {
  return {hn::MulAdd(a.w, b.x, hn::MulAdd(a.x, b.w, hn::MulSub(a.y, b.z, hn::Mul(a.z, b.y)))),
          hn::MulAdd(a.w, b.y, hn::MulAdd(a.y, b.w, hn::MulSub(a.z, b.x, hn::Mul(a.x, b.z)))),
          hn::MulAdd(a.w, b.z, hn::MulAdd(a.z, b.w, hn::MulSub(a.x, b.y, hn::Mul(a.y, b.x)))),
          hn::MulSub(a.w, b.w, hn::MulAdd(a.x, b.x, hn::MulAdd(a.y, b.y, hn::Mul(a.z, b.z))))};
}

HWY_INLINE M all_finite(const Quat& q) {
  return hn::And(hn::And(hn::IsFinite(q.x), hn::IsFinite(q.y)), hn::And(hn::IsFinite(q.z), hn::IsFinite(q.w)));
}
HWY_INLINE M all_finite(const Vec3& v) { return hn::And(hn::And(hn::IsFinite(v.x), hn::IsFinite(v.y)), hn::IsFinite(v.z)); }
HWY_INLINE V max_abs(const Quat& q) { return hn::Max(hn::Max(hn::Abs(q.x), hn::Abs(q.y)), hn::Max(hn::Abs(q.z), hn::Abs(q.w))); }
HWY_INLINE V max_abs(const Vec3& v) { return hn::Max(hn::Max(hn::Abs(v.x), hn::Abs(v.y)), hn::Abs(v.z)); }

/// A finite nonzero quaternion (EDGE-6, EDGE-7; -0 == +0, subnormals are nonzero).
HWY_INLINE M is_rotation(const Quat& q) { return hn::And(all_finite(q), hn::Gt(max_abs(q), hn::Zero(D()))); }

/// An exact power of two s with s * m in [2^-23, 4) for finite m >= 0, built from m's
/// exponent bits: squares and sums of four such terms neither overflow nor lose a normal
/// input to underflow. (m subnormal: s = 2^127; m in [2^127, 2^128): s = 2^-126.)
HWY_INLINE hn::Vec<DI> pow2_scale_biased_exponent(V m) {
  const DI di;
  const auto e = hn::And(hn::ShiftRight<23>(hn::BitCast(di, m)), hn::Set(di, 0xFF));
  return hn::Max(hn::Sub(hn::Set(di, 254), e), hn::Set(di, 1));
}
HWY_INLINE V pow2_scale(V m) { return hn::BitCast(D(), hn::ShiftLeft<23>(pow2_scale_biased_exponent(m))); }

/// q scaled by a power of two (exact) so that |q|^2 is safe to form; same rotation, same sign
/// of every dot product.
HWY_INLINE Quat safe_scaled(const Quat& q) { return scale(q, pow2_scale(max_abs(q))); }

/// x / |x| of a safely scaled quaternion: one division, then products.
HWY_INLINE Quat unit_of_scaled(const Quat& qs) {
  const D d;
  Quat u = scale(qs, hn::Div(hn::Set(d, 1.0f), hn::Sqrt(dot(qs, qs))));
  // A pure scalar (0, 0, 0, w) is exactly (0, 0, 0, +-1): w * (1 / sqrt(w^2)) is not always 1
  // (nlerp of the identity with itself extrapolated to t = 1.15 gave 1 - 2^-24: EDGE-1).
  const V zero = hn::Zero(d);
  const M scalar_only = hn::And(hn::And(hn::And(hn::Eq(qs.x, zero), hn::Eq(qs.y, zero)), hn::Eq(qs.z, zero)),
                                hn::And(hn::IsFinite(qs.w), hn::Ne(qs.w, zero)));  // 0 and NaN stay NaN
  u.w = hn::IfThenElse(scalar_only, hn::CopySign(hn::Set(d, 1.0f), qs.w), u.w);
  return u;
}

/// 1/sqrt(x) for x in [2^-60, 2^60] to about 2 ulp, for the normalisations inside slerp, nlerp
/// and QLB (whose bars are eps16 / eps32; NORM-1 itself keeps the exactly rounded sqrt and
/// division): the hardware estimate (relative error <= 1.5 * 2^-12 on SSE/AVX2, 2^-14 on AVX-512)
/// and one Newton step y (3 - x y^2) / 2, whose error is 1.5 e^2 + rounding <= ~2 ulp.
/// Targets without a hardware estimate (SCALAR, EMU128) divide.
HWY_INLINE V rsqrt(V x) {
#if HWY_TARGET == HWY_SCALAR || HWY_TARGET == HWY_EMU128
  return hn::Div(hn::Set(D(), 1.0f), hn::Sqrt(x));
#else
  const D d;
  const V one = hn::Set(d, 1.0f);
  const V y = hn::ApproximateReciprocalSqrt(x);
  const V r = hn::Mul(hn::Mul(y, hn::Set(d, 0.5f)), hn::NegMulAdd(x, hn::Mul(y, y), hn::Set(d, 3.0f)));
  return hn::IfThenElse(hn::Eq(x, one), one, r);  // exact for unit input: identity in, identity out (EDGE-1)
#endif
}
/// q/|q| through rsqrt; a pure scalar (x = y = z = 0) comes out as exactly (0, 0, 0, +-1), which
/// rsqrt alone guarantees only when |q| is exactly 1 (a weighted sum of identities is not: EDGE-1).
HWY_INLINE Quat fast_unit_of_scaled(const Quat& qs) {
  const D d;
  Quat u = scale(qs, rsqrt(dot(qs, qs)));
  const V zero = hn::Zero(d);
  const M scalar_only = hn::And(hn::And(hn::And(hn::Eq(qs.x, zero), hn::Eq(qs.y, zero)), hn::Eq(qs.z, zero)),
                                hn::And(hn::IsFinite(qs.w), hn::Ne(qs.w, zero)));  // 0 and NaN stay NaN
  u.w = hn::IfThenElse(scalar_only, hn::CopySign(hn::Set(d, 1.0f), qs.w), u.w);
  return u;
}

/// NORM-1 kernel: q/|q| for any finite nonzero q.
HWY_INLINE Quat normalized(const Quat& q) { return unit_of_scaled(safe_scaled(q)); }

/// Calls f(l) for every lane l set in `mask`: the scalar fallbacks (exact signs, binary64 paths)
/// of the few lanes a kernel cannot settle in SIMD. Free when no lane is set.
template <class F>
HWY_INLINE void for_each_set_lane(M mask, F f) {
  const D d;
  if (HWY_LIKELY(hn::AllFalse(d, mask))) return;
  std::uint8_t bits[kMaxLanes / 8] = {};
  hn::StoreMaskBits(d, mask, bits);
  for (std::size_t l = 0; l < hn::Lanes(d); ++l)
    if ((bits[l >> 3] >> (l & 7)) & 1) f(l);
}

/// Lanes where the exact dot product a.b of the inputs is < 0 (the hemisphere rule, strict).
/// as, bs: the inputs scaled by powers of two (no overflow in the float dot); a, b: the
/// inputs as given (for the exact path). The float dot decides when it is farther from 0
/// than its error bound 4u sum|a_i b_i| (times 4 for margin, plus an allowance for products
/// in the subnormal range); otherwise the lane's sign is computed exactly. The exact path runs
/// only for (near-)ties, e.g. half-turn pairs with dot = 0 exactly.
HWY_INLINE M dot_negative(const Quat& as, const Quat& bs, const Quat& a, const Quat& b) {
  const D d;
  const V dt = dot(as, bs);
  const V mag = hn::MulAdd(hn::Abs(hn::Mul(as.w, bs.w)), hn::Set(d, 1.0f),
                           hn::Add(hn::Add(hn::Abs(hn::Mul(as.x, bs.x)), hn::Abs(hn::Mul(as.y, bs.y))),
                                   hn::Abs(hn::Mul(as.z, bs.z))));
  const V bound = hn::MulAdd(mag, hn::Set(d, 0x1p-20f), hn::Set(d, 0x1p-126f));
  M neg = hn::Lt(dt, hn::Zero(d));
  const M unsure = hn::Le(hn::Abs(dt), bound);
  if (HWY_UNLIKELY(!hn::AllFalse(d, unsure))) {
    HWY_ALIGN float ra[4 * kMaxLanes], rb[4 * kMaxLanes], flag[kMaxLanes];
    store_quat(a, ra);
    store_quat(b, rb);
    hn::Store(hn::IfThenElse(neg, hn::Set(d, -1.0f), hn::Set(d, 1.0f)), d, flag);
    for_each_set_lane(unsure, [&](std::size_t l) {
      flag[l] = exact_dot_sign(ra + 4 * l, rb + 4 * l) < 0 ? -1.0f : 1.0f;
    });
    neg = hn::Lt(hn::Load(d, flag), hn::Zero(d));
  }
  return neg;
}

/// atan2(y, x) for y >= 0 (any x, not both 0), in [0, pi]: Highway's Atan (3 ulp) on the
/// ratio min/max in [0, 1], then the octant fix-ups. Highway 1.0.3 has no Atan2.
HWY_INLINE V atan2_nonneg_y(V y, V x) {
  const D d;
  const V ax = hn::Abs(x);
  const M swap = hn::Gt(y, ax);
  const V num = hn::IfThenElse(swap, ax, y), den = hn::IfThenElse(swap, y, ax);
  V a = hn::Atan(d, hn::Div(num, den));
  a = hn::IfThenElse(swap, hn::Sub(hn::Set(d, 1.57079632679489661923f), a), a);
  return hn::IfThenElse(hn::Lt(x, hn::Zero(d)), hn::Sub(hn::Set(d, 3.14159265358979323846f), a), a);
}

/// LOG-1 / LOG-2 of a unit quaternion u (quaternion view, [x, y, z] = (theta/2) axis):
/// atan2(|v|, w) v/|v| with |v| scaled safely (subnormal v keeps its direction); log(1) = 0
/// exactly, and v = 0 with w < 0 gives (0, 0, pi).
HWY_INLINE Vec3 log_unit(const Quat& u) {
  const D d;
  const Vec3 v{u.x, u.y, u.z};
  const V s = pow2_scale(max_abs(v));
  const Vec3 vs = scale(v, s);
  const V n = hn::Sqrt(dot(vs, vs));            // |v| s
  const V angle = atan2_nonneg_y(n, hn::Mul(u.w, s));  // atan2 is scale-free
  const M zero = hn::Eq(n, hn::Zero(d));
  const V f = hn::Div(angle, hn::IfThenElse(zero, hn::Set(d, 1.0f), n));
  Vec3 r = scale(vs, hn::IfThenZeroElse(zero, f));
  const M cut = hn::And(zero, hn::Lt(u.w, hn::Zero(d)));
  r.x = hn::IfThenZeroElse(zero, r.x);
  r.y = hn::IfThenZeroElse(zero, r.y);
  r.z = hn::IfThenElse(cut, hn::Set(d, 3.14159265358979323846f), hn::IfThenZeroElse(zero, r.z));
  return r;
}

/// INV-1: q* / |q|^2 for finite nonzero q, from qs = q s (s the exact power of two of
/// safe_scaled): q^-1 = (qs* / |qs|^2) s, the factor s last, so that only an inverse that itself
/// leaves the format overflows or underflows.
HWY_INLINE Quat inverse(const Quat& q) {
  const V s = pow2_scale(max_abs(q));
  const Quat qs = scale(q, s);
  const V n2 = dot(qs, qs);
  return {hn::Mul(hn::Div(hn::Neg(qs.x), n2), s), hn::Mul(hn::Div(hn::Neg(qs.y), n2), s),
          hn::Mul(hn::Div(hn::Neg(qs.z), n2), s), hn::Mul(hn::Div(qs.w, n2), s)};
}

/// AXANG-1 of a finite nonzero q: angle = 2 atan2(|v|, w) in [0, 2 pi] (scale-free: q need not be
/// unit), axis = v/|v|, from v rescaled by its own power of two (a subnormal v beside w = -1 keeps
/// its axis, EDGE-8). v = 0: the axis +z, the angle 0 (w > 0) or 2 pi (w < 0). Where w times v's
/// scale overflows (|v| below 2^-126 |w|), atan2(|v|, +-inf) gives 0 or pi, within 2^-125 of the
/// exact half angle.
HWY_INLINE void axis_angle(const Quat& q, V& angle, Vec3& axis) {
  const D d;
  // v's own scale, not q's: scaled by q's largest component (w) a v of 2^-130 |w| would go
  // subnormal and lose its direction's bits.
  const Vec3 v{q.x, q.y, q.z};
  const V s = pow2_scale(max_abs(v));
  const Vec3 vs = scale(v, s);
  const V n = hn::Sqrt(dot(vs, vs));
  angle = hn::Mul(hn::Set(d, 2.0f), atan2_nonneg_y(n, hn::Mul(q.w, s)));
  const M zero = hn::Eq(n, hn::Zero(d));
  const V nn = hn::IfThenElse(zero, hn::Set(d, 1.0f), n);
  axis = {hn::IfThenZeroElse(zero, hn::Div(vs.x, nn)), hn::IfThenZeroElse(zero, hn::Div(vs.y, nn)),
          hn::IfThenElse(zero, hn::Set(d, 1.0f), hn::Div(vs.z, nn))};
}

/// AXANG-2 for finite angle and finite nonzero axis: (sin(angle/2) u, cos(angle/2)) with
/// u = axis/|axis| (axis rescaled first); angle 0 gives the identity exactly (EDGE-1). Accurate
/// for |angle| <= 16; callers route larger angles to from_axis_angle_double.
HWY_INLINE Quat from_axis_angle(V angle, const Vec3& axis) {
  const D d;
  const Vec3 as = scale(axis, pow2_scale(max_abs(axis)));
  const V inv = hn::Div(hn::Set(d, 1.0f), hn::Sqrt(dot(as, as)));
  const V h = hn::Mul(angle, hn::Set(d, 0.5f));
  const V k = hn::Mul(hn::Sin(d, h), inv);
  const V c = hn::IfThenElse(hn::Eq(h, hn::Zero(d)), hn::Set(d, 1.0f), hn::Cos(d, h));
  return {hn::Mul(k, as.x), hn::Mul(k, as.y), hn::Mul(k, as.z), c};
}

/// EXP-1 of a bivector in the quaternion view: (cos|v|, sin|v| v/|v|), renormalised (the two
/// polynomials' errors would otherwise show in the norm); exp(0) = 1 exactly. Accurate for
/// |v| <= 8; callers route larger |v| to exp_double.
HWY_INLINE Quat exp_small(const Vec3& v, V* theta_out = nullptr) {
  const D d;
  const V s = pow2_scale(max_abs(v));
  const Vec3 vs = scale(v, s);
  const V ns = hn::Sqrt(dot(vs, vs));  // |v| s
  const V theta = hn::Div(ns, s);
  if (theta_out) *theta_out = theta;
  const M zero = hn::Eq(ns, hn::Zero(d));
  const V k = hn::IfThenZeroElse(zero, hn::Div(hn::Sin(d, theta), hn::IfThenElse(zero, hn::Set(d, 1.0f), ns)));
  Quat r{hn::Mul(vs.x, k), hn::Mul(vs.y, k), hn::Mul(vs.z, k),
         hn::IfThenElse(zero, hn::Set(d, 1.0f), hn::Cos(d, theta))};
  return unit_of_scaled(r);
}

}  // namespace rotorcert::rotor_simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // ROTORCERT_ROTOR_SIMD_KERNELS_INL_H_
