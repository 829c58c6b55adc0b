// The frame benchmarks' vertex loops (REPORT-2: one loop per technique, the same for every
// method), SIMD across vertices on Google Highway with dynamic dispatch (the best target of this
// CPU), so that the vertices cost what a tuned engine pays and the rotation libraries' share of
// the frame is not hidden behind slow suite code.
//
// Layout (laid out once by FrameJob::prepare, SoA so that a vector of lanes holds consecutive
// vertices; `count` is padded to a multiple of kVertexPad with vertices of weight (1, 0, 0, 0)
// on palette entry 0, so that the kernels only ever see whole vectors):
//
//   offset[k][v]            influence k of vertex v: index of its first scalar in the palette
//                           (12 j for LBS matrices, 8 j for DQS dual quaternions, j its joint)
//   weight[k][v]            w_k / W
//   position[c][v], normal[c][v]           bind-space coordinate c (x, y, z)
//   position_out[c][v], normal_out[c][v]   skinned coordinate c
//
// Palettes (AoS, one entry per joint):
//   LBS  12 scalars [R K_b | t] column-major: m[3 c + r] is row r of column c, t at m[9 + r]
//   DQS  8 scalars [x y z w | dx dy dz dw]: the skinning dual quaternion q_r + eps q_d (DQ-1)
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace rotorcert::bench::vertices {

/// Vertex counts are padded to a multiple of this (the widest vector of any target: 2048-bit
/// SVE holds 64 floats).
inline constexpr std::size_t kVertexPad = 64;

/// Gather indices have the width of the scalar (Highway's GatherIndex).
template <class S>
using Offset = std::conditional_t<std::is_same_v<S, float>, std::int32_t, std::int64_t>;

template <class S>
struct Streams {
  std::size_t count = 0;  // a multiple of kVertexPad
  const Offset<S>* offset[4] = {};
  const S* weight[4] = {};
  const S* position[3] = {};
  const S* normal[3] = {};
  S* position_out[3] = {};
  S* normal_out[3] = {};
};

/// LBS: m = sum_k w_k M_k over the 4 influences' 3x4 matrices; p' = m [p, 1], n' = m [n, 0].
void skin_lbs(const Streams<float>& v, const float* palette);
void skin_lbs(const Streams<double>& v, const double* palette);

/// DQS (Kavan et al. 2008, Algorithm 1): b = sum_k s_k w_k sigma_k with s_k = -1 iff the real
/// parts' dot with the pivot's (the first influence of weight > 0; DQ-6) is < 0; then
/// p' = R p + t and n' = R n with R and t of b / |b_r| (DQ-3).
void skin_dqs(const Streams<float>& v, const float* palette);
void skin_dqs(const Streams<double>& v, const double* palette);

}  // namespace rotorcert::bench::vertices
