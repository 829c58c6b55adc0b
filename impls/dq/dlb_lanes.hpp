// DQ-6 (DLB), DQ-3, DQ-4, DQ-2 and DQ-1 for L elements of a batch at once, in SoA lanes that the
// compiler turns into SIMD: the fast paths of dq.cpp's dq_blend_batch, dq_apply_point_batch,
// dq_normalize_batch, dq_compose_batch and dq_from_rotation_translation_batch for ordinary input,
// kept apart from the scalar math (dq.cpp) in the manner of ozz-animation's SoA jobs.
//
// Data: the ABI's AoS arrays in (element e: k influences of [real xyzw, dual xyzw] at
// d + 8 k e, k weights at w + k e) are copied influence by influence into lane arrays
// x[component][lane], component 0..3 the real part's x, y, z, w and 4..7 the dual part's, or (the
// kernels of dq_normalize, dq_compose and dq_from_rotation_translation) read in place in the loop
// over lanes; outputs go to out[component][lane].
//
// Every lane computes exactly what dq.cpp's element path computes for its element (dlb_ordinary(),
// normalized_ordinary(), the Dual product, apply_point(), from_rotation_translation()): the same
// IEEE operations (+, -, *, /, sqrt, each correctly rounded, in SIMD as in scalar code) in the
// same order, so the same bits. Where dq.cpp would leave that path (a cheap test fails), the
// lane's `ok` is false and the caller takes the checked path for that element; the lane's
// other values are then meaningless (they may be NaN or inf: no trap, no errno, see
// CMakeLists.txt: -fno-math-errno lets sqrt vectorise, -ffp-contract=off keeps a * b + c two
// roundings, as in the scalar code). No branch depends on a lane's value, so that the loops
// vectorise.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include <rotorcert/runtime/exact_sign.hpp>
#include <rotorcert/runtime/lane_store.hpp>
#include <rotorcert/runtime/lane_weights.hpp>
#include <rotorcert/runtime/ordinary_range.hpp>

namespace rotorcert::dq_lanes {

template <class S, std::size_t L>
struct DlbLanes {
  /// A lane flag, 1 or 0: bool arrays do not vectorise.
  using Flag = std::int32_t;

  S out[8][L];  // DQ-4 of the weighted sum, where ok
  Flag ok[L];

  /// The L elements starting at d (influences) and w (weights), k >= 1 influences each.
  void run(std::size_t k, const S* d, const S* w) {
    constexpr S kMax = std::numeric_limits<S>::max();
    constexpr S kLo = runtime::OrdinaryRange<S>::kLo, kHi = runtime::OrdinaryRange<S>::kHi;
    runtime::LaneWeights<S, L> weights;  // EDGE-9
    weights.scan(k, w);
    S pivot[4][L], sum[8][L];
    for (std::size_t l = 0; l < L; ++l) {
      ok[l] = weights.ok[l];
      const std::size_t at = weights.pivot_offset(k, 8, l);
      for (std::size_t c = 0; c < 4; ++c) pivot[c][l] = d[at + c];
      for (std::size_t c = 0; c < 8; ++c) sum[c][l] = 0;
    }

    S x[8][L];
    for (std::size_t i = 0; i < k; ++i) {
      for (std::size_t l = 0; l < L; ++l)
        for (std::size_t c = 0; c < 8; ++c) x[c][l] = d[8 * k * l + 8 * i + c];
      for (std::size_t l = 0; l < L; ++l) {
        // DQ-4 of the influence (dq.cpp normalized_ordinary), dots in x, y, z, w order.
        const S r2 = x[0][l] * x[0][l] + x[1][l] * x[1][l] + x[2][l] * x[2][l] + x[3][l] * x[3][l];
        const S d2 = x[4][l] * x[4][l] + x[5][l] * x[5][l] + x[6][l] * x[6][l] + x[7][l] * x[7][l];
        bool good = (r2 >= kLo) & (r2 <= kHi) & ((d2 == 0) | ((d2 >= kLo) & (d2 <= kHi)));
        const S n = std::sqrt(r2);
        const S u0 = x[0][l] / n, u1 = x[1][l] / n, u2 = x[2][l] / n, u3 = x[3][l] / n;
        const S along = u0 * x[4][l] + u1 * x[5][l] + u2 * x[6][l] + u3 * x[7][l];
        good = good & (d2 <= kMax) & !(along * along > S(0.9375) * d2);  // runtime::projection_cancels
        const S v0 = (x[4][l] - along * u0) / n, v1 = (x[5][l] - along * u1) / n;
        const S v2 = (x[6][l] - along * u2) / n, v3 = (x[7][l] - along * u3) / n;
        // The hemisphere sign by the filter of runtime::filtered_dot_sign<S, 4>, undecided -> not ok.
        bool negative;
        const bool decided = runtime::filtered_dot4_lane(x[0][l], x[1][l], x[2][l], x[3][l], pivot[0][l], pivot[1][l],
                                                         pivot[2][l], pivot[3][l], negative);
        good = good & decided;
        const S f0 = w[k * l + i] / weights.w_max[l];
        const S f = negative ? -f0 : f0;
        sum[0][l] = sum[0][l] + f * u0;
        sum[1][l] = sum[1][l] + f * u1;
        sum[2][l] = sum[2][l] + f * u2;
        sum[3][l] = sum[3][l] + f * u3;
        sum[4][l] = sum[4][l] + f * v0;
        sum[5][l] = sum[5][l] + f * v1;
        sum[6][l] = sum[6][l] + f * v2;
        sum[7][l] = sum[7][l] + f * v3;
        ok[l] = ok[l] & Flag(good);
      }
    }

    // DQ-4 of the sum, where it is ordinary and its projection does not cancel (else not ok: the
    // checked path normalises with scaling or without the subtraction).
    for (std::size_t l = 0; l < L; ++l) {
      const S r2 = sum[0][l] * sum[0][l] + sum[1][l] * sum[1][l] + sum[2][l] * sum[2][l] + sum[3][l] * sum[3][l];
      const S d2 = sum[4][l] * sum[4][l] + sum[5][l] * sum[5][l] + sum[6][l] * sum[6][l] + sum[7][l] * sum[7][l];
      const bool good = (r2 >= kLo) & (r2 <= kHi) & ((d2 == 0) | ((d2 >= kLo) & (d2 <= kHi)));
      const S n = std::sqrt(r2);
      const S u0 = sum[0][l] / n, u1 = sum[1][l] / n, u2 = sum[2][l] / n, u3 = sum[3][l] / n;
      const S along = u0 * sum[4][l] + u1 * sum[5][l] + u2 * sum[6][l] + u3 * sum[7][l];
      ok[l] = ok[l] & Flag(good & (d2 <= kMax) & !(along * along > S(0.9375) * d2));
      out[0][l] = u0;
      out[1][l] = u1;
      out[2][l] = u2;
      out[3][l] = u3;
      out[4][l] = (sum[4][l] - along * u0) / n;
      out[5][l] = (sum[5][l] - along * u1) / n;
      out[6][l] = (sum[6][l] - along * u2) / n;
      out[7][l] = (sum[7][l] - along * u3) / n;
    }
  }
};

/// DQ-3 for L elements of a dq_apply_point batch at once: dq.cpp's apply_point() (divide both
/// parts by |r|, rotate, add the translation) on elements whose |r|^2 is ordinary and |d|^2
/// ordinary or 0 (then safely_scaled() is the identity and every component is finite) and whose
/// point is finite; the same operations in the same order, so the same bits. Data: element e's
/// dual quaternion at d + 8 e, its point at p + 3 e (the ABI arrays).
template <class S, std::size_t L>
struct ApplyPointLanes {
  using Flag = std::int32_t;

  S out[3][L];  // R p + t, where ok
  Flag ok[L];

  void run(const S* d, const S* p) {
    constexpr S kLo = runtime::OrdinaryRange<S>::kLo, kHi = runtime::OrdinaryRange<S>::kHi;
    S x[8][L], v[3][L];
    for (std::size_t l = 0; l < L; ++l) {
      for (std::size_t c = 0; c < 8; ++c) x[c][l] = d[8 * l + c];
      for (std::size_t c = 0; c < 3; ++c) v[c][l] = p[3 * l + c];
    }
    for (std::size_t l = 0; l < L; ++l) {
      const S r2 = x[0][l] * x[0][l] + x[1][l] * x[1][l] + x[2][l] * x[2][l] + x[3][l] * x[3][l];
      const S d2 = x[4][l] * x[4][l] + x[5][l] * x[5][l] + x[6][l] * x[6][l] + x[7][l] * x[7][l];
      const bool finite_point = runtime::finite3_lane(v[0][l], v[1][l], v[2][l]);
      ok[l] = Flag((r2 >= kLo) & (r2 <= kHi) & ((d2 == 0) | ((d2 >= kLo) & (d2 <= kHi))) & finite_point);
      const S n = std::sqrt(r2);
      const S ux = x[0][l] / n, uy = x[1][l] / n, uz = x[2][l] / n, uw = x[3][l] / n;
      const S dx = x[4][l] / n, dy = x[5][l] / n, dz = x[6][l] / n, dw = x[7][l] / n;
      const S px = v[0][l], py = v[1][l], pz = v[2][l];
      // rotate(): t = 2 (u x p), p + w t + u x t.
      const S tx = S(2) * (uy * pz - uz * py), ty = S(2) * (uz * px - ux * pz), tz = S(2) * (ux * py - uy * px);
      const S rx = px + uw * tx + (uy * tz - uz * ty);
      const S ry = py + uw * ty + (uz * tx - ux * tz);
      const S rz = pz + uw * tz + (ux * ty - uy * tx);
      // translation(): 2 (r_w d_v - d_w r_v + r_v x d_v).
      const S sx = S(2) * (uw * dx - dw * ux + (uy * dz - uz * dy));
      const S sy = S(2) * (uw * dy - dw * uy + (uz * dx - ux * dz));
      const S sz = S(2) * (uw * dz - dw * uz + (ux * dy - uy * dx));
      out[0][l] = rx + sx;
      out[1][l] = ry + sy;
      out[2][l] = rz + sz;
    }
  }
};

/// dq.cpp's normalized_ordinary() (DQ-4: r' = r / |r|, d' = (d - (r'.d) r') / |r|) of the ABI
/// dual quaternion at x, into u; returns the lane's test: |r|^2 ordinary, |d|^2 ordinary or 0
/// (then every component is finite, r != 0 and safely_scaled() is the identity), and a projection
/// that does not cancel (runtime::projection_cancels). The kernels below call it on x = d + 8 l in
/// their loop over lanes l, reading the ABI array in place: the vectoriser turns those reads into
/// vector loads and shuffles (at n = 4096, 8 to 22% faster than a copy into lane arrays first).
template <class S>
[[gnu::always_inline]] inline bool normalized_lane(const S* x, S (&u)[8]) {
  constexpr S kMax = std::numeric_limits<S>::max();
  constexpr S kLo = runtime::OrdinaryRange<S>::kLo, kHi = runtime::OrdinaryRange<S>::kHi;
  const S x0 = x[0], x1 = x[1], x2 = x[2], x3 = x[3], x4 = x[4], x5 = x[5], x6 = x[6], x7 = x[7];
  const S r2 = x0 * x0 + x1 * x1 + x2 * x2 + x3 * x3;
  const S d2 = x4 * x4 + x5 * x5 + x6 * x6 + x7 * x7;
  const S n = std::sqrt(r2);
  u[0] = x0 / n;
  u[1] = x1 / n;
  u[2] = x2 / n;
  u[3] = x3 / n;
  const S along = u[0] * x4 + u[1] * x5 + u[2] * x6 + u[3] * x7;
  u[4] = (x4 - along * u[0]) / n;
  u[5] = (x5 - along * u[1]) / n;
  u[6] = (x6 - along * u[2]) / n;
  u[7] = (x7 - along * u[3]) / n;
  return (r2 >= kLo) & (r2 <= kHi) & ((d2 == 0) | ((d2 >= kLo) & (d2 <= kHi))) & (d2 <= kMax) &
         !(along * along > S(0.9375) * d2);
}

/// The Hamilton product a b (QUAT-1, dq.cpp's operator*), term by term in its order.
template <class S>
[[gnu::always_inline]] inline void product_lane(S ax, S ay, S az, S aw, S bx, S by, S bz, S bw, S& x, S& y, S& z,
                                                S& w) {
  x = aw * bx + ax * bw + ay * bz - az * by;
  y = aw * by - ax * bz + ay * bw + az * bx;
  z = aw * bz + ax * by - ay * bx + az * bw;
  w = aw * bw - ax * bx - ay * by - az * bz;
}

/// DQ-4 for L elements of a dq_normalize batch: dq.cpp's Dq::dq_normalize() where
/// normalized_ordinary() takes the element (the checks it passes then are implied by the test).
template <class S, std::size_t L>
struct DqNormalizeLanes {
  using Flag = std::int32_t;

  S out[8][L];  // DQ-4 of the input, where ok
  Flag ok[L];

  void run(const S* d, const S* /*unused*/) {
    for (std::size_t l = 0; l < L; ++l) {
      S u[8];
      ok[l] = Flag(normalized_lane(d + 8 * l, u));
      runtime::store_lane(u, l, out);
    }
  }
};

/// DQ-2 for L elements of a dq_compose batch: dq.cpp's Dq::dq_compose(), the product
/// (a_r b_r) + eps (a_r b_d + a_d b_r) of both inputs' normalized_ordinary() (DQ-4), where both
/// take that path.
template <class S, std::size_t L>
struct DqComposeLanes {
  using Flag = std::int32_t;

  S out[8][L];  // the product of the DQ-4 normalised inputs, where ok
  Flag ok[L];

  void run(const S* a, const S* b) {
    for (std::size_t l = 0; l < L; ++l) {
      S p[8], q[8];
      const bool good_a = normalized_lane(a + 8 * l, p);
      const bool good_b = normalized_lane(b + 8 * l, q);
      ok[l] = Flag(good_a & good_b);
      S rx, ry, rz, rw, sx, sy, sz, sw, tx, ty, tz, tw;
      product_lane(p[0], p[1], p[2], p[3], q[0], q[1], q[2], q[3], rx, ry, rz, rw);  // a_r b_r
      product_lane(p[0], p[1], p[2], p[3], q[4], q[5], q[6], q[7], sx, sy, sz, sw);  // a_r b_d
      product_lane(p[4], p[5], p[6], p[7], q[0], q[1], q[2], q[3], tx, ty, tz, tw);  // a_d b_r
      out[0][l] = rx;
      out[1][l] = ry;
      out[2][l] = rz;
      out[3][l] = rw;
      out[4][l] = sx + tx;
      out[5][l] = sy + ty;
      out[6][l] = sz + tz;
      out[7][l] = sw + tw;
    }
  }
};

/// DQ-1 for L elements of a dq_from_rotation_translation batch: dq.cpp's
/// Dq::dq_from_rotation_translation() where |q|^2 is ordinary (normalized() then divides by its
/// sqrt unscaled) and t is finite: (r, 1/2 t r) with r = q / |q|, t r = (-t.v, w t + t x v).
/// Data: element e's quaternion at q + 4 e, its translation at t + 3 e (the ABI arrays, read in
/// place as normalized_lane() does).
template <class S, std::size_t L>
struct FromRotationTranslationLanes {
  using Flag = std::int32_t;

  S out[8][L];  // the unit dual quaternion, where ok
  Flag ok[L];

  void run(const S* q, const S* t) {
    for (std::size_t l = 0; l < L; ++l) {
      const S qx = q[4 * l], qy = q[4 * l + 1], qz = q[4 * l + 2], qw = q[4 * l + 3];
      const S tx = t[3 * l], ty = t[3 * l + 1], tz = t[3 * l + 2];
      const S n2 = qx * qx + qy * qy + qz * qz + qw * qw;
      const bool ordinary_q = runtime::is_ordinary_square_lane(n2);
      const bool finite_t = runtime::finite3_lane(tx, ty, tz);
      ok[l] = Flag(ordinary_q & finite_t);
      const S n = std::sqrt(n2);
      const S ux = qx / n, uy = qy / n, uz = qz / n, uw = qw / n;
      out[0][l] = ux;
      out[1][l] = uy;
      out[2][l] = uz;
      out[3][l] = uw;
      // 1/2 (w t + t x v), then -1/2 t.v, as from_rotation_translation() groups them.
      out[4][l] = S(0.5) * (uw * tx + (ty * uz - tz * uy));
      out[5][l] = S(0.5) * (uw * ty + (tz * ux - tx * uz));
      out[6][l] = S(0.5) * (uw * tz + (tx * uy - ty * ux));
      out[7][l] = S(-0.5) * (tx * ux + ty * uy + tz * uz);
    }
  }
};

}  // namespace rotorcert::dq_lanes
