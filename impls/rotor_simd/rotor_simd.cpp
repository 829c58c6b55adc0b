// rotor_simd: batched rotor kernels in binary32 on Google Highway 1.0.3, with runtime dispatch.
//
// The file has three parts:
//   1. shared scalar code (compiled once): the dispatch table type, the exact sign of a dot
//      product, and binary64 fallbacks for the rare far-out lanes (|t| > 4 in slerp, |v| > 8 in
//      exp) where a binary32 polynomial would lose accuracy in proportion to the argument;
//   2. per-target code (compiled once per Highway target by foreach_target.h): the data-layout
//      transform (AoS ABI arrays <-> SoA lanes), the SoA math kernels, the fast paths of slerp,
//      nlerp and QLB (k = 4) for blocks of ordinary inputs, and the batch loops;
//   3. dispatch (compiled once): Highway's HWY_DYNAMIC_DISPATCH picks the default target, an
//      explicit table of the compiled targets lets select_target / ROTORCERT_SIMD_TARGET force one;
//      with the default target, a batch's tail shorter than one block (a single-element call is
//      all tail) runs on the narrowest SIMD target (split_tail).
//
// The rotor R = Phi(q) = w - x e23 - y e31 - z e12 (Q2R-1) is stored by its quaternion
// coefficients: the sandwich R v ~R, the product Phi(a)Phi(b) and the rotor log/exp are written
// in that view (they are the same numbers), so no sign conversion happens at the ABI boundary.
//
// Edge outcomes (EDGE-5..9) are computed branch-free with masks: every kernel computes a
// `bad` lane mask (zero or non-finite quaternion, non-finite vector or t, bad weights) and
// poisons that lane's outputs with quiet NaN and status RC_DOMAIN_ERROR. Non-unit inputs are
// scaled by an exact power of two near their largest |component| before any square is taken,
// so no input the format holds overflows or underflows (NORM-1, EDGE-5, EDGE-8). The fast
// paths (2b') skip all of that for blocks whose every lane is ordinary (unit inputs, t in
// [0, 1], ...) and hand any other block to these general kernels.

// ---- 1. shared scalar code ------------------------------------------------------------------
#ifndef ROTORCERT_ROTOR_SIMD_SHARED
#define ROTORCERT_ROTOR_SIMD_SHARED

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <mutex>
#include <vector>

#include <rotorcert/impl_table.hpp>
#include <rotorcert/runtime/exact_sign.hpp>

/// Forces a lambda inline (GCC and Clang attribute syntax for a lambda's call operator).
#define ROTORCERT_SIMD_INLINE __attribute__((always_inline))

namespace rotorcert::rotor_simd {

using Unary = int (*)(std::size_t, const float*, float*, std::uint8_t*);
using Binary = int (*)(std::size_t, const float*, const float*, float*, std::uint8_t*);
using Interp = int (*)(std::size_t, const float*, const float*, const float*, float*, std::uint8_t*);
using Blend = int (*)(std::size_t, std::size_t, const float*, const float*, float*, std::uint8_t*);

/// One target's kernels, all with the ABI's batch signatures.
struct Kernels {
  const char* name;  // hwy::TargetName of the target it was compiled for
  std::int64_t target;
  std::size_t lanes;  // floats per vector: elements per block
  Unary normalize;
  Binary compose;
  Binary apply_vector;  // also APPLY-2: bivector coefficients rotate like a vector
  Unary to_matrix;
  Unary log;
  Unary exp;
  Interp slerp;
  Interp nlerp;
  Blend blend_qlb;
  Blend blend_log;
};

/// Sign (-1, 0, +1) of the exact dot product of two float quaternions ([x, y, z, w] arrays):
/// the hemisphere rules (SLERP-1, QLB-1, EDGE-3) flip iff it is < 0 strictly, and a float dot
/// can turn an exact 0 into +-tiny. The kernels call this only when their float dot is within
/// its error bound of zero.
inline int exact_dot_sign(const float* a, const float* b) {
  return rotorcert::runtime::hemisphere_sign<float>({a[0], a[1], a[2], a[3]}, {b[0], b[1], b[2], b[3]});
}

/// q/|q| in double with the largest component scaled out first.
inline void normalized_double(const float* q, double out[4]) {
  double m = 0;
  for (int i = 0; i < 4; ++i) m = std::max(m, std::fabs(static_cast<double>(q[i])));
  double s[4], n2 = 0;
  for (int i = 0; i < 4; ++i) {
    s[i] = q[i] / m;
    n2 += s[i] * s[i];
  }
  const double n = std::sqrt(n2);
  for (int i = 0; i < 4; ++i) out[i] = s[i] / n;
}

/// SLERP-1 in binary64 for one valid lane ([x, y, z, w] arrays): the formula of the spec with
/// Omega from the chord lengths. Used for |t| > 4, where the binary32 argument t * Omega of
/// sin would carry an absolute error proportional to |t|.
inline void slerp_double(const float* qa, const float* qb, float t, float* out) {
  double a[4], b[4];
  normalized_double(qa, a);
  normalized_double(qb, b);
  if (exact_dot_sign(qa, qb) < 0)
    for (double& x : b) x = -x;
  double d2 = 0, s2 = 0;
  for (int i = 0; i < 4; ++i) {
    d2 += (a[i] - b[i]) * (a[i] - b[i]);
    s2 += (a[i] + b[i]) * (a[i] + b[i]);
  }
  const double omega = 2 * std::atan2(std::sqrt(d2), std::sqrt(s2));
  if (omega == 0) {
    for (int i = 0; i < 4; ++i) out[i] = static_cast<float>(a[i]);
    return;
  }
  const double sa = std::sin((1 - static_cast<double>(t)) * omega), sb = std::sin(t * omega), s = std::sin(omega);
  for (int i = 0; i < 4; ++i) out[i] = static_cast<float>((sa * a[i] + sb * b[i]) / s);
}

/// EXP-1 in binary64 for one lane: (sin|v| v/|v|, cos|v|). Used for |v| > 8.
inline void exp_double(const float* v, float* out) {
  const double x = v[0], y = v[1], z = v[2];
  const double m = std::max({std::fabs(x), std::fabs(y), std::fabs(z)});
  const double theta = m * std::sqrt((x / m) * (x / m) + (y / m) * (y / m) + (z / m) * (z / m));
  const double k = std::sin(theta) / theta;
  out[0] = static_cast<float>(k * x);
  out[1] = static_cast<float>(k * y);
  out[2] = static_cast<float>(k * z);
  out[3] = static_cast<float>(std::cos(theta));
}

}  // namespace rotorcert::rotor_simd

#endif  // ROTORCERT_ROTOR_SIMD_SHARED

// ---- 2. per-target code ------------------------------------------------------------------------
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "rotor_simd/rotor_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

HWY_BEFORE_NAMESPACE();
namespace rotorcert::rotor_simd::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;
using D = hn::ScalableTag<float>;
using DI = hn::RebindToSigned<D>;
using V = hn::Vec<D>;
using M = hn::Mask<D>;

/// Lanes of the widest target, for block buffers (AVX-512: 16).
constexpr std::size_t kMaxLanes = 64;

// ---- 2a. SoA layout and the data-layout transform ------------------------------------------
//
// A block is N = Lanes(D) consecutive elements of a batch. In SoA form a block of quaternions
// is four vectors, one per component, lane l holding element (block start + l):
//
//     Quat{ x = [x0 x1 .. x(N-1)], y = [y0 ..], z = [z0 ..], w = [w0 ..] }
//
// and a block of vectors (or bivectors [e23, e31, e12], or logs) is Vec3{x, y, z} likewise.
// The ABI arrays are AoS ([x, y, z, w] per element, LAYOUT-1); the functions of this section
// are the only ones that touch them. Blends read influence j of element i at (i*k + j)*4 with
// a gather. Everything after this section works on whole SoA blocks, lane-independently.

struct Quat {
  V x, y, z, w;
};
struct Vec3 {
  V x, y, z;
};

HWY_INLINE Quat load_quat(const float* p) {
  const D d;
  Quat q;
  hn::LoadInterleaved4(d, p, q.x, q.y, q.z, q.w);
  return q;
}
HWY_INLINE void store_quat(const Quat& q, float* p) { hn::StoreInterleaved4(q.x, q.y, q.z, q.w, D(), p); }
HWY_INLINE Vec3 load_vec3(const float* p) {
  const D d;
  Vec3 v;
  hn::LoadInterleaved3(d, p, v.x, v.y, v.z);
  return v;
}
HWY_INLINE void store_vec3(const Vec3& v, float* p) { hn::StoreInterleaved3(v.x, v.y, v.z, D(), p); }

/// Nine SoA vectors (column-major entries m[c*3 + r]) to N AoS matrices.
HWY_INLINE void store_mat3(const V (&m)[9], float* p) {
  const D d;
  const std::size_t n = hn::Lanes(d);
  HWY_ALIGN float tmp[9 * kMaxLanes];
  for (int e = 0; e < 9; ++e) hn::Store(m[e], d, tmp + e * n);
  for (std::size_t l = 0; l < n; ++l)
    for (int e = 0; e < 9; ++e) p[l * 9 + e] = tmp[e * n + l];
}

/// Influence j of each element of a block of blends: lane l reads element l's j-th entry
/// of `width` floats, component c, from p[(l*k + j)*width + c].
HWY_INLINE V gather(const float* p, std::size_t k, std::size_t j, std::size_t width, std::size_t c) {
  const D d;
  const DI di;
  const auto idx = hn::Add(hn::Mul(hn::Iota(di, 0), hn::Set(di, static_cast<std::int32_t>(k * width))),
                           hn::Set(di, static_cast<std::int32_t>(j * width + c)));
  return hn::GatherIndex(d, p, idx);
}
HWY_INLINE Quat gather_quat(const float* p, std::size_t k, std::size_t j) {
  return {gather(p, k, j, 4, 0), gather(p, k, j, 4, 1), gather(p, k, j, 4, 2), gather(p, k, j, 4, 3)};
}

/// Per-lane status bytes from the DOMAIN_ERROR mask (N bytes).
HWY_INLINE void store_status(M bad, std::uint8_t* status) {
  const DI di;
  const hn::Rebind<std::uint8_t, DI> du8;
  hn::StoreU(hn::DemoteTo(du8, hn::IfThenElseZero(hn::RebindMask(di, bad), hn::Set(di, 1))), du8, status);
}

/// The tail of a batch (n not a multiple of N) runs as a full block on copies padded with a
/// valid element (`fill`, `width` floats), so that every kernel only ever sees whole blocks.
/// Only the target's N lanes are filled, element by element: a single-element call pays for
/// N - 1 small copies, not for kMaxLanes memcpy calls (which made n = 1 cost ~250 ns).
struct Padded {
  HWY_ALIGN float data[16 * kMaxLanes];
  const float* from(const float* src, std::size_t count, std::size_t width, const float* fill) {
    const std::size_t lanes = hn::Lanes(D());
    std::memcpy(data, src, count * width * sizeof(float));
    for (std::size_t l = count; l < lanes; ++l)
      for (std::size_t c = 0; c < width; ++c) data[l * width + c] = fill[c];
    return data;
  }
};
constexpr float kIdentity[4] = {0, 0, 0, 1};
constexpr float kZero3[3] = {0, 0, 0};
constexpr float kZero1[1] = {0};

/// Runs block(offset, in-pointers..., out-pointer, status) over n elements: full blocks in
/// place, the tail through padded copies. `in_width` / `fill` describe each input array.
template <std::size_t kIns, class Block>
HWY_INLINE void for_blocks(std::size_t n, const float* const (&in)[kIns], const std::size_t (&in_width)[kIns],
                           const float* const (&fill)[kIns], float* out, std::size_t out_width,
                           std::uint8_t* status, const Block& block) {
  const std::size_t lanes = hn::Lanes(D());
  std::size_t i = 0;
  for (; i + lanes <= n; i += lanes) {
    const float* p[kIns];
    for (std::size_t a = 0; a < kIns; ++a) p[a] = in[a] + i * in_width[a];
    block(p, out + i * out_width, status + i);
  }
  if (i == n) return;
  const std::size_t count = n - i;
  Padded pads[kIns];
  const float* p[kIns];
  for (std::size_t a = 0; a < kIns; ++a) p[a] = pads[a].from(in[a] + i * in_width[a], count, in_width[a], fill[a]);
  HWY_ALIGN float o[16 * kMaxLanes];
  std::uint8_t s[kMaxLanes];
  block(p, o, s);
  std::memcpy(out + i * out_width, o, count * out_width * sizeof(float));
  std::memcpy(status + i, s, count);
}

// ---- 2a'. the fast paths' lane order ------------------------------------------------------
//
// The fast paths (slerp, nlerp, QLB with k = 4; section 2b') use a cheaper transform than
// LoadInterleaved4: a 4x4 transpose inside every 128-bit block, without LoadInterleaved4's
// block shuffles (8 shuffles per four vectors instead of 16 on AVX-512). With B = N/4 blocks
// per vector, lane 4b + p then holds element B*p + b of the block, not element 4b + p:
//
//     AVX-512 (B = 4): lanes 0..15 hold elements 0 4 8 12  1 5 9 13  2 6 10 14  3 7 11 15
//     AVX2    (B = 2): lanes 0..7  hold elements 0 2 4 6  1 3 5 7
//     SSE     (B = 1): the identity.
//
// The kernels are lane-wise, so this only matters for per-element scalars (t, loaded through
// a lane permutation) and blend weights (transposed the same way). The same transpose takes
// the results back to AoS. It relies on x86's per-block InterleaveLower/Upper; SCALAR (one lane)
// and other architectures keep the AoS order (LoadInterleaved4 and gathers).
#if HWY_TARGET != HWY_SCALAR && (HWY_ARCH_X86 || HWY_TARGET == HWY_EMU128)

/// 4x4 transpose inside every 128-bit block: lane i of block b of output o_j is lane j of
/// block b of input i. It is its own inverse.
HWY_INLINE void transpose_in_blocks(V i0, V i1, V i2, V i3, V& o0, V& o1, V& o2, V& o3) {
  const D d;
  const hn::Repartition<std::uint64_t, D> d64;
  const V lo01 = hn::InterleaveLower(d, i0, i1), lo23 = hn::InterleaveLower(d, i2, i3);  // [x0 x1 y0 y1]..
  const V hi01 = hn::InterleaveUpper(d, i0, i1), hi23 = hn::InterleaveUpper(d, i2, i3);  // [z0 z1 w0 w1]..
  o0 = hn::BitCast(d, hn::InterleaveLower(d64, hn::BitCast(d64, lo01), hn::BitCast(d64, lo23)));
  o1 = hn::BitCast(d, hn::InterleaveUpper(d64, hn::BitCast(d64, lo01), hn::BitCast(d64, lo23)));
  o2 = hn::BitCast(d, hn::InterleaveLower(d64, hn::BitCast(d64, hi01), hn::BitCast(d64, hi23)));
  o3 = hn::BitCast(d, hn::InterleaveUpper(d64, hn::BitCast(d64, hi01), hn::BitCast(d64, hi23)));
}

/// N quaternions (4N floats) in the fast paths' lane order.
HWY_INLINE Quat load_quat_blocked(const float* p) {
  const D d;
  const std::size_t n = hn::Lanes(d);
  Quat q;
  transpose_in_blocks(hn::LoadU(d, p), hn::LoadU(d, p + n), hn::LoadU(d, p + 2 * n), hn::LoadU(d, p + 3 * n), q.x, q.y,
                      q.z, q.w);
  return q;
}
HWY_INLINE void store_quat_blocked(const Quat& q, float* p) {
  const D d;
  const std::size_t n = hn::Lanes(d);
  V o0, o1, o2, o3;
  transpose_in_blocks(q.x, q.y, q.z, q.w, o0, o1, o2, o3);
  hn::StoreU(o0, d, p);
  hn::StoreU(o1, d, p + n);
  hn::StoreU(o2, d, p + 2 * n);
  hn::StoreU(o3, d, p + 3 * n);
}

/// N per-element floats (t) in the fast paths' lane order: lane 4b + p <- p[B*p + b].
HWY_INLINE V load_scalar_blocked(const float* p) {
  const D d;
  constexpr std::size_t kN = hn::MaxLanes(D());
  if constexpr (kN <= 4) {
    return hn::LoadU(d, p);
  } else {
    static constexpr auto kIdx = [] {
      std::array<std::int32_t, kN> idx{};
      for (std::size_t l = 0; l < kN; ++l) idx[l] = static_cast<std::int32_t>((kN / 4) * (l % 4) + l / 4);
      return idx;
    }();
    return hn::TableLookupLanes(hn::LoadU(d, p), hn::SetTableIndices(d, kIdx.data()));
  }
}

/// Four vectors of B elements of a k = 4 blend (16B floats at q) regrouped by influence: out_j
/// holds influence j of the B elements, one quaternion per block. With one block per vector that
/// is four loads; AVX2 and AVX-512 need Highway's block transpose, the first half of its
/// LoadInterleaved4, which Highway 1.0.3 names only in detail:: (x86_256/x86_512-inl.h).
HWY_INLINE void load_by_influence(const float* q, V& o0, V& o1, V& o2, V& o3) {
  const D d;
#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX2
  hn::detail::LoadTransposedBlocks4(d, q, o0, o1, o2, o3);
#else
  const std::size_t n = hn::Lanes(d);
  o0 = hn::LoadU(d, q), o1 = hn::LoadU(d, q + n), o2 = hn::LoadU(d, q + 2 * n), o3 = hn::LoadU(d, q + 3 * n);
#endif
}

/// The four influences of N blends of k = 4 (16N floats, [q0 q1 q2 q3] per element) and their
/// weights (4N floats), in the fast paths' lane order: influence j of each group of B elements
/// (load_by_influence), then the in-block transpose across the four groups.
HWY_INLINE void load_blend4_blocked(const float* q, const float* w, Quat& q0, Quat& q1, Quat& q2, Quat& q3, V& w0,
                                    V& w1, V& w2, V& w3) {
  const D d;
  const std::size_t n = hn::Lanes(d);
  V g0[4], g1[4], g2[4], g3[4];  // g<group>[influence]
  load_by_influence(q, g0[0], g0[1], g0[2], g0[3]);
  load_by_influence(q + 4 * n, g1[0], g1[1], g1[2], g1[3]);
  load_by_influence(q + 8 * n, g2[0], g2[1], g2[2], g2[3]);
  load_by_influence(q + 12 * n, g3[0], g3[1], g3[2], g3[3]);
  transpose_in_blocks(g0[0], g1[0], g2[0], g3[0], q0.x, q0.y, q0.z, q0.w);
  transpose_in_blocks(g0[1], g1[1], g2[1], g3[1], q1.x, q1.y, q1.z, q1.w);
  transpose_in_blocks(g0[2], g1[2], g2[2], g3[2], q2.x, q2.y, q2.z, q2.w);
  transpose_in_blocks(g0[3], g1[3], g2[3], g3[3], q3.x, q3.y, q3.z, q3.w);
  transpose_in_blocks(hn::LoadU(d, w), hn::LoadU(d, w + n), hn::LoadU(d, w + 2 * n), hn::LoadU(d, w + 3 * n), w0, w1, w2,
                      w3);
}
#else
HWY_INLINE Quat load_quat_blocked(const float* p) { return load_quat(p); }
HWY_INLINE void store_quat_blocked(const Quat& q, float* p) { store_quat(q, p); }
HWY_INLINE V load_scalar_blocked(const float* p) { return hn::LoadU(D(), p); }
HWY_INLINE void load_blend4_blocked(const float* q, const float* w, Quat& q0, Quat& q1, Quat& q2, Quat& q3, V& w0,
                                    V& w1, V& w2, V& w3) {
  q0 = gather_quat(q, 4, 0), q1 = gather_quat(q, 4, 1), q2 = gather_quat(q, 4, 2), q3 = gather_quat(q, 4, 3);
  w0 = gather(w, 4, 0, 1, 0), w1 = gather(w, 4, 1, 1, 0), w2 = gather(w, 4, 2, 1, 0), w3 = gather(w, 4, 3, 1, 0);
}
#endif

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
/// underflow for subnormal x); the correction is scaled back exactly.
int ApplyVector(std::size_t n, const float* q, const float* v, float* out, std::uint8_t* status) {
  for_blocks<2>(n, {q, v}, {4, 3}, {kIdentity, kZero3}, out, 3, status,
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
  const Quat res = select(hn::Eq(omega, hn::Zero(d)), ua, fast_unit_of_scaled(r));
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

const Kernels* GetKernels() {
  static const Kernels k{hwy::TargetName(HWY_TARGET), HWY_TARGET, hn::Lanes(D()), &Normalize, &Compose, &ApplyVector,
                         &ToMatrix, &Log, &Exp, &Slerp, &Nlerp, &BlendQlb, &BlendLog};
  return &k;
}

}  // namespace rotorcert::rotor_simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

// ---- 3. dispatch -------------------------------------------------------------------------------
#if HWY_ONCE
namespace rotorcert::rotor_simd {

HWY_EXPORT(GetKernels);

namespace {

using GetKernelsFn = const Kernels* (*)();

/// Every target compiled into this file, worst first (HWY_CHOOSE_* is nullptr for a target
/// that this Highway build and compiler did not compile).
const GetKernelsFn kCompiled[] = {HWY_CHOOSE_FALLBACK(GetKernels), HWY_CHOOSE_SSSE3(GetKernels),
                                  HWY_CHOOSE_SSE4(GetKernels),     HWY_CHOOSE_AVX2(GetKernels),
                                  HWY_CHOOSE_AVX3(GetKernels),     HWY_CHOOSE_AVX3_DL(GetKernels)};
constexpr std::size_t kMaxTargets = sizeof(kCompiled) / sizeof(kCompiled[0]);

struct State {
  const Kernels* runnable[kMaxTargets] = {};  // compiled and supported by this CPU, worst first
  std::size_t count = 0;
  const Kernels* fallback_default = nullptr;  // Highway's own choice
  const Kernels* env_default = nullptr;       // ROTORCERT_SIMD_TARGET, if it names a runnable target
  const Kernels* narrowest = nullptr;         // the runnable SIMD target with the fewest lanes
  std::atomic<const Kernels*> active{nullptr};
  std::atomic<bool> forced{false};            // a target chosen by select_target or the environment
};

/// The names of the runnable targets, NULL-terminated (rc_impl::simd_targets). Filled once.
const char* g_target_names[kMaxTargets + 1] = {};

const Kernels* find(const State& s, const char* name) {
  for (std::size_t i = 0; i < s.count; ++i)
    if (std::strcmp(s.runnable[i]->name, name) == 0) return s.runnable[i];
  return nullptr;
}

State& state() {
  // A static object, not a heap one: State is trivially destructible, so nothing runs at exit,
  // and a dlclose'd plugin leaves nothing behind (a `new State` leaked 80 bytes per unload).
  static State s;
  static const bool filled = [] {
    State* st = &s;
    const std::int64_t supported = hwy::SupportedTargets();
    for (GetKernelsFn f : kCompiled) {
      if (f == nullptr) continue;
      const Kernels* k = f();
      const bool fallback = (k->target == HWY_SCALAR || k->target == HWY_EMU128);
      if (fallback || (supported & k->target) != 0) st->runnable[st->count++] = k;
    }
    for (std::size_t i = 0; i < st->count; ++i) {
      g_target_names[i] = st->runnable[i]->name;
      const Kernels* k = st->runnable[i];
      const bool simd = k->target != HWY_SCALAR && k->target != HWY_EMU128;
      if (simd && (st->narrowest == nullptr || k->lanes <= st->narrowest->lanes)) st->narrowest = k;  // best of the narrowest
    }
    st->fallback_default = HWY_DYNAMIC_DISPATCH(GetKernels)();
    if (const char* env = std::getenv("ROTORCERT_SIMD_TARGET"); env != nullptr && *env != '\0') {
      st->env_default = find(*st, env);
      if (st->env_default == nullptr)
        std::fprintf(stderr, "rotor_simd: ROTORCERT_SIMD_TARGET=%s is not a runnable target; using %s\n", env,
                     st->fallback_default->name);
    }
    st->active.store(st->env_default ? st->env_default : st->fallback_default);
    st->forced.store(st->env_default != nullptr);
    return true;
  }();
  (void)filled;
  return s;
}

// Fill the target list at load time (dlopen runs this too), so simd_targets is complete before
// any hook is called.
const bool g_init = (state(), true);

inline const Kernels& active() { return *state().active.load(std::memory_order_relaxed); }

/// Runs a batch as call(kernels, first, count): the whole batch on the active target, except that
/// with the default target a tail shorter than its block (n mod lanes elements; a single-element
/// call is all tail) runs on the narrowest SIMD target instead. A wide target computes a tail as
/// a whole padded block, 16 lanes on AVX-512 for one element; on 4 lanes that costs a quarter.
/// A forced target (select_target, ROTORCERT_SIMD_TARGET) runs everything itself, so that the
/// tests of each target see its own tail code.
template <class Call>
int split_tail(std::size_t n, const Call& call) {
  State& s = state();
  const Kernels& wide = *s.active.load(std::memory_order_relaxed);
  const Kernels* narrow = s.narrowest;
  if (s.forced.load(std::memory_order_relaxed) || narrow == nullptr || narrow->lanes >= wide.lanes)
    return call(wide, 0, n);
  const std::size_t full = n - n % wide.lanes;
  if (full != 0)
    if (const int rc = call(wide, 0, full); rc != 0) return rc;
  return full == n ? 0 : call(*narrow, full, n - full);
}

}  // namespace

/// The implementation struct behind the "rotor_simd" table (binary32).
struct RotorSimd {
  using Scalar = float;
  static constexpr const char* name = "rotor_simd";
  static constexpr const char* version = "1.0.0 (Google Highway 1.0.3)";
  static constexpr const char* description =
      "Batched SoA rotor kernels in binary32 on Google Highway with runtime dispatch "
      "(scalar/EMU128, SSSE3, SSE4, AVX2, AVX-512)";
  static constexpr std::uint32_t levels = RC_LEVEL_CORE | RC_LEVEL_INTERP | RC_LEVEL_BLEND | RC_LEVEL_ROBUST;
  static constexpr const char* const clauses[] = {
      "NORM-1",  "COMPOSE-1", "APPLY-1",    "APPLY-2",  "APPLY-3",   "MAT-1",   "LOG-1",   "LOG-2",
      "EXP-1",   "EXP-2",     "SLERP-1",    "SLERP-3",  "SLERP-4",   "SLERP-5", "NLERP-1", "QLB-1",
      "LOGBLEND-1", "EDGE-1", "EDGE-2",     "EDGE-3",   "EDGE-4",    "EDGE-5",  "EDGE-6",  "EDGE-7",
      "EDGE-8",  "EDGE-9",    nullptr};

  static int normalize_batch(std::size_t n, const float* q, float* out, std::uint8_t* status) {
    return split_tail(n, [&](const Kernels& k, std::size_t i, std::size_t m) {
      return k.normalize(m, q + 4 * i, out + 4 * i, status + i);
    });
  }
  static int compose_batch(std::size_t n, const float* a, const float* b, float* out, std::uint8_t* status) {
    return split_tail(n, [&](const Kernels& k, std::size_t i, std::size_t m) {
      return k.compose(m, a + 4 * i, b + 4 * i, out + 4 * i, status + i);
    });
  }
  static int apply_vector_batch(std::size_t n, const float* q, const float* v, float* out, std::uint8_t* status) {
    return split_tail(n, [&](const Kernels& k, std::size_t i, std::size_t m) {
      return k.apply_vector(m, q + 4 * i, v + 3 * i, out + 3 * i, status + i);
    });
  }
  static int apply_bivector_batch(std::size_t n, const float* q, const float* b, float* out, std::uint8_t* status) {
    return apply_vector_batch(n, q, b, out, status);  // I is central: R (I b) ~R = I (R b ~R)
  }
  /// APPLY-3: R (s I) ~R = s I for every rotor; only the domain is checked.
  static int apply_trivector_batch(std::size_t n, const float* q, const float* s, float* out, std::uint8_t* status) {
    for (std::size_t i = 0; i < n; ++i) {
      bool ok = std::isfinite(s[i]);
      bool nonzero = false;
      for (int c = 0; c < 4; ++c) {
        ok = ok && std::isfinite(q[i * 4 + c]);
        nonzero = nonzero || q[i * 4 + c] != 0;
      }
      ok = ok && nonzero;
      out[i] = ok ? s[i] : std::numeric_limits<float>::quiet_NaN();
      status[i] = ok ? RC_OK : RC_DOMAIN_ERROR;
    }
    return 0;
  }
  static int to_matrix_batch(std::size_t n, const float* q, float* out, std::uint8_t* status) {
    return split_tail(n, [&](const Kernels& k, std::size_t i, std::size_t m) {
      return k.to_matrix(m, q + 4 * i, out + 9 * i, status + i);
    });
  }
  static int log_batch(std::size_t n, const float* q, float* out, std::uint8_t* status) {
    return split_tail(n, [&](const Kernels& k, std::size_t i, std::size_t m) {
      return k.log(m, q + 4 * i, out + 3 * i, status + i);
    });
  }
  static int exp_batch(std::size_t n, const float* v, float* out, std::uint8_t* status) {
    return split_tail(n, [&](const Kernels& k, std::size_t i, std::size_t m) {
      return k.exp(m, v + 3 * i, out + 4 * i, status + i);
    });
  }
  static int slerp_batch(std::size_t n, const float* a, const float* b, const float* t, float* out,
                         std::uint8_t* status) {
    return split_tail(n, [&](const Kernels& k, std::size_t i, std::size_t m) {
      return k.slerp(m, a + 4 * i, b + 4 * i, t + i, out + 4 * i, status + i);
    });
  }
  static int nlerp_batch(std::size_t n, const float* a, const float* b, const float* t, float* out,
                         std::uint8_t* status) {
    return split_tail(n, [&](const Kernels& k, std::size_t i, std::size_t m) {
      return k.nlerp(m, a + 4 * i, b + 4 * i, t + i, out + 4 * i, status + i);
    });
  }
  static int blend_qlb_batch(std::size_t n, std::size_t k, const float* q, const float* w, float* out,
                             std::uint8_t* status) {
    try {
      return split_tail(n, [&](const Kernels& ks, std::size_t i, std::size_t m) {
        return ks.blend_qlb(m, k, q + 4 * k * i, w + k * i, out + 4 * i, status + i);
      });
    } catch (...) {  // the tail buffer could not be allocated
      return 1;
    }
  }
  static int blend_log_batch(std::size_t n, std::size_t k, const float* q, const float* w, float* out,
                             std::uint8_t* status) {
    try {
      return split_tail(n, [&](const Kernels& ks, std::size_t i, std::size_t m) {
        return ks.blend_log(m, k, q + 4 * k * i, w + k * i, out + 4 * i, status + i);
      });
    } catch (...) {
      return 1;
    }
  }

  // SIMD dispatch hooks (rc_impl): the list is filled at load time.
  static constexpr const char* const* simd_targets = g_target_names;
  static int select_target(const char* target) {
    State& s = state();
    if (target == nullptr) {
      s.active.store(s.env_default ? s.env_default : s.fallback_default);
      s.forced.store(s.env_default != nullptr);
      return 0;
    }
    const Kernels* k = find(s, target);
    if (k == nullptr) return 1;
    s.active.store(k);
    s.forced.store(true);
    return 0;
  }
  static const char* current_target() { return active().name; }
};

}  // namespace rotorcert::rotor_simd

ROTORCERT_DEFINE_ENTRY(rotor_simd, ::rotorcert::rotor_simd::RotorSimd)

#endif  // HWY_ONCE
