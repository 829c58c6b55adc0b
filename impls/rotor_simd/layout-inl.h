// rotor_simd, per target: the vector types, the SoA layout of quaternions and vectors, and the
// only functions that touch the ABI's AoS arrays (loads, stores, gathers, padded tails, the fast
// paths' in-block transpose). Included once per Highway target from rotor_simd.cpp.
#if defined(ROTORCERT_ROTOR_SIMD_LAYOUT_INL_H_) == defined(HWY_TARGET_TOGGLE)  // per-target include guard
#ifdef ROTORCERT_ROTOR_SIMD_LAYOUT_INL_H_
#undef ROTORCERT_ROTOR_SIMD_LAYOUT_INL_H_
#else
#define ROTORCERT_ROTOR_SIMD_LAYOUT_INL_H_
#endif

#include <hwy/highway.h>

#include "rotor_simd/shared.hpp"

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
constexpr float kUnitZ[3] = {0, 0, 1};

/// Runs block(in-pointers, out-pointers, status) over n elements: full blocks in place, the tail
/// through padded copies. `in_width` / `fill` describe each input array, `out_width` each output
/// array (to_axis_angle has two: the angle and the axis).
template <std::size_t kIns, std::size_t kOuts, class Block>
HWY_INLINE void for_blocks(std::size_t n, const float* const (&in)[kIns], const std::size_t (&in_width)[kIns],
                           const float* const (&fill)[kIns], float* const (&out)[kOuts],
                           const std::size_t (&out_width)[kOuts], std::uint8_t* status, const Block& block) {
  const std::size_t lanes = hn::Lanes(D());
  std::size_t i = 0;
  for (; i + lanes <= n; i += lanes) {
    const float* p[kIns];
    float* o[kOuts];
    for (std::size_t a = 0; a < kIns; ++a) p[a] = in[a] + i * in_width[a];
    for (std::size_t a = 0; a < kOuts; ++a) o[a] = out[a] + i * out_width[a];
    block(p, o, status + i);
  }
  if (i == n) return;
  const std::size_t count = n - i;
  Padded pads[kIns];
  const float* p[kIns];
  for (std::size_t a = 0; a < kIns; ++a) p[a] = pads[a].from(in[a] + i * in_width[a], count, in_width[a], fill[a]);
  HWY_ALIGN float tail[kOuts][16 * kMaxLanes];
  float* o[kOuts];
  for (std::size_t a = 0; a < kOuts; ++a) o[a] = tail[a];
  std::uint8_t s[kMaxLanes];
  block(p, o, s);
  for (std::size_t a = 0; a < kOuts; ++a) std::memcpy(out[a] + i * out_width[a], tail[a], count * out_width[a] * sizeof(float));
  std::memcpy(status + i, s, count);
}

/// The same with one output array: block(in-pointers, out-pointer, status).
template <std::size_t kIns, class Block>
HWY_INLINE void for_blocks(std::size_t n, const float* const (&in)[kIns], const std::size_t (&in_width)[kIns],
                           const float* const (&fill)[kIns], float* out, std::size_t out_width,
                           std::uint8_t* status, const Block& block) {
  for_blocks<kIns, 1>(n, in, in_width, fill, {out}, {out_width}, status,
                      [&](const float* const* p, float* const* o, std::uint8_t* s) ROTORCERT_SIMD_INLINE {
                        block(p, o[0], s);
                      });
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

}  // namespace rotorcert::rotor_simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // ROTORCERT_ROTOR_SIMD_LAYOUT_INL_H_
