// Motors of PGA Cl(3,0,1) as small runtime types, klein style: fixed layouts, hand-expanded
// products, closed-form exp and log. Used by motor_pga.cpp; its test checks the products
// against the reference's generic geometric product (rotorcert::ref pga gp).
//
// Algebra (ALG-7): e0^2 = 0, e1^2 = e2^2 = e3^2 = 1; named blades e01, e02, e03, e23, e31, e12,
// e032, e013, e021, e123, e0123 (e31 = e3 e1, e032 = e0 e3 e2, ...).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include <rotorcert/runtime/ordinary_range.hpp>
#include <rotorcert/runtime/perpendicular_part.hpp>

namespace rotorcert::motor_pga {

/// An even element of Cl(3,0,1), 8 coefficients in this order:
///   M = s + e23 e23 + e31 e31 + e12 e12 + e01 e01 + e02 e02 + e03 e03 + e0123 e0123.
/// (s, e23, e31, e12) is the Euclidean rotor R, (e01, e02, e03, e0123) the ideal (e0) part.
/// MOTOR-1, the map from the dual quaternion (q_r, q_d) = ([x_r, y_r, z_r, w_r], [x_d, ...]):
///   M = w_r - x_r e23 - y_r e31 - z_r e12 - x_d e01 - y_d e02 - z_d e03 - w_d e0123,
/// i.e. s = w_r, (e23, e31, e12) = -(x_r, y_r, z_r), (e01, e02, e03) = -(x_d, y_d, z_d),
/// e0123 = -w_d. It only moves and negates coefficients (exact) and turns the dual-quaternion
/// product (DQ-2) into the geometric product (MOTOR-3). A motor is unit when M ~M = 1.
template <class S>
struct Motor {
  S s, e23, e31, e12, e01, e02, e03, e0123;
};

/// A bivector B = e23 e23 + e31 e31 + e12 e12 + e01 e01 + e02 e02 + e03 e03: Euclidean part
/// (e23, e31, e12), the rotation axis scaled by minus half the angle, and ideal part (e01, e02,
/// e03). Motor logs live here.
template <class S>
struct Bivector {
  S e23, e31, e12, e01, e02, e03;
};

/// A point (klein's convention): P = e032 e032 + e013 e013 + e021 e021 + e123 e123; the
/// Euclidean point (x, y, z) is (x, y, z, 1), a weight w != 1 stands for (x, y, z)/w.
template <class S>
struct Point {
  S e032, e013, e021, e123;
};

// ---- 3-vector helpers on coefficient triples ----------------------------------------------------

template <class S> using V3 = std::array<S, 3>;
template <class S> S dot3(const V3<S>& a, const V3<S>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
template <class S> V3<S> cross3(const V3<S>& a, const V3<S>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class S> V3<S> euclid(const Motor<S>& m) { return {m.e23, m.e31, m.e12}; }
template <class S> V3<S> ideal(const Motor<S>& m) { return {m.e01, m.e02, m.e03}; }
template <class S> Motor<S> motor(S s, const V3<S>& b, const V3<S>& c, S p) {
  return {s, b[0], b[1], b[2], c[0], c[1], c[2], p};
}

// ---- MOTOR-1 --------------------------------------------------------------------------------------

/// From the ABI dual quaternion [x_r, y_r, z_r, w_r, x_d, y_d, z_d, w_d].
template <class S> Motor<S> from_dual_quaternion(const std::array<S, 8>& d) {
  return {d[3], -d[0], -d[1], -d[2], -d[4], -d[5], -d[6], -d[7]};
}
template <class S> std::array<S, 8> to_dual_quaternion(const Motor<S>& m) {
  return {-m.e23, -m.e31, -m.e12, m.s, -m.e01, -m.e02, -m.e03, -m.e0123};
}

// ---- products ---------------------------------------------------------------------------------------

/// Geometric product of two even elements, hand-expanded. With R = (s, b), b = (e23, e31, e12),
/// ideal part c = (e01, e02, e03), pseudoscalar coefficient p:
///   e23 e31 = -e12 (cyclic), so (s_a + b_a)(s_b + b_b) = s_a s_b - b_a.b_b + s_a b_b + s_b b_a - b_a x b_b;
///   e23 e01 = e01 e23 = e0123, e23 e02 = -e03, e02 e23 = e03 (cyclic), e0123 e23 = -e01,
///   ideal times ideal = 0 and e0123 times ideal = 0 (e0^2 = 0).
template <class S> Motor<S> operator*(const Motor<S>& a, const Motor<S>& b) {
  const V3<S> ba = euclid(a), bb = euclid(b), ca = ideal(a), cb = ideal(b);
  const V3<S> x = cross3(ba, bb), y = cross3(ba, cb), z = cross3(ca, bb);
  return {a.s * b.s - dot3(ba, bb),
          a.s * bb[0] + b.s * ba[0] - x[0],
          a.s * bb[1] + b.s * ba[1] - x[1],
          a.s * bb[2] + b.s * ba[2] - x[2],
          a.s * cb[0] + b.s * ca[0] - b.e0123 * ba[0] - a.e0123 * bb[0] - y[0] - z[0],
          a.s * cb[1] + b.s * ca[1] - b.e0123 * ba[1] - a.e0123 * bb[1] - y[1] - z[1],
          a.s * cb[2] + b.s * ca[2] - b.e0123 * ba[2] - a.e0123 * bb[2] - y[2] - z[2],
          a.s * b.e0123 + a.e0123 * b.s + dot3(ba, cb) + dot3(ca, bb)};
}

/// Reverse: bivectors change sign, scalar and e0123 do not.
template <class S> Motor<S> reverse(const Motor<S>& m) {
  return {m.s, -m.e23, -m.e31, -m.e12, -m.e01, -m.e02, -m.e03, m.e0123};
}

/// <A ~B>_0 of two even elements (the 4D dot product of the Euclidean rotor parts).
template <class S> S rotor_dot(const Motor<S>& a, const Motor<S>& b) {
  return a.s * b.s + a.e23 * b.e23 + a.e31 * b.e31 + a.e12 * b.e12;
}

/// The translator T(t) = 1 - 1/2 (tx e01 + ty e02 + tz e03) and the rotor of the unit
/// quaternion [x, y, z, w] (Q2R-1): w - x e23 - y e31 - z e12.
template <class S> Motor<S> translator(const V3<S>& t) { return {1, 0, 0, 0, -t[0] / 2, -t[1] / 2, -t[2] / 2, 0}; }
template <class S> Motor<S> rotor(S x, S y, S z, S w) { return {w, -x, -y, -z, 0, 0, 0, 0}; }

// ---- normalisation ----------------------------------------------------------------------------------

/// The normalised ideal part (c', p') where (c, -p) is mostly parallel to (b, s): the form without
/// the subtraction (runtime/perpendicular_part.hpp), as DQ-4 in dq.cpp; out of line (rare) so that
/// normalized's common path stays small enough to inline.
template <class S>
[[gnu::noinline, gnu::cold]] std::pair<V3<S>, S> ideal_part_without_subtraction(S s, const V3<S>& b, const V3<S>& c, S p,
                                                                               S n) {
  const std::array<S, 4> d = runtime::perpendicular_times_norm2<S>({b[0], b[1], b[2], s}, {c[0], c[1], c[2], -p});
  const S f = S(1) / (n * n * n);
  return {V3<S>{f * d[0], f * d[1], f * d[2]}, -f * d[3]};
}

/// The rotor part's n^2 and the ideal part's squares of M.
template <class S> S rotor_norm2(const Motor<S>& m) { return m.s * m.s + m.e23 * m.e23 + m.e31 * m.e31 + m.e12 * m.e12; }
template <class S> S ideal_norm2(const Motor<S>& m) {
  return m.e01 * m.e01 + m.e02 * m.e02 + m.e03 * m.e03 + m.e0123 * m.e0123;
}

/// normalized(m) below where n2 = rotor_norm2(m) and i2 = ideal_norm2(m) are ordinary (i2 may be 0)
/// and the subtraction does not cancel: the same operations in the same order, so the same bits,
/// inline for the batch fast paths. Returns false, having written nothing, elsewhere.
template <class S>
[[gnu::always_inline]] inline bool normalized_ordinary(const Motor<S>& m, S n2, S i2, Motor<S>& out) {
  if (!runtime::is_ordinary_square(n2) || !(i2 == 0 || runtime::is_ordinary_square(i2))) return false;
  const V3<S> b{m.e23, m.e31, m.e12}, c{m.e01, m.e02, m.e03};
  const S n = std::sqrt(m.s * m.s + dot3(b, b));
  const S su = m.s / n;
  const V3<S> bu{b[0] / n, b[1] / n, b[2] / n};
  const S k = dot3(bu, c) - su * m.e0123;
  if (runtime::projection_cancels(k, i2)) return false;
  out = motor(su, bu, V3<S>{(c[0] - k * bu[0]) / n, (c[1] - k * bu[1]) / n, (c[2] - k * bu[2]) / n},
              (m.e0123 + k * su) / n);
  return true;
}

/// M (M ~M)^(-1/2). With n^2 = s^2 + |b|^2 and M ~M = n^2 + 2 (s p - b.c) e0123 this is
///   (s, b, c, p) -> (s, b, c - k b, p + k s) / n,   k = (b.c - s p) / n^2,
/// i.e. DQ-4 carried over by MOTOR-1. A common power-of-two scale (exact) comes first so that
/// n^2 neither overflows nor underflows, unless the rotor part's n^2 and the ideal part's squares
/// are ordinary (runtime/ordinary_range.hpp: then the scale would change nothing but underflows
/// far below the unit roundoff). Where the subtraction of k b would cancel, the ideal part comes from
/// runtime/perpendicular_part.hpp instead. Precondition: finite, rotor part nonzero.
template <class S> Motor<S> normalized(const Motor<S>& m) {
  using std::abs;
  const S n2 = rotor_norm2(m);
  const S i2 = ideal_norm2(m);
  if (Motor<S> u; normalized_ordinary(m, n2, i2, u)) return u;
  const bool ordinary = runtime::is_ordinary_square(n2) && (i2 == 0 || runtime::is_ordinary_square(i2));
  const int e = ordinary ? 0 : -std::ilogb(std::max({abs(m.s), abs(m.e23), abs(m.e31), abs(m.e12)}));
  const auto scaled = [&](S x) { return ordinary ? x : std::scalbn(x, e); };
  const S s = scaled(m.s);
  const V3<S> b{scaled(m.e23), scaled(m.e31), scaled(m.e12)};
  const V3<S> c{scaled(m.e01), scaled(m.e02), scaled(m.e03)};
  const S p = scaled(m.e0123);
  const S n = std::sqrt(s * s + dot3(b, b));
  const S su = s / n;
  const V3<S> bu{b[0] / n, b[1] / n, b[2] / n};
  const S k = dot3(bu, c) - su * p;
  if (runtime::projection_cancels(k, ordinary ? i2 : dot3(c, c) + p * p)) [[unlikely]] {
    const auto [c_unit, p_unit] = ideal_part_without_subtraction(s, b, c, p, n);
    return motor(su, bu, c_unit, p_unit);
  }
  return motor(su, bu, V3<S>{(c[0] - k * bu[0]) / n, (c[1] - k * bu[1]) / n, (c[2] - k * bu[2]) / n},
               (p + k * su) / n);
}

// ---- action on points -----------------------------------------------------------------------------

/// The sandwich M P ~M of a unit motor, in closed form. With M = T(t) R, the rotor part
/// (s, b) turns the Euclidean part (R x ~R as the quaternion (s, -b) does: x + s u + (-b) x u,
/// u = 2 (-b) x x) and the ideal part carries the translation
///   t = -2 (p b + s c - b x c)      (= 2 vec(q_d q_r*) under MOTOR-1);
/// a point of weight w moves by w t. The weight is unchanged for a unit motor.
template <class S> Point<S> sandwich(const Motor<S>& m, const Point<S>& pt) {
  const V3<S> b = euclid(m), c = ideal(m);
  const V3<S> x{pt.e032, pt.e013, pt.e021};
  const V3<S> u = cross3(b, x);  // u = b x x, the rotation is x - 2 s u + 2 b x u
  const V3<S> bu = cross3(b, u);
  const V3<S> bc = cross3(b, c);
  const S w2 = 2 * pt.e123;
  return {x[0] - 2 * m.s * u[0] + 2 * bu[0] - w2 * (m.e0123 * b[0] + m.s * c[0] - bc[0]),
          x[1] - 2 * m.s * u[1] + 2 * bu[1] - w2 * (m.e0123 * b[1] + m.s * c[1] - bc[1]),
          x[2] - 2 * m.s * u[2] + 2 * bu[2] - w2 * (m.e0123 * b[2] + m.s * c[2] - bc[2]), pt.e123};
}

// ---- exp and log (MOTOR-4) ----------------------------------------------------------------------

/// Below this |beta| the coefficient functions use their Taylor series (the next term is below
/// 2^-70 relative), above it the closed forms, whose cancellation is harmless there.
template <class S> constexpr S kSeriesBelow = S(0.0625);

/// sin b / b.
template <class S> S sinc(S b, S sin_b) {
  if (b >= kSeriesBelow<S>) return sin_b / b;
  const S b2 = b * b;
  return 1 + b2 * (S(-1) / 6 + b2 * (S(1) / 120 + b2 * (S(-1) / 5040 + b2 * (S(1) / 362880))));
}

/// (cos b - sin b / b) / b^2 (-> -1/3 as b -> 0).
template <class S> S coupling(S b, S sin_b, S cos_b) {
  if (b >= kSeriesBelow<S>) return (cos_b - sin_b / b) / (b * b);
  const S b2 = b * b;
  return S(-1) / 3 + b2 * (S(1) / 30 + b2 * (S(-1) / 840 + b2 * (S(1) / 45360 + b2 * (S(-1) / 3991680))));
}

/// exp(B) for B = beta + u (beta Euclidean, u ideal), b = |beta|, k = u.beta (B^2 = -b^2 + 2k e0123):
///   exp(B) = cos b + sinc(b) beta + (sinc(b) u + f(b) k beta) + k sinc(b) e0123,
/// f(b) = (cos b - sinc b)/b^2, the closed form of Gunn / De Keninck & Dorst written in
/// coefficients (the ideal part of -(k/b^2)(cos b - sinc b) e0123 beta is +k f beta).
/// b = 0: exp(u) = 1 + u, a translator.
template <class S> Motor<S> exp(const Bivector<S>& B) {
  const V3<S> beta{B.e23, B.e31, B.e12}, u{B.e01, B.e02, B.e03};
  const S b = std::sqrt(dot3(beta, beta));
  const S sn = std::sin(b), cs = std::cos(b);
  const S sc = sinc(b, sn), f = coupling(b, sn, cs), k = dot3(u, beta);
  return {cs,
          sc * beta[0],
          sc * beta[1],
          sc * beta[2],
          sc * u[0] + f * k * beta[0],
          sc * u[1] + f * k * beta[1],
          sc * u[2] + f * k * beta[2],
          k * sc};
}

/// log past a quarter turn (s < 0, n > 0) of the unit motor m, whose rotor part was `raw` (s, e23,
/// e31, e12) before normalising: the angle and axis are read off raw. Towards the cut (n -> 0)
/// rho = b / n grows without bound: rho c - f p rho^3 beta would cancel its large parallel terms
/// (and rho^3 overflow), and n = |raw_v| / |raw| can be subnormal in m with few bits left. So the
/// axis comes from raw's Euclidean part scaled by its own power of two, n from the two parts' own
/// scales, beta = b n^, and the ideal part is a n^ + (b / n) c_perp: from exp, c = cos b a n^ +
/// sinc(b) u_perp and p = a sin b, so a = c.n^ / s (|s| >= n) or p / n; c_perp without the
/// subtraction (perpendicular_part.hpp).
template <class S>
[[gnu::noinline]] Bivector<S> log_past_quarter_turn(const Motor<S>& m, const std::array<S, 4>& raw, const V3<S>& raw_c) {
  using std::abs;
  const V3<S> c = ideal(m);
  const int er = std::ilogb(std::max({abs(raw[0]), abs(raw[1]), abs(raw[2]), abs(raw[3])}));
  const int ev = std::ilogb(std::max({abs(raw[1]), abs(raw[2]), abs(raw[3])}));
  const V3<S> w{std::scalbn(raw[1], -ev), std::scalbn(raw[2], -ev), std::scalbn(raw[3], -ev)};
  S r2 = 0;
  for (const S x : raw) {
    const S x_own = std::scalbn(x, -er);
    r2 += x_own * x_own;
  }
  const S w2 = dot3(w, w), wn = std::sqrt(w2), rn = std::sqrt(r2);
  const S n = std::scalbn(wn / rn, ev - er);  // |raw_v| / |raw|, possibly subnormal: only a guess
  const S b = std::atan2(std::scalbn(wn, ev - er), std::scalbn(raw[0], -er));
  const V3<S> axis{w[0] / wn, w[1] / wn, w[2] / wn};
  const S a = abs(m.s) >= n ? dot3(c, axis) / m.s : m.e0123 / n;
  // (b / n) c_perp = b (raw_c)_perp / |raw_v|: normalising scales c_perp by 1 / |raw| and leaves
  // it otherwise alone (its projection runs along the rotor part), so read it off raw_c, whose
  // normalised copy can be subnormal.
  const S cmax = std::max({abs(raw_c[0]), abs(raw_c[1]), abs(raw_c[2])});
  if (cmax == 0) return {b * axis[0], b * axis[1], b * axis[2], a * axis[0], a * axis[1], a * axis[2]};
  const int ec = std::ilogb(cmax);
  const auto pp = runtime::perpendicular_times_norm2<S>(
      {w[0], w[1], w[2], 0}, {std::scalbn(raw_c[0], -ec), std::scalbn(raw_c[1], -ec), std::scalbn(raw_c[2], -ec), 0});
  const S k = b / (w2 * wn);  // (b / n) c_perp = 2^(ec - ev) k pp
  return {b * axis[0], b * axis[1], b * axis[2], a * axis[0] + std::scalbn(k * pp[0], ec - ev),
          a * axis[1] + std::scalbn(k * pp[1], ec - ev), a * axis[2] + std::scalbn(k * pp[2], ec - ev)};
}

/// log of a unit motor with s > -1 (interpolation only takes it with s >= 0, b <= pi/2), the
/// inverse of exp: with n = |Euclidean part| = sin b, b = atan2(n, s), rho = b / n (-> 1):
///   beta = rho (e23, e31, e12),   u = rho c - f(b) p rho^3 (e23, e31, e12)
/// (from exp: k = u.beta = p rho, sinc(b) u = c - f k beta). n = 0: the log of the translator,
/// beta = 0 and u = c. Past a quarter turn: log_past_quarter_turn, from `raw` and `raw_c`, m's
/// rotor part and ideal vector part before m was normalised (m's own by default).
template <class S> Bivector<S> log(const Motor<S>& m, const std::array<S, 4>& raw, const V3<S>& raw_c) {
  const V3<S> bv = euclid(m), c = ideal(m);
  if (m.s < 0 && (raw[1] != 0 || raw[2] != 0 || raw[3] != 0)) return log_past_quarter_turn(m, raw, raw_c);
  const S n = std::sqrt(dot3(bv, bv));
  const S b = std::atan2(n, m.s);
  const S rho = n > 0 ? b / n : S(1);
  const S g = coupling(b, n, m.s) * m.e0123 * rho * rho * rho;
  return {rho * bv[0], rho * bv[1], rho * bv[2], rho * c[0] - g * bv[0], rho * c[1] - g * bv[1], rho * c[2] - g * bv[2]};
}
template <class S> Bivector<S> log(const Motor<S>& m) { return log(m, {m.s, m.e23, m.e31, m.e12}, ideal(m)); }

template <class S> Bivector<S> operator*(S t, const Bivector<S>& B) {
  return {t * B.e23, t * B.e31, t * B.e12, t * B.e01, t * B.e02, t * B.e03};
}

template <class S> Motor<S> operator-(const Motor<S>& m) {
  return {-m.s, -m.e23, -m.e31, -m.e12, -m.e01, -m.e02, -m.e03, -m.e0123};
}

/// MOTOR-4 interpolation of unit motors already on one hemisphere (<M_B ~M_A>_0 >= 0; the caller
/// flips M_B -> -M_B iff it is < 0 strictly, deciding on its inputs as given):
/// exp(t log(M_B ~M_A)) M_A. Any real t (extrapolates).
template <class S> Motor<S> interpolate_aligned(const Motor<S>& a, const Motor<S>& b, S t) {
  return exp(t * log(b * reverse(a))) * a;
}

}  // namespace rotorcert::motor_pga
