// Rotor3: the runtime Cl(3,0) rotor of the paper-rotor group (rotor_m1, rotor_m2,
// paper_literal). Small scalar math in the manner of klein / ozz-animation.
//
// Layout: struct Rotor3<S> { S s, e23, e31, e12; } is the even multivector
//
//     R = s + e23 e2e3 + e31 e3e1 + e12 e1e2 = s + I a,   a = (e23, e31, e12),  I = e1e2e3,
//
// in the cyclic bivector basis of the spec (ALG-1; e31 = e3e1 = -e1e3). Since I e1 = e23,
// I e2 = e31, I e3 = e12, the bivector part is I times the vector a, which is why every formula
// below is a 3-vector formula.
//
// Quaternions map in by Q2R-1:
//
//     Phi(q) = w - x e23 - y e31 - z e12,   i.e. Rotor3{w, -x, -y, -z},
//
// an algebra isomorphism (Phi(pq) = Phi(p) Phi(q)) with Phi(q) v ~Phi(q) = q v q*. The way a
// quaternion becomes a rotor (Method 1 through angle and axis, Method 2 = Phi, the paper's
// printed map) is each implementation's own conversion policy; everything after it is here,
// in RotorOps<S, Conversion>.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <type_traits>
#include <span>
#include <vector>

#include <rotorcert/impl.hpp>
#include <rotorcert/runtime/exact_sign.hpp>
#include <rotorcert/runtime/ordinary_range.hpp>

namespace rotorcert::rotor {

using impl::Status;

template <class S>
struct Rotor3 {
  S s, e23, e31, e12;
};

// ---- scalar helpers --------------------------------------------------------------------

template <class S> constexpr S kEps = std::numeric_limits<S>::epsilon();

/// The exponent that brings m into [1, 2); scalbn(x, -e) is then an exact rescaling of every
/// component, subnormal or huge (NORM-1: no intermediate overflow or underflow).
template <class S>
int scale_exponent(S m) { return std::ilogb(m); }

template <class S, std::size_t N>
bool all_finite(const std::array<S, N>& a) {
  for (S x : a)
    if (!std::isfinite(x)) return false;
  return true;
}

/// A quaternion that stands for a rotation: finite and not all (+-)0 (EDGE-6, EDGE-7).
template <class S>
bool is_rotation(const impl::Quat<S>& q) {
  return all_finite(q) && !(q[0] == 0 && q[1] == 0 && q[2] == 0 && q[3] == 0);
}

/// q 2^e, exact unless a component leaves the format.
template <class S>
impl::Quat<S> rescaled(const impl::Quat<S>& q, int e) {
  return {std::scalbn(q[0], e), std::scalbn(q[1], e), std::scalbn(q[2], e), std::scalbn(q[3], e)};
}

template <class S>
S norm2(const impl::Quat<S>& q) { return q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]; }

template <class S>
S max_abs(const impl::Quat<S>& q) { return std::max({std::abs(q[0]), std::abs(q[1]), std::abs(q[2]), std::abs(q[3])}); }

/// q rescaled by the exact power of two that brings its largest |component| into [1, 2), so that
/// its squares neither overflow nor underflow; q itself where |q|^2 is ordinary already
/// (runtime/ordinary_range.hpp). Precondition: q finite, nonzero.
template <class S>
impl::Quat<S> safely_rescaled(const impl::Quat<S>& q) {
  return runtime::is_ordinary_square(norm2(q)) ? q : rescaled(q, -scale_exponent(max_abs(q)));
}

/// q/|q|. Precondition: is_rotation(q).
template <class S>
impl::Quat<S> normalized(const impl::Quat<S>& q) {
  impl::Quat<S> r = safely_rescaled(q);
  const S n = std::sqrt(norm2(r));
  for (S& c : r) c /= n;
  return r;
}

/// |q| without overflow or underflow.
template <class S>
S norm4(const impl::Quat<S>& q) {
  if (const S n2 = norm2(q); runtime::is_ordinary_square(n2)) return std::sqrt(n2);
  const S m = max_abs(q);
  if (m == 0) return m;
  const int e = scale_exponent(m);
  S sum = 0;
  for (S c : q) sum += std::scalbn(c, -e) * std::scalbn(c, -e);
  return std::scalbn(std::sqrt(sum), e);
}

/// |v| without overflow or underflow.
template <class S>
S norm3(S a, S b, S c) {
  if (const S n2 = a * a + b * b + c * c; runtime::is_ordinary_square(n2)) return std::sqrt(n2);
  const S m = std::max({std::abs(a), std::abs(b), std::abs(c)});
  if (m == 0) return m;
  const int e = scale_exponent(m);
  a = std::scalbn(a, -e), b = std::scalbn(b, -e), c = std::scalbn(c, -e);
  return std::scalbn(std::sqrt(a * a + b * b + c * c), e);
}

/// v/|v| from the rescaled components, so a subnormal v keeps full relative accuracy.
/// Precondition: v finite, nonzero.
template <class S>
impl::Vec3<S> unit_vector(const impl::Vec3<S>& v) {
  if (const S n2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2]; runtime::is_ordinary_square(n2)) {
    const S n = std::sqrt(n2);
    return {v[0] / n, v[1] / n, v[2] / n};
  }
  const S m = std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])});
  const int e = scale_exponent(m);
  const S a = std::scalbn(v[0], -e), b = std::scalbn(v[1], -e), c = std::scalbn(v[2], -e);
  const S n = std::sqrt(a * a + b * b + c * c);
  return {a / n, b / n, c / n};
}

// ---- the algebra -------------------------------------------------------------------------

/// Geometric product, hand-expanded. With R = s + I a: (s + I a)(t + I b) =
/// (s t - a.b) + I (s b + t a - a x b), from I^2 = -1 and a b = a.b + I (a x b).
template <class S>
Rotor3<S> gp(const Rotor3<S>& p, const Rotor3<S>& q) {
  return {p.s * q.s - p.e23 * q.e23 - p.e31 * q.e31 - p.e12 * q.e12,
          p.s * q.e23 + q.s * p.e23 - (p.e31 * q.e12 - p.e12 * q.e31),
          p.s * q.e31 + q.s * p.e31 - (p.e12 * q.e23 - p.e23 * q.e12),
          p.s * q.e12 + q.s * p.e12 - (p.e23 * q.e31 - p.e31 * q.e23)};
}

/// ~R: reversion negates bivectors.
template <class S>
Rotor3<S> reverse(const Rotor3<S>& r) { return {r.s, -r.e23, -r.e31, -r.e12}; }

template <class S>
Rotor3<S> negated(const Rotor3<S>& r) { return {-r.s, -r.e23, -r.e31, -r.e12}; }

/// <A ~B>_0, the coefficient dot product (equal to a.b of the quaternions under Phi).
template <class S>
S dot(const Rotor3<S>& a, const Rotor3<S>& b) { return a.s * b.s + a.e23 * b.e23 + a.e31 * b.e31 + a.e12 * b.e12; }

/// R/|R| after an exact rescaling.
template <class S>
Rotor3<S> normalized(const Rotor3<S>& r) {
  const impl::Quat<S> n = normalized(impl::Quat<S>{r.e23, r.e31, r.e12, r.s});
  return {n[3], n[0], n[1], n[2]};
}

/// R x ~R for a unit rotor, closed form: with t = 2 (x ^ a)-dual = -2 a x x,
/// R x ~R = x + s t - a x t (the quaternion formula x + 2w (v x x) + 2 v x (v x x), v = -a).
template <class S>
impl::Vec3<S> sandwich_vector(const Rotor3<S>& r, const impl::Vec3<S>& x) {
  const S tx = S(-2) * (r.e31 * x[2] - r.e12 * x[1]);
  const S ty = S(-2) * (r.e12 * x[0] - r.e23 * x[2]);
  const S tz = S(-2) * (r.e23 * x[1] - r.e31 * x[0]);
  return {x[0] + r.s * tx - (r.e31 * tz - r.e12 * ty),
          x[1] + r.s * ty - (r.e12 * tx - r.e23 * tz),
          x[2] + r.s * tz - (r.e23 * ty - r.e31 * tx)};
}

/// R B ~R for a unit rotor and B = b23 e23 + b31 e31 + b12 e12 = I b: I is central, so
/// R (I b) ~R = I (R b ~R) and the coefficients rotate exactly like a vector (APPLY-2).
template <class S>
impl::Vec3<S> sandwich_bivector(const Rotor3<S>& r, const impl::Vec3<S>& b) { return sandwich_vector(r, b); }

/// The matrix of x -> R x ~R (unit R), column-major: column c is the image of e_c.
/// In quaternion terms (w, x, y, z) = (s, -e23, -e31, -e12); the rows of MAT-1.
template <class S>
impl::Mat3<S> to_matrix(const Rotor3<S>& r) {
  const S w = r.s, x = -r.e23, y = -r.e31, z = -r.e12;
  const S xx = x * x, yy = y * y, zz = z * z, xy = x * y, xz = x * z, yz = y * z, wx = w * x, wy = w * y, wz = w * z;
  return {S(1) - S(2) * (yy + zz), S(2) * (xy + wz), S(2) * (xz - wy),
          S(2) * (xy - wz), S(1) - S(2) * (xx + zz), S(2) * (yz + wx),
          S(2) * (xz + wy), S(2) * (yz - wx), S(1) - S(2) * (xx + yy)};
}

/// atan2(y, x); for binary32 arguments computed in binary64 and rounded once (within half a
/// binary32 ulp plus glibc's binary64 error), which is also faster: glibc 2.36's atan2f takes
/// longer per call than its atan2.
template <class S>
S atan2_in_binary64(S y, S x) {
  if constexpr (std::is_same_v<S, float>) return float(std::atan2(double(y), double(x)));
  else return std::atan2(y, x);
}

/// exp of the bivector b = (e23, e31, e12) (EXP-1, the paper's eq. 5 with b = -u theta/2):
/// exp(b) = cos|b| + b sin|b|/|b|. sin x / x by its series where x^2 < eps (no 0/0; exp(0) = 1
/// exactly).
template <class S>
Rotor3<S> exp(const impl::Vec3<S>& b) {
  const S n = norm3(b[0], b[1], b[2]);
  if (n == 0) return {S(1), S(0), S(0), S(0)};
  const S sinc = n * n < kEps<S> ? S(1) - n * n / S(6) : std::sin(n) / n;
  return {std::cos(n), sinc * b[0], sinc * b[1], sinc * b[2]};
}

/// Principal log (LOG-1, LOG-2) of R/|R| as a bivector (e23, e31, e12), |log| in [0, pi]:
/// log(s + B) = atan2(|B|, s) B/|B|. Scale-free, so R need not be unit. atan2, never acos:
/// acos loses half the digits near the identity. For |B| << s the factor atan(r)/r with
/// r = |B|/s is its series 1 - r^2/3 + r^4/5 (truncation r^6/7 < eps). log(1) = 0 exactly;
/// the cut log(-1) = -pi e12.
template <class S>
impl::Vec3<S> log(const Rotor3<S>& r) {
  const S n = norm3(r.e23, r.e31, r.e12);
  if (n == 0) {
    if (r.s > 0) return {S(0), S(0), S(0)};
    return {S(0), S(0), -std::numbers::pi_v<S>};
  }
  if (r.s > 0) {
    const S q = n / r.s, q2 = q * q;
    if (q2 * q2 * q2 < kEps<S>) {
      const S f = (S(1) - q2 / S(3) + q2 * q2 / S(5)) / r.s;
      return {f * r.e23, f * r.e31, f * r.e12};
    }
  }
  // The direction from the rescaled components (unit_vector): B / |B| on B itself loses the
  // relative accuracy of a subnormal |B| (fuzz/corpus/log_exp/regression-rotor-log-*).
  const S angle = atan2_in_binary64(n, r.s);
  const impl::Vec3<S> u = unit_vector(impl::Vec3<S>{r.e23, r.e31, r.e12});
  return {angle * u[0], angle * u[1], angle * u[2]};
}

/// Rotor interpolation (SLERP-2): R(t) = exp(t log(R_B ~R_A)) R_A for unit R_A, R_B, on the
/// shorter arc: R_B -> -R_B iff <R_B ~R_A>_0 < 0 strictly (a tie +-0 does not flip, EDGE-3).
/// Any finite t (extrapolation, SLERP-4). R_A = R_B gives a difference with zero bivector
/// part exactly, hence R_A exactly.
/// `flip` is the hemisphere decision; callers take it on their inputs as given
/// (runtime::hemisphere_sign), because the rotors' own <R_B ~R_A>_0 is rounded.
template <class S>
Rotor3<S> interpolate(const Rotor3<S>& ra, const Rotor3<S>& rb, S t, bool flip) {
  Rotor3<S> d = gp(rb, reverse(ra));
  if (flip) d = negated(d);
  const impl::Vec3<S> l = log(d);
  return gp(exp(impl::Vec3<S>{t * l[0], t * l[1], t * l[2]}), ra);
}
template <class S>
Rotor3<S> interpolate(const Rotor3<S>& ra, const Rotor3<S>& rb, S t) {
  const std::array<S, 4> a{ra.s, ra.e23, ra.e31, ra.e12}, b{rb.s, rb.e23, rb.e31, rb.e12};
  return interpolate(ra, rb, t, runtime::hemisphere_sign(a, b) < 0);
}

namespace matrix_detail {

template <class S>
S at(const impl::Mat3<S>& m, int r, int c) { return m[c * 3 + r]; }

/// cof(M) (cof[c*3 + r] = cofactor of (r, c), i.e. det M M^-T) and det M.
template <class S>
impl::Mat3<S> cofactors(const impl::Mat3<S>& m, S& det) {
  impl::Mat3<S> cof;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      const int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
      cof[c * 3 + r] = at(m, r1, c1) * at(m, r2, c2) - at(m, r1, c2) * at(m, r2, c1);
    }
  det = at(m, 0, 0) * cof[0] + at(m, 0, 1) * cof[3] + at(m, 0, 2) * cof[6];
  return cof;
}

/// |M|_F, with the largest |entry| divided out so that no square under- or overflows.
template <class S>
S frobenius(const impl::Mat3<S>& m) {
  S big = 0;
  for (S e : m) big = std::max(big, std::abs(e));
  if (big == 0) return 0;
  S s = 0;
  for (S e : m) s += (e / big) * (e / big);
  return big * std::sqrt(s);
}

/// det M > 0, decided on M as given at any spread of scales: each of the six terms of det M is
/// a product of frexp mantissas times 2^(sum of exponents), and the terms are summed at the
/// largest exponent. No product under- or overflows, so the computed sign is det M's wherever
/// |det M| > 8u per(|M|) (MAT-3's band: two roundings per term, five in the sum).
template <class S>
bool determinant_is_positive(const impl::Mat3<S>& m) {
  constexpr int kPermutations[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  std::array<S, 6> mantissa{};
  std::array<int, 6> exponent{};
  int largest = std::numeric_limits<int>::min();
  for (int p = 0; p < 6; ++p) {
    S product = p < 3 ? S(1) : S(-1);
    for (int row = 0; row < 3; ++row) {
      int e = 0;
      product *= std::frexp(at(m, row, kPermutations[p][row]), &e);
      exponent[p] += e;
    }
    mantissa[p] = product;
    if (product != 0) largest = std::max(largest, exponent[p]);
  }
  S sum = 0;
  for (int p = 0; p < 6; ++p)
    if (mantissa[p] != 0) sum += std::scalbn(mantissa[p], exponent[p] - largest);
  return sum > 0;
}

/// ||X^T X - I||_F^2: MAT-3's delta, squared, as computed in S.
template <class S>
S orthonormality_defect2(const impl::Mat3<S>& x) {
  S defect = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      S g = i == j ? S(-1) : S(0);
      for (int k = 0; k < 3; ++k) g += at(x, k, i) * at(x, k, j);
      defect += g * g;
    }
  return defect;
}

}  // namespace matrix_detail

/// Shepperd's quaternion of a matrix x that is a rotation or the polar factor's stand-in
/// (MAT-2): the largest of 4w^2, 4x^2, 4y^2, 4z^2 (trace or a diagonal entry) is the pivot, so
/// no division is by a small number. Read out as Phi of the normalised quaternion; nullopt
/// where the quaternion is not a rotation (zero or non-finite).
template <class S>
std::optional<Rotor3<S>> shepperd_rotor(const impl::Mat3<S>& x) {
  using matrix_detail::at;
  const S m00 = at(x, 0, 0), m11 = at(x, 1, 1), m22 = at(x, 2, 2);
  const S trace = m00 + m11 + m22;
  impl::Quat<S> q;  // [x, y, z, w]
  if (trace >= m00 && trace >= m11 && trace >= m22) {
    const S w = S(0.5) * std::sqrt(S(1) + trace), f = S(0.25) / w;
    q = {(at(x, 2, 1) - at(x, 1, 2)) * f, (at(x, 0, 2) - at(x, 2, 0)) * f, (at(x, 1, 0) - at(x, 0, 1)) * f, w};
  } else if (m00 >= m11 && m00 >= m22) {
    const S v = S(0.5) * std::sqrt(S(1) + m00 - m11 - m22), f = S(0.25) / v;
    q = {v, (at(x, 0, 1) + at(x, 1, 0)) * f, (at(x, 0, 2) + at(x, 2, 0)) * f, (at(x, 2, 1) - at(x, 1, 2)) * f};
  } else if (m11 >= m22) {
    const S v = S(0.5) * std::sqrt(S(1) - m00 + m11 - m22), f = S(0.25) / v;
    q = {(at(x, 0, 1) + at(x, 1, 0)) * f, v, (at(x, 1, 2) + at(x, 2, 1)) * f, (at(x, 0, 2) - at(x, 2, 0)) * f};
  } else {
    const S v = S(0.5) * std::sqrt(S(1) - m00 - m11 + m22), f = S(0.25) / v;
    q = {(at(x, 0, 2) + at(x, 2, 0)) * f, (at(x, 1, 2) + at(x, 2, 1)) * f, v, (at(x, 1, 0) - at(x, 0, 1)) * f};
  }
  if (!is_rotation(q)) return std::nullopt;
  q = normalized(q);
  return Rotor3<S>{q[3], -q[0], -q[1], -q[2]};
}

/// The cheap test of MAT-3's fast path: M is finite, its entries at most 2 in magnitude, det M
/// (cofactor expansion) above 1/2 and delta = ||M^T M - I||_F at most `tolerance`. Such an M is a
/// rotation to within delta, so Shepperd's quaternion of M as given is within about 0.66 delta
/// of the polar factor's (first order; sampled with rotations near pi) plus a few roundings,
/// inside MAT-3's strict bar 16 eps + 2 delta, and the polar iteration with its scaling is
/// not needed. nullopt: the input needs rotor_from_matrix_wide (or is not a rotation).
template <class S>
std::optional<Rotor3<S>> rotor_from_near_orthonormal_matrix(const impl::Mat3<S>& x, S tolerance) {
  using matrix_detail::at;
  bool bounded = true;  // also false for NaN
  for (S e : x) bounded = bounded & (std::abs(e) <= S(2));
  if (!bounded) return std::nullopt;
  const S det = at(x, 0, 0) * (at(x, 1, 1) * at(x, 2, 2) - at(x, 1, 2) * at(x, 2, 1)) -
                at(x, 0, 1) * (at(x, 1, 0) * at(x, 2, 2) - at(x, 1, 2) * at(x, 2, 0)) +
                at(x, 0, 2) * (at(x, 1, 0) * at(x, 2, 1) - at(x, 1, 1) * at(x, 2, 0));
  if (!(det > S(0.5))) return std::nullopt;
  if (!(matrix_detail::orthonormality_defect2(x) <= tolerance * tolerance)) return std::nullopt;
  return shepperd_rotor(x);
}

/// rotor_from_matrix in one format (binary64 for every caller).
template <class S>
std::optional<Rotor3<S>> rotor_from_matrix_wide(const impl::Mat3<S>& matrix) {
  using matrix_detail::at;
  using matrix_detail::cofactors;
  using matrix_detail::frobenius;
  if (!all_finite(matrix)) return std::nullopt;
  S big = 0;
  for (S e : matrix) big = std::max(big, std::abs(e));
  if (big == 0) return std::nullopt;
  const int ex = scale_exponent(big);
  impl::Mat3<S> x;
  for (int i = 0; i < 9; ++i) x[i] = std::scalbn(matrix[i], -ex);
  S det;
  impl::Mat3<S> cof = cofactors(x, det);
  const S small_det = std::sqrt(std::numeric_limits<S>::min());  // the cheap test's threshold
  if (!(det >= small_det)) {
    // Every nonzero entry of M at least 2^(emin/3) in x's scale (read on M: x may have lost
    // entries to underflow): no product of three underflows, and the cofactor expansion's sign
    // is det M's outside MAT-3's band (an exactly repeated column gives det = 0 exactly,
    // EX-MAT-3-f). Otherwise the sign comes from M as given.
    bool products_normal = true;
    for (S e : matrix)
      products_normal = products_normal && (e == 0 || std::ilogb(e) - ex >= std::numeric_limits<S>::min_exponent / 3);
    if (!(products_normal ? det > 0 : matrix_detail::determinant_is_positive(matrix))) return std::nullopt;
    // Lift the small singular values (at most twice: the second pass lifts a second tiny one).
    for (int pass = 0; pass < 2 && !(det >= small_det); ++pass) {
      const S c = frobenius(cof);
      // Rank <= 1 at this scale (the rest underflowed when M was scaled): the polar factor is
      // lost to the format; Shepperd below still returns a unit rotor, as MAT-3's bar asks.
      if (!(c > 0)) break;
      for (int i = 0; i < 9; ++i) x[i] += cof[i] / c;
      cof = cofactors(x, det);
    }
  }
  if (std::sqrt(matrix_detail::orthonormality_defect2(x)) > S(8) * kEps<S>) {
    for (int iteration = 0; iteration < 60; ++iteration) {
      if (iteration > 0) cof = cofactors(x, det);
      if (!(det > 0)) break;
      const S r = std::sqrt(frobenius(cof) / frobenius(x)), root_det = std::sqrt(det);
      const S g = r / root_det, h = S(1) / (r * root_det);  // g, and 1/(g det)
      S change = 0;
      for (int i = 0; i < 9; ++i) {
        const S next = S(0.5) * (g * x[i] + h * cof[i]);
        change += (next - x[i]) * (next - x[i]);
        x[i] = next;
      }
      if (std::sqrt(change) <= S(16) * kEps<S>) break;
    }
  }
  return shepperd_rotor(x);
}

/// The rotor of a matrix M: the unit R with R e_c ~R = column c of M's orthogonal polar factor
/// (the nearest rotation, MAT-3), returned as Phi of the quaternion from Shepperd's largest-
/// pivot method (MAT-2). det <= 0, zero or non-finite M: nullopt.
///
/// A rotation rounded to the format (the cheap test of rotor_from_near_orthonormal_matrix) goes
/// straight to Shepperd. Any other M: the polar factor comes from Higham's scaled Newton
/// iteration X <- (g X + X^-T / g) / 2. Range (MAT-3 lets det M be any
/// positive number, so the singular values may spread over the whole exponent range):
///  - X^-T and g are never formed: with C = cof(X) = det X^-T, g = r / sqrt(det) and
///    X^-T / g = C / (r sqrt(det)), r = sqrt(|C|_F / |X|_F), all finite for any det > 0;
///  - a det below sqrt(min normal) at the scale max|x| in [1, 2) is the cheap test for the
///    rare input that needs more: its sign is that of the cofactor expansion where no product
///    of three entries underflows, else decided on M as given (determinant_is_positive), and
///    X becomes X + C / |C|_F, which has the same U and V as X = U S V^T (cof(X) = U S' V^T
///    with S' the products of the other two singular values, all > 0 for det > 0) and so the
///    same polar factor, with its smallest singular value lifted to about 1;
///  - binary32 input runs in binary64, whose range covers every product of three binary32.
template <class S>
std::optional<Rotor3<S>> rotor_from_matrix(const impl::Mat3<S>& matrix) {
  // The fast path's tolerance is 8 eps of the input's format: a rotation rounded to the format
  // passes it, and Shepperd's error on it (about 5 eps) is inside the strict bar whatever delta.
  if constexpr (std::is_same_v<S, float>) {
    impl::Mat3<double> wide;
    for (int i = 0; i < 9; ++i) wide[i] = matrix[i];
    std::optional<Rotor3<double>> r = rotor_from_near_orthonormal_matrix(wide, 8.0 * kEps<float>);
    if (!r) r = rotor_from_matrix_wide(wide);
    if (!r) return std::nullopt;
    const impl::Quat<float> q{float(r->e23), float(r->e31), float(r->e12), float(r->s)};
    if (!is_rotation(q)) return std::nullopt;
    const impl::Quat<float> n = normalized(q);
    return Rotor3<float>{n[3], n[0], n[1], n[2]};
  } else {
    if (std::optional<Rotor3<S>> r = rotor_from_near_orthonormal_matrix(matrix, S(8) * kEps<S>)) return r;
    return rotor_from_matrix_wide(matrix);
  }
}

/// MAT-2's sign rule on a quaternion [x, y, z, w]: w > 0, or for w = 0 the first nonzero of
/// x, y, z positive.
template <class S>
impl::Quat<S> canonical_sign(impl::Quat<S> q) {
  bool flip = q[3] < 0;
  if (q[3] == 0) {
    const S first = q[0] != 0 ? q[0] : (q[1] != 0 ? q[1] : q[2]);
    flip = first < 0;
  }
  if (flip)
    for (S& c : q) c = -c;
  return q;
}

// ---- the operations of the ABI, for any quaternion -> rotor conversion -----------------

/// Phi and its inverse (Q2R-1), the read-out of rotor_m1 and rotor_m2.
struct PhiReadout {
  template <class S> static impl::Quat<S> out(const Rotor3<S>& r) { return {-r.e23, -r.e31, -r.e12, r.s}; }
  /// The quaternion view of a bivector (a log): the pure quaternion v with Phi(v) = B.
  template <class S> static impl::Vec3<S> pure_out(const impl::Vec3<S>& b) { return {-b[0], -b[1], -b[2]}; }
  template <class S> static impl::Vec3<S> pure_in(const impl::Vec3<S>& v) { return {-v[0], -v[1], -v[2]}; }
};

/// The corrected Method 2 (ERRATUM-2): quaternion -> rotor by the coefficient map Phi (Q2R-1), no
/// trigonometry on the way in; the conversion of rotor_m2 and rotor_gen.
struct Method2 : PhiReadout {
  /// Phi(q/|q|): a normalisation (EDGE-5) and a move of coefficients with sign changes.
  template <class S>
  static Rotor3<S> in(const impl::Quat<S>& q) {
    const impl::Quat<S> n = normalized(q);
    return {n[3], -n[0], -n[1], -n[2]};
  }
  /// Phi(q), exact (COMPOSE-1 and INV-1 keep the scale of their inputs).
  template <class S>
  static Rotor3<S> in_scaled(const impl::Quat<S>& q) { return {q[3], -q[0], -q[1], -q[2]}; }
};

/// What a complete Cl(3,0) rotor implementation on RotorOps claims (rotor_m1, rotor_m2, rotor_gen):
/// its levels and every clause of them (nullptr-terminated, as impl.hpp's `clauses`).
inline constexpr std::uint32_t kRotorLevels =
    RC_LEVEL_CORE | RC_LEVEL_INTERP | RC_LEVEL_BLEND | RC_LEVEL_SKINNING | RC_LEVEL_ROBUST;
inline constexpr const char* kRotorClauses[] = {
    // Core
    "QUAT-2", "AXANG-1", "AXANG-2", "AXANG-3", "AXANG-4", "NORM-1", "COMPOSE-1", "INV-1", "APPLY-1", "APPLY-2",
    "APPLY-3", "MAT-1", "MAT-2",
    // Interp
    "LOG-1", "LOG-2", "EXP-1", "EXP-2", "SQRT-1", "SLERP-1", "SLERP-2", "SLERP-3", "SLERP-4", "SLERP-5", "NLERP-1",
    // Blend
    "QLB-1", "LOGBLEND-1",
    // Skinning (linear blend skinning only)
    "SKIN-1",
    // Robust
    "MAT-3", "EDGE-1", "EDGE-2", "EDGE-3", "EDGE-4", "EDGE-5", "EDGE-6", "EDGE-7", "EDGE-8", "EDGE-9", nullptr};

/// The operations of the ABI (impl.hpp element functions), computed on rotors. Conv provides
///   static Rotor3<S> in(const Quat<S>& q);         // unit rotor of q/|q|; q a rotation
///   static Rotor3<S> in_scaled(const Quat<S>& q);  // |q| times that (COMPOSE-1, INV-1)
///   static Quat<S> out(const Rotor3<S>& r);        // the read-out map
///   static Vec3<S> pure_in(v), pure_out(b);        // pure quaternion <-> bivector
/// Only the conversion differs between rotor_m1, rotor_m2 and paper_literal.
template <class S, class Conv>
struct RotorOps {
  using Scalar = S;
  using Q = impl::Quat<S>;
  using V = impl::Vec3<S>;
  using M = impl::Mat3<S>;
  static constexpr Status ok = Status::ok, bad = Status::domain_error;

  static Status normalize(const Q& q, Q& out) {
    if (!is_rotation(q)) return bad;
    out = Conv::out(Conv::in(q));
    return ok;
  }
  /// a b, no normalisation (COMPOSE-1): the rotors carry |a| and |b|. Each factor is rescaled
  /// by a power of two first and the product scaled back once, so |a| or |b| beyond the format
  /// (components near the overflow threshold, EDGE-5) cannot turn a representable product into
  /// Inf * 0 = NaN. Ordinary |a|^2 and |b|^2 (runtime/ordinary_range.hpp) need no rescaling.
  static Status compose(const Q& a, const Q& b, Q& out) {
    if (!is_rotation(a) || !is_rotation(b)) return bad;
    if (runtime::is_ordinary_square(norm2(a)) && runtime::is_ordinary_square(norm2(b))) {
      out = Conv::out(gp(Conv::in_scaled(a), Conv::in_scaled(b)));
      return ok;
    }
    const int ea = scale_exponent(max_abs(a)), eb = scale_exponent(max_abs(b));
    const Rotor3<S> p = gp(Conv::in_scaled(rescaled(a, -ea)), Conv::in_scaled(rescaled(b, -eb)));
    out = Conv::out(Rotor3<S>{std::scalbn(p.s, ea + eb), std::scalbn(p.e23, ea + eb), std::scalbn(p.e31, ea + eb),
                              std::scalbn(p.e12, ea + eb)});
    return ok;
  }
  /// R^-1 = ~R / (R ~R), on q rescaled by a power of two so |q|^2 cannot overflow.
  static Status inverse(const Q& q, Q& out) {
    if (!is_rotation(q)) return bad;
    if (const S n2 = norm2(q); runtime::is_ordinary_square(n2)) {
      const Rotor3<S> rr = reverse(Conv::in_scaled(q));
      out = Conv::out(Rotor3<S>{rr.s / n2, rr.e23 / n2, rr.e31 / n2, rr.e12 / n2});
      return ok;
    }
    const int e = scale_exponent(max_abs(q));
    const Rotor3<S> r = Conv::in_scaled(rescaled(q, -e));
    const S n2 = dot(r, r);
    const Rotor3<S> rr = reverse(r);
    out = Conv::out(Rotor3<S>{std::scalbn(rr.s / n2, -e), std::scalbn(rr.e23 / n2, -e), std::scalbn(rr.e31 / n2, -e),
                              std::scalbn(rr.e12 / n2, -e)});
    return ok;
  }
  static Status apply_vector(const Q& q, const V& v, V& out) {
    if (!is_rotation(q) || !all_finite(v)) return bad;
    out = sandwich_vector(Conv::in(q), v);
    return ok;
  }
  static Status apply_bivector(const Q& q, const V& b, V& out) {
    if (!is_rotation(q) || !all_finite(b)) return bad;
    out = sandwich_bivector(Conv::in(q), b);
    return ok;
  }
  /// R (a I) ~R = a (R ~R) I = a I: I is central and R ~R = 1, so nothing is computed.
  static Status apply_trivector(const Q& q, const S& a, S& out) {
    if (!is_rotation(q) || !std::isfinite(a)) return bad;
    out = a;
    return ok;
  }
  static Status to_matrix(const Q& q, M& out) {
    if (!is_rotation(q)) return bad;
    out = rotor::to_matrix(Conv::in(q));
    return ok;
  }
  /// Shepperd's quaternion (of the polar factor), converted in and read out, sign by MAT-2.
  static Status from_matrix(const M& m, Q& out) {
    const std::optional<Rotor3<S>> r = rotor_from_matrix(m);
    if (!r) return bad;
    out = canonical_sign(Conv::out(Conv::in(PhiReadout::out(*r))));
    return ok;
  }
  /// B/|B| of q's rotor from q's vector part alone, as the bivector of the rotor of the half turn
  /// (x, y, z, 0). q/|q| flushes a vector part below 2^-1074 |q| (2^-149 in binary32) to zero and
  /// keeps a few bits of one near it, beside w ~ -|q| a rotation just short of a full turn whose
  /// axis is still v/|v| (fuzz/corpus/rotation_parts/regression-rotor-tiny-vector-part-*).
  /// Precondition: the vector part is nonzero.
  static V plane_of(const Q& q) {
    const Rotor3<S> half_turn = Conv::in(Q{q[0], q[1], q[2], S(0)});
    return {half_turn.e23, half_turn.e31, half_turn.e12};
  }
  static bool zero_vector_part(const Q& q) { return q[0] == 0 && q[1] == 0 && q[2] == 0; }

  /// The paper's eq. 5 read backwards: R = cos(theta/2) - I u sin(theta/2), so
  /// theta = 2 atan2(|B|, s) in [0, 2 pi] and u = -B/|B| (B's coefficients as a vector).
  static Status to_axis_angle(const Q& q, S& angle, V& axis) {
    if (!is_rotation(q)) return bad;
    angle = angle_of(q);
    axis = axis_of(q);
    return ok;
  }
  /// ABI version 3, AXANG-3 and AXANG-4: the two halves of to_axis_angle, each computing only
  /// its own half (the same values as to_axis_angle's).
  static Status to_angle(const Q& q, S& angle) {
    if (!is_rotation(q)) return bad;
    angle = angle_of(q);
    return ok;
  }
  static Status to_axis(const Q& q, V& axis) {
    if (!is_rotation(q)) return bad;
    axis = axis_of(q);
    return ok;
  }
  /// theta of the rotor of q (a rotation), through the method's conversion.
  static S angle_of(const Q& q) {
    const Rotor3<S> r = Conv::in(q);
    return S(2) * atan2_in_binary64(norm3(r.e23, r.e31, r.e12), r.s);
  }
  /// u of q (a rotation): -B/|B| from q's vector part (plane_of), +z for the identity's.
  static V axis_of(const Q& q) {
    if (zero_vector_part(q)) return {S(0), S(0), S(1)};
    const V b = plane_of(q);
    return {-b[0], -b[1], -b[2]};
  }
  /// ABI version 3, SQRT-1: sqrt(R) = (1 + R)/|1 + R| for the unit rotor R = s + B of q, half the
  /// angle about the same plane. For s < 0, 1 + s = |B|^2/(1 - s) (R ~R = 1) without cancellation,
  /// and the common factor |B| is divided out first: (|B|/(1 - s), B/|B|), normalised. R = -1 has
  /// every unit bivector as a root: -e12, the quaternion +z (LOG-2's axis). The plane B/|B| is
  /// plane_of(q): the root of (2^-815 (1, -1, 1), -2^760) is about (1, -1, 1)/sqrt(3), not +z.
  static Status sqrt(const Q& q, Q& out) {
    if (!is_rotation(q)) return bad;
    const Rotor3<S> r = Conv::in(q);
    if (r.s >= 0) {
      out = Conv::out(normalized(Rotor3<S>{S(1) + r.s, r.e23, r.e31, r.e12}));
      return ok;
    }
    if (zero_vector_part(q)) {
      out = Conv::out(Rotor3<S>{S(0), S(0), S(0), S(-1)});
      return ok;
    }
    const S n = norm3(r.e23, r.e31, r.e12);
    const V b = plane_of(q);
    out = Conv::out(normalized(Rotor3<S>{n / (S(1) - r.s), b[0], b[1], b[2]}));
    return ok;
  }
  /// Eq. 5: R = exp(-I u theta/2) = cos(theta/2) - I u sin(theta/2), u = axis/|axis|.
  static Status from_axis_angle(const S& angle, const V& axis, Q& out) {
    if (!std::isfinite(angle) || !all_finite(axis) || (axis[0] == 0 && axis[1] == 0 && axis[2] == 0)) return bad;
    const V u = unit_vector(axis);
    const S h = angle / S(2), c = std::cos(h), s = std::sin(h);
    out = Conv::out(Rotor3<S>{c, -s * u[0], -s * u[1], -s * u[2]});
    return ok;
  }
  static Status log(const Q& q, V& out) {
    if (!is_rotation(q)) return bad;
    const Rotor3<S> r = Conv::in(q);
    if (r.s >= 0 || zero_vector_part(q)) {
      out = Conv::pure_out(rotor::log(r));
      return ok;
    }
    // atan2(|B|, s) B/|B| with the plane from plane_of: near a full turn |log| ~ pi, and a B that
    // q/|q| lost would give LOG-2's -pi e12 instead of pi times q's own axis.
    const S angle = atan2_in_binary64(norm3(r.e23, r.e31, r.e12), r.s);
    const V b = plane_of(q);
    out = Conv::pure_out(V{angle * b[0], angle * b[1], angle * b[2]});
    return ok;
  }
  static Status exp(const V& v, Q& out) {
    if (!all_finite(v)) return bad;
    out = Conv::out(rotor::exp(Conv::pure_in(v)));
    return ok;
  }
  static Status slerp(const Q& a, const Q& b, const S& t, Q& out) {
    if (!is_rotation(a) || !is_rotation(b) || !std::isfinite(t)) return bad;
    out = Conv::out(interpolate(Conv::in(a), Conv::in(b), t, runtime::hemisphere_sign(a, b) < 0));
    return ok;
  }
  /// normalize(R_A + t (R_B' - R_A)) in rotor coefficients, flip iff <R_B ~R_A>_0 < 0. The
  /// sum is scaled by 1/max(1, |t|) so a huge t cannot overflow; R_A = R_B' gives R_A exactly.
  static Status nlerp(const Q& a, const Q& b, const S& t, Q& out) {
    if (!is_rotation(a) || !is_rotation(b) || !std::isfinite(t)) return bad;
    const Rotor3<S> ra = Conv::in(a);
    Rotor3<S> rb = Conv::in(b);
    if (runtime::hemisphere_sign(a, b) < 0) rb = negated(rb);  // on the inputs as given (EDGE-3)
    const S k = S(1) / std::max(S(1), std::abs(t)), u = t * k;
    const Rotor3<S> sum{k * ra.s + u * (rb.s - ra.s), k * ra.e23 + u * (rb.e23 - ra.e23),
                        k * ra.e31 + u * (rb.e31 - ra.e31), k * ra.e12 + u * (rb.e12 - ra.e12)};
    out = Conv::out(normalized(sum));
    return ok;
  }

  /// A blend's weights divided by the largest: on the stack up to 16 influences (the suite's
  /// blends have at most 8), where a heap allocation per element cost more than the arithmetic.
  class BlendWeights {
   public:
    explicit BlendWeights(std::size_t k) {
      if (k > local_.size()) heap_.resize(k);
    }
    S* data() { return heap_.empty() ? local_.data() : heap_.data(); }
    S& operator[](std::size_t i) { return data()[i]; }

   private:
    std::array<S, 16> local_;
    std::vector<S> heap_;
  };

  /// Blend rules (EDGE-9): sizes match, nonempty, every quaternion a rotation (even with
  /// weight 0), weights finite and >= 0 (-0 is 0), some weight > 0. Sets the pivot (first
  /// weight > 0) and the weights divided by the largest (the blends are scale-free in w).
  static bool influences(std::span<const Q> q, std::span<const S> w, std::size_t& pivot, S* scaled) {
    if (q.empty() || q.size() != w.size()) return false;
    S wmax = 0;
    for (std::size_t i = 0; i < q.size(); ++i) {
      if (!is_rotation(q[i]) || !std::isfinite(w[i]) || w[i] < 0) return false;
      wmax = std::max(wmax, w[i]);
    }
    if (!(wmax > 0)) return false;
    pivot = q.size();
    for (std::size_t i = 0; i < q.size(); ++i) {
      if (pivot == q.size() && w[i] > 0) pivot = i;
      scaled[i] = w[i] / wmax;
    }
    return true;
  }

  /// QLB-1 in rotor coefficients: normalize(sum w_i s_i R_i), s_i = -1 iff <R_i ~R_p>_0 < 0.
  static Status blend_qlb(std::span<const Q> q, std::span<const S> w, Q& out) {
    std::size_t p = 0;
    BlendWeights ws(q.size());
    if (!influences(q, w, p, ws.data())) return bad;
    Rotor3<S> sum{0, 0, 0, 0};
    for (std::size_t i = 0; i < q.size(); ++i) {
      const Rotor3<S> r = Conv::in(q[i]);
      const S k = runtime::hemisphere_sign(q[i], q[p]) < 0 ? -ws[i] : ws[i];  // exact (EDGE-3)
      sum = {sum.s + k * r.s, sum.e23 + k * r.e23, sum.e31 + k * r.e31, sum.e12 + k * r.e12};
    }
    out = Conv::out(normalized(sum));
    return ok;
  }
  /// LOGBLEND-1: R_p exp(sum (w_i/W) log(align(~R_p R_i))), align negates when the scalar < 0.
  static Status blend_log(std::span<const Q> q, std::span<const S> w, Q& out) {
    std::size_t p = 0;
    BlendWeights ws(q.size());
    if (!influences(q, w, p, ws.data())) return bad;
    S total = 0;
    for (std::size_t i = 0; i < q.size(); ++i) total += ws[i];
    const Rotor3<S> rp = Conv::in(q[p]);
    const Rotor3<S> rp_rev = reverse(rp);
    V sum{0, 0, 0};
    for (std::size_t i = 0; i < q.size(); ++i) {
      Rotor3<S> d = gp(rp_rev, Conv::in(q[i]));
      if (runtime::hemisphere_sign(q[p], q[i]) < 0) d = negated(d);  // <d>_0 = q_p . q_i, exactly
      const V l = rotor::log(d);
      const S k = ws[i] / total;
      for (int c = 0; c < 3; ++c) sum[c] += k * l[c];
    }
    out = Conv::out(gp(rp, rotor::exp(sum)));
    return ok;
  }
  /// SKIN-1: sum (w_i/W) (M_i v + t_i) with M_i the matrix of the rotor of q_i.
  static Status skin_linear(std::span<const Q> q, std::span<const V> t, std::span<const S> w, const V& v, V& out) {
    std::size_t p = 0;
    BlendWeights ws(q.size());
    if (t.size() != q.size() || !all_finite(v) || !influences(q, w, p, ws.data())) return bad;
    for (const V& ti : t)
      if (!all_finite(ti)) return bad;
    S total = 0;
    V acc{0, 0, 0};
    for (std::size_t i = 0; i < q.size(); ++i) {
      total += ws[i];
      const M m = rotor::to_matrix(Conv::in(q[i]));
      for (int r = 0; r < 3; ++r) acc[r] += ws[i] * (m[r] * v[0] + m[3 + r] * v[1] + m[6 + r] * v[2] + t[i][r]);
    }
    out = {acc[0] / total, acc[1] / total, acc[2] / total};
    return ok;
  }
};

}  // namespace rotorcert::rotor
