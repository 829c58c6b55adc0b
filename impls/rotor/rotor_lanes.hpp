// NORM-1, COMPOSE-1, INV-1, APPLY-1, APPLY-2, APPLY-3, MAT-1, MAT-2, AXANG-1..4, LOG-1, EXP-1,
// NLERP-1, SLERP-2, QLB-1 and SKIN-1 of RotorOps<S, Method2>
// (rotor3.hpp) for L elements of a batch at once, in SoA lanes that the compiler turns into SIMD: the fast paths of rotor_m2's batch
// functions for ordinary input, kept apart from the scalar math in the manner of ozz-animation's
// SoA jobs (and of dq/dlb_lanes.hpp, whose driver runtime/lane_blocks.hpp runs these too).
//
// Data: the ABI's AoS arrays (quaternion e at q + 4 e as [x, y, z, w], LAYOUT-1; vector e at
// v + 3 e) copied into lane arrays x[component][lane]. The rotor of q is Phi(q) = w - x e23 -
// y e31 - z e12 (Q2R-1).
//
// Every lane computes exactly what RotorOps computes for its element when |q|^2 is ordinary
// (runtime/ordinary_range.hpp: then safely_rescaled() is the identity, every component is finite
// and q is not zero, so is_rotation() holds): the same IEEE operations in the same order, so the
// same bits. A lane whose cheap test fails has `ok` false and the caller takes RotorOps for that
// element; its other values are then meaningless. No branch depends on a lane's value, so the
// loops vectorise (rotor_m2's CMakeLists.txt: -fno-math-errno for sqrt, -ffp-contract=off so that
// no lane contracts a * b + c where the scalar code rounds twice).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>

#include <rotorcert/runtime/exact_sign.hpp>
#include <rotorcert/runtime/lane_weights.hpp>
#include <rotorcert/runtime/ordinary_range.hpp>

#include "rotor3.hpp"

namespace rotorcert::rotor::lanes {

/// A lane flag, 1 or 0: bool arrays do not vectorise.
using Flag = std::int32_t;

/// A block's quaternions in SoA lanes: x[c][l] = q[4 l + c].
template <class S, std::size_t L>
[[gnu::always_inline]] inline void load_lanes(const S* q, S (&x)[4][L]) {
  for (std::size_t l = 0; l < L; ++l)
    for (std::size_t c = 0; c < 4; ++c) x[c][l] = q[4 * l + c];
}

/// |q|^2 of lane l, in norm2()'s order.
template <class S, std::size_t L>
[[gnu::always_inline]] inline S norm2_lane(const S (&x)[4][L], std::size_t l) {
  return x[0][l] * x[0][l] + x[1][l] * x[1][l] + x[2][l] * x[2][l] + x[3][l] * x[3][l];
}

/// Method2::in of lane l where |q|^2 is ordinary, given n = sqrt(|q|^2): Phi(q/|q|).
template <class S, std::size_t L>
[[gnu::always_inline]] inline Rotor3<S> unit_rotor_lane(const S (&x)[4][L], std::size_t l, S n) {
  return {x[3][l] / n, -(x[0][l] / n), -(x[1][l] / n), -(x[2][l] / n)};
}

/// Phi^-1(r) = (-e23, -e31, -e12, s) into lane l of out.
template <class S, std::size_t L>
[[gnu::always_inline]] inline void readout_lane(const Rotor3<S>& r, std::size_t l, S (&out)[4][L]) {
  out[0][l] = -r.e23;
  out[1][l] = -r.e31;
  out[2][l] = -r.e12;
  out[3][l] = r.s;
}

/// Phi^-1(normalized(r)) into lane l of out where |r|^2 is ordinary; returns whether it is.
/// normalized(Rotor3) divides the quaternion (e23, e31, e12, s) by its norm, in that order.
template <class S, std::size_t L>
[[gnu::always_inline]] inline bool normalized_readout_lane(const Rotor3<S>& r, std::size_t l, S (&out)[4][L]) {
  const S n2 = r.e23 * r.e23 + r.e31 * r.e31 + r.e12 * r.e12 + r.s * r.s;
  const S n = std::sqrt(n2);
  readout_lane(Rotor3<S>{r.s / n, r.e23 / n, r.e31 / n, r.e12 / n}, l, out);
  return runtime::is_ordinary_square_lane(n2);
}

/// NORM-1 as RotorOps::normalize with Method2 computes it: Phi^-1(Phi(q/|q|)) = normalized(q),
/// q / sqrt(x^2 + y^2 + z^2 + w^2), four divisions.
template <class S, std::size_t L>
struct NormalizeLanes {
  S out[4][L];
  Flag ok[L];

  void run(const S* q, const S* /*unused*/) {
    S x[4][L];
    load_lanes(q, x);
    for (std::size_t l = 0; l < L; ++l) {
      const S n2 = norm2_lane(x, l);
      ok[l] = Flag(runtime::is_ordinary_square_lane(n2));
      const S n = std::sqrt(n2);
      for (std::size_t c = 0; c < 4; ++c) out[c][l] = x[c][l] / n;
    }
  }
};

/// COMPOSE-1 as RotorOps::compose computes it for ordinary |a|^2 and |b|^2: Phi^-1(gp(Phi(a),
/// Phi(b))), rotor3.hpp's gp term for term.
template <class S, std::size_t L>
struct ComposeLanes {
  S out[4][L];
  Flag ok[L];

  void run(const S* a, const S* b) {
    S x[4][L], y[4][L];
    load_lanes(a, x);
    load_lanes(b, y);
    for (std::size_t l = 0; l < L; ++l) {
      const S na = norm2_lane(x, l), nb = norm2_lane(y, l);
      // Named before the &: clang warns on & of two calls.
      const bool ordinary_a = runtime::is_ordinary_square_lane(na), ordinary_b = runtime::is_ordinary_square_lane(nb);
      ok[l] = Flag(ordinary_a & ordinary_b);
      const Rotor3<S> p{x[3][l], -x[0][l], -x[1][l], -x[2][l]}, q{y[3][l], -y[0][l], -y[1][l], -y[2][l]};
      readout_lane(gp(p, q), l, out);
    }
  }
};

/// APPLY-1 as RotorOps::apply_vector computes it for ordinary |q|^2 and finite v:
/// sandwich_vector(Phi(normalized(q)), v); and APPLY-2, whose sandwich_bivector is the same.
template <class S, std::size_t L>
struct ApplyVectorLanes {
  S out[3][L];
  Flag ok[L];

  void run(const S* q, const S* v) {
    S x[4][L], p[3][L];
    for (std::size_t l = 0; l < L; ++l) {
      for (std::size_t c = 0; c < 4; ++c) x[c][l] = q[4 * l + c];
      for (std::size_t c = 0; c < 3; ++c) p[c][l] = v[3 * l + c];
    }
    for (std::size_t l = 0; l < L; ++l) {
      const S n2 = norm2_lane(x, l);
      const bool finite_v = runtime::finite3_lane(p[0][l], p[1][l], p[2][l]);
      const bool ordinary_q = runtime::is_ordinary_square_lane(n2);
      ok[l] = Flag(ordinary_q & finite_v);
      const impl::Vec3<S> y = sandwich_vector(unit_rotor_lane(x, l, std::sqrt(n2)), impl::Vec3<S>{p[0][l], p[1][l], p[2][l]});
      for (std::size_t c = 0; c < 3; ++c) out[c][l] = y[c];
    }
  }
};

/// APPLY-3 as RotorOps::apply_trivector computes it where |q|^2 is ordinary (q a rotation) and a
/// is finite: R (a I) ~R = a I, so the output is a itself.
template <class S, std::size_t L>
struct ApplyTrivectorLanes {
  S out[1][L];
  Flag ok[L];

  void run(const S* q, const S* a) {
    constexpr S kMax = std::numeric_limits<S>::max();
    S x[4][L];
    load_lanes(q, x);
    for (std::size_t l = 0; l < L; ++l) {
      const S al = a[l];
      ok[l] = Flag(runtime::is_ordinary_square_lane(norm2_lane(x, l)) & (al <= kMax) & (al >= -kMax));
      out[0][l] = al;
    }
  }
};

/// INV-1 as RotorOps::inverse computes it with Method2 for ordinary |q|^2: Phi^-1(~Phi(q) / |q|^2),
/// i.e. (-x, -y, -z, w) / |q|^2 divided component by component.
template <class S, std::size_t L>
struct InverseLanes {
  S out[4][L];
  Flag ok[L];

  void run(const S* q, const S* /*unused*/) {
    S x[4][L];
    load_lanes(q, x);
    for (std::size_t l = 0; l < L; ++l) {
      const S n2 = norm2_lane(x, l);
      ok[l] = Flag(runtime::is_ordinary_square_lane(n2));
      out[0][l] = -(x[0][l] / n2);
      out[1][l] = -(x[1][l] / n2);
      out[2][l] = -(x[2][l] / n2);
      out[3][l] = x[3][l] / n2;
    }
  }
};

/// MAT-1 as RotorOps::to_matrix computes it for ordinary |q|^2: to_matrix(Phi(normalized(q))).
template <class S, std::size_t L>
struct ToMatrixLanes {
  S out[9][L];
  Flag ok[L];

  void run(const S* q, const S* /*unused*/) {
    S x[4][L];
    load_lanes(q, x);
    for (std::size_t l = 0; l < L; ++l) {
      const S n2 = norm2_lane(x, l);
      ok[l] = Flag(runtime::is_ordinary_square_lane(n2));
      const impl::Mat3<S> m = to_matrix(unit_rotor_lane(x, l, std::sqrt(n2)));
      out[0][l] = m[0], out[1][l] = m[1], out[2][l] = m[2], out[3][l] = m[3], out[4][l] = m[4];
      out[5][l] = m[5], out[6][l] = m[6], out[7][l] = m[7], out[8][l] = m[8];
    }
  }
};

/// AXANG-4 as RotorOps::to_axis computes it with Method2 where |q|^2 and |v|^2 are ordinary:
/// -plane_of(q), the bivector of Phi((x, y, z, 0)/|v|) negated, which is v/|v| (two exact
/// negations).
template <class S, std::size_t L>
struct ToAxisLanes {
  S out[3][L];
  Flag ok[L];

  void run(const S* q, const S* /*unused*/) {
    S x[4][L];
    load_lanes(q, x);
    for (std::size_t l = 0; l < L; ++l) {
      const S n2 = norm2_lane(x, l);
      const S v2 = x[0][l] * x[0][l] + x[1][l] * x[1][l] + x[2][l] * x[2][l];  // norm2 of (x, y, z, 0)
      // Named before the &: clang warns on & of two calls.
      const bool ordinary_q = runtime::is_ordinary_square_lane(n2), ordinary_v = runtime::is_ordinary_square_lane(v2);
      ok[l] = Flag(ordinary_q & ordinary_v);
      const S n = std::sqrt(v2);
      out[0][l] = x[0][l] / n;
      out[1][l] = x[1][l] / n;
      out[2][l] = x[2][l] / n;
    }
  }
};

/// NLERP-1 as RotorOps::nlerp computes it with Method2 where |a|^2 and |b|^2 are ordinary, t is
/// finite, the filter of runtime/exact_sign.hpp decides the hemisphere sign (as hemisphere_sign()
/// then does) and the sum's |.|^2 is ordinary: R_A = Phi(a/|a|), R_B' = +-Phi(b/|b|),
/// normalized(k R_A + u (R_B' - R_A)) with k = 1/max(1, |t|), u = t k, read back by Phi^-1.
template <class S, std::size_t L>
struct NlerpLanes {
  S out[4][L];
  Flag ok[L];

  void run(const S* a, const S* b, const S* t) {
    S x[4][L], y[4][L], tt[L];
    load_lanes(a, x);
    load_lanes(b, y);
    for (std::size_t l = 0; l < L; ++l) tt[l] = t[l];
    for (std::size_t l = 0; l < L; ++l) {
      const S na = norm2_lane(x, l), nb = norm2_lane(y, l);
      bool negative = false;
      const bool decided = runtime::filtered_dot4_lane(x[0][l], x[1][l], x[2][l], x[3][l], y[0][l], y[1][l], y[2][l],
                                                       y[3][l], negative);
      constexpr S kMax = std::numeric_limits<S>::max();
      const bool finite_t = (tt[l] <= kMax) & (tt[l] >= -kMax);
      const bool ordinary_a = runtime::is_ordinary_square_lane(na), ordinary_b = runtime::is_ordinary_square_lane(nb);
      const S sa = std::sqrt(na), sb = std::sqrt(nb);
      // R_B' = +-Phi(b/|b|): the flip as a multiplication by -1 (exact, = negated()), so that no
      // branch depends on the lane; a select, since GCC 12 does not vectorise bool -> float.
      const S sign = negative ? S(-1) : S(1);
      const Rotor3<S> ra = unit_rotor_lane(x, l, sa), r = unit_rotor_lane(y, l, sb);
      const Rotor3<S> rb{sign * r.s, sign * r.e23, sign * r.e31, sign * r.e12};
      // max(1, |t|) as a select, as std::max gives it for every t (1 for NaN, where the lane is
      // not ok anyway): GCC 12 leaves std::max a branch, and vectorises fmax only without NaNs.
      const S at = std::abs(tt[l]);
      const S k = S(1) / (at > S(1) ? at : S(1)), u = tt[l] * k;
      const Rotor3<S> sum{k * ra.s + u * (rb.s - ra.s), k * ra.e23 + u * (rb.e23 - ra.e23),
                          k * ra.e31 + u * (rb.e31 - ra.e31), k * ra.e12 + u * (rb.e12 - ra.e12)};
      const bool ordinary_sum = normalized_readout_lane(sum, l, out);
      ok[l] = Flag(ordinary_a & ordinary_b & finite_t & decided & ordinary_sum);
    }
  }
};

/// QLB-1 as RotorOps::blend_qlb computes it with Method2 where every weight is in [0, max], some
/// weight is > 0, every |q_i|^2 is ordinary, the filter decides each hemisphere sign against the
/// pivot (the first weight > 0, EDGE-9) and the sum's |.|^2 is ordinary: normalized(sum_i
/// (+-w_i/w_max) Phi(q_i/|q_i|)), summed from 0 in influence order, read back by Phi^-1.
/// Data: element e's k quaternions at q + 4 k e, its k weights at w + k e (the ABI's arrays).
template <class S, std::size_t L>
struct BlendQlbLanes {
  S out[4][L];
  Flag ok[L];

  void run(std::size_t k, const S* q, const S* w) {
    runtime::LaneWeights<S, L> weights;
    weights.scan(k, w);
    S pivot[4][L], sum[4][L];  // sum: s, e23, e31, e12
    for (std::size_t l = 0; l < L; ++l) {
      ok[l] = weights.ok[l];
      const std::size_t at = weights.pivot_offset(k, 4, l);
      for (std::size_t c = 0; c < 4; ++c) pivot[c][l] = q[at + c];
      for (std::size_t c = 0; c < 4; ++c) sum[c][l] = 0;
    }
    S x[4][L];
    for (std::size_t i = 0; i < k; ++i) {
      for (std::size_t l = 0; l < L; ++l)
        for (std::size_t c = 0; c < 4; ++c) x[c][l] = q[4 * k * l + 4 * i + c];
      for (std::size_t l = 0; l < L; ++l) {
        const S n2 = norm2_lane(x, l);
        bool negative = false;  // hemisphere_sign(q_i, q_p) < 0, where decided (EDGE-3)
        const bool decided = runtime::filtered_dot4_lane(x[0][l], x[1][l], x[2][l], x[3][l], pivot[0][l], pivot[1][l],
                                                         pivot[2][l], pivot[3][l], negative);
        const bool ordinary = runtime::is_ordinary_square_lane(n2);
        ok[l] = ok[l] & Flag(ordinary & decided);
        const Rotor3<S> r = unit_rotor_lane(x, l, std::sqrt(n2));
        const S f0 = w[k * l + i] / weights.w_max[l];
        const S f = negative ? -f0 : f0;
        sum[0][l] = sum[0][l] + f * r.s;
        sum[1][l] = sum[1][l] + f * r.e23;
        sum[2][l] = sum[2][l] + f * r.e31;
        sum[3][l] = sum[3][l] + f * r.e12;
      }
    }
    for (std::size_t l = 0; l < L; ++l) {
      const bool ordinary_sum = normalized_readout_lane(Rotor3<S>{sum[0][l], sum[1][l], sum[2][l], sum[3][l]}, l, out);
      ok[l] = ok[l] & Flag(ordinary_sum);
    }
  }
};

/// MAT-2 as RotorOps::from_matrix computes it with Method2 where rotor_from_matrix takes its fast
/// path (rotor_from_near_orthonormal_matrix: entries at most 2, det > 1/2, ||M^T M - I||_F at
/// most 8 eps of the input format; binary32 in binary64) and every normalisation's |.|^2 is
/// ordinary: Shepperd's quaternion with the largest pivot, normalised; for binary32 rounded to
/// binary32 and normalised again; then Phi^-1(Method2::in(.)) normalises once more and
/// canonical_sign() picks MAT-2's sign. Shepperd's four cases become selects: the pivot's radicand
/// in its case's order of additions, the three other components from the six sums and differences
/// of off-diagonal pairs, each multiplied by f = 1/(4 v) after the select, as in the case itself.
/// Data: element e's column-major matrix at m + 9 e.
template <class S, std::size_t L>
struct FromMatrixLanes {
  S out[4][L];
  Flag ok[L];

  void run(const S* m, const S* /*unused*/) {
    // The format rotor_from_matrix works in, and its fast path's tolerance (8 eps of S).
    using W = std::conditional_t<std::is_same_v<S, float>, double, S>;
    constexpr W kTolerance = W(8) * W(std::numeric_limits<S>::epsilon());
    W x[9][L];
    for (std::size_t l = 0; l < L; ++l)
      for (std::size_t c = 0; c < 9; ++c) x[c][l] = W(m[9 * l + c]);
    for (std::size_t l = 0; l < L; ++l) {
      // at(r, c) = x[3 c + r]
      const W m00 = x[0][l], m10 = x[1][l], m20 = x[2][l], m01 = x[3][l], m11 = x[4][l], m21 = x[5][l];
      const W m02 = x[6][l], m12 = x[7][l], m22 = x[8][l];
      // Written out term by term: GCC 12 vectorises no loop nest with inner loops here.
      const auto bounded = [](W e) { return std::abs(e) <= W(2); };  // false for NaN
      // Flags, not bools: clang warns on & between two calls.
      Flag good = Flag(bounded(m00)) & Flag(bounded(m10)) & Flag(bounded(m20)) & Flag(bounded(m01)) &
                  Flag(bounded(m11)) & Flag(bounded(m21)) & Flag(bounded(m02)) & Flag(bounded(m12)) &
                  Flag(bounded(m22));
      const W det = m00 * (m11 * m22 - m12 * m21) - m01 * (m10 * m22 - m12 * m20) + m02 * (m10 * m21 - m11 * m20);
      good = good & Flag(det > W(0.5));
      // orthonormality_defect2: g_ij = -[i = j] + sum_k at(k, i) at(k, j), g_ij^2 summed row by row.
      const auto g2 = [](W init, W a0, W a1, W a2, W b0, W b1, W b2) {
        const W g = init + a0 * b0 + a1 * b1 + a2 * b2;
        return g * g;
      };
      const W defect = W(0) + g2(W(-1), m00, m10, m20, m00, m10, m20) + g2(W(0), m00, m10, m20, m01, m11, m21) +
                       g2(W(0), m00, m10, m20, m02, m12, m22) + g2(W(0), m01, m11, m21, m00, m10, m20) +
                       g2(W(-1), m01, m11, m21, m01, m11, m21) + g2(W(0), m01, m11, m21, m02, m12, m22) +
                       g2(W(0), m02, m12, m22, m00, m10, m20) + g2(W(0), m02, m12, m22, m01, m11, m21) +
                       g2(W(-1), m02, m12, m22, m02, m12, m22);
      good = good & Flag(defect <= kTolerance * kTolerance);
      // shepperd_rotor: the case, then its radicand and components (q = [x, y, z, w]).
      const W trace = m00 + m11 + m22;
      const bool c0 = (trace >= m00) & (trace >= m11) & (trace >= m22);
      const bool c1 = !c0 & (m00 >= m11) & (m00 >= m22);
      const bool c2 = !c0 & !c1 & (m11 >= m22);
      const W r0 = W(1) + trace, r1 = W(1) + m00 - m11 - m22, r2 = W(1) - m00 + m11 - m22;
      const W r3 = W(1) - m00 - m11 + m22;
      const W radicand = c0 ? r0 : c1 ? r1 : c2 ? r2 : r3;
      const W v = W(0.5) * std::sqrt(radicand), f = W(0.25) / v;
      const W dx = m21 - m12, dy = m02 - m20, dz = m10 - m01, sxy = m01 + m10, sxz = m02 + m20, syz = m12 + m21;
      const W qx = c0 ? dx * f : c1 ? v : c2 ? sxy * f : sxz * f;
      const W qy = c0 ? dy * f : c1 ? sxy * f : c2 ? v : syz * f;
      const W qz = c0 ? dz * f : c1 ? sxz * f : c2 ? syz * f : v;
      const W qw = c0 ? v : c1 ? dx * f : c2 ? dy * f : dz * f;
      // normalized(q) on an ordinary |q|^2 (then q is finite and nonzero: is_rotation holds).
      const W qn2 = qx * qx + qy * qy + qz * qz + qw * qw;
      good = good & Flag(runtime::is_ordinary_square_lane(qn2));
      const W qn = std::sqrt(qn2);
      // The rotor {w, -x, -y, -z}/|q|; binary32 rounds it and normalises {e23, e31, e12, s} again.
      S a0, a1, a2, a3;  // PhiReadout::out of rotor_from_matrix's rotor: [x, y, z, w]
      if constexpr (std::is_same_v<S, float>) {
        const float e23 = float(-(qx / qn)), e31 = float(-(qy / qn)), e12 = float(-(qz / qn)), s = float(qw / qn);
        const float n2 = e23 * e23 + e31 * e31 + e12 * e12 + s * s;
        good = good & Flag(runtime::is_ordinary_square_lane(n2));
        const float n = std::sqrt(n2);
        a0 = -(e23 / n), a1 = -(e31 / n), a2 = -(e12 / n), a3 = s / n;
      } else {
        a0 = -(-(qx / qn)), a1 = -(-(qy / qn)), a2 = -(-(qz / qn)), a3 = qw / qn;
      }
      // Phi^-1(Method2::in(a)) = normalized(a), then MAT-2's sign (canonical_sign).
      const S an2 = a0 * a0 + a1 * a1 + a2 * a2 + a3 * a3;
      good = good & Flag(runtime::is_ordinary_square_lane(an2));
      const S an = std::sqrt(an2);
      const S o0 = a0 / an, o1 = a1 / an, o2 = a2 / an, o3 = a3 / an;
      const S first = o0 != 0 ? o0 : (o1 != 0 ? o1 : o2);
      const bool flip = (o3 < 0) | ((o3 == 0) & (first < 0));
      out[0][l] = flip ? -o0 : o0;
      out[1][l] = flip ? -o1 : o1;
      out[2][l] = flip ? -o2 : o2;
      out[3][l] = flip ? -o3 : o3;
      ok[l] = good;
    }
  }
};

/// SLERP-2 as RotorOps::slerp computes it with Method2 (interpolate(): exp(t log(R_B' ~R_A)) R_A)
/// where |a|^2 and |b|^2 are ordinary, t is finite, the filter decides the hemisphere sign, and
/// the squared norms of log's bivector B and of exp's argument t log(.) are ordinary (so neither
/// is zero). Both branches of log (its series for |B| << s, and atan2(|B|, s) B/|B|) and of exp's
/// sin|b|/|b| (its series for |b|^2 < eps) are computed and selected. atan2, sin and cos are the
/// element function's libm calls, made one lane at a time between the vectorised loops.
template <class S, std::size_t L>
struct SlerpLanes {
  S out[4][L];
  Flag ok[L];

  void run(const S* a, const S* b, const S* t) {
    constexpr S kMax = std::numeric_limits<S>::max();
    S x[4][L], y[4][L], tt[L];
    load_lanes(a, x);
    load_lanes(b, y);
    for (std::size_t l = 0; l < L; ++l) tt[l] = t[l];
    // R_A, and log(D) of D = +-R_B ~R_A up to its angle: |B|, s, the series' log and B/|B|.
    S ra[4][L], n[L], s[L], series[3][L], unit[3][L];
    Flag use_series[L];
    for (std::size_t l = 0; l < L; ++l) {
      const S na = norm2_lane(x, l), nb = norm2_lane(y, l);
      bool negative = false;
      const bool decided = runtime::filtered_dot4_lane(x[0][l], x[1][l], x[2][l], x[3][l], y[0][l], y[1][l], y[2][l],
                                                       y[3][l], negative);
      const bool finite_t = (tt[l] <= kMax) & (tt[l] >= -kMax);
      const bool ordinary_a = runtime::is_ordinary_square_lane(na), ordinary_b = runtime::is_ordinary_square_lane(nb);
      const Rotor3<S> rra = unit_rotor_lane(x, l, std::sqrt(na)), rrb = unit_rotor_lane(y, l, std::sqrt(nb));
      const Rotor3<S> d0 = gp(rrb, reverse(rra));
      const S sign = negative ? S(-1) : S(1);  // negated(): exact
      const Rotor3<S> d{sign * d0.s, sign * d0.e23, sign * d0.e31, sign * d0.e12};
      const S n2 = d.e23 * d.e23 + d.e31 * d.e31 + d.e12 * d.e12;  // norm3 and unit_vector
      ok[l] = Flag(ordinary_a & ordinary_b & decided & finite_t & runtime::is_ordinary_square_lane(n2));
      const S nd = std::sqrt(n2);
      const S q = nd / d.s, q2 = q * q;
      use_series[l] = Flag((d.s > 0) & (q2 * q2 * q2 < kEps<S>));
      const S f = (S(1) - q2 / S(3) + q2 * q2 / S(5)) / d.s;
      series[0][l] = f * d.e23, series[1][l] = f * d.e31, series[2][l] = f * d.e12;
      unit[0][l] = d.e23 / nd, unit[1][l] = d.e31 / nd, unit[2][l] = d.e12 / nd;
      n[l] = nd, s[l] = d.s;
      ra[0][l] = rra.s, ra[1][l] = rra.e23, ra[2][l] = rra.e31, ra[3][l] = rra.e12;
    }
    S angle[L];
    for (std::size_t l = 0; l < L; ++l) angle[l] = atan2_in_binary64(n[l], s[l]);
    // exp(t log D) up to sin and cos: b = t log D, |b|, and sin|b|/|b|'s series.
    S e[3][L], m[L], sinc_series[L];
    Flag small[L];
    for (std::size_t l = 0; l < L; ++l) {
      const bool by_series = use_series[l] != 0;
      const S l0 = by_series ? series[0][l] : angle[l] * unit[0][l];
      const S l1 = by_series ? series[1][l] : angle[l] * unit[1][l];
      const S l2 = by_series ? series[2][l] : angle[l] * unit[2][l];
      const S b0 = tt[l] * l0, b1 = tt[l] * l1, b2 = tt[l] * l2;
      const S m2 = b0 * b0 + b1 * b1 + b2 * b2;
      ok[l] = ok[l] & Flag(runtime::is_ordinary_square_lane(m2));
      const S mm = std::sqrt(m2);
      small[l] = Flag(mm * mm < kEps<S>);
      sinc_series[l] = S(1) - mm * mm / S(6);
      e[0][l] = b0, e[1][l] = b1, e[2][l] = b2, m[l] = mm;
    }
    S sn[L], cs[L];
    for (std::size_t l = 0; l < L; ++l) sn[l] = std::sin(m[l]), cs[l] = std::cos(m[l]);
    // exp(b) R_A, read back by Phi^-1.
    for (std::size_t l = 0; l < L; ++l) {
      const S sinc = small[l] != 0 ? sinc_series[l] : sn[l] / m[l];
      const Rotor3<S> ex{cs[l], sinc * e[0][l], sinc * e[1][l], sinc * e[2][l]};
      readout_lane(gp(ex, Rotor3<S>{ra[0][l], ra[1][l], ra[2][l], ra[3][l]}), l, out);
    }
  }
};

/// LOG-1 as RotorOps::log computes it with Method2 where |q|^2 and |B|^2 of R = s + B = Phi(q/|q|)
/// are ordinary (so B is not zero) and, for s < 0, |v|^2 of q's vector part v too: rotor::log(R)
/// for s >= 0, its series for |B| << s or atan2(|B|, s) B/|B|, both computed and selected; for
/// s < 0 atan2(|B|, s) times plane_of(q) = -v/|v|. Read back by pure_out (a negation). atan2 is
/// the element function's call, one lane at a time.
template <class S, std::size_t L>
struct LogLanes {
  S out[3][L];
  Flag ok[L];

  void run(const S* q, const S* /*unused*/) {
    S x[4][L], n[L], s[L], series[3][L], dir[3][L];
    Flag use_series[L];
    load_lanes(q, x);
    for (std::size_t l = 0; l < L; ++l) {
      const S n2q = norm2_lane(x, l);
      const Rotor3<S> r = unit_rotor_lane(x, l, std::sqrt(n2q));
      const S n2 = r.e23 * r.e23 + r.e31 * r.e31 + r.e12 * r.e12;  // norm3 and unit_vector
      const S v2 = x[0][l] * x[0][l] + x[1][l] * x[1][l] + x[2][l] * x[2][l];  // plane_of's |v|^2
      const bool ordinary_q = runtime::is_ordinary_square_lane(n2q), ordinary_b = runtime::is_ordinary_square_lane(n2);
      const bool ordinary_v = runtime::is_ordinary_square_lane(v2);
      ok[l] = Flag(ordinary_q & ordinary_b & ((r.s >= 0) | ordinary_v));
      const S nb = std::sqrt(n2), nv = std::sqrt(v2);
      const S ratio = nb / r.s, ratio2 = ratio * ratio;
      use_series[l] = Flag((r.s > 0) & (ratio2 * ratio2 * ratio2 < kEps<S>));
      const S f = (S(1) - ratio2 / S(3) + ratio2 * ratio2 / S(5)) / r.s;
      series[0][l] = f * r.e23, series[1][l] = f * r.e31, series[2][l] = f * r.e12;
      const bool own_plane = r.s >= 0;
      dir[0][l] = own_plane ? r.e23 / nb : -(x[0][l] / nv);
      dir[1][l] = own_plane ? r.e31 / nb : -(x[1][l] / nv);
      dir[2][l] = own_plane ? r.e12 / nb : -(x[2][l] / nv);
      n[l] = nb, s[l] = r.s;
    }
    S angle[L];
    for (std::size_t l = 0; l < L; ++l) angle[l] = atan2_in_binary64(n[l], s[l]);
    for (std::size_t l = 0; l < L; ++l) {
      const bool by_series = use_series[l] != 0;
      out[0][l] = -(by_series ? series[0][l] : angle[l] * dir[0][l]);
      out[1][l] = -(by_series ? series[1][l] : angle[l] * dir[1][l]);
      out[2][l] = -(by_series ? series[2][l] : angle[l] * dir[2][l]);
    }
  }
};

/// EXP-1 as RotorOps::exp computes it with Method2 where |v|^2 is ordinary (v finite, not zero):
/// rotor::exp(b) of b = pure_in(v) = -v, cos|b| + b sin|b|/|b| (the series 1 - |b|^2/6 where
/// |b|^2 < eps, selected), read back by Phi^-1. sin and cos are the element function's calls, one
/// lane at a time.
template <class S, std::size_t L>
struct ExpLanes {
  S out[4][L];
  Flag ok[L];

  void run(const S* v, const S* /*unused*/) {
    S b[3][L], n[L];
    for (std::size_t l = 0; l < L; ++l)
      for (std::size_t c = 0; c < 3; ++c) b[c][l] = -v[3 * l + c];
    for (std::size_t l = 0; l < L; ++l) {
      const S n2 = b[0][l] * b[0][l] + b[1][l] * b[1][l] + b[2][l] * b[2][l];
      ok[l] = Flag(runtime::is_ordinary_square_lane(n2));
      n[l] = std::sqrt(n2);
    }
    S sn[L], cs[L];
    for (std::size_t l = 0; l < L; ++l) sn[l] = std::sin(n[l]), cs[l] = std::cos(n[l]);
    for (std::size_t l = 0; l < L; ++l) {
      const S sinc = n[l] * n[l] < kEps<S> ? S(1) - n[l] * n[l] / S(6) : sn[l] / n[l];
      out[0][l] = -(sinc * b[0][l]);
      out[1][l] = -(sinc * b[1][l]);
      out[2][l] = -(sinc * b[2][l]);
      out[3][l] = cs[l];
    }
  }
};

/// RotorOps::angle_of's arguments for lane l: |B| and s of R = s + B = Phi(q/|q|), where |q|^2
/// is ordinary and |B|^2 ordinary or B exactly zero (norm3's own cases without scaling; it
/// returns +0 for B = 0); returns whether they hold.
template <class S, std::size_t L>
[[gnu::always_inline]] inline bool angle_arguments_lane(const S (&x)[4][L], std::size_t l, S& n, S& s) {
  const S n2q = norm2_lane(x, l);
  const Rotor3<S> r = unit_rotor_lane(x, l, std::sqrt(n2q));
  const S n2 = r.e23 * r.e23 + r.e31 * r.e31 + r.e12 * r.e12;
  const bool no_plane = (r.e23 == 0) & (r.e31 == 0) & (r.e12 == 0);
  const bool ordinary_q = runtime::is_ordinary_square_lane(n2q), ordinary_b = runtime::is_ordinary_square_lane(n2);
  n = std::sqrt(n2), s = r.s;
  return ordinary_q & (ordinary_b | no_plane);
}

/// AXANG-3 as RotorOps::to_angle computes it with Method2 where |q|^2 is ordinary and |B|^2 of
/// R = s + B = Phi(q/|q|) is ordinary or B is exactly zero (norm3's own cases without scaling):
/// 2 atan2(|B|, s), atan2 the element function's call, one lane at a time.
template <class S, std::size_t L>
struct ToAngleLanes {
  S out[1][L];
  Flag ok[L];

  void run(const S* q, const S* /*unused*/) {
    S x[4][L], n[L], s[L];
    load_lanes(q, x);
    for (std::size_t l = 0; l < L; ++l) ok[l] = Flag(angle_arguments_lane(x, l, n[l], s[l]));
    for (std::size_t l = 0; l < L; ++l) out[0][l] = S(2) * atan2_in_binary64(n[l], s[l]);
  }
};

/// AXANG-1 as RotorOps::to_axis_angle computes it with Method2 where ToAngleLanes computes the
/// angle and the axis is +z for a zero vector part v (axis_of's own case) or v/|v| for an ordinary
/// |v|^2 (ToAxisLanes). Data: out[0] the angle, out[1..3] the axis.
template <class S, std::size_t L>
struct ToAxisAngleLanes {
  S out[4][L];
  Flag ok[L];

  void run(const S* q, const S* /*unused*/) {
    S x[4][L], n[L], s[L];
    load_lanes(q, x);
    for (std::size_t l = 0; l < L; ++l) {
      const bool angle_ok = angle_arguments_lane(x, l, n[l], s[l]);
      const S v2 = x[0][l] * x[0][l] + x[1][l] * x[1][l] + x[2][l] * x[2][l];
      const bool no_vector = (x[0][l] == 0) & (x[1][l] == 0) & (x[2][l] == 0);
      ok[l] = Flag(angle_ok & (runtime::is_ordinary_square_lane(v2) | no_vector));
      const S nv = std::sqrt(v2);
      out[1][l] = no_vector ? S(0) : x[0][l] / nv;
      out[2][l] = no_vector ? S(0) : x[1][l] / nv;
      out[3][l] = no_vector ? S(1) : x[2][l] / nv;
    }
    for (std::size_t l = 0; l < L; ++l) out[0][l] = S(2) * atan2_in_binary64(n[l], s[l]);
  }
};

/// AXANG-2 as RotorOps::from_axis_angle computes it with Method2 where the angle is finite and
/// |axis|^2 ordinary: u = axis/|axis|, h = angle/2, Phi^-1(cos h - sin h (u_x e23 + u_y e31 +
/// u_z e12)) = (sin h u, cos h) with the rotor's two negations. cos and sin are the element
/// function's calls, one lane at a time.
template <class S, std::size_t L>
struct FromAxisAngleLanes {
  S out[4][L];
  Flag ok[L];

  void run(const S* angle, const S* axis) {
    constexpr S kMax = std::numeric_limits<S>::max();
    S u[3][L], h[L];
    for (std::size_t l = 0; l < L; ++l)
      for (std::size_t c = 0; c < 3; ++c) u[c][l] = axis[3 * l + c];
    for (std::size_t l = 0; l < L; ++l) {
      const S a = angle[l];
      const S n2 = u[0][l] * u[0][l] + u[1][l] * u[1][l] + u[2][l] * u[2][l];
      ok[l] = Flag(runtime::is_ordinary_square_lane(n2) & (a <= kMax) & (a >= -kMax));
      const S n = std::sqrt(n2);
      u[0][l] = u[0][l] / n, u[1][l] = u[1][l] / n, u[2][l] = u[2][l] / n;
      h[l] = a / S(2);
    }
    S cs[L], sn[L];
    for (std::size_t l = 0; l < L; ++l) cs[l] = std::cos(h[l]), sn[l] = std::sin(h[l]);
    for (std::size_t l = 0; l < L; ++l) {
      out[0][l] = -(-sn[l] * u[0][l]);
      out[1][l] = -(-sn[l] * u[1][l]);
      out[2][l] = -(-sn[l] * u[2][l]);
      out[3][l] = cs[l];
    }
  }
};

/// SKIN-1 as RotorOps::skin_linear computes it with Method2 where the weights pass EDGE-9 (as in
/// BlendQlbLanes), every |q_i|^2 is ordinary and v and every t_i finite: sum_i (w_i/w_max)
/// (M_i v + t_i) over the total of the w_i/w_max, summed from 0 in influence order, with M_i =
/// to_matrix(Phi(q_i/|q_i|)). Data: element e's k quaternions at q + 4 k e, translations at
/// t + 3 k e, weights at w + k e and its vertex at v + 3 e (the ABI's arrays).
template <class S, std::size_t L>
struct SkinLinearLanes {
  S out[3][L];
  Flag ok[L];

  void run(std::size_t k, const S* q, const S* t, const S* w, const S* v) {
    runtime::LaneWeights<S, L> weights;
    weights.scan(k, w);
    S p[3][L], acc[3][L], total[L];
    for (std::size_t l = 0; l < L; ++l)
      for (std::size_t c = 0; c < 3; ++c) p[c][l] = v[3 * l + c];
    for (std::size_t l = 0; l < L; ++l) {
      ok[l] = weights.ok[l] & Flag(runtime::finite3_lane(p[0][l], p[1][l], p[2][l]));
      acc[0][l] = acc[1][l] = acc[2][l] = total[l] = 0;
    }
    S x[4][L], tr[3][L];
    for (std::size_t i = 0; i < k; ++i) {
      for (std::size_t l = 0; l < L; ++l) {
        for (std::size_t c = 0; c < 4; ++c) x[c][l] = q[4 * k * l + 4 * i + c];
        for (std::size_t c = 0; c < 3; ++c) tr[c][l] = t[3 * k * l + 3 * i + c];
      }
      for (std::size_t l = 0; l < L; ++l) {
        const S n2 = norm2_lane(x, l);
        const bool ordinary = runtime::is_ordinary_square_lane(n2);
        const bool finite_t = runtime::finite3_lane(tr[0][l], tr[1][l], tr[2][l]);
        ok[l] = ok[l] & Flag(ordinary & finite_t);
        const S wi = w[k * l + i] / weights.w_max[l];
        total[l] = total[l] + wi;
        const impl::Mat3<S> m = to_matrix(unit_rotor_lane(x, l, std::sqrt(n2)));
        const S v0 = p[0][l], v1 = p[1][l], v2 = p[2][l];
        acc[0][l] = acc[0][l] + wi * (m[0] * v0 + m[3] * v1 + m[6] * v2 + tr[0][l]);
        acc[1][l] = acc[1][l] + wi * (m[1] * v0 + m[4] * v1 + m[7] * v2 + tr[1][l]);
        acc[2][l] = acc[2][l] + wi * (m[2] * v0 + m[5] * v1 + m[8] * v2 + tr[2][l]);
      }
    }
    for (std::size_t l = 0; l < L; ++l) {
      out[0][l] = acc[0][l] / total[l];
      out[1][l] = acc[1][l] / total[l];
      out[2][l] = acc[2][l] / total[l];
    }
  }
};

}  // namespace rotorcert::rotor::lanes
