// Rigid transforms: dual quaternions (DQ-1 .. DQ-6), their motors in PGA (MOTOR-1 .. MOTOR-5),
// rotation about an off-origin line (AXIS-1) and skinning of one vertex (SKIN-1, SKIN-2).
//
// Two independent routes on purpose:
//   DQ-*    by the quaternion formulas that the clauses state (Hamilton products of quaternion.hpp),
//   MOTOR-* in the algebra: geometric products, sandwiches, exp and log of motor.hpp.
// The tests show that the two agree (MOTOR-2 .. MOTOR-5); neither calls the other's arithmetic,
// only the coefficient map MOTOR-1 joins them.
//
// Every clause function validates first (EDGE-6, EDGE-7, EDGE-9): a non-finite component
// anywhere, a zero real part, or bad weights give DOMAIN_ERROR with all-NaN output. A
// non-unit dual quaternion stands for its DQ-4 normalisation (EDGE-5), except in DQ-2 and
// MOTOR-3, whose product is defined on the inputs as given ("No normalisation").
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "cl3.hpp"
#include "motor.hpp"
#include "pga.hpp"
#include "quaternion.hpp"
#include "result.hpp"

namespace rotorcert::ref::rigid {

// ---- input checks ----------------------------------------------------------------------------

/// A usable dual quaternion: every component finite and the real part nonzero.
template <class T>
bool valid(const DualQuaternion<T>& d) { return finite(d) && !is_zero(d.real); }

/// A usable rotation quaternion: finite and nonzero.
template <class T>
bool valid(const Quaternion<T>& q) { return finite(q) && !is_zero(q); }

/// EDGE-9: as many weights as influences, at least one, each finite and >= 0 (-0 counts as 0),
/// and a positive sum.
template <class T>
bool valid_weights(std::span<const T> w, std::size_t influences) {
  if (w.empty() || w.size() != influences) return false;
  bool positive = false;
  for (const T& x : w) {
    if (!finite(x) || x < 0) return false;
    if (x > 0) positive = true;
  }
  return positive;
}

/// The weights divided by the largest one (so that their sum cannot overflow in binary64);
/// DLB and LBS only depend on the ratios.
template <class T>
std::vector<T> scaled_weights(std::span<const T> w) {
  using std::max;  // the type's own max: Bounded's needs no decision between equal weights
  T largest(0);
  for (const T& x : w) largest = max(largest, x);
  std::vector<T> r;
  for (const T& x : w) r.push_back(x / largest);
  return r;
}

// ---- quaternion arithmetic --------------------------------------------------------------------

template <class T>
T largest_component(const Quaternion<T>& q) {
  using std::abs;
  return largest_magnitude(q.w, q.x, q.y, q.z);
}

/// q / s, component by component (not q * (1/s): 1/s overflows for a subnormal s in binary64).
template <class T>
Quaternion<T> divided(const Quaternion<T>& q, const T& s) { return {q.w / s, q.x / s, q.y / s, q.z / s}; }

/// q / |q|, scaling by the largest |component| first (no overflow or underflow, NORM-1).
template <class T>
Quaternion<T> unit(const Quaternion<T>& q) {
  const Quaternion<T> s = divided(q, largest_component(q));
  return divided(s, norm(s));
}

/// Pure quaternion (v, 0) and the vector part of a quaternion.
template <class T>
Quaternion<T> pure(const Vec3<T>& v) { return {T(0), v[0], v[1], v[2]}; }
template <class T>
Vec3<T> vector_part(const Quaternion<T>& q) { return {q.x, q.y, q.z}; }

// ---- dual-quaternion arithmetic ------------------------------------------------------------

/// DQ-2: (a_r b_r) + eps (a_r b_d + a_d b_r).
template <class T>
DualQuaternion<T> product(const DualQuaternion<T>& a, const DualQuaternion<T>& b) {
  return {a.real * b.real, a.real * b.dual + a.dual * b.real};
}

/// sigma* = (q_r*, q_d*): the inverse of a unit dual quaternion.
template <class T>
DualQuaternion<T> conjugate(const DualQuaternion<T>& d) { return {conj(d.real), conj(d.dual)}; }

template <class T>
DualQuaternion<T> negated(const DualQuaternion<T>& d) { return {-d.real, -d.dual}; }

/// DQ-4: r' = r/|r|, d' = d/|r| - (r.d / |r|^3) r. Both parts are first divided by the largest
/// |component| of r; the formula is invariant under that common scale.
template <class T>
DualQuaternion<T> normalized(const DualQuaternion<T>& d) {
  const T k = largest_component(d.real);
  const Quaternion<T> r = divided(d.real, k), e = divided(d.dual, k);
  const T n = norm(r);
  const T c = dot(r, e) / (n * n * n);
  return {divided(r, n), divided(e, n) - c * r};
}

/// DQ-1: sigma = (q_r, (1/2) t q_r) with q_r = q/|q|.
template <class T>
DualQuaternion<T> from_rotation_translation(const Quaternion<T>& q, const Vec3<T>& t) {
  const Quaternion<T> r = unit(q);
  return {r, (T(1) / T(2)) * (pure(t) * r)};
}

/// DQ-1 / DQ-3 for a unit dual quaternion: t = 2 q_d q_r*, p' = q_r p q_r* + t.
template <class T>
Vec3<T> translation_of_unit(const DualQuaternion<T>& u) { return vector_part(T(2) * (u.dual * conj(u.real))); }

/// R v as the sandwich u v u* of a unit quaternion u.
template <class T>
Vec3<T> rotated(const Quaternion<T>& u, const Vec3<T>& v) { return vector_part(u * pure(v) * conj(u)); }

/// The rigid motion x -> R x + t of a unit rotation u and a translation t, applied to p.
template <class T>
Vec3<T> moved(const Quaternion<T>& u, const Vec3<T>& t, const Vec3<T>& p) {
  const Vec3<T> rp = rotated(u, p);
  return {rp[0] + t[0], rp[1] + t[1], rp[2] + t[2]};
}

template <class T>
Vec3<T> apply_unit(const DualQuaternion<T>& u, const Vec3<T>& p) { return moved(u.real, translation_of_unit(u), p); }

/// Screw power sigma^tau of a unit dual quaternion whose real part has w >= 0, by its screw
/// parameters (dual angle theta + eps d, dual axis l + eps m, Kavan et al. 2008):
///   sigma = cos(theta^/2) + sin(theta^/2) (l + eps m),   theta^ = theta + eps d,
///   sigma^tau = cos(tau theta^/2) + sin(tau theta^/2) (l + eps m), expanded with
///   f(a + eps b) = f(a) + eps b f'(a). Reading the parameters off sigma = (w + v, d_w + d_v):
///   sin(theta/2) = |v|, l = v/|v|, d = -2 d_w / |v|, m = (d_v - (d/2) w l) / |v|.
/// No rotation (v = 0, then w = 1): a translation, sigma^tau = (1, tau q_d).
template <class T>
DualQuaternion<T> screw_power(const DualQuaternion<T>& u, const T& tau) {
  using std::atan2;
  using std::cos;
  using std::sin;
  const Vec3<T> v = vector_part(u.real), dv = vector_part(u.dual);
  const T s = pga::norm3(v), w = u.real.w;
  if (s == 0) return {Quaternion<T>::identity(), tau * u.dual};
  const T half = atan2(s, w);  // theta / 2
  const Vec3<T> l = pga::divided3(v, s);
  const T pitch = -T(2) * u.dual.w / s;
  const Vec3<T> m = pga::divided3(pga::minus3(dv, pga::scaled3(pitch / T(2) * w, l)), s);
  const T c = cos(tau * half), sn = sin(tau * half), h = tau * pitch / T(2);
  return {{c, sn * l[0], sn * l[1], sn * l[2]},
          {-h * sn, sn * m[0] + h * c * l[0], sn * m[1] + h * c * l[1], sn * m[2] + h * c * l[2]}};
}

/// DQ-6 on validated input: DQ-4 of every influence (EDGE-5: a non-unit sigma_i is the rigid
/// motion of DQ-4(sigma_i), its weight is w_i whatever its norm), s_i = -1 iff r_i . r_p < 0
/// against the pivot p (first weight > 0), sum w_i s_i DQ-4(sigma_i), DQ-4 of the sum.
/// The sign of r_i . r_p is that of the real parts as given (a positive scale keeps it) and is
/// decided exactly on them (EDGE-3); `reals`, if not empty, holds positive multiples of the
/// real parts to decide it on instead (SKIN-2: the q_i as given, not their rounded q_i/|q_i|).
template <class T>
DualQuaternion<T> dlb(std::span<const DualQuaternion<T>> d, std::span<const T> w_in,
                      std::span<const Quaternion<T>> reals = {}) {
  const std::vector<T> w = scaled_weights(w_in);
  std::size_t p = 0;
  while (!(w[p] > 0)) ++p;
  auto real = [&](std::size_t i) -> const Quaternion<T>& { return reals.empty() ? d[i].real : reals[i]; };
  DualQuaternion<T> sum{{T(0), T(0), T(0), T(0)}, {T(0), T(0), T(0), T(0)}};
  for (std::size_t i = 0; i < d.size(); ++i) {
    DualQuaternion<T> u = normalized(d[i]);
    if (hemisphere_sign(real(i), real(p)) < 0) u = negated(u);  // exact decision (EDGE-3)
    sum = {sum.real + w[i] * u.real, sum.dual + w[i] * u.dual};
  }
  return normalized(sum);
}

/// Validation shared by SKIN-1 and SKIN-2.
template <class T>
bool valid_skin_input(std::span<const Quaternion<T>> q, std::span<const Vec3<T>> t, std::span<const T> w,
                      const Vec3<T>& v) {
  if (q.size() != t.size() || !valid_weights(w, q.size()) || !finite(v)) return false;
  for (std::size_t i = 0; i < q.size(); ++i)
    if (!valid(q[i]) || !finite(t[i])) return false;
  return true;
}

// ---- motors ---------------------------------------------------------------------------------

/// MOTOR-1 followed by normalisation in the algebra (M (M ~M)^(-1/2), not DQ-4's formula).
template <class T>
pga::MV<T> unit_motor(const DualQuaternion<T>& d) {
  return pga::normalize_motor(pga::motor_from_dual_quaternion(d.real, d.dual));
}

template <class T>
DualQuaternion<T> to_dual_quaternion(const pga::MV<T>& m) {
  const auto [real, dual] = pga::dual_quaternion_from_motor(m);
  return {real, dual};
}

}  // namespace rotorcert::ref::rigid

namespace rotorcert::ref::clause {

// ---- dual quaternions (quaternion formulas) -------------------------------------------------

/// DQ-1: sigma = (q_r, (1/2) t q_r), q_r = q/|q|.
template <class T>
Result<DualQuaternion<T>> DQ_1_from_rotation_translation(const Quaternion<T>& q, const Vec3<T>& t) {
  if (!rigid::valid(q) || !finite(t)) return domain_error<DualQuaternion<T>>();
  return {rigid::from_rotation_translation(q, t), Status::ok};
}

/// DQ-1: translation t = 2 q_d q_r* of the DQ-4-normalised input.
template <class T>
Result<Vec3<T>> DQ_1_translation(const DualQuaternion<T>& d) {
  if (!rigid::valid(d)) return domain_error<Vec3<T>>();
  return {rigid::translation_of_unit(rigid::normalized(d)), Status::ok};
}

/// DQ-2: the product a b of the inputs as given (apply b first). No normalisation: for non-unit
/// inputs the result is the exact product, whose DQ-4 normalisation is DQ-4(a) DQ-4(b) (the dual
/// norm is multiplicative), so METRIC-7, which normalises both sides, judges the rigid motion.
template <class T>
Result<DualQuaternion<T>> DQ_2_compose(const DualQuaternion<T>& a, const DualQuaternion<T>& b) {
  if (!rigid::valid(a) || !rigid::valid(b)) return domain_error<DualQuaternion<T>>();
  return {rigid::product(a, b), Status::ok};
}

/// DQ-3: p' = R p + t of the normalised input (R p as q_r p q_r*).
template <class T>
Result<Vec3<T>> DQ_3_apply_point(const DualQuaternion<T>& d, const Vec3<T>& p) {
  if (!rigid::valid(d) || !finite(p)) return domain_error<Vec3<T>>();
  return {rigid::apply_unit(rigid::normalized(d), p), Status::ok};
}

/// DQ-4: (r/|r|, d/|r| - (r.d/|r|^3) r).
template <class T>
Result<DualQuaternion<T>> DQ_4_normalize(const DualQuaternion<T>& d) {
  if (!rigid::valid(d)) return domain_error<DualQuaternion<T>>();
  return {rigid::normalized(d), Status::ok};
}

/// DQ-5: ScLERP sigma_a (sigma_a* sigma_b')^t of the normalised inputs, b' = -b (both parts)
/// iff dot(a_r, b_r) < 0 strictly; the power by screw parameters (rigid::screw_power).
/// Any real t: outside [0, 1] it extrapolates along the same screw.
template <class T>
Result<DualQuaternion<T>> DQ_5_sclerp(const DualQuaternion<T>& a, const DualQuaternion<T>& b, const T& t) {
  if (!rigid::valid(a) || !rigid::valid(b) || !finite(t)) return domain_error<DualQuaternion<T>>();
  const DualQuaternion<T> ua = rigid::normalized(a);
  DualQuaternion<T> ub = rigid::normalized(b);
  if (hemisphere_sign(a.real, b.real) < 0) ub = rigid::negated(ub);  // exact decision (EDGE-3)
  const DualQuaternion<T> relative = rigid::product(rigid::conjugate(ua), ub);
  return {rigid::product(ua, rigid::screw_power(relative, t)), Status::ok};
}

/// DQ-6: dual-quaternion linear blending (Kavan et al. 2008); see rigid::dlb.
template <class T>
Result<DualQuaternion<T>> DQ_6_dlb(std::span<const DualQuaternion<T>> d, std::span<const T> w) {
  if (!rigid::valid_weights(w, d.size())) return domain_error<DualQuaternion<T>>();
  for (const auto& x : d)
    if (!rigid::valid(x)) return domain_error<DualQuaternion<T>>();
  return {rigid::dlb(d, w), Status::ok};
}

}  // namespace rotorcert::ref::clause

namespace rotorcert::ref {

/// The pure dual quaternion xi = xi_r + eps xi_d (two 3-vectors, the quaternion view of the motor's
/// bivector: MOTOR-1 maps it to -(xi_r on e23, e31, e12) - (xi_d on e01, e02, e03)). DQ-8, DQ-9.
template <class T>
struct DualVector {
  Vec3<T> real, dual;
};
template <class T> void poison(DualVector<T>& v) { poison(v.real); poison(v.dual); }

/// A rigid transform x -> R x + t held as a rotation quaternion q (R of q/|q|) and a translation t.
/// RIGID-1 .. RIGID-3.
template <class T>
struct RotationTranslation {
  Quaternion<T> q;
  Vec3<T> t;
};
template <class T> void poison(RotationTranslation<T>& r) { poison(r.q); poison(r.t); }

}  // namespace rotorcert::ref

namespace rotorcert::ref::clause {

// ---- logarithm and exponential of unit dual quaternions (DQ-8, DQ-9) --------------------------


/// DQ-9: exp(xi_r + eps xi_d) = exp(xi_r) + eps Dexp(xi_r)[xi_d] (a dual-number function: the
/// power series of (a + eps b)^n is a^n + eps sum a^k b a^(n-1-k), the derivative of x^n). With
/// b = |xi_r|, n = xi_r / b, a = xi_d . n and xi_perp = xi_d - a n:
///   real = (cos b, sin b n),   dual = (-a sin b, a cos b n + (sin b / b) xi_perp);
/// b = 0: (1, (0, xi_d)) (a translation by 2 xi_d). The result is unit: real . dual = 0.
template <class T>
Result<DualQuaternion<T>> DQ_9_exp(const DualVector<T>& xi) {
  using std::cos;
  using std::sin;
  if (!finite(xi.real) || !finite(xi.dual)) return domain_error<DualQuaternion<T>>();
  const T b = pga::norm3(xi.real);
  if (b == 0) return {{Quaternion<T>::identity(), rigid::pure(xi.dual)}, Status::ok};
  const Vec3<T> n = pga::divided3(xi.real, b);
  const T a = pga::dot3(xi.dual, n);
  const Vec3<T> perp = pga::minus3(xi.dual, pga::scaled3(a, n));
  const T c = cos(b), s = sin(b), sinc = s / b;
  return {{{c, s * n[0], s * n[1], s * n[2]},
           {-a * s, a * c * n[0] + sinc * perp[0], a * c * n[1] + sinc * perp[1], a * c * n[2] + sinc * perp[2]}},
          Status::ok};
}

/// DQ-8: the principal logarithm of DQ-4(sigma), the inverse of DQ-9. With (r, d) = DQ-4(sigma),
/// r = (cos b, sin b n) and b = atan2(|r_v|, r_w) in [0, pi] (LOG-1's branch: no hemisphere flip):
///   xi_r = b n,   xi_d = a n + (b / sin b) d_perp,   a = (d_v . n) cos b - d_w sin b,
/// d_perp = d_v - (d_v . n) n (DQ-9 solved for xi_d; a is the combination of d_w = -a sin b and
/// d_v . n = a cos b that never divides by sin b). b = 0: xi = (0, d_v). The branch cut r = -1
/// (b = pi; then d_w = 0 and t = -2 d_v): only the part of xi_d along n is determined, and n must
/// be +-t/|t|; the spec's choice is xi = (pi t/|t|, t/2), and (pi (0, 0, 1), 0) for t = 0 (LOG-2).
template <class T>
Result<DualVector<T>> DQ_8_log(const DualQuaternion<T>& sigma) {
  using std::atan2;
  if (!rigid::valid(sigma)) return domain_error<DualVector<T>>();
  const DualQuaternion<T> u = rigid::normalized(sigma);
  const Vec3<T> rv = rigid::vector_part(u.real), dv = rigid::vector_part(u.dual);
  const T s = pga::norm3(rv);
  if (s == 0 && u.real.w > 0) return {{{T(0), T(0), T(0)}, dv}, Status::ok};
  if (s == 0) {  // r = -1
    const Vec3<T> t = rigid::translation_of_unit(u);
    const T len = pga::norm3(t);
    const T pi = ScalarTraits<T>::pi();
    if (len == 0) return {{{T(0), T(0), pi}, {T(0), T(0), T(0)}}, Status::ok};
    return {{pga::scaled3(pi / len, t), pga::scaled3(T(1) / T(2), t)}, Status::ok};
  }
  const T b = atan2(s, u.real.w);
  const Vec3<T> n = pga::divided3(rv, s);
  const T along = pga::dot3(dv, n);
  const T a = along * u.real.w - u.dual.w * s;  // cos b = r_w, sin b = |r_v| on the unit r
  const Vec3<T> perp = pga::minus3(dv, pga::scaled3(along, n));
  const T k = b / s;
  return {{pga::scaled3(b, n), {a * n[0] + k * perp[0], a * n[1] + k * perp[1], a * n[2] + k * perp[2]}}, Status::ok};
}

// ---- rotation and translation of a dual quaternion (DQ-7) -----------------------------------------

/// DQ-7: DQ-1 read backwards after DQ-4: q = r/|r| and t = 2 d' r'* of (r', d') = DQ-4(sigma) (the
/// part of d along r carries no translation).
template <class T>
Result<RotationTranslation<T>> DQ_7_to_rotation_translation(const DualQuaternion<T>& sigma) {
  if (!rigid::valid(sigma)) return domain_error<RotationTranslation<T>>();
  const DualQuaternion<T> unit = rigid::normalized(sigma);
  return {{unit.real, rigid::translation_of_unit(unit)}, Status::ok};
}

// ---- rigid transforms as rotation + translation (RIGID-1 .. RIGID-3) ----------------------------


/// RIGID-1: (q_a, t_a) o (q_b, t_b) = (q^_a q^_b, R_a t_b + t_a): apply b first (as DQ-2).
template <class T>
Result<RotationTranslation<T>> RIGID_1_compose(const Quaternion<T>& qa, const Vec3<T>& ta, const Quaternion<T>& qb,
                                               const Vec3<T>& tb) {
  if (!rigid::valid(qa) || !rigid::valid(qb) || !finite(ta) || !finite(tb)) return domain_error<RotationTranslation<T>>();
  const Quaternion<T> ua = rigid::unit(qa), ub = rigid::unit(qb);
  return {{ua * ub, rigid::moved(ua, ta, tb)}, Status::ok};
}

/// RIGID-2: p' = R p + t with R the rotation of q/|q| (the motion of DQ-3 for sigma = DQ-1(q, t)).
template <class T>
Result<Vec3<T>> RIGID_2_apply(const Quaternion<T>& q, const Vec3<T>& t, const Vec3<T>& p) {
  if (!rigid::valid(q) || !finite(t) || !finite(p)) return domain_error<Vec3<T>>();
  return {rigid::moved(rigid::unit(q), t, p), Status::ok};
}

/// RIGID-3: the inverse transform x -> R^-1 (x - t): (q^*, -R^-1 t).
template <class T>
Result<RotationTranslation<T>> RIGID_3_inverse(const Quaternion<T>& q, const Vec3<T>& t) {
  if (!rigid::valid(q) || !finite(t)) return domain_error<RotationTranslation<T>>();
  const Quaternion<T> inv = conj(rigid::unit(q));
  const Vec3<T> back = rigid::rotated(inv, t);
  return {{inv, {-back[0], -back[1], -back[2]}}, Status::ok};
}

// ---- motors (in the algebra) ------------------------------------------------------------------

/// MOTOR-1: M = w_r - x_r e23 - y_r e31 - z_r e12 - x_d e01 - y_d e02 - z_d e03 - w_d e0123,
/// i.e. M = Phi(q_r) - e0123 Phi(q_d). A coefficient map: exact, no normalisation.
template <class T>
pga::MV<T> MOTOR_1_from_dual_quaternion(const DualQuaternion<T>& d) {
  return pga::motor_from_dual_quaternion(d.real, d.dual);
}

/// MOTOR-1, inverse map (odd grades ignored).
template <class T>
DualQuaternion<T> MOTOR_1_to_dual_quaternion(const pga::MV<T>& m) { return rigid::to_dual_quaternion(m); }

/// MOTOR-2: the point P(p) = x e032 + y e013 + z e021 + e123 moved by the sandwich M P ~M.
template <class T>
Result<Vec3<T>> MOTOR_2_apply_point(const DualQuaternion<T>& d, const Vec3<T>& p) {
  if (!rigid::valid(d) || !finite(p)) return domain_error<Vec3<T>>();
  const pga::MV<T> m = rigid::unit_motor(d);
  return {pga::point_coordinates(gp(gp(m, pga::point(p)), reverse(m))), Status::ok};
}

/// MOTOR-3: the geometric product M_a M_b (apply b first) of the MOTOR-1 images of the inputs as
/// given, mapped back by MOTOR-1: the motor form of DQ-2's product, not normalised either.
template <class T>
Result<DualQuaternion<T>> MOTOR_3_compose(const DualQuaternion<T>& a, const DualQuaternion<T>& b) {
  if (!rigid::valid(a) || !rigid::valid(b)) return domain_error<DualQuaternion<T>>();
  return {rigid::to_dual_quaternion(gp(pga::motor_from_dual_quaternion(a.real, a.dual),
                                       pga::motor_from_dual_quaternion(b.real, b.dual))),
          Status::ok};
}

/// MOTOR-4: exp(t log(M_B ~M_A)) M_A with M_B -> -M_B iff <M_B ~M_A>_0 < 0 (the same test as
/// DQ-5's dot(a_r, b_r) < 0); exp and log in closed form (motor.hpp).
template <class T>
Result<DualQuaternion<T>> MOTOR_4_interpolate(const DualQuaternion<T>& a, const DualQuaternion<T>& b, const T& t) {
  if (!rigid::valid(a) || !rigid::valid(b) || !finite(t)) return domain_error<DualQuaternion<T>>();
  const pga::MV<T> ma = rigid::unit_motor(a);
  pga::MV<T> mb = rigid::unit_motor(b);
  if (hemisphere_sign(a.real, b.real) < 0) mb = -mb;  // <M_B ~M_A>_0 = a_r . b_r, decided exactly (EDGE-3)
  const pga::MV<T> relative = gp(mb, reverse(ma));
  return {rigid::to_dual_quaternion(gp(MOTOR_4_exp(t * MOTOR_4_log(relative)), ma)), Status::ok};
}

/// MOTOR-5: normalise(sum w_i s_i M_i) with every M_i normalised in the algebra (M (M ~M)^(-1/2),
/// DQ-4 transported by MOTOR-1, as DQ-6 normalises every influence), the pivot the first positive
/// weight and s_i = -1 iff <M_i ~M_p>_0 < 0.
template <class T>
Result<DualQuaternion<T>> MOTOR_5_blend(std::span<const DualQuaternion<T>> d, std::span<const T> w_in) {
  if (!rigid::valid_weights(w_in, d.size())) return domain_error<DualQuaternion<T>>();
  for (const auto& x : d)
    if (!rigid::valid(x)) return domain_error<DualQuaternion<T>>();
  const std::vector<T> w = rigid::scaled_weights(w_in);
  std::size_t p = 0;
  while (!(w[p] > 0)) ++p;
  pga::MV<T> sum;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const pga::MV<T> m = rigid::unit_motor(d[i]);
    const T s = hemisphere_sign(d[i].real, d[p].real) < 0 ? T(-1) : T(1);  // <M_i ~M_p>_0, exactly (EDGE-3)
    sum = sum + (s * w[i]) * m;
  }
  return {rigid::to_dual_quaternion(pga::normalize_motor(sum)), Status::ok};
}

// ---- rotation about a line ------------------------------------------------------------------

/// AXIS-1: rotation by `angle` (right-handed) about the line through c with direction u/|u|:
/// x -> R (x - c) + c, computed as the motor T_c R ~T_c applied to the point, with
/// R = exp(-I u angle/2) = cos(angle/2) - sin(angle/2) (u1 e23 + u2 e31 + u3 e12).
/// u = 0 has no direction: DOMAIN_ERROR.
template <class T>
Result<Vec3<T>> AXIS_1_rotate_about_line(const Vec3<T>& c, const Vec3<T>& u, const T& angle, const Vec3<T>& p) {
  using std::abs;
  using std::cos;
  using std::sin;
  if (!finite(c) || !finite(u) || !finite(angle) || !finite(p)) return domain_error<Vec3<T>>();
  const T largest = largest_magnitude(u[0], u[1], u[2]);
  if (largest == 0) return domain_error<Vec3<T>>();
  const Vec3<T> us{u[0] / largest, u[1] / largest, u[2] / largest};
  const T n = pga::norm3(us);
  const Vec3<T> axis{us[0] / n, us[1] / n, us[2] / n};
  const T half = angle / T(2);
  const pga::MV<T> r = pga::euclidean_even(cos(half), pga::scaled3(-sin(half), axis));
  const pga::MV<T> tc = pga::translator(c);
  const pga::MV<T> m = gp(gp(tc, r), reverse(tc));
  return {pga::point_coordinates(gp(gp(m, pga::point(p)), reverse(m))), Status::ok};
}

// ---- skinning ---------------------------------------------------------------------------------

/// SKIN-1: linear blend skinning, sum (w_i / W) (R_i v + t_i), R_i v the Cl(3,0) sandwich
/// Phi(q_i) v ~Phi(q_i) of the normalised q_i.
template <class T>
Result<Vec3<T>> SKIN_1_linear_blend(std::span<const Quaternion<T>> q, std::span<const Vec3<T>> t,
                                    std::span<const T> w_in, const Vec3<T>& v) {
  if (!rigid::valid_skin_input(q, t, w_in, v)) return domain_error<Vec3<T>>();
  const std::vector<T> w = rigid::scaled_weights(w_in);
  T total(0);
  for (const T& x : w) total += x;
  Vec3<T> sum{T(0), T(0), T(0)};
  for (std::size_t i = 0; i < q.size(); ++i) {
    const cl3::MV<T> r = cl3::rotor_from_quaternion(rigid::unit(q[i]));
    const Vec3<T> moved = cl3::vector_part(cl3::sandwich(r, cl3::vector(v)));
    const T f = w[i] / total;
    for (int k = 0; k < 3; ++k) sum[k] += f * (moved[k] + t[i][k]);
  }
  return {sum, Status::ok};
}

/// SKIN-2: dual-quaternion skinning, DQ-3 of the DLB (DQ-6) of sigma_i = DQ-1(q_i, t_i). The real
/// part of sigma_i is q_i/|q_i|, so DQ-6's sign s_i is that of q_i . q_p, decided exactly on the
/// q_i as given (EDGE-3).
template <class T>
Result<Vec3<T>> SKIN_2_dual_quaternion(std::span<const Quaternion<T>> q, std::span<const Vec3<T>> t,
                                       std::span<const T> w, const Vec3<T>& v) {
  if (!rigid::valid_skin_input(q, t, w, v)) return domain_error<Vec3<T>>();
  std::vector<DualQuaternion<T>> d;
  for (std::size_t i = 0; i < q.size(); ++i) d.push_back(rigid::from_rotation_translation(q[i], t[i]));
  return {rigid::apply_unit(rigid::dlb<T>(d, w, q), v), Status::ok};
}

}  // namespace rotorcert::ref::clause
