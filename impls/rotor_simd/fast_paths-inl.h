// rotor_simd, per target: the fast paths of slerp, nlerp and QLB (k = 4) for whole blocks of
// ordinary lanes; a block with any other lane goes to the general kernels.
#if defined(ROTORCERT_ROTOR_SIMD_FAST_PATHS_INL_H_) == defined(HWY_TARGET_TOGGLE)  // per-target include guard
#ifdef ROTORCERT_ROTOR_SIMD_FAST_PATHS_INL_H_
#undef ROTORCERT_ROTOR_SIMD_FAST_PATHS_INL_H_
#else
#define ROTORCERT_ROTOR_SIMD_FAST_PATHS_INL_H_
#endif

#include <hwy/highway.h>

#include "rotor_simd/kernels-inl.h"

HWY_BEFORE_NAMESPACE();
namespace rotorcert::rotor_simd::HWY_NAMESPACE {

// ---- 2b'. fast paths: whole blocks of ordinary lanes ---------------------------------------
//
// A fast path computes a block in the lane order of section 2a' without writing anything and
// returns its result with a mask of the lanes that are ordinary; the batch loop (fast_blocks)
// stores the block if ALL lanes are (one mask test per block), else the general kernel (2c)
// redoes the whole block. Ordinary lanes: every quaternion unit to within 2^-12 in
// |q|^2 (any unit quaternion rounded to binary32, by a wide margin), hemisphere dots clearly
// away from 0, t in [0, 1], blend weights >= 0 with the pivot first. Zero, non-finite, tiny or
// huge inputs and negative weights all fail the test, so every edge outcome (EDGE-5..9), every
// exact-sign tie (EDGE-3) and all extrapolation (SLERP-4) stay with the general kernels.

constexpr float kUnitLo = 1.0f - 0x1p-12f, kUnitHi = 1.0f + 0x1p-12f;
/// |a.b| above this is 8 times the float dot's error bound (4u |a| |b|, |a|, |b| ~ 1): its
/// sign is the exact sign, no exact_dot_sign needed.
constexpr float kSureSign = 0x1p-19f;

/// lo <= x <= hi (0 <= lo < hi; NaN is outside). On AVX-512, where unsigned compares are native,
/// as one compare of bit patterns: nonnegative floats order like their bits, and NaN, negative
/// values and -0 wrap around to large differences (-0 then fails, which only costs a block its
/// fast path).
HWY_INLINE M in_range(V x, float lo, float hi) {
#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX3
  const hn::RebindToUnsigned<D> du;
  const auto bits = [](float f) { return std::bit_cast<std::uint32_t>(f); };
  // Highway 1.0.3 has only Gt for unsigned lanes: diff <= hi - lo as hi - lo + 1 > diff.
  return hn::RebindMask(D(), hn::Gt(hn::Set(du, bits(hi) - bits(lo) + 1), hn::Sub(hn::BitCast(du, x), hn::Set(du, bits(lo)))));
#else
  return hn::And(hn::Ge(x, hn::Set(D(), lo)), hn::Le(x, hn::Set(D(), hi)));
#endif
}
HWY_INLINE M near_unit(V n2) { return in_range(n2, kUnitLo, kUnitHi); }

/// 1/sqrt(n2) for n2 within 2^-12 of 1: 1 - (n2 - 1)/2. The next term, 3/8 (n2 - 1)^2 <=
/// 2^-25.4, is below half an ulp; exact (1) for n2 = 1, so identities stay exact (EDGE-1).
HWY_INLINE V inv_norm_near_unit(V n2) { return hn::NegMulAdd(hn::Set(D(), 0.5f), n2, hn::Set(D(), 1.5f)); }

/// A block computed by a fast path: valid iff AllTrue(ordinary).
struct FastBlock {
  Quat q;
  M ordinary;
};
HWY_INLINE void store_fast(const FastBlock& r, float* o, std::uint8_t* s) {
  store_quat_blocked(r.q, o);
  std::memset(s, RC_OK, hn::Lanes(D()));
}

/// sin(s phi) / sin(phi) for s0 and s1 as polynomials in y = cos(phi) - 1 (Eberly 2011): the
/// series sum_i c_i(s) y^i with c_0 = s, c_i = c_(i-1) (s^2 - i^2) / (i (2i + 1)), i.e. the
/// nested form s p_1 with p_i = 1 + u_i (s^2 - i^2) y p_(i+1), u_i = 1 / (i (2i + 1)),
/// p_(n+1) = 1. Evaluated as P_i = U_i p_i with U_i = u_1 .. u_(i-1) (compile-time constants
/// from that recurrence), P_i = U_i + (s^2 y - i^2 y) P_(i+1), P_1 = p_1, two terms per step.
/// Used with phi <= pi/4 (y >= -0.293) and s in [0, 2], where kTerms = 7 leaves the
/// truncation below the rounding: the whole fast slerp, simulated in binary32 on 2e6 inputs
/// (Omega up to pi/2), errs by at most ~3.1 eps in METRIC-1 (6 terms: 5.2 eps; measured on
/// the tests' inputs: <= 2 eps). Without the angle halving (phi = Omega <= pi/2) even 14 terms
/// would not do: Eberly's own revised bound for 8 terms is 2.6e-5.
constexpr double sin_ratio_u_product(int i) {  // U_i
  double u = 1;
  for (int j = 1; j < i; ++j) u /= j * (2.0 * j + 1);
  return u;
}
template <int kI, int kN>
HWY_INLINE void sin_ratio_tail(V a0, V a1, V y, V& p0, V& p1) {  // P_kI for both s
  const D d;
  const V u = hn::Set(d, static_cast<float>(sin_ratio_u_product(kI)));
  const V i2 = hn::Set(d, static_cast<float>(kI * kI));
  const V b0 = hn::NegMulAdd(i2, y, a0), b1 = hn::NegMulAdd(i2, y, a1);  // s^2 y - i^2 y
  if constexpr (kI == kN) {
    const V un = hn::Set(d, static_cast<float>(sin_ratio_u_product(kN + 1)));
    p0 = hn::MulAdd(b0, un, u);
    p1 = hn::MulAdd(b1, un, u);
  } else {
    // P_i = (U_i + b_i U_(i+1)) + (b_i b_(i+1)) P_(i+2): half the dependency chain of Horner's
    // rule for one more operation per pair (a few % faster, measured).
    const V u1 = hn::Set(d, static_cast<float>(sin_ratio_u_product(kI + 1)));
    const V j2 = hn::Set(d, static_cast<float>((kI + 1) * (kI + 1)));
    const V c0 = hn::NegMulAdd(j2, y, a0), c1 = hn::NegMulAdd(j2, y, a1);
    V q0 = hn::Set(d, static_cast<float>(sin_ratio_u_product(kN + 1))), q1 = q0;
    if constexpr (kI + 1 < kN) sin_ratio_tail<kI + 2, kN>(a0, a1, y, q0, q1);
    p0 = hn::MulAdd(hn::Mul(b0, c0), q0, hn::MulAdd(b0, u1, u));
    p1 = hn::MulAdd(hn::Mul(b1, c1), q1, hn::MulAdd(b1, u1, u));
  }
}
template <int kTerms>
HWY_INLINE void sin_ratio2(V s0, V s1, V y, V& f0, V& f1) {
  const V a0 = hn::Mul(hn::Mul(s0, s0), y), a1 = hn::Mul(hn::Mul(s1, s1), y);  // s^2 y
  V p0, p1;
  sin_ratio_tail<1, kTerms>(a0, a1, y, p0, p1);
  f0 = hn::Mul(s0, p0);
  f1 = hn::Mul(s1, p1);
}

/// SLERP-1 fast path: the general kernel's formula without atan and sin (Highway's cost
/// 30-40 cycles per vector each): sin((1-t) Omega) a + sin(t Omega) b' with the sine ratios
/// f(t, Omega) = sin(t Omega) / sin(Omega) from the polynomial above: directly when every
/// Omega of the block is <= pi/4, else after halving the angle, f(t, Omega) = f(2t, Omega/2) /
/// (2 cos(Omega/2)), cos(Omega/2) = sqrt((1 + cos Omega) / 2).
HWY_INLINE FastBlock slerp_fast(const float* pa, const float* pb, const float* pt) {
  const D d;
  const Quat a = load_quat_blocked(pa), b = load_quat_blocked(pb);
  const V t = load_scalar_blocked(pt);
  const V na = dot(a, a), nb = dot(b, b), ab = dot(a, b);
  const M ordinary = hn::And(hn::And(near_unit(na), near_unit(nb)),
                             hn::And(in_range(t, 0.0f, 1.0f), hn::Gt(hn::Abs(ab), hn::Set(d, kSureSign))));
  const V ra = inv_norm_near_unit(na), rb = inv_norm_near_unit(nb);
  const V cos_omega = hn::Mul(hn::Abs(ab), hn::Mul(ra, rb));  // Omega in [0, pi/2] after the flip
  V fa, fb, k;
  if (hn::AllTrue(d, hn::Ge(cos_omega, hn::Set(d, 0.7072f)))) {
    // Every Omega <= pi/4 (keyframe neighbours): the series in cos(Omega) - 1 (exact, Sterbenz)
    // converges fast enough without halving; 6 terms (simulated: <= 3.3 eps, the rounding floor).
    sin_ratio2<6>(hn::Sub(hn::Set(d, 1.0f), t), t, hn::Sub(cos_omega, hn::Set(d, 1.0f)), fa, fb);
    k = hn::Set(d, 1.0f);
  } else {
    const V h = hn::MulAdd(cos_omega, hn::Set(d, 0.5f), hn::Set(d, 0.5f));  // cos^2(Omega/2)
    const V inv_c = rsqrt(h);                                              // 1 / cos(Omega/2); 1 for h = 1
    const V y = hn::MulSub(h, inv_c, hn::Set(d, 1.0f));                     // cos(Omega/2) - 1, one rounding
    sin_ratio2<7>(hn::NegMulAdd(hn::Set(d, 2.0f), t, hn::Set(d, 2.0f)), hn::Add(t, t), y, fa, fb);
    // The common factor 1 / (2 cos(Omega/2)) keeps r unit up to rounding, so that one
    // first-order step normalises it (and a = b' = 1 gives exactly 1: EDGE-1).
    k = hn::Mul(inv_c, hn::Set(d, 0.5f));
  }
  const V ca = hn::Mul(hn::Mul(fa, ra), k);
  const V cb = hn::CopySign(hn::Mul(hn::Mul(fb, rb), k), ab);  // b' = -b iff a.b < 0
  const Quat r{hn::MulAdd(ca, a.x, hn::Mul(cb, b.x)), hn::MulAdd(ca, a.y, hn::Mul(cb, b.y)),
               hn::MulAdd(ca, a.z, hn::Mul(cb, b.z)), hn::MulAdd(ca, a.w, hn::Mul(cb, b.w))};
  return {scale(r, inv_norm_near_unit(dot(r, r))), ordinary};
}

/// NLERP-1 fast path: normalize((1 - t) a + t b') of the normalised inputs, t in [0, 1]; the sum
/// has norm >= cos(Omega/2) >= 1/sqrt(2), inside rsqrt's range.
HWY_INLINE FastBlock nlerp_fast(const float* pa, const float* pb, const float* pt) {
  const D d;
  const Quat a = load_quat_blocked(pa), b = load_quat_blocked(pb);
  const V t = load_scalar_blocked(pt);
  const V na = dot(a, a), nb = dot(b, b), ab = dot(a, b);
  const M ordinary = hn::And(hn::And(near_unit(na), near_unit(nb)),
                             hn::And(in_range(t, 0.0f, 1.0f), hn::Gt(hn::Abs(ab), hn::Set(d, kSureSign))));
  const V ca = hn::Mul(hn::Sub(hn::Set(d, 1.0f), t), inv_norm_near_unit(na));
  const V cb = hn::CopySign(hn::Mul(t, inv_norm_near_unit(nb)), ab);  // b' = -b iff a.b < 0
  const Quat r{hn::MulAdd(ca, a.x, hn::Mul(cb, b.x)), hn::MulAdd(ca, a.y, hn::Mul(cb, b.y)),
               hn::MulAdd(ca, a.z, hn::Mul(cb, b.z)), hn::MulAdd(ca, a.w, hn::Mul(cb, b.w))};
  // a = b' = 1: r = (1 - t) + t rounds to exactly 1 for t in [0, 1], and rsqrt(1) = 1 (EDGE-1).
  return {scale(r, rsqrt(dot(r, r))), ordinary};
}

/// QLB-1 fast path for k = 4 when influence 0 is the pivot (w_0 > 0). Non-finite inputs need
/// no test of their own: they make the sum non-finite, which its norm test rejects.
HWY_INLINE FastBlock qlb4_fast(const float* bq, const float* bw) {
  const D d;
  Quat q0, q1, q2, q3;
  V w0, w1, w2, w3;
  load_blend4_blocked(bq, bw, q0, q1, q2, q3, w0, w1, w2, w3);
  V n2 = dot(q0, q0);
  V lo = n2, hi = n2, wmin = w0, dmin = hn::Set(d, 1.0f);
  Quat sum = scale(q0, hn::Mul(w0, inv_norm_near_unit(n2)));
  const auto add = [&](const Quat& qj, V wj) {
    n2 = dot(qj, qj);
    lo = hn::Min(lo, n2);
    hi = hn::Max(hi, n2);
    wmin = hn::Min(wmin, wj);
    const V dj = dot(qj, q0);  // s_j = -1 iff q_j . q_0 < 0
    dmin = hn::Min(dmin, hn::Abs(dj));
    const V c = hn::CopySign(hn::Mul(wj, inv_norm_near_unit(n2)), dj);
    sum = {hn::MulAdd(c, qj.x, sum.x), hn::MulAdd(c, qj.y, sum.y), hn::MulAdd(c, qj.z, sum.z), hn::MulAdd(c, qj.w, sum.w)};
  };
  add(q1, w1);
  add(q2, w2);
  add(q3, w3);
  const V v2 = hn::MulAdd(sum.z, sum.z, hn::MulAdd(sum.y, sum.y, hn::Mul(sum.x, sum.x)));
  const V s2 = hn::MulAdd(sum.w, sum.w, v2);
  const M ordinary = hn::And(hn::And(hn::And(hn::Ge(lo, hn::Set(d, kUnitLo)), hn::Le(hi, hn::Set(d, kUnitHi))),
                                     hn::And(hn::Ge(wmin, hn::Zero(d)), hn::Gt(w0, hn::Zero(d)))),
                             hn::And(hn::Gt(dmin, hn::Set(d, kSureSign)),
                                     hn::And(hn::Ge(s2, hn::Set(d, 0x1p-100f)), hn::Le(s2, hn::Set(d, 0x1p100f)))));
  Quat u = scale(sum, rsqrt(s2));
  // A weighted sum of identities is (0, 0, 0, W): exactly +-1 out (EDGE-1).
  u.w = hn::IfThenElse(hn::Eq(v2, hn::Zero(d)), hn::CopySign(hn::Set(d, 1.0f), sum.w), u.w);
  return {u, ordinary};
}

/// The batch loop of a fast path over the full blocks of n elements: fast(i) computes the block
/// at element i, general(i) is the general kernel for it. kPerStep = 2 computes two blocks
/// before storing either: two independent dependency chains in one basic block overlap better
/// (a few % for slerp and nlerp, measured). `fast` must be inlined for that, hence the
/// ROTORCERT_SIMD_INLINE on its lambdas. Returns the number of elements done (a multiple of N;
/// the caller does the tail).
template <int kPerStep, class Fast, class General>
HWY_INLINE std::size_t fast_blocks(std::size_t n, float* out, std::uint8_t* status, const Fast& fast,
                                   const General& general) {
  const D d;
  const std::size_t lanes = hn::Lanes(d);
  const auto finish = [&](const FastBlock& r, std::size_t i) {
    if (HWY_LIKELY(hn::AllTrue(d, r.ordinary))) {
      store_fast(r, out + 4 * i, status + i);
    } else {
      general(i);
    }
  };
  std::size_t i = 0;
  if constexpr (kPerStep == 2) {
    for (; i + 2 * lanes <= n; i += 2 * lanes) {
      const FastBlock r0 = fast(i), r1 = fast(i + lanes);
      finish(r0, i);
      finish(r1, i + lanes);
    }
  }
  for (; i + lanes <= n; i += lanes) {
    finish(fast(i), i);
  }
  return i;
}

}  // namespace rotorcert::rotor_simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // ROTORCERT_ROTOR_SIMD_FAST_PATHS_INL_H_
