// DQ-6 (DLB), DQ-3, DQ-4, DQ-2, DQ-1, SKIN-2, SKIN-1 and AXIS-1 for L elements of a batch at once,
// in SoA lanes that the compiler turns into SIMD: the fast paths of dq.cpp's dq_blend_batch,
// dq_apply_point_batch, dq_normalize_batch, dq_compose_batch, dq_from_rotation_translation_batch,
// skin_dual_quaternion_batch, skin_linear_batch and rotate_about_axis_batch for ordinary input,
// kept apart from the scalar math (dq.cpp) in the manner of ozz-animation's SoA jobs.
//
// Data: the ABI's AoS arrays in (element e: k influences of [real xyzw, dual xyzw] at
// d + 8 k e, k weights at w + k e) are copied influence by influence into lane arrays
// x[component][lane], component 0..3 the real part's x, y, z, w and 4..7 the dual part's, or (the
// kernels of dq_normalize, dq_compose and dq_from_rotation_translation) read in place in the loop
// over lanes; the skinning kernels copy rotations q + 4 k e and translations t + 3 k e influence by
// influence the same way; outputs go to out[component][lane].
//
// Every lane computes exactly what dq.cpp's element path computes for its element (dlb_ordinary(),
// normalized_ordinary(), the Dual product, apply_point(), from_rotation_translation(), dlb(),
// skin_linear(), rotate_about_axis()): the same IEEE operations (+, -, *, /, sqrt, each correctly
// rounded, in SIMD as in scalar code) in the same order, so the same bits; AXIS-1's sin and cos are
// the element function's libm calls, made lane by lane between the vectorised loops. Where dq.cpp would leave that path (a cheap test fails), the
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
#include <rotorcert/runtime/axis_angle_lanes.hpp>
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

/// dq.cpp's rotate(u_r, p) + translation(u) of the dual quaternion u = (u_r, u_d) (DQ-3 on a
/// unit one, AXIS-1's last step) into lane l of out, term by term in their order.
template <class S, std::size_t L>
[[gnu::always_inline]] inline void moved_point_lane(const S (&u)[8], S px, S py, S pz, std::size_t l, S (&out)[3][L]) {
  const S ux = u[0], uy = u[1], uz = u[2], uw = u[3], dx = u[4], dy = u[5], dz = u[6], dw = u[7];
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
      const S u[8] = {x[0][l] / n, x[1][l] / n, x[2][l] / n, x[3][l] / n,
                      x[4][l] / n, x[5][l] / n, x[6][l] / n, x[7][l] / n};
      moved_point_lane(u, v[0][l], v[1][l], v[2][l], l, out);
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

/// The unit dual quaternion of dq.cpp's from_rotation_translation(q / |q|, t) (DQ-1) into u, for a
/// quaternion whose n2 = |q|^2 is ordinary (normalized() then divides by its sqrt unscaled): the
/// operations of FromRotationTranslationLanes.
template <class S>
[[gnu::always_inline]] inline void rigid_lane(S qx, S qy, S qz, S qw, S n2, S tx, S ty, S tz, S (&u)[8]) {
  const S n = std::sqrt(n2);
  const S ux = qx / n, uy = qy / n, uz = qz / n, uw = qw / n;
  u[0] = ux;
  u[1] = uy;
  u[2] = uz;
  u[3] = uw;
  u[4] = S(0.5) * (uw * tx + (ty * uz - tz * uy));
  u[5] = S(0.5) * (uw * ty + (tz * ux - tx * uz));
  u[6] = S(0.5) * (uw * tz + (tx * uy - ty * ux));
  u[7] = S(-0.5) * (tx * ux + ty * uy + tz * uz);
}

/// SKIN-2 for L elements of a skin_dual_quaternion batch: dq.cpp's Dq::skin_dual_quaternion()
/// (DQ-1 of each influence, dlb() against the pivot, DQ-3 of the vertex) where the weights pass
/// EDGE-9's tests (runtime::LaneWeights), the vertex and every translation are finite, every
/// |q_i|^2 is ordinary, the filter decides every hemisphere sign (EDGE-3) and the sum's DQ-4 takes
/// normalized_ordinary(). Data: element e's k rotations at q + 4 k e, translations at t + 3 k e,
/// weights at w + k e, vertex at v + 3 e (the ABI arrays).
template <class S, std::size_t L>
struct SkinDualQuaternionLanes {
  using Flag = std::int32_t;

  S out[3][L];  // the skinned vertex, where ok
  Flag ok[L];

  void run(std::size_t k, const S* q, const S* t, const S* w, const S* v) {
    runtime::LaneWeights<S, L> weights;  // EDGE-9
    weights.scan(k, w);
    S pivot[4][L], sum[8][L], p[3][L];
    for (std::size_t l = 0; l < L; ++l) {
      const std::size_t at = weights.pivot_offset(k, 4, l);
      for (std::size_t c = 0; c < 4; ++c) pivot[c][l] = q[at + c];
      for (std::size_t c = 0; c < 3; ++c) p[c][l] = v[3 * l + c];
      for (std::size_t c = 0; c < 8; ++c) sum[c][l] = 0;
    }
    for (std::size_t l = 0; l < L; ++l) ok[l] = weights.ok[l] & Flag(runtime::finite3_lane(p[0][l], p[1][l], p[2][l]));
    S x[4][L], tr[3][L];
    for (std::size_t i = 0; i < k; ++i) {
      for (std::size_t l = 0; l < L; ++l) {
        for (std::size_t c = 0; c < 4; ++c) x[c][l] = q[4 * k * l + 4 * i + c];
        for (std::size_t c = 0; c < 3; ++c) tr[c][l] = t[3 * k * l + 3 * i + c];
      }
      for (std::size_t l = 0; l < L; ++l) {
        const S n2 = x[0][l] * x[0][l] + x[1][l] * x[1][l] + x[2][l] * x[2][l] + x[3][l] * x[3][l];
        const bool ordinary = runtime::is_ordinary_square_lane(n2);
        const bool finite_t = runtime::finite3_lane(tr[0][l], tr[1][l], tr[2][l]);
        S u[8];
        rigid_lane(x[0][l], x[1][l], x[2][l], x[3][l], n2, tr[0][l], tr[1][l], tr[2][l], u);
        // dlb()'s hemisphere_dot(q_i, q_p) by the filter of runtime::filtered_dot_sign<S, 4>,
        // undecided -> not ok (the exact sum is the checked path's).
        bool negative;
        const bool decided = runtime::filtered_dot4_lane(x[0][l], x[1][l], x[2][l], x[3][l], pivot[0][l], pivot[1][l],
                                                         pivot[2][l], pivot[3][l], negative);
        const S f0 = w[k * l + i] / weights.w_max[l];
        const S f = negative ? -f0 : f0;
        sum[0][l] = sum[0][l] + f * u[0];  // written out: a loop over c here keeps l's loop scalar
        sum[1][l] = sum[1][l] + f * u[1];
        sum[2][l] = sum[2][l] + f * u[2];
        sum[3][l] = sum[3][l] + f * u[3];
        sum[4][l] = sum[4][l] + f * u[4];
        sum[5][l] = sum[5][l] + f * u[5];
        sum[6][l] = sum[6][l] + f * u[6];
        sum[7][l] = sum[7][l] + f * u[7];
        ok[l] = ok[l] & Flag(ordinary & finite_t & decided);
      }
    }
    for (std::size_t l = 0; l < L; ++l) {
      const S s[8] = {sum[0][l], sum[1][l], sum[2][l], sum[3][l], sum[4][l], sum[5][l], sum[6][l], sum[7][l]};
      S u[8];
      ok[l] = ok[l] & Flag(normalized_lane(s, u));  // DQ-4 of the sum
      moved_point_lane(u, p[0][l], p[1][l], p[2][l], l, out);
    }
  }
};

/// SKIN-1 for L elements of a skin_linear batch: dq.cpp's Dq::skin_linear() (the sum of
/// (w_i / w_max) MAT-1(q_i / |q_i|) and of (w_i / w_max) t_i, applied to v, divided by the sum of
/// the w_i / w_max) where the weights pass EDGE-9's tests, the vertex and every translation are
/// finite and every |q_i|^2 is ordinary. Data as SkinDualQuaternionLanes.
template <class S, std::size_t L>
struct SkinLinearLanes {
  using Flag = std::int32_t;

  S out[3][L];  // the skinned vertex, where ok
  Flag ok[L];

  void run(std::size_t k, const S* q, const S* t, const S* w, const S* v) {
    runtime::LaneWeights<S, L> weights;  // EDGE-9
    weights.scan(k, w);
    S m[9][L], tsum[3][L], total[L], p[3][L];
    for (std::size_t l = 0; l < L; ++l) {
      for (std::size_t c = 0; c < 3; ++c) p[c][l] = v[3 * l + c];
      for (std::size_t c = 0; c < 9; ++c) m[c][l] = 0;
      for (std::size_t c = 0; c < 3; ++c) tsum[c][l] = 0;
      total[l] = 0;
    }
    for (std::size_t l = 0; l < L; ++l) ok[l] = weights.ok[l] & Flag(runtime::finite3_lane(p[0][l], p[1][l], p[2][l]));
    S x[4][L], tr[3][L];
    for (std::size_t i = 0; i < k; ++i) {
      for (std::size_t l = 0; l < L; ++l) {
        for (std::size_t c = 0; c < 4; ++c) x[c][l] = q[4 * k * l + 4 * i + c];
        for (std::size_t c = 0; c < 3; ++c) tr[c][l] = t[3 * k * l + 3 * i + c];
      }
      for (std::size_t l = 0; l < L; ++l) {
        const S n2 = x[0][l] * x[0][l] + x[1][l] * x[1][l] + x[2][l] * x[2][l] + x[3][l] * x[3][l];
        const bool ordinary = runtime::is_ordinary_square_lane(n2);
        const bool finite_t = runtime::finite3_lane(tr[0][l], tr[1][l], tr[2][l]);
        ok[l] = ok[l] & Flag(ordinary & finite_t);
        const S f = w[k * l + i] / weights.w_max[l];
        const S n = std::sqrt(n2);
        const S rx = x[0][l] / n, ry = x[1][l] / n, rz = x[2][l] / n, rw = x[3][l] / n;
        const S xx = rx * rx, yy = ry * ry, zz = rz * rz, xy = rx * ry, xz = rx * rz, yz = ry * rz;
        const S wx = rw * rx, wy = rw * ry, wz = rw * rz;
        m[0][l] = m[0][l] + f * (S(1) - S(2) * (yy + zz));
        m[1][l] = m[1][l] + f * (S(2) * (xy + wz));
        m[2][l] = m[2][l] + f * (S(2) * (xz - wy));
        m[3][l] = m[3][l] + f * (S(2) * (xy - wz));
        m[4][l] = m[4][l] + f * (S(1) - S(2) * (xx + zz));
        m[5][l] = m[5][l] + f * (S(2) * (yz + wx));
        m[6][l] = m[6][l] + f * (S(2) * (xz + wy));
        m[7][l] = m[7][l] + f * (S(2) * (yz - wx));
        m[8][l] = m[8][l] + f * (S(1) - S(2) * (xx + yy));
        tsum[0][l] = tsum[0][l] + f * tr[0][l];
        tsum[1][l] = tsum[1][l] + f * tr[1][l];
        tsum[2][l] = tsum[2][l] + f * tr[2][l];
        total[l] = total[l] + f;
      }
    }
    for (std::size_t l = 0; l < L; ++l) {
      const S vx = p[0][l], vy = p[1][l], vz = p[2][l];
      const S mvx = m[0][l] * vx + m[3][l] * vy + m[6][l] * vz;
      const S mvy = m[1][l] * vx + m[4][l] * vy + m[7][l] * vz;
      const S mvz = m[2][l] * vx + m[5][l] * vy + m[8][l] * vz;
      const S inv = S(1) / total[l];
      out[0][l] = inv * (mvx + tsum[0][l]);
      out[1][l] = inv * (mvy + tsum[1][l]);
      out[2][l] = inv * (mvz + tsum[2][l]);
    }
  }
};

/// AXIS-1 for L elements of a rotate_about_axis batch: dq.cpp's Dq::rotate_about_axis() (q = (sin
/// h u/|u|, cos h) with h = angle / 2, sigma = (q, 1/2 (c q - q c)), DQ-3 of the point) where the
/// centre, angle and point are finite and |u|^2 is ordinary (normalized() then divides by its
/// sqrt unscaled; u is finite and nonzero). Data: element e's centre at c + 3 e, axis at u + 3 e,
/// angle at angle + e, point at p + 3 e (the ABI arrays).
template <class S, std::size_t L>
struct RotateAboutAxisLanes {
  using Flag = std::int32_t;

  S out[3][L];  // the moved point, where ok
  Flag ok[L];

  void run(const S* c, const S* u, const S* angle, const S* p) {
    runtime::AxisAngleLanes<S, L> in;
    in.load(c, u, angle, p);
    for (std::size_t l = 0; l < L; ++l) {
      ok[l] = in.ok[l];
      const S sn = in.sin_half[l];
      const S qx = sn * in.axis[0][l], qy = sn * in.axis[1][l], qz = sn * in.axis[2][l], qw = in.cos_half[l];
      const S cx = in.centre[0][l], cy = in.centre[1][l], cz = in.centre[2][l];
      // c q - q c of the pure quaternion c, every product term included (signed zeros as dq.cpp's).
      S ax, ay, az, aw, bx, by, bz, bw;
      product_lane(cx, cy, cz, S(0), qx, qy, qz, qw, ax, ay, az, aw);
      product_lane(qx, qy, qz, qw, cx, cy, cz, S(0), bx, by, bz, bw);
      const S sigma[8] = {qx, qy, qz, qw, S(0.5) * (ax - bx), S(0.5) * (ay - by), S(0.5) * (az - bz), S(0.5) * (aw - bw)};
      moved_point_lane(sigma, in.point[0][l], in.point[1][l], in.point[2][l], l, out);
    }
  }
};

}  // namespace rotorcert::dq_lanes
