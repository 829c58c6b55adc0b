// Motors of PGA Cl(3,0,1) in closed form: normalisation, exp of a bivector, log of a motor
// (MOTOR-4). Dorst & De Keninck, "May the forque be with you", and Gunn's PGA notes.
//
// The structure that everything here rests on: the pseudoscalar I = e0123 commutes with every
// even element and squares to 0, and it turns a Euclidean bivector into an ideal one:
//     I e23 = -e01,   I e31 = -e02,   I e12 = -e03.
// So every even element is X = A + I C with A, C in the even subalgebra of e1, e2, e3 (the
// rotors of Cl(3,0)), and I behaves like the dual unit eps of the dual numbers (eps^2 = 0).
//   A bivector is  B = beta + I gamma   (beta, gamma Euclidean bivectors),
//   a motor is     M = R + I S          (R a unit rotor, S scalar + Euclidean bivector).
// Under MOTOR-1, R = Phi(q_r) and S = -Phi(q_d).
#pragma once

#include <array>

#include "cl3.hpp"
#include "pga.hpp"

namespace rotorcert::ref::pga {

/// I = e0123.
template <class T> MV<T> I() { return MV<T>::pseudoscalar(); }

/// The Euclidean bivector b23 e23 + b31 e31 + b12 e12 of PGA.
template <class T>
MV<T> euclidean(const std::array<T, 3>& b) { return bivector<T>(b, {T(0), T(0), T(0)}); }

/// The Euclidean even element s + b23 e23 + b31 e31 + b12 e12 (a rotor when unit).
template <class T>
MV<T> euclidean_even(const T& s, const std::array<T, 3>& b) {
  MV<T> m = euclidean(b);
  m.c[0] = s;
  return m;
}

/// gamma of B = beta + I gamma: I gamma = -(g23 e01 + g31 e02 + g12 e03), so gamma = -ideal part.
template <class T>
std::array<T, 3> ideal_as_euclidean(const MV<T>& b) {
  const std::array<T, 3> ideal = ideal_bivector(b);
  return {-ideal[0], -ideal[1], -ideal[2]};
}

/// A = <M>_0 + Euclidean bivector part: the rotor R of M = R + I S.
template <class T>
MV<T> real_part(const MV<T>& m) { return euclidean_even(m.c[0], euclidean_bivector(m)); }

/// S of M = R + I S, read off I S = S0 e0123 - s23 e01 - s31 e02 - s12 e03.
template <class T>
MV<T> dual_part(const MV<T>& m) { return euclidean_even(m.c[kE0123], ideal_as_euclidean(m)); }

// ---- small Euclidean 3-vector helpers (coefficients [e23, e31, e12]) ----------------------

template <class T>
T dot3(const std::array<T, 3>& a, const std::array<T, 3>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// |a|, scaled against overflow and underflow: the one of cl3.hpp.
using cl3::norm3;

template <class T>
std::array<T, 3> scaled3(const T& s, const std::array<T, 3>& a) { return {s * a[0], s * a[1], s * a[2]}; }

template <class T>
std::array<T, 3> divided3(const std::array<T, 3>& a, const T& s) { return {a[0] / s, a[1] / s, a[2] / s}; }

template <class T>
std::array<T, 3> minus3(const std::array<T, 3>& a, const std::array<T, 3>& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

// ---- normalisation -------------------------------------------------------------------------

/// M ~M of an even M is a dual number n + I m (grades 2 cancel), and
///   (n + I m)^(-1/2) = n^(-1/2) - I m / (2 n^(3/2))       (I^2 = 0).
/// So M (M ~M)^(-1/2) has M ~M = 1. Under MOTOR-1 this is DQ-4. Needs n = |R|^2 > 0.
/// Odd grades of the input are dropped.
template <class T>
MV<T> normalize_motor(const MV<T>& m_in) {
  using std::sqrt;
  const MV<T> m = even(m_in);
  const MV<T> mm = gp(m, reverse(m));
  const T n = mm.c[0], mi = mm.c[kE0123];
  const T root = sqrt(n);
  MV<T> inv_sqrt(T(1) / root);
  inv_sqrt.c[kE0123] = -mi / (T(2) * n * root);
  return gp(m, inv_sqrt);
}

// ---- exp and log ----------------------------------------------------------------------------

}  // namespace rotorcert::ref::pga

namespace rotorcert::ref::clause {

/// MOTOR-4, exp of the bivector part B = beta + I gamma of the input (other grades ignored).
/// Split gamma into the part along beta, which commutes with beta, and the part perpendicular
/// to it, which anticommutes; with b = |beta|, beta^ = beta / b:
///   exp(B) = exp(beta) + I ( gamma_par exp(beta) + (sin b / b) gamma_perp ),
///   exp(beta) = cos b + beta sin b / b;       b = 0:  exp(B) = 1 + I gamma.
/// (The I-part is the derivative of exp at beta in the direction gamma:
///  int_0^1 exp((1-u) beta) gamma exp(u beta) du, which is gamma exp(beta) for the commuting
///  part and (sin b / b) gamma for the anticommuting part.)
template <class T>
pga::MV<T> MOTOR_4_exp(const pga::MV<T>& bivector) {
  using std::cos;
  using std::sin;
  using namespace pga;
  const std::array<T, 3> beta = euclidean_bivector(bivector);
  const std::array<T, 3> gamma = ideal_as_euclidean(bivector);
  const T b = norm3(beta);
  if (b == 0) return MV<T>(T(1)) + gp(I<T>(), euclidean(gamma));

  const T sinc = sin(b) / b;
  const MV<T> r = euclidean_even(cos(b), scaled3(sinc, beta));  // exp(beta)
  const std::array<T, 3> axis = divided3(beta, b);            // beta^
  const std::array<T, 3> gamma_par = scaled3(dot3(gamma, axis), axis);
  const std::array<T, 3> gamma_perp = minus3(gamma, gamma_par);
  return r + gp(I<T>(), gp(euclidean(gamma_par), r) + sinc * euclidean(gamma_perp));
}

/// MOTOR-4, the log of the motor M = R + I S (normalised first, M ~M = 1, odd grades dropped):
/// the bivector beta + I gamma with exp(beta + I gamma) = M. Inverting MOTOR_4_exp with
/// R = cos b + beta^ sin b and S = S0 + S_par beta^ + S_perp:
///   beta = log R (LOG-1, b = |beta| in [0, pi]),
///   gamma = g beta^ + (b / sin b) S_perp,   g = S_par cos b - S0 sin b;
///   b = 0 (R = 1):  gamma = bivector part of S.
/// The singular case b = pi is R = -1 (a translation times -1: rotor angle 2 pi). There S is a
/// pure bivector s and only gamma_par is determined by exp, so the axis is chosen along s:
///   beta = pi s/|s|, gamma = -s  (then exp(log M) = M exactly);  s = 0: beta = -pi e12 (LOG-2),
///   gamma = 0. Interpolation (MOTOR_4_interpolate) aligns the hemisphere first, so there
///   b <= pi/2 and this case never occurs.
template <class T>
pga::MV<T> MOTOR_4_log(const pga::MV<T>& motor) {
  using std::sqrt;
  using namespace pga;
  const MV<T> m = normalize_motor(motor);
  const MV<T> r = real_part(m), s = dual_part(m);
  const T s0 = s.c[0];
  const std::array<T, 3> s_biv = euclidean_bivector(s);
  // R = cos b + beta^ sin b: read cos b and sin b off R itself (exact on the unit circle).
  const std::array<T, 3> r_biv = euclidean_bivector(r);
  const T cos_b = r.c[0], sin_b = norm3(r_biv);

  if (sin_b == 0 && cos_b > 0) return bivector<T>({T(0), T(0), T(0)}, scaled3(T(-1), s_biv));  // b = 0
  if (sin_b == 0) {                                                                          // b = pi
    const T sn = norm3(s_biv);
    if (sn == 0) return bivector<T>({T(0), T(0), -ScalarTraits<T>::pi()}, {T(0), T(0), T(0)});
    const std::array<T, 3> beta = scaled3(ScalarTraits<T>::pi() / sn, s_biv);
    return bivector<T>(beta, s_biv);  // I gamma with gamma = -s: ideal part = +s
  }

  cl3::MV<T> r3;  // the same rotor in Cl(3,0), for LOG-1
  r3.c[0] = cos_b;
  r3.c[cl3::kE23] = r_biv[0];
  r3.c[cl3::kE13] = -r_biv[1];
  r3.c[cl3::kE12] = r_biv[2];
  const std::array<T, 3> beta = cl3::log_rotor(r3);
  const T b = norm3(beta);
  const std::array<T, 3> axis = divided3(r_biv, sin_b);  // beta^
  const T s_par = dot3(s_biv, axis);
  const std::array<T, 3> s_perp = minus3(s_biv, scaled3(s_par, axis));
  const T g = s_par * cos_b - s0 * sin_b;
  const std::array<T, 3> gamma = {g * axis[0] + b / sin_b * s_perp[0], g * axis[1] + b / sin_b * s_perp[1],
                                  g * axis[2] + b / sin_b * s_perp[2]};
  return bivector<T>(beta, scaled3(T(-1), gamma));
}

}  // namespace rotorcert::ref::clause
