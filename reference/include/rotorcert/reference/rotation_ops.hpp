// The rotation operations of the spec (NORM-1 ... BLENDQ-1): the functions that define the
// expected result of each clause.
//
// Written like a textbook (Dorst, Fontijne & Mann): where a clause is about rotors, the
// reference computes in Cl(3,0) -- Phi(q) = w - x e23 - y e31 - z e12 (Q2R-1), the sandwich
// R x ~R, exp and log of bivectors -- and reads the quaternion back with the inverse map.
// Plain quaternion formulas appear only where the clause itself is written in them (QUAT-1,
// the slerp formula of SLERP-1, nlerp, QLB). Clarity beats speed.
//
// Every function is a template over the scalar T (Real = MPFR at >= 256 bits, the oracle; or
// double) and validates its input first (EDGE-6, EDGE-7, EDGE-9): a non-finite component, a
// zero quaternion, or bad weights give DOMAIN_ERROR with every output component NaN.
// A finite nonzero quaternion stands for the rotation q/|q| (EDGE-5); normalisation scales
// by the largest |component| first, so it neither overflows nor underflows (NORM-1).
#pragma once

#include <algorithm>
#include <array>
#include <optional>
#include <cstddef>
#include <span>
#include <type_traits>
#include <vector>

#include "cl3.hpp"
#include "metrics.hpp"
#include "multivector.hpp"
#include "quaternion.hpp"
#include "result.hpp"
#include "scalar.hpp"

namespace rotorcert::ref::clause {

/// Which blend BLENDQ-1 compares with the Karcher mean.
enum class BlendMethod { qlb, log_blend };

namespace detail {

/// A finite, nonzero quaternion: one that stands for a rotation (EDGE-6, EDGE-7).
template <class T>
bool is_rotation(const Quaternion<T>& q) { return finite(q) && !is_zero(q); }

/// x + 0 turns -0 into +0 and changes nothing else (round to nearest): the reference never
/// answers "-0" for a coefficient that is simply absent.
template <class T>
T plus_zero(const T& x) { return x + T(0); }

/// The rotor of the rotation q/|q| (Q2R-1 applied to the normalised quaternion).
template <class T>
cl3::MV<T> rotor(const Quaternion<T>& q) { return cl3::rotor_from_quaternion(normalized(q)); }

/// The inverse map of Q2R-1, with absent coefficients read as +0.
template <class T>
Quaternion<T> quaternion(const cl3::MV<T>& r) {
  const Quaternion<T> q = cl3::quaternion_from_rotor(r);
  return {plus_zero(q.w), plus_zero(q.x), plus_zero(q.y), plus_zero(q.z)};
}

/// Inverse of a versor: ~R / (R ~R) (INV-1).
template <class T>
cl3::MV<T> versor_inverse(const cl3::MV<T>& r) { return reverse(r) / scp(r, reverse(r)); }

/// v/|v| without overflow or underflow (largest |component| first). Precondition: v finite, nonzero.
template <class T>
Vec3<T> unit_vector(const Vec3<T>& v) {
  using std::abs;
  using std::sqrt;
  const T m = largest_magnitude(v[0], v[1], v[2]);
  const Vec3<T> s{v[0] / m, v[1] / m, v[2] / m};
  const T n = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  return {s[0] / n, s[1] / n, s[2] / n};
}

/// Rotor log and exp as multivectors: cl3::log_rotor and cl3::exp_bivector (LOG-1, LOG-2,
/// EXP-1), whose |B| is scaled so that double keeps subnormal and huge angles.
template <class T>
cl3::MV<T> log(const cl3::MV<T>& r) { return cl3::bivector(cl3::log_rotor(r)); }
template <class T>
cl3::MV<T> exp(const cl3::MV<T>& bivector) { return cl3::exp_bivector(cl3::bivector_part(bivector)); }

/// SLERP-2 in the algebra: exp(t log(R_B ~R_A)) R_A, on the shorter arc: R_B -> -R_B iff
/// <R_B ~R_A>_0 < 0 strictly (the tie rule of SLERP-1; EDGE-3). R_A, R_B unit rotors.
/// `flip` is the hemisphere decision, taken by the caller on the exact inputs (hemisphere_sign).
template <class T>
cl3::MV<T> rotor_interpolation(const cl3::MV<T>& ra, const cl3::MV<T>& rb, const T& t, bool flip) {
  cl3::MV<T> d = gp(rb, reverse(ra));  // the rotor that takes R_A to R_B
  if (flip) d = -d;
  return gp(exp(t * log(d)), ra);
}

/// A span of influences is usable when sizes match, it is not empty, every quaternion is a
/// rotation, every weight is finite and >= 0 (-0 counts as 0), and some weight is > 0
/// (EDGE-9). On success `pivot` is the first influence with weight > 0 (QLB-1) and `scaled`
/// holds w_i / max w: the same blend (every blend divides by the sum or normalises), but sums
/// of huge doubles cannot overflow.
template <class T>
bool valid_influences(std::span<const Quaternion<T>> q, std::span<const T> w, std::size_t& pivot,
                      std::vector<T>& scaled) {
  if (q.size() != w.size() || q.empty()) return false;
  using std::max;  // max, not a comparison: equal weights need no decision (Bounded)
  T wmax(0);
  for (std::size_t i = 0; i < q.size(); ++i) {
    if (!is_rotation(q[i]) || !finite(w[i]) || w[i] < 0) return false;
    wmax = max(wmax, w[i]);
  }
  if (!(wmax > 0)) return false;  // all weights zero: zero sum
  pivot = q.size();
  scaled.clear();
  for (std::size_t i = 0; i < q.size(); ++i) {
    if (pivot == q.size() && w[i] > 0) pivot = i;
    scaled.push_back(w[i] / wmax);
  }
  return true;
}

/// KARCHER-1 stopping rule: the norm of the last update's log below 2^-(precision - 16)
/// for Real (NUM-2); 1e-15 for double.
template <class T>
T karcher_step_tolerance() {
  if constexpr (std::is_same_v<T, double>) {
    return 1e-15;
  } else {
    using std::ldexp;
    return ldexp(T(1), -(static_cast<int>(T::get_default_prec()) - 16));
  }
}

/// Karcher mean of unit rotors (the fixed-point iteration of KARCHER-1), weights scaled.
template <class T>
cl3::MV<T> karcher_rotor(const std::vector<cl3::MV<T>>& r, const std::vector<T>& w, std::size_t pivot) {
  using std::sqrt;
  T total(0);
  for (const T& wi : w) total += wi;
  cl3::MV<T> m = r[pivot];
  for (int iteration = 0; iteration < 200; ++iteration) {
    // The Riemannian gradient of sum w_i dist(m, r_i)^2 is (up to a factor) the weighted
    // mean of the logs of ~m r_i, each on the shorter arc.
    cl3::MV<T> step;
    for (std::size_t i = 0; i < r.size(); ++i) {
      cl3::MV<T> d = gp(reverse(m), r[i]);
      if (d.c[0] < 0) d = -d;
      step = step + (w[i] / total) * log(d);
    }
    m = gp(m, exp(step));
    m = m / sqrt(scp(m, reverse(m)));  // stay on the rotor group despite rounding
    if (sqrt(scp(step, reverse(step))) < karcher_step_tolerance<T>()) break;
  }
  return m;
}

/// Symmetric 4x4 eigen-decomposition by the cyclic Jacobi method: rotate away each
/// off-diagonal entry in turn until the off-diagonal part is negligible. `vectors[k][j]` is
/// component k of eigenvector j.
template <class T>
struct Eigen4 {
  std::array<T, 4> values;
  std::array<std::array<T, 4>, 4> vectors;
};

template <class T>
Eigen4<T> jacobi_eigen(std::array<std::array<T, 4>, 4> a) {
  using std::abs;
  using std::hypot;
  using std::sqrt;
  std::array<std::array<T, 4>, 4> v;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) v[i][j] = T(i == j ? 1 : 0);
  const T eps = ScalarTraits<T>::epsilon();
  for (int sweep = 0; sweep < 64; ++sweep) {
    T off(0), total(0);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        total += a[i][j] * a[i][j];
        if (i != j) off += a[i][j] * a[i][j];
      }
    if (off <= eps * eps * total / T(16)) break;
    for (int p = 0; p < 3; ++p)
      for (int q = p + 1; q < 4; ++q) {
        if (a[p][q] == 0) continue;
        // Rotation in the (p, q) plane that zeroes a[p][q]: t = tan(phi) is the smaller root
        // of t^2 + 2 theta t - 1 = 0, theta = cot(2 phi) (Numerical Recipes, section 11.1).
        const T theta = (a[q][q] - a[p][p]) / (T(2) * a[p][q]);
        const T t = (theta >= 0 ? T(1) : T(-1)) / (abs(theta) + hypot(theta, T(1)));
        const T c = T(1) / sqrt(t * t + T(1));
        const T s = t * c;
        for (int k = 0; k < 4; ++k) {  // A <- A P (columns p and q)
          const T akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 4; ++k) {  // A <- P^T A (rows p and q)
          const T apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        a[p][q] = a[q][p] = T(0);
        for (int k = 0; k < 4; ++k) {  // V <- V P
          const T vkp = v[k][p], vkq = v[k][q];
          v[k][p] = c * vkp - s * vkq;
          v[k][q] = s * vkp + c * vkq;
        }
      }
  }
  return {{a[0][0], a[1][1], a[2][2], a[3][3]}, v};
}

}  // namespace detail

// ---- normalisation, composition, inverse -----------------------------------------------

/// NORM-1: q/|q|, scaled by the largest |component| first (no intermediate overflow or
/// underflow at any scale, subnormals included: EDGE-5, EDGE-8).
template <class T>
Result<Quaternion<T>> NORM_1_normalize(const Quaternion<T>& q) {
  if (!detail::is_rotation(q)) return domain_error<Quaternion<T>>();
  return {normalized(q), Status::ok};
}

/// COMPOSE-1: compose(a, b) = a b (apply b first), computed as Phi(a) Phi(b). The plain product,
/// not normalised: its norm is |a||b| and its rotation is that of a/|a| after b/|b| (EDGE-5).
template <class T>
Result<Quaternion<T>> COMPOSE_1_compose(const Quaternion<T>& a, const Quaternion<T>& b) {
  if (!detail::is_rotation(a) || !detail::is_rotation(b)) return domain_error<Quaternion<T>>();
  return {detail::quaternion(gp(cl3::rotor_from_quaternion(a), cl3::rotor_from_quaternion(b))), Status::ok};
}

/// INV-1: q^-1 = q*/|q|^2, as the versor inverse ~R/(R ~R) of R = Phi(q). Not normalised
/// (the clause defines the algebraic inverse). To avoid overflow R is Phi(q/m), m the largest
/// |component|, and Phi(q)^-1 = (Phi(q/m))^-1 / m.
template <class T>
Result<Quaternion<T>> INV_1_inverse(const Quaternion<T>& q) {
  using std::abs;
  if (!detail::is_rotation(q)) return domain_error<Quaternion<T>>();
  const T m = largest_magnitude(q.w, q.x, q.y, q.z);
  const cl3::MV<T> r = cl3::rotor_from_quaternion(Quaternion<T>{q.w / m, q.x / m, q.y / m, q.z / m});
  return {detail::quaternion(detail::versor_inverse(r) / m), Status::ok};
}

// ---- action on vectors, bivectors, trivectors ------------------------------------------

/// APPLY-1: R x ~R with R = Phi(q/|q|).
template <class T>
Result<Vec3<T>> APPLY_1_apply_vector(const Quaternion<T>& q, const Vec3<T>& v) {
  if (!detail::is_rotation(q) || !finite(v)) return domain_error<Vec3<T>>();
  return {cl3::vector_part(cl3::sandwich(detail::rotor(q), cl3::vector(v))), Status::ok};
}

/// APPLY-2: R B ~R for the bivector B = b23 e23 + b31 e31 + b12 e12. (Since I is central,
/// R (I n) ~R = I (R n ~R): the coefficients rotate like a vector. The test checks that;
/// here the bivector is rotated as itself.)
template <class T>
Result<Vec3<T>> APPLY_2_apply_bivector(const Quaternion<T>& q, const Vec3<T>& b) {
  if (!detail::is_rotation(q) || !finite(b)) return domain_error<Vec3<T>>();
  return {cl3::bivector_part(cl3::sandwich(detail::rotor(q), cl3::bivector(b))), Status::ok};
}

/// APPLY-3: R (s I) ~R, which is s I: rotations preserve oriented volume.
template <class T>
Result<T> APPLY_3_apply_trivector(const Quaternion<T>& q, const T& s) {
  if (!detail::is_rotation(q) || !finite(s)) return domain_error<T>();
  return {cl3::sandwich(detail::rotor(q), s * cl3::I<T>()).c[cl3::kE123], Status::ok};
}

// ---- matrices ---------------------------------------------------------------------------

/// MAT-1: the matrix of the linear map x -> R x ~R, R = Phi(q/|q|): column c is the image

namespace detail {

/// A/|A|_F + cof(A)/|cof(A)|_F for det A > 0 (see MAT_2_from_matrix): the same polar factor.
/// cof(A)[c*3 + r] is the cofactor of entry (r, c).
template <class T>
Mat3<T> lift_small_singular_values(const Mat3<T>& a) {
  using std::sqrt;
  const auto at = [&](int r, int c) { return a[c * 3 + r]; };
  Mat3<T> cof;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      const int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
      cof[c * 3 + r] = at(r1, c1) * at(r2, c2) - at(r1, c2) * at(r2, c1);
    }
  T na(0), nc(0);
  for (int i = 0; i < 9; ++i) na += a[i] * a[i], nc += cof[i] * cof[i];
  na = sqrt(na), nc = sqrt(nc);
  Mat3<T> out;
  for (int i = 0; i < 9; ++i) out[i] = a[i] / na + cof[i] / nc;
  return out;
}

}  // namespace detail

/// of e_c. Column-major: m[c*3 + r].
template <class T>
Result<Mat3<T>> MAT_1_to_matrix(const Quaternion<T>& q) {
  if (!detail::is_rotation(q)) return domain_error<Mat3<T>>();
  const cl3::MV<T> r = detail::rotor(q);
  Mat3<T> m;
  for (int c = 0; c < 3; ++c) {
    Vec3<T> e{T(0), T(0), T(0)};
    e[c] = T(1);
    const Vec3<T> image = cl3::vector_part(cl3::sandwich(r, cl3::vector(e)));
    for (int row = 0; row < 3; ++row) m[c * 3 + row] = image[row];
  }
  return {m, Status::ok};
}

namespace detail {

/// MAT-2's symmetric 4x4 K of M (rows and columns in the order x, y, z, w; see MAT_2_from_matrix
/// below), or nullopt where M is outside the domain: a non-finite entry, det M <= 0.
template <class T>
std::optional<std::array<std::array<T, 4>, 4>> from_matrix_k(const Mat3<T>& matrix) {
  using std::abs;
  using std::max;  // (unqualified: a bounded scalar's max needs no branch)
  if (!finite(matrix)) return std::nullopt;
  // A positive scale changes neither the nearest rotation nor the sign of det; dividing by
  // the largest |entry| keeps det and K finite in double.
  T big(0);
  for (const T& e : matrix) big = max(big, T(abs(e)));
  if (big == 0) return std::nullopt;
  auto m = [&](int r, int c) { return matrix[c * 3 + r] / big; };
  const T det = m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)) -
                m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0)) +
                m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
  if (!(det > 0)) return std::nullopt;
  Mat3<T> a;  // column-major, as M
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) a[c * 3 + r] = m(r, c);
  for (int pass = 0; pass < 2; ++pass) a = lift_small_singular_values(a);
  const auto at = [&](int r, int c) { return a[c * 3 + r]; };
  const T third = T(1) / T(3);
  return std::array<std::array<T, 4>, 4>{{
      {third * (at(0, 0) - at(1, 1) - at(2, 2)), third * (at(1, 0) + at(0, 1)), third * (at(2, 0) + at(0, 2)), third * (at(2, 1) - at(1, 2))},
      {third * (at(1, 0) + at(0, 1)), third * (at(1, 1) - at(0, 0) - at(2, 2)), third * (at(2, 1) + at(1, 2)), third * (at(0, 2) - at(2, 0))},
      {third * (at(2, 0) + at(0, 2)), third * (at(2, 1) + at(1, 2)), third * (at(2, 2) - at(0, 0) - at(1, 1)), third * (at(1, 0) - at(0, 1))},
      {third * (at(2, 1) - at(1, 2)), third * (at(0, 2) - at(2, 0)), third * (at(1, 0) - at(0, 1)), third * (at(0, 0) + at(1, 1) + at(2, 2))},
  }};
}

/// The eigenvector of the largest eigenvalue, its components in K's order.
template <class T>
std::array<T, 4> top_eigenvector(const Eigen4<T>& eig) {
  int best = 0;
  for (int j = 1; j < 4; ++j)
    if (eig.values[j] > eig.values[best]) best = j;
  return {eig.vectors[0][best], eig.vectors[1][best], eig.vectors[2][best], eig.vectors[3][best]};
}

/// MAT-2's answer from a (near-)unit eigenvector q of K's largest eigenvalue: normalised, with
/// w > 0, or, if w == 0, the first nonzero of x, y, z positive.
template <class T>
Quaternion<T> from_matrix_answer(Quaternion<T> q) {
  q = normalized(q);
  bool negate = q.w < 0;
  if (q.w == 0) {
    const T first = q.x != 0 ? q.x : (q.y != 0 ? q.y : q.z);
    negate = first < 0;
  }
  if (negate) q = -q;
  return {plus_zero(q.w), plus_zero(q.x), plus_zero(q.y), plus_zero(q.z)};
}

}  // namespace detail

/// MAT-2, MAT-3: the quaternion of the rotation nearest to M in the Frobenius norm
/// (Bar-Itzhack 2000): for unit q, tr(M^T R(q)) = 3 q^T K q with the symmetric 4x4 K below,
/// so the nearest rotation is the eigenvector of K's largest eigenvalue. For an exact rotation
/// matrix that is the quaternion of M itself (eigenvalue 1).
/// K's two largest eigenvalues differ by about twice the sum of M's two smaller singular
/// values, relative to the largest: a matrix whose singular values spread beyond the working
/// precision (MAT-3 allows any det > 0) would leave the eigenvector undetermined. So K is built
/// from A = M/|M|_F + C/|C|_F, applied twice, with C = cof(M) = det(M) M^-T: with M = U S V^T,
/// C = U S' V^T (S'_i the product of the other two singular values, > 0 for det > 0), so A has
/// M's U and V and the same polar factor, and its smallest singular value is lifted to at
/// least about 1/sqrt(3) of its largest (the second pass lifts a second small one).
/// Sign: w > 0; if w == 0, the first nonzero of x, y, z positive. det(M) <= 0 or a
/// non-finite entry: DOMAIN_ERROR.
template <class T>
Result<Quaternion<T>> MAT_2_from_matrix(const Mat3<T>& matrix) {
  const auto k = detail::from_matrix_k(matrix);
  if (!k) return domain_error<Quaternion<T>>();
  // (Components that are exactly 0 in a half turn stay exactly 0: for an exactly formed matrix
  // their rows and columns of K are 0 off the diagonal, so no Jacobi rotation ever mixes them in.)
  const std::array<T, 4> v = detail::top_eigenvector(detail::jacobi_eigen(*k));  // x, y, z, w
  return {detail::from_matrix_answer(Quaternion<T>{v[3], v[0], v[1], v[2]}), Status::ok};
}

// ---- angle and axis ---------------------------------------------------------------------

/// AXANG-1: R = Phi(q/|q|) = cos(theta/2) - I u sin(theta/2). The scalar part is cos(theta/2),
/// the undual of the bivector part is sin(theta/2) u, so theta = 2 atan2(|v|, w) in [0, 2 pi],
/// u = v/|v|; u = (0, 0, 1) when v = 0.
template <class T>
Result<AxisAngle<T>> AXANG_1_to_axis_angle(const Quaternion<T>& q) {
  using std::atan2;
  if (!detail::is_rotation(q)) return domain_error<AxisAngle<T>>();
  const cl3::MV<T> r = detail::rotor(q);
  const Vec3<T> v = cl3::vector_part(cl3::undual(grade(r, 2)));  // sin(theta/2) u
  const T s = cl3::norm3(v);
  AxisAngle<T> a;
  a.angle = T(2) * atan2(s, r.c[0]);
  if (s == 0) a.axis = {T(0), T(0), T(1)};
  else a.axis = {detail::plus_zero(v[0] / s), detail::plus_zero(v[1] / s), detail::plus_zero(v[2] / s)};
  return {a, Status::ok};
}

/// Q2R-4, Method 1: R = exp(-I u theta/2) for the unit u = axis/|axis|, computed in the
/// algebra: the bivector -I u theta/2 is a geometric product, exp is EXP-1.
/// Zero or non-finite axis, non-finite angle: DOMAIN_ERROR.
template <class T>
Result<cl3::MV<T>> Q2R_4_method1(const T& angle, const Vec3<T>& axis) {
  if (!finite(angle) || !finite(axis) || (axis[0] == 0 && axis[1] == 0 && axis[2] == 0)) {
    Result<cl3::MV<T>> bad;
    for (T& c : bad.value.c) c = ScalarTraits<T>::nan();
    bad.status = Status::domain_error;
    return bad;
  }
  const cl3::MV<T> u = cl3::vector(detail::unit_vector(axis));
  const cl3::MV<T> b = gp(cl3::I<T>(), u) * (-angle / T(2));
  return {detail::exp(b), Status::ok};
}

/// AXANG-2: q = (cos(theta/2), sin(theta/2) u/|u|), as Phi^-1 of Method 1 (Q2R-4).
template <class T>
Result<Quaternion<T>> AXANG_2_from_axis_angle(const T& angle, const Vec3<T>& axis) {
  const Result<cl3::MV<T>> r = Q2R_4_method1(angle, axis);
  if (r.status != Status::ok) return domain_error<Quaternion<T>>();
  return {detail::quaternion(r.value), Status::ok};
}

/// SQRT-1: for finite nonzero q with R = Phi(q/|q|) != -1, the rotor square root (1 + R)/|1 + R|
/// (the unique s with s^2 = q/|q| and s.w > 0: half the angle of AXANG-1 about the same axis);
/// R = -1 (v = 0, w < 0): s = (0, 0, 1, 0), +z exactly (LOG-2's axis). Formed in the quaternion
/// view; 1 + w is formed as |v|^2 / (1 - w) for w < 0, without cancellation.
template <class T>
Result<Quaternion<T>> SQRT_1_sqrt(const Quaternion<T>& q) {
  if (!finite(q) || is_zero(q)) return domain_error<Quaternion<T>>();
  if (q.x == 0 && q.y == 0 && q.z == 0 && q.w < 0) return {Quaternion<T>{T(0), T(0), T(0), T(1)}, Status::ok};
  const Quaternion<T> u = normalized(q);
  const T v2 = u.x * u.x + u.y * u.y + u.z * u.z;
  const T a = u.w >= 0 ? T(1) + u.w : v2 / (T(1) - u.w);
  return {normalized(Quaternion<T>{a, u.x, u.y, u.z}), Status::ok};
}

// ---- the quaternion <-> rotor map -------------------------------------------------------

/// Q2R-1: Phi(q) = w - x e23 - y e31 - z e12 (exact, no normalisation).
template <class T>
cl3::MV<T> Q2R_1_rotor_from_quaternion(const Quaternion<T>& q) { return cl3::rotor_from_quaternion(q); }

/// Q2R-1, inverse: w = <R>_0, x = -R_e23, y = -R_e31, z = -R_e12 (exact).
template <class T>
Quaternion<T> Q2R_1_quaternion_from_rotor(const cl3::MV<T>& r) { return cl3::quaternion_from_rotor(r); }

/// Q2R-5: one of the 48 coefficient maps w -> w, (x, y, z) -> a signed permutation onto
/// (e23, e31, e12). Component k of (x, y, z) goes to sign[k] * basis[target[k]].
/// Q2R-1 is target (0, 1, 2), signs (-1, -1, -1).
struct SignedMap {
  std::array<int, 3> target{0, 1, 2};
  std::array<int, 3> sign{-1, -1, -1};
};

struct MapVerdict {
  SignedMap map;
  bool is_homomorphism = false;    // Psi(pq) = Psi(p) Psi(q)  (Q2R-2)
  bool rotates_correctly = false;  // Psi(q) v ~Psi(q) = q v q* (Q2R-3)
};

template <class T>
cl3::MV<T> Q2R_5_apply_map(const SignedMap& map, const Quaternion<T>& q) {
  const std::array<T, 3> v{q.x, q.y, q.z};
  Vec3<T> b{T(0), T(0), T(0)};
  for (int k = 0; k < 3; ++k) b[map.target[k]] = T(map.sign[k]) * v[k];
  cl3::MV<T> r = cl3::bivector(b);
  r.c[0] = q.w;
  return r;
}

/// All 48 signed maps: 6 permutations times 8 sign patterns.
inline std::array<SignedMap, 48> Q2R_5_all_maps() {
  std::array<SignedMap, 48> maps;
  std::array<int, 3> perm{0, 1, 2};
  int n = 0;
  do {
    for (int signs = 0; signs < 8; ++signs) {
      SignedMap m;
      m.target = perm;
      for (int k = 0; k < 3; ++k) m.sign[k] = (signs >> k) & 1 ? -1 : +1;
      maps[n++] = m;
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
  return maps;
}

/// Decides both properties exactly, in Real with small integer quaternions (every product is
/// exact). The homomorphism is checked on all 16 pairs of basis quaternions 1, i, j, k, which
/// by bilinearity proves it; the rotation on i, j, k, 1+i, 1+j, 1+k and a generic q against
/// e1, e2, e3, unnormalised (both sides scale by |q|^2), with the hand-written Hamilton product.
inline MapVerdict Q2R_5_classify(const SignedMap& map) {
  using Q = Quaternion<Real>;
  const std::array<Q, 4> basis{Q{1, 0, 0, 0}, Q{0, 1, 0, 0}, Q{0, 0, 1, 0}, Q{0, 0, 0, 1}};
  auto same = [](const cl3::MV<Real>& a, const cl3::MV<Real>& b) { return a.c == b.c; };
  MapVerdict verdict;
  verdict.map = map;
  verdict.is_homomorphism = true;
  for (const Q& p : basis)
    for (const Q& q : basis)
      if (!same(Q2R_5_apply_map(map, p * q), gp(Q2R_5_apply_map(map, p), Q2R_5_apply_map(map, q))))
        verdict.is_homomorphism = false;
  const std::array<Q, 7> rotations{Q{0, 1, 0, 0}, Q{0, 0, 1, 0}, Q{0, 0, 0, 1}, Q{1, 1, 0, 0},
                                   Q{1, 0, 1, 0}, Q{1, 0, 0, 1}, Q{1, 2, -3, 4}};
  verdict.rotates_correctly = true;
  for (const Q& q : rotations)
    for (int k = 0; k < 3; ++k) {
      const Q v{0, k == 0 ? 1 : 0, k == 1 ? 1 : 0, k == 2 ? 1 : 0};
      const Q expected = q * v * conj(q);
      const cl3::MV<Real> psi = Q2R_5_apply_map(map, q);
      const cl3::MV<Real> got = gp(gp(psi, cl3::vector<Real>({v.x, v.y, v.z})), reverse(psi));
      if (!same(got, cl3::vector<Real>({expected.x, expected.y, expected.z}))) verdict.rotates_correctly = false;
    }
  return verdict;
}

/// Q2R-5 helper: the verdict for each of the 48 maps, in the order of Q2R_5_all_maps().
inline std::array<MapVerdict, 48> Q2R_5_classify_maps() {
  std::array<MapVerdict, 48> verdicts;
  const std::array<SignedMap, 48> maps = Q2R_5_all_maps();
  for (int i = 0; i < 48; ++i) verdicts[i] = Q2R_5_classify(maps[i]);
  return verdicts;
}

/// Q2R-5: how many of the 48 maps are both a homomorphism and rotate like q v q*. Expect 1.
inline int Q2R_5_count_valid_maps() {
  int n = 0;
  for (const MapVerdict& v : Q2R_5_classify_maps())
    if (v.is_homomorphism && v.rotates_correctly) ++n;
  return n;
}

// ---- log and exp ------------------------------------------------------------------------

/// LOG-1, LOG-2: log of q/|q| in the quaternion view, (x, y, z) = atan2(|v|, w) v/|v| (half
/// angle times axis). Computed as the principal rotor log of Phi(q/|q|), a bivector B with
/// |B| <= pi; Phi maps the pure quaternion (x, y, z) to -(x e23 + y e31 + z e12), so the view
/// is -B's coefficients. log(1) = (0, 0, 0) exactly; log(-1) = -pi e12 = (0, 0, pi).
template <class T>
Result<Vec3<T>> LOG_1_log(const Quaternion<T>& q) {
  if (!detail::is_rotation(q)) return domain_error<Vec3<T>>();
  const Vec3<T> b = cl3::bivector_part(detail::log(detail::rotor(q)));
  // 0 - b rather than -b: a zero coefficient reads +0.
  return {{T(0) - b[0], T(0) - b[1], T(0) - b[2]}, Status::ok};
}

/// EXP-1: exp of the pure quaternion v: (cos|v|, sin|v| v/|v|), computed as the rotor exp of
/// the bivector Phi(v) = -(v1 e23 + v2 e31 + v3 e12). exp(0) = 1 exactly.
template <class T>
Result<Quaternion<T>> EXP_1_exp(const Vec3<T>& v) {
  if (!finite(v)) return domain_error<Quaternion<T>>();
  const cl3::MV<T> b = cl3::rotor_from_quaternion(Quaternion<T>{T(0), v[0], v[1], v[2]});
  return {detail::quaternion(detail::exp(b)), Status::ok};
}

// ---- interpolation ----------------------------------------------------------------------

/// SLERP-1, SLERP-3, SLERP-4: a (a^-1 b')^t for the normalised inputs, b' = -b iff
/// a.b < 0 strictly (EDGE-3), evaluated as (sin((1-t) W) a + sin(t W) b') / sin W.
/// W = 2 atan2(|a - b'|, |a + b'|), the angle between a and b' on S^3 in [0, pi/2]: chord
/// lengths keep full accuracy at small angles where acos(a.b') does not. W = 0 returns a
/// exactly (no 0/0). Any finite t, inside [0, 1] or not, uses the same formula.
template <class T>
Result<Quaternion<T>> SLERP_1_slerp(const Quaternion<T>& qa, const Quaternion<T>& qb, const T& t) {
  using std::atan2;
  using std::sin;
  if (!detail::is_rotation(qa) || !detail::is_rotation(qb) || !finite(t)) return domain_error<Quaternion<T>>();
  const Quaternion<T> a = normalized(qa);
  Quaternion<T> b = normalized(qb);
  if (hemisphere_sign(qa, qb) < 0) b = -b;  // decided on the exact inputs (EDGE-3)
  const T omega = T(2) * atan2(norm(a - b), norm(a + b));
  if (omega == 0) return {a, Status::ok};
  const T sa = sin((T(1) - t) * omega), sb = sin(t * omega), s = sin(omega);
  return {{(sa * a.w + sb * b.w) / s, (sa * a.x + sb * b.x) / s, (sa * a.y + sb * b.y) / s, (sa * a.z + sb * b.z) / s},
          Status::ok};
}

/// SLERP-2: rotor interpolation exp(t log(R_B ~R_A)) R_A in Cl(3,0), R = Phi(q/|q|), on the
/// shorter arc (R_B -> -R_B iff <R_B ~R_A>_0 < 0). Equals Phi(slerp(a, b, t)).
template <class T>
Result<Quaternion<T>> SLERP_2_rotor_interpolation(const Quaternion<T>& a, const Quaternion<T>& b, const T& t) {
  if (!detail::is_rotation(a) || !detail::is_rotation(b) || !finite(t)) return domain_error<Quaternion<T>>();
  return {detail::quaternion(detail::rotor_interpolation(detail::rotor(a), detail::rotor(b), t, hemisphere_sign(a, b) < 0)), Status::ok};
}

/// NLERP-1: normalize((1-t) a + t b'), with a, b normalised and the flip rule of SLERP-1.
/// The sum is never zero (a and b' are independent or equal). Evaluated as a + t (b' - a),
/// the same vector, which is exactly a when b' = a (no cancellation between (1-t) and t for
/// large |t|), and divided by max(1, |t|) first so that a huge t cannot overflow.
template <class T>
Result<Quaternion<T>> NLERP_1_nlerp(const Quaternion<T>& qa, const Quaternion<T>& qb, const T& t) {
  using std::abs;
  if (!detail::is_rotation(qa) || !detail::is_rotation(qb) || !finite(t)) return domain_error<Quaternion<T>>();
  const Quaternion<T> a = normalized(qa);
  Quaternion<T> b = normalized(qb);
  if (hemisphere_sign(qa, qb) < 0) b = -b;  // decided on the exact inputs (EDGE-3)
  const T scale = std::max(T(1), T(abs(t)));
  return {normalized((T(1) / scale) * a + (t / scale) * (b - a)), Status::ok};
}

// ---- blending ----------------------------------------------------------------------------

/// QLB-1: normalize(sum w_i s_i q_i) of the normalised q_i, s_i = -1 iff q_i . q_p < 0
/// (strictly), pivot p the first influence with weight > 0. Weights need not sum to 1.
/// The sum is never zero: its dot with q_p is at least w_p > 0.
template <class T>
Result<Quaternion<T>> QLB_1_blend(std::span<const Quaternion<T>> q, std::span<const T> w) {
  std::size_t p = 0;
  std::vector<T> ws;
  if (!detail::valid_influences(q, w, p, ws)) return domain_error<Quaternion<T>>();
  Quaternion<T> sum{T(0), T(0), T(0), T(0)};
  for (std::size_t i = 0; i < q.size(); ++i) {
    const Quaternion<T> qi = normalized(q[i]);
    sum = sum + (hemisphere_sign(q[i], q[p]) < 0 ? -ws[i] : ws[i]) * qi;  // exact decision (EDGE-3)
  }
  return {normalized(sum), Status::ok};
}

/// LOGBLEND-1: q_p exp(sum (w_i/W) log(align(q_p^-1 q_i))), W = sum w, align negates when the
/// w component is < 0 (strictly). In the algebra: R_p exp(sum (w_i/W) log(align(~R_p R_i))).
template <class T>
Result<Quaternion<T>> LOGBLEND_1_blend(std::span<const Quaternion<T>> q, std::span<const T> w) {
  std::size_t p = 0;
  std::vector<T> ws;
  if (!detail::valid_influences(q, w, p, ws)) return domain_error<Quaternion<T>>();
  T total(0);
  for (const T& wi : ws) total += wi;
  const cl3::MV<T> rp = detail::rotor(q[p]);
  cl3::MV<T> b;
  for (std::size_t i = 0; i < q.size(); ++i) {
    // The pivot's own term: ~R_p R_p = |R_p|^2 is a positive scalar, whose log is exactly 0 (LOG-1).
    // Skipped rather than computed: in interval arithmetic (the fuzzers' ref::Bounded) its
    // bivector part is only nearly 0, and log's branch at 0 could not be decided.
    if (i == p) continue;
    cl3::MV<T> d = gp(reverse(rp), detail::rotor(q[i]));  // q_p^-1 q_i; <d>_0 = q_p . q_i
    if (hemisphere_sign(q[p], q[i]) < 0) d = -d;          // decided on the exact inputs (EDGE-3)
    b = b + (ws[i] / total) * detail::log(d);
  }
  return {detail::quaternion(gp(rp, detail::exp(b))), Status::ok};
}

/// KARCHER-1: the weighted geodesic mean, minimiser of sum w_i dist(m, q_i)^2, by the
/// fixed-point iteration m <- m exp(sum (w_i/W) log(align(m^-1 q_i))) from the pivot, until
/// the update's log norm is below 2^-(precision-16) (Real) or 1e-15 (double), at most 200 steps.
template <class T>
Result<Quaternion<T>> KARCHER_1_mean(std::span<const Quaternion<T>> q, std::span<const T> w) {
  std::size_t p = 0;
  std::vector<T> ws;
  if (!detail::valid_influences(q, w, p, ws)) return domain_error<Quaternion<T>>();
  std::vector<cl3::MV<T>> r;
  for (const Quaternion<T>& qi : q) r.push_back(detail::rotor(qi));
  return {detail::quaternion(detail::karcher_rotor(r, ws, p)), Status::ok};
}

/// BLENDQ-1 (informative): the rotation distance (METRIC-1) of a blend from the Karcher mean
/// of the same influences.
template <class T>
Result<T> BLENDQ_1_deviation(std::span<const Quaternion<T>> q, std::span<const T> w, BlendMethod method) {
  const Result<Quaternion<T>> blend = method == BlendMethod::qlb ? QLB_1_blend(q, w) : LOGBLEND_1_blend(q, w);
  const Result<Quaternion<T>> mean = KARCHER_1_mean(q, w);
  if (blend.status != Status::ok || mean.status != Status::ok) return domain_error<T>();
  return {METRIC_1_rotation_distance(blend.value, mean.value), Status::ok};
}

}  // namespace rotorcert::ref::clause
