// rotor_simd, per target: the batch loops of every op, AoS in, SoA kernel, AoS out, with the
// ABI's batch signatures (the functions the dispatch table of rotor_simd.cpp points to).
#if defined(ROTORCERT_ROTOR_SIMD_BATCH_INL_H_) == defined(HWY_TARGET_TOGGLE)  // per-target include guard
#ifdef ROTORCERT_ROTOR_SIMD_BATCH_INL_H_
#undef ROTORCERT_ROTOR_SIMD_BATCH_INL_H_
#else
#define ROTORCERT_ROTOR_SIMD_BATCH_INL_H_
#endif

#include <hwy/highway.h>

#include "rotor_simd/fast_paths-inl.h"

HWY_BEFORE_NAMESPACE();
namespace rotorcert::rotor_simd::HWY_NAMESPACE {

// ---- 2c. batch loops: AoS in, SoA kernel, AoS out ------------------------------------------

HWY_INLINE V nan_v() { return hn::Set(D(), std::numeric_limits<float>::quiet_NaN()); }
HWY_INLINE Quat poison(M bad, const Quat& q) {
  const V nan = nan_v();
  return {hn::IfThenElse(bad, nan, q.x), hn::IfThenElse(bad, nan, q.y), hn::IfThenElse(bad, nan, q.z),
          hn::IfThenElse(bad, nan, q.w)};
}
HWY_INLINE Vec3 poison(M bad, const Vec3& v) {
  const V nan = nan_v();
  return {hn::IfThenElse(bad, nan, v.x), hn::IfThenElse(bad, nan, v.y), hn::IfThenElse(bad, nan, v.z)};
}

int Normalize(std::size_t n, const float* q, float* out, std::uint8_t* status) {
  for_blocks<1>(n, {q}, {4}, {kIdentity}, out, 4, status, [](const float* const* p, float* o, std::uint8_t* s) {
    const Quat a = load_quat(p[0]);
    const M bad = hn::Not(is_rotation(a));
    store_quat(poison(bad, normalized(a)), o);
    store_status(bad, s);
  });
  return 0;
}

/// COMPOSE-1: the exact product a b of the inputs as given (not normalised).
int Compose(std::size_t n, const float* a, const float* b, float* out, std::uint8_t* status) {
  for_blocks<2>(n, {a, b}, {4, 4}, {kIdentity, kIdentity}, out, 4, status,
                [](const float* const* p, float* o, std::uint8_t* s) {
                  const Quat qa = load_quat(p[0]), qb = load_quat(p[1]);
                  const M bad = hn::Not(hn::And(is_rotation(qa), is_rotation(qb)));
                  // The product of the power-of-two-scaled inputs, scaled back: no intermediate
                  // underflow or overflow unless the product itself is out of range.
                  // The inverse scale 2^k, k in [-252, 252], is applied in two halves (each a
                  // normal float): an intermediate can then neither overflow nor go subnormal
                  // while the final product is in range.
                  const D d;
                  const DI di;
                  const auto ea = pow2_scale_biased_exponent(max_abs(qa)), eb = pow2_scale_biased_exponent(max_abs(qb));
                  const Quat r = hamilton(scale(qa, hn::BitCast(d, hn::ShiftLeft<23>(ea))),
                                          scale(qb, hn::BitCast(d, hn::ShiftLeft<23>(eb))));
                  const auto k = hn::Sub(hn::Set(di, 254), hn::Add(ea, eb));  // 2^k undoes both scales
                  const auto k1 = hn::ShiftRight<1>(k), k2 = hn::Sub(k, k1);
                  const auto pow2 = [&](hn::Vec<DI> e) { return hn::BitCast(d, hn::ShiftLeft<23>(hn::Add(e, hn::Set(di, 127)))); };
                  store_quat(poison(bad, scale(scale(r, pow2(k1)), pow2(k2))), o);
                  store_status(bad, s);
                });
  return 0;
}

/// APPLY-1 (and APPLY-2): R x ~R = q x q* / |q|^2 = x + (w t + u x t) / |q|^2, t = 2 u x x,
/// with q and x each scaled by a power of two first (no overflow for |x| near FLT_MAX, no
/// underflow for subnormal x); the correction is scaled back exactly. A padded tail's spare
/// lanes hold the unit vector e3, not 0: the scale of a zero vector is 2^127, its reciprocal
/// subnormal, and a division with a subnormal quotient takes a microcode assist on x86 (it
/// made a single-element call 60 ns slower).
int ApplyVector(std::size_t n, const float* q, const float* v, float* out, std::uint8_t* status) {
  for_blocks<2>(n, {q, v}, {4, 3}, {kIdentity, kUnitZ}, out, 3, status,
                [](const float* const* p, float* o, std::uint8_t* s) {
                  const D d;
                  const Quat qa = load_quat(p[0]);
                  const Vec3 x = load_vec3(p[1]);
                  const M bad = hn::Not(hn::And(is_rotation(qa), all_finite(x)));
                  const Quat qs = safe_scaled(qa);
                  const V inv_n2 = hn::Div(hn::Set(d, 1.0f), dot(qs, qs));
                  const V xs_scale = pow2_scale(max_abs(x));
                  const Vec3 xs = scale(x, xs_scale);
                  const Vec3 u{qs.x, qs.y, qs.z};
                  Vec3 t = cross(u, xs);
                  t = {hn::Add(t.x, t.x), hn::Add(t.y, t.y), hn::Add(t.z, t.z)};
                  const Vec3 c = cross(u, t);
                  // The correction is scaled back and added to x as given: x + 0 = x exactly
                  // for the identity (EDGE-1), at any dynamic range of x.
                  const V back = hn::Div(hn::Set(d, 1.0f), xs_scale);
                  const Vec3 r{hn::MulAdd(hn::Mul(hn::MulAdd(qs.w, t.x, c.x), inv_n2), back, x.x),
                               hn::MulAdd(hn::Mul(hn::MulAdd(qs.w, t.y, c.y), inv_n2), back, x.y),
                               hn::MulAdd(hn::Mul(hn::MulAdd(qs.w, t.z, c.z), inv_n2), back, x.z)};
                  store_vec3(poison(bad, r), o);
                  store_status(bad, s);
                });
  return 0;
}

/// MAT-1: the matrix of x -> q x q* / |q|^2, entries 1 - s(..) and s(..) with s = 2/|q|^2.
int ToMatrix(std::size_t n, const float* q, float* out, std::uint8_t* status) {
  for_blocks<1>(n, {q}, {4}, {kIdentity}, out, 9, status, [](const float* const* p, float* o, std::uint8_t* st) {
    const D d;
    const Quat qa = load_quat(p[0]);
    const M bad = hn::Not(is_rotation(qa));
    const Quat u = safe_scaled(qa);
    const V s = hn::Div(hn::Set(d, 2.0f), dot(u, u));
    const V xx = hn::Mul(u.x, u.x), yy = hn::Mul(u.y, u.y), zz = hn::Mul(u.z, u.z);
    const V xy = hn::Mul(u.x, u.y), xz = hn::Mul(u.x, u.z), yz = hn::Mul(u.y, u.z);
    const V wx = hn::Mul(u.w, u.x), wy = hn::Mul(u.w, u.y), wz = hn::Mul(u.w, u.z);
    const V one = hn::Set(d, 1.0f), nan = nan_v();
    V m[9] = {hn::NegMulAdd(s, hn::Add(yy, zz), one), hn::Mul(s, hn::Add(xy, wz)), hn::Mul(s, hn::Sub(xz, wy)),
              hn::Mul(s, hn::Sub(xy, wz)), hn::NegMulAdd(s, hn::Add(xx, zz), one), hn::Mul(s, hn::Add(yz, wx)),
              hn::Mul(s, hn::Add(xz, wy)), hn::Mul(s, hn::Sub(yz, wx)), hn::NegMulAdd(s, hn::Add(xx, yy), one)};
    for (V& e : m) e = hn::IfThenElse(bad, nan, e);
    store_mat3(m, o);
    store_status(bad, st);
  });
  return 0;
}

/// INV-1 (kernels: inverse).
int Inverse(std::size_t n, const float* q, float* out, std::uint8_t* status) {
  for_blocks<1>(n, {q}, {4}, {kIdentity}, out, 4, status, [](const float* const* p, float* o, std::uint8_t* s) {
    const Quat a = load_quat(p[0]);
    const M bad = hn::Not(is_rotation(a));
    store_quat(poison(bad, inverse(a)), o);
    store_status(bad, s);
  });
  return 0;
}

/// AXANG-1 (kernels: axis_angle): two output arrays, the angle and the axis.
int ToAxisAngle(std::size_t n, const float* q, float* angle, float* axis, std::uint8_t* status) {
  for_blocks<1, 2>(n, {q}, {4}, {kIdentity}, {angle, axis}, {1, 3}, status,
                   [](const float* const* p, float* const* o, std::uint8_t* s) {
                     const Quat a = load_quat(p[0]);
                     const M bad = hn::Not(is_rotation(a));
                     V ang;
                     Vec3 ax;
                     axis_angle(a, ang, ax);
                     hn::StoreU(hn::IfThenElse(bad, nan_v(), ang), D(), o[0]);
                     store_vec3(poison(bad, ax), o[1]);
                     store_status(bad, s);
                   });
  return 0;
}

/// AXANG-2 (kernels: from_axis_angle); lanes with |angle| > 16 in binary64.
int FromAxisAngle(std::size_t n, const float* angle, const float* axis, float* out, std::uint8_t* status) {
  for_blocks<2>(n, {angle, axis}, {1, 3}, {kZero1, kUnitZ}, out, 4, status,
                [](const float* const* p, float* o, std::uint8_t* s) {
                  const D d;
                  const V a = hn::LoadU(d, p[0]);
                  const Vec3 u = load_vec3(p[1]);
                  const M bad = hn::Not(hn::And(hn::And(hn::IsFinite(a), all_finite(u)),
                                                hn::Gt(max_abs(u), hn::Zero(d))));
                  store_quat(poison(bad, from_axis_angle(a, u)), o);
                  const M far = hn::AndNot(bad, hn::Gt(hn::Abs(a), hn::Set(d, 16.0f)));
                  for_each_set_lane(far, [&](std::size_t l) { from_axis_angle_double(p[0][l], p[1] + 3 * l, o + 4 * l); });
                  store_status(bad, s);
                });
  return 0;
}

int Log(std::size_t n, const float* q, float* out, std::uint8_t* status) {
  for_blocks<1>(n, {q}, {4}, {kIdentity}, out, 3, status, [](const float* const* p, float* o, std::uint8_t* s) {
    const Quat a = load_quat(p[0]);
    const M bad = hn::Not(is_rotation(a));
    store_vec3(poison(bad, log_unit(normalized(a))), o);
    store_status(bad, s);
  });
  return 0;
}

int Exp(std::size_t n, const float* v, float* out, std::uint8_t* status) {
  for_blocks<1>(n, {v}, {3}, {kZero3}, out, 4, status, [](const float* const* p, float* o, std::uint8_t* s) {
    const D d;
    const Vec3 x = load_vec3(p[0]);
    const M bad = hn::Not(all_finite(x));
    V theta;
    store_quat(poison(bad, exp_small(x, &theta)), o);
    const M far = hn::AndNot(bad, hn::Gt(theta, hn::Set(d, 8.0f)));
    for_each_set_lane(far, [&](std::size_t l) { exp_double(p[0] + 3 * l, o + 4 * l); });
    store_status(bad, s);
  });
  return 0;
}

/// SLERP-1..5: Omega = 2 atan(|a - b'| / |a + b'|) (chord lengths: accurate at every angle,
/// unlike acos(a.b')), then normalize(sin((1-t) Omega) a + sin(t Omega) b'). The exact slerp
/// is unit, so the sum's norm is sin(Omega) and normalising replaces the division by sin(Omega)
/// with one that is never 0/0: Omega = 0 (a == b') returns a itself. Lanes with |t| > 4 are
/// recomputed in binary64 (slerp_double). The general kernel for one block (any input; the fast
/// path declined it).
HWY_NOINLINE void slerp_block(const float* const* p, float* o, std::uint8_t* s) {
  const D d;
  const Quat qa = load_quat(p[0]), qb = load_quat(p[1]);
  const V tt = hn::LoadU(d, p[2]);
  const M bad = hn::Not(hn::And(hn::And(is_rotation(qa), is_rotation(qb)), hn::IsFinite(tt)));
  const Quat as = safe_scaled(qa), bs = safe_scaled(qb);
  const Quat ua = fast_unit_of_scaled(as);
  const Quat ub = negate_if(dot_negative(as, bs, qa, qb), fast_unit_of_scaled(bs));
  const Quat diff{hn::Sub(ua.x, ub.x), hn::Sub(ua.y, ub.y), hn::Sub(ua.z, ub.z), hn::Sub(ua.w, ub.w)};
  const Quat sum{hn::Add(ua.x, ub.x), hn::Add(ua.y, ub.y), hn::Add(ua.z, ub.z), hn::Add(ua.w, ub.w)};
  // a.b' >= 0, so |a - b'| <= |a + b'| and the ratio is tan(Omega/2) in [0, 1].
  // hn::Atan's own polynomial for [0, 1] (hn::Atan adds a division for |x| > 1).
  const V half = hn::impl::AtanImpl<float>().AtanPoly(d, hn::Sqrt(hn::Div(dot(diff, diff), dot(sum, sum))));
  const V omega = hn::Add(half, half);
  const V sa = hn::Sin(d, hn::Mul(hn::Sub(hn::Set(d, 1.0f), tt), omega));
  const V sb = hn::Sin(d, hn::Mul(tt, omega));
  const Quat r{hn::MulAdd(sa, ua.x, hn::Mul(sb, ub.x)), hn::MulAdd(sa, ua.y, hn::Mul(sb, ub.y)),
               hn::MulAdd(sa, ua.z, hn::Mul(sb, ub.z)), hn::MulAdd(sa, ua.w, hn::Mul(sb, ub.w))};
  // r has the size of sin(Omega): for Omega near 2^-72 its squares underflow, and rsqrt of 0 made
  // the result inf / NaN on every target but AVX-512 (fuzz/corpus/interpolation/
  // regression-simd-slerp-tiny-omega); scaled by a power of two first, as every normalisation is.
  const Quat res = select(hn::Eq(omega, hn::Zero(d)), ua, fast_unit_of_scaled(safe_scaled(r)));
  store_quat(poison(bad, res), o);
  const M far = hn::AndNot(bad, hn::Gt(hn::Abs(tt), hn::Set(d, 4.0f)));
  for_each_set_lane(far, [&](std::size_t l) {
    slerp_double(p[0] + 4 * l, p[1] + 4 * l, p[2][l], o + 4 * l);
  });
  store_status(bad, s);
}

/// The batch of an interpolation kernel pair (slerp, nlerp): full blocks through the fast
/// kernel two at a time (fast_blocks), the tail through for_blocks, and any block the fast
/// kernel declines through the general one. The kernels are template arguments, so every call
/// is direct and inlined as fast_blocks needs.
template <FastBlock (*kFast)(const float*, const float*, const float*),
          void (*kGeneral)(const float* const*, float*, std::uint8_t*)>
HWY_INLINE int interpolate(std::size_t n, const float* a, const float* b, const float* t, float* out,
                           std::uint8_t* status) {
  const std::size_t done = fast_blocks<2>(
      n, out, status, [&](std::size_t i) ROTORCERT_SIMD_INLINE { return kFast(a + 4 * i, b + 4 * i, t + i); },
      [&](std::size_t i) {
        const float* const p[3] = {a + 4 * i, b + 4 * i, t + i};
        kGeneral(p, out + 4 * i, status + i);
      });
  for_blocks<3>(n - done, {a + 4 * done, b + 4 * done, t + done}, {4, 4, 1}, {kIdentity, kIdentity, kZero1},
                out + 4 * done, 4, status + done, [](const float* const* p, float* o, std::uint8_t* s) {
                  const FastBlock r = kFast(p[0], p[1], p[2]);
                  if (hn::AllTrue(D(), r.ordinary)) {
                    store_fast(r, o, s);
                  } else {
                    kGeneral(p, o, s);
                  }
                });
  return 0;
}

int Slerp(std::size_t n, const float* a, const float* b, const float* t, float* out, std::uint8_t* status) {
  return interpolate<slerp_fast, slerp_block>(n, a, b, t, out, status);
}

/// NLERP-1: normalize(a + t (b' - a)), divided by max(1, |t|) first so that no finite t
/// overflows; exactly a when b' == a. The general kernel for one block.
HWY_NOINLINE void nlerp_block(const float* const* p, float* o, std::uint8_t* s) {
  const D d;
  const Quat qa = load_quat(p[0]), qb = load_quat(p[1]);
  const V tt = hn::LoadU(d, p[2]);
  const M bad = hn::Not(hn::And(hn::And(is_rotation(qa), is_rotation(qb)), hn::IsFinite(tt)));
  const Quat as = safe_scaled(qa), bs = safe_scaled(qb);
  const Quat ua = fast_unit_of_scaled(as);
  const Quat ub = negate_if(dot_negative(as, bs, qa, qb), fast_unit_of_scaled(bs));
  const V big = hn::Max(hn::Set(d, 1.0f), hn::Abs(tt));
  const V inv = hn::Div(hn::Set(d, 1.0f), big);
  const V ts = hn::Div(tt, big);
  const Quat r{hn::MulAdd(ts, hn::Sub(ub.x, ua.x), hn::Mul(ua.x, inv)),
               hn::MulAdd(ts, hn::Sub(ub.y, ua.y), hn::Mul(ua.y, inv)),
               hn::MulAdd(ts, hn::Sub(ub.z, ua.z), hn::Mul(ua.z, inv)),
               hn::MulAdd(ts, hn::Sub(ub.w, ua.w), hn::Mul(ua.w, inv))};
  store_quat(poison(bad, normalized(r)), o);  // exactly rounded: a stays a (EDGE-1)
  store_status(bad, s);
}

int Nlerp(std::size_t n, const float* a, const float* b, const float* t, float* out, std::uint8_t* status) {
  return interpolate<nlerp_fast, nlerp_block>(n, a, b, t, out, status);
}

/// Weights of a block of blends (EDGE-9): all finite and >= 0 (-0 counts as 0), some > 0.
/// Returns the power-of-two scale that brings the largest weight to [1, 4) (blends are
/// invariant under a common weight scale; this keeps sums of huge weights finite).
HWY_INLINE V weight_scale(const float* w, std::size_t k, M* ok) {
  const D d;
  V wmax = hn::Zero(d);
  M good = hn::Eq(wmax, wmax);
  for (std::size_t j = 0; j < k; ++j) {
    const V wj = gather(w, k, j, 1, 0);
    good = hn::And(good, hn::AndNot(hn::Lt(wj, hn::Zero(d)), hn::IsFinite(wj)));
    wmax = hn::Max(wmax, hn::IfThenElseZero(hn::IsFinite(wj), wj));
  }
  *ok = hn::And(good, hn::Gt(wmax, hn::Zero(d)));
  return pow2_scale(wmax);
}

/// Runs a blend block over n elements with k influences, the tail through padded copies.
template <class Block>
int for_blend_blocks(std::size_t n, std::size_t k, const float* q, const float* w, float* out, std::uint8_t* status,
                     const Block& block) {
  const std::size_t lanes = hn::Lanes(D());
  std::size_t i = 0;
  for (; i + lanes <= n; i += lanes) block(q + i * k * 4, w + i * k, out + i * 4, status + i);
  if (i == n) return 0;
  const std::size_t count = n - i;
  // The padded tail on the stack up to 8 influences (every blend the suite and a skinning rig
  // make); beyond that on the heap.
  constexpr std::size_t kStackInfluences = 8;
  HWY_ALIGN float stack_q[kStackInfluences * 4 * kMaxLanes], stack_w[kStackInfluences * kMaxLanes];
  std::vector<float> heap_q, heap_w;
  float* pq = stack_q;
  float* pw = stack_w;
  if (k > kStackInfluences) {
    heap_q.resize(lanes * k * 4);
    heap_w.resize(lanes * k);
    pq = heap_q.data();
    pw = heap_w.data();
  }
  std::memcpy(pq, q + i * k * 4, count * k * 4 * sizeof(float));
  std::memcpy(pw, w + i * k, count * k * sizeof(float));
  for (std::size_t e = count * k; e < lanes * k; ++e) {
    for (std::size_t c = 0; c < 4; ++c) pq[e * 4 + c] = kIdentity[c];
    pw[e] = 1.0f;
  }
  HWY_ALIGN float o[4 * kMaxLanes];
  std::uint8_t s[kMaxLanes];
  block(pq, pw, o, s);
  std::memcpy(out + i * 4, o, count * 4 * sizeof(float));
  std::memcpy(status + i, s, count);
  return 0;
}

/// QLB-1: normalize(sum w_j s_j q_j/|q_j|), s_j = -1 iff q_j . q_p < 0 (exact sign), pivot p
/// the first influence with w > 0. One pass: influences before the pivot have weight 0, so
/// the running pivot can stand in for them without changing the sum. The general kernel for one
/// block of blends of k influences (any input; the k = 4 fast path declined it or k != 4).
HWY_NOINLINE void qlb_block(std::size_t k, const float* bq, const float* bw, float* o, std::uint8_t* s) {
  const D d;
  M ok;
  const V ws = weight_scale(bw, k, &ok);
  Quat sum{hn::Zero(d), hn::Zero(d), hn::Zero(d), hn::Zero(d)};
  Quat pivot_raw = sum, pivot_scaled = sum;
  M found = hn::Ne(ws, ws);  // all false
  for (std::size_t j = 0; j < k; ++j) {
    const Quat qj = gather_quat(bq, k, j);
    const V wraw = gather(bw, k, j, 1, 0);
    const V wj = hn::Mul(wraw, ws);
    ok = hn::And(ok, is_rotation(qj));
    const Quat qs = safe_scaled(qj);
    pivot_raw = select(found, pivot_raw, qj);
    pivot_scaled = select(found, pivot_scaled, qs);
    // The pivot is decided on the weight as given: a tiny w > 0 beside huge ones scales to 0.
    found = hn::Or(found, hn::Gt(wraw, hn::Zero(d)));
    const V c = hn::Mul(wj, rsqrt(dot(qs, qs)));
    const V cs = hn::IfThenElse(dot_negative(qs, pivot_scaled, qj, pivot_raw), hn::Neg(c), c);
    sum = {hn::MulAdd(cs, qs.x, sum.x), hn::MulAdd(cs, qs.y, sum.y), hn::MulAdd(cs, qs.z, sum.z),
           hn::MulAdd(cs, qs.w, sum.w)};
  }
  const M bad = hn::Not(ok);
  store_quat(poison(bad, fast_unit_of_scaled(safe_scaled(sum))), o);
  store_status(bad, s);
}

int BlendQlb(std::size_t n, std::size_t k, const float* q, const float* w, float* out, std::uint8_t* status) {
  if (k == 0) {  // empty influence set: DOMAIN_ERROR for every element (EDGE-9)
    for (std::size_t i = 0; i < n * 4; ++i) out[i] = std::numeric_limits<float>::quiet_NaN();
    std::memset(status, RC_DOMAIN_ERROR, n);
    return 0;
  }
  std::size_t done = 0;
  if (k == 4) {
    // One block per step: two QLB blocks (16 live vectors of influences each) spill registers.
    done = fast_blocks<1>(
        n, out, status, [&](std::size_t i) ROTORCERT_SIMD_INLINE { return qlb4_fast(q + 16 * i, w + 4 * i); },
        [&](std::size_t i) { qlb_block(4, q + 16 * i, w + 4 * i, out + 4 * i, status + i); });
  }
  return for_blend_blocks(n - done, k, q + 4 * k * done, w + k * done, out + 4 * done, status + done,
                          [k](const float* bq, const float* bw, float* o, std::uint8_t* s) {
                            if (k == 4) {
                              const FastBlock r = qlb4_fast(bq, bw);
                              if (hn::AllTrue(D(), r.ordinary)) return store_fast(r, o, s);
                            }
                            qlb_block(k, bq, bw, o, s);
                          });
}

/// LOGBLEND-1: q_p exp(sum (w_j/W) log(align(q_p^-1 q_j))), align = negate iff the w
/// component (= q_p . q_j, exact sign) is < 0.
int BlendLog(std::size_t n, std::size_t k, const float* q, const float* w, float* out, std::uint8_t* status) {
  if (k == 0) {
    for (std::size_t i = 0; i < n * 4; ++i) out[i] = std::numeric_limits<float>::quiet_NaN();
    std::memset(status, RC_DOMAIN_ERROR, n);
    return 0;
  }
  return for_blend_blocks(n, k, q, w, out, status, [k](const float* bq, const float* bw, float* o, std::uint8_t* s) {
    const D d;
    M ok;
    const V ws = weight_scale(bw, k, &ok);
    // Pass 1: validity, the pivot, and the total weight.
    Quat pivot_raw{hn::Zero(d), hn::Zero(d), hn::Zero(d), hn::Set(d, 1.0f)};
    M found = hn::Ne(ws, ws);
    V total = hn::Zero(d);
    for (std::size_t j = 0; j < k; ++j) {
      const Quat qj = gather_quat(bq, k, j);
      const V wraw = gather(bw, k, j, 1, 0);
      const V wj = hn::Mul(wraw, ws);
      ok = hn::And(ok, is_rotation(qj));
      // The pivot is the first influence whose weight as given is > 0: after the common scaling
      // a subnormal weight beside weights near 2^100 is 0 (fuzz/corpus/blending/regression-simd-*).
      const M take = hn::AndNot(found, hn::Gt(wraw, hn::Zero(d)));
      pivot_raw = select(take, qj, pivot_raw);
      found = hn::Or(found, take);
      total = hn::Add(total, hn::IfThenElseZero(hn::IsFinite(wj), wj));
    }
    pivot_raw = select(ok, pivot_raw, Quat{hn::Zero(d), hn::Zero(d), hn::Zero(d), hn::Set(d, 1.0f)});
    const Quat ps = safe_scaled(pivot_raw);
    const Quat pu = unit_of_scaled(ps);
    const Quat pinv{hn::Neg(pu.x), hn::Neg(pu.y), hn::Neg(pu.z), pu.w};
    const V inv_total = hn::Div(hn::Set(d, 1.0f), total);
    // Pass 2: the weighted mean of the aligned logs about the pivot.
    Vec3 acc{hn::Zero(d), hn::Zero(d), hn::Zero(d)};
    for (std::size_t j = 0; j < k; ++j) {
      const Quat qj = gather_quat(bq, k, j);
      const V c = hn::Mul(hn::Mul(gather(bw, k, j, 1, 0), ws), inv_total);
      const Quat qs = safe_scaled(qj);
      const Quat rel = negate_if(dot_negative(ps, qs, pivot_raw, qj), hamilton(pinv, unit_of_scaled(qs)));
      const Vec3 l = log_unit(rel);
      acc = {hn::MulAdd(c, l.x, acc.x), hn::MulAdd(c, l.y, acc.y), hn::MulAdd(c, l.z, acc.z)};
    }
    const M bad = hn::Not(ok);
    store_quat(poison(bad, hamilton(pu, exp_small(acc))), o);
    store_status(bad, s);
  });
}

}  // namespace rotorcert::rotor_simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // ROTORCERT_ROTOR_SIMD_BATCH_INL_H_
